// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/part/profile_validation.h"

#include "core/part/profile_geometry.h"
#include "core/project/keywords.h"

#include <QCoreApplication>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <set>

namespace tolturn {

namespace {

struct ProfileValidation {
    Q_DECLARE_TR_FUNCTIONS(ProfileValidation)
};

QString num(double v)
{
    return formatNumber(v);
}

QString pointText(const ProfilePoint &p)
{
    return QStringLiteral("(z %1, r %2)").arg(num(p.z_mm), num(p.r_mm));
}

bool same(double a, double b)
{
    return std::abs(a - b) <= kProfileEpsilon_mm;
}

bool same(const ProfilePoint &a, const ProfilePoint &b)
{
    return same(a.z_mm, b.z_mm) && same(a.r_mm, b.r_mm);
}

QString segmentPath(ContourSide side, std::size_t index)
{
    return QStringLiteral("part.%1[%2]").arg(contourName(side)).arg(index);
}

class ContourChecker {
public:
    ContourChecker(const Contour &contour, ContourSide side, Diagnostics &out)
        : m_contour(contour)
        , m_side(side)
        , m_out(out)
    {
    }

    void run()
    {
        for (std::size_t i = 0; i < m_contour.segments.size(); ++i) {
            const QString path = segmentPath(m_side, i);
            const Segment &s = m_contour.segments[i];
            if (!checkFinite(s, path))
                continue;
            checkKind(s, path);
            if (i > 0)
                checkJoint(m_contour.segments[i - 1], s, i, path);
        }
    }

private:
    void error(const QString &field, const QString &message) { m_out.push_back(makeError(field, message)); }

    bool checkFinite(const Segment &s, const QString &path)
    {
        bool ok = true;
        const std::pair<const char *, double> coords[] = {
            {"from.z_mm", s.from.z_mm}, {"from.r_mm", s.from.r_mm}, {"to.z_mm", s.to.z_mm}, {"to.r_mm", s.to.r_mm}};
        for (const auto &[name, value] : coords) {
            const QString field = path + QLatin1Char('.') + QLatin1String(name);
            if (!std::isfinite(value)) {
                error(field, ProfileValidation::tr("the coordinate is not a finite number"));
                ok = false;
            } else if (value < 0.0) {
                error(field, ProfileValidation::tr("must not be negative, but is %1 mm").arg(num(value)));
                ok = false;
            }
        }
        return ok;
    }

    void checkKind(const Segment &s, const QString &path)
    {
        const double dz = s.to.z_mm - s.from.z_mm;
        const double dr = s.to.r_mm - s.from.r_mm;
        const QString kind = keyword(s.kind);
        if (s.kind == SegmentKind::Cylinder && dz < -kProfileEpsilon_mm) {
            error(path + QStringLiteral(".to.z_mm"),
                  ProfileValidation::tr(
                      "the cylinder runs backwards along z, from z = %1 mm to z = %2 mm: a contour runs from left "
                      "to right, and only an undercut's cones and radii may go back")
                      .arg(num(s.from.z_mm), num(s.to.z_mm)));
            return;
        }
        switch (s.kind) {
        case SegmentKind::Cylinder:
            if (!same(dr, 0.0))
                error(path + QStringLiteral(".to.r_mm"),
                      ProfileValidation::tr(
                          "a cylinder keeps one radius, but this one goes from r = %1 mm to r = %2 mm (a cone?)")
                          .arg(num(s.from.r_mm), num(s.to.r_mm)));
            else if (dz <= kProfileEpsilon_mm)
                error(path + QStringLiteral(".to.z_mm"),
                      ProfileValidation::tr("the cylinder has zero length: it starts and ends at z = %1 mm")
                          .arg(num(s.to.z_mm)));
            else if (s.from.r_mm <= kProfileEpsilon_mm)
                error(
                    path + QStringLiteral(".from.r_mm"),
                    ProfileValidation::tr("a cylinder needs a radius above zero, but r = %1 mm").arg(num(s.from.r_mm)));
            break;
        case SegmentKind::Face:
            if (!same(dz, 0.0))
                error(path + QStringLiteral(".to.z_mm"),
                      ProfileValidation::tr(
                          "a face stays at one z, but this one goes from z = %1 mm to z = %2 mm (a cone?)")
                          .arg(num(s.from.z_mm), num(s.to.z_mm)));
            else if (same(dr, 0.0))
                error(path + QStringLiteral(".to.r_mm"),
                      ProfileValidation::tr("the face has zero length: it starts and ends at r = %1 mm")
                          .arg(num(s.to.r_mm)));
            break;
        case SegmentKind::Cone:
        case SegmentKind::Chamfer:
            if (std::abs(dz) <= kProfileEpsilon_mm)
                error(path + QStringLiteral(".to.z_mm"),
                      ProfileValidation::tr("a %1 must move along z, but it starts and ends at z = %2 mm (a face?)")
                          .arg(kind, num(s.to.z_mm)));
            else if (same(dr, 0.0))
                error(path + QStringLiteral(".to.r_mm"),
                      ProfileValidation::tr("a %1 must change radius, but it stays at r = %2 mm (a cylinder?)")
                          .arg(kind, num(s.to.r_mm)));
            break;
        case SegmentKind::Radius:
            checkArc(s, path);
            break;
        }
    }

    void checkArc(const Segment &s, const QString &path)
    {
        const double chord = std::hypot(s.to.z_mm - s.from.z_mm, s.to.r_mm - s.from.r_mm);
        if (!std::isfinite(s.arcRadius_mm) || s.arcRadius_mm <= 0.0) {
            error(path + QStringLiteral(".radius_mm"),
                  ProfileValidation::tr("the radius must be above zero, but is %1 mm").arg(num(s.arcRadius_mm)));
            return;
        }
        if (chord <= kProfileEpsilon_mm) {
            error(path + QStringLiteral(".to"),
                  ProfileValidation::tr("the radius has zero length: both ends are at %1").arg(pointText(s.to)));
            return;
        }
        const auto arc = arcGeometry(s);
        if (!arc) {
            error(
                path + QStringLiteral(".radius_mm"),
                ProfileValidation::tr("a radius of %1 mm cannot join two points %2 mm apart (it needs at least %3 mm)")
                    .arg(num(s.arcRadius_mm), num(chord), num(0.5 * chord)));
            return;
        }
    }

    void checkJoint(const Segment &prev, const Segment &s, std::size_t i, const QString &path)
    {
        const QString prevPath = segmentPath(m_side, i - 1);
        if (!same(prev.to, s.from)) {
            if (isSolidBetweenBores(prev, s)) {
                if (++m_breaks > 1)
                    error(path + QStringLiteral(".from"),
                          ProfileValidation::tr("the inner contour leaves the axis a second time at z = %1 mm: a "
                                                "part has at most one bore from each end")
                              .arg(num(s.from.z_mm)));
                return;
            }
            const bool overlap = s.from.z_mm < prev.to.z_mm - kProfileEpsilon_mm;
            error(path + QStringLiteral(".from"),
                  (overlap ? ProfileValidation::tr("overlaps %1: it starts at %2, left of where %1 ends, %3")
                           : ProfileValidation::tr("leaves a gap: it starts at %2, but %1 ends at %3"))
                      .arg(prevPath, pointText(s.from), pointText(prev.to)));
            return;
        }
        if (m_side == ContourSide::Inner && same(s.from.r_mm, 0.0)) {
            error(path + QStringLiteral(".from"),
                  ProfileValidation::tr("the bores from both ends meet on the axis at z = %1 mm, leaving no solid "
                                        "between them: make them one through bore, stepped by a face from r = %2 mm "
                                        "to r = %3 mm")
                      .arg(num(s.from.z_mm), num(prev.from.r_mm), num(s.to.r_mm)));
            return;
        }
        const bool bothFaces = prev.kind == SegmentKind::Face && s.kind == SegmentKind::Face;
        if (bothFaces && (prev.to.r_mm - prev.from.r_mm) * (s.to.r_mm - s.from.r_mm) < 0.0)
            error(path, ProfileValidation::tr("the face turns back over %1 at z = %2 mm: the two faces overlap")
                            .arg(prevPath, num(s.from.z_mm)));
    }

    // A bore from the left end closes on the axis and one from the right end starts on it further
    // right: the inner contour's one allowed break, the solid between them.
    [[nodiscard]] bool isSolidBetweenBores(const Segment &prev, const Segment &s) const
    {
        return m_side == ContourSide::Inner && same(prev.to.r_mm, 0.0) && same(s.from.r_mm, 0.0) &&
               s.from.z_mm > prev.to.z_mm + kProfileEpsilon_mm;
    }

    const Contour &m_contour;
    ContourSide m_side;
    Diagnostics &m_out;
    int m_breaks = 0;
};

// The radius of the inner contour (or the axis, r = 0) where the outer contour must close.
double closingRadius(const Contour &inner, double z_mm)
{
    if (inner.empty())
        return 0.0;
    if (same(inner.front().z_mm, z_mm))
        return inner.front().r_mm;
    if (same(inner.back().z_mm, z_mm))
        return inner.back().r_mm;
    return 0.0;
}

void checkEnds(const PartProfile &p, Diagnostics &out)
{
    const ProfilePoint first = p.outer.front();
    const ProfilePoint last = p.outer.back();
    const QString lastPath = segmentPath(ContourSide::Outer, p.outer.segments.size() - 1);
    if (!same(first.z_mm, 0.0))
        out.push_back(
            makeError(QStringLiteral("part.outer[0].from.z_mm"),
                      ProfileValidation::tr("the outer contour must start at the left end of the part, z = 0 mm, but "
                                            "starts at z = %1 mm")
                          .arg(num(first.z_mm))));
    if (p.length_mm() <= kProfileEpsilon_mm) {
        out.push_back(makeError(lastPath + QStringLiteral(".to.z_mm"),
                                ProfileValidation::tr("the part has zero length: the outer contour ends at z = %1 mm")
                                    .arg(num(last.z_mm))));
        return;
    }
    const double rLeft = closingRadius(p.inner, 0.0);
    const double rRight = closingRadius(p.inner, p.length_mm());
    if (!same(first.r_mm, rLeft))
        out.push_back(makeError(
            QStringLiteral("part.outer[0].from.r_mm"),
            ProfileValidation::tr("the left end face must start at r = %1 mm (%2), but starts at r = %3 mm")
                .arg(num(rLeft), rLeft > 0.0 ? ProfileValidation::tr("the bore") : ProfileValidation::tr("the axis"),
                     num(first.r_mm))));
    if (!same(last.r_mm, rRight))
        out.push_back(makeError(
            lastPath + QStringLiteral(".to.r_mm"),
            ProfileValidation::tr("the right end face must end at r = %1 mm (%2), but ends at r = %3 mm")
                .arg(num(rRight), rRight > 0.0 ? ProfileValidation::tr("the bore") : ProfileValidation::tr("the axis"),
                     num(last.r_mm))));
}

// Each bore (the inner contour's pieces either side of the solid between two bores) opens at an
// end of the part and closes on the axis, or runs through.
void checkBoreEnds(const PartProfile &p, std::size_t firstIndex, std::size_t lastIndex, Diagnostics &out)
{
    const ProfilePoint first = p.inner.segments[firstIndex].from;
    const ProfilePoint last = p.inner.segments[lastIndex].to;
    const QString firstPath = segmentPath(ContourSide::Inner, firstIndex);
    const QString lastPath = segmentPath(ContourSide::Inner, lastIndex);
    const bool openLeft = same(first.z_mm, 0.0);
    const bool openRight = same(last.z_mm, p.length_mm());
    if (!openLeft && !same(first.r_mm, 0.0))
        out.push_back(makeError(firstPath + QStringLiteral(".from"),
                                ProfileValidation::tr("the inner contour must start at the left end (z = 0 mm) or on "
                                                      "the axis (r = 0 mm), but starts at %1")
                                    .arg(pointText(first))));
    if (!openRight && !same(last.r_mm, 0.0))
        out.push_back(makeError(lastPath + QStringLiteral(".to"),
                                ProfileValidation::tr("the inner contour must end at the right end (z = %1 mm) or on "
                                                      "the axis (r = 0 mm), but ends at %2")
                                    .arg(num(p.length_mm()), pointText(last))));
    if (!openLeft && !openRight && same(first.r_mm, 0.0) && same(last.r_mm, 0.0))
        out.push_back(
            makeError(firstIndex == 0 ? QStringLiteral("part.inner") : firstPath,
                      ProfileValidation::tr("the bore from z = %1 mm to z = %2 mm is closed at both ends (a cavity "
                                            "that no tool can reach): it must open at z = 0 mm or at z = %3 mm")
                          .arg(num(first.z_mm), num(last.z_mm), num(p.length_mm()))));
    if (last.z_mm > p.length_mm() + kProfileEpsilon_mm)
        out.push_back(
            makeError(lastPath + QStringLiteral(".to.z_mm"),
                      ProfileValidation::tr("the bore ends at z = %1 mm, beyond the right end of the part at z = %2 mm")
                          .arg(num(last.z_mm), num(p.length_mm()))));
}

void checkInnerEnds(const PartProfile &p, Diagnostics &out)
{
    for (const auto &[first, end] : p.inner.pieces())
        checkBoreEnds(p, first, end - 1, out);
}

// The wall between bore and outside must stay positive. Both contours are straight or circular
// between their vertices, so checking at every vertex (from both sides) and at sample points
// of arcs finds the thinnest place.
void checkWall(const PartProfile &p, Diagnostics &out)
{
    std::set<double> stations; // ordered: the first thin place found is the leftmost
    for (const Contour *c : {&p.outer, &p.inner}) {
        for (const Segment &s : c->segments) {
            for (const ProfilePoint &q : samplePoints(s, 9))
                stations.insert(q.z_mm);
        }
    }
    for (std::size_t i = 0; i < p.inner.segments.size(); ++i) {
        const Segment &s = p.inner.segments[i];
        if (!s.isAxial())
            continue;
        for (const double z : stations) {
            if (z < s.from.z_mm - kProfileEpsilon_mm || z > s.to.z_mm + kProfileEpsilon_mm)
                continue;
            const double rIn = radiusOnSegment(s, z);
            for (const Approach a : {Approach::FromLeft, Approach::FromRight}) {
                const auto rOut = radiusAt(p.outer, z, a);
                if (rOut && rIn >= *rOut - kProfileEpsilon_mm) {
                    out.push_back(makeError(
                        segmentPath(ContourSide::Inner, i),
                        ProfileValidation::tr("the bore reaches r = %1 mm at z = %2 mm, where the outer contour "
                                              "is at r = %3 mm: the inner radius meets the outer one")
                            .arg(num(rIn), num(z), num(*rOut))));
                    return;
                }
            }
        }
    }
}

// A contour with an undercut can cross itself or the other contour (a recess cut deeper than the
// wall). Each segment as a polyline (arcs sampled finely enough to see a crossing of a tenth of
// their radius), compared with every segment that is not its neighbour where their boxes meet.
struct Polyline {
    ContourSide side;
    std::size_t index;
    std::vector<ProfilePoint> points;
    double zLo, zHi, rLo, rHi;
};

std::vector<Polyline> polylines(const Contour &c, ContourSide side)
{
    std::vector<Polyline> out;
    for (std::size_t i = 0; i < c.segments.size(); ++i) {
        Polyline l{side, i, samplePoints(c.segments[i], 17), HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
        for (const ProfilePoint &q : l.points) {
            l.zLo = std::min(l.zLo, q.z_mm);
            l.zHi = std::max(l.zHi, q.z_mm);
            l.rLo = std::min(l.rLo, q.r_mm);
            l.rHi = std::max(l.rHi, q.r_mm);
        }
        out.push_back(std::move(l));
    }
    return out;
}

double cross(const ProfilePoint &o, const ProfilePoint &a, const ProfilePoint &b)
{
    return (a.z_mm - o.z_mm) * (b.r_mm - o.r_mm) - (a.r_mm - o.r_mm) * (b.z_mm - o.z_mm);
}

// Where two polylines cross properly (not where they merely touch at an end).
std::optional<ProfilePoint> crossing(const Polyline &a, const Polyline &b)
{
    constexpr double tiny = 1e-12;
    for (std::size_t i = 1; i < a.points.size(); ++i) {
        const ProfilePoint &p = a.points[i - 1];
        const ProfilePoint &q = a.points[i];
        for (std::size_t j = 1; j < b.points.size(); ++j) {
            const ProfilePoint &u = b.points[j - 1];
            const ProfilePoint &v = b.points[j];
            const double d1 = cross(p, q, u);
            const double d2 = cross(p, q, v);
            const double d3 = cross(u, v, p);
            const double d4 = cross(u, v, q);
            if (((d1 > tiny && d2 < -tiny) || (d1 < -tiny && d2 > tiny)) &&
                ((d3 > tiny && d4 < -tiny) || (d3 < -tiny && d4 > tiny))) {
                const double t = d3 / (d3 - d4);
                return ProfilePoint{p.z_mm + t * (q.z_mm - p.z_mm), p.r_mm + t * (q.r_mm - p.r_mm)};
            }
        }
    }
    return std::nullopt;
}

void checkCrossings(const PartProfile &p, Diagnostics &out)
{
    std::vector<Polyline> all = polylines(p.outer, ContourSide::Outer);
    std::vector<Polyline> inner = polylines(p.inner, ContourSide::Inner);
    all.insert(all.end(), std::make_move_iterator(inner.begin()), std::make_move_iterator(inner.end()));
    for (std::size_t i = 0; i < all.size(); ++i) {
        for (std::size_t j = i + 1; j < all.size(); ++j) {
            const Polyline &a = all[i];
            const Polyline &b = all[j];
            if (a.side == b.side && b.index == a.index + 1)
                continue; // neighbours share their joint
            if (a.zHi < b.zLo || b.zHi < a.zLo || a.rHi < b.rLo || b.rHi < a.rLo)
                continue;
            if (const auto x = crossing(a, b)) {
                out.push_back(makeError(segmentPath(a.side, a.index),
                                        ProfileValidation::tr("crosses %1 at %2: the contour overlaps itself (an "
                                                              "undercut deeper than the material around it?)")
                                            .arg(segmentPath(b.side, b.index), pointText(*x))));
                return;
            }
        }
    }
}

void checkIds(const PartProfile &p, Diagnostics &out)
{
    QSet<QString> seen;
    for (const ContourSide side : {ContourSide::Outer, ContourSide::Inner}) {
        const Contour &c = p.contour(side);
        for (std::size_t i = 0; i < c.segments.size(); ++i) {
            const QString field = segmentPath(side, i) + QStringLiteral(".id");
            const QString &id = c.segments[i].id;
            if (id.trimmed().isEmpty())
                out.push_back(
                    makeError(field, ProfileValidation::tr("every feature needs an id, but this one is empty")));
            else if (seen.contains(id))
                out.push_back(makeError(
                    field,
                    ProfileValidation::tr("the id '%1' is used by another feature; ids must be unique").arg(id)));
            seen.insert(id);
        }
    }
}

} // namespace

Diagnostics validateProfile(const PartProfile &profile)
{
    Diagnostics out;
    if (!std::isfinite(profile.stockDiameter_mm) || profile.stockDiameter_mm <= 0.0)
        out.push_back(makeError(QStringLiteral("part.stock_diameter_mm"),
                                ProfileValidation::tr("the stock diameter must be above zero, but is %1 mm")
                                    .arg(num(profile.stockDiameter_mm))));
    if (profile.outer.empty()) {
        out.push_back(
            makeError(QStringLiteral("part.outer"), ProfileValidation::tr("the outer contour has no segments")));
        return out;
    }
    checkIds(profile, out);
    ContourChecker(profile.outer, ContourSide::Outer, out).run();
    if (!profile.inner.empty())
        ContourChecker(profile.inner, ContourSide::Inner, out).run();
    if (hasErrors(out))
        return out; // the checks below assume well-formed chains
    checkEnds(profile, out);
    if (!profile.inner.empty()) {
        checkInnerEnds(profile, out);
        if (!hasErrors(out))
            checkWall(profile, out);
    }
    if (!hasErrors(out))
        checkCrossings(profile, out);
    const double needed = 2.0 * profile.maxOuterRadius_mm();
    if (profile.stockDiameter_mm < needed - kProfileEpsilon_mm)
        out.push_back(makeError(
            QStringLiteral("part.stock_diameter_mm"),
            ProfileValidation::tr("the stock diameter %1 mm is smaller than the part, whose largest diameter is "
                                  "%2 mm")
                .arg(num(profile.stockDiameter_mm), num(needed))));
    return out;
}

} // namespace tolturn
