// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/part/profile.h"

#include "core/part/profile_geometry.h"

#include <algorithm>

namespace tolturn {

double PartProfile::gripRadius_mm(double clampedLength_mm) const
{
    double grip = 0.0;
    for (const Segment &s : outer.segments)
        if (std::min(s.from.z_mm, s.to.z_mm) < clampedLength_mm)
            grip = std::max({grip, s.from.r_mm, s.to.r_mm});
    return grip;
}

double PartProfile::maxOuterRadius_mm() const
{
    double rMax = 0.0;
    for (const Segment &s : outer.segments) {
        rMax = std::max(rMax, radiusRange(s).second);
    }
    return rMax;
}

std::optional<FeatureRef> findFeature(const PartProfile &profile, const QString &id)
{
    for (ContourSide side : {ContourSide::Outer, ContourSide::Inner}) {
        const Contour &contour = side == ContourSide::Outer ? profile.outer : profile.inner;
        for (std::size_t i = 0; i < contour.segments.size(); ++i) {
            if (contour.segments[i].id == id)
                return FeatureRef{&contour.segments[i], side, static_cast<int>(i)};
        }
    }
    return std::nullopt;
}

QString contourName(ContourSide side)
{
    return side == ContourSide::Outer ? QStringLiteral("outer") : QStringLiteral("inner");
}

} // namespace tolturn
