// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/mechanics/section.h"

#include "core/part/profile_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

namespace tolturn {

double cowperShearCoefficient(double radiusRatio, double poissonRatio)
{
    const double m2 = radiusRatio * radiusRatio;
    const double a = (1.0 + m2) * (1.0 + m2);
    const double nu = poissonRatio;
    return 6.0 * (1.0 + nu) * a / ((7.0 + 6.0 * nu) * a + (20.0 + 12.0 * nu) * m2);
}

double RoundSection::area_mm2() const
{
    return std::numbers::pi * (outerRadius_mm * outerRadius_mm - innerRadius_mm * innerRadius_mm);
}

double RoundSection::secondMoment_mm4() const
{
    const double ro2 = outerRadius_mm * outerRadius_mm;
    const double ri2 = innerRadius_mm * innerRadius_mm;
    return 0.25 * std::numbers::pi * (ro2 * ro2 - ri2 * ri2);
}

SectionAlongZ::SectionAlongZ(const PartProfile &profile, double outerAllowance_mm, double innerAllowance_mm,
                             std::vector<std::pair<double, double>> stockOuter_mm,
                             std::vector<std::pair<double, double>> solidInner_mm)
    : m_profile(profile)
    , m_outer(profile.outer)
    , m_inner(profile.inner)
    , m_outerAllowance_mm(outerAllowance_mm)
    , m_innerAllowance_mm(innerAllowance_mm)
    , m_stockRadius_mm(0.5 * profile.stockDiameter_mm)
    , m_stockOuter_mm(std::move(stockOuter_mm))
    , m_solidInner_mm(std::move(solidInner_mm))
{
    std::set<double> breaks;
    for (const Contour *c : {&profile.outer, &profile.inner}) {
        for (const Segment &s : c->segments) {
            breaks.insert(s.from.z_mm);
            breaks.insert(s.to.z_mm);
            // An undercut radius's furthest point along z, where the section changes its rule.
            if (s.kind == SegmentKind::Radius && s.turnsBack()) {
                if (const auto arc = arcGeometry(s)) {
                    const auto [lo, hi] = zRange(*arc);
                    breaks.insert(lo);
                    breaks.insert(hi);
                }
            }
        }
    }
    m_breakpoints.assign(breaks.begin(), breaks.end());
}

RoundSection SectionAlongZ::at(double z_mm) const
{
    // Inside an element the limit from either side is the same; FromRight picks the segment
    // that starts at z when z is a vertex, FromLeft at the right end.
    const Approach side = z_mm < m_profile.length_mm() ? Approach::FromRight : Approach::FromLeft;
    RoundSection section;
    section.outerRadius_mm = m_outer.coreRadiusAt(z_mm, side, ContourSide::Outer).value_or(0.0);
    // Inside a range a later operation turns the part is still the bar; its ends are the
    // segments' own ends, so an element never spans one (they are breakpoints).
    const auto inRange = [&](const std::pair<double, double> &r) {
        return side == Approach::FromRight ? z_mm >= r.first && z_mm < r.second : z_mm > r.first && z_mm <= r.second;
    };
    const bool stock = std::any_of(m_stockOuter_mm.begin(), m_stockOuter_mm.end(), inRange);
    if (stock)
        section.outerRadius_mm = std::max(section.outerRadius_mm, m_stockRadius_mm);
    else if (m_outerAllowance_mm > 0.0)
        section.outerRadius_mm =
            std::min(section.outerRadius_mm + m_outerAllowance_mm, std::max(m_stockRadius_mm, section.outerRadius_mm));
    const bool solid = std::any_of(m_solidInner_mm.begin(), m_solidInner_mm.end(), inRange);
    if (const auto bore = m_inner.coreRadiusAt(z_mm, side, ContourSide::Inner); bore && !solid)
        section.innerRadius_mm = std::max(0.0, *bore - m_innerAllowance_mm);
    return section;
}

} // namespace tolturn
