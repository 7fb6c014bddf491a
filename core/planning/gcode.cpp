// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/gcode.h"

#include "core/common/library_info.h"
#include "core/project/keywords.h"
#include "core/tooling/iso1832.h"

#include <QCoreApplication>

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

} // namespace

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
    program.text = postProcess(program.path, project.part.length_mm(), post);
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
