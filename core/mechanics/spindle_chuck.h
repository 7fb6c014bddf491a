// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/mechanics/beam.h"

namespace tolturn {

// Spring model of the spindle–chuck unit in one direction (Valiño et al. 2008 §II eq. 3–4,
// after Mladenov 2002): a rigid body held by a translational spring k1 at the chuck face, a
// rotational spring k2 about a pivot Lc behind the chuck face (the spindle bearings) and a
// rotational spring k3 at the chuck face (the jaws).
struct SpindleChuckSprings {
    double k1_N_per_mm = 0.0;
    double k2_Nmm_per_rad = 0.0;
    double k3_Nmm_per_rad = 0.0;
    double pivotDistance_mm = 0.0; // Lc
};

// Compliance of the chuck face on (shear V, moment M) applied there, derived in docs/model.md §2:
//   w = V/k1 + Lc (V Lc + M)/k2,   theta = (V Lc + M)/k2 + M/k3
[[nodiscard]] Matrix2 chuckFaceCompliance(const SpindleChuckSprings &springs);
// Its inverse: the 2x2 spring matrix that holds the beam at the chuck face.
[[nodiscard]] Matrix2 chuckFaceStiffness(const SpindleChuckSprings &springs);

// Deflection of a rigid part at distance z from the chuck face under a force F there and the
// moment M of the feed force about the part's axis line (M = -F_a D/2 when it opposes F):
//   delta_sc(z) = F (1/k2 + 1/k3) z^2 + [2 F Lc/k2 + M (1/k2 + 1/k3)] z + F/k1 + F Lc^2/k2 + M Lc/k2
// With M = -F_a D/2 the z^2 and constant terms are those printed in Valiño et al. (2008) eq. 3;
// the printed z term (F_a/2)(D/k3 - (D - 2F_r)/k2) is dimensionally inconsistent and is
// replaced by the one the mechanics gives (docs/model.md §2).
[[nodiscard]] double spindleChuckDeflection(const SpindleChuckSprings &springs, double force_N, double moment_Nmm,
                                            double z_mm);

// Axial shortening of tool and holder under the radial force, which moves the tool tip away
// from the part (Valiño et al. 2008 eq. 5; the sign there belongs to their force convention,
// here a positive result is a larger machined radius):
//   delta_tp = F_r (l_t / (A_t E_t) + l_h / (A_h E_h))
struct ToolpostCompliance {
    double toolLength_mm = 0.0;
    double toolArea_mm2 = 0.0;
    double toolModulus_MPa = 0.0;
    double holderLength_mm = 0.0;
    double holderArea_mm2 = 0.0;
    double holderModulus_MPa = 0.0;

    [[nodiscard]] double compliance_mm_per_N() const;
};

} // namespace tolturn
