// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/gcode.h"

#include "core/common/library_info.h"
#include "core/planning/path_geometry.h"
#include "core/project/keywords.h"
#include "core/tooling/iso1832.h"

#include <QCoreApplication>
#include <QCryptographicHash>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tolturn {

namespace {

struct Programs {
    Q_DECLARE_TR_FUNCTIONS(GCode)
};

QString compensationSummary(const CompensationPlan *plan)
{
    if (plan == nullptr)
        return Programs::tr("No compensation: toleranced diameters at the middle of their zone");
    QStringList parts;
    for (const FeatureCompensation &f : plan->features) {
        if (f.side != ContourSide::Outer)
            continue;
        if (f.action == CompensationAction::ConstantOffset)
            parts << Programs::tr("%1 offset %2 um on diameter").arg(f.featureId, QString::number(f.offset_um, 'f', 1));
        else if (f.action == CompensationAction::ProfileCorrection)
            parts << Programs::tr("%1 profile corrected by the predicted deviation").arg(f.featureId);
    }
    return parts.isEmpty() ? Programs::tr("Compensated path: no feature needs a correction")
                           : Programs::tr("Compensated: %1").arg(parts.join(QStringLiteral("; ")));
}

// kappa' = 180° - kappa_r - epsilon_r: the minor (trailing) cutting edge angle from the tool
// cutting edge angle of the holder and the corner angle of the insert (ISO 3002-1 tool angles).
std::optional<double> trailingEdgeAngle_deg(const Project &project, const TurningInputs &inputs)
{
    const InsertParseResult insert = parseInsertCode(project.tool.insertCode);
    if (!insert.insert || insert.insert->includedAngle_deg <= 0.0 || inputs.enteringAngle_deg <= 0.0)
        return std::nullopt;
    return 180.0 - inputs.enteringAngle_deg - insert.insert->includedAngle_deg;
}

std::vector<CuttingPass> roughingPasses(const Project &project)
{
    std::vector<CuttingPass> out;
    for (const CuttingPass &p : project.passes)
        if (p.kind == PassKind::Roughing)
            out.push_back(p);
    return out;
}

QString passConditions(const CuttingPass &p)
{
    return Programs::tr("vc %1 m/min, f %2 mm/rev, ap %3 mm")
        .arg(QString::number(p.cuttingSpeed_m_min, 'f', 0), QString::number(p.feed_mm_rev, 'f', 3),
             QString::number(p.depthOfCut_mm, 'f', 3));
}

// The passes in words, equal roughing passes together: "passes 1-8 roughing vc …; pass 9 finishing …".
QString conditionsText(const Toolpath &path)
{
    QStringList parts;
    for (std::size_t i = 0; i < path.roughing.size();) {
        std::size_t j = i;
        while (j + 1 < path.roughing.size() && path.roughing[j + 1].conditions == path.roughing[i].conditions)
            ++j;
        const QString numbers =
            i == j ? Programs::tr("pass %1").arg(path.roughing[i].number)
                   : Programs::tr("passes %1-%2").arg(path.roughing[i].number).arg(path.roughing[j].number);
        parts << Programs::tr("%1 roughing %2").arg(numbers, passConditions(path.roughing[i].conditions));
        i = j + 1;
    }
    parts << Programs::tr("pass %1 finishing %2")
                 .arg(path.finishing.number)
                 .arg(passConditions(path.finishing.conditions));
    return parts.join(QStringLiteral("; "));
}

// Spindle speed on radius r under G96 with the limit [rpm].
double spindleSpeed_rpm(double cuttingSpeed_m_min, double r_mm, double limit_rpm)
{
    if (r_mm <= 1e-9)
        return limit_rpm;
    return std::min(limit_rpm, 1000.0 * cuttingSpeed_m_min / (2.0 * std::numbers::pi * r_mm));
}

PassSummary summarise(const PassPath &pass, double limit_rpm)
{
    PassSummary s;
    s.number = pass.number;
    s.kind = pass.conditions.kind;
    s.conditions = pass.conditions;
    s.lowestSpeed_rpm = limit_rpm;
    s.highestSpeed_rpm = 0.0;
    std::optional<ProfilePoint> at;
    for (const ToolMove &m : pass.moves) {
        if (m.kind != MoveKind::Rapid && at) {
            PathElement e;
            e.from = *at;
            e.to = m.to;
            e.arc = m.kind != MoveKind::Feed;
            e.centre = m.centre;
            e.radius_mm = m.radius_mm;
            e.counterClockwise = m.kind == MoveKind::ArcCounterClockwise;
            const std::vector<ProfilePoint> points = sampled(e, 0.05);
            for (std::size_t i = 1; i < points.size(); ++i) {
                const double length =
                    std::hypot(points[i].z_mm - points[i - 1].z_mm, points[i].r_mm - points[i - 1].r_mm);
                const double r = 0.5 * (points[i].r_mm + points[i - 1].r_mm);
                const double n = spindleSpeed_rpm(pass.conditions.cuttingSpeed_m_min, r, limit_rpm);
                s.time_min += length / (pass.conditions.feed_mm_rev * n);
            }
            for (const ProfilePoint &q : points) {
                const double n = spindleSpeed_rpm(pass.conditions.cuttingSpeed_m_min, q.r_mm, limit_rpm);
                s.lowestSpeed_rpm = std::min(s.lowestSpeed_rpm, n);
                s.highestSpeed_rpm = std::max(s.highestSpeed_rpm, n);
            }
        }
        at = m.to;
    }
    return s;
}

} // namespace

std::vector<PassSummary> passSummaries(const Toolpath &path, const SpindleLimit &limit,
                                       const std::optional<ForceFunction> &forces)
{
    std::vector<PassSummary> out;
    for (const PassPath &p : path.roughing)
        out.push_back(summarise(p, limit.speed_rpm));
    out.push_back(summarise(path.finishing, limit.speed_rpm));
    if (forces) {
        for (PassSummary &s : out) // P = F_c v_c / 60 000 [kW] (F_c in N, v_c in m/min)
            s.power_kW = (*forces)(s.conditions.feed_mm_rev, s.conditions.depthOfCut_mm).tangential_N *
                         s.conditions.cuttingSpeed_m_min / 60000.0;
    }
    return out;
}

std::optional<ControlDialect> machineDialect(const DataLibrary &data, const QString &machineId)
{
    const MachineData *m = data.machine(machineId);
    return m ? controlDialectFromKeyword(m->control) : std::nullopt;
}

TurningProgram turningProgram(const Project &project, const DataLibrary &data, const TurningInputs &inputs,
                              const GCodeOptions &options)
{
    TurningProgram program;
    if (options.dialect) {
        program.dialect = *options.dialect;
        program.dialectReason = Programs::tr("%1, as chosen").arg(displayName(program.dialect));
    } else if (const auto fromMachine = machineDialect(data, project.machineId)) {
        program.dialect = *fromMachine;
        program.dialectReason =
            Programs::tr("%1, the control of machine %2").arg(displayName(program.dialect), project.machineId);
    } else {
        program.dialect = ControlDialect::FanucHaas;
        program.dialectReason = Programs::tr("%1: machine %2 has no CNC control in the data; choose the dialect of "
                                             "yours")
                                    .arg(displayName(program.dialect), project.machineId);
    }
    ToolpathOptions pathOptions;
    pathOptions.nose = options.nose;
    pathOptions.compensation = options.compensation;
    pathOptions.clearance_mm = options.clearance_mm;
    program.path = turningToolpath(project, inputs.pass, roughingPasses(project), inputs.noseRadius_mm,
                                   trailingEdgeAngle_deg(project, inputs), pathOptions);
    const std::optional<double> machineLimit =
        project.planning.maxSpindleSpeed_rpm ? project.planning.maxSpindleSpeed_rpm : inputs.maxSpindleSpeed_rpm;
    program.spindle = spindleLimit(program.path, machineLimit);
    program.conditions = conditionsText(program.path);

    PostOptions post;
    post.dialect = program.dialect;
    post.programNumber = options.programNumber;
    post.tool = options.tool;
    post.spindle = program.spindle;
    post.header << Programs::tr("TolTurn %1: %2").arg(tolturnVersion(), project.part.name)

                << Programs::tr("Material %1, insert %2, holder %3, clamping %4")
                       .arg(project.materialId, project.tool.insertCode, project.tool.holderCode,
                            keyword(project.clamping.method))
                << Programs::tr("Dialect: %1").arg(program.dialectReason) << compensationSummary(options.compensation)
                << Programs::tr("Conditions: %1").arg(program.conditions);
    if (project.scope) // one set-up of several: which, and which end of the drawing is in the chuck
        post.header.insert(1, Programs::tr("%1, operation %2 of %3: the drawing's %4 end held; the right end face "
                                           "below is the free end of this set-up")
                                  .arg(project.scope->name)
                                  .arg(project.scope->index + 1)
                                  .arg(project.scope->count)
                                  .arg(displayName(project.clamping.heldEnd)));
    program.programNumber = options.programNumber;
    program.text = postProcess(program.path, project.part.length_mm(), post);
    program.checksum = QString::fromLatin1(
        QCryptographicHash::hash(program.text.toUtf8(), QCryptographicHash::Sha256).toHex().left(16));
    Diagnostics ignored; // the deviation model has reported them already
    program.passes = passSummaries(program.path, program.spindle, projectForceModel(project, data, ignored));
    return program;
}

QString keyword(NoseHandling nose)
{
    return nose == NoseHandling::TipPath ? QStringLiteral("tip-path") : QStringLiteral("control");
}

std::optional<NoseHandling> noseHandlingFromKeyword(const QString &text)
{
    const QString t = text.trimmed().toLower();
    if (t == QLatin1String("control"))
        return NoseHandling::ControlCompensation;
    if (t == QLatin1String("tip-path") || t == QLatin1String("tip"))
        return NoseHandling::TipPath;
    return std::nullopt;
}

} // namespace tolturn
