// SPDX-License-Identifier: GPL-3.0-or-later
// Geometry of profile segments against hand-worked circle and line geometry.
#include "core/part/profile_geometry.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace tolturn;

namespace {

Segment line(SegmentKind kind, ProfilePoint a, ProfilePoint b)
{
    Segment s;
    s.id = QStringLiteral("S");
    s.kind = kind;
    s.from = a;
    s.to = b;
    return s;
}

Segment arc(ProfilePoint a, ProfilePoint b, double radius, ArcDirection direction)
{
    Segment s = line(SegmentKind::Radius, a, b);
    s.arcRadius_mm = radius;
    s.arcDirection = direction;
    return s;
}

constexpr double kPi = std::numbers::pi;

} // namespace

class TestProfileGeometry : public QObject {
    Q_OBJECT
private Q_SLOTS:

    // A convex edge round R2 from the top of a cylinder r = 20 down to a face at z = 120:
    // centre (118, 18), from 90 degrees clockwise to 0 degrees.
    void convexEdgeRound()
    {
        const auto g = arcGeometry(arc({118, 20}, {120, 18}, 2.0, ArcDirection::Clockwise));
        QVERIFY(g.has_value());
        QCOMPARE(g->centre.z_mm, 118.0);
        QVERIFY(std::abs(g->centre.r_mm - 18.0) < 1e-12);
        QVERIFY(std::abs(g->startAngle_rad - kPi / 2) < 1e-12);
        QVERIFY(std::abs(g->sweep_rad + kPi / 2) < 1e-12);
        QVERIFY(isMonotoneInZ(*g));
        // r(119) = 18 + sqrt(2^2 - 1^2)
        const Segment s = arc({118, 20}, {120, 18}, 2.0, ArcDirection::Clockwise);
        QVERIFY(std::abs(radiusOnSegment(s, 119.0) - (18.0 + std::sqrt(3.0))) < 1e-12);
        // quarter circle of radius 2: length pi
        QVERIFY(std::abs(segmentLength_mm(s) - kPi) < 1e-12);
    }

    // A concave fillet R2 at a shoulder, from a cylinder r = 5 up to a face at z = 12:
    // centre (10, 7), from -90 degrees counter-clockwise to 0 degrees.
    void concaveShoulderFillet()
    {
        const Segment s = arc({10, 5}, {12, 7}, 2.0, ArcDirection::CounterClockwise);
        const auto g = arcGeometry(s);
        QVERIFY(g.has_value());
        QVERIFY(std::abs(g->centre.z_mm - 10.0) < 1e-12);
        QVERIFY(std::abs(g->centre.r_mm - 7.0) < 1e-12);
        QVERIFY(std::abs(g->sweep_rad - kPi / 2) < 1e-12);
        QVERIFY(std::abs(radiusOnSegment(s, 11.0) - (7.0 - std::sqrt(3.0))) < 1e-12);
        const auto [lo, hi] = radiusRange(s);
        QCOMPARE(lo, 5.0);
        QCOMPARE(hi, 7.0);
    }

    // A half circle from (0, 4) to (4, 4) bulging upwards (clockwise): centre (2, 4), top at r = 6.
    void halfCircleBulge()
    {
        const Segment s = arc({0, 4}, {4, 4}, 2.0, ArcDirection::Clockwise);
        const auto g = arcGeometry(s);
        QVERIFY(g.has_value());
        QVERIFY(std::abs(std::abs(g->sweep_rad) - kPi) < 1e-12);
        QVERIFY(isMonotoneInZ(*g));
        QVERIFY(std::abs(radiusRange(s).second - 6.0) < 1e-12);
        QVERIFY(std::abs(radiusOnSegment(s, 2.0) - 6.0) < 1e-12);
        // counter-clockwise the same chord bulges downwards, to r = 2
        const Segment down = arc({0, 4}, {4, 4}, 2.0, ArcDirection::CounterClockwise);
        QVERIFY(std::abs(radiusRange(down).first - 2.0) < 1e-12);
        QVERIFY(std::abs(radiusOnSegment(down, 2.0) - 2.0) < 1e-12);
    }

    // An arc from (0, 0) up to (0, 4) passes the rightmost (or leftmost) point of its circle:
    // it turns back along z whichever way it runs.
    void arcTurningBackIsNotMonotone()
    {
        for (const ArcDirection d : {ArcDirection::Clockwise, ArcDirection::CounterClockwise}) {
            const auto g = arcGeometry(arc({0, 0}, {0, 4}, 2.0, d));
            QVERIFY(g.has_value());
            QVERIFY(!isMonotoneInZ(*g));
        }
    }

    void radiusShorterThanHalfChordHasNoArc()
    {
        QVERIFY(!arcGeometry(arc({0, 0}, {4, 0}, 1.9, ArcDirection::Clockwise)).has_value());
    }

    // Cone from r = 10 at z = 0 to r = 5 at z = 10: r(4) = 10 - 5 * 4 / 10 = 8; 3-4-5 length.
    void coneInterpolationAndLength()
    {
        QCOMPARE(radiusOnSegment(line(SegmentKind::Cone, {0, 10}, {10, 5}), 4.0), 8.0);
        QCOMPARE(segmentLength_mm(line(SegmentKind::Cone, {0, 0}, {3, 4})), 5.0);
    }

    // A step down at z = 5: the radius from the left is the larger one, from the right the smaller.
    void radiusAtStep()
    {
        Contour c;
        c.segments = {line(SegmentKind::Cylinder, {0, 10}, {5, 10}), line(SegmentKind::Face, {5, 10}, {5, 8}),
                      line(SegmentKind::Cylinder, {5, 8}, {9, 8})};
        QCOMPARE(radiusAt(c, 2.0, Approach::FromLeft).value(), 10.0);
        QCOMPARE(radiusAt(c, 5.0, Approach::FromLeft).value(), 10.0);
        QCOMPARE(radiusAt(c, 5.0, Approach::FromRight).value(), 8.0);
        QCOMPARE(radiusAt(c, 9.0, Approach::FromRight).value(), 8.0);
        QVERIFY(!radiusAt(c, 9.5, Approach::FromLeft).has_value());
    }

    void maxOuterRadiusIncludesArcBulge()
    {
        PartProfile p;
        p.outer.segments = {line(SegmentKind::Face, {0, 0}, {0, 4}), arc({0, 4}, {4, 4}, 2.0, ArcDirection::Clockwise),
                            line(SegmentKind::Face, {4, 4}, {4, 0})};
        QVERIFY(std::abs(p.maxOuterRadius_mm() - 6.0) < 1e-12);
        QCOMPARE(p.length_mm(), 4.0);
    }
};

QTEST_GUILESS_MAIN(TestProfileGeometry)
#include "tst_profile_geometry.moc"
