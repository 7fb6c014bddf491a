// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace tolturn {

// Kinematics and power of turning (any machining textbook, e.g. Kalpakjian & Schmid,
// Manufacturing Engineering and Technology, §23.2).
// n = 1000 v / (pi D)  [rpm], v in m/min, D in mm
[[nodiscard]] double spindleSpeed_rpm(double cuttingSpeed_m_min, double diameter_mm);
// P = Fc v  [kW], Fc in N, v in m/min
[[nodiscard]] double cuttingPower_kW(double cuttingForce_N, double cuttingSpeed_m_min);
// T = Fc D / 2  [N·m]
[[nodiscard]] double spindleTorque_Nm(double cuttingForce_N, double diameter_mm);

// Theoretical (kinematic) roughness of a round-nosed tool, f < 2 r_eps (e.g. Shaw, Metal Cutting
// Principles, 2nd ed., OUP 2005, §21): Ra ≈ f² / (32 r_eps), Rz ≈ f² / (8 r_eps). Results in µm.
[[nodiscard]] double theoreticalRa_um(double feed_mm_rev, double noseRadius_mm);
[[nodiscard]] double theoreticalRz_um(double feed_mm_rev, double noseRadius_mm);
// The same relations solved for the largest feed [mm/rev] that leaves a roughness, and for the
// smallest nose radius [mm] that leaves it at a feed: f = sqrt(32 r Ra), r = f² / (32 Ra) (Rz: 8).
[[nodiscard]] double feedForRa_mm_rev(double ra_um, double noseRadius_mm);
[[nodiscard]] double feedForRz_mm_rev(double rz_um, double noseRadius_mm);
[[nodiscard]] double noseRadiusForRa_mm(double ra_um, double feed_mm_rev);
[[nodiscard]] double noseRadiusForRz_mm(double rz_um, double feed_mm_rev);

// Taylor (1907), v T^n = C: the constant C [m/min] from a speed v [m/min] that gives a tool life
// T [min], as an insert catalogue states its recommended speed at a reference life.
[[nodiscard]] double taylorConstant_m_min(double cuttingSpeed_m_min, double toolLife_min, double exponent);
// The same solved for the highest cutting speed [m/min] that gives at least a tool life T [min]:
// v = C T^-n.
[[nodiscard]] double speedForToolLife_m_min(double taylorC_m_min, double toolLife_min, double exponent);

} // namespace tolturn
