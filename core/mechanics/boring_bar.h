// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/mechanics/section.h"

namespace tolturn {

// A boring bar held in the turret: a round cantilever along the part's axis, clamped at one end,
// loaded at the cutting edge, which stands `edgeOffset_mm` off the bar's axis towards the bore
// wall (the maker's functional dimension f). A coolant bore makes the section a tube.
struct BoringBar {
    double diameter_mm = 0.0;
    double coolantBore_mm = 0.0;
    double overhang_mm = 0.0; // from the clamping to the cutting edge
    double edgeOffset_mm = 0.0;
    ElasticMaterial material;

    [[nodiscard]] double overhangRatio() const { return diameter_mm > 0.0 ? overhang_mm / diameter_mm : 0.0; }
};

// Flexibilities of the bar at its tip (docs/model.md §3.1):
//   bending  L^3 / (3 E I)         (Euler–Bernoulli cantilever under a tip force)
//   shear    L / (kappa G A)       (Timoshenko; kappa of Cowper 1966 for the round section)
//   moment   L^2 / (2 E I)         (tip deflection under a tip moment)
//   torsion  L / (G J)             (twist under a torque, J = 2 I for a round section)
struct BoringBarCompliance {
    double bending_mm_per_N = 0.0;
    double shear_mm_per_N = 0.0;
    double tipMoment_mm_per_Nmm = 0.0;
    double torsion_rad_per_Nmm = 0.0;

    // Tip deflection per unit transverse force at the tip: bending + shear.
    [[nodiscard]] double transverse_mm_per_N() const { return bending_mm_per_N + shear_mm_per_N; }
};

[[nodiscard]] BoringBarCompliance boringBarCompliance(const BoringBar &bar);

// Where the bar's deflection leaves the cutting edge, in the directions of the turning model:
// radial as material left on the bore (positive: the bore too small), tangential along the
// cutting speed. Under the passive force F_r (pushing the edge off the wall), the cutting force
// F_t and the feed force F_a (along the bar, towards its clamping, at the edge's offset e):
//   radial      = F_r (L^3/3EI + L/kGA) - F_a e L^2/2EI
//   tangential  = F_t (L^3/3EI + L/kGA) + F_t e^2 L/GJ
// The feed force's moment F_a e bends the tip towards the wall (the fibres on the edge's side
// are compressed more), so it takes material off; the torque F_t e turns the edge, at e from
// the axis, along the cutting speed.
struct BoringBarDeflection {
    double radial_mm = 0.0;
    double tangential_mm = 0.0;
};

[[nodiscard]] BoringBarDeflection boringBarDeflection(const BoringBar &bar, const BoringBarCompliance &c,
                                                      double radial_N, double tangential_N, double axial_N);

} // namespace tolturn
