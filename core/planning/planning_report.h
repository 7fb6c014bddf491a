// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/progress.h"
#include "core/planning/clamping_advisor.h"
#include "core/planning/compensation.h"
#include "core/planning/cutting_window.h"
#include "core/planning/gcode.h"

#include <functional>

namespace tolturn {

// Everything the planning view shows, computed in one go off the GUI thread: the optimum, the
// cutting window around it, the clamping ranking.
struct PlanningReport {
    std::shared_ptr<const PlanningProblem> problem;
    PlanResult plan;
    CuttingWindow window;
    std::vector<ClampingOption> clamping;
    Diagnostics diagnostics;
    bool cancelled = false;
};

struct PlanningJobOptions {
    WindowPlane plane = WindowPlane::FeedSpeed;
    int windowSize = 128;
    bool adviseClamping = true;
    Progress progress; // a stop cancels
    // What was learned of the machine, when the planner plans with it (PlanningProblem::build).
    std::shared_ptr<const LoadedModel> learned;
};

[[nodiscard]] PlanningReport runPlanningJob(const Project &project, const DataLibrary &data,
                                            const PlanningJobOptions &options);

// The compensation of the project's own finishing pass and its finishing program, nominal or
// compensated (cheap: the deviation of one pass).
// The finishing verdicts' compensation plan and the programs with and without it, in the dialect
// and nose handling of `options` (its compensation pointer is ignored).
struct FinishingOutput {
    DeviationResult deviation;
    CompensationPlan compensation;
    TurningProgram nominal;
    TurningProgram compensated;
};

[[nodiscard]] FinishingOutput finishingOutput(const Project &project, const DataLibrary &data,
                                              const GCodeOptions &options = {});
// The same from a deviation the caller computed (with what was learned added, say): the
// compensation is planned from that prediction.
[[nodiscard]] FinishingOutput finishingOutputFor(const Project &project, const DataLibrary &data,
                                                 DeviationResult deviation, const GCodeOptions &options = {});

} // namespace tolturn
