// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/toolpath.h"

#include "core/part/profile_geometry.h"
#include "core/planning/path_geometry.h"
#include "core/planning/toolpath_detail.h"
#include "core/tolerance/target_contour.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

namespace tolturn {

namespace {

struct Toolpaths {
    Q_DECLARE_TR_FUNCTIONS(Toolpath)
};

constexpr double kTiny = 1e-9;

QString mm(double value)
{
    return QString::number(value, 'f', 3);
}

PathElement line(ProfilePoint from, ProfilePoint to, const QString &featureId)
{
    PathElement e;
    e.from = from;
    e.to = to;
    e.featureId = featureId;
    return e;
}

// A feature moved by a compensation meets its neighbour across a gap of micrometres. The neighbour
// takes it up where that changes nothing the verdicts judge: a face (a radial gap leaves it the same
// plane), or a line no tolerance is on (a chamfer, say) by moving its end, a gap small against its
// length. A step of a few µm beside a corner is a move no control can follow with the nose radius
// compensated (LinuxCNC: "Straight feed in concave corner cannot be reached by the tool without
// gouging"), so it is programmed only where neither holds: beside a round or a toleranced feature.
// The moved feature itself is never moved back.
void joinMovedFeature(std::vector<PathElement> &out, PathElement &next, bool nextMoved, const CompensationPlan *plan)
{
    PathElement &previous = out.back();
    PathElement &neighbour = nextMoved ? previous : next;
    const double gapZ = next.from.z_mm - previous.to.z_mm;
    const double gap = std::hypot(gapZ, next.from.r_mm - previous.to.r_mm);
    const double length = std::hypot(neighbour.to.z_mm - neighbour.from.z_mm, neighbour.to.r_mm - neighbour.from.r_mm);
    const bool face = !neighbour.arc && std::abs(neighbour.from.z_mm - neighbour.to.z_mm) < kTiny;
    const FeatureCompensation *c = plan ? plan->find(neighbour.featureId) : nullptr;
    const bool toleranced = c != nullptr && !c->tolerances.isEmpty();
    const bool radialGap = std::abs(gapZ) < kTiny;
    const bool takesItUp = !neighbour.arc && gap < 0.5 * length && ((face && radialGap) || (!face && !toleranced));
    if (!takesItUp)
        out.push_back(line(previous.to, next.from, next.featureId));
    else if (nextMoved)
        previous.to = next.from;
    else
        next.from = previous.to;
}

ToolMove move(MoveKind kind, ProfilePoint to, const QString &featureId = {})
{
    ToolMove m;
    m.kind = kind;
    m.to = to;
    m.featureId = featureId;
    return m;
}

ToolMove moveAlong(const PathElement &e)
{
    ToolMove m = move(MoveKind::Feed, e.to, e.featureId);
    if (e.arc) {
        m.kind = e.counterClockwise ? MoveKind::ArcCounterClockwise : MoveKind::ArcClockwise;
        m.centre = e.centre;
        m.radius_mm = e.radius_mm;
    }
    return m;
}

// With the control's nose radius compensation a concave arc tighter than the nose is refused (the
// offset arc would have a negative radius): it is programmed as the corner where its neighbours
// meet, which the nose rounds with its own radius. A neighbour that is a line is extended to the
// corner; one that is a convex arc is left as it is and its tangent at the joint is programmed on to
// the corner (the tangent of a convex arc runs outside its material, so the nose cuts nothing of it).
// A concave arc next to it, or neighbours that do not meet, leave the arc as it is: `kept` gets its
// id. Returns the ids of the arcs replaced.
QStringList sharpenTightConcaveArcs(std::vector<PathElement> &chain, double noseRadius_mm, QStringList &kept)
{
    QStringList replaced;
    for (std::size_t i = 1; i + 1 < chain.size(); ++i) {
        const PathElement &e = chain[i];
        if (!e.arc || e.counterClockwise || e.radius_mm > noseRadius_mm + kTiny)
            continue;
        const PathElement &before = chain[i - 1];
        const PathElement &after = chain[i + 1];
        const ProfilePoint d1 = endTangent(before);
        const ProfilePoint d2 = startTangent(after);
        const double det = d1.z_mm * d2.r_mm - d1.r_mm * d2.z_mm;
        const bool concaveNeighbour =
            (before.arc && !before.counterClockwise) || (after.arc && !after.counterClockwise);
        if (concaveNeighbour || std::abs(det) < 1e-12) {
            kept << e.featureId;
            continue;
        }
        const ProfilePoint p1 = before.to;
        const ProfilePoint p2 = after.from;
        const double t = ((p2.z_mm - p1.z_mm) * d2.r_mm - (p2.r_mm - p1.r_mm) * d2.z_mm) / det;
        const ProfilePoint corner{p1.z_mm + t * d1.z_mm, p1.r_mm + t * d1.r_mm};
        replaced << e.featureId;
        std::vector<PathElement> bridge;
        if (before.arc)
            bridge.push_back(line(p1, corner, e.featureId));
        else
            chain[i - 1].to = corner;
        if (after.arc)
            bridge.push_back(line(corner, p2, e.featureId));
        else
            chain[i + 1].from = corner;
        chain.erase(chain.begin() + static_cast<std::ptrdiff_t>(i));
        chain.insert(chain.begin() + static_cast<std::ptrdiff_t>(i), bridge.begin(), bridge.end());
        i += bridge.size();
        --i;
    }
    return replaced;
}

// The envelope from index i in direction `step` until it first reaches `level`: the points passed
// (nose-centre coordinates; -infinity where no contour is near), ending on the level. Between two
// samples the path runs straight where the envelope is gentle (its chord then stays within the
// sagitta of the nose circle, far below a micrometre on this grid) and, where it rises or falls
// by more than a grid step, goes round the step at the higher of the two samples, so that it
// never cuts into the allowance. At the end of the region the tool climbs straight up to the level.
std::vector<ProfilePoint> flank(const Envelope &env, std::ptrdiff_t i, std::ptrdiff_t step, double level)
{
    std::vector<ProfilePoint> points;
    const auto n = static_cast<std::ptrdiff_t>(env.r_mm.size());
    for (; i >= 0 && i < n; i += step) {
        const double z = env.z(static_cast<std::size_t>(i));
        const double r = env.r_mm[static_cast<std::size_t>(i)];
        const bool steep = points.empty() || !std::isfinite(points.back().r_mm) || !std::isfinite(r) ||
                           std::abs(r - points.back().r_mm) > env.step_mm;
        if (r >= level) {
            if (steep) {
                if (!points.empty())
                    points.push_back({points.back().z_mm, level});
                else
                    points.push_back({z, level});
            } else {
                const ProfilePoint previous = points.back();
                const double t = (level - previous.r_mm) / (r - previous.r_mm);
                points.push_back({previous.z_mm + t * (z - previous.z_mm), level});
            }
            return points;
        }
        if (steep && !points.empty() && std::isfinite(r) && std::isfinite(points.back().r_mm)) {
            const ProfilePoint previous = points.back();
            points.push_back(r > previous.r_mm ? ProfilePoint{previous.z_mm, r} : ProfilePoint{z, previous.r_mm});
        }
        points.push_back({z, r});
    }
    if (!points.empty())
        points.push_back({points.back().z_mm, level});
    return points;
}

void addFeeds(PassPath &pass, const std::vector<ProfilePoint> &points, double noseRadius_mm)
{
    for (const ProfilePoint &p : simplified(points, 0.001))
        pass.moves.push_back(move(MoveKind::Feed, {p.z_mm - noseRadius_mm, p.r_mm - noseRadius_mm}));
}

// One roughing level (nose-centre coordinates): every stretch where the allowance lies below the
// level, entered from the right (in the air or down the right flank from the level above) and left
// up the left flank to the level above. Rapid moves are at the safe radius (tool tip).
void roughLevel(PassPath &pass, const Envelope &env, double level, double levelAbove, double safeRadius,
                double noseRadius_mm, double clearance_mm)
{
    auto raised = [level](ProfilePoint p) { return ProfilePoint{p.z_mm, std::max(p.r_mm, level)}; };
    std::ptrdiff_t i = static_cast<std::ptrdiff_t>(env.r_mm.size()) - 1;
    while (i >= 0) {
        if (env.r_mm[static_cast<std::size_t>(i)] >= level) {
            --i;
            continue;
        }
        const std::ptrdiff_t right = i;
        while (i >= 0 && env.r_mm[static_cast<std::size_t>(i)] < level)
            --i;
        const std::ptrdiff_t left = i + 1;
        std::vector<ProfilePoint> cut;
        const std::vector<ProfilePoint> down = flank(env, right, +1, levelAbove);
        for (std::size_t k = down.size(); k-- > 0;) // clang 14 cannot use views::reverse
            cut.push_back(raised(down[k]));
        cut.push_back({env.z(static_cast<std::size_t>(left)), level});
        for (const ProfilePoint &p : flank(env, left, -1, levelAbove))
            cut.push_back(raised(p));
        const double zEntry = cut.front().z_mm - noseRadius_mm;
        pass.moves.push_back(move(MoveKind::Rapid, {zEntry, safeRadius}));
        pass.moves.push_back(move(MoveKind::Rapid, {zEntry, levelAbove - noseRadius_mm + clearance_mm}));
        addFeeds(pass, cut, noseRadius_mm);
        pass.moves.push_back(move(MoveKind::Rapid, {pass.moves.back().to.z_mm, safeRadius}));
    }
}

} // namespace

namespace toolpath_detail {

// The outline a turning insert cuts of a contour with undercuts: a run of elements that go back
// along z between a face and the floor beside it (an undercut's recess under its shoulder) is
// bridged: the face runs on to where the recess's radius crosses its z, and the part of that radius
// from there to the floor stays (without such a radius, the face and the floor meet at a corner).
// The recess is the undercut insert's; warnAtUndercuts says so. Other runs are followed as drawn.
// `bridged` gets the ids of the elements left out.
Contour withoutUndercuts(Contour contour, QStringList *bridged)
{
    std::vector<Segment> &s = contour.segments;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s[i].turnsBack())
            continue;
        std::size_t j = i;
        while (j + 1 < s.size() && s[j + 1].turnsBack())
            ++j;
        const bool faceBefore =
            i > 0 && j + 1 < s.size() && s[i - 1].kind == SegmentKind::Face && s[j + 1].kind == SegmentKind::Cylinder;
        const bool faceAfter =
            i > 0 && j + 1 < s.size() && s[i - 1].kind == SegmentKind::Cylinder && s[j + 1].kind == SegmentKind::Face;
        if (!faceBefore && !faceAfter) {
            i = j; // no face and floor to bridge between: followed as drawn
            continue;
        }
        Segment &face = faceBefore ? s[i - 1] : s[j + 1];
        Segment &floor = faceBefore ? s[j + 1] : s[i - 1];
        const double zFace = face.from.z_mm;
        const Segment &floorSide = faceBefore ? s[j] : s[i];
        std::vector<Segment> kept;
        ProfilePoint rim{zFace, floor.from.r_mm};
        const std::vector<double> crossing =
            floorSide.kind == SegmentKind::Radius ? crossingRadii(floorSide, zFace) : std::vector<double>{};
        if (crossing.size() == 1) {
            rim.r_mm = crossing.front();
            Segment part = floorSide; // the same circle, from the rim to the floor
            (faceBefore ? part.from : part.to) = rim;
            kept.push_back(part);
        } else {
            (faceBefore ? floor.from : floor.to) = rim;
        }
        (faceBefore ? face.to : face.from) = rim;
        for (std::size_t k = i; k <= j && bridged != nullptr; ++k)
            *bridged << s[k].id;
        s.erase(s.begin() + static_cast<std::ptrdiff_t>(i), s.begin() + static_cast<std::ptrdiff_t>(j) + 1);
        s.insert(s.begin() + static_cast<std::ptrdiff_t>(i), kept.begin(), kept.end());
        i += kept.size();
    }
    return contour;
}

// The radial correction of a feature at z, linear between its stations (corrected − target radius),
// held at the end stations beyond them.
double correctionAt(const std::vector<std::pair<double, double>> &byZ, double z)
{
    if (z <= byZ.front().first)
        return byZ.front().second;
    for (std::size_t i = 1; i < byZ.size(); ++i) {
        if (z <= byZ[i].first) {
            const double t = (z - byZ[i - 1].first) / (byZ[i].first - byZ[i - 1].first);
            return byZ[i - 1].second + t * (byZ[i].second - byZ[i - 1].second);
        }
    }
    return byZ.back().second;
}

// A round corrected station by station, as lines short enough that each stays within 0.25 µm of
// the corrected arc: the sagitta of a chord over the angle θ of an arc of radius R is R(1 − cos θ/2)
// (a chord between the stations, spaced evenly in z, would cut up to tens of µm into a small round
// where it turns steep). Each point is the arc's, moved by the stations' correction at its z.
std::vector<PathElement> correctedArc(const PathElement &arc, const std::vector<ProfilePoint> &stations)
{
    std::vector<std::pair<double, double>> byZ;
    byZ.reserve(stations.size());
    for (const ProfilePoint &st : stations)
        byZ.emplace_back(st.z_mm, st.r_mm - pointAtZ(arc, st.z_mm).r_mm);
    std::sort(byZ.begin(), byZ.end());
    constexpr double kSagitta_mm = 0.25e-3;
    const double angle = 2.0 * std::acos(1.0 - kSagitta_mm / arc.radius_mm);
    std::vector<ProfilePoint> points = sampled(arc, angle * arc.radius_mm);
    for (ProfilePoint &q : points)
        q.r_mm += correctionAt(byZ, q.z_mm);
    std::vector<PathElement> out;
    for (std::size_t i = 1; i < points.size(); ++i)
        out.push_back(line(points[i - 1], points[i], arc.featureId));
    return out;
}

std::vector<PathElement> compensatedChain(const Contour &target, const CompensationPlan *plan)
{
    std::vector<PathElement> out;
    for (PathElement e : reversedElements(withoutUndercuts(target).segments)) {
        const FeatureCompensation *c = plan ? plan->find(e.featureId) : nullptr;
        std::vector<PathElement> pieces;
        if (c && c->action == CompensationAction::ProfileCorrection && c->correctedPath.size() >= 2 && e.arc) {
            pieces = correctedArc(e, c->correctedPath);
        } else if (c && c->action == CompensationAction::ProfileCorrection && c->correctedPath.size() >= 2) {
            for (std::size_t j = c->correctedPath.size() - 1; j > 0; --j)
                pieces.push_back(line(c->correctedPath[j], c->correctedPath[j - 1], e.featureId));
            // The stations end at the chuck face; a bore runs on inside the jaws, from the last corrected
            // radius to the drawn one at its end.
            const double zEnd = c->correctedPath.front().z_mm;
            if (!e.arc && std::abs(e.to.z_mm - zEnd) > kTiny && (e.to.z_mm - zEnd) * (e.to.z_mm - e.from.z_mm) > 0.0)
                pieces.push_back(line(c->correctedPath.front(), e.to, e.featureId)); // from the corrected radius
        } else {
            if (c && c->action == CompensationAction::ConstantOffset) {
                const double shift = 0.5e-3 * c->offset_um;
                e.from.r_mm += shift;
                e.to.r_mm += shift;
                e.centre.r_mm += shift;
            }
            pieces.push_back(e);
        }
        for (PathElement p : pieces) {
            if (!out.empty() && std::hypot(out.back().to.z_mm - p.from.z_mm, out.back().to.r_mm - p.from.r_mm) > kTiny)
                joinMovedFeature(out, p, c != nullptr && c->action != CompensationAction::None, plan);
            out.push_back(p);
        }
    }
    return out;
}

// The point of an element where z = zCut (the element crosses it).
ProfilePoint pointAtZ(const PathElement &e, double zCut)
{
    if (!e.arc) {
        const double t = (zCut - e.from.z_mm) / (e.to.z_mm - e.from.z_mm);
        return {zCut, e.from.r_mm + t * (e.to.r_mm - e.from.r_mm)};
    }
    const double dz = zCut - e.centre.z_mm;
    const double h = std::sqrt(std::max(e.radius_mm * e.radius_mm - dz * dz, 0.0));
    const double lo = std::min(e.from.r_mm, e.to.r_mm) - kTiny;
    const double hi = std::max(e.from.r_mm, e.to.r_mm) + kTiny;
    const double up = e.centre.r_mm + h;
    return {zCut, (up >= lo && up <= hi) ? up : e.centre.r_mm - h};
}

// The chain up to where it first passes z = zMin going left. `zMin` is a limit of the nose centre;
// a face that faces the free end (on an outer contour r rises along it going left, in a bore it
// falls) is cut with the centre `faceReach_mm` (r_e) right of it, so it is kept while it lies no
// further left than that. So is a concave fillet tighter than the nose in front of such a face: the
// nose, touching the face, does not touch the fillet (it is programmed as the corner, see
// sharpenTightConcaveArcs), so it does not stop the nose short of the face.
std::vector<PathElement> clippedAtLeft(const std::vector<PathElement> &chain, double zMin, double faceReach_mm,
                                       bool bore)
{
    const auto reachableFace = [&](const PathElement &e) {
        const bool face = !e.arc && std::abs(e.from.z_mm - e.to.z_mm) < kTiny;
        const bool facesTheFreeEnd = face && (bore ? e.to.r_mm < e.from.r_mm : e.to.r_mm > e.from.r_mm);
        return facesTheFreeEnd && e.from.z_mm + faceReach_mm >= zMin - kTiny;
    };
    const auto tightConcaveFillet = [&](const PathElement &e) { // concave: turning away from the material
        return e.arc && e.radius_mm <= faceReach_mm + kTiny && e.counterClockwise == bore;
    };
    const auto leadsIntoReachableFace = [&](std::size_t j) {
        while (j < chain.size() && tightConcaveFillet(chain[j]))
            ++j;
        return j < chain.size() && reachableFace(chain[j]);
    };
    std::vector<PathElement> out;
    for (std::size_t i = 0; i < chain.size(); ++i) {
        PathElement e = chain[i];
        if (reachableFace(e) || (tightConcaveFillet(e) && leadsIntoReachableFace(i + 1))) {
            out.push_back(e);
            continue;
        }
        if (e.from.z_mm <= zMin + kTiny)
            break;
        // An element that runs into such a face is cut to its corner: the nose, touching both,
        // stays r_e right of the face.
        if (e.to.z_mm < zMin && !leadsIntoReachableFace(i + 1)) {
            e.to = pointAtZ(e, zMin);
            out.push_back(e);
            break;
        }
        out.push_back(e);
    }
    return out;
}

double smallestAxialRadius(const std::vector<PathElement> &chain)
{
    double smallest = std::numeric_limits<double>::infinity();
    for (const PathElement &e : chain)
        if (std::abs(e.from.z_mm - e.to.z_mm) > kTiny) // a face does not count: G96 is clamped there
            smallest = std::min({smallest, e.from.r_mm, e.to.r_mm});
    return std::isfinite(smallest) ? smallest : 0.0;
}

// A tool whose trailing (minor) edge makes kappa' = 180° - kappa_r - epsilon_r with the axis
// (ISO 3002-1, tool cutting edge angle and minor cutting edge angle; the corner angle of the insert
// between them) can follow a contour that falls, in its feed direction, no steeper than kappa':
// with the nose centre phi round a falling corner the edge dips r_e (1 - cos(phi - kappa'))/cos
// kappa' below the surface behind it. A sharp step lower than r_e (1 - cos kappa') turns the nose
// less than kappa' and is cut by its corner (3 µm for r_e 0.8 mm and 5°): not worth a warning.
// The steepest a tool may descend towards the headstock without its trailing edge touching the
// surface behind it: the trailing edge's angle less the free cutting angle of at least 2° that
// Sandvik Coromant asks to keep between workpiece and insert in profiling ("Internal turning",
// profile turning; 7° recommended for finish and tool life).
constexpr double kFreeCuttingAngle_deg = 2.0;

double rideAngle_deg(double trailing_deg)
{
    return std::max(0.0, trailing_deg - kFreeCuttingAngle_deg);
}

// What the trailing edge leaves of a contour a tool follows towards the headstock, each stretch a
// warning (a fall of less than a micrometre, as in a compensated path, is left unsaid).
void warnWhereTheToolRidesOver(const std::vector<RiddenOver> &ridden, double trailing_deg, double noseRadius_mm,
                               QStringList &warnings)
{
    const double cutByTheCorner_mm = noseRadius_mm * (1.0 - std::cos(trailing_deg * std::numbers::pi / 180.0));
    for (const RiddenOver &r : ridden) {
        if (r.deepest_mm <= std::max(cutByTheCorner_mm, 1e-3))
            continue;
        if (std::abs(r.from.z_mm - r.to.z_mm) < 1e-3) { // at the contour's end: nothing to ride down to
            warnings << Toolpaths::tr("%1 falls at %2° in the feed direction, steeper than the insert's trailing edge "
                                      "(%3°) less the 2° of free cutting angle it needs: the finishing pass stops at "
                                      "z = %4 mm and leaves up to %5 mm of %6 uncut. Turn it from the other side or "
                                      "with a neutral tool.")
                            .arg(r.featureIds.constFirst(), QString::number(r.steepest_deg, 'f', 1),
                                 QString::number(trailing_deg, 'f', 1), mm(r.from.z_mm), mm(r.deepest_mm),
                                 r.featureIds.join(QStringLiteral(", ")));
            continue;
        }
        warnings << Toolpaths::tr("%1 falls at %2° in the feed direction, steeper than the insert's trailing edge "
                                  "(%3°) less the 2° of free cutting angle it needs: the finishing pass rides over "
                                  "it at %4° from z = %5 to %6 mm and leaves up to %7 mm of %8 uncut. Turn it from "
                                  "the other side or with a neutral tool.")
                        .arg(r.featureIds.constFirst(), QString::number(r.steepest_deg, 'f', 1),
                             QString::number(trailing_deg, 'f', 1),
                             QString::number(rideAngle_deg(trailing_deg), 'f', 1), mm(r.from.z_mm), mm(r.to.z_mm),
                             mm(r.deepest_mm), r.featureIds.join(QStringLiteral(", ")));
    }
}

std::vector<PathElement> mirrored(std::vector<PathElement> chain)
{
    for (PathElement &e : chain) {
        e.from.r_mm = -e.from.r_mm;
        e.to.r_mm = -e.to.r_mm;
        e.centre.r_mm = -e.centre.r_mm;
        e.counterClockwise = !e.counterClockwise;
    }
    return chain;
}

std::vector<Segment> mirrored(std::vector<Segment> segments)
{
    for (Segment &s : segments) {
        s.from.r_mm = -s.from.r_mm;
        s.to.r_mm = -s.to.r_mm;
        s.arcDirection =
            s.arcDirection == ArcDirection::Clockwise ? ArcDirection::CounterClockwise : ArcDirection::Clockwise;
    }
    return segments;
}

ToolMove mirrored(ToolMove move)
{
    move.to.r_mm = -move.to.r_mm;
    move.centre.r_mm = -move.centre.r_mm;
    if (move.kind == MoveKind::ArcClockwise)
        move.kind = MoveKind::ArcCounterClockwise;
    else if (move.kind == MoveKind::ArcCounterClockwise)
        move.kind = MoveKind::ArcClockwise;
    return move;
}

PassPath contourPass(const std::vector<PathElement> &contour, bool faced, const CuttingPass &conditions,
                     const ToolpathOptions &options, double noseRadius_mm, double safeRadius, double partLength_mm,
                     QStringList &warnings)
{
    PassPath pass;
    pass.conditions = conditions;
    if (contour.empty())
        return pass;
    pass.smallestDiameter_mm = 2.0 * smallestAxialRadius(contour);
    std::vector<PathElement> programmed = contour;
    if (options.nose == NoseHandling::TipPath) {
        QStringList dropped;
        programmed = translated(offsetToTheRight(contour, noseRadius_mm, &dropped), -noseRadius_mm, -noseRadius_mm);
        for (const QString &id : dropped)
            warnings << Toolpaths::tr("%1 is narrower or tighter than the nose radius %2 mm: the nose cannot "
                                      "follow it and leaves it rounded.")
                            .arg(id, mm(noseRadius_mm));
    } else {
        QStringList kept;
        for (const QString &id : sharpenTightConcaveArcs(programmed, noseRadius_mm, kept))
            warnings << Toolpaths::tr("%1 is tighter than the nose radius %2 mm: it is programmed as the sharp "
                                      "corner it rounds (a control's compensation cannot follow a concave arc "
                                      "tighter than the nose), and the nose leaves it rounded to %2 mm.")
                            .arg(id, mm(noseRadius_mm));
        for (const QString &id : kept)
            warnings << Toolpaths::tr("%1 is tighter than the nose radius %2 mm, and its neighbours give no corner "
                                      "to program instead: a control's compensation refuses it. Use an insert "
                                      "with a smaller nose, or --nose tip-path.")
                            .arg(id, mm(noseRadius_mm));
    }
    // The entry move, longer than r_e (a compensation needs that): along -z onto a face that is faced,
    // else along the first element's own line, so that a control's G42 starts with the nose square to
    // it and the element is turned from its first point.
    const double entryLength = options.clearance_mm + 2.0 * noseRadius_mm;
    const double zApproach = partLength_mm + entryLength;
    const ProfilePoint start = programmed.front().from;
    ProfilePoint entryFrom{zApproach, start.r_mm};
    if (options.nose == NoseHandling::ControlCompensation && !faced) {
        const ProfilePoint t = startTangent(programmed.front());
        entryFrom = {start.z_mm - entryLength * t.z_mm, start.r_mm - entryLength * t.r_mm};
    }
    pass.moves.push_back(move(MoveKind::Rapid, {entryFrom.z_mm, safeRadius}));
    pass.moves.push_back(move(MoveKind::Rapid, entryFrom));
    ToolMove entry = move(MoveKind::Feed, start);
    entry.startsNoseCompensation = options.nose == NoseHandling::ControlCompensation;
    pass.moves.push_back(entry);
    for (const PathElement &e : programmed)
        pass.moves.push_back(moveAlong(e));
    ToolMove exit = move(MoveKind::Feed, {programmed.back().to.z_mm, safeRadius});
    exit.endsNoseCompensation = options.nose == NoseHandling::ControlCompensation;
    pass.moves.push_back(exit);
    pass.moves.push_back(move(MoveKind::Rapid, {std::max(zApproach, entryFrom.z_mm), safeRadius}));
    return pass;
}

double roughLevels(std::vector<PassPath> &passes, const std::vector<CuttingPass> &roughing, const Envelope &env,
                   double stockLevel, double safeRadius, double noseRadius_mm, double clearance_mm)
{
    double levelAbove = stockLevel;
    for (const CuttingPass &conditions : roughing) {
        PassPath pass;
        pass.conditions = conditions;
        const double level = levelAbove - conditions.depthOfCut_mm;
        roughLevel(pass, env, level, levelAbove, safeRadius, noseRadius_mm, clearance_mm);
        pass.smallestDiameter_mm = 2.0 * (level - noseRadius_mm);
        passes.push_back(std::move(pass));
        levelAbove = level;
    }
    return levelAbove;
}

double stockLeftAboveAllowance(const Envelope &env, double lastLevel, double partLength_mm)
{
    double left = 0.0;
    for (std::size_t i = 0; i < env.r_mm.size(); ++i)
        if (env.z(i) <= partLength_mm && std::isfinite(env.r_mm[i]) && env.r_mm[i] < lastLevel)
            left = std::max(left, lastLevel - env.r_mm[i]);
    return left;
}

} // namespace toolpath_detail

namespace {

using namespace toolpath_detail;

// The left end of the region the tool may cut: the chuck face or the left centre, plus the
// clearance the nose keeps from the jaws or the driver.
double leftSupport_mm(const Project &project)
{
    return project.clamping.method == ClampingMethod::BetweenCentres ? 0.0 : project.clamping.clampedLength_mm;
}

// In one operation of several (docs/operations.md): the left end of the run of features this
// operation turns from the free end; what lies left of it another operation turns (or turned).
std::optional<double> operationBoundary_mm(const Project &project)
{
    if (!project.scope)
        return std::nullopt;
    const std::vector<Segment> &segments = project.part.outer.segments;
    for (std::size_t i = segments.size(); i-- > 0;) { // clang 14 cannot use views::reverse
        if (!project.scope->cutFeatures.contains(segments[i].id))
            return std::max(segments[i].from.z_mm, segments[i].to.z_mm);
    }
    return std::nullopt;
}

// The leftmost z of the nose centre: clear of the jaws (or the driver) by the clearance, and not
// left of the operation's boundary, where the nose reaches the corner of the last face it turns.
double toolStop_mm(const Project &project, const ToolpathOptions &options, double noseRadius_mm)
{
    const double jaws = leftSupport_mm(project) + options.clearance_mm + noseRadius_mm;
    const auto boundary = operationBoundary_mm(project);
    return boundary ? std::max(jaws, *boundary + noseRadius_mm) : jaws;
}

// What holds the left end, as the program's notes name it.
QString supportName(ClampingMethod method)
{
    switch (method) {
    case ClampingMethod::BetweenCentres:
        return Toolpaths::tr("left centre and driver");
    case ClampingMethod::Collet:
        return Toolpaths::tr("collet");
    case ClampingMethod::Chuck:
    case ClampingMethod::ChuckTailstock:
        break;
    }
    return Toolpaths::tr("chuck jaws");
}

bool rightEndOnCentre(const Project &project)
{
    return !holdsOneEndOnly(project.clamping.method);
}

// The chain up to an operation's boundary at z = zb: a face at zb that this operation cuts is the
// last element (the shoulder it faces down to the surface another one turns), a surface crossing
// zb ends there.
std::vector<PathElement> clippedAtBoundary(const std::vector<PathElement> &chain, double zb,
                                           const QStringList &cutFeatures)
{
    constexpr double kOnBoundary_mm = 1e-6;
    std::vector<PathElement> out;
    for (PathElement e : chain) {
        const bool face = std::abs(e.from.z_mm - zb) < kOnBoundary_mm && std::abs(e.to.z_mm - zb) < kOnBoundary_mm;
        if (face) {
            if (cutFeatures.contains(e.featureId))
                out.push_back(e);
            break;
        }
        if (e.from.z_mm <= zb + kOnBoundary_mm)
            break;
        if (e.to.z_mm < zb) {
            e.to = pointAtZ(e, zb);
            out.push_back(e);
            break;
        }
        out.push_back(e);
    }
    return out;
}

// Whether the finishing contour reaches the left end of segment `s`: clippedAtLeft keeps a face the
// nose reaches, and a tight fillet in front of it, though they lie left of the nose centre's stop.
bool turnedToItsLeftEnd(const std::vector<PathElement> &contour, const Segment &s)
{
    // More than a compensation moves a face (micrometres), less than a stop that leaves stock.
    constexpr double kOnLeftEnd_mm = 0.01;
    const double left = std::min(s.from.z_mm, s.to.z_mm);
    return std::any_of(contour.begin(), contour.end(), [&s, left](const PathElement &e) {
        return e.featureId == s.id && std::min(e.from.z_mm, e.to.z_mm) <= left + kOnLeftEnd_mm;
    });
}

// Features outside the jaws (or the driver) that reach closer to them than the tool goes.
void warnWhereTheJawsKeepTheToolOff(const Project &project, const std::vector<PathElement> &finishingContour,
                                    double zReached_mm, double clearance_mm, QStringList &warnings)
{
    const double support = leftSupport_mm(project);
    QStringList features;
    for (const Segment &s : project.part.outer.segments) {
        if (project.scope && !project.scope->cutFeatures.contains(s.id))
            continue; // another operation turns it
        if (turnedToItsLeftEnd(finishingContour, s))
            continue;
        const double zMin = std::min(s.from.z_mm, s.to.z_mm);
        const double zMax = std::max(s.from.z_mm, s.to.z_mm);
        if (zMax > support + kTiny && zMin < zReached_mm - 1e-6)
            features << s.id;
    }
    if (features.isEmpty())
        return;
    const bool centres = project.clamping.method == ClampingMethod::BetweenCentres;
    const QString where = centres ? Toolpaths::tr("left centre") : Toolpaths::tr("chuck face");
    const QString text =
        features.size() == 1
            ? Toolpaths::tr("%1 reaches within %2 mm of the %3, where the tool does not go (it keeps %4 mm from it): "
                            "it is not turned there.")
            : Toolpaths::tr("%1 reach within %2 mm of the %3, where the tool does not go (it keeps %4 mm from it): "
                            "they are not turned there.");
    const QString advice = centres ? Toolpaths::tr("Turn that end with the part turned end for end.")
                                   : Toolpaths::tr("Grip the part shorter, or turn that end in another set-up.");
    warnings << text.arg(features.join(QStringLiteral(", ")), mm(zReached_mm - support), where, mm(clearance_mm)) +
                    QLatin1Char(' ') + advice;
}

// An undercut's recess lies behind its shoulder: the program bridges it (withoutUndercuts), and
// an undercut or grooving insert cuts it; one without a face beside it is followed as drawn, but
// a turning insert's body would cut what overhangs it (its outline is not modelled).
void warnAtUndercuts(const Project &project, QStringList &warnings)
{
    QStringList bridged;
    const Contour outline = withoutUndercuts(project.part.outer, &bridged);
    QStringList followed;
    for (const Segment &s : outline.segments) {
        if (s.turnsBack())
            followed << s.id;
    }
    const auto cutHere = [&](QStringList ids) {
        ids.removeIf([&](const QString &id) { return project.scope && !project.scope->cutFeatures.contains(id); });
        return ids;
    };
    bridged = cutHere(bridged);
    followed = cutHere(followed);
    if (!bridged.isEmpty())
        warnings << Toolpaths::tr("%1: the recess of an undercut under its shoulder is not in this program (it "
                                  "turns the face down to the recess and the floor up to it): cut the recess with "
                                  "an undercut or grooving insert in a program of its own.")
                        .arg(bridged.join(QStringLiteral(", ")));
    if (!followed.isEmpty())
        warnings << Toolpaths::tr("%1: goes back along z (an undercut) without a face and a floor beside it: the "
                                  "program follows it, but only an insert that fits under the overhang can cut it; "
                                  "the insert's outline is not checked.")
                        .arg(followed.join(QStringLiteral(", ")));
}

struct FinishingGeometry {
    std::vector<PathElement> contour; // what is programmed (control) or offset (tip path)
    bool faced = false;
    std::vector<RiddenOver> riddenOver; // where the trailing edge keeps the tool off the contour
};

FinishingGeometry finishingGeometry(const Project &project, const ToolpathOptions &options, double noseRadius_mm,
                                    std::optional<double> trailing_deg)
{
    FinishingGeometry g;
    std::vector<PathElement> chain = compensatedChain(targetContour(project, ContourSide::Outer), options.compensation);
    const double length = project.part.length_mm();
    // The right end face: the leading elements at z = length that run up from the axis or the bore.
    std::size_t face = 0;
    while (face < chain.size() && std::abs(chain[face].from.z_mm - length) < kTiny &&
           std::abs(chain[face].to.z_mm - length) < kTiny)
        ++face;
    if (face > 0 && rightEndOnCentre(project)) {
        chain.erase(chain.begin(), chain.begin() + static_cast<std::ptrdiff_t>(face));
    } else if (face > 0) {
        g.faced = true;
        // Programmed past the axis or the bore edge by r_e, so that the nose centre reaches it and
        // no pip is left (with the control's compensation the nose centre follows the line r_e off
        // the programmed face, from the programmed start).
        if (options.nose == NoseHandling::ControlCompensation)
            chain.front().from.r_mm -= noseRadius_mm;
    }
    const double jaws = leftSupport_mm(project) + options.clearance_mm + noseRadius_mm;
    const auto boundary = operationBoundary_mm(project);
    g.contour = boundary && *boundary > jaws ? clippedAtBoundary(chain, *boundary, project.scope->cutFeatures)
                                             : clippedAtLeft(chain, jaws, noseRadius_mm, false);
    if (trailing_deg)
        g.contour = riddenOverSteepFalls(g.contour, rideAngle_deg(*trailing_deg), &g.riddenOver);
    return g;
}

PassPath finishingPass(const Project &project, const CuttingPass &conditions, const ToolpathOptions &options,
                       double noseRadius_mm, std::optional<double> trailing_deg, double safeRadius, Toolpath &path)
{
    const FinishingGeometry g = finishingGeometry(project, options, noseRadius_mm, trailing_deg);
    path.endFaceFaced = g.faced;
    return contourPass(g.contour, g.faced, conditions, options, noseRadius_mm, safeRadius, project.part.length_mm(),
                       path.warnings);
}

std::vector<PassPath> roughingPasses(const Project &project, const std::vector<CuttingPass> &roughing,
                                     double allowance_mm, double noseRadius_mm, std::optional<double> trailing_deg,
                                     double safeRadius, const ToolpathOptions &options, QStringList &warnings)
{
    const double length = project.part.length_mm();
    const double zLeft = toolStop_mm(project, options, noseRadius_mm); // nose centre
    const double zRight = length + options.clearance_mm + noseRadius_mm;
    const Contour target = targetContour(project, ContourSide::Outer);
    Envelope env = widenedEnvelope(target.segments, allowance_mm + noseRadius_mm, zLeft, zRight, kEnvelopeStep_mm);
    if (trailing_deg)
        rideOverSteepFalls(env, rideAngle_deg(*trailing_deg));
    const double stockRadius = 0.5 * project.part.stockDiameter_mm;
    std::vector<PassPath> passes;
    const double lastLevel = roughLevels(passes, roughing, env, stockRadius + noseRadius_mm, safeRadius, noseRadius_mm,
                                         options.clearance_mm);
    const double left = stockLeftAboveAllowance(env, lastLevel, length);
    if (left > std::max(0.01, 0.1 * allowance_mm)) // within 10 % of the allowance the finishing pass takes it
        warnings << Toolpaths::tr("The planned roughing leaves up to %1 mm more than the finishing allowance of "
                                  "%2 mm: the finishing pass would cut it.")
                        .arg(mm(left), mm(allowance_mm));
    return passes;
}

} // namespace

Toolpath turningToolpath(const Project &project, const CuttingPass &finishing, const std::vector<CuttingPass> &roughing,
                         double noseRadius_mm, std::optional<double> trailingEdgeAngle_deg,
                         const ToolpathOptions &options)
{
    Toolpath path;
    path.nose = options.nose;
    path.noseRadius_mm = noseRadius_mm;
    path.safeDiameter_mm = project.part.stockDiameter_mm + 2.0 * options.clearance_mm;
    const double safeRadius = 0.5 * path.safeDiameter_mm;
    path.roughing = roughingPasses(project, roughing, finishing.depthOfCut_mm, noseRadius_mm, trailingEdgeAngle_deg,
                                   safeRadius, options, path.warnings);
    path.finishing = finishingPass(project, finishing, options, noseRadius_mm, trailingEdgeAngle_deg, safeRadius, path);
    int number = 1;
    for (PassPath &p : path.roughing)
        p.number = number++;
    path.finishing.number = number;
    const FinishingGeometry g = finishingGeometry(project, options, noseRadius_mm, trailingEdgeAngle_deg);
    if (trailingEdgeAngle_deg)
        warnWhereTheToolRidesOver(g.riddenOver, *trailingEdgeAngle_deg, noseRadius_mm, path.warnings);
    else
        path.warnings << Toolpaths::tr("The trailing edge angle of the tool is not known (holder entering angle and "
                                       "insert shape): falling contours are not checked.");
    warnWhereTheJawsKeepTheToolOff(project, g.contour, leftSupport_mm(project) + options.clearance_mm + noseRadius_mm,
                                   options.clearance_mm, path.warnings);
    warnAtUndercuts(project, path.warnings);
    if (const auto boundary = operationBoundary_mm(project))
        path.notes << Toolpaths::tr("%1 turns from the free end to z = %2 mm (from the held end); the rest of the "
                                    "outer contour is another operation's.")
                          .arg(project.scope->name, mm(*boundary));
    if (rightEndOnCentre(project))
        path.notes << Toolpaths::tr("The right end face is held by a centre and is not faced: it is faced and "
                                    "centred before the part is set up.");
    path.notes << Toolpaths::tr("The tool stops %1 mm short of the %2; the stock there is not turned.")
                      .arg(mm(options.clearance_mm), supportName(project.clamping.method));
    const bool turnsOuterFeatures = std::any_of(
        project.part.outer.segments.begin(), project.part.outer.segments.end(),
        [&project](const Segment &seg) { return !project.scope || project.scope->cutFeatures.contains(seg.id); });
    if (path.finishing.moves.empty() && turnsOuterFeatures) // a set-up that only bores turns nothing outside
        path.warnings << Toolpaths::tr("The finishing pass cuts nothing: every outer feature of this set-up lies "
                                       "within the tool's stop of the %1. Grip the part shorter.")
                             .arg(supportName(project.clamping.method));
    const double radialStock = 0.5 * project.part.stockDiameter_mm -
                               0.5 * std::max(path.finishing.smallestDiameter_mm, 0.0) - finishing.depthOfCut_mm;
    const double turned = path.finishing.smallestDiameter_mm; // none where the pass only faces
    if (roughing.empty() && std::isfinite(turned) && turned > 0.0 && radialStock > 1e-3)
        path.warnings << Toolpaths::tr("No roughing pass is planned: the finishing pass would cut up to %1 mm more "
                                       "than its depth of cut.")
                             .arg(mm(radialStock));
    return path;
}

} // namespace tolturn