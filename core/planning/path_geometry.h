// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Plane geometry of tool paths in the half-section (z to the right, r upwards): lines and arcs in
// the order the tool travels them, their offset to the right of the travel (where the tool is when
// it turns an outer contour towards the chuck), and the upper envelope of a contour widened by a
// distance. Millimetres throughout.

#include "core/part/profile.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace tolturn {

struct PathElement {
    ProfilePoint from;
    ProfilePoint to;
    bool arc = false;
    ProfilePoint centre;    // arc
    double radius_mm = 0.0; // arc
    bool counterClockwise = false;
    QString featureId;
};

// The elements of a contour (left to right, as stored) in the order a tool meets them going from
// its right end to its left end: reversed, arcs turning the other way.
[[nodiscard]] std::vector<PathElement> reversedElements(const std::vector<Segment> &segments);

// Unit tangent of an element in its travel direction, at its start and at its end.
[[nodiscard]] ProfilePoint startTangent(const PathElement &e);
[[nodiscard]] ProfilePoint endTangent(const PathElement &e);

// The chain offset by a distance to the right of the travel: lines shifted along their normal,
// arcs with their radius grown (counter-clockwise) or shrunk (clockwise); a gap at a convex corner
// closed by an arc of the distance about the corner, an overlap at a concave corner trimmed at the
// intersection of the two offsets. Elements that vanish (an arc of smaller radius than the
// distance, a step narrower than the offset can enter) are dropped and named in `dropped`.
[[nodiscard]] std::vector<PathElement> offsetToTheRight(const std::vector<PathElement> &chain, double distance_mm,
                                                        QStringList *dropped = nullptr);

// A stretch of a contour that the insert's trailing edge keeps the tool off: where the contour
// falls in the feed direction (towards the headstock, -z) steeper than the trailing edge, the tool
// rides down a line at the trailing edge's angle from `from` until it meets the contour again at
// `to`, and leaves up to `deepest_mm` (radial) of what lies below that line.
struct RiddenOver {
    ProfilePoint from;
    ProfilePoint to;
    double deepest_mm = 0.0;
    QStringList featureIds;    // the features below the line, in the order the tool meets them
    double steepest_deg = 0.0; // of the fall, from the feed direction
};

// The chain (in the feed direction, towards -z) as a tool whose trailing edge rises `trailing_deg`
// from the z axis can follow it without cutting into what it has finished: a fall steeper than
// that is replaced by the line at `trailing_deg` from where it starts to where it meets the chain
// again (or the chain's last z). The nose centre, offset from that chain, then never descends
// steeper than the trailing edge, and so the edge never dips below the surface behind the nose.
// The stretches ridden over are appended to `riddenOver`.
[[nodiscard]] std::vector<PathElement> riddenOverSteepFalls(const std::vector<PathElement> &chain, double trailing_deg,
                                                            std::vector<RiddenOver> *riddenOver = nullptr);

// The shortest distance from a point to an element (a line segment, or an arc between its ends).
[[nodiscard]] double distanceTo(const PathElement &e, ProfilePoint p);

// Moves every point (and arc centre) of a chain by (dz, dr).
[[nodiscard]] std::vector<PathElement> translated(std::vector<PathElement> chain, double dz_mm, double dr_mm);

// Points along an element at most `step_mm` apart, both ends included, in at most `mostSteps` steps
// (then further apart).
[[nodiscard]] std::vector<ProfilePoint> sampled(const PathElement &e, double step_mm, int mostSteps = 100000);

// The upper envelope of the disc of radius `distance_mm` swept along a contour: for each z of a
// regular grid, the highest r that a point at `distance_mm` from the contour has (the region a
// nose centre kept at that distance may not enter from above). -infinity where the contour has no
// point within the distance.
struct Envelope {
    double z0_mm = 0.0;
    double step_mm = 0.0;
    std::vector<double> r_mm;

    [[nodiscard]] double z(std::size_t i) const { return z0_mm + step_mm * static_cast<double>(i); }
};

[[nodiscard]] Envelope widenedEnvelope(const std::vector<Segment> &contour, double distance_mm, double zFrom_mm,
                                       double zTo_mm, double step_mm);

// The envelope as a tool coming from +z with that trailing edge can cut down to it: no point
// lower than the line at `trailing_deg` down from any point on its right.
void rideOverSteepFalls(Envelope &env, double trailing_deg);

// Ramer–Douglas–Peucker: the fewest of the points that stay within `tolerance_mm` of the polyline.
[[nodiscard]] std::vector<ProfilePoint> simplified(const std::vector<ProfilePoint> &points, double tolerance_mm);

} // namespace tolturn
