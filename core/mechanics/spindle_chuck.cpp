// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/mechanics/spindle_chuck.h"

#include <Eigen/LU>

namespace tolturn {

Matrix2 chuckFaceCompliance(const SpindleChuckSprings &s)
{
    const double lc = s.pivotDistance_mm;
    Matrix2 c;
    c << 1.0 / s.k1_N_per_mm + lc * lc / s.k2_Nmm_per_rad, lc / s.k2_Nmm_per_rad, lc / s.k2_Nmm_per_rad,
        1.0 / s.k2_Nmm_per_rad + 1.0 / s.k3_Nmm_per_rad;
    return c;
}

Matrix2 chuckFaceStiffness(const SpindleChuckSprings &springs)
{
    return chuckFaceCompliance(springs).inverse();
}

double spindleChuckDeflection(const SpindleChuckSprings &s, double force_N, double moment_Nmm, double z_mm)
{
    const double lc = s.pivotDistance_mm;
    const double rot = 1.0 / s.k2_Nmm_per_rad + 1.0 / s.k3_Nmm_per_rad;
    return force_N * rot * z_mm * z_mm + (2.0 * force_N * lc / s.k2_Nmm_per_rad + moment_Nmm * rot) * z_mm +
           force_N / s.k1_N_per_mm + force_N * lc * lc / s.k2_Nmm_per_rad + moment_Nmm * lc / s.k2_Nmm_per_rad;
}

double ToolpostCompliance::compliance_mm_per_N() const
{
    double c = 0.0;
    if (toolArea_mm2 > 0.0 && toolModulus_MPa > 0.0)
        c += toolLength_mm / (toolArea_mm2 * toolModulus_MPa);
    if (holderArea_mm2 > 0.0 && holderModulus_MPa > 0.0)
        c += holderLength_mm / (holderArea_mm2 * holderModulus_MPa);
    return c;
}

} // namespace tolturn
