// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// How long a pass of a program takes: its feed moves cut into short steps, each at the spindle
// speed constant cutting speed (G96) asks for on its radius, under the program's spindle limit.
// The set-up sheet (gcode.h) and the planner (planning_problem.h) time the same path with it.

#include "core/planning/toolpath.h"

#include <optional>
#include <vector>

namespace tolturn {

// A short piece of a feed move: where it starts and ends, and the move's own feed if it has one.
struct FeedStep {
    ProfilePoint from;
    ProfilePoint to;
    std::optional<double> feed_mm_rev; // unset: the pass's feed
};

// Every feed and arc move of a pass in steps of at most 0.05 mm (n changes with r under G96), at
// most 2000 on a move: a face's time is then within far less than its 0.01 min as printed.
[[nodiscard]] std::vector<FeedStep> feedSteps(const PassPath &pass);

// Spindle speed on radius r under G96 with the limit: n = min(1000 v / (2 pi r), limit) [rpm].
[[nodiscard]] double g96SpindleSpeed_rpm(double cuttingSpeed_m_min, double r_mm, double limit_rpm);

// Time along the steps: sum of length / (f n(r)) with r the middle of each step [min].
[[nodiscard]] double feedTime_min(const std::vector<FeedStep> &steps, double cuttingSpeed_m_min, double feed_mm_rev,
                                  double limit_rpm);

} // namespace tolturn
