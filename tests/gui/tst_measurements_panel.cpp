// SPDX-License-Identifier: GPL-3.0-or-later
// The Measurements dock (docs/learning.md): listing, filtering and removing stored parts in the
// background, typing a part in (bad cells named by row and column), learning with progress and
// cancel, the window's verdicts and curves with what was learned, an unreachable shop database.
// With TOLTURN_SCREENSHOTS=DIR the window with the dock is saved as DIR/measurements.png.
#include "tests/examples.h"
#include "tests/gui/screenshot.h"

#include "app/gui/main_window.h"
#include "core/data/data_library.h"
#include "core/deviation/deviation_model.h"
#include "core/io/project_file.h"
#include "core/io/project_json.h"
#include "core/learning/machine_learning.h"
#include "core/measurements/measurement_store.h"
#include "core/tolerance/target_contour.h"
#include "widgets/document/project_document.h"
#include "widgets/measurements/measured_parts_model.h"
#include "widgets/measurements/measurement_entry_dialog.h"
#include "widgets/measurements/measurements_panel.h"
#include "widgets/planning/planning_panel.h"
#include "widgets/plot/line_plot.h"
#include "widgets/results/deflection_panel.h"
#include "widgets/tolerances/tolerance_panel.h"
#include "widgets/tolerances/tolerance_verdict_model.h"

#include <QDockWidget>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace tolturn;
using tolturn::test::saveScreenshot;

namespace {

constexpr int kWait_ms = 60000;

using tolturn::test::example;

Project steppedShaft()
{
    return *readProjectFile(example("stepped-shaft-chuck.tolturn")).project;
}

// A part of the stepped shaft as a machine that cuts `offset_mm` large on the radius everywhere
// would make it: the physics' prediction plus the offset at every fifth station of its cylinders.
MeasuredPart offsetPart(const Project &p, double offset_mm, const QString &by, int index)
{
    const DeviationResult physics = computeDeviation(p, DataLibrary::builtIn(), {});
    const ProgramTargets targets = programTargets(p);
    MeasuredPart part;
    part.machineId = p.machineId;
    part.measuredAt = QDateTime(QDate(2026, 11, 2), QTime(8 + index, 0), Qt::UTC);
    part.measuredBy = by;
    part.method = QStringLiteral("micrometer");
    part.timeSinceStart_min = 30.0 * index;
    part.ambient_C = 19.0 + index;
    part.projectJson = serializeProjectJson(p);
    for (const FeatureDeviation &f : physics.features) {
        if (f.kind != SegmentKind::Cylinder)
            continue;
        for (std::size_t i = 0; i < f.stations.size(); i += 5) {
            const Station &st = f.stations[i];
            const double target = *targetRadius_mm(targets.outer, f.featureId, st.z_mm);
            part.points.push_back(
                {f.featureId, st.z_mm, MeasuredQuantity::Diameter, 2.0 * (target + st.radiusError_mm + offset_mm)});
        }
    }
    return part;
}

} // namespace

class TestMeasurementsPanel : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

    StoreLocation store(const char *name) const
    {
        StoreLocation l;
        l.file = m_dir.filePath(QLatin1String(name));
        return l;
    }

    // Fills `location` with `count` parts of the stepped shaft cut 5 µm large on haas-st-20
    // (measured by Ada, the second by Ben), and one part on haas-st-30.
    static bool fillStore(const StoreLocation &location, int count)
    {
        QString error;
        auto s = MeasurementStore::open(location, &error);
        if (!s)
            return false;
        Project p = steppedShaft();
        Diagnostics problems;
        for (int i = 0; i < count; ++i) {
            if (!s->add(offsetPart(p, 0.005, i == 1 ? QStringLiteral("Ben") : QStringLiteral("Ada"), i), problems))
                return false;
        }
        p.machineId = QStringLiteral("haas-st-30");
        return s->add(offsetPart(p, 0.0, QStringLiteral("Cem"), 9), problems).has_value();
    }

    static bool waitFor(QSignalSpy &spy) { return !spy.isEmpty() || spy.wait(kWait_ms); }

private Q_SLOTS:

    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
    }

    void listsFiltersAndRemovesInTheBackground()
    {
        MeasurementsPanel panel;
        const Project project = steppedShaft();
        QSignalSpy listed(&panel, &MeasurementsPanel::listingFinished);
        const StoreLocation location = store("list.sqlite");
        QVERIFY(fillStore(location, 3));
        panel.setStoreLocation(location);
        panel.setProject(&project);
        // The listing runs in a worker: the call returns before the rows arrive.
        QCOMPARE(panel.partsModel()->rowCount(), 0);
        QTRY_COMPARE_WITH_TIMEOUT(panel.partsModel()->rowCount(), 3, kWait_ms);
        QVERIFY2(panel.statusText().contains(QStringLiteral("3 measured part")) &&
                     panel.statusText().contains(QStringLiteral("of haas-st-20")),
                 qPrintable(panel.statusText()));
        panel.setAllMachines(true);
        QTRY_COMPARE_WITH_TIMEOUT(panel.partsModel()->rowCount(), 4, kWait_ms);
        panel.setFilterText(QStringLiteral("bEn"));
        QTRY_COMPARE_WITH_TIMEOUT(panel.partsModel()->rowCount(), 1, kWait_ms);
        const qint64 ben = panel.partsModel()->partAt(0)->id;
        QCOMPARE(panel.partsModel()->partAt(0)->measuredBy, QStringLiteral("Ben"));
        QSignalSpy done(&panel, &MeasurementsPanel::operationFinished);
        panel.removeParts({ben});
        QVERIFY(waitFor(done));
        QVERIFY2(done.first().at(0).toBool(), qPrintable(done.first().at(1).toString()));
        QTRY_COMPARE_WITH_TIMEOUT(panel.partsModel()->rowCount(), 0, kWait_ms);
        // The store itself, on a connection of this thread: Ben's part is gone, the rest kept.
        QString error;
        auto s = MeasurementStore::open(panel.storeLocation(), &error);
        QVERIFY2(s, qPrintable(error));
        QCOMPARE(s->count({}, &error).value_or(-1), 3);
        QVERIFY(!s->part(ben, &error));
    }

    void typedPartNamesBadCellsAndIsStored()
    {
        const Project project = steppedShaft();
        MeasurementEntryDialog dialog(project, QStringLiteral("Ada"));
        // O4 is the bearing seat, z 35–80 mm: z = 120 mm is not on it.
        dialog.addPoint(QStringLiteral("O4"), 50.0, MeasuredQuantity::Diameter, 50.004);
        dialog.addPoint(QStringLiteral("O4"), 120.0, MeasuredQuantity::Diameter, 50.004);
        dialog.addPoint(QStringLiteral("O6"), 100.0, MeasuredQuantity::RadialDeviation, 3.0);
        QCOMPARE(dialog.table()->rowCount(), 3);
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Rejected)); // still open
        QVERIFY2(dialog.problemsText().contains(QStringLiteral("row 2, z")), qPrintable(dialog.problemsText()));
        QVERIFY2(!dialog.problemsText().contains(QStringLiteral("row 1")), qPrintable(dialog.problemsText()));
        dialog.table()->item(1, MeasurementEntryDialog::Z)->setText(QStringLiteral("60"));
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        const MeasuredPart part = dialog.part();
        QCOMPARE(part.points.size(), std::size_t(3));
        QCOMPARE(part.points[2].quantity, MeasuredQuantity::RadialDeviation);
        QCOMPARE(part.points[2].value_mm, 0.003); // typed in µm, kept in mm
        QCOMPARE(part.machineId, project.machineId);
        QCOMPARE(*parseProjectJson(part.projectJson).project, project);
        // A part the store refused comes back into a new dialog whole.
        MeasurementEntryDialog again(project, QString());
        again.setPart(part);
        QCOMPARE(again.part().points, part.points);
        QCOMPARE(again.part().measuredBy, QStringLiteral("Ada"));
        // A CMM point typed as "x; y": its radius √(12² + 16²) = 20 mm on the Ø40 seat O6.
        dialog.addCmmPoint(QStringLiteral("O6"), 12.0, 16.0, 105.0);
        QCOMPARE(dialog.table()->item(3, MeasurementEntryDialog::Value)->text(), QStringLiteral("12; 16"));
        const MeasuredPart withCmm = dialog.part();
        QCOMPARE(withCmm.points.size(), std::size_t(4));
        QCOMPARE(withCmm.points[3].quantity, MeasuredQuantity::CmmPoint);
        QCOMPARE(withCmm.points[3].value_mm, 20.0);
        dialog.table()->item(3, MeasurementEntryDialog::Value)->setText(QStringLiteral("12"));
        dialog.accept();
        QVERIFY2(dialog.problemsText().contains(QStringLiteral("row 4, value")), qPrintable(dialog.problemsText()));
        dialog.table()->removeRow(3);

        // A CSV with a bad cell: named by line and column, the table unchanged.
        const QString csv = m_dir.filePath(QStringLiteral("bad.csv"));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("feature,z_mm,diameter_mm\nO4,50,50.004\nO4,fifty,50.004\n");
        file.close();
        QVERIFY(!dialog.readCsv(csv));
        QVERIFY2(dialog.problemsText().contains(QStringLiteral("bad.csv:3: z_mm")) &&
                     dialog.problemsText().contains(QStringLiteral("\"fifty\"")),
                 qPrintable(dialog.problemsText()));
        QCOMPARE(dialog.table()->rowCount(), 3);

        MeasurementsPanel panel;
        panel.setStoreLocation(store("typed.sqlite"));
        panel.setProject(&project);
        QSignalSpy done(&panel, &MeasurementsPanel::operationFinished);
        panel.addPart(part);
        QVERIFY(waitFor(done));
        QVERIFY2(done.first().at(0).toBool(), qPrintable(done.first().at(1).toString()));
        QTRY_COMPARE_WITH_TIMEOUT(panel.partsModel()->rowCount(), 1, kWait_ms);
        QCOMPARE(panel.partsModel()->partAt(0)->pointCount, 3);
    }

    // Parts cut 5 µm large: learning runs in the background, and the parts left out are
    // predicted by the physics alone to 5 µm RMS and with what was learned to almost nothing.
    void learnsInTheBackgroundAndCancels()
    {
        MeasurementsPanel panel;
        const Project project = steppedShaft();
        const StoreLocation location = store("learn.sqlite");
        QVERIFY(fillStore(location, 5));
        panel.setStoreLocation(location);
        panel.setProject(&project);
        QSignalSpy learned(&panel, &MeasurementsPanel::learningFinished);
        panel.learn();
        // Returned at once, the work in a worker thread: nothing finished yet.
        QVERIFY(panel.isLearning());
        QCOMPARE(learned.count(), 0);
        panel.cancelLearning();
        QVERIFY(waitFor(learned));
        QCOMPARE(learned.first().at(0).toBool(), false);
        QVERIFY2(learned.first().at(1).toString().contains(QStringLiteral("cancelled")),
                 qPrintable(learned.first().at(1).toString()));
        QVERIFY(!panel.model());
        learned.clear();
        panel.learn();
        QVERIFY(waitFor(learned));
        QVERIFY2(learned.first().at(0).toBool(), qPrintable(learned.first().at(1).toString()));
        QVERIFY(panel.model());
        QCOMPARE(panel.model()->record.parts, 5);
        QVERIFY2(std::abs(panel.model()->record.physicsRms_mm - 0.005) < 1e-9,
                 qPrintable(QString::number(panel.model()->record.physicsRms_mm)));
        QVERIFY(panel.model()->record.learnedRms_mm < 1e-4);
        QVERIFY2(panel.modelText().contains(QStringLiteral("physics alone 5.0 µm RMS")), qPrintable(panel.modelText()));
        // And where it holds: every part cut at the stepped shaft's finishing feed.
        QVERIFY2(panel.modelText().contains(QStringLiteral("Learned at spindle speed")) &&
                     panel.modelText().contains(QStringLiteral("feed 0.100–0.100 mm/rev")),
                 qPrintable(panel.modelText()));
        // A part against the predictions: its points, the physics and physics + learned.
        QSignalSpy shown(&panel, &MeasurementsPanel::comparisonShown);
        panel.comparePart(1);
        QVERIFY(waitFor(shown));
        QVERIFY(shown.first().at(0).toBool());
        QStringList curves;
        for (int i = 0; i < panel.plot()->curveCount(); ++i)
            curves << panel.plot()->curveName(i);
        QVERIFY2(curves.contains(QStringLiteral("measured")) && curves.contains(QStringLiteral("physics")) &&
                     curves.contains(QStringLiteral("physics + learned")),
                 qPrintable(curves.join(QStringLiteral(", "))));
    }

    // The window with what was learned switched on: every predicted diameter 10 µm larger than
    // with the physics alone (5 µm on the radius), the banner names the model, the curves show it,
    // and the planner plans with it.
    void windowPredictsWithWhatWasLearned()
    {
        const StoreLocation location = store("window.sqlite");
        QVERIFY(fillStore(location, 4));
        {
            QString error;
            auto s = MeasurementStore::open(location, &error);
            const auto parts = storedPartsOf(*s, QStringLiteral("haas-st-20"), &error);
            const MachineLearning run = learnMachine(*parts, DataLibrary::builtIn(), {});
            QVERIFY2(run.ok(), qPrintable(run.error));
            QVERIFY(s->addLearnedModel(learnedModelRecord(QStringLiteral("haas-st-20"), run), &error));
        }
        MainWindow w;
        w.resize(1600, 1000);
        w.show();
        MeasurementsPanel &panel = *w.measurementsPanel();
        panel.setStoreLocation(location);
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        QTRY_VERIFY_WITH_TIMEOUT(panel.model() != nullptr, kWait_ms);
        const ToleranceVerdictModel &verdicts = *w.tolerancePanel()->model();
        auto diameterMax = [&verdicts](const char *id) {
            for (int row = 0; row < verdicts.rowCount(); ++row) {
                if (verdicts.verdict(row).toleranceId == QLatin1String(id))
                    return verdicts.verdict(row).predictedMax_um.value_or(NAN);
            }
            return double(NAN);
        };
        const double physics = diameterMax("T1");
        QVERIFY(std::isfinite(physics));
        QVERIFY(!w.deflectionPanel()->learned());
        panel.setUseLearned(true);
        QVERIFY2(std::abs(diameterMax("T1") - physics - 10.0) < 0.2,
                 qPrintable(QStringLiteral("%1 %2").arg(diameterMax("T1")).arg(physics)));
        QVERIFY2(w.tolerancePanel()->banner()->text().contains(QStringLiteral("learned from its measured parts")),
                 qPrintable(w.tolerancePanel()->banner()->text()));
        QVERIFY(w.deflectionPanel()->learned());
        QVERIFY(!w.deflectionPanel()->stiffEnd()); // the learned machine replaces the range
        bool curve = false;
        for (int i = 0; i < w.deflectionPanel()->plot()->curveCount(); ++i)
            curve = curve || w.deflectionPanel()->plot()->curveName(i) == QLatin1String("total, physics + learned");
        QVERIFY(curve);
        QCOMPARE(w.planningPanel()->learnedModel(), panel.model());
        if (!qEnvironmentVariableIsEmpty("TOLTURN_SCREENSHOTS")) {
            panel.setProject(&w.document()->project());
            QTRY_VERIFY_WITH_TIMEOUT(panel.partsModel()->rowCount() == 4, kWait_ms);
            w.findChild<QDockWidget *>(QStringLiteral("measurementsDock"))->raise();
            QSignalSpy shown(&panel, &MeasurementsPanel::comparisonShown);
            panel.comparePart(panel.partsModel()->partAt(0)->id);
            QVERIFY(waitFor(shown));
            QTest::qWait(200);
            saveScreenshot(w, "measurements.png");
        }
        // Switched off: the physics and the stiffness range again.
        panel.setUseLearned(false);
        QCOMPARE(diameterMax("T1"), physics);
        QVERIFY(!w.planningPanel()->learnedModel());
    }

    // A shop database that cannot be reached: named by its address, and the local store offered.
    void unreachableShopDatabaseOffersTheLocalStore()
    {
        MeasurementsPanel panel;
        StoreLocation shop;
        shop.kind = StoreLocation::Kind::PostgreSQL;
        shop.host = m_dir.path(); // a socket folder with no server in it
        shop.port = 1;
        shop.database = QStringLiteral("shop");
        shop.user = QStringLiteral("planner");
        QSignalSpy listed(&panel, &MeasurementsPanel::listingFinished);
        panel.setStoreLocation(shop);
        QVERIFY(waitFor(listed));
        QCOMPARE(listed.first().at(0).toBool(), false);
        QVERIFY2(panel.statusText().contains(QStringLiteral("postgresql://planner@")), qPrintable(panel.statusText()));
        auto *useLocal = panel.findChild<QPushButton *>(QStringLiteral("useLocalStore"));
        QVERIFY(useLocal);
        QVERIFY(!useLocal->isHidden());
        listed.clear();
        useLocal->click();
        QVERIFY(waitFor(listed));
        QVERIFY(listed.first().at(0).toBool());
        QCOMPARE(panel.storeLocation().kind, StoreLocation::Kind::SQLite);
        QVERIFY(useLocal->isHidden());
    }
};

QTEST_MAIN(TestMeasurementsPanel)
#include "tst_measurements_panel.moc"
