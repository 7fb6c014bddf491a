// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/part/undercuts.h"

#include "core/common/diagnostic.h"
#include "core/part/profile_geometry.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace tolturn {

namespace {

struct Undercuts {
    Q_DECLARE_TR_FUNCTIONS(Undercuts)
};

constexpr double kInf = std::numeric_limits<double>::infinity();

// DIN 509:2006-12, Table 1, the rows the standard recommends by diameter, as the HEIDENHAIN CNC
// PILOT 4290 operation manual, §11.1 "Undercut DIN 509 E / F, parameters", tabulates them: depth
// I = t1, width K = f, radius R = r, undercut angle W = 15°, face depth P = t2, transverse angle
// A = 8° (form F).
constexpr std::array<UndercutSize, 6> kDin509 = {{
    {0.0, 1.6, 0.1, 0.1, 0.5, 0.1, 15.0, 8.0},
    {1.6, 3.0, 0.2, 0.1, 1.0, 0.1, 15.0, 8.0},
    {3.0, 10.0, 0.2, 0.2, 2.0, 0.1, 15.0, 8.0},
    {10.0, 18.0, 0.6, 0.2, 2.0, 0.1, 15.0, 8.0},
    {18.0, 80.0, 0.6, 0.3, 2.5, 0.2, 15.0, 8.0},
    {80.0, kInf, 1.0, 0.4, 4.0, 0.3, 15.0, 8.0},
}};

double degrees(double deg)
{
    return deg * std::numbers::pi / 180.0;
}

// Fresh ids for n new features of a contour: the next free number and those after it.
QStringList freshIds(const PartProfile &profile, ContourSide side, int n)
{
    const QString first = nextFeatureId(profile, side);
    QStringList ids;
    for (int i = 0; i < n; ++i)
        ids << first.left(1) + QString::number(featureNumber(first) + i);
    return ids;
}

// A Radius segment from `from` to `to` about `centre`: counter-clockwise when the centre lies to
// the left of the chord (the minor arc, as arcGeometry() reads it).
Segment makeArc(const QString &id, const QString &name, ProfilePoint from, ProfilePoint to, ProfilePoint centre,
                double radius_mm)
{
    Segment s = makeFeature(id, name, SegmentKind::Radius, from, to);
    s.arcRadius_mm = radius_mm;
    const double cross =
        (to.z_mm - from.z_mm) * (centre.r_mm - from.r_mm) - (to.r_mm - from.r_mm) * (centre.z_mm - from.z_mm);
    s.arcDirection = cross > 0.0 ? ArcDirection::CounterClockwise : ArcDirection::Clockwise;
    return s;
}

// The corner's frame: a runs along the cylinder away from the face (a = 0 on the face), b into
// the material below the cylinder's surface (b = 0 on it).
struct CornerFrame {
    double faceZ_mm;
    double cylinderRadius_mm;
    double zSign; // +1: the cylinder lies left of the face
    double rSign; // +1: outer contour, the material below

    [[nodiscard]] ProfilePoint at(double a, double b) const
    {
        return {faceZ_mm - zSign * a, cylinderRadius_mm - rSign * b};
    }
};

// The undercut's points in the corner frame from the cylinder to the face, and its features.
struct UndercutShape {
    std::vector<ProfilePoint> points; // P0 on the cylinder … the last on the face
    std::vector<SegmentKind> kinds;   // between consecutive points
    std::vector<QString> names;
    std::optional<std::pair<double, double>> arcCentre; // (a, b) of the radius
    double radius_mm = 0.0;
};

// DIN 509 geometry (Figures 1 and 2): a run-out at 15° from the cylinder down to the depth t1, the
// bottom, the radius r; form E's radius ends on the face, form F's continues past the face by t2
// and is tangent to a flank at 8° to the face that comes back to it.
UndercutShape undercutShape(const UndercutSize &u, UndercutForm form)
{
    const double f = u.width_mm, t1 = u.depth_mm, r = u.radius_mm, t2 = u.faceDepth_mm;
    UndercutShape s;
    s.radius_mm = r;
    const ProfilePoint p0{f, 0.0};
    const ProfilePoint p1{f - t1 / std::tan(degrees(u.runOut_deg)), t1};
    const QString size = u.designation(form);
    if (form == UndercutForm::E) {
        s.arcCentre = {r, t1 - r};
        s.points = {p0, p1, {r, t1}, {0.0, t1 - r}};
        s.kinds = {SegmentKind::Cone, SegmentKind::Cylinder, SegmentKind::Radius};
        s.names = {Undercuts::tr("undercut %1 run-out").arg(size), Undercuts::tr("undercut %1 bottom").arg(size),
                   Undercuts::tr("undercut %1 radius").arg(size)};
        return s;
    }
    const double flank = degrees(u.flank_deg);
    const ProfilePoint centre{r - t2, t1 - r};
    // The flank rises towards the face at `flank` from it: its normal towards the recess side.
    const ProfilePoint tangent{centre.z_mm - r * std::cos(flank), centre.r_mm - r * std::sin(flank)};
    const double along = -tangent.z_mm / std::sin(flank); // from the tangent point to a = 0
    const ProfilePoint onFace{0.0, tangent.r_mm - along * std::cos(flank)};
    s.arcCentre = {centre.z_mm, centre.r_mm};
    s.points = {p0, p1, {r - t2, t1}, tangent, onFace};
    s.kinds = {SegmentKind::Cone, SegmentKind::Cylinder, SegmentKind::Radius, SegmentKind::Cone};
    s.names = {Undercuts::tr("undercut %1 run-out").arg(size), Undercuts::tr("undercut %1 bottom").arg(size),
               Undercuts::tr("undercut %1 radius").arg(size), Undercuts::tr("undercut %1 flank").arg(size)};
    return s;
}

// The undercut's features in contour order (left to right), with fresh ids.
std::vector<Segment> undercutSegments(const UndercutShape &shape, const CornerFrame &frame, const QStringList &ids)
{
    std::vector<Segment> out;
    for (std::size_t i = 0; i + 1 < shape.points.size(); ++i) {
        ProfilePoint from = frame.at(shape.points[i].z_mm, shape.points[i].r_mm);
        ProfilePoint to = frame.at(shape.points[i + 1].z_mm, shape.points[i + 1].r_mm);
        if (frame.zSign < 0.0)
            std::swap(from, to); // the face comes first along z
        const QString &id = ids[static_cast<int>(i)];
        if (shape.kinds[i] == SegmentKind::Radius) {
            const ProfilePoint centre = frame.at(shape.arcCentre->first, shape.arcCentre->second);
            out.push_back(makeArc(id, shape.names[i], from, to, centre, shape.radius_mm));
        } else {
            out.push_back(makeFeature(id, shape.names[i], shape.kinds[i], from, to));
        }
    }
    if (frame.zSign < 0.0)
        std::reverse(out.begin(), out.end());
    return out;
}

QString mm(double v)
{
    return formatNumber(v);
}

} // namespace

QString UndercutSize::designation(UndercutForm form) const
{
    return QStringLiteral("%1%2×%3").arg(form == UndercutForm::E ? QStringLiteral("E") : QStringLiteral("F"),
                                         formatNumber(radius_mm), formatNumber(depth_mm));
}

std::optional<UndercutSize> undercutSizeFor(double diameter_mm)
{
    if (!std::isfinite(diameter_mm) || diameter_mm <= 0.0)
        return std::nullopt;
    for (const UndercutSize &row : kDin509) {
        if (diameter_mm > row.diameterAbove_mm && diameter_mm <= row.diameterUpTo_mm)
            return row;
    }
    return std::nullopt;
}

ProfileEdit insertUndercut(const PartProfile &profile, ContourSide side, int vertex, UndercutForm form)
{
    PartProfile result = profile;
    Contour &contour = result.contour(side);
    std::vector<Segment> &s = contour.segments;
    const auto k = static_cast<std::size_t>(std::max(vertex, 0));
    if (vertex <= 0 || k >= s.size() || contour.breaksBefore(k))
        return Undercuts::tr("an undercut is cut into a corner between two features; the %1 contour has no such "
                             "corner %2")
            .arg(contourName(side))
            .arg(vertex);
    const bool cylinderFirst = s[k - 1].kind == SegmentKind::Cylinder && s[k].kind == SegmentKind::Face;
    const bool faceFirst = s[k - 1].kind == SegmentKind::Face && s[k].kind == SegmentKind::Cylinder;
    if (!cylinderFirst && !faceFirst)
        return Undercuts::tr("a DIN 509 undercut sits where a cylinder meets a face, but corner %1 joins %2 and %3")
            .arg(vertex)
            .arg(s[k - 1].id, s[k].id);
    Segment &cylinder = cylinderFirst ? s[k - 1] : s[k];
    Segment &face = cylinderFirst ? s[k] : s[k - 1];
    const CornerFrame frame{face.from.z_mm, cylinder.from.r_mm, cylinderFirst ? 1.0 : -1.0,
                            side == ContourSide::Outer ? 1.0 : -1.0};
    const double shoulderR = cylinderFirst ? face.to.r_mm : face.from.r_mm;
    const double shoulderHeight = frame.rSign * (shoulderR - frame.cylinderRadius_mm);
    if (shoulderHeight <= 0.0)
        return Undercuts::tr("corner %1 is an outside corner (face %2 falls away from cylinder %3): an undercut sits "
                             "in the inside corner of a shoulder")
            .arg(vertex)
            .arg(face.id, cylinder.id);
    const double diameter = 2.0 * frame.cylinderRadius_mm;
    const auto size = undercutSizeFor(diameter);
    if (!size)
        return Undercuts::tr("cylinder %1 has no diameter (Ø%2 mm) to size an undercut for")
            .arg(cylinder.id, mm(diameter));
    const double length = std::abs(cylinder.to.z_mm - cylinder.from.z_mm);
    if (length < size->width_mm + kProfileEpsilon_mm)
        return Undercuts::tr("cylinder %1 is %2 mm long, not longer than the width f = %3 mm of undercut %4")
            .arg(cylinder.id, mm(length), mm(size->width_mm), size->designation(form));
    const UndercutShape shape = undercutShape(*size, form);
    const double rimHeight = -shape.points.back().r_mm; // where the undercut meets the face, above the cylinder
    if (rimHeight >= shoulderHeight - kProfileEpsilon_mm)
        return Undercuts::tr("face %1 rises %2 mm above cylinder %3, but undercut %4 meets it %5 mm above: the "
                             "shoulder is too low for it")
            .arg(face.id, mm(shoulderHeight), cylinder.id, size->designation(form), mm(rimHeight));
    // The cylinder ends where the undercut begins; the face starts where it ends.
    const ProfilePoint start = frame.at(shape.points.front().z_mm, 0.0);
    const ProfilePoint rim = frame.at(0.0, shape.points.back().r_mm);
    (cylinderFirst ? cylinder.to : cylinder.from) = start;
    (cylinderFirst ? face.from : face.to) = rim;
    const std::vector<Segment> added =
        undercutSegments(shape, frame, freshIds(profile, side, static_cast<int>(shape.kinds.size())));
    s.insert(s.begin() + static_cast<std::ptrdiff_t>(k), added.begin(), added.end());
    return result;
}

ProfileEdit insertGroove(const PartProfile &profile, const QString &featureId, double zStart_mm, double width_mm,
                         double depth_mm)
{
    const std::optional<FeatureRef> ref = findFeature(profile, featureId);
    if (!ref || ref->segment->kind != SegmentKind::Cylinder)
        return Undercuts::tr("a groove is cut into a cylinder; %1 is not one").arg(featureId);
    const Segment &cylinder = *ref->segment;
    const double z0 = cylinder.from.z_mm, z1 = cylinder.to.z_mm, r = cylinder.from.r_mm;
    if (!std::isfinite(width_mm) || width_mm <= 0.0)
        return Undercuts::tr("the groove's width must be above zero, but is %1 mm").arg(mm(width_mm));
    if (!std::isfinite(depth_mm) || depth_mm <= 0.0)
        return Undercuts::tr("the groove's depth must be above zero, but is %1 mm").arg(mm(depth_mm));
    const double zEnd = zStart_mm + width_mm;
    if (!(zStart_mm > z0 + kProfileEpsilon_mm && zEnd < z1 - kProfileEpsilon_mm))
        return Undercuts::tr("the groove from z = %1 mm to z = %2 mm must lie inside %3 (z %4 … %5 mm)")
            .arg(mm(zStart_mm), mm(zEnd), featureId, mm(z0), mm(z1));
    const double bottom = ref->side == ContourSide::Outer ? r - depth_mm : r + depth_mm;
    if (bottom <= kProfileEpsilon_mm)
        return Undercuts::tr("a groove %1 mm deep would reach the axis from Ø%2 mm").arg(mm(depth_mm), mm(2.0 * r));
    PartProfile result = profile;
    std::vector<Segment> &s = result.contour(ref->side).segments;
    const auto i = static_cast<std::size_t>(ref->index);
    const QStringList ids = freshIds(profile, ref->side, 4);
    const Segment rest = makeFeature(ids[3], cylinder.name, SegmentKind::Cylinder, {zEnd, r}, {z1, r});
    s[i].to = {zStart_mm, r};
    const std::array<Segment, 4> groove = {
        makeFeature(ids[0], Undercuts::tr("groove flank"), SegmentKind::Face, {zStart_mm, r}, {zStart_mm, bottom}),
        makeFeature(ids[1], Undercuts::tr("groove bottom Ø%1").arg(mm(2.0 * bottom)), SegmentKind::Cylinder,
                    {zStart_mm, bottom}, {zEnd, bottom}),
        makeFeature(ids[2], Undercuts::tr("groove flank"), SegmentKind::Face, {zEnd, bottom}, {zEnd, r}), rest};
    s.insert(s.begin() + static_cast<std::ptrdiff_t>(i) + 1, groove.begin(), groove.end());
    return result;
}

std::vector<Groove> groovesOf(const Contour &contour, ContourSide side)
{
    // Depth into the material: below the surface on the outer contour, beyond it in a bore.
    const double sign = side == ContourSide::Outer ? 1.0 : -1.0;
    const auto intoMaterial = [&](const Segment &f) { return sign * (f.from.r_mm - f.to.r_mm) > 0.0; };
    std::vector<Groove> out;
    const std::vector<Segment> &s = contour.segments;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i].kind != SegmentKind::Face || !intoMaterial(s[i]))
            continue;
        // Levels as heights above the axis on the outer contour, depths from it in a bore.
        const double rimLeft = sign * s[i].from.r_mm;
        double deepest = sign * s[i].to.r_mm;
        double highest = deepest; // of what lies between the two faces
        for (std::size_t j = i + 1; j < s.size() && !contour.breaksBefore(j); ++j) {
            const Segment &t = s[j];
            if (t.kind == SegmentKind::Face && !intoMaterial(t)) {
                // A groove when all between lies below both rims; else a step down, then up.
                const double rim = std::min(rimLeft, sign * t.to.r_mm);
                if (highest < rim - kProfileEpsilon_mm)
                    out.push_back({s[i].id, t.id, t.from.z_mm - s[i].from.z_mm, rim - deepest});
                break;
            }
            const auto [lo, hi] = radiusRange(t);
            highest = std::max({highest, sign * lo, sign * hi});
            deepest = std::min({deepest, sign * lo, sign * hi});
            if (highest >= rimLeft - kProfileEpsilon_mm)
                break; // it rises to the left rim: no groove starts at this face
        }
    }
    return out;
}

} // namespace tolturn
