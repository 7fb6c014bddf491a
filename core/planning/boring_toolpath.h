// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The boring passes of a set-up: the bore open at its free (right) end, cut by the boring bar from
// the pilot hole to the finishing allowance and finished along the contour the verdicts assume.

#include "core/planning/toolpath.h"

#include <optional>

namespace tolturn {

// What the path needs of the boring bar: its section and reach, and its insert.
struct BoringBarGeometry {
    QString holderCode;
    double barDiameter_mm = 0.0;
    double edgeOffset_mm = 0.0; // cutting edge from the bar's axis, the maker's f
    double overhang_mm = 0.0;   // out of its clamping to the cutting edge
    double noseRadius_mm = 0.0;
    std::optional<double> trailingEdgeAngle_deg;
    std::optional<double> pilotHoleDiameter_mm; // the hole drilled (or cored) before the bar starts
};

// The bore is computed on its mirror image about the axis (r -> -r), where it is an outer contour:
// the roughing levels and the finishing pass are those of turning (toolpath_detail.h), mirrored
// back; the nose is compensated to the left of the travel (G41) and the imaginary tool tip is r_e
// above and r_e left of the nose centre (the point a boring bar is touched off with on a bore and
// a face).
//  - Roughing: from the pilot hole outwards, at the depths of the project's roughing passes in
//    order (the last one repeated until the finishing allowance is reached; the bores share the
//    turning tool's conditions), each level cut from the free end towards the bottom of the bore.
//    Without a pilot hole the bore is taken as roughed to its finishing allowance before this
//    program, and the program says so.
//  - Finishing: the inner target contour (targetContour(), the compensation plan applied) from the
//    free end to the bottom of the bore, the bottom face down to the pilot hole (or as far as the
//    bar reaches it without touching the opposite wall).
//  - The bar reaches no deeper than its overhang less the clearance from the end face; a bar that
//    does not fit the hole it moves in, and what it cannot reach, are warnings.
// Returns no path when the set-up bores nothing (no bore open at the free end, or another set-up's).
[[nodiscard]] std::optional<Toolpath> boringToolpath(const Project &project, const CuttingPass &finishing,
                                                     const std::vector<CuttingPass> &roughing,
                                                     const BoringBarGeometry &bar, const ToolpathOptions &options);

} // namespace tolturn
