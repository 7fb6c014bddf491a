// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/part/profile.h"

#include "core/part/profile_geometry.h"

#include <algorithm>
#include <cmath>

namespace tolturn {

bool Segment::turnsBack() const
{
    if (kind == SegmentKind::Cone || kind == SegmentKind::Chamfer)
        return to.z_mm < from.z_mm - kProfileEpsilon_mm;
    if (kind == SegmentKind::Radius) {
        // Past its end points by more than the profile's tolerance: a fillet whose end lies a
        // rounding error beyond its tangent point (as read from a STEP file) is not an undercut.
        const auto arc = arcGeometry(*this);
        if (!arc)
            return false;
        const auto [lo, hi] = zRange(*arc);
        return lo < std::min(from.z_mm, to.z_mm) - kProfileEpsilon_mm ||
               hi > std::max(from.z_mm, to.z_mm) + kProfileEpsilon_mm;
    }
    return false;
}

bool Contour::breaksBefore(std::size_t i) const
{
    if (i == 0 || i >= segments.size())
        return false;
    const ProfilePoint &a = segments[i - 1].to;
    const ProfilePoint &b = segments[i].from;
    return std::abs(a.z_mm - b.z_mm) > kProfileEpsilon_mm || std::abs(a.r_mm - b.r_mm) > kProfileEpsilon_mm;
}

std::vector<std::pair<std::size_t, std::size_t>> Contour::pieces() const
{
    std::vector<std::pair<std::size_t, std::size_t>> out;
    std::size_t start = 0;
    for (std::size_t i = 1; i <= segments.size(); ++i) {
        if (i == segments.size() || breaksBefore(i)) {
            out.emplace_back(start, i);
            start = i;
        }
    }
    return out;
}

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
        const Contour &contour = profile.contour(side);
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
