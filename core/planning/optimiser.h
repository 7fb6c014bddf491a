// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/progress.h"
#include "core/planning/planning_problem.h"

#include <functional>

namespace tolturn {

struct OptimisationOptions {
    int globalEvaluations = 600; // per number of roughing passes
    int localEvaluations = 300;
    // Wall-clock bound on the whole search; the best plan found by then is returned, marked
    // timedOut. The evaluation budgets bound it too; this bounds a part whose evaluations are slow.
    double timeLimit_s = 60.0;
    // Told now and then the fraction done; a stop cancels.
    Progress progress;
};

struct PlanResult {
    bool feasible = false;
    bool cancelled = false;
    bool timedOut = false; // stopped at OptimisationOptions::timeLimit_s: the best plan by then
    PlanCandidate candidate;
    CandidateEvaluation evaluation;
    std::vector<ConstraintValue> binding;   // within 1 % of their limit at the optimum
    std::vector<ConstraintValue> conflicts; // when infeasible: violated at the least-violating plan
    QStringList remedies;                   // what it would take to meet them, where a closed form says (remedies.h)
    int evaluations = 0;
    QStringList notes;
};

// Minimum time or cost per part over the cutting speed, feed and depth of the finishing pass and
// the speed and feed of the roughing passes, for every number of roughing passes the stock
// allows (docs/planning.md §2). For each number of passes: a global search (NLopt DIRECT-L on the
// objective with a penalty for violated constraints) and a local refinement with the constraints
// themselves (NLopt COBYLA). When no plan meets every constraint, the plan that violates them
// least is reported with the constraints it violates and by how much.
[[nodiscard]] PlanResult optimisePlan(const PlanningProblem &problem, const OptimisationOptions &options = {});

// The box of the variables for `roughingPasses` passes: finishing speed, feed, depth, roughing
// speed, feed. Empty (lo > hi in some coordinate) when that number of passes cannot take the stock.
struct PlanBox {
    std::vector<double> lower;
    std::vector<double> upper;
    [[nodiscard]] bool empty() const;
};

[[nodiscard]] PlanBox planBox(const PlanningProblem &p, int k);
[[nodiscard]] PlanCandidate candidateAt(const std::vector<double> &x, int roughingPasses);

} // namespace tolturn
