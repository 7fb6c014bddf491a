// SPDX-License-Identifier: GPL-3.0-or-later
// The profile editor's edits on a two-diameter shaft, checked against coordinates worked out
// by hand, and each result checked by validateProfile.
#include "core/common/diagnostic.h"
#include "core/part/profile_editing.h"
#include "core/part/profile_validation.h"
#include "core/part/undercuts.h"

#include <QTest>

using namespace tolturn;

namespace {

Segment seg(const char *id, SegmentKind kind, double z0, double r0, double z1, double r1)
{
    Segment s;
    s.id = QString::fromLatin1(id);
    s.kind = kind;
    s.from = {z0, r0};
    s.to = {z1, r1};
    return s;
}

// Ø40 × 50 then Ø30 × 50: O1 left face, O2 Ø40, O3 shoulder, O4 Ø30, O5 right face.
PartProfile shaft()
{
    PartProfile p;
    p.name = QStringLiteral("shaft");
    p.stockDiameter_mm = 45.0;
    p.outer.segments = {seg("O1", SegmentKind::Face, 0, 0, 0, 20), seg("O2", SegmentKind::Cylinder, 0, 20, 50, 20),
                        seg("O3", SegmentKind::Face, 50, 20, 50, 15), seg("O4", SegmentKind::Cylinder, 50, 15, 100, 15),
                        seg("O5", SegmentKind::Face, 100, 15, 100, 0)};
    return p;
}

PartProfile edited(const ProfileEdit &edit)
{
    if (const auto *error = std::get_if<QString>(&edit))
        qFatal("edit refused: %s", qPrintable(*error));
    PartProfile p = std::get<PartProfile>(edit);
    if (hasErrors(validateProfile(p)))
        qFatal("edit gives an invalid profile: %s", qPrintable(validateProfile(p).front().toString()));
    return p;
}

QString refusal(const ProfileEdit &edit)
{
    const auto *error = std::get_if<QString>(&edit);
    return error ? *error : QString();
}

ProfilePoint pt(double z, double r)
{
    return {z, r};
}

// Within 1e-5 mm of the hand calculation (the trigonometry there is taken to 6 decimals).
bool near(const ProfilePoint &p, double z, double r)
{
    return std::abs(p.z_mm - z) < 1e-5 && std::abs(p.r_mm - r) < 1e-5;
}

QString text(const ProfilePoint &p)
{
    return QStringLiteral("(%1, %2)").arg(p.z_mm, 0, 'f', 6).arg(p.r_mm, 0, 'f', 6);
}

#define QVERIFY_NEAR(point, z, r) QVERIFY2(near(point, z, r), qPrintable(text(point)))

} // namespace

class TestProfileEditing : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void movingTheShoulderKeepsCylindersAndFaces()
    {
        // The corner O2|O3 to (60, 22): O2 becomes Ø44 up to z 60, the left face grows to r 22,
        // the shoulder O3 moves to z 60 and still ends at r 15.
        const PartProfile p = edited(moveVertex(shaft(), ContourSide::Outer, 2, pt(60, 22)));
        const auto &s = p.outer.segments;
        QCOMPARE(s[0].to, pt(0, 22));
        QCOMPARE(s[1].from, pt(0, 22));
        QCOMPARE(s[1].to, pt(60, 22));
        QCOMPARE(s[2].from, pt(60, 22));
        QCOMPARE(s[2].to, pt(60, 15));
        QCOMPARE(s[3].from, pt(60, 15));
        QCOMPARE(s.size(), std::size_t{5});
    }

    void insertingAStep()
    {
        // Ø30 from z 50 to 100 stepped down to Ø20 at z 80.
        const PartProfile p = edited(insertStep(shaft(), QStringLiteral("O4"), 80.0, 20.0));
        const auto &s = p.outer.segments;
        QCOMPARE(s.size(), std::size_t{7});
        QCOMPARE(s[3].to, pt(80, 15));
        QCOMPARE(s[4].id, QStringLiteral("O6"));
        QCOMPARE(s[4].kind, SegmentKind::Face);
        QCOMPARE(s[4].to, pt(80, 10));
        QCOMPARE(s[5].id, QStringLiteral("O7"));
        QCOMPARE(s[5].to, pt(100, 10));
        QCOMPARE(s[6].from, pt(100, 10)); // the end face now starts at the new diameter
        QCOMPARE(s[6].to, pt(100, 0));
    }

    void stepRefusals()
    {
        QVERIFY(refusal(insertStep(shaft(), QStringLiteral("O3"), 50.0, 20.0)).contains(QStringLiteral("O3")));
        QVERIFY(refusal(insertStep(shaft(), QStringLiteral("O4"), 120.0, 20.0)).contains(QStringLiteral("120")));
        QVERIFY(refusal(insertStep(shaft(), QStringLiteral("O4"), 80.0, 30.0)).contains(QStringLiteral("Ø30")));
    }

    void chamferAndBackToTheCorner()
    {
        // 1 mm × 45° on the right end: O4 ends 1 mm early, the chamfer runs down to r 14.
        const PartProfile p = edited(breakCorner(shaft(), ContourSide::Outer, 4, 1.0, false));
        const auto &s = p.outer.segments;
        QCOMPARE(s[3].to, pt(99, 15));
        QCOMPARE(s[4].kind, SegmentKind::Chamfer);
        QCOMPARE(s[4].from, pt(99, 15));
        QCOMPARE(s[4].to, pt(100, 14));
        QCOMPARE(s[5].from, pt(100, 14));
        QVERIFY(edited(deleteFeature(p, s[4].id)) == shaft());
    }

    void roundTurnsWithThePath()
    {
        // Along the outer contour the path turns right (clockwise) at the right end (along z,
        // then down) and left (counter-clockwise) into the shoulder's lower step.
        const PartProfile end = edited(breakCorner(shaft(), ContourSide::Outer, 4, 2.0, true));
        QCOMPARE(end.outer.segments[4].kind, SegmentKind::Radius);
        QCOMPARE(end.outer.segments[4].arcRadius_mm, 2.0);
        QCOMPARE(end.outer.segments[4].arcDirection, ArcDirection::Clockwise);
        const PartProfile fillet = edited(breakCorner(shaft(), ContourSide::Outer, 3, 1.0, true));
        QCOMPARE(fillet.outer.segments[3].arcDirection, ArcDirection::CounterClockwise);
        QCOMPARE(fillet.outer.segments[3].from, pt(50, 16));
        QCOMPARE(fillet.outer.segments[3].to, pt(51, 15));
    }

    // A 1.5 mm × 45° chamfer at the right end (z 98.5 → 100, r 15 → 13.5) becomes a quarter
    // circle of radius 1.5 between the same two points, turning right, under the same id; and
    // back to the chamfer it was.
    void chamferBecomesRoundAndBack()
    {
        const PartProfile chamfered = edited(breakCorner(shaft(), ContourSide::Outer, 4, 1.5, false));
        const QString id = chamfered.outer.segments[4].id;
        const PartProfile rounded = edited(swapCornerBreak(chamfered, id));
        const Segment &round = rounded.outer.segments[4];
        QCOMPARE(round.id, id);
        QCOMPARE(round.kind, SegmentKind::Radius);
        QCOMPARE(round.arcRadius_mm, 1.5);
        QCOMPARE(round.arcDirection, ArcDirection::Clockwise);
        QCOMPARE(round.from, pt(98.5, 15));
        QCOMPARE(round.to, pt(100, 13.5));
        QCOMPARE(rounded.outer.segments.size(), std::size_t(6));
        QVERIFY(edited(swapCornerBreak(rounded, id)) == chamfered);
        QVERIFY(refusal(swapCornerBreak(shaft(), QStringLiteral("O2"))).contains(QStringLiteral("O2")));
    }

    void cornerRefusals()
    {
        // 6 mm does not fit on the 5 mm shoulder.
        QVERIFY(refusal(breakCorner(shaft(), ContourSide::Outer, 3, 6.0, false)).contains(QStringLiteral("6 mm")));
        QVERIFY(!refusal(breakCorner(shaft(), ContourSide::Outer, 0, 1.0, false)).isEmpty());
    }

    void cylinderBecomesConeAndBack()
    {
        // O4 tapered from Ø30 at z 50 to Ø24 at z 100; the right end face follows to r 12.
        const PartProfile taper = edited(makeCone(shaft(), QStringLiteral("O4"), 24.0));
        QCOMPARE(taper.outer.segments[3].kind, SegmentKind::Cone);
        QCOMPARE(taper.outer.segments[3].from, pt(50, 15));
        QCOMPARE(taper.outer.segments[3].to, pt(100, 12));
        QCOMPARE(taper.outer.segments[4].from, pt(100, 12));
        QVERIFY(edited(makeCylinder(taper, QStringLiteral("O4"))) == shaft());
        QVERIFY(refusal(makeCone(shaft(), QStringLiteral("O4"), 30.0)).contains(QStringLiteral("Ø30")));
        QVERIFY(refusal(makeCone(shaft(), QStringLiteral("O3"), 20.0)).contains(QStringLiteral("O3")));
    }

    void boringTheShaft()
    {
        // A Ø16 hole 40 mm deep from the right end: its bottom at z 60, the end face O5 now
        // closes at r 8.
        const PartProfile blind = edited(addBore(shaft(), QStringLiteral("O5"), 40.0, 16.0));
        QCOMPARE(blind.inner.segments.size(), std::size_t{2});
        QCOMPARE(blind.inner.segments[0].kind, SegmentKind::Face);
        QCOMPARE(blind.inner.segments[0].from, pt(60, 0));
        QCOMPARE(blind.inner.segments[1].to, pt(100, 8));
        QCOMPARE(blind.outer.segments.back().to, pt(100, 8));
        QCOMPARE(blind.outer.segments.front().from, pt(0, 0)); // the left end stays solid
        // Through from the left: both end faces close at the bore.
        const PartProfile through = edited(addBore(shaft(), QStringLiteral("O1"), 100.0, 16.0));
        QCOMPARE(through.inner.segments.size(), std::size_t{1});
        QCOMPARE(through.outer.segments.front().from, pt(0, 8));
        QCOMPARE(through.outer.segments.back().to, pt(100, 8));
        QVERIFY(refusal(addBore(shaft(), QStringLiteral("O3"), 10.0, 16.0)).contains(QStringLiteral("O3")));
        QVERIFY(!refusal(addBore(blind, QStringLiteral("O5"), 10.0, 10.0)).isEmpty()); // bored there already
        QVERIFY(!refusal(addBore(through, QStringLiteral("O1"), 10.0, 10.0)).isEmpty());
    }

    // Issue 16: a Ø10 bore 20 deep from the left end into the shaft bored Ø16 40 deep from the
    // right: the inner contour is I3 (Ø10, z 0 … 20), I4 (its bottom down to the axis), then the
    // right bore as before; solid from z 20 to 60. A bore that would reach z 60 is refused.
    void boringFromBothEnds()
    {
        const PartProfile blind = edited(addBore(shaft(), QStringLiteral("O5"), 40.0, 16.0));
        const PartProfile both = edited(addBore(blind, QStringLiteral("O1"), 20.0, 10.0));
        const auto &in = both.inner.segments;
        QCOMPARE(in.size(), std::size_t{4});
        QCOMPARE(in[0].id, QStringLiteral("I3"));
        QCOMPARE(in[0].from, pt(0, 5));
        QCOMPARE(in[1].to, pt(20, 0));
        QCOMPARE(in[2].from, pt(60, 0));
        QVERIFY(both.inner.breaksBefore(2));
        QCOMPARE(both.inner.pieces().size(), std::size_t{2});
        QCOMPARE(both.outer.segments.front().from, pt(0, 5));
        QVERIFY(refusal(addBore(blind, QStringLiteral("O1"), 60.0, 10.0)).contains(QStringLiteral("z = 60 mm")));
        // The left bore's bottom corner to Ø12: I3 and its bottom I4 follow; the right bore's
        // bottom, beyond the solid, stays where it is.
        const PartProfile wider = edited(moveVertex(both, ContourSide::Inner, 1, pt(20, 6)));
        QCOMPARE(wider.inner.segments[0].to, pt(20, 6));
        QCOMPARE(wider.inner.segments[1].from, pt(20, 6));
        QCOMPARE(wider.inner.segments[1].to, pt(20, 0));
        QCOMPARE(wider.inner.segments[2].from, pt(60, 0));
        QCOMPARE(wider.inner.segments[2].to, pt(60, 8));
        // The right bore deeper from its bottom corner: the left bore does not move.
        const PartProfile deeper = edited(moveVertex(both, ContourSide::Inner, 3, pt(50, 8)));
        QCOMPARE(deeper.inner.segments[2].from, pt(50, 0));
        QCOMPARE(deeper.inner.segments[1].to, pt(20, 0));
        // A bore's bottom is an end of its piece: deleting it is refused.
        QVERIFY(refusal(deleteFeature(both, QStringLiteral("I4"))).contains(QStringLiteral("I4")));
    }

    // DIN 509 F0.6×0.3 (Ø30 is in the row d > 18 … 80: r 0.6, t1 0.3, f 2.5, t2 0.2, run-out 15°,
    // flank 8°) in the inside corner O3|O4 (shoulder face at z 50 down to the Ø30 cylinder, which
    // runs right). By hand, z = 50 + a, r = 15 - b with a along the cylinder, b into it:
    //   run-out from a = f = 2.5 to a = 2.5 - 0.3 / tan 15° = 1.380385 at b = 0.3;
    //   bottom to a = r - t2 = 0.4; radius about (0.4, -0.3) to the tangent point of the flank,
    //   a = 0.4 - 0.6 cos 8° = -0.194161, b = -0.3 - 0.6 sin 8° = -0.383504;
    //   flank back to the face (a = 0) over 0.194161 / sin 8° = 1.395106 mm, to
    //   b = -0.383504 - 1.395106 cos 8° = -1.765033.
    void din509FormFInAShoulder()
    {
        const PartProfile p = edited(insertUndercut(shaft(), ContourSide::Outer, 3, UndercutForm::F));
        const auto &s = p.outer.segments;
        QCOMPARE(s.size(), std::size_t{9});
        QCOMPARE(s[2].id, QStringLiteral("O3"));
        QVERIFY_NEAR(s[2].to, 50.0, 16.765033);
        QCOMPARE(s[3].kind, SegmentKind::Cone); // the flank, back along z
        QVERIFY_NEAR(s[3].to, 49.805839, 15.383504);
        QVERIFY(s[3].turnsBack());
        QCOMPARE(s[4].kind, SegmentKind::Radius);
        QCOMPARE(s[4].arcRadius_mm, 0.6);
        QVERIFY_NEAR(s[4].to, 50.4, 14.7);
        QVERIFY(s[4].turnsBack()); // it reaches z = 49.8, under the shoulder
        QVERIFY_NEAR(s[5].to, 51.380385, 14.7);
        QVERIFY_NEAR(s[6].to, 52.5, 15.0);
        QCOMPARE(s[7].id, QStringLiteral("O4"));
        QVERIFY_NEAR(s[7].from, 52.5, 15.0);
        QVERIFY(s[4].name.contains(QStringLiteral("F0.6×0.3")));
        QVERIFY(!s[5].turnsBack() && s[5].isAxial());
    }

    // Form E in the same corner: the radius ends on the face at b = t1 - r = -0.3 (r 15.3) and
    // runs counter-clockwise (down the face, then along the bottom) to a = r = 0.6 at the depth.
    void din509FormEInAShoulder()
    {
        const PartProfile p = edited(insertUndercut(shaft(), ContourSide::Outer, 3, UndercutForm::E));
        const auto &s = p.outer.segments;
        QCOMPARE(s.size(), std::size_t{8});
        QVERIFY_NEAR(s[2].to, 50.0, 15.3);
        QCOMPARE(s[3].kind, SegmentKind::Radius);
        QCOMPARE(s[3].arcDirection, ArcDirection::CounterClockwise);
        QVERIFY_NEAR(s[3].to, 50.6, 14.7);
        QVERIFY(!s[3].turnsBack());
        QVERIFY_NEAR(s[4].to, 51.380385, 14.7);
        QVERIFY_NEAR(s[5].to, 52.5, 15.0);
    }

    void undercutRefusals()
    {
        // O2|O3 is an outside corner (the face falls from Ø40 to Ø30).
        QVERIFY(refusal(insertUndercut(shaft(), ContourSide::Outer, 2, UndercutForm::E))
                    .contains(QStringLiteral("outside")));
        // O1|O2: a face and a cylinder, but the left end face is not a shoulder above Ø40.
        QVERIFY(!refusal(insertUndercut(shaft(), ContourSide::Outer, 1, UndercutForm::E)).isEmpty());
        // A shoulder only 1 mm high cannot take form F's flank, which meets it 1.765 mm up.
        PartProfile low = shaft();
        low.outer.segments[1].from.r_mm = low.outer.segments[1].to.r_mm = 16.0;
        low.outer.segments[0].to.r_mm = 16.0;
        low.outer.segments[2].from.r_mm = 16.0;
        QVERIFY(
            refusal(insertUndercut(low, ContourSide::Outer, 3, UndercutForm::F)).contains(QStringLiteral("too low")));
        QVERIFY(undercutSizeFor(0.0) == std::nullopt);
        QCOMPARE(undercutSizeFor(80.0)->radius_mm, 0.6); // d <= 80 is the row above 18
        QCOMPARE(undercutSizeFor(80.5)->radius_mm, 1.0);
    }

    // A groove 3 wide and 2 deep in the Ø30 cylinder from z 70: O4 to z 70, a flank down to r 13,
    // the bottom to z 73, a flank up, the rest of O4; groovesOf() finds it 3 wide, 2 deep.
    void grooveInACylinder()
    {
        const PartProfile p = edited(insertGroove(shaft(), QStringLiteral("O4"), 70.0, 3.0, 2.0));
        const auto &s = p.outer.segments;
        QCOMPARE(s.size(), std::size_t{9});
        QCOMPARE(s[3].to, pt(70, 15));
        QCOMPARE(s[4].to, pt(70, 13));
        QCOMPARE(s[5].to, pt(73, 13));
        QCOMPARE(s[6].to, pt(73, 15));
        QCOMPARE(s[7].to, pt(100, 15));
        const std::vector<Groove> grooves = groovesOf(p.outer, ContourSide::Outer);
        QCOMPARE(grooves.size(), std::size_t{1});
        QCOMPARE(grooves[0].leftFaceId, s[4].id);
        QCOMPARE(grooves[0].rightFaceId, s[6].id);
        QCOMPARE(grooves[0].width_mm, 3.0);
        QCOMPARE(grooves[0].depth_mm, 2.0);
        QVERIFY(groovesOf(shaft().outer, ContourSide::Outer).empty()); // a step is not a groove
        QVERIFY(refusal(insertGroove(shaft(), QStringLiteral("O4"), 98.0, 3.0, 2.0)).contains(QStringLiteral("101")));
        QVERIFY(refusal(insertGroove(shaft(), QStringLiteral("O4"), 70.0, 3.0, 15.0)).contains(QStringLiteral("axis")));
    }

    // A bore is edited like the outside: a through Ø16 bore stepped at z 20 to Ø24 (I1 Ø16 over
    // z 0 … 20, the step face I2, I3 Ø24 to the right end, whose face now closes at r 12), the
    // inner corner at the step chamfered 1 mm × 45°.
    void steppingAndChamferingTheBore()
    {
        const PartProfile through = edited(addBore(shaft(), QStringLiteral("O1"), 100.0, 16.0));
        const PartProfile stepped = edited(insertStep(through, QStringLiteral("I1"), 20.0, 24.0));
        const auto &in = stepped.inner.segments;
        QCOMPARE(in.size(), std::size_t{3});
        QCOMPARE(in[0].to, pt(20, 8));
        QCOMPARE(in[1].kind, SegmentKind::Face);
        QCOMPARE(in[1].to, pt(20, 12));
        QCOMPARE(in[2].to, pt(100, 12));
        QCOMPARE(stepped.outer.segments.back().to, pt(100, 12));
        const PartProfile chamfered = edited(breakCorner(stepped, ContourSide::Inner, 2, 1.0, false));
        QCOMPARE(chamfered.inner.segments[2].kind, SegmentKind::Chamfer);
        QCOMPARE(chamfered.inner.segments[2].from, pt(20, 11));
        QCOMPARE(chamfered.inner.segments[2].to, pt(21, 12));
    }

    void deletingTheShoulderRemovesTheStep()
    {
        const PartProfile p = edited(deleteFeature(shaft(), QStringLiteral("O3")));
        const auto &s = p.outer.segments;
        QCOMPARE(s.size(), std::size_t{3});
        QCOMPARE(s[1].id, QStringLiteral("O2"));
        QCOMPARE(s[1].to, pt(100, 20)); // one Ø40 cylinder over the whole length
        QCOMPARE(s[2].from, pt(100, 20));
        QVERIFY(refusal(deleteFeature(shaft(), QStringLiteral("O1"))).contains(QStringLiteral("O1")));
        QVERIFY(refusal(deleteFeature(shaft(), QStringLiteral("O9"))).contains(QStringLiteral("O9")));
    }
};

QTEST_GUILESS_MAIN(TestProfileEditing)
#include "tst_profile_editing.moc"
