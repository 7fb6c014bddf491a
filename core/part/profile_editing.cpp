// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/part/profile_editing.h"

#include "core/common/diagnostic.h"
#include "core/part/profile_geometry.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {

struct ProfileEditing {
    Q_DECLARE_TR_FUNCTIONS(ProfileEditing)
};

bool near(double a, double b)
{
    return std::abs(a - b) <= kProfileEpsilon_mm;
}

// A bore open at an end of the part is where that end face stops: after an edit of the bore,
// the outer contour's end faces close at the bore's new radius there.
void joinEndFacesToBore(PartProfile &p)
{
    if (p.inner.empty() || p.outer.empty())
        return;
    const Segment &first = p.inner.segments.front();
    const Segment &last = p.inner.segments.back();
    if (near(first.from.z_mm, 0.0) && first.from.r_mm > kProfileEpsilon_mm)
        p.outer.segments.front().from.r_mm = first.from.r_mm;
    if (near(last.to.z_mm, p.length_mm()) && last.to.r_mm > kProfileEpsilon_mm)
        p.outer.segments.back().to.r_mm = last.to.r_mm;
}

bool samePoint(const ProfilePoint &a, const ProfilePoint &b)
{
    return near(a.z_mm, b.z_mm) && near(a.r_mm, b.r_mm);
}

// Moves the start of segment i to `to`; a cylinder or face keeps its kind by moving its other
// end too, and so the start of the segment after it.
void moveStart(std::vector<Segment> &s, std::size_t i, ProfilePoint to)
{
    // Nothing is carried across the inner contour's break (the solid between two bores).
    const bool joined = i + 1 < s.size() && samePoint(s[i].to, s[i + 1].from);
    s[i].from = to;
    if (s[i].kind == SegmentKind::Cylinder)
        s[i].to.r_mm = to.r_mm;
    else if (s[i].kind == SegmentKind::Face)
        s[i].to.z_mm = to.z_mm;
    else
        return;
    if (joined)
        s[i + 1].from = s[i].to;
}

// The mirror of moveStart for the end of segment i and the segment before it.
void moveEnd(std::vector<Segment> &s, std::size_t i, ProfilePoint to)
{
    const bool joined = i > 0 && samePoint(s[i - 1].to, s[i].from);
    s[i].to = to;
    if (s[i].kind == SegmentKind::Cylinder)
        s[i].from.r_mm = to.r_mm;
    else if (s[i].kind == SegmentKind::Face)
        s[i].from.z_mm = to.z_mm;
    else
        return;
    if (joined)
        s[i - 1].to = s[i].from;
}

// Joins two neighbours that became one feature: cylinders at one diameter, faces at one z.
void mergeAt(std::vector<Segment> &s, std::size_t i)
{
    if (i == 0 || i >= s.size() || s[i - 1].kind != s[i].kind)
        return;
    const bool cylinders = s[i].kind == SegmentKind::Cylinder && near(s[i - 1].to.r_mm, s[i].from.r_mm);
    const bool faces = s[i].kind == SegmentKind::Face && near(s[i - 1].to.z_mm, s[i].from.z_mm);
    if (!cylinders && !faces)
        return;
    s[i - 1].to = s[i].to;
    s.erase(s.begin() + static_cast<std::ptrdiff_t>(i));
}

// Where the lines of two straight segments meet, if they are not parallel.
std::optional<ProfilePoint> lineIntersection(const Segment &a, const Segment &b)
{
    const double dz1 = a.to.z_mm - a.from.z_mm, dr1 = a.to.r_mm - a.from.r_mm;
    const double dz2 = b.to.z_mm - b.from.z_mm, dr2 = b.to.r_mm - b.from.r_mm;
    const double det = dz1 * dr2 - dr1 * dz2;
    if (std::abs(det) < 1e-12)
        return std::nullopt;
    const double t = ((b.from.z_mm - a.from.z_mm) * dr2 - (b.from.r_mm - a.from.r_mm) * dz2) / det;
    return ProfilePoint{a.from.z_mm + t * dz1, a.from.r_mm + t * dr1};
}

} // namespace

int featureNumber(const QString &id)
{
    bool ok = false;
    const int n = id.mid(1).toInt(&ok);
    return ok ? n : 0;
}

Segment makeFeature(const QString &id, const QString &name, SegmentKind kind, ProfilePoint from, ProfilePoint to)
{
    Segment s;
    s.id = id;
    s.name = name;
    s.kind = kind;
    s.from = from;
    s.to = to;
    return s;
}

QString nextFeatureId(const PartProfile &profile, ContourSide side)
{
    const Contour &c = profile.contour(side);
    int highest = 0;
    for (const Segment &s : c.segments)
        highest = std::max(highest, featureNumber(s.id));
    return (side == ContourSide::Outer ? QStringLiteral("O") : QStringLiteral("I")) + QString::number(highest + 1);
}

ProfileEdit moveVertex(const PartProfile &profile, ContourSide side, int vertex, ProfilePoint to, AtBreak atBreak)
{
    PartProfile result = profile;
    Contour &contour = result.contour(side);
    std::vector<Segment> &s = contour.segments;
    if (vertex < 0 || vertex > static_cast<int>(s.size()) || s.empty())
        return ProfileEditing::tr("the %1 contour has no vertex %2").arg(contourName(side)).arg(vertex);
    const auto k = static_cast<std::size_t>(vertex);
    const bool atTheBreak = contour.breaksBefore(k);
    if (k > 0 && (!atTheBreak || atBreak == AtBreak::EndOfSegment))
        moveEnd(s, k - 1, to);
    if (k < s.size() && (!atTheBreak || atBreak == AtBreak::StartOfSegment))
        moveStart(s, k, to);
    // An undercut is drawn on purpose (insertUndercut), never made by dragging a corner.
    const std::vector<Segment> &before = profile.contour(side).segments;
    for (std::size_t i = 0; i < s.size() && i < before.size(); ++i) {
        if (s[i].turnsBack() && !before[i].turnsBack())
            return ProfileEditing::tr("moving the corner would make %1 turn back along z (an undercut), which "
                                      "needs an undercut insert; move it less, or insert a DIN 509 undercut")
                .arg(s[i].id);
    }
    joinEndFacesToBore(result);
    return result;
}

ProfileEdit insertStep(const PartProfile &profile, const QString &featureId, double z_mm, double diameter_mm)
{
    const std::optional<FeatureRef> ref = findFeature(profile, featureId);
    if (!ref || ref->segment->kind != SegmentKind::Cylinder)
        return ProfileEditing::tr("a step is inserted into a cylinder; %1 is not one").arg(featureId);
    const Segment &cylinder = *ref->segment;
    const double z0 = std::min(cylinder.from.z_mm, cylinder.to.z_mm),
                 z1 = std::max(cylinder.from.z_mm, cylinder.to.z_mm);
    if (!(z_mm > z0 + kProfileEpsilon_mm && z_mm < z1 - kProfileEpsilon_mm))
        return ProfileEditing::tr("the step of %1 must lie inside it (z %2 … %3 mm), but z is %4 mm")
            .arg(featureId, formatNumber(z0), formatNumber(z1), formatNumber(z_mm));
    if (!(diameter_mm > 0.0) || near(diameter_mm / 2.0, cylinder.from.r_mm))
        return ProfileEditing::tr("the step's diameter must differ from Ø%1 mm and be above zero, but is %2 mm")
            .arg(formatNumber(2.0 * cylinder.from.r_mm), formatNumber(diameter_mm));
    PartProfile result = profile;
    std::vector<Segment> &s = result.contour(ref->side).segments;
    const auto i = static_cast<std::size_t>(ref->index);
    const double r = cylinder.from.r_mm, r2 = diameter_mm / 2.0;
    const ProfilePoint corner{z_mm, r}, stepped{z_mm, r2};
    const QString faceId = nextFeatureId(result, ref->side);
    const QString cylinderId = (ref->side == ContourSide::Outer ? QStringLiteral("O") : QStringLiteral("I")) +
                               QString::number(featureNumber(faceId) + 1);
    const ProfilePoint end = s[i].to;
    s[i].to = corner;
    const Segment face = makeFeature(faceId, ProfileEditing::tr("step face"), SegmentKind::Face, corner, stepped);
    const Segment second =
        makeFeature(cylinderId, ProfileEditing::tr("step diameter"), SegmentKind::Cylinder, stepped, {end.z_mm, r2});
    s.insert(s.begin() + static_cast<std::ptrdiff_t>(i) + 1, {face, second});
    if (i + 3 < s.size())
        moveStart(s, i + 3, s[i + 2].to);
    joinEndFacesToBore(result);
    return result;
}

ProfileEdit breakCorner(const PartProfile &profile, ContourSide side, int vertex, double size_mm, bool round)
{
    PartProfile result = profile;
    std::vector<Segment> &s = result.contour(side).segments;
    if (vertex <= 0 || vertex >= static_cast<int>(s.size()))
        return ProfileEditing::tr("vertex %1 of the %2 contour is not a corner between two features")
            .arg(vertex)
            .arg(contourName(side));
    const auto k = static_cast<std::size_t>(vertex);
    Segment &before = s[k - 1];
    Segment &after = s[k];
    const bool faceAndCylinder = (before.kind == SegmentKind::Face && after.kind == SegmentKind::Cylinder) ||
                                 (before.kind == SegmentKind::Cylinder && after.kind == SegmentKind::Face);
    if (!faceAndCylinder)
        return ProfileEditing::tr("a corner is broken between a face and a cylinder; %1 and %2 are not")
            .arg(before.id, after.id);
    const double lenBefore = segmentLength_mm(before), lenAfter = segmentLength_mm(after);
    if (!(size_mm > 0.0) || size_mm >= lenBefore || size_mm >= lenAfter)
        return ProfileEditing::tr("the corner of %1 and %2 takes at most %3 mm, but the size is %4 mm")
            .arg(before.id, after.id, formatNumber(std::min(lenBefore, lenAfter)), formatNumber(size_mm));
    const ProfilePoint corner = before.to;
    // Unit directions into the corner along `before` and out of it along `after`.
    const double d1z = (before.to.z_mm - before.from.z_mm) / lenBefore,
                 d1r = (before.to.r_mm - before.from.r_mm) / lenBefore;
    const double d2z = (after.to.z_mm - after.from.z_mm) / lenAfter, d2r = (after.to.r_mm - after.from.r_mm) / lenAfter;
    const ProfilePoint start{corner.z_mm - size_mm * d1z, corner.r_mm - size_mm * d1r};
    const ProfilePoint end{corner.z_mm + size_mm * d2z, corner.r_mm + size_mm * d2r};
    before.to = start;
    after.from = end;
    Segment edge = makeFeature(nextFeatureId(result, side),
                               round ? ProfileEditing::tr("edge round") : ProfileEditing::tr("chamfer"),
                               round ? SegmentKind::Radius : SegmentKind::Chamfer, start, end);
    if (round) {
        // A quarter circle tangent to both: turning right (clockwise) when the path turns right.
        edge.arcRadius_mm = size_mm;
        edge.arcDirection = d1z * d2r - d1r * d2z < 0.0 ? ArcDirection::Clockwise : ArcDirection::CounterClockwise;
    }
    s.insert(s.begin() + static_cast<std::ptrdiff_t>(k), edge);
    return result;
}

ProfileEdit makeCone(const PartProfile &profile, const QString &featureId, double endDiameter_mm)
{
    const std::optional<FeatureRef> ref = findFeature(profile, featureId);
    if (!ref || ref->segment->kind != SegmentKind::Cylinder)
        return ProfileEditing::tr("a cone is made from a cylinder; %1 is not one").arg(featureId);
    if (!(endDiameter_mm > 0.0) || near(endDiameter_mm / 2.0, ref->segment->from.r_mm))
        return ProfileEditing::tr("the cone's end needs a diameter other than Ø%1 mm, but it is %2 mm")
            .arg(formatNumber(2.0 * ref->segment->from.r_mm), formatNumber(endDiameter_mm));
    PartProfile result = profile;
    std::vector<Segment> &s = result.contour(ref->side).segments;
    const auto i = static_cast<std::size_t>(ref->index);
    const bool joined = i + 1 < s.size() && samePoint(s[i].to, s[i + 1].from);
    s[i].kind = SegmentKind::Cone;
    s[i].to.r_mm = endDiameter_mm / 2.0;
    if (joined)
        moveStart(s, i + 1, s[i].to);
    joinEndFacesToBore(result);
    return result;
}

ProfileEdit makeCylinder(const PartProfile &profile, const QString &featureId)
{
    const std::optional<FeatureRef> ref = findFeature(profile, featureId);
    if (!ref || ref->segment->kind != SegmentKind::Cone)
        return ProfileEditing::tr("a cylinder is made from a cone; %1 is not one").arg(featureId);
    PartProfile result = profile;
    std::vector<Segment> &s = result.contour(ref->side).segments;
    const auto i = static_cast<std::size_t>(ref->index);
    const bool joined = i + 1 < s.size() && samePoint(s[i].to, s[i + 1].from);
    s[i].kind = SegmentKind::Cylinder;
    s[i].to.r_mm = s[i].from.r_mm;
    if (joined)
        moveStart(s, i + 1, s[i].to);
    joinEndFacesToBore(result);
    return result;
}

namespace {

// A blind bore from the end face that is still closed, when the part has one from the other end:
// the inner contour gets its second piece, with solid material between the bottoms.
ProfileEdit addSecondBore(const PartProfile &profile, bool left, double depth_mm, double r)
{
    const Contour &inner = profile.inner;
    const double length = profile.length_mm();
    const bool onePiece = inner.pieces().size() == 1;
    const bool blindFromRight = onePiece && near(inner.front().r_mm, 0.0) && near(inner.back().z_mm, length);
    const bool blindFromLeft = onePiece && near(inner.front().z_mm, 0.0) && near(inner.back().r_mm, 0.0);
    if (!(left ? blindFromRight : blindFromLeft))
        return ProfileEditing::tr("the part is bored from this end already (or through); edit its bore instead");
    const double bottom = left ? depth_mm : length - depth_mm;
    const double otherBottom = left ? inner.front().z_mm : inner.back().z_mm;
    if (left ? bottom >= otherBottom - kProfileEpsilon_mm : bottom <= otherBottom + kProfileEpsilon_mm)
        return ProfileEditing::tr("a bore %1 mm deep would meet the bore from the other end, whose bottom is at z = "
                                  "%2 mm: leave solid between them, or make it one through bore")
            .arg(formatNumber(depth_mm), formatNumber(otherBottom));
    PartProfile result = profile;
    const QString boreId = nextFeatureId(profile, ContourSide::Inner);
    const QString bottomId = QStringLiteral("I") + QString::number(featureNumber(boreId) + 1);
    std::vector<Segment> &s = result.inner.segments;
    if (left) {
        const Segment bore =
            makeFeature(boreId, ProfileEditing::tr("bore"), SegmentKind::Cylinder, {0.0, r}, {bottom, r});
        const Segment face =
            makeFeature(bottomId, ProfileEditing::tr("bore bottom"), SegmentKind::Face, {bottom, r}, {bottom, 0.0});
        s.insert(s.begin(), {bore, face});
        result.outer.segments.front().from.r_mm = r;
    } else {
        s.push_back(
            makeFeature(bottomId, ProfileEditing::tr("bore bottom"), SegmentKind::Face, {bottom, 0.0}, {bottom, r}));
        s.push_back(makeFeature(boreId, ProfileEditing::tr("bore"), SegmentKind::Cylinder, {bottom, r}, {length, r}));
        result.outer.segments.back().to.r_mm = r;
    }
    return result;
}

} // namespace

ProfileEdit addBore(const PartProfile &profile, const QString &endFaceId, double depth_mm, double diameter_mm)
{
    const std::vector<Segment> &outer = profile.outer.segments;
    const bool left = !outer.empty() && outer.front().id == endFaceId;
    const bool right = !outer.empty() && outer.back().id == endFaceId;
    if (!left && !right)
        return ProfileEditing::tr("a bore starts at an end face of the part; %1 is not one").arg(endFaceId);
    const double length = profile.length_mm();
    const double r = diameter_mm / 2.0;
    if (!(depth_mm > 0.0) || !(r > 0.0))
        return ProfileEditing::tr("a bore needs a depth and a diameter above zero, but they are %1 and %2 mm")
            .arg(formatNumber(depth_mm), formatNumber(diameter_mm));
    if (!profile.inner.empty())
        return addSecondBore(profile, left, depth_mm, r);
    PartProfile result = profile;
    std::vector<Segment> &inner = result.inner.segments;
    const bool through = depth_mm >= length - kProfileEpsilon_mm;
    const double bottom = left ? std::min(depth_mm, length) : std::max(length - depth_mm, 0.0);
    if (through) {
        inner.push_back(makeFeature(QStringLiteral("I1"), ProfileEditing::tr("bore"), SegmentKind::Cylinder, {0.0, r},
                                    {length, r}));
    } else if (left) {
        inner.push_back(makeFeature(QStringLiteral("I1"), ProfileEditing::tr("bore"), SegmentKind::Cylinder, {0.0, r},
                                    {bottom, r}));
        inner.push_back(makeFeature(QStringLiteral("I2"), ProfileEditing::tr("bore bottom"), SegmentKind::Face,
                                    {bottom, r}, {bottom, 0.0}));
    } else {
        inner.push_back(makeFeature(QStringLiteral("I1"), ProfileEditing::tr("bore bottom"), SegmentKind::Face,
                                    {bottom, 0.0}, {bottom, r}));
        inner.push_back(makeFeature(QStringLiteral("I2"), ProfileEditing::tr("bore"), SegmentKind::Cylinder,
                                    {bottom, r}, {length, r}));
    }
    if (left || through)
        result.outer.segments.front().from.r_mm = r;
    if (right || through)
        result.outer.segments.back().to.r_mm = r;
    return result;
}

ProfileEdit swapCornerBreak(const PartProfile &profile, const QString &featureId)
{
    const std::optional<FeatureRef> ref = findFeature(profile, featureId);
    const bool edge = ref && (ref->segment->kind == SegmentKind::Chamfer || ref->segment->kind == SegmentKind::Radius);
    if (!edge)
        return ProfileEditing::tr("only a chamfer or an edge round changes into the other; %1 is neither")
            .arg(featureId);
    const Segment old = *ref->segment;
    const bool toRound = old.kind == SegmentKind::Chamfer;
    // The size both breaks share at a right-angled corner: a 45° chamfer's leg along each side
    // is the tangent length of the quarter circle that replaces it, which is its radius.
    const double size_mm = toRound
                               ? std::max(std::abs(old.to.z_mm - old.from.z_mm), std::abs(old.to.r_mm - old.from.r_mm))
                               : old.arcRadius_mm;
    const ProfileEdit sharp = deleteFeature(profile, featureId);
    if (const auto *refusal = std::get_if<QString>(&sharp))
        return *refusal;
    ProfileEdit swapped = breakCorner(std::get<PartProfile>(sharp), ref->side, ref->index, size_mm, toRound);
    if (auto *part = std::get_if<PartProfile>(&swapped)) {
        // The break keeps its id, so that tolerances on it stay attached.
        Segment &made = part->contour(ref->side).segments[static_cast<std::size_t>(ref->index)];
        made.id = old.id;
    }
    return swapped;
}

ProfileEdit deleteFeature(const PartProfile &profile, const QString &featureId)
{
    const std::optional<FeatureRef> ref = findFeature(profile, featureId);
    if (!ref)
        return ProfileEditing::tr("there is no feature %1").arg(featureId);
    PartProfile result = profile;
    std::vector<Segment> &s = result.contour(ref->side).segments;
    const auto i = static_cast<std::size_t>(ref->index);
    const Contour &original = profile.contour(ref->side);
    if (i == 0 || i + 1 >= s.size() || original.breaksBefore(i) || original.breaksBefore(i + 1))
        return ProfileEditing::tr("%1 is an end of the %2 contour (or of a bore); move it instead of deleting it")
            .arg(featureId, contourName(ref->side));
    // The end (exclusive, after the erase below) of the run of features joined to it.
    std::size_t pieceEnd = i;
    while (pieceEnd + 1 < original.segments.size() && !original.breaksBefore(pieceEnd + 1))
        ++pieceEnd;
    const Segment removed = s[i];
    s.erase(s.begin() + static_cast<std::ptrdiff_t>(i));
    Segment &before = s[i - 1];
    if (removed.kind == SegmentKind::Chamfer || removed.kind == SegmentKind::Radius) {
        const std::optional<ProfilePoint> corner = lineIntersection(before, s[i]);
        if (!corner)
            return ProfileEditing::tr("the features beside %1 are parallel: there is no corner to give back")
                .arg(featureId);
        before.to = *corner;
        s[i].from = *corner;
    } else if (removed.kind == SegmentKind::Face && before.kind == SegmentKind::Cylinder &&
               s[i].kind == SegmentKind::Cylinder) {
        moveStart(s, i, before.to); // the step goes: the second cylinder takes the first's diameter
    } else {
        // Close the gap: the rest of the contour shifts by the removed feature's extent.
        const double dz = removed.to.z_mm - removed.from.z_mm, dr = removed.to.r_mm - removed.from.r_mm;
        for (std::size_t j = i; j < pieceEnd; ++j) {
            s[j].from = {s[j].from.z_mm - dz, s[j].from.r_mm - dr};
            s[j].to = {s[j].to.z_mm - dz, s[j].to.r_mm - dr};
        }
    }
    mergeAt(s, i);
    joinEndFacesToBore(result);
    return result;
}

} // namespace tolturn
