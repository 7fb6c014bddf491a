// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/part/profile_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tolturn {

namespace {

constexpr double kPi = std::numbers::pi;

// True when `angle` lies strictly inside the swept interval of the arc.
bool sweepContains(const ArcGeometry &arc, double angle)
{
    double offset = std::remainder(angle - arc.startAngle_rad, 2.0 * kPi); // (-pi, pi]
    if (arc.sweep_rad < 0.0)
        offset = -offset;
    if (offset < 0.0)
        offset += 2.0 * kPi;
    const double sweep = std::abs(arc.sweep_rad);
    return offset > 1e-12 && offset < sweep - 1e-12;
}

} // namespace

ProfilePoint ArcGeometry::pointAt(double angle_rad) const
{
    return {centre.z_mm + radius_mm * std::cos(angle_rad), centre.r_mm + radius_mm * std::sin(angle_rad)};
}

std::optional<ArcGeometry> arcGeometry(const Segment &segment)
{
    const double dz = segment.to.z_mm - segment.from.z_mm;
    const double dr = segment.to.r_mm - segment.from.r_mm;
    const double chord = std::hypot(dz, dr);
    const double radius = segment.arcRadius_mm;
    if (chord <= 0.0 || radius < 0.5 * chord - kProfileEpsilon_mm)
        return std::nullopt;
    // Centre on the perpendicular bisector of the chord, to the left of the travel direction
    // for counter-clockwise travel (minor arc), to the right for clockwise.
    const double halfChord = 0.5 * chord;
    const double h = std::sqrt(std::max(0.0, radius * radius - halfChord * halfChord));
    const double side = segment.arcDirection == ArcDirection::CounterClockwise ? 1.0 : -1.0;
    const ProfilePoint mid{0.5 * (segment.from.z_mm + segment.to.z_mm), 0.5 * (segment.from.r_mm + segment.to.r_mm)};
    const ProfilePoint centre{mid.z_mm - side * h * dr / chord, mid.r_mm + side * h * dz / chord};

    ArcGeometry arc;
    arc.centre = centre;
    arc.radius_mm = radius;
    arc.startAngle_rad = std::atan2(segment.from.r_mm - centre.r_mm, segment.from.z_mm - centre.z_mm);
    const double endAngle = std::atan2(segment.to.r_mm - centre.r_mm, segment.to.z_mm - centre.z_mm);
    double sweep = std::remainder(endAngle - arc.startAngle_rad, 2.0 * kPi);
    // A half circle: remainder() may return either sign; the direction decides.
    if (std::abs(std::abs(sweep) - kPi) < 1e-12)
        sweep = side * kPi;
    arc.sweep_rad = sweep;
    return arc;
}

bool isMonotoneInZ(const ArcGeometry &arc)
{
    return !sweepContains(arc, 0.0) && !sweepContains(arc, kPi);
}

std::pair<double, double> zRange(const ArcGeometry &arc)
{
    const ProfilePoint a = arc.pointAt(arc.startAngle_rad);
    const ProfilePoint b = arc.pointAt(arc.startAngle_rad + arc.sweep_rad);
    double lo = std::min(a.z_mm, b.z_mm);
    double hi = std::max(a.z_mm, b.z_mm);
    if (sweepContains(arc, 0.0))
        hi = arc.centre.z_mm + arc.radius_mm;
    if (sweepContains(arc, kPi))
        lo = arc.centre.z_mm - arc.radius_mm;
    return {lo, hi};
}

double radiusOnSegment(const Segment &segment, double z_mm)
{
    const double z0 = segment.from.z_mm;
    const double z1 = segment.to.z_mm;
    if (segment.kind == SegmentKind::Radius) {
        if (const auto arc = arcGeometry(segment)) {
            const double dz = std::clamp(z_mm - arc->centre.z_mm, -arc->radius_mm, arc->radius_mm);
            const double root = std::sqrt(arc->radius_mm * arc->radius_mm - dz * dz);
            // A z-monotone arc lies wholly above or below its centre: the mid-sweep tells which.
            const double midAngle = arc->startAngle_rad + 0.5 * arc->sweep_rad;
            return std::sin(midAngle) >= 0.0 ? arc->centre.r_mm + root : arc->centre.r_mm - root;
        }
    }
    if (z1 - z0 <= 0.0)
        return std::max(segment.from.r_mm, segment.to.r_mm);
    const double t = std::clamp((z_mm - z0) / (z1 - z0), 0.0, 1.0);
    return segment.from.r_mm + t * (segment.to.r_mm - segment.from.r_mm);
}

std::pair<double, double> radiusRange(const Segment &segment)
{
    double lo = std::min(segment.from.r_mm, segment.to.r_mm);
    double hi = std::max(segment.from.r_mm, segment.to.r_mm);
    if (segment.kind == SegmentKind::Radius) {
        if (const auto arc = arcGeometry(segment)) {
            if (sweepContains(*arc, 0.5 * kPi))
                hi = arc->centre.r_mm + arc->radius_mm;
            if (sweepContains(*arc, -0.5 * kPi))
                lo = arc->centre.r_mm - arc->radius_mm;
        }
    }
    return {lo, hi};
}

namespace {

// Of the axial segments (in contour order) the one covering z; at a shared end point the approach
// decides which. `knownAxial`: the caller passes axial segments only (isAxial() costs an arc's
// geometry).
template <class Segments, class Get>
const Segment *coveringSegment(const Segments &segments, Get get, double z_mm, Approach approach, bool knownAxial)
{
    const Segment *best = nullptr;
    for (const auto &item : segments) {
        const Segment &s = get(item);
        if (!knownAxial && !s.isAxial())
            continue;
        const double z0 = s.from.z_mm;
        const double z1 = s.to.z_mm;
        if (z_mm < z0 - kProfileEpsilon_mm || z_mm > z1 + kProfileEpsilon_mm)
            continue;
        const bool interior = z_mm > z0 + kProfileEpsilon_mm && z_mm < z1 - kProfileEpsilon_mm;
        const bool wanted =
            approach == Approach::FromLeft ? z_mm > z0 + kProfileEpsilon_mm : z_mm < z1 - kProfileEpsilon_mm;
        if (interior || wanted) {
            best = &s;
            break;
        }
        if (best == nullptr)
            best = &s;
    }
    return best;
}

} // namespace

std::optional<double> radiusAt(const Contour &contour, double z_mm, Approach approach)
{
    const Segment *s = coveringSegment(
        contour.segments, [](const Segment &x) -> const Segment & { return x; }, z_mm, approach, false);
    return s ? std::optional<double>(radiusOnSegment(*s, z_mm)) : std::nullopt;
}

AxialSegments::AxialSegments(const Contour &contour)
{
    for (const Segment &s : contour.segments) {
        if (s.kind == SegmentKind::Face)
            continue;
        m_undercut = m_undercut || s.turnsBack();
        if (!s.turnsBack())
            m_axial.push_back(&s);
        m_crossing.push_back(&s);
    }
}

std::optional<double> AxialSegments::coreRadiusAt(double z_mm, Approach approach, ContourSide side) const
{
    const Segment *s = coveringSegment(
        m_axial, [](const Segment *x) -> const Segment & { return *x; }, z_mm, approach, true);
    std::optional<double> r = s ? std::optional<double>(radiusOnSegment(*s, z_mm)) : std::nullopt;
    if (!m_undercut)
        return r;
    for (const Segment *c : m_crossing) {
        for (const double x : crossingRadii(*c, z_mm)) {
            if (!r)
                r = x;
            else
                r = side == ContourSide::Outer ? std::min(*r, x) : std::max(*r, x);
        }
    }
    return r;
}

std::vector<double> crossingRadii(const Segment &segment, double z_mm)
{
    const double zLo = std::min(segment.from.z_mm, segment.to.z_mm);
    const double zHi = std::max(segment.from.z_mm, segment.to.z_mm);
    if (segment.kind == SegmentKind::Face)
        return {};
    if (segment.kind != SegmentKind::Radius) {
        if (z_mm <= zLo + kProfileEpsilon_mm || z_mm >= zHi - kProfileEpsilon_mm)
            return {};
        const double t = (z_mm - segment.from.z_mm) / (segment.to.z_mm - segment.from.z_mm);
        return {segment.from.r_mm + t * (segment.to.r_mm - segment.from.r_mm)};
    }
    const auto arc = arcGeometry(segment);
    if (!arc)
        return {};
    const double dz = z_mm - arc->centre.z_mm;
    if (std::abs(dz) >= arc->radius_mm)
        return {};
    std::vector<double> radii;
    const double angle = std::acos(dz / arc->radius_mm); // of the upper crossing; the lower is -angle
    for (const double a : {angle, -angle}) {
        if (sweepContains(*arc, a))
            radii.push_back(arc->pointAt(a).r_mm);
    }
    return radii;
}

std::vector<ProfilePoint> samplePoints(const Segment &segment, int arcPoints)
{
    if (segment.kind != SegmentKind::Radius)
        return {segment.from, segment.to};
    const auto arc = arcGeometry(segment);
    if (!arc)
        return {segment.from, segment.to};
    const int n = std::max(arcPoints, 2);
    std::vector<ProfilePoint> points;
    points.reserve(static_cast<std::size_t>(n));
    points.push_back(segment.from);
    for (int i = 1; i < n - 1; ++i)
        points.push_back(arc->pointAt(arc->startAngle_rad + arc->sweep_rad * i / (n - 1)));
    points.push_back(segment.to);
    return points;
}

double segmentLength_mm(const Segment &segment)
{
    if (segment.kind == SegmentKind::Radius) {
        if (const auto arc = arcGeometry(segment))
            return arc->radius_mm * std::abs(arc->sweep_rad);
    }
    return std::hypot(segment.to.z_mm - segment.from.z_mm, segment.to.r_mm - segment.from.r_mm);
}

} // namespace tolturn
