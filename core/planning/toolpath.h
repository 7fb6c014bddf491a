// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The tool paths of a turning plan, independent of any control's dialect: the roughing passes
// the plan takes off the stock and the finishing pass along the contour the verdicts assume.
// The post-processors (post_processor.h) turn them into programs.

#include "core/planning/compensation.h"
#include "core/project/project.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace tolturn {

// Arcs are turned as seen with z to the right and r upwards, which is the ISO 6983 sense in the
// G18 plane seen from +Y: clockwise there is G02.
enum class MoveKind { Rapid, Feed, ArcClockwise, ArcCounterClockwise };

// One move to a point of the half-section (z from the part's left end, r from the axis) [mm].
struct ToolMove {
    MoveKind kind = MoveKind::Feed;
    ProfilePoint to;
    ProfilePoint centre;                 // arcs
    double radius_mm = 0.0;              // arcs
    QString featureId;                   // the feature the move finishes; empty for roughing and air moves
    bool startsNoseCompensation = false; // the entry move of G42 (control compensates)
    bool endsNoseCompensation = false;   // the exit move of G40
    std::optional<double> feed_mm_rev;   // a feed of its own (feed_schedule.h); unset: the pass's
};

// How the nose radius r_e is taken into account in the finishing pass.
//  - ControlCompensation: the program is the contour; the control offsets it by its own tool data
//    (G41/G42, ISO 6983-1 "tool nose radius compensation"), which the program's header names.
//  - TipPath: TolTurn offsets the contour itself: the nose centre runs at r_e from the contour,
//    and the program is the path of the imaginary tool tip, r_e below and r_e left of the nose
//    centre (the point a tool is touched off with on a diameter and on a face; tip position 3
//    on Fanuc-style controls), for controls without compensation.
enum class NoseHandling { ControlCompensation, TipPath };

struct PassPath {
    CuttingPass conditions;
    int number = 0; // 1, 2, … in the order the passes are cut
    std::vector<ToolMove> moves;
    double smallestDiameter_mm = 0.0; // the smallest diameter the pass cuts (not counting a face)
};

struct ToolpathOptions {
    NoseHandling nose = NoseHandling::ControlCompensation;
    const CompensationPlan *compensation = nullptr; // nullptr: the target contour as it is
    // Distance kept from the stock, the end face and the jaws in air moves, and the shortest
    // distance of the tool from the chuck jaws [mm]. A setting of the program, not a datum.
    double clearance_mm = kToolClearance_mm;
};

struct Toolpath {
    ContourSide side = ContourSide::Outer; // inner: a boring path (boring_toolpath.h), the nose left of the travel
    std::vector<PassPath> roughing;
    PassPath finishing;
    double noseRadius_mm = 0.0;
    double safeDiameter_mm = 0.0; // rapid moves along z happen at this diameter or above
    NoseHandling nose = NoseHandling::ControlCompensation;
    bool endFaceFaced = false; // the right end face is in the finishing pass
    QStringList notes;         // what the program does not do, and why (for its header and people)
    QStringList warnings;      // what a planner must resolve before running it
};

// Roughing: one level per planned roughing pass, a_p,1, a_p,2, … below the stock radius, each cut
// from the right towards the chuck wherever the stock reaches above the finishing allowance. The
// allowance is the finishing pass's depth of cut, measured along the normal of the contour from the
// nose circle: the nose centre stays a_p,f + r_e from the contour. After each level the tool climbs
// along the allowance to the level above, so no steps are left on cones, arcs and shoulders.
// Finishing: the outer target contour (targetContour(), with the compensation plan applied), from
// the right end face to the chuck jaws less the clearance. A right end face held by a centre is not
// faced (it was faced and centred before the part went between centres). Both passes stop short of
// the jaws; features the tool cannot reach from the right with its trailing edge are warnings.
[[nodiscard]] Toolpath turningToolpath(const Project &project, const CuttingPass &finishing,
                                       const std::vector<CuttingPass> &roughing, double noseRadius_mm,
                                       std::optional<double> trailingEdgeAngle_deg, const ToolpathOptions &options);

} // namespace tolturn
