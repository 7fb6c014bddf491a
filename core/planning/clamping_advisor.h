// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/planning/optimiser.h"

namespace tolturn {

// One way of holding the part, planned: whether the part allows it, the optimal plan, and why it
// ranks where it does.
struct ClampingOption {
    ClampingMethod method = ClampingMethod::Chuck;
    double clampedLength_mm = 0.0;
    bool possible = false;
    PlanResult plan;
    std::vector<ToleranceLeftOut> tolerancesNotHeld; // those this set-up cannot hold (a feature in the jaws)
    QString reason;
};

// The plan for chuck, between centres and chuck + tailstock, ranked (rankClampingOptions)
// (Valiño et al. 2008 §VII: the error model "can be useful for deciding the most suitable clamping
// method"). A chuck grips the first outer cylinder of the part, past the end face's edge break (the
// project's clamped length when it is held in a chuck already, else to that cylinder's end, at
// most a third of the part).
[[nodiscard]] std::vector<ClampingOption> adviseClamping(const Project &project, const DataLibrary &data,
                                                         const OptimisationOptions &options = {});

// The ranking adviseClamping gives: feasible plans that hold every tolerance by their objective
// (equal to the millionth: the one with more margin on its tightest tolerance first), then
// feasible plans that leave a tolerance to another set-up (a feature in the jaws) in the same
// order, then infeasible ones by how much they violate, then the methods the part does not allow.
// Stable: equal options keep their order.
void rankClampingOptions(std::vector<ClampingOption> &options);

} // namespace tolturn
