// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/part/profile.h"
#include "core/part/profile_geometry.h"

#include <utility>
#include <vector>

namespace tolturn {

// Elastic constants of the work material. MPa = N/mm².
struct ElasticMaterial {
    double youngsModulus_MPa = 0.0;
    double poissonRatio = 0.0;
    // Timoshenko (bending + shear) when true; Euler–Bernoulli (bending only) when false.
    bool shearDeformation = true;

    [[nodiscard]] double shearModulus_MPa() const { return youngsModulus_MPa / (2.0 * (1.0 + poissonRatio)); }
};

// Shear coefficient kappa of a circular tube with inner/outer radius ratio m = r_i / r_o
// (m = 0: solid), so that the shear deflection of a Timoshenko beam is V / (kappa G A):
//   kappa = 6 (1 + nu) (1 + m^2)^2 / [ (7 + 6 nu) (1 + m^2)^2 + (20 + 12 nu) m^2 ]
// G. R. Cowper, "The shear coefficient in Timoshenko's beam theory", J. Appl. Mech. 33(2),
// 335–340 (1966), Table 1 (hollow circle). For a solid bar this is 6(1+nu)/(7+6nu).
// The shear factor chi of Valiño et al. (2008) eq. 6 is 1 / kappa.
[[nodiscard]] double cowperShearCoefficient(double radiusRatio, double poissonRatio);

// Cross-section of a (possibly hollow) round bar.
struct RoundSection {
    double outerRadius_mm = 0.0;
    double innerRadius_mm = 0.0;

    [[nodiscard]] double area_mm2() const;
    [[nodiscard]] double secondMoment_mm4() const; // I = pi (r_o^4 - r_i^4) / 4
};

// The section of the part along z, as the beam sees it: outer radius from the outer contour
// (optionally increased by an allowance, the material a pass has not yet removed, capped at the
// stock), inner radius from the bore (reduced by an allowance for a bore not yet bored out).
class SectionAlongZ {
public:
    // `stockOuter_mm`: z ranges where the outer radius is still the stock's (features a later
    // operation turns, docs/operations.md); `solidInner_mm`: where a later operation bores, the
    // part is still solid.
    SectionAlongZ(const PartProfile &profile, double outerAllowance_mm = 0.0, double innerAllowance_mm = 0.0,
                  std::vector<std::pair<double, double>> stockOuter_mm = {},
                  std::vector<std::pair<double, double>> solidInner_mm = {});

    [[nodiscard]] RoundSection at(double z_mm) const;

    // z positions where the section changes its law (profile vertices): elements must not span them.
    [[nodiscard]] const std::vector<double> &breakpoints() const { return m_breakpoints; }

private:
    const PartProfile &m_profile;
    AxialSegments m_outer;
    AxialSegments m_inner;
    double m_outerAllowance_mm;
    double m_innerAllowance_mm;
    double m_stockRadius_mm;
    std::vector<std::pair<double, double>> m_stockOuter_mm;
    std::vector<std::pair<double, double>> m_solidInner_mm;
    std::vector<double> m_breakpoints;
};

} // namespace tolturn
