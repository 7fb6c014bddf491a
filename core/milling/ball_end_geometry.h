// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The geometry of a ball-end mill in the cut, after Öztürk & Budak (seed 001, in Turkish; MODEL
// §6): the local radius along the tool axis, the engagement limits of a disc element for a cut
// into uncut or previously cut material, and the lead–tilt transformation of five-axis milling.
// z is measured up the tool axis from the tip; angles in radians.

#include "core/milling/milling_kinds.h"

#include <Eigen/Core>

namespace tolturn {

// R(z) = sqrt(R_o² − (R_o − z)²) on the ball (001 eq. 4), R_o above it; 0 below the tip.
[[nodiscard]] double localRadius_mm(double ballRadius_mm, double z_mm);

// hc = R_o − sqrt(R_o² − (s − R(a))²) (001 eq. 3): below this height the edge does not cut when
// entering uncut material at radial depth s and axial depth a.
[[nodiscard]] double uncutEngagementHeight_mm(double ballRadius_mm, double radialDepth_mm, double axialDepth_mm);

// The scallop (cusp) height h = R_o − sqrt(R_o² − s² / 4) (001 eq. 5) of passes s apart.
[[nodiscard]] double scallopHeight_mm(double ballRadius_mm, double stepOver_mm);

struct Engagement {
    double entry_rad = 0.0; // φ_st
    double exit_rad = 0.0;  // φ_ex; equal to the entry where the element does not cut

    [[nodiscard]] bool cuts() const { return exit_rad > entry_rad; }
};

// The engagement limits of the disc element at height z (001 tables 1 and 2): cutting into uncut
// material (table 1) or beside a previous pass s away (table 2).
[[nodiscard]] Engagement uncutEngagement(double ballRadius_mm, double radialDepth_mm, double axialDepth_mm, double z_mm,
                                         MillingDirection direction);
[[nodiscard]] Engagement previouslyCutEngagement(double ballRadius_mm, double stepOver_mm, double z_mm,
                                                 MillingDirection direction);

// T(lead, tilt) (001 eq. 6): a point of the tool's frame (x, y, z) in the workpiece's (X, Y, Z).
// It is the rotation by the tilt about X after the rotation by the lead about Y.
[[nodiscard]] Eigen::Matrix3d leadTiltTransform(double lead_rad, double tilt_rad);

// κ = asin(R(z) / R_o) (001 eq. 9), the angle between the tool axis and the normal of the ball
// at height z.
[[nodiscard]] double axialImmersionAngle_rad(double ballRadius_mm, double z_mm);

} // namespace tolturn
