// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/part/profile_validation.h"

#include "core/part/profile_geometry.h"
#include "core/project/keywords.h"

#include <QCoreApplication>
#include <QSet>

#include <cmath>
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
        if (dz < -kProfileEpsilon_mm) {
            error(path + QStringLiteral(".to.z_mm"),
                  ProfileValidation::tr(
                      "the %1 runs backwards along z, from z = %2 mm to z = %3 mm: a contour runs from left to "
                      "right, so this segment overlaps the one before it")
                      .arg(kind, num(s.from.z_mm), num(s.to.z_mm)));
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
            if (dz <= kProfileEpsilon_mm)
                error(path + QStringLiteral(".to.z_mm"),
                      ProfileValidation::tr("a %1 must advance along z, but it starts and ends at z = %2 mm (a face?)")
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
        if (!isMonotoneInZ(*arc))
            error(path + QStringLiteral(".direction"),
                  ProfileValidation::tr(
                      "the %1 arc of radius %2 mm turns back along z (an undercut), which cannot be turned "
                      "from left to right; try the other direction")
                      .arg(keyword(s.arcDirection), num(s.arcRadius_mm)));
    }

    void checkJoint(const Segment &prev, const Segment &s, std::size_t i, const QString &path)
    {
        const QString prevPath = segmentPath(m_side, i - 1);
        if (!same(prev.to, s.from)) {
            const bool overlap = s.from.z_mm < prev.to.z_mm - kProfileEpsilon_mm;
            error(path + QStringLiteral(".from"),
                  (overlap ? ProfileValidation::tr("overlaps %1: it starts at %2, left of where %1 ends, %3")
                           : ProfileValidation::tr("leaves a gap: it starts at %2, but %1 ends at %3"))
                      .arg(prevPath, pointText(s.from), pointText(prev.to)));
            return;
        }
        const bool bothFaces = prev.kind == SegmentKind::Face && s.kind == SegmentKind::Face;
        if (bothFaces && (prev.to.r_mm - prev.from.r_mm) * (s.to.r_mm - s.from.r_mm) < 0.0)
            error(path, ProfileValidation::tr("the face turns back over %1 at z = %2 mm: the two faces overlap")
                            .arg(prevPath, num(s.from.z_mm)));
    }

    const Contour &m_contour;
    ContourSide m_side;
    Diagnostics &m_out;
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

void checkInnerEnds(const PartProfile &p, Diagnostics &out)
{
    const ProfilePoint first = p.inner.front();
    const ProfilePoint last = p.inner.back();
    const QString lastPath = segmentPath(ContourSide::Inner, p.inner.segments.size() - 1);
    const bool openLeft = same(first.z_mm, 0.0);
    const bool openRight = same(last.z_mm, p.length_mm());
    if (!openLeft && !same(first.r_mm, 0.0))
        out.push_back(
            makeError(QStringLiteral("part.inner[0].from"),
                      ProfileValidation::tr("the inner contour must start at the left end (z = 0 mm) or on the axis "
                                            "(r = 0 mm), but starts at %1")
                          .arg(pointText(first))));
    if (!openRight && !same(last.r_mm, 0.0))
        out.push_back(
            makeError(lastPath + QStringLiteral(".to"),
                      ProfileValidation::tr("the inner contour must end at the right end (z = %1 mm) or on the axis "
                                            "(r = 0 mm), but ends at %2")
                          .arg(num(p.length_mm()), pointText(last))));
    if (!openLeft && !openRight && same(first.r_mm, 0.0) && same(last.r_mm, 0.0))
        out.push_back(makeError(
            QStringLiteral("part.inner"),
            ProfileValidation::tr("the bore is closed at both ends (a cavity that no tool can reach): it must "
                                  "open at z = 0 mm or at z = %1 mm")
                .arg(num(p.length_mm()))));
    if (last.z_mm > p.length_mm() + kProfileEpsilon_mm)
        out.push_back(
            makeError(lastPath + QStringLiteral(".to.z_mm"),
                      ProfileValidation::tr("the bore ends at z = %1 mm, beyond the right end of the part at z = %2 mm")
                          .arg(num(last.z_mm), num(p.length_mm()))));
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

void checkIds(const PartProfile &p, Diagnostics &out)
{
    QSet<QString> seen;
    for (const ContourSide side : {ContourSide::Outer, ContourSide::Inner}) {
        const Contour &c = side == ContourSide::Outer ? p.outer : p.inner;
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
