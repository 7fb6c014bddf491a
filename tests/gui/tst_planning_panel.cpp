// SPDX-License-Identifier: GPL-3.0-or-later
// The planning panel offscreen: the optimisation runs off the GUI thread and fills the plan, the
// window map, the clamping ranking; applying the plan is undoable; constraints switch on and off;
// G-code preview and export. With TOLTURN_SCREENSHOTS=DIR the window is saved as DIR/planning.png.
#include "tests/gui/screenshot.h"

#include "app/gui/main_window.h"
#include "widgets/document/project_document.h"
#include "widgets/planning/planning_panel.h"
#include "widgets/plot/map_plot.h"

#include <QAbstractItemModelTester>
#include <QCheckBox>
#include <QDockWidget>
#include <QFile>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace tolturn;

namespace {

QString example(const char *name)
{
    return QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/") + QString::fromLatin1(name);
}

} // namespace

using tolturn::test::saveScreenshot;

class TestPlanningPanel : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("TolTurnTest"));
    }

    void optimisationFillsTheViews()
    {
        MainWindow w;
        w.resize(1500, 950);
        w.show();
        QVERIFY(w.fileController()->openFile(example("long-shaft-centres.tolturn")));
        PlanningPanel *panel = w.planningPanel();
        // The tables' models are checked through every fill the run makes.
        const QAbstractItemModelTester clampingModel(panel->clampingTable()->model(),
                                                     QAbstractItemModelTester::FailureReportingMode::QtTest);
        const QAbstractItemModelTester compensationModel(panel->compensationTable()->model(),
                                                         QAbstractItemModelTester::FailureReportingMode::QtTest);
        QSignalSpy finished(panel, &PlanningPanel::finished);
        panel->optimise();
        QVERIFY(panel->isRunning() || finished.count() == 1);
        QVERIFY(finished.count() == 1 || finished.wait(60000));
        QVERIFY(panel->report() != nullptr);
        QVERIFY(panel->report()->plan.feasible);
        QVERIFY(panel->planText().contains(QStringLiteral("Binding: tolerance T4")));
        QVERIFY(panel->windowPlot()->labelCount() >= 1);
        QCOMPARE(panel->clampingTable()->rowCount(), 3);
        QCOMPARE(panel->clampingTable()->item(0, 1)->text(), QStringLiteral("chuck + tailstock"));
        QVERIFY(panel->compensationTable()->rowCount() >= 5);
        QVERIFY(panel->gcodeText().contains(QStringLiteral("G96 S230 M03")));

        // Show the window map for the screenshot.
        panel->findChild<QTabWidget *>()->setCurrentIndex(1);
        w.findChild<QDockWidget *>(QStringLiteral("planningDock"))->raise();
        QTest::qWait(50);
        saveScreenshot(w, "planning.png");

        // Apply the optimal passes, undo them.
        ProjectDocument *doc = w.document();
        const std::vector<CuttingPass> before = doc->project().passes;
        panel->applyPlan();
        QVERIFY(doc->project().passes != before);
        QCOMPARE(doc->project().passes.back().feed_mm_rev, panel->report()->plan.candidate.finishing.feed_mm_rev);
        doc->undoStack()->undo();
        QVERIFY(doc->project().passes == before);
    }

    void constraintSwitchesEditThePlanningSettings()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        QCheckBox *roughness = nullptr;
        for (QCheckBox *box : w.planningPanel()->findChildren<QCheckBox *>()) {
            if (box->property("constraint").toString() == QLatin1String("roughness"))
                roughness = box;
        }
        QVERIFY(roughness != nullptr);
        if (roughness == nullptr)
            return; // QVERIFY has returned already; this tells the static analyser so
        QVERIFY(roughness->isChecked());
        roughness->setChecked(false);
        QCOMPARE(w.document()->project().planning.disabledConstraints, QStringList{QStringLiteral("roughness")});
        w.document()->undoStack()->undo();
        QVERIFY(w.document()->project().planning.disabledConstraints.isEmpty());
        QVERIFY(roughness->isChecked());
    }

    void cancelStopsTheRun()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        PlanningPanel *panel = w.planningPanel();
        // The tables' models are checked through every fill the run makes.
        const QAbstractItemModelTester clampingModel(panel->clampingTable()->model(),
                                                     QAbstractItemModelTester::FailureReportingMode::QtTest);
        const QAbstractItemModelTester compensationModel(panel->compensationTable()->model(),
                                                         QAbstractItemModelTester::FailureReportingMode::QtTest);
        QSignalSpy finished(panel, &PlanningPanel::finished);
        panel->optimise();
        panel->cancel();
        QVERIFY(finished.count() == 1 || finished.wait(60000));
        QVERIFY(!panel->isRunning());
    }

    void exportWritesThePreview()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("finish.nc"));
        QVERIFY(w.planningPanel()->exportGCode(path).isEmpty());
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(QString::fromUtf8(file.readAll()), w.planningPanel()->gcodeText());
        QVERIFY(!w.planningPanel()->exportGCode(QStringLiteral("/nonexistent-folder/x.nc")).isEmpty());
    }
};

QTEST_MAIN(TestPlanningPanel)
#include "tst_planning_panel.moc"
