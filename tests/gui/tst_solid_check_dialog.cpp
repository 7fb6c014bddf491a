// SPDX-License-Identifier: GPL-3.0-or-later
// Tools > Check with Solid FE…, offscreen, through gmsh and CalculiX on a coarse mesh: the table
// and the plot fill, the beam and the solid agree, a cancelled run and a missing engine are said in
// the dialog, closing it while it runs cancels, and the project is never changed. With
// TOLTURN_SCREENSHOTS=DIR the dialog with its results is saved as DIR/solid-check.png.
#include "tests/core/test_support.h"
#include "tests/examples.h"
#include "tests/gui/screenshot.h"

#include "app/gui/file_controller.h"
#include "app/gui/main_window.h"
#include "core/io/project_file.h"
#include "core/project/operations.h"
#include "widgets/common/length_spin_box.h"
#include "widgets/document/project_document.h"
#include "widgets/fe/solid_check_dialog.h"
#include "widgets/fe/solid_check_view.h"
#include "widgets/plot/line_plot.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QMenu>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>
#include <QTimer>

#include <cmath>
#include <set>

using namespace tolturn;

namespace {

constexpr int kRunTimeout_ms = 120000;
constexpr double kCoarseMesh_mm = 8.0;

using tolturn::test::example;

Project steppedShaft()
{
    ProjectParseResult read = readProjectFile(example("stepped-shaft-chuck.tolturn"));
    if (!read.project)
        qFatal("cannot read the stepped-shaft example");
    return *read.project;
}

// The diameters of the part's outer cylinders, in mm.
std::set<double> cylinderDiameters(const Project &project)
{
    std::set<double> out;
    for (const Segment &s : project.part.outer.segments)
        if (s.kind == SegmentKind::Cylinder)
            out.insert(2.0 * s.from.r_mm);
    return out;
}

double number(const QTableWidget &table, int row, int column)
{
    bool ok = false;
    const double v = table.item(row, column)->text().toDouble(&ok);
    if (!ok)
        qFatal("cell %d,%d is not a number: %s", row, column, qPrintable(table.item(row, column)->text()));
    return v;
}

// Half a unit of the last digit a cell shows: how far its rounding can be from the value.
double halfLastDigit(const QString &text)
{
    const qsizetype point = text.indexOf(QLatin1Char('.'));
    const qsizetype decimals = point < 0 ? 0 : text.size() - point - 1;
    return 0.5 * std::pow(10.0, -static_cast<double>(decimals));
}

void setCoarse(SolidCheckDialog &dialog, int stations)
{
    dialog.meshSizeBox()->setMillimetres(kCoarseMesh_mm);
    dialog.stationsBox()->setValue(stations);
}

// Runs the modal dialog once it is shown, on a coarse mesh, and closes it when the run ends.
void runInOpenDialog(int *rows)
{
    auto *dialog = qobject_cast<SolidCheckDialog *>(QApplication::activeModalWidget());
    if (dialog == nullptr) {
        QTimer::singleShot(10, [rows] { runInOpenDialog(rows); }); // not shown yet
        return;
    }
    setCoarse(*dialog, 2);
    QObject::connect(dialog, &SolidCheckDialog::checkFinished, dialog, [dialog, rows] {
        *rows = dialog->view()->table()->rowCount();
        dialog->reject();
    });
    dialog->run();
}

} // namespace

using tolturn::test::ScopedEnv;

class TestSolidCheckDialog : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("TolTurnTest"));
    }

    // The defaults: 5 stations, the core's default mesh size, one operation (no choice shown).
    void defaults()
    {
        const Project project = steppedShaft();
        SolidCheckDialog dialog(project);
        QCOMPARE(dialog.stationsBox()->value(), 5);
        QCOMPARE(dialog.stationsBox()->minimum(), 1);
        QCOMPARE(dialog.stationsBox()->maximum(), 50);
        QCOMPARE(dialog.meshSizeBox()->millimetres(), defaultMeshSize(project.part));
        QVERIFY(dialog.runButton()->isEnabled());
        QVERIFY(!dialog.cancelButton()->isEnabled());
        QVERIFY(!dialog.isRunning());
        QCOMPARE(dialog.view()->table()->rowCount(), 0);
        QVERIFY(dialog.size().width() >= 800 && dialog.size().height() >= 600);
    }

    // A project of two set-ups: the choice shown, on the set-up asked for, with its own default size.
    void operationChoice()
    {
        const Project project = *readProjectFile(example("bushing-two-setups.tolturn")).project;
        QCOMPARE(operationCount(project), 2);
        SolidCheckDialog single(steppedShaft());
        QVERIFY(!single.operationBox()->isVisibleTo(&single));
        SolidCheckDialog dialog(project, 1);
        QVERIFY(dialog.operationBox()->isVisibleTo(&dialog));
        QCOMPARE(dialog.operationBox()->count(), 2);
        QCOMPARE(dialog.operationBox()->currentIndex(), 1);
        QVERIFY(dialog.operationBox()->currentText().startsWith(operationName(project, 1)));
        QCOMPARE(dialog.meshSizeBox()->millimetres(), defaultMeshSize(operationView(project, 1).part));
        dialog.operationBox()->setCurrentIndex(0);
        QCOMPARE(dialog.meshSizeBox()->millimetres(), defaultMeshSize(operationView(project, 0).part));
    }

    // Three stations on a coarse mesh: a row each, z increasing, each at a diameter of the part,
    // beam and solid positive and within 30 % of each other (the beam's assumptions hold roughly
    // on a stepped shaft of L/D about 4: Timoshenko and Goodier, Theory of Elasticity, §21).
    void runFillsTheTableAndThePlot()
    {
        const Project project = steppedShaft();
        SolidCheckDialog dialog(project);
        dialog.show();
        setCoarse(dialog, 3);
        QTest::mouseClick(dialog.runButton(), Qt::LeftButton);
        QVERIFY(dialog.isRunning());
        QVERIFY(!dialog.runButton()->isEnabled());
        QVERIFY(dialog.cancelButton()->isEnabled());
        QStringList stages;
        QElapsedTimer clock;
        clock.start();
        while (dialog.isRunning() && clock.elapsed() < kRunTimeout_ms) {
            QTest::qWait(20);
            if (!stages.contains(dialog.progressText()))
                stages << dialog.progressText();
        }
        QVERIFY2(!dialog.isRunning(), "the check did not end in time");
        QVERIFY2(stages.join(QLatin1Char('\n')).contains(QStringLiteral("CalculiX")),
                 qPrintable(stages.join(QLatin1Char('\n'))));
        const QTableWidget &table = *dialog.view()->table();
        QTRY_VERIFY_WITH_TIMEOUT(table.rowCount() == 3, kRunTimeout_ms);
        QVERIFY2(dialog.messageText().contains(QStringLiteral("at most")), qPrintable(dialog.messageText()));
        const std::set<double> diameters = cylinderDiameters(project);
        for (int row = 0; row < table.rowCount(); ++row) {
            const double z = number(table, row, 0);
            QVERIFY(z > 0.0 && z < project.part.length_mm());
            if (row > 0)
                QVERIFY(z > number(table, row - 1, 0));
            QVERIFY2(diameters.count(number(table, row, 1)) == 1, qPrintable(table.item(row, 1)->text()));
            const double beam = number(table, row, 2);
            const double solid = number(table, row, 3);
            QVERIFY2(beam > 0.0 && solid > 0.0, qPrintable(QStringLiteral("%1 %2").arg(beam).arg(solid)));
            QVERIFY2(std::abs(beam - solid) <= 0.3 * solid, qPrintable(QStringLiteral("%1 %2").arg(beam).arg(solid)));
            // The difference column is (beam - solid) / solid, to the rounding of the cells.
            const double h = halfLastDigit(table.item(row, 2)->text());
            const double bound = 100.0 * h * (1.0 / solid + beam / (solid * solid)) * 1.01 + 0.05;
            QVERIFY2(std::abs(number(table, row, 4) - 100.0 * (beam - solid) / solid) <= bound,
                     qPrintable(table.item(row, 4)->text()));
            QVERIFY(number(table, row, 5) > 0.0 && number(table, row, 6) > 0.0);
            // Held in a chuck: the corrected beam is softer than plain Timoshenko (the root).
            QVERIFY2(number(table, row, 7) > 0.0 && number(table, row, 7) < beam,
                     qPrintable(table.item(row, 7)->text()));
        }
        QVERIFY(table.horizontalHeaderItem(2)->text().contains(QStringLiteral("µm")));
        LinePlot *plot = dialog.view()->plot();
        QVERIFY(plot->isVisible());
        QCOMPARE(plot->curveCount(), 3); // beam, beam without corrections, solid
        QVERIFY(plot->legendRect().width() >= plot->legendNeeds().width());
        const QString summary = dialog.view()->summaryText();
        QVERIFY2(summary.contains(QStringLiteral("8 mm")) && summary.contains(QStringLiteral("degrees of freedom")),
                 qPrintable(summary));
        QVERIFY(!dialog.view()->notesText().isEmpty());
        QVERIFY(dialog.runButton()->isEnabled());
        QVERIFY(!dialog.cancelButton()->isEnabled());
        test::saveScreenshot(dialog, "solid-check.png");
    }

    // Cancelled at once: said, no rows, ready to run again.
    void cancelRightAfterStart()
    {
        SolidCheckDialog dialog(steppedShaft());
        dialog.show();
        setCoarse(dialog, 3);
        QTest::mouseClick(dialog.runButton(), Qt::LeftButton);
        QTest::mouseClick(dialog.cancelButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog.isRunning(), kRunTimeout_ms);
        QVERIFY2(dialog.messageText().contains(QStringLiteral("cancelled")), qPrintable(dialog.messageText()));
        QCOMPARE(dialog.view()->table()->rowCount(), 0);
        QVERIFY(!dialog.view()->plot()->isVisible());
        QVERIFY(dialog.runButton()->isEnabled());
    }

    // gmsh not where TOLTURN_GMSH points: the dialog says so and how to install it.
    void missingGmshIsSaid()
    {
        const ScopedEnv missing("TOLTURN_GMSH", "/nonexistent/gmsh");
        SolidCheckDialog dialog(steppedShaft());
        dialog.show();
        setCoarse(dialog, 3);
        dialog.run();
        QTRY_VERIFY_WITH_TIMEOUT(!dialog.isRunning(), kRunTimeout_ms);
        const QString message = dialog.messageText();
        QVERIFY2(message.contains(QStringLiteral("gmsh")) && message.contains(QStringLiteral("apt install")),
                 qPrintable(message));
        QCOMPARE(dialog.view()->table()->rowCount(), 0);
    }

    // Closing the dialog while gmsh or CalculiX runs stops them and waits: at once, and no crash.
    void closingWhileRunningCancels()
    {
        auto dialog = std::make_unique<SolidCheckDialog>(steppedShaft());
        dialog->show();
        dialog->meshSizeBox()->setMillimetres(3.0); // seconds of work, at least
        dialog->stationsBox()->setValue(10);
        dialog->run();
        QTRY_VERIFY_WITH_TIMEOUT(dialog->progressText().contains(QStringLiteral("gmsh")) || !dialog->isRunning(),
                                 kRunTimeout_ms);
        QVERIFY(dialog->isRunning());
        QElapsedTimer clock;
        clock.start();
        dialog->reject();
        QVERIFY(!dialog->isVisible());
        QVERIFY2(clock.elapsed() < 5000, qPrintable(QString::number(clock.elapsed())));
        dialog.reset();
        QTest::qWait(50); // events posted for the dialog must not reach it
    }

    // Destroyed while it runs (its parent closed): the run is stopped and waited for.
    void destroyedWhileRunning()
    {
        auto dialog = std::make_unique<SolidCheckDialog>(steppedShaft());
        dialog->meshSizeBox()->setMillimetres(3.0);
        dialog->run();
        QTest::qWait(200);
        dialog.reset();
        QTest::qWait(50);
    }

    // From the window: Tools > Check with Solid FE… opens the dialog on the set-up shown; a run in
    // it leaves the document as it was.
    void windowOpensTheDialog()
    {
        MainWindow w;
        auto *action = w.findChild<QAction *>(QStringLiteral("solidCheckAction"));
        if (action == nullptr)
            QFAIL("no Check with Solid FE action");
        const auto *menu = qobject_cast<QMenu *>(action->associatedObjects().value(0));
        QVERIFY(menu != nullptr && menu->title() == QStringLiteral("&Tools"));
        QVERIFY(!action->isEnabled()); // no project
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        QVERIFY(action->isEnabled());
        const Project before = w.document()->project();
        int rows = -1;
        QTimer::singleShot(0, this, [&rows] { runInOpenDialog(&rows); });
        action->trigger();
        QCOMPARE(rows, 2);
        QVERIFY(w.document()->project() == before);
        QVERIFY(!w.document()->isModified());
    }
};

QTEST_MAIN(TestSolidCheckDialog)
#include "tst_solid_check_dialog.moc"
