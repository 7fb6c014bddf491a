// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/planning_report.h"

#include "core/planning/gcode.h"

#include <utility>

namespace tolturn {

PlanningReport runPlanningJob(const Project &project, const DataLibrary &data, const PlanningJobOptions &options)
{
    PlanningReport report;
    const PlanningProblem::BuildResult built =
        PlanningProblem::build(project, data, StiffnessEnd::Compliant, options.learned);
    report.diagnostics = built.diagnostics;
    report.problem = built.problem;
    if (!built.problem)
        return report;
    // Shares of the work: optimisation 40 %, window 30 %, clamping 30 %.
    OptimisationOptions o;
    o.progress = Progress(options.progress, 0.0, 0.4);
    report.plan = optimisePlan(*built.problem, o);
    if (report.plan.cancelled) {
        report.cancelled = true;
        return report;
    }
    WindowOptions w;
    w.columns = w.rows = options.windowSize;
    w.progress = Progress(options.progress, 0.4, 0.7);
    report.window = cuttingWindow(*built.problem, options.plane, report.plan.candidate, w);
    if (report.window.cancelled) {
        report.cancelled = true;
        return report;
    }
    if (options.adviseClamping) {
        OptimisationOptions c;
        c.progress = Progress(options.progress, 0.7, 1.0);
        report.clamping = adviseClamping(project, data, c);
        if (c.progress.stopped()) { // a ranking of stopped searches is no ranking
            report.clamping.clear();
            report.cancelled = true;
            return report;
        }
    }
    (void)options.progress.report(1.0);
    return report;
}

FinishingOutput finishingOutput(const Project &project, const DataLibrary &data, const GCodeOptions &options)
{
    return finishingOutputFor(project, data, computeDeviation(project, data, {}), options);
}

FinishingOutput finishingOutputFor(const Project &project, const DataLibrary &data, DeviationResult deviation,
                                   const GCodeOptions &options)
{
    FinishingOutput out;
    out.deviation = std::move(deviation);
    if (!out.deviation.inputs)
        return out;
    out.compensation = planCompensation(project, out.deviation, evaluateTolerances(project, out.deviation));
    GCodeOptions g = options;
    g.compensation = nullptr;
    out.nominal = turningProgram(project, data, *out.deviation.inputs, g);
    g.compensation = &out.compensation;
    out.compensated = turningProgram(project, data, *out.deviation.inputs, g);
    return out;
}

} // namespace tolturn
