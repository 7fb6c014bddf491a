// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/project.h"

#include <QString>

#include <optional>
#include <vector>

namespace tolturn {

// The size a finishing program aims at for one diameter (MODEL §3: "whatever the verdicts assume
// the program to be, the G-code must program exactly that"): the middle of its tolerance zone.
struct DiameterTarget {
    QString featureId;
    double nominal_mm = 0.0;
    double upper_um = 0.0; // the zone the target is the middle of: every diameter tolerance of
    double lower_um = 0.0; // the feature intersected

    [[nodiscard]] double target_mm() const { return nominal_mm + 0.5e-3 * (upper_um + lower_um); }
};

// The middle of the zone of every cylinder that carries a diameter tolerance (ISO 286 class or
// explicit limit deviations). Sizes whose limits cannot be formed are left out (the verdicts say
// why); untoleranced sizes are aimed at nominal.
[[nodiscard]] std::vector<DiameterTarget> diameterTargets(const Project &project);

// A contour of the part with every toleranced cylinder moved radially to the middle of its zone.
// The chamfers, cones and edge rounds that join such a cylinder move with it (their shape is
// kept), and the faces between take up the difference in their length, as a programmer shifts a
// feature's chain when aiming at the middle of a zone. A vertex between two cylinders' chains
// (a cone joining two toleranced diameters directly) follows the nearer cylinder.
[[nodiscard]] Contour targetContour(const Project &project, ContourSide side);

// A station of a feature with a profile tolerance: the exact profile's slope dr/dz there and how
// far the program's target lies from it (aimed less nominal radius) [mm]. Both are fixed by the
// part and the program, not by the cutting conditions.
struct ProfileStationGeometry {
    double z_mm = 0.0;
    double slope = 0.0;
    double targetOffset_mm = 0.0;
};

struct ProfileGeometry {
    QString featureId;
    std::vector<ProfileStationGeometry> stations;
};

// Everything the program aims at, formed once: for callers that evaluate one project many times.
// `profiles`, where given (addProfileGeometry, evaluation.h), holds the profile tolerances'
// station geometry for the stations a planner evaluates over and over.
struct ProgramTargets {
    std::vector<DiameterTarget> diameters;
    Contour outer;
    Contour inner;
    std::vector<ProfileGeometry> profiles;
};

[[nodiscard]] ProgramTargets programTargets(const Project &project);

// The radius the finishing program aims at on a feature at z: the target contour's.
[[nodiscard]] std::optional<double> targetRadius_mm(const Contour &target, const QString &featureId, double z_mm);

} // namespace tolturn
