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

// The time of the same steps for many speeds and feeds (the planner evaluates thousands): the
// steps' middle radii sorted, with the running sums of their lengths from the axis outwards and
// of length x radius from the outside inwards. Under G96 with a limit, the steps on radii below
// r_c = 1000 v / (2 pi limit) run at the limit and the others at n = 1000 v / (2 pi r), so
// t = (sum below r_c of length / limit + sum above of length r 2 pi / (1000 v)) / f, found with one
// binary search; the same sum as feedTime_min. The steps' own feeds are not kept: the pass's feed
// throughout.
class FeedTimeTable {
public:
    FeedTimeTable() = default;
    explicit FeedTimeTable(const std::vector<FeedStep> &steps);

    [[nodiscard]] double time_min(double cuttingSpeed_m_min, double feed_mm_rev, double limit_rpm) const;

    [[nodiscard]] bool empty() const { return m_radius_mm.empty(); }

private:
    std::vector<double> m_radius_mm;  // middle radius of each step, ascending
    std::vector<double> m_lengthUpTo; // [i]: total length of steps 0..i-1
    std::vector<double> m_momentFrom; // [i]: total length x radius of steps i..n-1
};

} // namespace tolturn
