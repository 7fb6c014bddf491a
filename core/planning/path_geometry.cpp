// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/path_geometry.h"

#include "core/part/profile_geometry.h"

#include <QStringList>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace tolturn {

namespace {

constexpr double kTiny = 1e-9;

ProfilePoint operator+(ProfilePoint a, ProfilePoint b)
{
    return {a.z_mm + b.z_mm, a.r_mm + b.r_mm};
}

ProfilePoint operator-(ProfilePoint a, ProfilePoint b)
{
    return {a.z_mm - b.z_mm, a.r_mm - b.r_mm};
}

ProfilePoint operator*(double k, ProfilePoint a)
{
    return {k * a.z_mm, k * a.r_mm};
}

double dot(ProfilePoint a, ProfilePoint b)
{
    return a.z_mm * b.z_mm + a.r_mm * b.r_mm;
}

double cross(ProfilePoint a, ProfilePoint b)
{
    return a.z_mm * b.r_mm - a.r_mm * b.z_mm;
}

double norm(ProfilePoint a)
{
    return std::hypot(a.z_mm, a.r_mm);
}

ProfilePoint unit(ProfilePoint a)
{
    const double n = norm(a);
    return n > kTiny ? (1.0 / n) * a : ProfilePoint{};
}

ProfilePoint rightNormal(ProfilePoint direction)
{
    return {direction.r_mm, -direction.z_mm};
}

ProfilePoint tangentAt(const PathElement &e, ProfilePoint p)
{
    if (!e.arc)
        return unit(e.to - e.from);
    const ProfilePoint radial = unit(p - e.centre);
    const ProfilePoint ccw{-radial.r_mm, radial.z_mm};
    return e.counterClockwise ? ccw : -1.0 * ccw;
}

PathElement offsetElement(const PathElement &e, double d)
{
    PathElement o = e;
    if (!e.arc) {
        const ProfilePoint n = d * rightNormal(unit(e.to - e.from));
        o.from = e.from + n;
        o.to = e.to + n;
        return o;
    }
    o.radius_mm = e.radius_mm + (e.counterClockwise ? d : -d); // the right side is outside a CCW arc
    const double k = o.radius_mm / e.radius_mm;
    o.from = e.centre + k * (e.from - e.centre);
    o.to = e.centre + k * (e.to - e.centre);
    return o;
}

// Intersections of the lines/circles carrying two elements.
std::vector<ProfilePoint> intersections(const PathElement &a, const PathElement &b)
{
    auto lineCircle = [](const PathElement &line, const PathElement &circle) {
        const ProfilePoint d = unit(line.to - line.from);
        const ProfilePoint f = line.from - circle.centre;
        const double bq = dot(f, d);
        const double cq = dot(f, f) - circle.radius_mm * circle.radius_mm;
        const double disc = bq * bq - cq;
        std::vector<ProfilePoint> out;
        if (disc < -kTiny)
            return out;
        const double s = std::sqrt(std::max(disc, 0.0));
        out.push_back(line.from + (-bq - s) * d);
        out.push_back(line.from + (-bq + s) * d);
        return out;
    };
    if (!a.arc && !b.arc) {
        const ProfilePoint da = a.to - a.from;
        const ProfilePoint db = b.to - b.from;
        const double den = cross(da, db);
        if (std::abs(den) < kTiny)
            return {};
        const double t = cross(b.from - a.from, db) / den;
        return {a.from + t * da};
    }
    if (!a.arc)
        return lineCircle(a, b);
    if (!b.arc)
        return lineCircle(b, a);
    const ProfilePoint d = b.centre - a.centre;
    const double dist = norm(d);
    if (dist < kTiny || dist > a.radius_mm + b.radius_mm + kTiny || dist < std::abs(a.radius_mm - b.radius_mm) - kTiny)
        return {};
    const double x = (dist * dist + a.radius_mm * a.radius_mm - b.radius_mm * b.radius_mm) / (2.0 * dist);
    const double h = std::sqrt(std::max(a.radius_mm * a.radius_mm - x * x, 0.0));
    const ProfilePoint u = unit(d);
    const ProfilePoint base = a.centre + x * u;
    const ProfilePoint perp{-u.r_mm, u.z_mm};
    return {base + h * perp, base - h * perp};
}

std::optional<ProfilePoint> nearestIntersection(const PathElement &a, const PathElement &b, ProfilePoint near)
{
    std::optional<ProfilePoint> best;
    for (const ProfilePoint &p : intersections(a, b))
        if (!best || norm(p - near) < norm(*best - near))
            best = p;
    return best;
}

// The angle of a point about an arc's centre.
double angleAbout(const PathElement &arc, ProfilePoint p)
{
    return std::atan2(p.r_mm - arc.centre.r_mm, p.z_mm - arc.centre.z_mm);
}

// The angle swept from `from` to `to` [rad] turning the arc's way: positive counter-clockwise,
// negative clockwise.
double sweptAngle(const PathElement &arc, double from, double to)
{
    double w = to - from;
    const double turn = 2.0 * std::numbers::pi;
    if (arc.counterClockwise)
        while (w < 0.0)
            w += turn;
    else
        while (w > 0.0)
            w -= turn;
    return w;
}

// Whether an offset element, trimmed to new ends, still runs the way its original did.
bool keepsItsSense(const PathElement &original, const PathElement &offset)
{
    if (!offset.arc)
        return dot(offset.to - offset.from, original.to - original.from) > kTiny;
    if (offset.radius_mm <= kTiny)
        return false;
    const double originalSweep =
        sweptAngle(original, angleAbout(original, original.from), angleAbout(original, original.to));
    const double offsetSweep = sweptAngle(original, angleAbout(offset, offset.from), angleAbout(offset, offset.to));
    return std::abs(offsetSweep) <= std::abs(originalSweep) + 1e-6 && std::abs(offsetSweep) > 1e-9;
}

// The angle below the feed direction (-z) at which a travel direction falls: 0 along -z, 90°
// straight down, above 90° down and back; not positive where it does not fall.
double fallAngle_deg(ProfilePoint direction)
{
    if (direction.r_mm >= -kTiny)
        return 0.0;
    return std::atan2(-direction.r_mm, -direction.z_mm) * 180.0 / std::numbers::pi;
}

// Whether a point on the circle carrying an arc lies on the arc (between its ends, its way).
bool onArc(const PathElement &e, ProfilePoint p)
{
    const double start = angleAbout(e, e.from);
    return std::abs(sweptAngle(e, start, angleAbout(e, p))) <=
           std::abs(sweptAngle(e, start, angleAbout(e, e.to))) + 1e-9;
}

bool onElement(const PathElement &e, ProfilePoint p)
{
    if (e.arc)
        return std::abs(norm(p - e.centre) - e.radius_mm) < 1e-6 && onArc(e, p);
    const ProfilePoint d = e.to - e.from;
    const double t = dot(p - e.from, d) / dot(d, d);
    return t >= -1e-9 && t <= 1.0 + 1e-9 && std::abs(cross(p - e.from, unit(d))) < 1e-6;
}

// Where an element starts to fall steeper than `trailing_deg`: its start, or for an arc that
// steepens along its way, the point where its tangent passes that angle.
std::optional<ProfilePoint> steepFrom(const PathElement &e, double trailing_deg)
{
    if (fallAngle_deg(startTangent(e)) > trailing_deg + 1e-6)
        return e.from;
    if (!e.arc || fallAngle_deg(endTangent(e)) <= trailing_deg + 1e-6)
        return std::nullopt;
    // The tangent (-cos t, -sin t): at 90° + t about the centre counter-clockwise, t - 90° clockwise.
    const double t = trailing_deg * std::numbers::pi / 180.0;
    const double psi = e.counterClockwise ? 0.5 * std::numbers::pi + t : t - 0.5 * std::numbers::pi;
    const ProfilePoint p = e.centre + e.radius_mm * ProfilePoint{std::cos(psi), std::sin(psi)};
    return onElement(e, p) ? p : e.from;
}

// The first point after `from` where the ray from it along `d` meets the chain from element
// `first` on: its element and the point.
std::optional<std::pair<std::size_t, ProfilePoint>> firstHit(const std::vector<PathElement> &chain, std::size_t first,
                                                             ProfilePoint from, ProfilePoint d)
{
    PathElement ray;
    ray.from = from;
    ray.to = from + d;
    for (std::size_t j = first; j < chain.size(); ++j) {
        std::optional<ProfilePoint> best;
        double bestS = std::numeric_limits<double>::infinity();
        for (const ProfilePoint &q : intersections(ray, chain[j])) {
            const double s = dot(q - from, d);
            if (s > 1e-6 && s < bestS && onElement(chain[j], q)) {
                bestS = s;
                best = q;
            }
        }
        if (best)
            return std::make_pair(j, *best);
    }
    return std::nullopt;
}

} // namespace

std::vector<PathElement> reversedElements(const std::vector<Segment> &segments)
{
    std::vector<PathElement> out;
    out.reserve(segments.size());
    for (std::size_t i = segments.size(); i-- > 0;) { // clang 14 cannot use views::reverse
        const Segment *it = &segments[i];
        PathElement e;
        e.from = it->to;
        e.to = it->from;
        e.featureId = it->id;
        if (it->kind == SegmentKind::Radius) {
            if (const auto arc = arcGeometry(*it)) {
                e.arc = true;
                e.centre = arc->centre;
                e.radius_mm = arc->radius_mm;
                e.counterClockwise = it->arcDirection == ArcDirection::Clockwise; // travelled backwards
            }
        }
        if (norm(e.to - e.from) > kTiny)
            out.push_back(e);
    }
    return out;
}

ProfilePoint startTangent(const PathElement &e)
{
    return tangentAt(e, e.from);
}

ProfilePoint endTangent(const PathElement &e)
{
    return tangentAt(e, e.to);
}

std::vector<PathElement> offsetToTheRight(const std::vector<PathElement> &chain, double distance_mm,
                                          QStringList *dropped)
{
    std::vector<PathElement> source;
    for (const PathElement &e : chain) {
        if (e.arc && !e.counterClockwise && e.radius_mm <= distance_mm + kTiny) {
            if (dropped)
                *dropped << e.featureId; // a concave arc tighter than the offset: a corner for it
            PathElement corner;
            corner.from = e.from;
            corner.to = e.to;
            corner.featureId = e.featureId;
            source.push_back(corner);
            continue;
        }
        source.push_back(e);
    }
    std::vector<PathElement> out;
    for (std::size_t i = 0; i < source.size(); ++i) {
        PathElement next = offsetElement(source[i], distance_mm);
        if (out.empty()) {
            out.push_back(next);
            continue;
        }
        const PathElement &previous = source[i - 1];
        const ProfilePoint t1 = endTangent(previous);
        const ProfilePoint t2 = startTangent(source[i]);
        const double turn = cross(t1, t2);
        const ProfilePoint corner = source[i].from;
        const bool tangent = std::abs(turn) < 1e-9 && dot(t1, t2) > 0.0;
        const std::optional<ProfilePoint> meet =
            !tangent && turn < 0.0 ? nearestIntersection(out.back(), next, corner) : std::nullopt;
        if (!tangent && turn > 0.0) {
            PathElement round; // convex: roll round the corner
            round.from = out.back().to;
            round.to = next.from;
            round.arc = true;
            round.centre = corner;
            round.radius_mm = distance_mm;
            round.counterClockwise = true;
            round.featureId = source[i].featureId;
            out.push_back(round);
        } else if (meet) { // concave: trim both at their intersection
            const PathElement before = out.back();
            out.back().to = *meet;
            next.from = *meet;
            if (!keepsItsSense(before, out.back())) {
                if (dropped)
                    *dropped << out.back().featureId;
                out.pop_back();
                if (!out.empty()) { // re-join the one before with this one
                    if (const auto q = nearestIntersection(out.back(), next, *meet)) {
                        out.back().to = *q;
                        next.from = *q;
                    }
                }
            }
        } else {
            next.from = out.back().to; // tangent, or the parallel offsets of a reversal: they meet
        }
        out.push_back(next);
    }
    return out;
}

double distanceTo(const PathElement &e, ProfilePoint p)
{
    const double toEnds = std::min(norm(p - e.from), norm(p - e.to));
    if (e.arc) {
        const double fromCentre = norm(p - e.centre);
        if (fromCentre > kTiny && onArc(e, e.centre + (e.radius_mm / fromCentre) * (p - e.centre)))
            return std::abs(fromCentre - e.radius_mm);
        return toEnds;
    }
    const ProfilePoint d = e.to - e.from;
    const double length2 = dot(d, d);
    if (length2 < kTiny * kTiny)
        return toEnds;
    const double t = std::clamp(dot(p - e.from, d) / length2, 0.0, 1.0);
    return norm(p - (e.from + t * d));
}

namespace {

// What a ride from `ridden.from` to `ridden.to` passes over, elements `first` to `last` of the
// chain: the steepest fall, the features below the line (the last only where the line meets it
// past its start) and the most it leaves, an arc's lowest point too.
void describeRide(RiddenOver &ridden, const std::vector<PathElement> &rest, std::size_t first, std::size_t last,
                  bool lastMetPastItsStart, double slope)
{
    for (std::size_t j = first; j <= last; ++j) {
        ridden.steepest_deg =
            std::max({ridden.steepest_deg, fallAngle_deg(startTangent(rest[j])), fallAngle_deg(endTangent(rest[j]))});
        const bool under = j < last || lastMetPastItsStart;
        if (under && !ridden.featureIds.contains(rest[j].featureId))
            ridden.featureIds << rest[j].featureId;
        for (const ProfilePoint q : sampled(rest[j], 0.05, 2000)) {
            if (q.z_mm < ridden.to.z_mm - 1e-6 || q.z_mm > ridden.from.z_mm + 1e-6)
                continue;
            const double line = ridden.from.r_mm - (ridden.from.z_mm - q.z_mm) * slope;
            ridden.deepest_mm = std::max(ridden.deepest_mm, line - q.r_mm);
        }
    }
}

} // namespace

std::vector<PathElement> riddenOverSteepFalls(const std::vector<PathElement> &chain, double trailing_deg,
                                              std::vector<RiddenOver> *riddenOver)
{
    const double t = trailing_deg * std::numbers::pi / 180.0;
    const ProfilePoint down{-std::cos(t), -std::sin(t)}; // the steepest way down the tool may take
    std::vector<PathElement> rest = chain;
    std::vector<PathElement> out;
    std::size_t i = 0;
    std::size_t rides = 0; // bounded: each ride moves on along the chain
    while (i < rest.size()) {
        const PathElement &e = rest[i];
        const std::optional<ProfilePoint> p = steepFrom(e, trailing_deg);
        if (!p) {
            out.push_back(e);
            ++i;
            continue;
        }
        if (norm(*p - e.from) > 1e-6) { // an arc steepening on its way: followed up to there
            PathElement head = e;
            head.to = *p;
            out.push_back(head);
        }
        const auto hit = ++rides <= 4 * chain.size() ? firstHit(rest, i, *p, down) : std::nullopt;
        RiddenOver ridden;
        ridden.from = *p;
        ridden.to = hit ? hit->second : *p + (std::max(0.0, p->z_mm - rest.back().to.z_mm) / std::cos(t)) * down;
        const std::size_t last = hit ? hit->first : rest.size() - 1;
        describeRide(ridden, rest, i, last, !hit || norm(hit->second - rest[last].from) > 1e-6, std::tan(t));
        PathElement line;
        line.from = *p;
        line.to = ridden.to;
        line.featureId = e.featureId;
        if (norm(line.to - line.from) > 1e-6)
            out.push_back(line);
        if (riddenOver)
            riddenOver->push_back(ridden);
        if (!hit)
            break;
        rest[last].from = hit->second; // the chain goes on from where the line meets it
        i = norm(rest[last].to - rest[last].from) < 1e-6 ? last + 1 : last;
    }
    return out;
}

void rideOverSteepFalls(Envelope &env, double trailing_deg)
{
    const double drop = std::tan(trailing_deg * std::numbers::pi / 180.0) * env.step_mm;
    for (std::size_t i = env.r_mm.size(); i-- > 1;)
        env.r_mm[i - 1] = std::max(env.r_mm[i - 1], env.r_mm[i] - drop);
}

std::vector<PathElement> translated(std::vector<PathElement> chain, double dz_mm, double dr_mm)
{
    const ProfilePoint d{dz_mm, dr_mm};
    for (PathElement &e : chain) {
        e.from = e.from + d;
        e.to = e.to + d;
        e.centre = e.centre + d;
    }
    return chain;
}

namespace {

// The number of steps of `length` at `step`, at least 1 and at most `most` (a path kilometres long,
// from a deviation that is not physical, must not take the machine's memory; nor overflow an int).
int stepsAlong(double length_mm, double step_mm, int most)
{
    const double steps = std::ceil(length_mm / step_mm);
    return std::isfinite(steps) ? std::clamp(static_cast<int>(std::min(steps, double(most))), 1, most) : most;
}

} // namespace

std::vector<ProfilePoint> sampled(const PathElement &e, double step_mm, int mostSteps)
{
    std::vector<ProfilePoint> out;
    if (!e.arc) {
        const int n = stepsAlong(norm(e.to - e.from), step_mm, mostSteps);
        for (int i = 0; i <= n; ++i)
            out.push_back(e.from + (static_cast<double>(i) / n) * (e.to - e.from));
        return out;
    }
    const double a0 = std::atan2(e.from.r_mm - e.centre.r_mm, e.from.z_mm - e.centre.z_mm);
    double a1 = std::atan2(e.to.r_mm - e.centre.r_mm, e.to.z_mm - e.centre.z_mm);
    const double turn = 2.0 * std::numbers::pi;
    if (e.counterClockwise)
        while (a1 < a0)
            a1 += turn;
    else
        while (a1 > a0)
            a1 -= turn;
    const int n = stepsAlong(std::abs(a1 - a0) * e.radius_mm, step_mm, mostSteps);
    for (int i = 0; i <= n; ++i) {
        const double a = a0 + (a1 - a0) * static_cast<double>(i) / n;
        out.push_back({e.centre.z_mm + e.radius_mm * std::cos(a), e.centre.r_mm + e.radius_mm * std::sin(a)});
    }
    out.back() = e.to;
    return out;
}

namespace {

// The envelope raised to r(z) at every grid z within [zLow, zHigh].
template <class Height>
void raise(Envelope &env, double zLow_mm, double zHigh_mm, const Height &r)
{
    const double lo = std::max(0.0, std::ceil((zLow_mm - env.z0_mm) / env.step_mm));
    const double hi = std::floor((zHigh_mm - env.z0_mm) / env.step_mm);
    if (!(lo < static_cast<double>(env.r_mm.size()))) // beyond the grid (or not a number)
        return;
    for (auto i = static_cast<std::size_t>(lo); static_cast<double>(i) <= hi && i < env.r_mm.size(); ++i)
        env.r_mm[i] = std::max(env.r_mm[i], r(env.z(i)));
}

// The envelope raised to the top of a disc of radius d about p.
void raiseToDisc(Envelope &env, const ProfilePoint &p, double d)
{
    raise(env, p.z_mm - d, p.z_mm + d, [&](double z) {
        const double dz = z - p.z_mm;
        return p.r_mm + std::sqrt(std::max(d * d - dz * dz, 0.0));
    });
}

// The envelope raised to a line element moved by d along its upward normal. A disc swept along a
// line is the two end discs and the band between the line moved by d to either side (the
// Minkowski sum of a segment and a disc), so with raiseToDisc at both ends this is exact.
void raiseToMovedLine(Envelope &env, const PathElement &e, double d)
{
    const ProfilePoint t = e.to - e.from;
    const double length = norm(t);
    if (length <= kTiny)
        return;
    ProfilePoint n{-t.r_mm / length, t.z_mm / length};
    if (n.r_mm < 0.0)
        n = ProfilePoint{-n.z_mm, -n.r_mm};
    const ProfilePoint a = e.from + d * n;
    const ProfilePoint b = e.to + d * n;
    if (std::abs(b.z_mm - a.z_mm) <= kTiny)
        return; // a face: its end discs bound it from above
    raise(env, std::min(a.z_mm, b.z_mm), std::max(a.z_mm, b.z_mm),
          [&](double z) { return a.r_mm + (z - a.z_mm) / (b.z_mm - a.z_mm) * (b.r_mm - a.r_mm); });
}

} // namespace

Envelope widenedEnvelope(const std::vector<Segment> &contour, double distance_mm, double zFrom_mm, double zTo_mm,
                         double step_mm)
{
    Envelope env;
    env.z0_mm = zFrom_mm;
    const auto count = static_cast<std::size_t>(std::max(1.0, std::ceil((zTo_mm - zFrom_mm) / step_mm))) + 1;
    env.step_mm = (zTo_mm - zFrom_mm) / static_cast<double>(count - 1); // the grid ends on zTo exactly
    env.r_mm.assign(count, -std::numeric_limits<double>::infinity());
    for (const PathElement &e : reversedElements(contour)) {
        if (e.arc) { // an arc by discs about points along it, half a grid step apart
            for (const ProfilePoint &p : sampled(e, 0.5 * env.step_mm))
                raiseToDisc(env, p, distance_mm);
            continue;
        }
        raiseToDisc(env, e.from, distance_mm);
        raiseToDisc(env, e.to, distance_mm);
        raiseToMovedLine(env, e, distance_mm);
    }
    return env;
}

std::vector<ProfilePoint> simplified(const std::vector<ProfilePoint> &points, double tolerance_mm)
{
    if (points.size() < 3)
        return points;
    std::vector<bool> keep(points.size(), false);
    keep.front() = keep.back() = true;
    std::vector<std::pair<std::size_t, std::size_t>> stack{{0, points.size() - 1}};
    while (!stack.empty()) {
        const auto [first, last] = stack.back();
        stack.pop_back();
        const ProfilePoint chord = points[last] - points[first];
        const double length = norm(chord);
        double worst = 0.0;
        std::size_t at = first;
        for (std::size_t i = first + 1; i < last; ++i) {
            const ProfilePoint v = points[i] - points[first];
            const double d = length > kTiny ? std::abs(cross(chord, v)) / length : norm(v);
            if (d > worst) {
                worst = d;
                at = i;
            }
        }
        if (worst > tolerance_mm) {
            keep[at] = true;
            stack.emplace_back(first, at);
            stack.emplace_back(at, last);
        }
    }
    std::vector<ProfilePoint> out;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (keep[i])
            out.push_back(points[i]);
    return out;
}

} // namespace tolturn
