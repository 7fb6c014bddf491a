// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The pieces the turning path (toolpath.cpp) and the boring path (boring_toolpath.cpp) share: a
// contour with its compensation as a chain in the order the tool meets it, the finishing pass
// along a chain, the roughing levels above an envelope, and the checks of a chain against the
// insert. They work in the frame of outer turning (the material above the contour, the tool
// above it, moving towards the chuck); the boring path uses them on its bore mirrored about the
// axis (r -> -r), where a bore looks like an outer contour.

#include "core/planning/path_geometry.h"
#include "core/planning/toolpath.h"

#include <QStringList>

#include <vector>

namespace tolturn::toolpath_detail {

inline constexpr double kEnvelopeStep_mm = 0.02; // grid of the roughing envelope; roughing needs no finer

// The contour as the tool meets it from the right, with the compensation plan applied (a constant
// offset moves a feature radially, a profile correction replaces it by its corrected stations; a
// radial step joins a moved feature to its neighbours), after the undercuts' recesses are
// bridged (withoutUndercuts).
[[nodiscard]] std::vector<PathElement> compensatedChain(const Contour &target, const CompensationPlan *plan);

// The outline a turning insert cuts of a contour with undercuts; `bridged` gets the ids left out.
[[nodiscard]] Contour withoutUndercuts(Contour contour, QStringList *bridged = nullptr);

// The chain up to where it first passes z = zMin (a limit of the nose centre) going left; a face that
// faces the free end is kept while the centre, faceReach_mm right of it, is within the limit.
[[nodiscard]] std::vector<PathElement> clippedAtLeft(const std::vector<PathElement> &chain, double zMin,
                                                     double faceReach_mm, bool bore);

// The point of an element where z = zCut (the element crosses it).
[[nodiscard]] ProfilePoint pointAtZ(const PathElement &e, double zCut);

// The smallest radius of the elements that run along z (faces do not count: G96 is clamped there).
[[nodiscard]] double smallestAxialRadius(const std::vector<PathElement> &chain);

// Mirror images about the axis (r -> -r, arcs turning the other way).
[[nodiscard]] std::vector<PathElement> mirrored(std::vector<PathElement> chain);
[[nodiscard]] std::vector<Segment> mirrored(std::vector<Segment> segments);
[[nodiscard]] ToolMove mirrored(ToolMove move);

// The finishing pass along `contour` (the chain from right to left, compensation applied): the
// nose handled as the options say (tip path or the control's compensation), entered along -z onto
// a faced end face or along the first element's line from beyond the end face at z = partLength,
// left straight up to the safe radius. Chains the nose cannot follow are warnings.
[[nodiscard]] PassPath contourPass(const std::vector<PathElement> &contour, bool faced, const CuttingPass &conditions,
                                   const ToolpathOptions &options, double noseRadius_mm, double safeRadius,
                                   double partLength_mm, QStringList &warnings);

// The roughing levels below `stockLevel` (nose-centre coordinates, the stock's radius plus r_e),
// one per pass of `roughing`, above the envelope of the allowance: each cut from the right
// wherever the allowance lies below the level, then up the flanks to the level above. Returns the
// level the last pass leaves.
double roughLevels(std::vector<PassPath> &passes, const std::vector<CuttingPass> &roughing, const Envelope &env,
                   double stockLevel, double safeRadius, double noseRadius_mm, double clearance_mm);

// The largest stock above the allowance that no level above `lastLevel` takes, on the part
// (z <= partLength): more than a tenth of the allowance is what the finishing pass would cut.
[[nodiscard]] double stockLeftAboveAllowance(const Envelope &env, double lastLevel, double partLength_mm);

// The steepest a tool may descend towards the headstock (or, mirrored, a boring bar away from
// the axis) without its trailing edge touching the surface behind it: the trailing edge's angle
// less the free cutting angle profiling needs.
[[nodiscard]] double rideAngle_deg(double trailing_deg);

// What the trailing edge leaves of a contour a tool follows towards the headstock, each stretch
// ridden over a warning; a fall the nose's corner cuts (r_e (1 - cos kappa'), the micrometre steps of
// a compensated path, say) is left unsaid.
void warnWhereTheToolRidesOver(const std::vector<RiddenOver> &ridden, double trailing_deg, double noseRadius_mm,
                               QStringList &warnings);

} // namespace tolturn::toolpath_detail
