// SPDX-License-Identifier: GPL-3.0-or-later
// Geometry of profile segments against hand-worked circle and line geometry.
#include "core/common/diagnostic.h"
#include "core/mechanics/section.h"
#include "core/part/profile_geometry.h"
#include "core/part/profile_validation.h"
#include "core/part/undercuts.h"

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

Segment named(Segment s, const char *id)
{
    s.id = QString::fromLatin1(id);
    return s;
}

// A bushing Ø40 × 100 bored Ø20 30 deep from the left and Ø16 40 deep from the right, solid
// from z 30 to z 60 (issue 16).
PartProfile boredFromBothEnds()
{
    using K = SegmentKind;
    PartProfile p;
    p.stockDiameter_mm = 45.0;
    p.outer.segments = {named(line(K::Face, {0, 10}, {0, 20}), "O1"),
                        named(line(K::Cylinder, {0, 20}, {100, 20}), "O2"),
                        named(line(K::Face, {100, 20}, {100, 8}), "O3")};
    p.inner.segments = {named(line(K::Cylinder, {0, 10}, {30, 10}), "I1"),
                        named(line(K::Face, {30, 10}, {30, 0}), "I2"), named(line(K::Face, {60, 0}, {60, 8}), "I3"),
                        named(line(K::Cylinder, {60, 8}, {100, 8}), "I4")};
    return p;
}

QString firstError(const PartProfile &p)
{
    for (const Diagnostic &d : validateProfile(p)) {
        if (d.severity == Severity::Error)
            return d.toString();
    }
    return {};
}

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

    // The bores' section: Ø20 in the left bore, solid between the bottoms, Ø16 in the right bore.
    void boresFromBothEndsWithSolidBetween()
    {
        const PartProfile p = boredFromBothEnds();
        QVERIFY2(firstError(p).isEmpty(), qPrintable(firstError(p)));
        QCOMPARE(p.inner.pieces().size(), std::size_t{2});
        const SectionAlongZ section(p, 0.0, 0.0);
        QCOMPARE(section.at(10.0).innerRadius_mm, 10.0);
        QCOMPARE(section.at(45.0).innerRadius_mm, 0.0);
        QCOMPARE(section.at(45.0).outerRadius_mm, 20.0);
        QCOMPARE(section.at(80.0).innerRadius_mm, 8.0);
    }

    void boresThatMeetOrLeaveTheAxisTwiceAreRefused()
    {
        PartProfile meeting = boredFromBothEnds(); // the right bore's bottom on the left one's
        meeting.inner.segments[2].from.z_mm = meeting.inner.segments[2].to.z_mm = 30.0;
        meeting.inner.segments[3].from.z_mm = 30.0;
        QVERIFY2(firstError(meeting).contains(QStringLiteral("part.inner[2].from: the bores from both ends meet")),
                 qPrintable(firstError(meeting)));
        PartProfile cavity = boredFromBothEnds(); // the left bore starts on the axis
        cavity.inner.segments[0] = named(line(SegmentKind::Cylinder, {10, 10}, {30, 10}), "I1");
        cavity.inner.segments.insert(cavity.inner.segments.begin(),
                                     named(line(SegmentKind::Face, {10, 0}, {10, 10}), "I0"));
        cavity.outer.segments[0].from.r_mm = 0.0;
        QVERIFY2(firstError(cavity).contains(QStringLiteral("closed at both ends")), qPrintable(firstError(cavity)));
        PartProfile three = boredFromBothEnds(); // a third piece: the axis left twice
        three.inner.segments.insert(three.inner.segments.begin() + 2,
                                    {named(line(SegmentKind::Face, {40, 0}, {40, 5}), "I5"),
                                     named(line(SegmentKind::Cylinder, {40, 5}, {45, 5}), "I6"),
                                     named(line(SegmentKind::Face, {45, 5}, {45, 0}), "I7")});
        QVERIFY2(firstError(three).contains(QStringLiteral("a second time")), qPrintable(firstError(three)));
    }

    // DIN 509 F0.6×0.3 under a shoulder at z 50 (Ø40 left of it, Ø30 right): at z 49.9 the beam's
    // section is the core inside the recess, the lower crossing of the R0.6 about (50.4, 15.3):
    // 15.3 - sqrt(0.6² - 0.5²) = 14.968338 mm; the ring of the shoulder beyond is left out.
    void undercutSectionIsTheCore()
    {
        using K = SegmentKind;
        PartProfile shaft;
        shaft.stockDiameter_mm = 45.0;
        shaft.outer.segments = {
            named(line(K::Face, {0, 0}, {0, 20}), "O1"), named(line(K::Cylinder, {0, 20}, {50, 20}), "O2"),
            named(line(K::Face, {50, 20}, {50, 15}), "O3"), named(line(K::Cylinder, {50, 15}, {100, 15}), "O4"),
            named(line(K::Face, {100, 15}, {100, 0}), "O5")};
        const auto edit = insertUndercut(shaft, ContourSide::Outer, 3, UndercutForm::F);
        const PartProfile p = std::get<PartProfile>(edit);
        QVERIFY2(firstError(p).isEmpty(), qPrintable(firstError(p)));
        const SectionAlongZ section(p, 0.0, 0.0);
        QVERIFY(std::abs(section.at(49.9).outerRadius_mm - (15.3 - std::sqrt(0.36 - 0.25))) < 1e-9);
        QCOMPARE(section.at(49.0).outerRadius_mm, 20.0); // left of the recess: the Ø40
        QCOMPARE(section.at(51.0).outerRadius_mm, 14.7); // the bottom
        const auto &breaks = section.breakpoints();      // the recess's deepest point, z 50 - t2
        QVERIFY(std::any_of(breaks.begin(), breaks.end(), [](double z) { return std::abs(z - 49.8) < 1e-9; }));
    }

    // An edge round R2 about (118, 18) from the top of a cylinder (118, 20) clockwise to just past
    // the circle's rightmost point (120, 18), as a STEP file can give it: 1e-5 rad past, it comes
    // back 2 (1 - cos 1e-5) = 1e-10 mm along z, a rounding error, not an undercut; 0.1 rad past,
    // 2 (1 - cos 0.1) = 0.00999 mm, an undercut.
    void filletEndingARoundingErrorPastItsTangentIsNoUndercut()
    {
        const auto endAt = [](double below) {
            return ProfilePoint{118 + 2 * std::cos(below), 18 - 2 * std::sin(below)};
        };
        QVERIFY(!arc({118, 20}, endAt(1e-5), 2.0, ArcDirection::Clockwise).turnsBack());
        QVERIFY(arc({118, 20}, endAt(0.1), 2.0, ArcDirection::Clockwise).turnsBack());
    }

    // A cone that goes back along z above the cylinder it came from, then a face down through
    // that cylinder: the contour crosses itself at (z 30, r 20).
    void contourCrossingItselfIsRefused()
    {
        using K = SegmentKind;
        PartProfile p;
        p.stockDiameter_mm = 60.0;
        p.outer.segments = {
            named(line(K::Face, {0, 0}, {0, 20}), "O1"),         named(line(K::Cylinder, {0, 20}, {50, 20}), "O2"),
            named(line(K::Cone, {50, 20}, {30, 25}), "O3"),      named(line(K::Face, {30, 25}, {30, 10}), "O4"),
            named(line(K::Cylinder, {30, 10}, {100, 10}), "O5"), named(line(K::Face, {100, 10}, {100, 0}), "O6")};
        const QString error = firstError(p);
        QVERIFY2(error.contains(QStringLiteral("part.outer[1]")) && error.contains(QStringLiteral("part.outer[3]")) &&
                     error.contains(QStringLiteral("(z 30, r 20)")),
                 qPrintable(error));
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
