// SPDX-License-Identifier: GPL-3.0-or-later
// The Milling dock (issue 19, docs/milling.md): what it asks for before it computes, the forces and
// surface error it shows, and the lead–tilt plan. The numbers are the model's, tested in
// tst_ball_end_forces and tst_ball_end_planning; here one of them is checked by hand through the
// dock, so that the dock shows the cut it was given.
#include "tests/gui/milled_features_fixture.h"
#include "tests/gui/screenshot.h"

#include "core/io/project_file.h"
#include "widgets/document/project_document.h"
#include "widgets/milling/milled_features_box.h"
#include "widgets/milling/milling_panel.h"
#include "widgets/plot/line_plot.h"
#include "widgets/plot/map_plot.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <numbers>

using namespace tolturn;

namespace {

// The stepped shaft with a flat and an imported keyway.
Project projectWithMilledFeatures()
{
    Project p =
        *readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/stepped-shaft-chuck.tolturn")).project;
    p.milledFeatures = test::flatAndImportedKeyway(QStringLiteral("test values"));
    return p;
}

} // namespace

class TestMillingPanel : public QObject {
    Q_OBJECT

private Q_SLOTS:

    // Without coefficients nothing is computed and the dock says why, naming the field; the plan
    // cannot start.
    void asksForTheCoefficients()
    {
        MillingPanel panel;
        QVERIFY2(panel.summary()->text().contains(QStringLiteral("Coefficients: not given")),
                 qPrintable(panel.summary()->text()));
        QCOMPARE(panel.forcePlot()->curveCount(), 0);
        QVERIFY(!panel.planButton()->isEnabled());
        panel.coefficients()->setText(QStringLiteral("1,2,3"));
        Q_EMIT panel.coefficients()->editingFinished();
        QVERIFY(panel.summary()->text().contains(QStringLiteral("is not six numbers")));
        // Two problems at once, one a line each: a 60° lead keeps a 3 mm cut off the ball.
        panel.lead()->setValue(60.0);
        const QString text = panel.summary()->text();
        QVERIFY2(text.contains(QStringLiteral("<br>axial depth: 3 mm is not within the ball")), qPrintable(text));
        QVERIFY(!text.contains(QStringLiteral("&lt;br&gt;")));
    }

    // 001 case 2 with K_tc = 1000 N/mm² only: the mean torque is K_tc f_t ∫₀³R dz / π =
    // 1000 · 0.1 · (6π − 1.5√27) / π = 351.9 N·mm (at any lead and tilt: tst_ball_end_forces), shown
    // as 0.352 N·m; its power at 269 1/min 9.9 W.
    void showsTheForcesOfTheCut()
    {
        MillingPanel panel;
        panel.loadCase(2);
        panel.coefficients()->setText(QStringLiteral("1000, 0, 0, 0, 0, 0"));
        Q_EMIT panel.coefficients()->editingFinished();
        QCOMPARE(panel.forcePlot()->curveCount(), 4);
        const double torque = 1000.0 * 0.1 * (6.0 * std::numbers::pi - 1.5 * std::sqrt(27.0)) / std::numbers::pi;
        QVERIFY2(panel.summary()->text().contains(QStringLiteral("mean torque %1 N·m").arg(torque / 1000.0, 0, 'f', 3)),
                 qPrintable(panel.summary()->text()));
        // No structure yet: no surface error, and the dock says which field is missing.
        QVERIFY2(panel.summary()->text().contains(QStringLiteral("give the tool's overhang")),
                 qPrintable(panel.summary()->text()));
        QVERIFY(!panel.planButton()->isEnabled());
    }

    // With the tool's structure the surface error is drawn with its zone and given a verdict; the
    // plan runs on a worker thread and draws the window with the plan's star.
    void plansLeadTiltAndFeed()
    {
        MillingPanel panel;
        panel.resize(1400, 560);
        panel.loadCase(1);
        panel.coefficients()->setText(QStringLiteral("2000, 700, 400, 25, 40, 8"));
        Q_EMIT panel.coefficients()->editingFinished();
        auto *overhang = panel.findChild<QDoubleSpinBox *>(QStringLiteral("millingOverhang"));
        auto *equivalent = panel.findChild<QDoubleSpinBox *>(QStringLiteral("millingEquivalentDiameter"));
        QVERIFY(overhang && equivalent);
        QCOMPARE(overhang->specialValueText(), QStringLiteral("not given"));
        overhang->setValue(40.0);
        equivalent->setValue(9.6);
        QCOMPARE(panel.errorPlot()->curveCount(), 3);
        QVERIFY2(panel.summary()->text().contains(QStringLiteral("passes")) ||
                     panel.summary()->text().contains(QStringLiteral("fails")),
                 qPrintable(panel.summary()->text()));
        QVERIFY(panel.planButton()->isEnabled());
        panel.show();
        panel.plots()->setCurrentIndex(0);
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        test::saveScreenshot(panel, "milling-forces.png");
        QSignalSpy finished(&panel, &MillingPanel::planFinished);
        panel.planButton()->click();
        QVERIFY(finished.wait(30000));
        QVERIFY(panel.lastPlan().has_value());
        QVERIFY(panel.lastPlan()->feasible);
        QVERIFY(panel.windowPlot()->markers().contains(QStringLiteral("plan")));
        QCOMPARE(panel.plots()->currentIndex(), 2);
        QVERIFY(panel.planButton()->isEnabled());
        test::saveScreenshot(panel, "milling-window.png");
        panel.plots()->setCurrentIndex(1);
        test::saveScreenshot(panel, "milling-error.png");
        // It fits the bottom dock of a 1366 × 768 screen (about 380 px high): the inputs scroll.
        QVERIFY2(
            panel.minimumSizeHint().height() <= 380 && panel.minimumSizeHint().width() <= 1366,
            qPrintable(
                QStringLiteral("%1 × %2").arg(panel.minimumSizeHint().width()).arg(panel.minimumSizeHint().height())));
        panel.resize(1366, 380);
        panel.plots()->setCurrentIndex(2);
        QTest::qWait(50);
        test::saveScreenshot(panel, "milling-dock-1366.png");
        // An edit after the plan says the plan is for the inputs before it.
        panel.lead()->setValue(5.0);
        const QLabel *planText = panel.findChild<QLabel *>(QStringLiteral("millingPlanSummary"));
        QVERIFY(planText);
        QVERIFY2(planText->text().contains(QStringLiteral("plan again")), qPrintable(planText->text()));
    }

    // The project's milled features in the dock: each with its verdict (the flat is evaluated, the
    // keyway named as lacking its inputs); a chosen one fills the fields and draws its error along
    // the path; the cut of the fields becomes a new feature, undoably; a cut the project refuses
    // (no overhang) is not added and the reason is shown.
    void featuresOfTheProject()
    {
        ProjectDocument document;
        document.load(projectWithMilledFeatures(), QString());
        MillingPanel panel(&document);
        panel.resize(1500, 620);
        MilledFeaturesBox *box = panel.features();
        QVERIFY(box);
        QSignalSpy evaluated(box, &MilledFeaturesBox::evaluated);
        QTRY_VERIFY_WITH_TIMEOUT(!evaluated.isEmpty(), 10000);
        QCOMPARE(box->table()->rowCount(), 2);
        const QString flatVerdict = box->table()->item(0, 4)->text();
        QVERIFY2(flatVerdict.startsWith(QStringLiteral("passes")) || flatVerdict.startsWith(QStringLiteral("fails")),
                 qPrintable(flatVerdict));
        QVERIFY2(box->table()->item(1, 4)->text().contains(QStringLiteral("lacks")),
                 qPrintable(box->table()->item(1, 4)->text()));

        box->table()->selectRow(0);
        QVERIFY2(panel.coefficients()->text().startsWith(QStringLiteral("2000")),
                 qPrintable(panel.coefficients()->text()));
        QCOMPARE(panel.lead()->value(), 10.0);
        QCOMPARE(panel.tolerance()->value(), 3.0);
        QCOMPARE(box->pathPlot()->curveCount(), 4); // the band's two edges and the zone's two limits
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        panel.plots()->setCurrentIndex(panel.plots()->count() - 1);
        test::saveScreenshot(panel, "milling-features.png");

        panel.tolerance()->setValue(50.0);
        box->addButton()->click();
        QCOMPARE(document.project().milledFeatures.size(), std::size_t{3});
        const MilledFeature &added = document.project().milledFeatures.back();
        QCOMPARE(added.id, QStringLiteral("M3"));
        QCOMPARE(added.tolerance->zone_um, 50.0);
        QCOMPARE(added.conditions->lead_deg, 10.0);
        QCOMPARE(added.coefficientsSource, QStringLiteral("test values"));
        QVERIFY(!added.tool->youngsModulus_N_mm2.has_value()); // carbide's, still an assumption
        QVERIFY(box->saveButton()->isEnabled());
        document.undoStack()->undo();
        QCOMPARE(document.project().milledFeatures.size(), std::size_t{2});

        auto *overhang = panel.findChild<QDoubleSpinBox *>(QStringLiteral("millingOverhang"));
        overhang->setValue(0.0);
        box->addButton()->click();
        QCOMPARE(document.project().milledFeatures.size(), std::size_t{2});
        QVERIFY2(panel.summary()->text().contains(QStringLiteral("overhang")), qPrintable(panel.summary()->text()));
        // A source without coefficients would be lost on saving: refused, named.
        overhang->setValue(40.0);
        panel.coefficients()->clear();
        box->addButton()->click();
        QCOMPARE(document.project().milledFeatures.size(), std::size_t{2});
        QVERIFY2(panel.summary()->text().contains(QStringLiteral("Coefficients from: &quot;test values&quot;")),
                 qPrintable(panel.summary()->text()));

        // A feature removed leaves nothing chosen, so no cut is saved to the one that takes its row;
        // the one still there stays chosen by its id after an edit that moves it.
        box->table()->selectRow(0);
        box->removeButton()->click();
        QCOMPARE(document.project().milledFeatures.size(), std::size_t{1});
        QCOMPARE(document.project().milledFeatures.front().id, QStringLiteral("M2"));
        QVERIFY(box->table()->selectedItems().isEmpty());
        QVERIFY(!box->saveButton()->isEnabled());
        box->table()->selectRow(0);
        document.undoStack()->undo(); // M1 back before M2
        QCOMPARE(box->table()->item(box->table()->selectedItems().constFirst()->row(), 0)->text(),
                 QStringLiteral("M2"));
    }
};

QTEST_MAIN(TestMillingPanel)
#include "tst_milling_panel.moc"
