// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/gcode.h"

#include "core/common/library_info.h"
#include "core/planning/boring_toolpath.h"
#include "core/planning/feed_schedule.h"
#include "core/planning/pass_time.h"
#include "core/project/keywords.h"
#include "core/tooling/iso1832.h"

#include <QCoreApplication>
#include <QCryptographicHash>

#include <algorithm>

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
std::optional<double> trailingEdgeAngle_deg(const Tool &tool, double enteringAngle_deg)
{
    const InsertParseResult insert = parseInsertCode(tool.insertCode);
    if (!insert.insert || insert.insert->includedAngle_deg <= 0.0 || enteringAngle_deg <= 0.0)
        return std::nullopt;
    return 180.0 - enteringAngle_deg - insert.insert->includedAngle_deg;
}

bool hasFinishingPass(const Project &project)
{
    return std::any_of(project.passes.begin(), project.passes.end(),
                       [](const CuttingPass &p) { return p.kind == PassKind::Finishing; });
}

// The roughing passes cut before the contour pass. Without a finishing pass the last pass is the
// contour pass (as the deviation model takes it, choosePass): it is not cut as a level first.
std::vector<CuttingPass> roughingPasses(const Project &project)
{
    std::vector<CuttingPass> out;
    for (const CuttingPass &p : project.passes)
        if (p.kind == PassKind::Roughing)
            out.push_back(p);
    if (!hasFinishingPass(project) && !out.empty())
        out.pop_back();
    return out;
}

QString passConditions(const CuttingPass &p)
{
    return Programs::tr("vc %1 m/min, f %2 mm/rev, ap %3 mm")
        .arg(QString::number(p.cuttingSpeed_m_min, 'f', 0), QString::number(p.feed_mm_rev, 'f', 3),
             QString::number(p.depthOfCut_mm, 'f', 3));
}

// The passes in words, equal roughing passes together: "passes 1-8 roughing vc …; pass 9 finishing …";
// a boring path's as "bore passes 10-12 roughing …".
QString conditionsText(const Toolpath &path)
{
    const bool bore = path.side == ContourSide::Inner;
    QStringList parts;
    for (std::size_t i = 0; i < path.roughing.size();) {
        std::size_t j = i;
        while (j + 1 < path.roughing.size() && path.roughing[j + 1].conditions == path.roughing[i].conditions)
            ++j;
        const QString numbers =
            i == j ? (bore ? Programs::tr("bore pass %1") : Programs::tr("pass %1")).arg(path.roughing[i].number)
                   : (bore ? Programs::tr("bore passes %1-%2") : Programs::tr("passes %1-%2"))
                         .arg(path.roughing[i].number)
                         .arg(path.roughing[j].number);
        parts << Programs::tr("%1 roughing %2").arg(numbers, passConditions(path.roughing[i].conditions));
        i = j + 1;
    }
    parts << (bore ? Programs::tr("bore pass %1 finishing %2") : Programs::tr("pass %1 finishing %2"))
                 .arg(path.finishing.number)
                 .arg(passConditions(path.finishing.conditions));
    return parts.join(QStringLiteral("; "));
}

PassSummary summarise(const PassPath &pass, ContourSide side, double limit_rpm)
{
    PassSummary s;
    s.number = pass.number;
    s.side = side;
    s.kind = pass.conditions.kind;
    s.conditions = pass.conditions;
    s.lowestSpeed_rpm = limit_rpm;
    s.highestSpeed_rpm = 0.0;
    const std::vector<FeedStep> steps = feedSteps(pass);
    s.time_min = feedTime_min(steps, pass.conditions.cuttingSpeed_m_min, pass.conditions.feed_mm_rev, limit_rpm);
    for (const FeedStep &step : steps)
        for (const ProfilePoint &q : {step.from, step.to}) {
            const double n = g96SpindleSpeed_rpm(pass.conditions.cuttingSpeed_m_min, q.r_mm, limit_rpm);
            s.lowestSpeed_rpm = std::min(s.lowestSpeed_rpm, n);
            s.highestSpeed_rpm = std::max(s.highestSpeed_rpm, n);
        }
    return s;
}

} // namespace

QStringList TurningProgram::warnings() const
{
    QStringList all = path.warnings;
    if (boring)
        all << boring->warnings;
    return all;
}

QString passKindText(const PassSummary &pass)
{
    const bool roughing = pass.kind == PassKind::Roughing;
    if (pass.side == ContourSide::Inner)
        return roughing ? Programs::tr("boring, roughing") : Programs::tr("boring, finishing");
    return roughing ? Programs::tr("roughing") : Programs::tr("finishing");
}

std::vector<PassSummary> passSummaries(const Toolpath &path, const SpindleLimit &limit,
                                       const std::optional<ForceFunction> &forces)
{
    std::vector<PassSummary> out;
    for (const PassPath &p : path.roughing)
        out.push_back(summarise(p, path.side, limit.speed_rpm));
    out.push_back(summarise(path.finishing, path.side, limit.speed_rpm));
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

namespace {

// The boring bar as the path needs it: its section and reach from the resolved inputs, the pilot
// hole from the project.
BoringBarGeometry boringBarGeometry(const Project &project, const BoringInputs &boring)
{
    BoringBarGeometry bar;
    bar.holderCode = boring.holderCode;
    bar.barDiameter_mm = boring.bar.diameter_mm;
    bar.edgeOffset_mm = boring.bar.edgeOffset_mm;
    bar.overhang_mm = boring.bar.overhang_mm;
    bar.noseRadius_mm = boring.noseRadius_mm;
    bar.trailingEdgeAngle_deg = trailingEdgeAngle_deg(*project.boringTool, boring.enteringAngle_deg);
    bar.pilotHoleDiameter_mm = project.boringTool->pilotHoleDiameter_mm;
    return bar;
}

// The boring path of the set-up, numbered after the turning passes; a bore without a bar is a note.
std::optional<Toolpath> boringPath(const Project &project, const TurningInputs &inputs, const ToolpathOptions &options,
                                   Toolpath &turning)
{
    if (!project.boringTool || !inputs.boring) {
        if (!project.part.inner.empty())
            turning.notes << Programs::tr("The bores are not in this program: the set-up has no boring bar (Set-up "
                                          "dock, Boring bar).");
        return std::nullopt;
    }
    if (!holdsOneEndOnly(project.clamping.method)) {
        turning.warnings << Programs::tr("The bores are not in this program: a centre holds the set-up's free end, "
                                         "so the boring bar cannot enter it. Bore them in a set-up held in the chuck "
                                         "alone.");
        return std::nullopt;
    }
    std::optional<Toolpath> boring = boringToolpath(project, inputs.pass, roughingPasses(project),
                                                    boringBarGeometry(project, *inputs.boring), options);
    if (!boring)
        return std::nullopt;
    if (boring->roughing.empty() && boring->finishing.moves.empty()) {
        turning.warnings << boring->warnings; // why nothing is bored
        return std::nullopt;
    }
    int number = turning.finishing.number + 1;
    for (PassPath &p : boring->roughing)
        p.number = number++;
    boring->finishing.number = number;
    return boring;
}

// The forces of the boring bar's insert (the project seen with it as the tool).
std::optional<ForceFunction> boringForceModel(const Project &project, const DataLibrary &data)
{
    if (!project.boringTool)
        return std::nullopt;
    Project view = project;
    view.tool = *project.boringTool;
    Diagnostics ignored; // the deviation model has reported them already
    return projectForceModel(view, data, ignored);
}

QStringList programHeader(const Project &project, const TurningProgram &program, const GCodeOptions &options)
{
    QStringList header;
    header << Programs::tr("TolTurn %1: %2").arg(tolturnVersion(), project.part.name)
           << Programs::tr("Material %1, insert %2, holder %3, clamping %4")
                  .arg(project.materialId, project.tool.insertCode, project.tool.holderCode,
                       displayName(project.clamping.method))
           << Programs::tr("Dialect: %1").arg(program.dialectReason) << compensationSummary(options.compensation)
           << Programs::tr("Conditions: %1").arg(program.conditions);
    if (!options.finishingFeeds_mm_rev.isEmpty()) {
        QStringList feeds;
        for (auto it = options.finishingFeeds_mm_rev.cbegin(); it != options.finishingFeeds_mm_rev.cend(); ++it)
            feeds << QStringLiteral("%1 F%2").arg(it.key(), QString::number(it.value(), 'f', 3));
        header << Programs::tr("Finishing feed scheduled by feature (TolTurn feed schedule): %1")
                      .arg(feeds.join(QStringLiteral(", ")));
    }
    if (options.roughingFeedSchedule)
        header << Programs::tr("Roughing feed raised where a level cuts less than its depth, to the planned force "
                               "(TolTurn feed schedule)");
    if (project.scope) // one set-up of several: which, and which end of the drawing is in the chuck
        header.insert(1, Programs::tr("%1, operation %2 of %3: the drawing's %4 end held; the right end face "
                                      "below is the free end of this set-up")
                             .arg(project.scope->name)
                             .arg(project.scope->index + 1)
                             .arg(project.scope->count)
                             .arg(displayName(project.clamping.heldEnd)));
    return header;
}

} // namespace

std::vector<PassPath> finishingPasses(const Project &project, const TurningInputs &inputs)
{
    Toolpath turning = turningToolpath(project, inputs.pass, roughingPasses(project), inputs.noseRadius_mm,
                                       trailingEdgeAngle_deg(project.tool, inputs.enteringAngle_deg), {});
    std::vector<PassPath> passes{turning.finishing};
    if (const std::optional<Toolpath> boring = boringPath(project, inputs, {}, turning))
        passes.push_back(boring->finishing);
    return passes;
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
                                   trailingEdgeAngle_deg(project.tool, inputs.enteringAngle_deg), pathOptions);
    if (!hasFinishingPass(project))
        program.path.warnings << Programs::tr("The project has no finishing pass: its last pass (%1) is cut along the "
                                              "contour as the finishing pass, and the passes before it leave it its "
                                              "depth. Add a finishing pass.")
                                     .arg(passConditions(inputs.pass));
    for (ToolMove &m : program.path.finishing.moves)
        if (m.kind != MoveKind::Rapid && options.finishingFeeds_mm_rev.contains(m.featureId))
            m.feed_mm_rev = options.finishingFeeds_mm_rev.value(m.featureId);
    GCodeOptions headerOptions = options; // the header names the roughing schedule only where it raised a feed
    if (options.roughingFeedSchedule) {
        Diagnostics ignored; // the deviation model has reported them already
        const std::optional<ForceFunction> forces = projectForceModel(project, data, ignored);
        int raised = 0;
        if (forces && project.planning.feed_mm_rev)
            raised = scheduleRoughingFeeds(project, *forces, project.planning.feed_mm_rev->max, program.path.roughing);
        else
            program.path.notes << Programs::tr("Roughing feed not scheduled: the plan's settings give no feed range "
                                               "to stay within.");
        headerOptions.roughingFeedSchedule = raised > 0;
    }
    program.boring = boringPath(project, inputs, pathOptions, program.path);
    const std::optional<double> machineLimit =
        project.planning.maxSpindleSpeed_rpm ? project.planning.maxSpindleSpeed_rpm : inputs.maxSpindleSpeed_rpm;
    std::vector<const Toolpath *> paths{&program.path};
    if (program.boring)
        paths.push_back(&*program.boring);
    program.spindle = spindleLimit(paths, machineLimit);
    program.conditions = conditionsText(program.path);
    if (program.boring)
        program.conditions += QStringLiteral("; ") + conditionsText(*program.boring);

    PostOptions post;
    post.dialect = program.dialect;
    post.programNumber = options.programNumber;
    post.tool = options.tool;
    post.boringTool = options.boringTool;
    post.spindle = program.spindle;
    post.header = programHeader(project, program, headerOptions);
    if (program.boring) {
        post.toolChangeAt = {project.part.length_mm() + inputs.boring->bar.overhang_mm + options.clearance_mm,
                             0.5 * program.path.safeDiameter_mm};
        post.boringToolLine =
            Programs::tr("Tool %1: boring bar %2 (D%3 mm, overhang %4 mm), insert %5")
                .arg(options.boringTool)
                .arg(inputs.boring->holderCode, QString::number(inputs.boring->bar.diameter_mm, 'f', 1),
                     QString::number(inputs.boring->bar.overhang_mm, 'f', 1), project.boringTool->insertCode);
    }
    program.programNumber = options.programNumber;
    program.text =
        postProcess(program.path, program.boring ? &*program.boring : nullptr, project.part.length_mm(), post);
    program.checksum = QString::fromLatin1(
        QCryptographicHash::hash(program.text.toUtf8(), QCryptographicHash::Sha256).toHex().left(16));
    Diagnostics ignored; // the deviation model has reported them already
    program.passes = passSummaries(program.path, program.spindle, projectForceModel(project, data, ignored));
    if (program.boring) {
        const std::vector<PassSummary> bore =
            passSummaries(*program.boring, program.spindle, boringForceModel(project, data));
        program.passes.insert(program.passes.end(), bore.begin(), bore.end());
    }
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
