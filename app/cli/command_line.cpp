// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/command_line.h"

#include "app/cli/cli_common.h"
#include "app/cli/gcode_command.h"
#include "app/cli/import_command.h"
#include "app/cli/stiffness_command.h"
#include "core/common/library_info.h"
#include "core/deviation/deviation_model.h"
#include "core/io/force_measurements.h"
#include "core/io/project_file.h"
#include "core/planning/clamping_advisor.h"
#include "core/planning/cutting_window.h"
#include "core/planning/optimiser.h"
#include "core/planning/plausibility.h"
#include "core/project/keywords.h"
#include "core/tolerance/evaluation.h"
#include "core/tolerance/iso286.h"
#include "core/tolerance/range_verdicts.h"
#include "widgets/dialogs/about_dialog.h"
#include "widgets/report/report_writer.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace tolturn {

namespace {

struct CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};

using Handler = std::function<int(const QStringList &, QTextStream &, QTextStream &)>;

struct Command {
    QString name;
    QString synopsis;
    QString summary;
    Handler run;
};

const std::vector<Command> &commands();

// The command called `name` (for its synopsis and summary in --help).
const Command &commandNamed(const QString &name)
{
    const std::vector<Command> &list = commands();
    return *std::find_if(list.begin(), list.end(), [&name](const Command &c) { return c.name == name; });
}

QString usage()
{
    QString text = CommandLine::tr("Usage: %1 [--help] [--version] COMMAND [ARGUMENTS]\n\n"
                                   "TolTurn's command-line front end: the same computations as the desktop program, "
                                   "headless, for batch use and regression tests.\n\nCommands:\n")
                       .arg(programName());
    for (const Command &c : commands())
        text += QStringLiteral("  %1\n      %2\n").arg(c.synopsis, c.summary);
    text += CommandLine::tr("\nRun '%1 COMMAND --help' for the options of a command.\n"
                            "Exit codes: 0 success, 1 the input has errors, 2 wrong command line.\n")
                .arg(programName());
    return text;
}

QString versionText()
{
    QString text = QStringLiteral("tolturn-cli %1\n").arg(tolturnVersion());
    for (const LibraryInfo &lib : applicationLibraries())
        text += QStringLiteral("  %1 %2 (%3)\n").arg(lib.name, lib.version, lib.licence);
    return text;
}

// Parses the options of one command; handles --help. Returns -1 to go on, or an exit code when
// the command must stop here.
int parseCommand(QCommandLineParser &parser, const Command &command, const QStringList &args, QTextStream &out,
                 QTextStream &err)
{
    return tolturn::parseCommand(parser, command.name, command.synopsis, command.summary, args, out, err);
}

// The project file of a command that takes exactly one; empty after printing the usage error.
QString oneProjectFile(const QCommandLineParser &parser, const QString &command, QTextStream &err)
{
    if (parser.positionalArguments().size() == 1)
        return parser.positionalArguments().constFirst();
    err << programName() << ' ' << command << ": " << CommandLine::tr("give exactly one project file") << '\n';
    return {};
}

QString projectSummary(const Project &p)
{
    return CommandLine::tr("part \"%1\", %2 mm long, %3 outer and %4 inner features, %5, %6 passes, %7 tolerances")
        .arg(p.part.name)
        .arg(p.part.length_mm())
        .arg(p.part.outer.segments.size())
        .arg(p.part.inner.segments.size())
        .arg(keyword(p.clamping.method))
        .arg(p.passes.size())
        .arg(p.tolerances.size());
}

int runCheck(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"),
                                  CommandLine::tr("Print the findings as JSON on standard output."));
    parser.addOption(json);
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project files to check."),
                                 QStringLiteral("PROJECT..."));
    if (const int stop = parseCommand(parser, commandNamed(QStringLiteral("check")), args, out, err); stop >= 0)
        return stop;
    const QStringList files = parser.positionalArguments();
    if (files.isEmpty()) {
        err << programName() << " check: " << CommandLine::tr("no project file given") << '\n';
        return kExitUsage;
    }
    bool anyErrors = false;
    QJsonArray reports;
    for (const QString &file : files) {
        ProjectParseResult result = readProjectFile(file);
        if (result.project) {
            // What the project asks of the data library and the machine (docs/planning.md).
            const Diagnostics plausibility = checkPlausibility(*result.project, DataLibrary::builtIn());
            result.diagnostics.insert(result.diagnostics.end(), plausibility.begin(), plausibility.end());
        }
        const bool valid = result.project.has_value() && !hasErrors(result.diagnostics);
        anyErrors = anyErrors || !valid;
        if (parser.isSet(json)) {
            QJsonArray list;
            for (const Diagnostic &d : result.diagnostics)
                list.append(diagnosticJson(d));
            reports.append(QJsonObject{{QStringLiteral("file"), file},
                                       {QStringLiteral("valid"), valid},
                                       {QStringLiteral("diagnostics"), list}});
            continue;
        }
        for (const Diagnostic &d : result.diagnostics)
            err << file << ": " << d.toString() << '\n';
        if (valid)
            out << file << ": " << CommandLine::tr("ok") << " — " << projectSummary(*result.project) << '\n';
    }
    if (parser.isSet(json))
        out << QJsonDocument(reports).toJson(QJsonDocument::Indented);
    return anyErrors ? kExitProblems : kExitOk;
}

// ---- deflect --------------------------------------------------------------------------------

constexpr double kUmPerMm = 1000.0;

QJsonObject contributionsJson(const Contributions &c, bool radial)
{
    QJsonObject o{{QStringLiteral("total"), c.total_mm() * kUmPerMm},
                  {QStringLiteral("spindle_chuck"), c.spindleChuck_mm * kUmPerMm},
                  {QStringLiteral("workpiece"), c.workpiece_mm * kUmPerMm}};
    if (radial) {
        o.insert(QStringLiteral("toolpost"), c.toolpost_mm * kUmPerMm);
        o.insert(QStringLiteral("thermal"), c.thermal_mm * kUmPerMm);
    }
    return o;
}

QJsonObject stationJson(const Station &st)
{
    return {{QStringLiteral("z_mm"), st.z_mm},
            {QStringLiteral("nominal_diameter_mm"), 2.0 * st.nominalRadius_mm},
            {QStringLiteral("spindle_speed_rpm"), st.spindleSpeed_rpm},
            {QStringLiteral("radial_um"), contributionsJson(st.radial, true)},
            {QStringLiteral("tangential_um"), contributionsJson(st.tangential, false)},
            {QStringLiteral("radius_error_um"), st.radiusError_mm * kUmPerMm},
            {QStringLiteral("diameter_error_um"), 2.0 * st.radiusError_mm * kUmPerMm},
            {QStringLiteral("section_rotation_urad"), st.sectionRotation_rad * 1e6}};
}

QJsonObject deviationJson(const QString &file, const Project &project, const DeviationResult &r)
{
    const TurningInputs &in = *r.inputs;
    QJsonArray features;
    for (const FeatureDeviation &f : r.features) {
        QJsonArray stations;
        for (const Station &st : f.stations)
            stations.append(stationJson(st));
        features.append(QJsonObject{{QStringLiteral("id"), f.featureId},
                                    {QStringLiteral("side"), contourName(f.side)},
                                    {QStringLiteral("type"), keyword(f.kind)},
                                    {QStringLiteral("stations"), stations}});
    }
    QJsonArray faces;
    for (const FaceConicity &f : r.faces)
        faces.append(QJsonObject{{QStringLiteral("id"), f.featureId},
                                 {QStringLiteral("side"), contourName(f.side)},
                                 {QStringLiteral("z_mm"), f.z_mm},
                                 {QStringLiteral("tan_theta"), f.tanTheta},
                                 {QStringLiteral("axial_runout_um"), f.axialRunout_mm * kUmPerMm}});
    QJsonArray warnings;
    for (const Diagnostic &d : r.diagnostics)
        warnings.append(diagnosticJson(d));
    return {{QStringLiteral("file"), file},
            {QStringLiteral("material"), project.materialId},
            {QStringLiteral("clamping"), keyword(project.clamping.method)},
            {QStringLiteral("force_model"), in.forceModel},
            {QStringLiteral("pass"), QJsonObject{{QStringLiteral("index"), in.passIndex},
                                                 {QStringLiteral("kind"), keyword(in.pass.kind)},
                                                 {QStringLiteral("cutting_speed_m_min"), in.pass.cuttingSpeed_m_min},
                                                 {QStringLiteral("feed_mm_rev"), in.pass.feed_mm_rev},
                                                 {QStringLiteral("depth_of_cut_mm"), in.pass.depthOfCut_mm}}},
            {QStringLiteral("forces_N"), QJsonObject{{QStringLiteral("tangential"), in.forces.tangential_N},
                                                     {QStringLiteral("axial"), in.forces.axial_N},
                                                     {QStringLiteral("radial"), in.forces.radial_N}}},
            {QStringLiteral("max_power_kW"), r.maxPower_kW},
            {QStringLiteral("max_torque_Nm"), r.maxTorque_Nm},
            {QStringLiteral("theoretical_Ra_um"), r.theoreticalRa_um},
            {QStringLiteral("theoretical_Rz_um"), r.theoreticalRz_um},
            {QStringLiteral("notes"), QJsonArray::fromStringList(in.notes)},
            {QStringLiteral("warnings"), warnings},
            {QStringLiteral("features"), features},
            {QStringLiteral("faces"), faces}};
}

void printDeviationText(QTextStream &out, const DeviationResult &r)
{
    const TurningInputs &in = *r.inputs;
    out << CommandLine::tr("Forces (%1): Fc = %2 N tangential, Ff = %3 N axial, Fp = %4 N radial")
               .arg(forceModelName(in.forceModel), QString::number(in.forces.tangential_N, 'f', 1),
                    QString::number(in.forces.axial_N, 'f', 1), QString::number(in.forces.radial_N, 'f', 1))
        << '\n';
    out << CommandLine::tr("Pass %1 (%2): vc %3 m/min, f %4 mm/rev, ap %5 mm; Ra %6 µm, Rz %7 µm; max %8 kW, %9 N·m")
               .arg(in.passIndex + 1)
               .arg(keyword(in.pass.kind), formatNumber(in.pass.cuttingSpeed_m_min), formatNumber(in.pass.feed_mm_rev),
                    formatNumber(in.pass.depthOfCut_mm), QString::number(r.theoreticalRa_um, 'f', 2),
                    QString::number(r.theoreticalRz_um, 'f', 2), QString::number(r.maxPower_kW, 'f', 2),
                    QString::number(r.maxTorque_Nm, 'f', 1))
        << '\n';
    for (const QString &note : in.notes)
        out << CommandLine::tr("note: ") << note << '\n';
    out << CommandLine::tr(
               "feature  side   z from–to [mm]    radial deviation [µm] min … max   diameter error [µm] min … max")
        << '\n';
    for (const FeatureDeviation &f : r.features) {
        double rMin = 1e300, rMax = -1e300, dMin = 1e300, dMax = -1e300;
        for (const Station &st : f.stations) {
            rMin = std::min(rMin, st.radial.total_mm());
            rMax = std::max(rMax, st.radial.total_mm());
            dMin = std::min(dMin, 2.0 * st.radiusError_mm);
            dMax = std::max(dMax, 2.0 * st.radiusError_mm);
        }
        out << QStringLiteral("%1 %2 %3–%4   %5 … %6   %7 … %8")
                   .arg(f.featureId, -8)
                   .arg(contourName(f.side), -6)
                   .arg(f.stations.front().z_mm, 7, 'f', 1)
                   .arg(f.stations.back().z_mm, -7, 'f', 1)
                   .arg(rMin * kUmPerMm, 10, 'f', 2)
                   .arg(rMax * kUmPerMm, -10, 'f', 2)
                   .arg(dMin * kUmPerMm, 10, 'f', 2)
                   .arg(dMax * kUmPerMm, -10, 'f', 2)
            << '\n';
    }
    for (const FaceConicity &f : r.faces)
        out << CommandLine::tr("face %1 at z = %2 mm: tan(theta) = %3, axial run-out e = %4 µm")
                   .arg(f.featureId, formatNumber(f.z_mm), QString::number(f.tanTheta, 'g', 4),
                        QString::number(f.axialRunout_mm * kUmPerMm, 'f', 3))
            << '\n';
}

int runDeflect(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the result as JSON."));
    const QCommandLineOption load(
        QStringLiteral("load"),
        CommandLine::tr("Use these forces [N] instead of the force model: radial, tangential, axial."),
        QStringLiteral("Fr,Ft,Fa"));
    const QCommandLineOption workpieceOnly(
        QStringLiteral("workpiece-only"),
        CommandLine::tr("Rigid machine supports, no toolpost or thermal term: the beam alone."));
    const QCommandLineOption stations(QStringLiteral("stations"),
                                      CommandLine::tr("Tool positions per turned feature (default 21)."),
                                      QStringLiteral("N"), QStringLiteral("21"));
    const QCommandLineOption pass(QStringLiteral("pass"),
                                  CommandLine::tr("Index of the pass (default: the last finishing pass)."),
                                  QStringLiteral("N"));
    const QCommandLineOption noInProcess(QStringLiteral("no-in-process"),
                                         CommandLine::tr("Ignore the stock still on the uncut side of the tool."));
    parser.addOptions({json, load, workpieceOnly, stations, pass, noInProcess});
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseCommand(parser, commandNamed(QStringLiteral("deflect")), args, out, err); stop >= 0)
        return stop;
    const QString file = oneProjectFile(parser, QStringLiteral("deflect"), err);
    if (file.isEmpty())
        return kExitUsage;
    DeviationOptions options;
    options.workpieceOnly = parser.isSet(workpieceOnly);
    options.inProcessSection = !parser.isSet(noInProcess);
    bool ok = true;
    options.stationsPerFeature = parser.value(stations).toInt(&ok);
    if (!ok || options.stationsPerFeature < 2 || options.stationsPerFeature > 100000) {
        err << programName() << " deflect: "
            << CommandLine::tr("--stations must be a whole number from 2 to 100000, not \"%1\"")
                   .arg(parser.value(stations))
            << '\n';
        return kExitUsage;
    }
    if (parser.isSet(pass)) {
        options.passIndex = parser.value(pass).toInt(&ok);
        if (!ok || options.passIndex < 0) {
            err << programName() << " deflect: "
                << CommandLine::tr("--pass must be a pass index (0, 1, …), not \"%1\"").arg(parser.value(pass)) << '\n';
            return kExitUsage;
        }
    }
    if (parser.isSet(load)) {
        options.loadOverride = parseLoad(parser.value(load));
        if (!options.loadOverride) {
            err << programName() << " deflect: "
                << CommandLine::tr(
                       "--load takes three numbers in newtons, radial,tangential,axial (e.g. 200,500,150), not \"%1\"")
                       .arg(parser.value(load))
                << '\n';
            return kExitUsage;
        }
    }
    const std::optional<Project> project = readProject(file, err);
    if (!project)
        return kExitProblems;
    const DeviationResult result = computeDeviation(*project, DataLibrary::builtIn(), options);
    for (const Diagnostic &d : result.diagnostics)
        err << file << ": " << d.toString() << '\n';
    if (!result.inputs)
        return kExitProblems;
    if (parser.isSet(json))
        out << QJsonDocument(deviationJson(file, *project, result)).toJson(QJsonDocument::Indented);
    else
        printDeviationText(out, result);
    return kExitOk;
}

// ---- calibrate-forces -----------------------------------------------------------------------

void printCalibration(QTextStream &out, const LiDuCalibration &cal, const LiDuToolGeometry &tool,
                      const std::vector<ForceMeasurement> &cuts)
{
    out << CommandLine::tr("K_n = %1 N/mm², K_f = %2 (Li & Du eq. 15), RMS residual %3 N over %4 cuts")
               .arg(QString::number(cal.coefficients->normalPressure_MPa, 'f', 1),
                    QString::number(cal.coefficients->frictionRatio, 'f', 4),
                    QString::number(cal.rmsResidual_N, 'f', 2))
               .arg(cuts.size())
        << '\n';
    out << CommandLine::tr("   f [mm/rev]  d [mm]   Ft meas   Ft model   Fa meas   Fa model   Fr model [N]") << '\n';
    for (const ForceMeasurement &m : cuts) {
        const CuttingForces f = liDuForces(*cal.coefficients, tool, m.feed_mm_rev, m.depthOfCut_mm).forces;
        out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7")
                   .arg(m.feed_mm_rev, 12, 'f', 3)
                   .arg(m.depthOfCut_mm, 7, 'f', 2)
                   .arg(m.tangential_N, 9, 'f', 1)
                   .arg(f.tangential_N, 10, 'f', 1)
                   .arg(m.axial_N, 9, 'f', 1)
                   .arg(f.axial_N, 10, 'f', 1)
                   .arg(f.radial_N, 10, 'f', 1)
            << '\n';
    }
}

int runCalibrateForces(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the result as JSON."));
    const QCommandLineOption write(
        QStringLiteral("write"), CommandLine::tr("Store K_n and K_f in the project (force model li_du) and save it."));
    parser.addOptions({json, write});
    parser.addPositionalArgument(QStringLiteral("project"),
                                 CommandLine::tr("Project file (its tool gives the geometry)."),
                                 QStringLiteral("PROJECT"));
    parser.addPositionalArgument(
        QStringLiteral("measurements"),
        CommandLine::tr("CSV of measured cuts: feed_mm_rev,depth_of_cut_mm,tangential_N,axial_N."),
        QStringLiteral("MEASUREMENTS.csv"));
    if (const int stop = parseCommand(parser, commandNamed(QStringLiteral("calibrate-forces")), args, out, err);
        stop >= 0)
        return stop;
    if (parser.positionalArguments().size() != 2) {
        err << programName() << " calibrate-forces: " << CommandLine::tr("give a project file and a measurements file")
            << '\n';
        return kExitUsage;
    }
    const QString projectPath = parser.positionalArguments().at(0);
    const QString csvPath = parser.positionalArguments().at(1);
    ProjectParseResult read = readProjectFile(projectPath);
    MeasurementsReadResult cuts = readForceMeasurements(csvPath);
    Diagnostics problems = read.diagnostics;
    problems.insert(problems.end(), cuts.diagnostics.begin(), cuts.diagnostics.end());
    std::optional<LiDuToolGeometry> tool;
    if (read.project)
        tool = resolveLiDuToolGeometry(*read.project, DataLibrary::builtIn(), problems);
    LiDuCalibration cal;
    if (tool && cuts.measurements) {
        cal = calibrateLiDu(*tool, *cuts.measurements);
        problems.insert(problems.end(), cal.diagnostics.begin(), cal.diagnostics.end());
        for (const ForceMeasurement &m : *cuts.measurements)
            (void)liDuEffectiveLeadAngle_rad(*tool, m.feed_mm_rev, m.depthOfCut_mm, &problems);
    }
    QStringList printed;
    for (const Diagnostic &d : problems) {
        if (!printed.contains(d.toString()))
            err << d.toString() << '\n';
        printed << d.toString();
    }
    if (!cal.coefficients)
        return kExitProblems;
    if (parser.isSet(json)) {
        out << QJsonDocument(QJsonObject{{QStringLiteral("normal_pressure_MPa"), cal.coefficients->normalPressure_MPa},
                                         {QStringLiteral("friction_ratio"), cal.coefficients->frictionRatio},
                                         {QStringLiteral("rms_residual_N"), cal.rmsResidual_N},
                                         {QStringLiteral("cuts"), static_cast<int>(cuts.measurements->size())}})
                   .toJson(QJsonDocument::Indented);
    } else {
        printCalibration(out, cal, *tool, *cuts.measurements);
    }
    if (parser.isSet(write)) {
        read.project->cuttingModel.forceModel = ForceModel::LiDu;
        read.project->cuttingModel.normalPressure_MPa = cal.coefficients->normalPressure_MPa;
        read.project->cuttingModel.frictionRatio = cal.coefficients->frictionRatio;
        const WriteResult w = writeProjectFile(projectPath, *read.project);
        if (!w.ok) {
            err << w.error << '\n';
            return kExitProblems;
        }
        err << CommandLine::tr("wrote %1: force model li_du").arg(projectPath) << '\n';
    }
    return kExitOk;
}

// ---- iso286, fit, evaluate ------------------------------------------------------------------

QJsonObject classLimitsJson(const iso286::ClassLimits &l)
{
    return {{QStringLiteral("nominal_mm"), l.nominal_mm},
            {QStringLiteral("class"), l.toleranceClass},
            {QStringLiteral("upper_um"), l.upper_um},
            {QStringLiteral("lower_um"), l.lower_um},
            {QStringLiteral("it_grade"), l.itName},
            {QStringLiteral("it_um"), l.it_um},
            {QStringLiteral("fundamental_um"), l.fundamental_um}};
}

QString signedUm(double v)
{
    return (v > 0.0 ? QStringLiteral("+") : QString()) + formatNumber(v);
}

void printDiagnostics(QTextStream &err, const Diagnostics &diagnostics)
{
    for (const Diagnostic &d : diagnostics)
        err << d.toString() << '\n';
}

// A nominal size argument: a number in mm, else a usage error naming it.
std::optional<double> nominalArgument(const QString &text, const QString &command, QTextStream &err)
{
    bool ok = false;
    const double v = QString(text).replace(QLatin1Char(','), QLatin1Char('.')).toDouble(&ok);
    if (!ok || !std::isfinite(v)) {
        err << programName() << ' ' << command << ": "
            << CommandLine::tr("the nominal size must be a number in mm, not \"%1\"").arg(text) << '\n';
        return std::nullopt;
    }
    return v;
}

int runIso286(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the limits as JSON."));
    parser.addOption(json);
    parser.addPositionalArgument(QStringLiteral("nominal"), CommandLine::tr("Nominal size [mm]."),
                                 QStringLiteral("NOMINAL"));
    parser.addPositionalArgument(QStringLiteral("class"), CommandLine::tr("Tolerance class, e.g. H7, g6, js12."),
                                 QStringLiteral("CLASS"));
    if (const int stop = parseCommand(parser, commandNamed(QStringLiteral("iso286")), args, out, err); stop >= 0)
        return stop;
    if (parser.positionalArguments().size() != 2) {
        err << programName() << " iso286: " << CommandLine::tr("give a nominal size and a tolerance class, e.g. 50 H7")
            << '\n';
        return kExitUsage;
    }
    const auto nominal = nominalArgument(parser.positionalArguments().at(0), QStringLiteral("iso286"), err);
    if (!nominal)
        return kExitUsage;
    const iso286::LimitsResult r = iso286::limits(*nominal, parser.positionalArguments().at(1));
    printDiagnostics(err, r.diagnostics);
    if (!r.limits)
        return kExitProblems;
    if (parser.isSet(json))
        out << QJsonDocument(classLimitsJson(*r.limits)).toJson(QJsonDocument::Indented);
    else
        out << CommandLine::tr("%1 %2: upper %3 µm, lower %4 µm (%5 = %6 µm)")
                   .arg(formatNumber(*nominal), r.limits->toleranceClass, signedUm(r.limits->upper_um),
                        signedUm(r.limits->lower_um), r.limits->itName, formatNumber(r.limits->it_um))
            << '\n';
    return kExitOk;
}

int runFit(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the fit as JSON."));
    parser.addOption(json);
    parser.addPositionalArgument(QStringLiteral("nominal"), CommandLine::tr("Nominal size [mm]."),
                                 QStringLiteral("NOMINAL"));
    parser.addPositionalArgument(QStringLiteral("fit"), CommandLine::tr("Hole and shaft class, e.g. H7/g6."),
                                 QStringLiteral("HOLE/SHAFT"));
    if (const int stop = parseCommand(parser, commandNamed(QStringLiteral("fit")), args, out, err); stop >= 0)
        return stop;
    const QStringList positional = parser.positionalArguments();
    const QStringList classes = positional.value(1).split(QLatin1Char('/'));
    if (positional.size() != 2 || classes.size() != 2) {
        err << programName() << " fit: " << CommandLine::tr("give a nominal size and a fit, e.g. 50 H7/g6") << '\n';
        return kExitUsage;
    }
    const auto nominal = nominalArgument(positional.at(0), QStringLiteral("fit"), err);
    if (!nominal)
        return kExitUsage;
    const iso286::FitResult r = iso286::fit(*nominal, classes.at(0).trimmed(), classes.at(1).trimmed());
    printDiagnostics(err, r.diagnostics);
    if (!r.fit)
        return kExitProblems;
    const iso286::Fit &f = *r.fit;
    if (parser.isSet(json)) {
        out << QJsonDocument(QJsonObject{{QStringLiteral("nominal_mm"), *nominal},
                                         {QStringLiteral("hole"), classLimitsJson(f.hole)},
                                         {QStringLiteral("shaft"), classLimitsJson(f.shaft)},
                                         {QStringLiteral("type"), iso286::fitTypeKeyword(f.type)},
                                         {QStringLiteral("max_clearance_um"), f.maxClearance_um},
                                         {QStringLiteral("min_clearance_um"), f.minClearance_um}})
                   .toJson(QJsonDocument::Indented);
    } else {
        out << CommandLine::tr(
                   "%1 %2/%3: %4 fit; hole %5/%6 µm, shaft %7/%8 µm; clearance max %9 µm, min %10 µm (negative: "
                   "interference)")
                   .arg(formatNumber(*nominal), f.hole.toleranceClass, f.shaft.toleranceClass,
                        iso286::fitTypeName(f.type), signedUm(f.hole.upper_um), signedUm(f.hole.lower_um),
                        signedUm(f.shaft.upper_um), signedUm(f.shaft.lower_um))
                   .arg(formatNumber(f.maxClearance_um), formatNumber(f.minClearance_um))
            << '\n';
    }
    return kExitOk;
}

QJsonObject evaluationJson(const ToleranceEvaluation &e)
{
    QJsonObject o{{QStringLiteral("id"), e.toleranceId},      {QStringLiteral("type"), keyword(e.type)},
                  {QStringLiteral("feature"), e.featureId},   {QStringLiteral("verdict"), verdictKeyword(e.verdict)},
                  {QStringLiteral("condition"), e.condition}, {QStringLiteral("reason"), e.reason}};
    const std::pair<const char *, std::optional<double>> numbers[] = {{"value_um", e.value_um},
                                                                      {"limit_um", e.limit_um},
                                                                      {"utilisation_pct", e.utilisation_pct},
                                                                      {"nominal_mm", e.nominal_mm},
                                                                      {"upper_um", e.upper_um},
                                                                      {"lower_um", e.lower_um},
                                                                      {"predicted_max_um", e.predictedMax_um},
                                                                      {"predicted_min_um", e.predictedMin_um},
                                                                      {"offset_um", e.offset_um}};
    for (const auto &[key, value] : numbers) {
        if (value)
            o.insert(QLatin1String(key), *value);
    }
    return o;
}

QString requiredKindKeyword(RequiredStiffness::Kind kind)
{
    switch (kind) {
    case RequiredStiffness::Kind::Found:
        return QStringLiteral("found");
    case RequiredStiffness::Kind::Window:
        return QStringLiteral("window");
    case RequiredStiffness::Kind::AnyStiffness:
        return QStringLiteral("any");
    case RequiredStiffness::Kind::NotReachable:
        return QStringLiteral("not_reachable");
    }
    return {};
}

QJsonValue requiredJson(const std::optional<RequiredStiffness> &r)
{
    if (!r)
        return QJsonValue::Null;
    QJsonObject o{{QStringLiteral("kind"), requiredKindKeyword(r->kind)}};
    if (r->kind != RequiredStiffness::Kind::NotReachable)
        o.insert(QStringLiteral("N_per_um"), r->value_N_per_mm / 1000.0);
    if (r->kind == RequiredStiffness::Kind::Window)
        o.insert(QStringLiteral("fails_again_at_N_per_um"), r->upper_N_per_mm / 1000.0);
    return o;
}

QJsonObject rangeEvaluationJson(const ToleranceRangeEvaluation &e)
{
    QJsonObject o = evaluationJson(e.compliant);
    o.insert(QStringLiteral("range_verdict"), rangeVerdictKeyword(e.range));
    o.insert(QStringLiteral("range_verdict_text"), rangeVerdictText(e));
    if (e.stiff)
        o.insert(QStringLiteral("at_stiff_end"), evaluationJson(*e.stiff));
    o.insert(QStringLiteral("required_chuck_stiffness"), requiredJson(e.chuck));
    o.insert(QStringLiteral("required_tailstock_stiffness"), requiredJson(e.tailstock));
    return o;
}

int runEvaluate(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the verdicts as JSON."));
    parser.addOption(json);
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseCommand(parser, commandNamed(QStringLiteral("evaluate")), args, out, err); stop >= 0)
        return stop;
    const QString file = oneProjectFile(parser, QStringLiteral("evaluate"), err);
    if (file.isEmpty())
        return kExitUsage;
    const std::optional<Project> project = readProject(file, err);
    if (!project)
        return kExitProblems;
    const RangeEvaluation range = evaluateOverStiffnessRange(*project, DataLibrary::builtIn());
    const DeviationResult &deviation = range.compliant;
    for (const Diagnostic &d : deviation.diagnostics)
        err << file << ": " << d.toString() << '\n';
    if (!deviation.inputs)
        return kExitProblems;
    const QString assumption = machineAssumptionText(range, DataLibrary::builtIn());
    if (parser.isSet(json)) {
        QJsonArray list;
        for (const ToleranceRangeEvaluation &e : range.tolerances)
            list.append(rangeEvaluationJson(e));
        out << QJsonDocument(QJsonObject{{QStringLiteral("file"), file},
                                         {QStringLiteral("machine_assumption"), assumption},
                                         {QStringLiteral("machine_is_range"), range.machineIsRange},
                                         {QStringLiteral("rigid_support_assumed"), range.someSupportRigid},
                                         {QStringLiteral("notes"), QJsonArray::fromStringList(deviation.inputs->notes)},
                                         {QStringLiteral("tolerances"), list}})
                   .toJson(QJsonDocument::Indented);
        return kExitOk;
    }
    if (!assumption.isEmpty())
        out << CommandLine::tr("Machine: %1").arg(assumption) << '\n';
    out << CommandLine::tr("tolerance  type                    feature  value [µm]  limit [µm]  use [%]  verdict")
        << '\n';
    for (const ToleranceRangeEvaluation &r : range.tolerances) {
        const ToleranceEvaluation &e = r.compliant;
        const auto number = [](const std::optional<double> &v, int width, int decimals) {
            return v ? QStringLiteral("%1").arg(*v, width, 'f', decimals)
                     : QStringLiteral("%1").arg(QStringLiteral("—"), width);
        };
        out << QStringLiteral("%1 %2 %3 %4 %5 %6  %7")
                   .arg(e.toleranceId, -10)
                   .arg(displayName(e.type), -23)
                   .arg(e.featureId, -8)
                   .arg(number(e.value_um, 10, 3), number(e.limit_um, 11, 3), number(e.utilisation_pct, 8, 1),
                        rangeVerdictText(r))
            << '\n';
        const QString indent = QStringLiteral("           ");
        if (r.range != RangeVerdict::NoRange && r.range != RangeVerdict::NotDecided)
            out << indent << CommandLine::tr("at the compliant end: %1").arg(verdictName(e.verdict)) << '\n';
        if (r.chuck)
            out << indent << CommandLine::tr("chuck stiffness needed: %1").arg(requiredStiffnessText(*r.chuck)) << '\n';
        if (r.tailstock)
            out << indent << CommandLine::tr("tailstock stiffness needed: %1").arg(requiredStiffnessText(*r.tailstock))
                << '\n';
        if (!e.condition.isEmpty())
            out << indent << e.condition << '\n';
        if (!e.reason.isEmpty())
            out << indent << e.reason << '\n';
    }
    return kExitOk;
}

// ---- optimize -------------------------------------------------------------------------------

QJsonObject passJson(const PassConditions &p)
{
    return {{QStringLiteral("cutting_speed_m_min"), p.cuttingSpeed_m_min},
            {QStringLiteral("feed_mm_rev"), p.feed_mm_rev},
            {QStringLiteral("depth_of_cut_mm"), p.depthOfCut_mm}};
}

QJsonArray constraintsJson(const std::vector<ConstraintValue> &list)
{
    QJsonArray out;
    for (const ConstraintValue &c : list)
        out.append(QJsonObject{{QStringLiteral("name"), c.name},
                               {QStringLiteral("subject"), c.subject},
                               {QStringLiteral("value"), c.value},
                               {QStringLiteral("limit"), c.limit},
                               {QStringLiteral("unit"), c.unit},
                               {QStringLiteral("violation_pct"), 100.0 * c.violation()}});
    return out;
}

QString constraintText(const ConstraintValue &c)
{
    return QStringLiteral("%1: %2 of %3 %4 (%5 %)")
        .arg(c.label(), QString::number(c.value, 'g', 4), QString::number(c.limit, 'g', 4), c.unit,
             QString::number(100.0 * (c.value / c.limit), 'f', 1));
}

PassConditions roughingOf(const PlanResult &r, const PlanningProblem &problem)
{
    PassConditions p = r.candidate.roughing;
    if (r.candidate.roughingPasses > 0)
        p.depthOfCut_mm = (problem.radialStock_mm() - r.candidate.finishing.depthOfCut_mm) / r.candidate.roughingPasses;
    return p;
}

QJsonObject planJson(const PlanResult &r, const PlanningProblem &problem)
{
    const CandidateEvaluation &e = r.evaluation;
    return {{QStringLiteral("feasible"), r.feasible},
            {QStringLiteral("objective"), keyword(problem.project().planning.objective)},
            {QStringLiteral("objective_value"), e.objective},
            {QStringLiteral("time_min"), e.time_min},
            {QStringLiteral("cost"), e.cost},
            {QStringLiteral("finishing_time_min"), e.finishingTime_min},
            {QStringLiteral("roughing_time_min"), e.roughingTime_min},
            {QStringLiteral("tool_edges_per_part"), e.toolEdgesPerPart},
            {QStringLiteral("finishing"), passJson(r.candidate.finishing)},
            {QStringLiteral("roughing"), QJsonObject{{QStringLiteral("passes"), r.candidate.roughingPasses},
                                                     {QStringLiteral("pass"), passJson(roughingOf(r, problem))}}},
            {QStringLiteral("constraints"), constraintsJson(e.constraints)},
            {QStringLiteral("binding"), constraintsJson(r.binding)},
            {QStringLiteral("conflicts"), constraintsJson(r.conflicts)},
            {QStringLiteral("evaluations"), r.evaluations},
            {QStringLiteral("notes"), QJsonArray::fromStringList(r.notes)}};
}

void printPlan(QTextStream &out, const PlanResult &r, const PlanningProblem &problem)
{
    const CandidateEvaluation &e = r.evaluation;
    const PassConditions rough = roughingOf(r, problem);
    out << (r.feasible ? CommandLine::tr("Optimum (%1)").arg(keyword(problem.project().planning.objective))
                       : CommandLine::tr("No plan meets every constraint; the one that violates them least"))
        << '\n';
    out << CommandLine::tr("  time per part %1 min (finishing %2, roughing %3), cost %4, %5 tool edges per part")
               .arg(QString::number(e.time_min, 'f', 3), QString::number(e.finishingTime_min, 'f', 3),
                    QString::number(e.roughingTime_min, 'f', 3), QString::number(e.cost, 'f', 2),
                    QString::number(e.toolEdgesPerPart, 'f', 3))
        << '\n';
    out << CommandLine::tr("  finishing: vc %1 m/min, f %2 mm/rev, ap %3 mm")
               .arg(QString::number(r.candidate.finishing.cuttingSpeed_m_min, 'f', 1),
                    QString::number(r.candidate.finishing.feed_mm_rev, 'f', 3),
                    QString::number(r.candidate.finishing.depthOfCut_mm, 'f', 3))
        << '\n';
    if (r.candidate.roughingPasses > 0)
        out << CommandLine::tr("  roughing: %1 passes of ap %2 mm at vc %3 m/min, f %4 mm/rev")
                   .arg(r.candidate.roughingPasses)
                   .arg(QString::number(rough.depthOfCut_mm, 'f', 3), QString::number(rough.cuttingSpeed_m_min, 'f', 1),
                        QString::number(rough.feed_mm_rev, 'f', 3))
            << '\n';
    for (const ConstraintValue &c : r.binding)
        out << CommandLine::tr("  binding: ") << constraintText(c) << '\n';
    for (const ConstraintValue &c : r.conflicts)
        out << CommandLine::tr("  violated: ") << constraintText(c) << '\n';
    for (const QString &note : r.notes)
        out << CommandLine::tr("note: ") << note << '\n';
}

// Loads a project and builds its planning problem; prints problems and returns null on failure.
std::shared_ptr<const PlanningProblem> loadPlanningProblem(const QString &file, QTextStream &err,
                                                           std::optional<Project> *project = nullptr)
{
    const std::optional<Project> read = readProject(file, err);
    if (!read)
        return nullptr;
    if (project != nullptr)
        *project = read;
    const PlanningProblem::BuildResult built = PlanningProblem::build(*read, DataLibrary::builtIn());
    for (const Diagnostic &d : built.diagnostics) {
        if (d.severity == Severity::Error)
            err << file << ": " << d.toString() << '\n';
    }
    return built.problem;
}

int runOptimize(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the plan as JSON."));
    const QCommandLineOption objective(QStringLiteral("objective"),
                                       CommandLine::tr("time or cost (default: the project's)."),
                                       QStringLiteral("OBJECTIVE"));
    const QCommandLineOption write(
        QStringLiteral("write"),
        CommandLine::tr("Store the optimal passes in the project (replacing its passes) and save it."));
    const QCommandLineOption machineEnd(
        QStringLiteral("machine-end"),
        CommandLine::tr(
            "Plan for the compliant (default) or the stiff end of an unmeasured machine's stiffness range."),
        QStringLiteral("END"));
    parser.addOptions({json, objective, write, machineEnd});
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseCommand(parser, commandNamed(QStringLiteral("optimize")), args, out, err); stop >= 0)
        return stop;
    const QString file = oneProjectFile(parser, QStringLiteral("optimize"), err);
    if (file.isEmpty())
        return kExitUsage;
    std::optional<Project> project = readProject(file, err);
    if (!project)
        return kExitProblems;
    if (parser.isSet(objective)) {
        const auto chosen = fromKeyword<PlanningObjective>(parser.value(objective));
        if (!chosen) {
            err << programName() << " optimize: "
                << CommandLine::tr("--objective is time or cost, not \"%1\"").arg(parser.value(objective)) << '\n';
            return kExitUsage;
        }
        project->planning.objective = *chosen;
    }
    StiffnessEnd end = StiffnessEnd::Compliant;
    if (parser.isSet(machineEnd)) {
        const QString value = parser.value(machineEnd);
        if (value != QLatin1String("compliant") && value != QLatin1String("stiff")) {
            err << programName()
                << " optimize: " << CommandLine::tr("--machine-end is compliant or stiff, not \"%1\"").arg(value)
                << '\n';
            return kExitUsage;
        }
        end = value == QLatin1String("stiff") ? StiffnessEnd::Stiff : StiffnessEnd::Compliant;
    }
    const PlanningProblem::BuildResult built = PlanningProblem::build(*project, DataLibrary::builtIn(), end);
    for (const Diagnostic &d : built.diagnostics) {
        if (d.severity == Severity::Error)
            err << file << ": " << d.toString() << '\n';
    }
    if (!built.problem)
        return kExitProblems;
    const PlanResult plan = optimisePlan(*built.problem);
    if (parser.isSet(json))
        out << QJsonDocument(planJson(plan, *built.problem)).toJson(QJsonDocument::Indented);
    else
        printPlan(out, plan, *built.problem);
    if (!plan.feasible)
        return kExitProblems;
    if (parser.isSet(write)) {
        const PassConditions rough = roughingOf(plan, *built.problem);
        project->passes.clear();
        for (int i = 0; i < plan.candidate.roughingPasses; ++i)
            project->passes.push_back(
                {PassKind::Roughing, rough.cuttingSpeed_m_min, rough.feed_mm_rev, rough.depthOfCut_mm});
        const PassConditions &f = plan.candidate.finishing;
        project->passes.push_back({PassKind::Finishing, f.cuttingSpeed_m_min, f.feed_mm_rev, f.depthOfCut_mm});
        const WriteResult w = writeProjectFile(file, *project);
        if (!w.ok) {
            err << w.error << '\n';
            return kExitProblems;
        }
        err << CommandLine::tr("wrote %1: %2 passes").arg(file).arg(project->passes.size()) << '\n';
    }
    return kExitOk;
}

int runWindow(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption plane(QStringLiteral("plane"), CommandLine::tr("feed-speed (default) or feed-depth."),
                                   QStringLiteral("PLANE"), QStringLiteral("feed-speed"));
    const QCommandLineOption csv(QStringLiteral("csv"), CommandLine::tr("Print every grid point as CSV."));
    const QCommandLineOption size(QStringLiteral("size"), CommandLine::tr("Points along each axis (default 256)."),
                                  QStringLiteral("N"), QStringLiteral("256"));
    parser.addOptions({plane, csv, size});
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseCommand(parser, commandNamed(QStringLiteral("window")), args, out, err); stop >= 0)
        return stop;
    bool ok = false;
    const int n = parser.value(size).toInt(&ok);
    const QString planeName = parser.value(plane);
    if (parser.positionalArguments().size() != 1 || !ok || n < 2 || n > 4096 ||
        (planeName != QLatin1String("feed-speed") && planeName != QLatin1String("feed-depth"))) {
        err << programName() << " window: "
            << CommandLine::tr("give one project file, --plane feed-speed or feed-depth, --size from 2 to 4096")
            << '\n';
        return kExitUsage;
    }
    const auto problem = loadPlanningProblem(parser.positionalArguments().constFirst(), err);
    if (!problem)
        return kExitProblems;
    const PlanResult plan = optimisePlan(*problem);
    WindowOptions options;
    options.columns = options.rows = n;
    const WindowPlane which =
        planeName == QLatin1String("feed-speed") ? WindowPlane::FeedSpeed : WindowPlane::FeedDepth;
    const CuttingWindow w =
        cuttingWindow(*problem, which, plan.candidate, options); // the optimum, or the least-violating plan
    const QString yName =
        which == WindowPlane::FeedSpeed ? QStringLiteral("cutting_speed_m_min") : QStringLiteral("depth_of_cut_mm");
    if (parser.isSet(csv)) {
        out << "feed_mm_rev," << yName << ",objective,feasible,binding\n";
        for (const WindowCell &c : w.cells)
            out << QString::number(c.x, 'g', 8) << ',' << QString::number(c.y, 'g', 8) << ','
                << QString::number(c.objective, 'g', 8) << ',' << (c.feasible ? 1 : 0) << ','
                << (c.feasible ? QString() : QLatin1Char('"') + c.bindingLabel + QLatin1Char('"')) << '\n';
        return kExitOk;
    }
    int feasible = 0;
    for (const WindowCell &c : w.cells)
        feasible += c.feasible ? 1 : 0;
    out << CommandLine::tr("%1 × %2 window, %3 % feasible; optimum at f = %4 mm/rev, %5 = %6")
               .arg(w.columns)
               .arg(w.rows)
               .arg(QString::number(100.0 * feasible / static_cast<double>(w.cells.size()), 'f', 1),
                    QString::number(w.base.finishing.feed_mm_rev, 'f', 3), yName,
                    QString::number(which == WindowPlane::FeedSpeed ? w.base.finishing.cuttingSpeed_m_min
                                                                    : w.base.finishing.depthOfCut_mm,
                                    'f', 3))
        << '\n';
    for (const auto &[label, cells] : w.boundaries())
        out << CommandLine::tr("  bounded by %1 (%2 points beyond it)").arg(label).arg(cells) << '\n';
    return kExitOk;
}

int runAdviseClamping(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the ranking as JSON."));
    parser.addOption(json);
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseCommand(parser, commandNamed(QStringLiteral("advise-clamping")), args, out, err);
        stop >= 0)
        return stop;
    const QString file = oneProjectFile(parser, QStringLiteral("advise-clamping"), err);
    if (file.isEmpty())
        return kExitUsage;
    const std::optional<Project> project = readProject(file, err);
    if (!project)
        return kExitProblems;
    const std::vector<ClampingOption> options = adviseClamping(*project, DataLibrary::builtIn());
    if (parser.isSet(json)) {
        QJsonArray list;
        int rank = 1;
        for (const ClampingOption &o : options) {
            QJsonObject entry{{QStringLiteral("rank"), rank++},
                              {QStringLiteral("method"), keyword(o.method)},
                              {QStringLiteral("clamped_length_mm"), o.clampedLength_mm},
                              {QStringLiteral("possible"), o.possible},
                              {QStringLiteral("feasible"), o.plan.feasible},
                              {QStringLiteral("reason"), o.reason}};
            if (o.possible)
                entry.insert(QStringLiteral("objective_value"), o.plan.evaluation.objective);
            list.append(entry);
        }
        out << QJsonDocument(QJsonObject{{QStringLiteral("file"), file},
                                         {QStringLiteral("objective"), keyword(project->planning.objective)},
                                         {QStringLiteral("ranking"), list}})
                   .toJson(QJsonDocument::Indented);
        return kExitOk;
    }
    int rank = 1;
    for (const ClampingOption &o : options)
        out << QStringLiteral("%1. %2: %3").arg(rank++).arg(displayName(o.method), o.reason) << '\n';
    return kExitOk;
}

int runReport(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption output({QStringLiteral("o"), QStringLiteral("output")},
                                    CommandLine::tr("PDF file to write."), QStringLiteral("FILE"));
    const QCommandLineOption planner(
        QStringLiteral("planner"), CommandLine::tr("The planner's name for the title block."), QStringLiteral("NAME"));
    parser.addOptions({output, planner});
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseCommand(parser, commandNamed(QStringLiteral("report")), args, out, err); stop >= 0)
        return stop;
    if (parser.positionalArguments().size() != 1 || !parser.isSet(output)) {
        err << programName() << " report: " << CommandLine::tr("give one project file and -o FILE.pdf") << '\n';
        return kExitUsage;
    }
    const QString file = parser.positionalArguments().constFirst();
    const std::optional<Project> project = readProject(file, err);
    if (!project)
        return kExitProblems;
    const ReportResult written =
        writeReport(*project, {QFileInfo(file).fileName(), parser.value(planner)}, parser.value(output));
    if (!written.ok) {
        err << programName() << " report: " << written.error << '\n';
        return kExitProblems;
    }
    out << CommandLine::tr("%1: %2 pages").arg(parser.value(output)).arg(written.pages) << '\n';
    return kExitOk;
}

const std::vector<Command> &commands()
{
    static const std::vector<Command> list{
        {QStringLiteral("check"), QStringLiteral("check [--json] PROJECT..."),
         CommandLine::tr("Validate project files: report every problem with the field and value; exit 1 on errors."),
         runCheck},
        {QStringLiteral("deflect"),
         QStringLiteral("deflect [--json] [--load Fr,Ft,Fa] [--workpiece-only] [--stations N] [--pass N] PROJECT"),
         CommandLine::tr(
             "Predict the deviation at each tool position along every turned feature: radial and tangential, total "
             "and per contribution (spindle–chuck, toolpost, workpiece, thermal), with the forces used."),
         runDeflect},
        {QStringLiteral("calibrate-forces"),
         QStringLiteral("calibrate-forces [--json] [--write] PROJECT MEASUREMENTS.csv"),
         CommandLine::tr(
             "Fit the Li & Du coefficients K_n and K_f to measured tangential and axial forces (eq. 17–18) for the "
             "project's tool; --write stores them in the project."),
         runCalibrateForces},
        {QStringLiteral("calibrate-stiffness"), calibrateStiffnessSynopsis(), calibrateStiffnessSummary(),
         runCalibrateStiffness},
        {QStringLiteral("iso286"), QStringLiteral("iso286 [--json] NOMINAL CLASS"),
         CommandLine::tr("ISO 286 limits of a tolerance class at a nominal size, e.g. 'iso286 50 H7'."), runIso286},
        {QStringLiteral("fit"), QStringLiteral("fit [--json] NOMINAL HOLE/SHAFT"),
         CommandLine::tr("ISO 286 fit of a hole and a shaft class, e.g. 'fit 50 H7/g6': type and clearances."), runFit},
        {QStringLiteral("evaluate"), QStringLiteral("evaluate [--json] PROJECT"),
         CommandLine::tr(
             "Every tolerance of the project against the predicted deviation: value, limit, utilisation, the "
             "deciding condition of Valiño et al. Fig. 4, and the verdict."),
         runEvaluate},
        {QStringLiteral("optimize"),
         QStringLiteral("optimize [--json] [--objective time|cost] [--machine-end compliant|stiff] [--write] PROJECT"),
         CommandLine::tr(
             "Cutting conditions of the finishing and roughing passes at least time or cost per part under every "
             "constraint (tolerances, roughness, power, torque, force, spindle speed, tool life)."),
         runOptimize},
        {QStringLiteral("window"), QStringLiteral("window [--plane feed-speed|feed-depth] [--csv] [--size N] PROJECT"),
         CommandLine::tr(
             "The cutting window of the finishing pass around the optimum: per grid point the objective, whether "
             "it is feasible and the constraint that bounds it."),
         runWindow},
        {QStringLiteral("advise-clamping"), QStringLiteral("advise-clamping [--json] PROJECT"),
         CommandLine::tr("The optimal plan for chuck, between centres and chuck + tailstock, ranked, with the reason."),
         runAdviseClamping},
        {QStringLiteral("gcode"), gcodeSynopsis(), gcodeSummary(), runGCode},
        {QStringLiteral("report"), QStringLiteral("report [--planner NAME] -o FILE.pdf PROJECT"),
         CommandLine::tr(
             "The PDF report: part, inputs, predicted deviation, tolerance verdicts, plan with the cutting window, "
             "clamping ranking, compensation, assumptions and sources."),
         runReport},
        {QStringLiteral("import"), importSynopsis(), importSummary(), runImport},
        {QStringLiteral("export-step"), exportStepSynopsis(), exportStepSummary(), runExportStep},
    };
    return list;
}

// Levenshtein distance, for suggesting a command to a mistyped one.
int editDistance(const QString &a, const QString &b)
{
    std::vector<int> row(static_cast<std::size_t>(b.size()) + 1);
    for (std::size_t j = 0; j < row.size(); ++j)
        row[j] = static_cast<int>(j);
    for (qsizetype i = 1; i <= a.size(); ++i) {
        int diagonal = row[0];
        row[0] = static_cast<int>(i);
        for (qsizetype j = 1; j <= b.size(); ++j) {
            const int above = row[static_cast<std::size_t>(j)];
            const int substitution = diagonal + (a.at(i - 1) == b.at(j - 1) ? 0 : 1);
            row[static_cast<std::size_t>(j)] =
                std::min({above + 1, row[static_cast<std::size_t>(j - 1)] + 1, substitution});
            diagonal = above;
        }
    }
    return row.back();
}

// The command a mistyped name most likely meant: within two edits, or the one it starts.
QString nearestCommand(const QString &typed)
{
    QString best;
    int bestDistance = 3;
    for (const Command &c : commands()) {
        const int d =
            c.name.startsWith(typed.toLower()) && typed.size() >= 3 ? 0 : editDistance(typed.toLower(), c.name);
        if (d < bestDistance) {
            bestDistance = d;
            best = c.name;
        }
    }
    return best;
}

} // namespace

int runCommandLine(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    const QStringList args = arguments.mid(1);
    if (args.isEmpty()) {
        err << usage();
        return kExitUsage;
    }
    const QString &first = args.constFirst();
    if (first == QLatin1String("--help") || first == QLatin1String("-h") || first == QLatin1String("help")) {
        out << usage();
        return kExitOk;
    }
    if (first == QLatin1String("--version") || first == QLatin1String("-v")) {
        out << versionText();
        return kExitOk;
    }
    // British spelling as well: the desktop program says "Optimise".
    const QString name = first == QLatin1String("optimise") ? QStringLiteral("optimize") : first;
    for (const Command &c : commands()) {
        if (c.name == name)
            return c.run(QStringList{programName() + QLatin1Char(' ') + c.name} + args.mid(1), out, err);
    }
    err << CommandLine::tr("%1: unknown command '%2'.").arg(programName(), first);
    if (const QString close = nearestCommand(first); !close.isEmpty())
        err << ' ' << CommandLine::tr("Did you mean '%1'?").arg(close);
    err << ' ' << CommandLine::tr("Run '%1 --help' for the list of commands.").arg(programName()) << '\n';
    return kExitUsage;
}

} // namespace tolturn
