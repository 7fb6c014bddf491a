// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/planning/planning_problem.h"

#include <QString>

namespace tolturn {

// What it would take to meet a constraint that the least-violating plan violates, where a closed
// form says it: the feed or the nose radius a roughness limit needs, the cutting speed or the
// Taylor constant a tool life needs (docs/planning.md §3), each limit rounded
// to its safe side. Empty for any other constraint: its
// value against its limit, with the verdicts' required stiffness for a tolerance, already says
// how far off the plan is.
[[nodiscard]] QString whatItWouldTake(const PlanningProblem &problem, const ConstraintValue &violated);

} // namespace tolturn
