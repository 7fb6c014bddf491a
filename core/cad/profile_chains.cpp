// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cad/profile_chains.h"

#include "core/part/profile_geometry.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace tolturn::cad {

namespace {

struct ProfileChains {
    Q_DECLARE_TR_FUNCTIONS(ProfileChains)
};

constexpr double kPi = std::numbers::pi;

// A chamfer is a 45° edge break on most drawings (ISO 13715 shows 45° as the default); one
// degree either side still counts, for files rounded by their writer.
constexpr double kChamferAngle_deg = 45.0;
constexpr double kChamferAngleSlack_deg = 1.0;

QString num(double v)
{
    return formatNumber(v);
}

bool near(const ProfilePoint &p, const ProfilePoint &q)
{
    return std::abs(p.z_mm - q.z_mm) <= kJoinTolerance_mm && std::abs(p.r_mm - q.r_mm) <= kJoinTolerance_mm;
}

// The pieces as a graph: vertices are the snapped end points, each piece an edge.
struct Graph {
    std::vector<ProfilePoint> vertices;
    std::vector<std::pair<int, int>> ends;  // per piece: vertex of a, vertex of b
    std::vector<std::vector<int>> incident; // per vertex: pieces

    int vertexOf(const ProfilePoint &p)
    {
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            if (near(vertices[i], p))
                return static_cast<int>(i);
        }
        vertices.push_back(p);
        incident.emplace_back();
        return static_cast<int>(vertices.size() - 1);
    }
};

Graph makeGraph(const std::vector<SectionPiece> &pieces)
{
    Graph g;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const int va = g.vertexOf(pieces[i].a);
        const int vb = g.vertexOf(pieces[i].b);
        g.ends.emplace_back(va, vb);
        g.incident[static_cast<std::size_t>(va)].push_back(static_cast<int>(i));
        if (vb != va)
            g.incident[static_cast<std::size_t>(vb)].push_back(static_cast<int>(i));
    }
    return g;
}

struct Step {
    int piece = -1;
    bool forward = true; // travelled from a to b
};

struct Walk {
    std::vector<Step> steps;
    int endVertex = -1;
    double maxR_mm = 0.0;
};

// Follows the chain from `start` through `first` until `stop`, a dead end (the axis, or a gap)
// or a branch. A turned part's section boundary passes each vertex once, so a vertex has two
// pieces except where the boundary meets the axis.
Walk walkChain(const Graph &g, int start, int first, int stop)
{
    Walk w;
    std::vector<bool> used(g.ends.size(), false);
    int v = start;
    int p = first;
    while (p >= 0 && !used[static_cast<std::size_t>(p)]) {
        used[static_cast<std::size_t>(p)] = true;
        const auto [va, vb] = g.ends[static_cast<std::size_t>(p)];
        const bool forward = va == v;
        w.steps.push_back({p, forward});
        v = forward ? vb : va;
        w.maxR_mm = std::max(w.maxR_mm, g.vertices[static_cast<std::size_t>(v)].r_mm);
        if (v == stop)
            break;
        const std::vector<int> &next = g.incident[static_cast<std::size_t>(v)];
        p = -1;
        if (next.size() == 2)
            p = next[0] == w.steps.back().piece ? next[1] : next[0];
    }
    w.endVertex = v;
    return w;
}

// The lowest vertex on the end face at z (the left or right end of the part): where the outer
// contour starts or ends.
int lowestVertexAt(const Graph &g, double z_mm)
{
    int best = -1;
    for (std::size_t i = 0; i < g.vertices.size(); ++i) {
        const ProfilePoint &p = g.vertices[i];
        if (std::abs(p.z_mm - z_mm) <= kJoinTolerance_mm &&
            (best < 0 || p.r_mm < g.vertices[static_cast<std::size_t>(best)].r_mm))
            best = static_cast<int>(i);
    }
    return best;
}

SegmentKind lineKind(const ProfilePoint &from, const ProfilePoint &to)
{
    if (std::abs(to.z_mm - from.z_mm) <= kJoinTolerance_mm)
        return SegmentKind::Face;
    if (std::abs(to.r_mm - from.r_mm) <= kJoinTolerance_mm)
        return SegmentKind::Cylinder;
    return SegmentKind::Cone;
}

// Travel sense in the (z right, r up) plane: the centre lies to the left of the chord for a
// counter-clockwise minor arc (the convention of arcGeometry in core/part/profile_geometry).
ArcDirection arcDirection(const ProfilePoint &from, const ProfilePoint &to, const ProfilePoint &centre)
{
    const double cross =
        (to.z_mm - from.z_mm) * (centre.r_mm - from.r_mm) - (to.r_mm - from.r_mm) * (centre.z_mm - from.z_mm);
    return cross > 0.0 ? ArcDirection::CounterClockwise : ArcDirection::Clockwise;
}

Segment toSegment(const Graph &g, const std::vector<SectionPiece> &pieces, const Step &step)
{
    const SectionPiece &piece = pieces[static_cast<std::size_t>(step.piece)];
    const auto [va, vb] = g.ends[static_cast<std::size_t>(step.piece)];
    Segment s;
    // Snapped vertices, so that joints are exactly equal.
    s.from = g.vertices[static_cast<std::size_t>(step.forward ? va : vb)];
    s.to = g.vertices[static_cast<std::size_t>(step.forward ? vb : va)];
    if (piece.arc) {
        s.kind = SegmentKind::Radius;
        s.arcRadius_mm = piece.radius_mm;
        s.arcDirection = arcDirection(s.from, s.to, piece.centre);
    } else {
        s.kind = lineKind(s.from, s.to);
    }
    return s;
}

std::vector<Segment> toSegments(const Graph &g, const std::vector<SectionPiece> &pieces, const std::vector<Step> &steps)
{
    std::vector<Segment> out;
    out.reserve(steps.size());
    for (const Step &step : steps)
        out.push_back(toSegment(g, pieces, step));
    return out;
}

void reverseChain(std::vector<Segment> &segments)
{
    std::reverse(segments.begin(), segments.end());
    for (Segment &s : segments) {
        std::swap(s.from, s.to);
        if (s.kind == SegmentKind::Radius)
            s.arcDirection =
                s.arcDirection == ArcDirection::Clockwise ? ArcDirection::CounterClockwise : ArcDirection::Clockwise;
    }
}

bool collinear(const Segment &s, const Segment &t)
{
    if (s.kind != t.kind || s.kind == SegmentKind::Radius)
        return false;
    const double cross =
        (s.to.z_mm - s.from.z_mm) * (t.to.r_mm - t.from.r_mm) - (s.to.r_mm - s.from.r_mm) * (t.to.z_mm - t.from.z_mm);
    return std::abs(cross) <= kJoinTolerance_mm * std::max(1.0, segmentLength_mm(s) + segmentLength_mm(t));
}

bool joined(const Segment &s, const Segment &t)
{
    return std::hypot(s.to.z_mm - t.from.z_mm, s.to.r_mm - t.from.r_mm) <= kJoinTolerance_mm;
}

// A face split into several (a cylinder cut in two along z by some writers) is one feature; the
// bottoms of a bore from each end are two, with the solid between them.
void mergeCollinear(std::vector<Segment> &segments)
{
    std::vector<Segment> out;
    for (const Segment &s : segments) {
        if (!out.empty() && joined(out.back(), s) && collinear(out.back(), s))
            out.back().to = s.to;
        else
            out.push_back(s);
    }
    segments = std::move(out);
}

double angleToAxis_deg(const Segment &s)
{
    return std::atan2(std::abs(s.to.r_mm - s.from.r_mm), std::abs(s.to.z_mm - s.from.z_mm)) * 180.0 / kPi;
}

bool isStraightCorner(const Segment *s)
{
    return s == nullptr || s->kind == SegmentKind::Cylinder || s->kind == SegmentKind::Face;
}

// A short cone that breaks an edge is a chamfer: no longer than the threshold along its slant,
// and either at 45° or between a cylinder and a face (the corner it breaks). Longer cones and
// short cones between cones or radii are turned as cones.
void markChamfers(std::vector<Segment> &segments, double maxLength_mm)
{
    for (std::size_t i = 0; i < segments.size(); ++i) {
        Segment &s = segments[i];
        if (s.kind != SegmentKind::Cone || segmentLength_mm(s) > maxLength_mm + kJoinTolerance_mm)
            continue;
        const Segment *before = i > 0 ? &segments[i - 1] : nullptr;
        const Segment *after = i + 1 < segments.size() ? &segments[i + 1] : nullptr;
        const bool at45 = std::abs(angleToAxis_deg(s) - kChamferAngle_deg) <= kChamferAngleSlack_deg;
        if (at45 || (isStraightCorner(before) && isStraightCorner(after)))
            s.kind = SegmentKind::Chamfer;
    }
}

QString diameterText(double r_mm)
{
    return QStringLiteral("Ø%1").arg(num(2.0 * r_mm));
}

QString outerName(const Segment &s, bool first, bool last)
{
    switch (s.kind) {
    case SegmentKind::Face:
        if (first)
            return ProfileChains::tr("left end face");
        if (last)
            return ProfileChains::tr("right end face");
        return ProfileChains::tr("shoulder");
    case SegmentKind::Cylinder:
        return ProfileChains::tr("cylinder %1").arg(diameterText(s.from.r_mm));
    case SegmentKind::Cone:
        return ProfileChains::tr("cone");
    case SegmentKind::Chamfer:
        return ProfileChains::tr("chamfer");
    case SegmentKind::Radius:
        return ProfileChains::tr("radius R%1").arg(num(s.arcRadius_mm));
    }
    return {};
}

QString innerName(const Segment &s)
{
    const bool onAxis = s.from.r_mm <= kJoinTolerance_mm || s.to.r_mm <= kJoinTolerance_mm;
    switch (s.kind) {
    case SegmentKind::Face:
        return onAxis ? ProfileChains::tr("bore bottom") : ProfileChains::tr("bore step");
    case SegmentKind::Cylinder:
        return ProfileChains::tr("bore %1").arg(diameterText(s.from.r_mm));
    case SegmentKind::Cone:
        return onAxis ? ProfileChains::tr("drill point") : ProfileChains::tr("bore cone");
    case SegmentKind::Chamfer:
        return ProfileChains::tr("bore chamfer");
    case SegmentKind::Radius:
        return ProfileChains::tr("bore radius R%1").arg(num(s.arcRadius_mm));
    }
    return {};
}

// Ids as the profile editor gives them (nextFeatureId): O1, O2, … and I1, I2, … in contour order.
void nameSegments(std::vector<Segment> &segments, ContourSide side)
{
    for (std::size_t i = 0; i < segments.size(); ++i) {
        Segment &s = segments[i];
        s.id = (side == ContourSide::Outer ? QStringLiteral("O") : QStringLiteral("I")) + QString::number(i + 1);
        s.name = side == ContourSide::Outer ? outerName(s, i == 0, i + 1 == segments.size()) : innerName(s);
    }
}

Contour finishContour(std::vector<Segment> segments, ContourSide side, double chamferMaxLength_mm)
{
    mergeCollinear(segments);
    markChamfers(segments, chamferMaxLength_mm);
    nameSegments(segments, side);
    return Contour{std::move(segments)};
}

void markUsed(const Walk &w, std::vector<bool> &used)
{
    for (const Step &s : w.steps)
        used[static_cast<std::size_t>(s.piece)] = true;
}

// The bore chains: from the left end to the right end (a through bore), or from either end to
// the axis (blind bores, centre holes).
struct Bores {
    std::optional<Walk> through;
    std::optional<Walk> left;
    std::optional<Walk> right; // walked from the right end towards the axis
};

Bores findBores(const Graph &g, int left, int right, const std::vector<Walk> &fromLeft, const std::vector<bool> &used)
{
    Bores b;
    for (const Walk &w : fromLeft) {
        if (used[static_cast<std::size_t>(w.steps.front().piece)])
            continue;
        if (w.endVertex == right)
            b.through = w;
        else
            b.left = w;
    }
    if (b.through)
        return b;
    for (const int p : g.incident[static_cast<std::size_t>(right)]) {
        if (!used[static_cast<std::size_t>(p)])
            b.right = walkChain(g, right, p, left);
    }
    return b;
}

void reportLeftOver(const std::vector<SectionPiece> &pieces, const std::vector<bool> &used, Diagnostics &out)
{
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        if (used[i])
            continue;
        const SectionPiece &p = pieces[i];
        out.push_back(makeWarning(
            QStringLiteral("step.face[%1]").arg(p.faces.empty() ? 0 : p.faces.front()),
            ProfileChains::tr("the revolved face %1 (from z = %2 mm to z = %3 mm, r = %4 to %5 mm) does not join the "
                              "outer or inner contour (a closed inner cavity, or faces beyond a gap in the "
                              "section) and is left out of the profile")
                .arg(p.faces.empty() ? 0 : p.faces.front())
                .arg(num(std::min(p.a.z_mm, p.b.z_mm)), num(std::max(p.a.z_mm, p.b.z_mm)),
                     num(std::min(p.a.r_mm, p.b.r_mm)), num(std::max(p.a.r_mm, p.b.r_mm)))));
    }
}

std::pair<double, double> zExtent(const std::vector<SectionPiece> &pieces)
{
    double lo = HUGE_VAL;
    double hi = -HUGE_VAL;
    for (const SectionPiece &p : pieces) {
        lo = std::min({lo, p.a.z_mm, p.b.z_mm});
        hi = std::max({hi, p.a.z_mm, p.b.z_mm});
    }
    return {lo, hi};
}

// Where the section breaks: the end of the longest chain from the left end (the place to look
// for the face that is missing or not turned).
Diagnostic brokenSectionError(const Graph &g, const std::vector<Walk> &fromLeft, int left, double zLeft, double zRight)
{
    int stop = left;
    std::size_t longest = 0;
    for (const Walk &w : fromLeft) {
        if (w.steps.size() > longest) {
            longest = w.steps.size();
            stop = w.endVertex;
        }
    }
    const ProfilePoint &p = g.vertices[static_cast<std::size_t>(stop)];
    return makeError(QStringLiteral("step"),
                     ProfileChains::tr("the revolved faces do not form a closed section from the left end (z = %1 mm) "
                                       "to the right end (z = %2 mm): the contour from the left end stops at z = %3 "
                                       "mm, r = %4 mm, where a face is missing or not turned (see the warnings)")
                         .arg(num(zLeft), num(zRight), num(p.z_mm), num(p.r_mm)));
}

} // namespace

double revolvedArea_mm2(const SectionPiece &piece)
{
    if (!piece.arc) {
        const double length = std::hypot(piece.b.z_mm - piece.a.z_mm, piece.b.r_mm - piece.a.r_mm);
        return kPi * (piece.a.r_mm + piece.b.r_mm) * length;
    }
    const ProfilePoint &c = piece.centre;
    const double rho = piece.radius_mm;
    const double t0 = std::atan2(piece.a.r_mm - c.r_mm, piece.a.z_mm - c.z_mm);
    const double sweep = std::remainder(std::atan2(piece.b.r_mm - c.r_mm, piece.b.z_mm - c.z_mm) - t0, 2.0 * kPi);
    // r = c.r + rho sin(t), ds = rho dt.
    const double integral = rho * (c.r_mm * sweep - rho * (std::cos(t0 + sweep) - std::cos(t0)));
    return 2.0 * kPi * std::abs(integral);
}

Placement placementOf(const std::vector<SectionPiece> &pieces, bool flip, double offset_mm)
{
    if (pieces.empty())
        return {0.0, 0.0, flip, offset_mm};
    const auto [lo, hi] = zExtent(pieces);
    return {lo, hi, flip, offset_mm};
}

void placePieces(std::vector<SectionPiece> &pieces, const Placement &placement)
{
    const auto place = [&](ProfilePoint &p) { p.z_mm = placement(p.z_mm); };
    for (SectionPiece &p : pieces) {
        place(p.a);
        place(p.b);
        place(p.centre);
    }
}

ContourBuild buildContours(const std::vector<SectionPiece> &pieces, double chamferMaxLength_mm)
{
    ContourBuild out;
    if (pieces.empty())
        return out;
    const Graph g = makeGraph(pieces);
    const auto [zLeft, zRight] = zExtent(pieces);
    const int left = lowestVertexAt(g, zLeft);
    const int right = lowestVertexAt(g, zRight);
    std::vector<Walk> fromLeft;
    for (const int p : g.incident[static_cast<std::size_t>(left)])
        fromLeft.push_back(walkChain(g, left, p, right));
    // The outer contour joins the two ends around the outside: of the chains from the left end
    // that reach the right end, the one that goes furthest from the axis.
    const Walk *outer = nullptr;
    for (const Walk &w : fromLeft) {
        if (w.endVertex == right && (outer == nullptr || w.maxR_mm > outer->maxR_mm))
            outer = &w;
    }
    std::vector<bool> used(pieces.size(), false);
    if (outer == nullptr) {
        out.diagnostics.push_back(brokenSectionError(g, fromLeft, left, zLeft, zRight));
        return out;
    }
    markUsed(*outer, used);
    std::vector<Segment> outerSegments = toSegments(g, pieces, outer->steps);
    // The inner contour: a through bore, or the bore from the left end (closing on the axis) and
    // then the one from the right end, walked from that end and turned to run left to right.
    const Bores bores = findBores(g, left, right, fromLeft, used);
    std::vector<Segment> inner;
    for (const std::optional<Walk> *bore : {&bores.through, &bores.left, &bores.right}) {
        if (!bore->has_value())
            continue;
        markUsed(**bore, used);
        std::vector<Segment> chain = toSegments(g, pieces, (*bore)->steps);
        if (bore == &bores.right)
            reverseChain(chain);
        inner.insert(inner.end(), chain.begin(), chain.end());
    }
    out.outer = finishContour(std::move(outerSegments), ContourSide::Outer, chamferMaxLength_mm);
    if (!inner.empty())
        out.inner = finishContour(std::move(inner), ContourSide::Inner, chamferMaxLength_mm);
    reportLeftOver(pieces, used, out.diagnostics);
    return out;
}

} // namespace tolturn::cad
