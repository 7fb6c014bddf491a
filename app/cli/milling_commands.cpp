// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/milling_commands.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "app/cli/milling_input.h"
#include "core/common/csv.h"
#include "core/io/project_file.h"
#include "core/milling/ball_end_deflection.h"
#include "core/milling/ball_end_planning.h"
#include "core/milling/seed_ball_end_cases.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <QTextStream>

#include <cmath>
#include <numbers>
#include <optional>

namespace tolturn {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

QString cutKindName(const BallEndCut &cut)
{
    switch (cut.kind) {
    case BallEndCutKind::Slot:
        return MillingCommand::tr("slot");
    case BallEndCutKind::SideCut:
        return MillingCommand::tr("side cut %1 mm wide").arg(cut.radialDepth_mm);
    case BallEndCutKind::StepOver:
        return MillingCommand::tr("step-over %1 mm").arg(cut.radialDepth_mm);
    }
    return {};
}

void printSetup(const MillingInput &in, QTextStream &out)
{
    if (in.caseNumber > 0)
        out << MillingCommand::tr("Öztürk & Budak (001) table 4, case %1: DMU 50 Evolution, Ti6Al4V").arg(in.caseNumber)
            << '\n';
    out << MillingCommand::tr("Ball-end mill Ø%1 mm, %2 flutes, helix %3°; %4, %5 milling, axial depth %6 mm, "
                              "feed %7 mm/tooth, %8 1/min; lead %9°, tilt %10°")
               .arg(in.mill.diameter_mm)
               .arg(in.mill.flutes)
               .arg(in.mill.helix_rad / kDegree, 0, 'f', 1)
               .arg(cutKindName(in.cut),
                    in.cut.direction == MillingDirection::Down ? MillingCommand::tr("down") : MillingCommand::tr("up"))
               .arg(in.cut.axialDepth_mm)
               .arg(in.cut.feedPerTooth_mm)
               .arg(in.spindle_rpm)
               .arg(in.cut.lead_rad / kDegree, 0, 'f', 1)
               .arg(in.cut.tilt_rad / kDegree, 0, 'f', 1)
        << '\n';
    const MillingForceCoefficients &k = in.coefficients;
    out << MillingCommand::tr("Coefficients (given): Ktc %1, Krc %2, Kac %3 N/mm²; Kte %4, Kre %5, Kae %6 N/mm")
               .arg(k.tangentialCutting_N_mm2)
               .arg(k.radialCutting_N_mm2)
               .arg(k.axialCutting_N_mm2)
               .arg(k.tangentialEdge_N_mm)
               .arg(k.radialEdge_N_mm)
               .arg(k.axialEdge_N_mm)
        << '\n';
    out << MillingCommand::tr("%1 disc elements, %2 rotation angles per revolution")
               .arg(in.resolution.axialSlices)
               .arg(in.resolution.anglesPerRevolution)
        << "\n\n";
}

QJsonObject vectorJson(const Eigen::Vector3d &v, const QString &a, const QString &b, const QString &c)
{
    return {{a, v.x()}, {b, v.y()}, {c, v.z()}};
}

QJsonObject summaryJson(const MillingInput &in, const BallEndForceSummary &s)
{
    return {{QStringLiteral("case"), in.caseNumber},
            {QStringLiteral("peak_N"),
             vectorJson(s.peak_N, QStringLiteral("feed"), QStringLiteral("cross_feed"), QStringLiteral("normal"))},
            {QStringLiteral("peak_resultant_N"), s.peakResultant_N},
            {QStringLiteral("mean_torque_N_mm"), s.meanTorque_N_mm},
            {QStringLiteral("peak_torque_N_mm"), s.peakTorque_N_mm},
            {QStringLiteral("mean_power_W"), spindlePower_W(s.meanTorque_N_mm, in.spindle_rpm)}};
}

void printSummary(const MillingInput &in, const BallEndForceSummary &s, QTextStream &out)
{
    out << MillingCommand::tr("Peak forces on the tool: F %1 N, C %2 N, N %3 N (feed, cross-feed, surface normal); "
                              "resultant %4 N")
               .arg(s.peak_N.x(), 0, 'f', 1)
               .arg(s.peak_N.y(), 0, 'f', 1)
               .arg(s.peak_N.z(), 0, 'f', 1)
               .arg(s.peakResultant_N, 0, 'f', 1)
        << '\n'
        << MillingCommand::tr("Torque: mean %1 N·m, peak %2 N·m; mean spindle power %3 W")
               .arg(s.meanTorque_N_mm / 1000.0, 0, 'f', 3)
               .arg(s.peakTorque_N_mm / 1000.0, 0, 'f', 3)
               .arg(spindlePower_W(s.meanTorque_N_mm, in.spindle_rpm), 0, 'f', 1)
        << '\n';
}

QString number(double v, int decimals)
{
    return QString::number(v, 'f', decimals);
}

void printForcesCsv(const std::vector<BallEndForceSample> &samples, QTextStream &out)
{
    out << csvLine({QStringLiteral("rotation_deg"), QStringLiteral("F_feed_N"), QStringLiteral("F_cross_feed_N"),
                    QStringLiteral("F_normal_N"), QStringLiteral("Fx_tool_N"), QStringLiteral("Fy_tool_N"),
                    QStringLiteral("Fz_tool_N"), QStringLiteral("torque_N_mm")})
        << '\n';
    for (const BallEndForceSample &s : samples)
        out << csvLine({number(s.rotation_rad / kDegree, 3), number(s.workpieceFrame_N.x(), 3),
                        number(s.workpieceFrame_N.y(), 3), number(s.workpieceFrame_N.z(), 3),
                        number(s.toolFrame_N.x(), 3), number(s.toolFrame_N.y(), 3), number(s.toolFrame_N.z(), 3),
                        number(s.torque_N_mm, 3)})
            << '\n';
}

QJsonArray forcesJson(const std::vector<BallEndForceSample> &samples)
{
    QJsonArray list;
    for (const BallEndForceSample &s : samples)
        list.append(QJsonObject{
            {QStringLiteral("rotation_deg"), s.rotation_rad / kDegree},
            {QStringLiteral("workpiece_N"), vectorJson(s.workpieceFrame_N, QStringLiteral("feed"),
                                                       QStringLiteral("cross_feed"), QStringLiteral("normal"))},
            {QStringLiteral("tool_N"),
             vectorJson(s.toolFrame_N, QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z"))},
            {QStringLiteral("torque_N_mm"), s.torque_N_mm}});
    return list;
}

// Parses a mill-* command's options (--json and --csv exclusive); -1 to go on, or the exit code.
int parseMilling(QCommandLineParser &parser, const MillingOptions &o, const QString &command, const QStringList &args,
                 QTextStream &out, QTextStream &err)
{
    if (const int stop = parseNamedCommand(parser, command, args, out, err); stop >= 0)
        return stop;
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1 || (files.size() == 1 && !parser.isSet(o.feature))) {
        complain(err, command,
                 MillingCommand::tr("takes a project file only with --feature ID: \"%1\"").arg(files.join(u' ')));
        return kExitUsage;
    }
    if (files.isEmpty() && parser.isSet(o.feature)) {
        complain(err, command, MillingCommand::tr("--feature needs the project file PROJECT it is in"));
        return kExitUsage;
    }
    if (parser.isSet(o.json) && parser.isSet(o.csv)) {
        complain(err, command, MillingCommand::tr("give --json or --csv, not both"));
        return kExitUsage;
    }
    return -1;
}

void printDeflectionCsv(const BallEndDeflection &d, QTextStream &out)
{
    out << csvLine({QStringLiteral("rotation_deg"), QStringLiteral("dx_um"), QStringLiteral("dy_um"),
                    QStringLiteral("dz_um"), QStringLiteral("d_feed_um"), QStringLiteral("d_cross_feed_um"),
                    QStringLiteral("d_normal_um")})
        << '\n';
    for (const BallEndDeflectionSample &s : d.deflection)
        out << csvLine({number(s.rotation_rad / kDegree, 3), number(1000.0 * s.toolFrame_mm.x(), 4),
                        number(1000.0 * s.toolFrame_mm.y(), 4), number(1000.0 * s.toolFrame_mm.z(), 4),
                        number(1000.0 * s.workpieceFrame_mm.x(), 4), number(1000.0 * s.workpieceFrame_mm.y(), 4),
                        number(1000.0 * s.workpieceFrame_mm.z(), 4)})
            << '\n';
}

struct OptimizeOptions {
    QCommandLineOption tolerance{QStringLiteral("tolerance"),
                                 MillingCommand::tr("The surface's flatness or profile tolerance t in mm."),
                                 QStringLiteral("MM")};
    QCommandLineOption located{QStringLiteral("located"),
                               MillingCommand::tr("A profile tolerance with datums: every normal error within ±t/2 "
                                                  "(default: a floating zone, the spread within t).")};
    QCommandLineOption highestFeed{QStringLiteral("max-feed-per-tooth"),
                                   MillingCommand::tr("The largest feed per tooth the tool's maker allows, in mm."),
                                   QStringLiteral("MM")};
    QCommandLineOption leadRange{QStringLiteral("lead-range"),
                                 MillingCommand::tr("Leads to search, LO,HI in degrees (default -40,40)."),
                                 QStringLiteral("LO,HI"), QStringLiteral("-40,40")};
    QCommandLineOption tiltRange{QStringLiteral("tilt-range"),
                                 MillingCommand::tr("Tilts to search, LO,HI in degrees (default -40,40)."),
                                 QStringLiteral("LO,HI"), QStringLiteral("-40,40")};
    QCommandLineOption cells{QStringLiteral("cells"),
                             MillingCommand::tr("Leads and tilts of the window, each (default 64)."),
                             QStringLiteral("N"), QStringLiteral("64")};
    QCommandLineOption threads{QStringLiteral("threads"), MillingCommand::tr("Threads (default 2)."),
                               QStringLiteral("N"), QStringLiteral("2")};
    QCommandLineOption save{QStringLiteral("save"),
                            MillingCommand::tr("With --feature: write the plan (lead, tilt, feed per tooth) into the "
                                               "feature's conditions in PROJECT.")};
};

// The tolerance: the feature's, or --tolerance and --located; nullopt after saying what is wrong.
std::optional<MilledSurfaceTolerance> readTolerance(const QCommandLineParser &parser, const OptimizeOptions &p,
                                                    const MillingInput &in, const QString &command, QTextStream &err)
{
    if (in.tolerance) {
        if (parser.isSet(p.tolerance) || parser.isSet(p.located)) {
            complain(err, command,
                     MillingCommand::tr("--tolerance, --located: the tolerance comes from the project's feature; "
                                        "change it there"));
            return std::nullopt;
        }
        return in.tolerance;
    }
    if (!parser.isSet(p.tolerance)) {
        complain(err, command, MillingCommand::tr("--tolerance is required: the surface's tolerance t in mm"));
        return std::nullopt;
    }
    const std::optional<double> t = numberInRange(parser, p.tolerance, 0.0001, 10.0, command, err);
    if (!t)
        return std::nullopt;
    return MilledSurfaceTolerance{*t, parser.isSet(p.located) ? SurfaceZone::Located : SurfaceZone::Floating};
}

// Writes a feasible plan into the feature's conditions in its project file (atomically).
int savePlan(const MillingInput &in, const MilledFeaturePlan &planned, const QString &command, QTextStream &out,
             QTextStream &err)
{
    if (!planned.plan.feasible) {
        complain(err, command,
                 MillingCommand::tr("--save: no plan holds the tolerance; %1 is left as it was").arg(in.projectFile));
        return kExitProblems;
    }
    std::optional<Project> project = readProject(in.projectFile, err);
    if (!project)
        return kExitProblems;
    for (MilledFeature &f : project->milledFeatures) {
        if (f.id != in.feature->id || !f.conditions)
            continue;
        if (planned.leadTiltPlanned) {
            f.conditions->lead_deg = planned.plan.cut.lead_rad / kDegree;
            f.conditions->tilt_deg = planned.plan.cut.tilt_rad / kDegree;
        }
        // Down to the 0.0001 mm a program gives, so that the saved feed holds as it is evaluated.
        f.conditions->feedPerTooth_mm = std::floor(planned.plan.cut.feedPerTooth_mm * 1e4) / 1e4;
    }
    const WriteResult written = writeProjectFile(in.projectFile, *project);
    if (!written.ok) {
        complain(err, command, written.error);
        return kExitProblems;
    }
    out << MillingCommand::tr("The plan is saved in %1, feature %2 (the feed per tooth rounded down to 0.0001 mm).")
               .arg(in.projectFile, in.feature->id)
        << '\n';
    return kExitOk;
}

// "LO,HI" in degrees within ±60° with LO < HI, into `lo` and `hi` in radians.
bool readAngleRange(const QCommandLineParser &parser, const QCommandLineOption &option, double &lo, double &hi,
                    const QString &command, QTextStream &err)
{
    const QStringList parts = parser.value(option).split(QLatin1Char(','));
    bool okLo = parts.size() == 2;
    bool okHi = okLo;
    if (okLo) {
        lo = parts.at(0).trimmed().toDouble(&okLo) * kDegree;
        hi = parts.at(1).trimmed().toDouble(&okHi) * kDegree;
    }
    if (okLo && okHi && lo >= -60.0 * kDegree && hi <= 60.0 * kDegree && lo < hi)
        return true;
    complain(err, command,
             MillingCommand::tr("--%1: \"%2\" is not LO,HI in degrees with -60 <= LO < HI <= 60")
                 .arg(option.names().constFirst(), parser.value(option)));
    return false;
}

std::optional<BallEndPlanSettings> readPlanSettings(const QCommandLineParser &parser, const OptimizeOptions &p,
                                                    const QString &command, QTextStream &err)
{
    BallEndPlanSettings settings;
    bool ok = readAngleRange(parser, p.leadRange, settings.leadLowest_rad, settings.leadHighest_rad, command, err);
    ok = readAngleRange(parser, p.tiltRange, settings.tiltLowest_rad, settings.tiltHighest_rad, command, err) && ok;
    const std::optional<long long> cells = wholeNumberInRange(parser, p.cells, 2, 512, command, err);
    const std::optional<long long> threads = wholeNumberInRange(parser, p.threads, 1, 64, command, err);
    if (!parser.isSet(p.highestFeed)) {
        complain(err, command,
                 MillingCommand::tr("--max-feed-per-tooth is required: the largest feed per tooth the tool's maker "
                                    "allows (TolTurn's data library has no ball-end mills)"));
        return std::nullopt;
    }
    const std::optional<double> highest = numberInRange(parser, p.highestFeed, 0.001, 2.0, command, err);
    if (!ok || !cells || !threads || !highest)
        return std::nullopt;
    settings.columns = settings.rows = static_cast<int>(*cells);
    settings.threads = static_cast<int>(*threads);
    settings.highestFeedPerTooth_mm = *highest;
    return settings;
}

QJsonArray windowJson(const LeadTiltWindow &w)
{
    QJsonArray cells;
    for (const LeadTiltCell &c : w.cells)
        cells.append(QJsonObject{{QStringLiteral("lead_deg"), c.lead_rad / kDegree},
                                 {QStringLiteral("tilt_deg"), c.tilt_rad / kDegree},
                                 {QStringLiteral("on_ball"), c.onBall},
                                 {QStringLiteral("largest_feed_per_tooth_mm"), c.largestFeed_mm},
                                 {QStringLiteral("form_error_um"), 1000.0 * c.formError_mm}});
    return cells;
}

void printWindowCsv(const LeadTiltWindow &w, QTextStream &out)
{
    out << csvLine({QStringLiteral("lead_deg"), QStringLiteral("tilt_deg"), QStringLiteral("on_ball"),
                    QStringLiteral("largest_feed_per_tooth_mm"), QStringLiteral("form_error_um")})
        << '\n';
    for (const LeadTiltCell &c : w.cells)
        out << csvLine({number(c.lead_rad / kDegree, 3), number(c.tilt_rad / kDegree, 3),
                        c.onBall ? QStringLiteral("1") : QStringLiteral("0"), number(c.largestFeed_mm, 5),
                        number(1000.0 * c.formError_mm, 4)})
            << '\n';
}

// A patch's plan: its path gives the tool axes, so only the feed is planned.
void printPathPlan(const BallEndPlan &plan, QTextStream &out)
{
    if (!plan.feasible) {
        out << MillingCommand::tr("No feed holds the tolerance along the path: the edge forces alone deflect the tool "
                                  "too far at its tool axes.")
            << '\n';
        return;
    }
    out << MillingCommand::tr("Plan along the path's own tool axes: feed %1 mm/tooth (%2 mm/min); form error %3 µm")
               .arg(plan.cut.feedPerTooth_mm, 0, 'f', 4)
               .arg(plan.feedRate_mm_min, 0, 'f', 1)
               .arg(1000.0 * plan.formError_mm, 0, 'f', 2)
        << '\n';
}

void printPlan(const MilledFeaturePlan &planned, const MilledSurfaceTolerance &tolerance, double highestFeed,
               QTextStream &out)
{
    const BallEndPlan &plan = planned.plan;
    int onBall = 0;
    int holding = 0;
    for (const LeadTiltCell &c : plan.window.cells) {
        onBall += c.onBall ? 1 : 0;
        holding += c.onBall && c.largestFeed_mm > 0.0 ? 1 : 0;
    }
    out << MillingCommand::tr("Tolerance %1 µm, %2; feed per tooth up to %3 mm")
               .arg(1000.0 * tolerance.tolerance_mm)
               .arg(tolerance.zone == SurfaceZone::Floating
                        ? MillingCommand::tr("floating zone (flatness, or profile without datums): spread of the "
                                             "normal error")
                        : MillingCommand::tr("located zone (profile with datums): normal error within ±t/2"))
               .arg(highestFeed)
        << '\n';
    if (!planned.leadTiltPlanned) {
        printPathPlan(plan, out);
        return;
    }
    out << MillingCommand::tr("Window %1 × %2: %3 cells with the cut on the ball, %4 of them hold the tolerance")
               .arg(plan.window.columns)
               .arg(plan.window.rows)
               .arg(onBall)
               .arg(holding)
        << '\n';
    if (!plan.feasible) {
        out << MillingCommand::tr("No lead and tilt in the bounds holds the tolerance at any feed: the edge forces "
                                  "alone deflect the tool too far, or the cut does not stay on the ball.")
            << '\n';
        return;
    }
    out << MillingCommand::tr("Plan: lead %1°, tilt %2°, feed %3 mm/tooth (%4 mm/min); form error %5 µm "
                              "(%6 NLopt Subplex evaluations after the window)")
               .arg(plan.cut.lead_rad / kDegree, 0, 'f', 2)
               .arg(plan.cut.tilt_rad / kDegree, 0, 'f', 2)
               .arg(plan.cut.feedPerTooth_mm, 0, 'f', 4)
               .arg(plan.feedRate_mm_min, 0, 'f', 1)
               .arg(1000.0 * plan.formError_mm, 0, 'f', 2)
               .arg(plan.evaluations)
        << '\n';
}

} // namespace

QString millForcesSynopsis()
{
    return QStringLiteral("mill-forces [PROJECT --feature ID [--point N]] [--case N] [--diameter MM --flutes N "
                          "--axial-depth MM --feed-per-tooth MM "
                          "--spindle-speed RPM] [--helix DEG] [--lead DEG] [--tilt DEG] [--radial-depth MM|--step-over "
                          "MM] [--up] --coefficients K [--slices N] [--angles N] [--json|--csv]");
}

QString millForcesSummary()
{
    return MillingCommand::tr("Five-axis ball-end milling forces over a revolution (Öztürk & Budak): on the tool in "
                              "feed, cross-feed and normal directions, torque and spindle power.");
}

int runMillForces(const QStringList &args, QTextStream &out, QTextStream &err)
{
    const QString command = QStringLiteral("mill-forces");
    QCommandLineParser parser;
    const MillingOptions o;
    parser.addOptions(o.all());
    if (const int stop = parseMilling(parser, o, command, args, out, err); stop >= 0)
        return stop;
    const std::optional<MillingInput> in = readMillingInput(parser, o, command, err);
    if (!in)
        return kExitUsage;
    const std::vector<BallEndForceSample> samples = ballEndForces(in->mill, in->coefficients, in->cut, in->resolution);
    const BallEndForceSummary summary = summarise(samples);
    if (parser.isSet(o.json)) {
        QJsonObject result = summaryJson(*in, summary);
        result.insert(QStringLiteral("samples"), forcesJson(samples));
        return printJson(result, out, err, command);
    }
    if (parser.isSet(o.csv)) {
        printForcesCsv(samples, out);
        return kExitOk;
    }
    printSetup(*in, out);
    printSummary(*in, summary, out);
    return kExitOk;
}

QString millDeflectSynopsis()
{
    return QStringLiteral("mill-deflect [mill-forces options] [PROJECT --feature ID [--point N]] --overhang MM "
                          "--equivalent-diameter MM [--modulus E] "
                          "[--holder K,KTHETA] [--json|--csv]");
}

QString millDeflectSummary()
{
    return MillingCommand::tr("The ball-end mill's deflection over a revolution and the surface error along the "
                              "normal it leaves (Öztürk & Budak table 3): the tool a cantilever on springs k, k_θ.");
}

int runMillDeflect(const QStringList &args, QTextStream &out, QTextStream &err)
{
    const QString command = QStringLiteral("mill-deflect");
    QCommandLineParser parser;
    const MillingOptions o;
    const DeflectOptions d;
    parser.addOptions(o.all());
    parser.addOptions({d.overhang, d.equivalentDiameter, d.modulus, d.holder});
    if (const int stop = parseMilling(parser, o, command, args, out, err); stop >= 0)
        return stop;
    const std::optional<MillingInput> in = readMillingInput(parser, o, command, err);
    if (!in)
        return kExitUsage;
    const std::optional<BallEndToolStructure> tool = readStructure(parser, d, *in, command, err);
    if (!tool)
        return kExitUsage;
    const BallEndDeflection result = ballEndDeflection(in->mill, *tool, in->coefficients, in->cut, in->resolution);
    const double generating = surfaceGenerationHeight_mm(in->mill, in->cut);
    for (const QString &w : ballEndValidityWarnings(in->mill, *tool, in->cut, result))
        err << programName() << ' ' << command << ": " << MillingCommand::tr("warning: %1").arg(w) << '\n';
    if (parser.isSet(o.json)) {
        QJsonObject json = summaryJson(*in, summarise(result.forces));
        json.insert(QStringLiteral("surface_normal_error_um"),
                    QJsonObject{{QStringLiteral("least"), 1000.0 * result.leastSurfaceNormal_mm},
                                {QStringLiteral("greatest"), 1000.0 * result.greatestSurfaceNormal_mm}});
        json.insert(QStringLiteral("generating_point_height_mm"), generating);
        QJsonArray samples;
        for (const BallEndDeflectionSample &s : result.deflection)
            samples.append(
                QJsonObject{{QStringLiteral("rotation_deg"), s.rotation_rad / kDegree},
                            {QStringLiteral("tool_um"), vectorJson(1000.0 * s.toolFrame_mm, QStringLiteral("x"),
                                                                   QStringLiteral("y"), QStringLiteral("z"))},
                            {QStringLiteral("normal_um"), 1000.0 * s.surfaceNormal_mm()}});
        json.insert(QStringLiteral("samples"), samples);
        return printJson(json, out, err, command);
    }
    if (parser.isSet(o.csv)) {
        printDeflectionCsv(result, out);
        return kExitOk;
    }
    printSetup(*in, out);
    printSummary(*in, summarise(result.forces), out);
    out << MillingCommand::tr("Tool: overhang %1 mm, a Ø%2 mm cylinder of E = %3 N/mm², holder k = %4 N/mm, k_θ = %5 "
                              "N·mm/rad%6")
               .arg(tool->overhang_mm)
               .arg(tool->equivalentDiameter_mm)
               .arg(tool->youngsModulus_N_mm2)
               .arg(tool->holderStiffness_N_mm)
               .arg(tool->holderRotational_N_mm_rad)
               .arg(parser.isSet(d.holder) ? QString() : MillingCommand::tr(" (001's calibration for its tool)"))
        << '\n'
        << MillingCommand::tr("Surface error along the normal, over a revolution: %1 to %2 µm (positive: material "
                              "left); generating point %3 mm up the axis. Only the tool deflects in this model.")
               .arg(1000.0 * result.leastSurfaceNormal_mm, 0, 'f', 2)
               .arg(1000.0 * result.greatestSurfaceNormal_mm, 0, 'f', 2)
               .arg(generating, 0, 'f', 3)
        << '\n';
    return kExitOk;
}

QString millOptimizeSynopsis()
{
    return QStringLiteral("mill-optimize [PROJECT --feature ID [--save]] [mill-forces options] [mill-deflect options] "
                          "--tolerance MM [--located] "
                          "--max-feed-per-tooth MM [--lead-range LO,HI] [--tilt-range LO,HI] [--cells N] "
                          "[--threads N] [--json|--csv]");
}

QString millOptimizeSummary()
{
    return MillingCommand::tr("The lead, tilt and feed per tooth of least machining time that keep the ball-end "
                              "surface within its flatness or profile tolerance, with the lead–tilt window.");
}

int runMillOptimize(const QStringList &args, QTextStream &out, QTextStream &err)
{
    const QString command = QStringLiteral("mill-optimize");
    QCommandLineParser parser;
    const MillingOptions o;
    const DeflectOptions d;
    const OptimizeOptions p;
    parser.addOptions(o.all());
    parser.addOptions({d.overhang, d.equivalentDiameter, d.modulus, d.holder});
    parser.addOptions({p.tolerance, p.located, p.highestFeed, p.leadRange, p.tiltRange, p.cells, p.threads, p.save});
    if (const int stop = parseMilling(parser, o, command, args, out, err); stop >= 0)
        return stop;
    const std::optional<MillingInput> in = readMillingInput(parser, o, command, err, true);
    if (!in)
        return kExitUsage;
    const std::optional<BallEndToolStructure> tool = readStructure(parser, d, *in, command, err);
    std::optional<BallEndPlanSettings> settings = readPlanSettings(parser, p, command, err);
    if (!tool || !settings)
        return kExitUsage;
    settings->planResolution = in->resolution; // --slices and --angles: the plan's check
    const std::optional<MilledSurfaceTolerance> tolerance = readTolerance(parser, p, *in, command, err);
    if (!tolerance)
        return kExitUsage;
    if (parser.isSet(p.save) && !in->feature) {
        complain(err, command, MillingCommand::tr("--save needs PROJECT --feature ID"));
        return kExitUsage;
    }
    if (parser.isSet(p.save) && (parser.isSet(o.slices) || parser.isSet(o.angles))) {
        complain(err, command,
                 MillingCommand::tr("--save plans at evaluate's resolution (200 slices, 360 angles): leave out "
                                    "--slices and --angles"));
        return kExitUsage;
    }
    MilledFeaturePlan planned;
    if (in->feature) {
        planned = planMilledFeature(*in->feature, *settings);
    } else {
        planned.leadTiltPlanned = true;
        planned.plan =
            planBallEndCut(in->mill, *tool, in->coefficients, in->cut, in->spindle_rpm, *tolerance, *settings);
    }
    const BallEndPlan &plan = planned.plan;
    for (const QString &w : plan.warnings)
        err << programName() << ' ' << command << ": " << MillingCommand::tr("warning: %1").arg(w) << '\n';
    if (parser.isSet(o.json)) {
        QJsonObject json{{QStringLiteral("feasible"), plan.feasible},
                         {QStringLiteral("lead_deg"), plan.cut.lead_rad / kDegree},
                         {QStringLiteral("tilt_deg"), plan.cut.tilt_rad / kDegree},
                         {QStringLiteral("feed_per_tooth_mm"), plan.cut.feedPerTooth_mm},
                         {QStringLiteral("feed_rate_mm_min"), plan.feedRate_mm_min},
                         {QStringLiteral("form_error_um"), 1000.0 * plan.formError_mm},
                         {QStringLiteral("lead_tilt_planned"), planned.leadTiltPlanned},
                         {QStringLiteral("tolerance_um"), 1000.0 * tolerance->tolerance_mm},
                         {QStringLiteral("zone"), tolerance->zone == SurfaceZone::Floating ? QStringLiteral("floating")
                                                                                           : QStringLiteral("located")},
                         {QStringLiteral("evaluations"), plan.evaluations},
                         {QStringLiteral("window"), windowJson(plan.window)}};
        const int printed = printJson(json, out, err, command);
        return parser.isSet(p.save) && printed == kExitOk ? savePlan(*in, planned, command, err, err) : printed;
    }
    if (parser.isSet(o.csv)) {
        printWindowCsv(plan.window, out);
        return parser.isSet(p.save) ? savePlan(*in, planned, command, err, err) : kExitOk;
    }
    printSetup(*in, out);
    printPlan(planned, *tolerance, settings->highestFeedPerTooth_mm, out);
    return parser.isSet(p.save) ? savePlan(*in, planned, command, out, err) : kExitOk;
}

} // namespace tolturn
