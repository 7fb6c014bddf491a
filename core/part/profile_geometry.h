// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/part/profile.h"

#include <optional>
#include <utility>
#include <vector>

namespace tolturn {

// Length tolerance for coordinates compared in a profile: 1 nm, far below any machining scale.
inline constexpr double kProfileEpsilon_mm = 1e-6;

// Centre and angular extent of a Radius segment in the (z, r) plane. Angles in radians,
// measured from the +z axis towards +r; the sweep is signed (positive counter-clockwise) and
// never exceeds pi: a Radius is always the minor arc between its end points.
struct ArcGeometry {
    ProfilePoint centre;
    double radius_mm = 0.0;
    double startAngle_rad = 0.0;
    double sweep_rad = 0.0;

    [[nodiscard]] ProfilePoint pointAt(double angle_rad) const;
};

// The arc of a Radius segment; nullopt when its radius is shorter than half the chord.
[[nodiscard]] std::optional<ArcGeometry> arcGeometry(const Segment &segment);

// True when the arc never turns back along z (it does not pass the leftmost or rightmost point
// of its circle), which a contour turned from left to right requires.
[[nodiscard]] bool isMonotoneInZ(const ArcGeometry &arc);

// Smallest and largest z an arc reaches (past its end points where it turns back).
[[nodiscard]] std::pair<double, double> zRange(const ArcGeometry &arc);

// Radius of an axial segment at z, for from.z <= z <= to.z.
[[nodiscard]] double radiusOnSegment(const Segment &segment, double z_mm);

// Smallest and largest radius reached along a segment (arcs can bulge past their end points).
[[nodiscard]] std::pair<double, double> radiusRange(const Segment &segment);

// Radius of a contour at z, as the limit from the left or from the right (they differ at a
// face). nullopt where the contour does not cover z.
enum class Approach { FromLeft, FromRight };
[[nodiscard]] std::optional<double> radiusAt(const Contour &contour, double z_mm, Approach approach);

// Where a segment (not a face) crosses the line z = const strictly inside its z range: one
// radius for a straight segment, one or two for an arc (an undercut radius crosses twice).
[[nodiscard]] std::vector<double> crossingRadii(const Segment &segment, double z_mm);

// The radius of the material's core at z for the beam: radiusAt(), and where an undercut
// overhangs the line z = const, the smallest crossing of the outer contour or the largest of the
// inner. The ring of material beyond an undercut's recess is left out (conservative; it spans
// at most the recess, tenths of a millimetre for DIN 509). Which segments are axial, and whether
// the contour has an undercut at all, is worked out once for the many z of a beam's sections.
// Keeps pointers into the contour.
class AxialSegments {
public:
    explicit AxialSegments(const Contour &contour);

    [[nodiscard]] std::optional<double> coreRadiusAt(double z_mm, Approach approach, ContourSide side) const;

private:
    std::vector<const Segment *> m_axial;    // in contour order
    std::vector<const Segment *> m_crossing; // every segment but faces
    bool m_undercut = false;
};

// Points along a segment for drawing: the two end points for straight segments, `arcPoints`
// points for a Radius.
[[nodiscard]] std::vector<ProfilePoint> samplePoints(const Segment &segment, int arcPoints = 24);

[[nodiscard]] double segmentLength_mm(const Segment &segment);

} // namespace tolturn
