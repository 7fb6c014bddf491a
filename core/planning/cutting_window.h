// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/progress.h"
#include "core/planning/optimiser.h"

#include <functional>

namespace tolturn {

enum class WindowPlane { FeedSpeed, FeedDepth };

// One point of the map: the objective there, and when a constraint is violated the one violated
// most (which is the constraint that makes the nearby boundary).
struct WindowCell {
    double x = 0.0; // feed [mm/rev]
    double y = 0.0; // cutting speed [m/min] or depth of cut [mm]
    double objective = 0.0;
    bool feasible = false;
    QString binding;      // constraint keyword, empty when feasible
    QString bindingLabel; // "tolerance T1", "roughness (Ra)", …
};

// The feasible region of the finishing pass in the feed–speed or feed–depth plane (Valiño et al.
// 2008 §VI; MODEL §4), the roughing passes and the third variable as in `base` (the optimum).
struct CuttingWindow {
    WindowPlane plane = WindowPlane::FeedSpeed;
    int columns = 0; // along the feed
    int rows = 0;    // along speed or depth
    ValueRange feed;
    ValueRange other;
    std::vector<WindowCell> cells; // row by row: cells[row * columns + column]
    PlanCandidate base;
    bool cancelled = false;

    [[nodiscard]] const WindowCell &at(int column, int row) const
    {
        return cells[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                     static_cast<std::size_t>(column)];
    }

    // Constraints that bound the feasible region somewhere in the map, with the number of cells
    // each one closes.
    [[nodiscard]] std::vector<std::pair<QString, int>> boundaries() const;
};

struct WindowOptions {
    int columns = 256;
    int rows = 256;
    int threads = 2;
    Progress progress; // a stop cancels
};

[[nodiscard]] CuttingWindow cuttingWindow(const PlanningProblem &problem, WindowPlane plane, const PlanCandidate &base,
                                          const WindowOptions &options = {});

} // namespace tolturn
