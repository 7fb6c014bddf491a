// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A milled feature of a mill-turn part (issue 19; docs/milling.md "Milled features"): a flat, a
// keyway or a surface patch given by its tool path, with the ball-end tool that mills it, its
// conditions, its cutting coefficients and its tolerance (ISO 1101 flatness or profile of a
// surface). Whatever is not given yet is absent, and the feature is then listed but not evaluated,
// with what is missing named (an imported flat has only its place on the part).

#include "core/adaptive/end_milling.h"
#include "core/milling/milling_kinds.h"

#include <QString>
#include <QStringList>

#include <array>
#include <optional>
#include <vector>

namespace tolturn {

enum class MilledFeatureKind { Flat, Keyway, Patch };

// The solid ball-end mill and what holds it (001 fig. 1, table 3).
struct BallEndTool {
    double diameter_mm = 0.0;
    int flutes = 0;
    double helix_deg = 0.0;
    double overhang_mm = 0.0;           // from where the holder grips the tool to its tip
    double equivalentDiameter_mm = 0.0; // of the cylinder that stands for the fluted tool
    // Unset: carbide's (kCarbideModulus_N_mm2, with its source), and the results say so.
    std::optional<double> youngsModulus_N_mm2;
    // The holder's springs (001 table 3). No default: they belong to a tool in its holder on its
    // machine, and a rigid holder is not assumed.
    std::optional<double> holderStiffness_N_mm;
    std::optional<double> holderRotational_N_mm_rad;

    friend bool operator==(const BallEndTool &, const BallEndTool &) = default;
};

struct MillingConditions {
    BallEndCutKind cut = BallEndCutKind::Slot;
    MillingDirection direction = MillingDirection::Down;
    double axialDepth_mm = 0.0;
    double radialDepth_mm = 0.0; // the width of a side cut or the step-over; not used in a slot
    double feedPerTooth_mm = 0.0;
    double spindle_rpm = 0.0;
    // The tool axis from the surface normal: the lead about the cross-feed direction, the tilt about
    // the feed direction (001 eq. 6). A patch's path gives them point by point instead.
    double lead_deg = 0.0;
    double tilt_deg = 0.0;

    friend bool operator==(const MillingConditions &, const MillingConditions &) = default;
};

// Flatness, or a profile of a surface (ISO 1101 §18.6, §18.5): without datums the zone floats,
// with datums it is located on the programmed surface.
enum class MilledToleranceType { Flatness, Profile };

struct MilledTolerance {
    MilledToleranceType type = MilledToleranceType::Flatness;
    double zone_um = 0.0;
    QStringList datums; // a profile's; a flatness has none

    friend bool operator==(const MilledTolerance &, const MilledTolerance &) = default;
};

// A cutter-location point of a patch's tool path, in the part's frame (z along the part axis): the
// tip of the ball, the tool axis (from the tip towards the holder) and the surface normal under the
// tool (out of the material). The feed direction is the path's own, from point to point.
struct ClPoint {
    std::array<double, 3> position_mm{};
    std::array<double, 3> toolAxis{};
    std::array<double, 3> surfaceNormal{};

    friend bool operator==(const ClPoint &, const ClPoint &) = default;
};

struct MilledFeature {
    QString id; // "M1"
    MilledFeatureKind kind = MilledFeatureKind::Flat;
    QString description; // the planner's, or the faces of the STEP file it came from
    double zFrom_mm = 0.0;
    double zTo_mm = 0.0; // its extent along the part axis
    std::optional<BallEndTool> tool;
    std::optional<MillingConditions> conditions;
    std::optional<MillingForceCoefficients> coefficients;
    QString coefficientsSource; // where the planner's coefficients come from
    std::optional<MilledTolerance> tolerance;
    std::vector<ClPoint> path; // a patch's; a flat or a keyway is one straight cut

    friend bool operator==(const MilledFeature &, const MilledFeature &) = default;
};

} // namespace tolturn
