// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/mechanics/boring_bar.h"

namespace tolturn {

BoringBarCompliance boringBarCompliance(const BoringBar &bar)
{
    const RoundSection section{0.5 * bar.diameter_mm, 0.5 * bar.coolantBore_mm};
    const double e = bar.material.youngsModulus_MPa;
    const double g = bar.material.shearModulus_MPa();
    const double i = section.secondMoment_mm4();
    const double l = bar.overhang_mm;
    BoringBarCompliance c;
    if (!(e > 0.0) || !(i > 0.0) || !(l > 0.0))
        return c;
    c.bending_mm_per_N = l * l * l / (3.0 * e * i);
    c.tipMoment_mm_per_Nmm = l * l / (2.0 * e * i);
    c.torsion_rad_per_Nmm = l / (g * 2.0 * i); // polar moment J = 2 I of a round section
    if (bar.material.shearDeformation) {
        const double m = bar.diameter_mm > 0.0 ? bar.coolantBore_mm / bar.diameter_mm : 0.0;
        c.shear_mm_per_N = l / (cowperShearCoefficient(m, bar.material.poissonRatio) * g * section.area_mm2());
    }
    return c;
}

BoringBarDeflection boringBarDeflection(const BoringBar &bar, const BoringBarCompliance &c, double radial_N,
                                        double tangential_N, double axial_N)
{
    const double e = bar.edgeOffset_mm;
    return {radial_N * c.transverse_mm_per_N() - axial_N * e * c.tipMoment_mm_per_Nmm,
            tangential_N * (c.transverse_mm_per_N() + e * e * c.torsion_rad_per_Nmm)};
}

} // namespace tolturn
