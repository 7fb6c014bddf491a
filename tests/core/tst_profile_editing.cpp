// SPDX-License-Identifier: GPL-3.0-or-later
// The profile editor's edits on a two-diameter shaft, checked against coordinates worked out
// by hand, and each result checked by validateProfile.
#include "core/common/diagnostic.h"
#include "core/part/profile_editing.h"
#include "core/part/profile_validation.h"

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
        QVERIFY(!refusal(addBore(blind, QStringLiteral("O1"), 10.0, 10.0)).isEmpty()); // bored already
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
