// SPDX-License-Identifier: GPL-3.0-or-later
// The profile editor's Feature dock driven on the stepped-shaft example: exact entry of a
// corner, a step, a chamfer, a delete; each one undoable step; refusals leave the part alone.
#include "tests/examples.h"
#include "tests/gui/screenshot.h"

#include "app/gui/file_controller.h"
#include "app/gui/main_window.h"
#include "widgets/common/length_spin_box.h"
#include "widgets/document/project_document.h"
#include "widgets/profile/feature_panel.h"
#include "widgets/profile/profile_view.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QStandardPaths>
#include <QTest>
#include <QUndoStack>

using namespace tolturn;

namespace {

using tolturn::test::example;

const Segment &feature(const MainWindow &w, const char *id)
{
    static const Segment none;
    const std::optional<FeatureRef> ref = findFeature(w.document()->project().part, QString::fromLatin1(id));
    return ref ? *ref->segment : none;
}

ProfilePoint pt(double z, double r)
{
    return {z, r};
}

} // namespace

class TestFeaturePanel : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void clickingAFeatureShowsIt()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        QVERIFY(!w.featurePanel()->isEnabled());
        w.profileView()->selectFeature(QStringLiteral("O6"));
        QCOMPARE(w.featurePanel()->feature(), QStringLiteral("O6"));
        QVERIFY(w.featurePanel()->isEnabled());
        QCOMPARE(w.featurePanel()->startZBox()->value(), 90.0);
        QCOMPARE(w.featurePanel()->startDiameterBox()->value(), 40.0);
        QCOMPARE(w.featurePanel()->endZBox()->value(), 118.0);
    }

    void diameterEntryMovesTheCylinder()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        w.profileView()->selectFeature(QStringLiteral("O4"));
        w.featurePanel()->startDiameterBox()->setValue(52.0);
        // The bearing seat O4 (z 35 … 80) goes to Ø52 over its length; the shoulder O3 now ends
        // at r 26 and the taper O5 starts there.
        QCOMPARE(feature(w, "O4").from, pt(35, 26));
        QCOMPARE(feature(w, "O4").to, pt(80, 26));
        QCOMPARE(feature(w, "O3").to, pt(35, 26));
        QCOMPARE(feature(w, "O5").from, pt(80, 26));
        QCOMPARE(w.document()->undoStack()->count(), 1);
        w.document()->undoStack()->undo();
        QCOMPARE(feature(w, "O4").from, pt(35, 25));
        QCOMPARE(w.featurePanel()->startDiameterBox()->value(), 50.0);
    }

    // The diameters a box goes through while it is stepped or typed into are one step in Undo.
    void steppingADiameterIsOneUndoStep()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        w.profileView()->selectFeature(QStringLiteral("O4"));
        for (const double d : {50.5, 51.0, 51.5, 52.0})
            w.featurePanel()->startDiameterBox()->setValue(d);
        QCOMPARE(feature(w, "O4").from, pt(35, 26));
        QCOMPARE(w.document()->undoStack()->count(), 1);
        w.document()->undoStack()->undo();
        QCOMPARE(feature(w, "O4").from, pt(35, 25));
        QVERIFY(!w.document()->isModified());
        // The same box on another feature, or after Return, is a step of its own.
        w.featurePanel()->startDiameterBox()->setValue(51.0);
        w.profileView()->selectFeature(QStringLiteral("O9")); // the Ø30 journal, z 120 … 149
        w.featurePanel()->startDiameterBox()->setValue(31.0);
        QCOMPARE(w.document()->undoStack()->count(), 2);
        Q_EMIT w.featurePanel()->startDiameterBox()->editingFinished();
        w.featurePanel()->startDiameterBox()->setValue(32.0);
        QCOMPARE(w.document()->undoStack()->count(), 3);
        w.document()->undoStack()->undo();
        QCOMPARE(feature(w, "O9").from, pt(120, 15.5));
    }

    void stepChamferAndDelete()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        const std::size_t segments = w.document()->project().part.outer.segments.size();
        w.profileView()->selectFeature(QStringLiteral("O9")); // the Ø30 journal, z 120 … 149
        w.featurePanel()->stepZBox()->setValue(135.0);
        w.featurePanel()->stepDiameterBox()->setValue(26.0);
        w.featurePanel()->insertStep();
        QCOMPARE(w.document()->project().part.outer.segments.size(), segments + 2);
        QCOMPARE(feature(w, "O9").to, pt(135, 15));
        QCOMPARE(feature(w, "O13").from, pt(135, 13)); // the new Ø26 cylinder
        QCOMPARE(feature(w, "O10").from, pt(149, 13)); // the end chamfer follows the new diameter

        w.profileView()->selectFeature(QStringLiteral("O7")); // the edge round: back to a corner
        w.featurePanel()->deleteFeature();
        QCOMPARE(feature(w, "O6").to, pt(120, 20));
        QCOMPARE(feature(w, "O8").from, pt(120, 20));
        QCOMPARE(w.profileView()->selectedFeature(), QString());

        w.profileView()->selectFeature(QStringLiteral("O6"));
        w.featurePanel()->cornerSizeBox()->setValue(1.5);
        w.featurePanel()->breakCorner(true, false); // chamfer the corner O6|O8
        QCOMPARE(feature(w, "O6").to, pt(118.5, 20));
        QCOMPARE(w.document()->undoStack()->count(), 3);
        for (int i = 0; i < 3; ++i)
            w.document()->undoStack()->undo();
        QCOMPARE(w.document()->project().part.outer.segments.size(), segments);
        QVERIFY(!w.document()->isModified());
    }

    void draggingACornerSnapsAndIsOneStep()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        ProfileView *view = w.profileView();
        view->selectFeature(QStringLiteral("O4")); // Ø50 from z 35 to 80; its end is vertex 4
        QWidget *viewport = view->viewport();
        const QPoint grab = view->mapFromScene(QPointF(80.0, -25.0));
        // A grid point, so that whole pixels (about 0.3 mm here) still snap to it.
        const QPoint drop = view->mapFromScene(QPointF(70.0, -26.5));
        QTest::mousePress(viewport, Qt::LeftButton, {}, grab);
        QTest::mouseMove(viewport, (grab + drop) / 2);
        QTest::mouseMove(viewport, drop);
        QTest::mouseRelease(viewport, Qt::LeftButton, {}, drop);
        // The cylinder keeps one diameter: both its ends go to r 26.5; the shoulder follows.
        QCOMPARE(feature(w, "O4").to, pt(70, 26.5));
        QCOMPARE(feature(w, "O4").from, pt(35, 26.5));
        QCOMPARE(feature(w, "O3").to, pt(35, 26.5));
        QCOMPARE(feature(w, "O5").from, pt(70, 26.5));
        QCOMPARE(w.document()->undoStack()->count(), 1);
        if (auto *dock = w.findChild<QDockWidget *>(QStringLiteral("featureDock")))
            dock->raise();
        QTest::qWait(50);
        tolturn::test::saveScreenshot(w, "profile-editor.png");
    }

    void cylinderToConeThenTaper()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        w.profileView()->selectFeature(QStringLiteral("O2")); // Ø56 clamping diameter, z 0 … 35
        w.featurePanel()->stepDiameterBox()->setValue(54.0);
        w.featurePanel()->changeKind(); // a taper to Ø54 at its end
        QVERIFY2(w.featurePanel()->message().isEmpty(), qPrintable(w.featurePanel()->message()));
        QCOMPARE(feature(w, "O2").kind, SegmentKind::Cone);
        QCOMPARE(feature(w, "O2").from, pt(0, 28));
        QCOMPARE(feature(w, "O2").to, pt(35, 27));
        QCOMPARE(feature(w, "O3").from, pt(35, 27)); // the shoulder O3 follows
        w.featurePanel()->changeKind();
        QCOMPARE(feature(w, "O2").kind, SegmentKind::Cylinder);
        QCOMPARE(feature(w, "O2").to, pt(35, 28));
        QCOMPARE(w.document()->undoStack()->count(), 2);
        // The journal O9 tapered to Ø28 would flatten the end chamfer O10: refused, named.
        w.profileView()->selectFeature(QStringLiteral("O9"));
        w.featurePanel()->stepDiameterBox()->setValue(28.0);
        w.featurePanel()->changeKind();
        QVERIFY2(w.featurePanel()->message().contains(QStringLiteral("part.outer[9]")),
                 qPrintable(w.featurePanel()->message()));
        QCOMPARE(feature(w, "O9").kind, SegmentKind::Cylinder);
        // The bearing seat O4 carries a diameter tolerance, which a cone cannot: refused.
        w.profileView()->selectFeature(QStringLiteral("O4"));
        w.featurePanel()->stepDiameterBox()->setValue(48.0);
        w.featurePanel()->changeKind();
        QVERIFY(!w.featurePanel()->message().isEmpty());
        QCOMPARE(feature(w, "O4").kind, SegmentKind::Cylinder);
    }

    // The end chamfer O10 (1 mm × 45°, z 149 → 150 down from the journal Ø30) becomes a 1 mm edge round
    // under the same id, and back; one undo step each.
    void chamferBecomesRound()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        const Segment chamfer = feature(w, "O10");
        QCOMPARE(chamfer.kind, SegmentKind::Chamfer);
        w.profileView()->selectFeature(QStringLiteral("O10"));
        w.featurePanel()->changeKind();
        QVERIFY2(w.featurePanel()->message().isEmpty(), qPrintable(w.featurePanel()->message()));
        QCOMPARE(feature(w, "O10").kind, SegmentKind::Radius);
        QCOMPARE(feature(w, "O10").from, chamfer.from);
        QCOMPARE(feature(w, "O10").to, chamfer.to);
        QCOMPARE(feature(w, "O10").arcRadius_mm, chamfer.to.z_mm - chamfer.from.z_mm);
        w.featurePanel()->changeKind();
        QCOMPARE(feature(w, "O10").kind, SegmentKind::Chamfer);
        QCOMPARE(feature(w, "O10").from, chamfer.from);
        QCOMPARE(feature(w, "O10").to, chamfer.to);
        QCOMPARE(w.document()->undoStack()->count(), 2);
        w.document()->undoStack()->undo();
        QCOMPARE(feature(w, "O10").kind, SegmentKind::Radius);
    }

    void boreFromTheRightEnd()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        w.profileView()->selectFeature(QStringLiteral("O11")); // the right end face
        w.featurePanel()->boreDepthBox()->setValue(40.0);
        w.featurePanel()->boreDiameterBox()->setValue(16.0);
        w.featurePanel()->addBore();
        QVERIFY2(w.featurePanel()->message().isEmpty(), qPrintable(w.featurePanel()->message()));
        const PartProfile &p = w.document()->project().part;
        QCOMPARE(p.inner.segments.size(), std::size_t{2});
        QCOMPARE(p.inner.segments[0].from, pt(110, 0)); // bottom 40 mm in from z 150
        QCOMPARE(p.outer.segments.back().to, pt(150, 8));
        w.document()->undoStack()->undo();
        QVERIFY(w.document()->project().part.inner.empty());
    }

    // Issue 16: a DIN 509 F undercut at the start of the Ø50 bearing seat O4, under the Ø56
    // shoulder at z 35 (Ø50 is in the row d > 18 … 80: f 2.5, so O4 now starts at z 37.5, and
    // four features are added), and a groove 3 wide, 1 deep in the Ø30 journal from z 130; each
    // one undoable edit.
    void grooveAndUndercutFromThePanel()
    {
        MainWindow w;
        w.show();
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        if (auto *dock = w.findChild<QDockWidget *>(QStringLiteral("featureDock")))
            dock->raise();
        const std::size_t before = w.document()->project().part.outer.segments.size();
        w.profileView()->selectFeature(QStringLiteral("O4"));
        w.featurePanel()->undercutFormBox()->setCurrentIndex(1); // form F
        w.featurePanel()->insertUndercut(false);
        QVERIFY2(w.featurePanel()->message().isEmpty(), qPrintable(w.featurePanel()->message()));
        QCOMPARE(w.document()->project().part.outer.segments.size(), before + 4);
        QCOMPARE(feature(w, "O4").from, pt(37.5, 25));
        QVERIFY(feature(w, "O14").turnsBack()); // the radius under the shoulder (O12 run-out, O13 bottom)
        w.profileView()->selectFeature(QStringLiteral("O9"));
        w.featurePanel()->grooveZBox()->setValue(130.0);
        w.featurePanel()->grooveWidthBox()->setValue(3.0);
        w.featurePanel()->grooveDepthBox()->setValue(1.0);
        w.featurePanel()->insertGroove();
        QVERIFY2(w.featurePanel()->message().isEmpty(), qPrintable(w.featurePanel()->message()));
        QCOMPARE(feature(w, "O9").to, pt(130, 15));
        QCOMPARE(feature(w, "O17").to, pt(133, 14)); // the groove's bottom
        w.profileView()->selectFeature(QStringLiteral("O9"));
        QTest::qWait(50);
        test::saveScreenshot(w, "feature-panel-groove-undercut.png");
        w.document()->undoStack()->undo();
        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->project().part.outer.segments.size(), before);
        // Form E at the end of O4 is refused: the taper O5 follows, not a shoulder face.
        w.profileView()->selectFeature(QStringLiteral("O4"));
        w.featurePanel()->insertUndercut(true);
        QVERIFY2(w.featurePanel()->message().contains(QStringLiteral("O5")), qPrintable(w.featurePanel()->message()));
    }

    void deleteKeyDeletesTheSelectedFeature()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        auto *action = w.findChild<QAction *>(QStringLiteral("deleteFeatureAction"));
        QVERIFY(action != nullptr);
        QCOMPARE(action->shortcut(), QKeySequence(QKeySequence::Delete));
        QVERIFY(!action->isEnabled());                         // nothing selected
        w.profileView()->selectFeature(QStringLiteral("O10")); // the end chamfer
        QVERIFY(action->isEnabled());
        action->trigger();
        QVERIFY(!findFeature(w.document()->project().part, QStringLiteral("O10")));
        QCOMPARE(feature(w, "O9").to, pt(150, 15)); // the sharp corner is back
    }

    void refusalsLeaveThePart()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        const PartProfile before = w.document()->project().part;
        w.profileView()->selectFeature(QStringLiteral("O4")); // carries tolerances T1 and T2
        w.featurePanel()->deleteFeature();
        QVERIFY2(w.featurePanel()->message().contains(QStringLiteral("O4")), qPrintable(w.featurePanel()->message()));
        QVERIFY(w.document()->project().part == before);
        w.featurePanel()->stepZBox()->setValue(10.0); // outside O4 (z 35 … 80)
        w.featurePanel()->insertStep();
        QVERIFY2(w.featurePanel()->message().contains(QStringLiteral("10")), qPrintable(w.featurePanel()->message()));
        QVERIFY(w.document()->project().part == before);
        // Ø42 on the hub seat would make the R2 edge round O7 bulge past the locating face and
        // come back: an undercut, which a dragged corner never makes.
        w.profileView()->selectFeature(QStringLiteral("O6"));
        w.featurePanel()->startDiameterBox()->setValue(42.0);
        QVERIFY2(w.featurePanel()->message().contains(QStringLiteral("O7 turn back along z")),
                 qPrintable(w.featurePanel()->message()));
        QCOMPARE(w.featurePanel()->startDiameterBox()->value(), 40.0);
        QCOMPARE(w.document()->undoStack()->count(), 0);
    }
};

QTEST_MAIN(TestFeaturePanel)
#include "tst_feature_panel.moc"
