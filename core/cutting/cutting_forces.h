// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"

#include <optional>
#include <vector>

namespace tolturn {

// Cutting force components in longitudinal turning, as they act on the workpiece: tangential
// (the cutting force Fc, along the cutting speed), axial (the feed force Ff, along the feed) and
// radial (the passive force Fp, pushing tool and part apart). Newtons.
struct CuttingForces {
    double tangential_N = 0.0;
    double axial_N = 0.0;
    double radial_N = 0.0;
};

// ---- Kienzle (DIN 6584 notation) -----------------------------------------------------------
// F_i = k_i1.1 · b · h^(1 - m_i),  h = f sin(kappa_r),  b = a_p / sin(kappa_r)
// (O. Kienzle, "Die Bestimmung von Kräften und Leistungen an spanenden Werkzeugen und
// Werkzeugmaschinen", VDI-Z 94 (1952) 299–305). Constants are for h and b in mm.
struct KienzleLaw {
    double k11_MPa = 0.0; // force per mm of width at h = 1 mm
    double m = 0.0;
};

struct KienzleConstants {
    KienzleLaw cutting;
    // Feed and passive force: their own Kienzle laws, or fixed ratios to the cutting force.
    std::optional<KienzleLaw> feed;
    std::optional<KienzleLaw> passive;
    double feedToCuttingRatio = 0.0;
    double passiveToCuttingRatio = 0.0;
    // Chip-thickness range the constants were measured over (mm); 0 = not stated.
    double validChipThicknessMin_mm = 0.0;
    double validChipThicknessMax_mm = 0.0;
};

struct ForceResult {
    CuttingForces forces;
    Diagnostics warnings; // conditions outside the model's stated validity
};

// With a nose radius r_n > 0 the chip section is taken at the equivalent entering angle
// kappa_eq = 90° - gamma_Le, gamma_Le the effective lead angle of Li & Du (2002) eq. 20, at every
// depth (their fit, continuous in the depth; a switch to kappa_r at a depth ratio would make the
// forces jump), so h = f sin(kappa_eq), b = a_p / sin(kappa_eq); and the thrust in the
// reference plane, (Ff, Fp) as the constants give them for the holder's entering angle kappa_r,
// turns towards the radial by kappa_r - kappa_eq, as the friction force follows gamma_Le in their
// eq. 18–19. Outside eq. 20's stated ranges the result carries a warning (docs/model.md §3).
[[nodiscard]] ForceResult kienzleForces(const KienzleConstants &constants, double feed_mm_rev, double depthOfCut_mm,
                                        double enteringAngle_rad, double noseRadius_mm = 0.0);
// The entering angle the chip section is taken at: kappa_eq for a nose radius as above, else kappa_r.
[[nodiscard]] double equivalentEnteringAngle_rad(double enteringAngle_rad, double noseRadius_mm, double feed_mm_rev,
                                                 double depthOfCut_mm, Diagnostics *warnings = nullptr);

// ---- Li & Du (2002), oblique mechanistic model (eq. 15–20) ---------------------------------
// X. Li, R. Du, "Analysis and compensation of workpiece errors in turning", Int. J. Prod. Res.
// 40(7) (2002) 1647–1667, §3.3.3, after Stephenson & Bandyopadhyay (1995) and Nair et al. (1999).
struct LiDuCoefficients {
    double normalPressure_MPa = 0.0; // K_n = N / A_c (eq. 15a)
    double frictionRatio = 0.0;      // K_f = P / N (eq. 15b)
};

struct LiDuToolGeometry {
    double normalRake_rad = 0.0; // alpha
    double backRake_rad = 0.0;   // alpha_b
    double leadAngle_rad = 0.0;  // gamma_L = 90° - kappa_r
    double noseRadius_mm = 0.0;  // r_n
};

// Uncut chip area after the first revolution (eq. 16a/16b).
[[nodiscard]] double liDuUncutChipArea_mm2(double feed_mm_rev, double depthOfCut_mm, double noseRadius_mm);
// Effective lead angle (eq. 20), with warnings naming the validity ranges the paper states.
[[nodiscard]] double liDuEffectiveLeadAngle_rad(const LiDuToolGeometry &tool, double feed_mm_rev, double depthOfCut_mm,
                                                Diagnostics *warnings = nullptr);
// Forces (eq. 17–19).
[[nodiscard]] ForceResult liDuForces(const LiDuCoefficients &coefficients, const LiDuToolGeometry &tool,
                                     double feed_mm_rev, double depthOfCut_mm);

// One measured cut for calibrating K_n and K_f: conditions and the measured Ft and Fa.
struct ForceMeasurement {
    double feed_mm_rev = 0.0;
    double depthOfCut_mm = 0.0;
    double tangential_N = 0.0;
    double axial_N = 0.0;
};

struct LiDuCalibration {
    std::optional<LiDuCoefficients> coefficients;
    double rmsResidual_N = 0.0;
    Diagnostics diagnostics;
};

// The paper's calibration step (§3.3.3: "K_n and K_f can be estimated using equations (17) and
// (18)"). With p = K_n and q = K_n K_f, eq. 17 and 18 are linear in (p, q):
//   Ft = A_c (c1 p + c2 q),  Fa = A_c (c3 p + c4 q)
// so all measurements are fitted at once by linear least squares.
[[nodiscard]] LiDuCalibration calibrateLiDu(const LiDuToolGeometry &tool,
                                            const std::vector<ForceMeasurement> &measurements);

} // namespace tolturn
