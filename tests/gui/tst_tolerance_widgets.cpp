// SPDX-License-Identifier: GPL-3.0-or-later
// Tolerances in the desktop program, offscreen: the verdict model, undoable edits that change the
// verdicts, the tolerance dialog's live ISO 286 limits and its refusals, feature selection.
#include "tests/examples.h"
#include "tests/gui/screenshot.h"

#include "app/gui/main_window.h"
#include "core/common/csv.h"
#include "core/io/project_file.h"
#include "widgets/document/project_document.h"
#include "widgets/profile/profile_scene.h"
#include "widgets/profile/profile_view.h"
#include "widgets/tolerances/tolerance_dialog.h"
#include "widgets/tolerances/tolerance_panel.h"
#include "widgets/tolerances/tolerance_verdict_model.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QGraphicsItem>
#include <QGraphicsScene>
#include <QLabel>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QTest>
#include <QUndoStack>

using namespace tolturn;

namespace {

using tolturn::test::example;

int rowOf(const ToleranceVerdictModel *model, const QString &id)
{
    for (int row = 0; row < model->rowCount(); ++row) {
        if (model->index(row, ToleranceVerdictModel::Id).data().toString() == id)
            return row;
    }
    return -1;
}

} // namespace

class TestToleranceWidgets : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("TolTurnTest"));
    }

    // The verdict table goes to the clipboard as CSV: headers with units, one line per tolerance,
    // fields with commas quoted (RFC 4180).
    void verdictTableCopiesAsCsv()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        QAction *copy = nullptr;
        const QList<QAction *> actions = w.tolerancePanel()->table()->actions();
        for (QAction *a : actions)
            copy = a->shortcut() == QKeySequence(QKeySequence::Copy) ? a : copy;
        if (copy == nullptr)
            QFAIL("the table has no Copy action");
        copy->trigger();
        const QStringList lines = QApplication::clipboard()->text().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1 + 8); // the example's eight tolerances
        QCOMPARE(lines.constFirst(), QString::fromUtf8("ID,Characteristic,Feature,Specification,Verdict,On the "
                                                       "machine range,Stiffness needed,Predicted [µm],Limit [µm],"
                                                       "Utilisation"));
        QVERIFY(lines.at(1).startsWith(QStringLiteral("T1,diameter,O4,h6,")));
        QCOMPARE(csvField(QStringLiteral("8 µm | A")), QString::fromUtf8("8 µm | A"));
        QCOMPARE(csvField(QStringLiteral("a,\"b\"")), QStringLiteral("\"a,\"\"b\"\"\""));
    }

    // The stepped shaft's machine is not measured: a banner above the verdicts says so, and each
    // row reads the verdict over the chuck's range with the stiffness it needs. The sleeve's
    // tailstock has no published stiffness: the banner is the warning colour and names it.
    void machineRangeIsShownWithTheVerdicts()
    {
        MainWindow w;
        w.show();
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        TolerancePanel *panel = w.tolerancePanel();
        QVERIFY(panel->banner()->isVisible());
        QVERIFY(panel->banner()->text().contains(QStringLiteral("66–216 N/µm")));
        // The example's machine has no thermal characterisation: zero drift is said here too.
        QVERIFY(panel->banner()->text().contains(QStringLiteral("thermal drift not measured: taken as zero")));
        const ToleranceVerdictModel *m = panel->model();
        // T4, Ø40 g6 on the journal O6.
        QCOMPARE(m->index(3, ToleranceVerdictModel::RangeColumn).data().toString(),
                 QStringLiteral("passes on any machine in the range"));
        QVERIFY(
            m->index(3, ToleranceVerdictModel::RequiredColumn).data().toString().startsWith(QStringLiteral("chuck ")));
        QCOMPARE(m->index(3, ToleranceVerdictModel::RangeColumn).data(ToleranceVerdictModel::RangeVerdictRole).toInt(),
                 static_cast<int>(RangeVerdict::PassesOnAnyMachine));
        // T1, Ø50 h6 on the seat O4 that starts at the jaw face (z 35): the tool keeps 2 mm + r_e 0.8 mm
        // from the jaws, and the program leaves z 35.000–37.750 mm of it (sampled every 0.05 mm).
        QCOMPARE(m->index(0, ToleranceVerdictModel::RangeColumn).data().toString(),
                 QStringLiteral("not finished by the program: z 35.000–37.750 mm of O4"));
        QCOMPARE(m->index(0, ToleranceVerdictModel::RangeColumn).data(ToleranceVerdictModel::RangeVerdictRole).toInt(),
                 static_cast<int>(RangeVerdict::NotFinished));
        QVERIFY(!panel->banner()->styleSheet().contains(QStringLiteral("#fde3c8")));

        QVERIFY(w.fileController()->openFile(example("hollow-sleeve-tailstock.tolturn")));
        QVERIFY(panel->banner()->text().contains(QStringLiteral("tailstock")));
        QVERIFY(panel->banner()->styleSheet().contains(QStringLiteral("#fde3c8")));
        QVERIFY( // T6, the size of O6, turned whole
            m->index(5, ToleranceVerdictModel::RequiredColumn).data().toString().contains(QStringLiteral("tailstock")));

        // The slender pin at a planner's catalogue conditions: its cylindricity fails on every machine
        // on what the program turns (its seat O4 also starts at the jaw face).
        QVERIFY(w.fileController()->openFile(example("slender-pin-chuck.tolturn")));
        QVERIFY(m->index(1, ToleranceVerdictModel::VerdictColumn)
                    .data(Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral(
                        "on what it turns: fails as programmed even on the stiffest machine of the range")));
        QTest::qWait(50);
        tolturn::test::saveScreenshot(w, "verdicts-range.png");
    }

    // At the default window size no verdict text is elided: every cell of the verdict, range and
    // stiffness columns is as wide as its text, for every example.
    void verdictTextsAreNeverElided()
    {
        MainWindow w;
        w.resize(1600, 1000);
        w.show();
        QTableView *table = w.tolerancePanel()->table();
        for (const char *file : {"stepped-shaft-chuck.tolturn", "hollow-sleeve-tailstock.tolturn",
                                 "long-shaft-centres.tolturn", "slender-pin-chuck.tolturn"}) {
            QVERIFY(w.fileController()->openFile(example(file)));
            const QFontMetrics metrics(table->font());
            for (const int column : {int(ToleranceVerdictModel::VerdictColumn), int(ToleranceVerdictModel::RangeColumn),
                                     int(ToleranceVerdictModel::RequiredColumn)}) {
                for (int row = 0; row < table->model()->rowCount(); ++row) {
                    const QString text = table->model()->index(row, column).data().toString();
                    QVERIFY2(table->columnWidth(column) >= metrics.horizontalAdvance(text),
                             qPrintable(QStringLiteral("%1 row %2: '%3' in %4 px")
                                            .arg(QString::fromLatin1(file))
                                            .arg(row)
                                            .arg(text)
                                            .arg(table->columnWidth(column))));
                }
            }
        }
    }

    void verdictModelIsAProperModel()
    {
        MainWindow w;
        ToleranceVerdictModel *model = w.tolerancePanel()->model();
        QAbstractItemModelTester tester(model, QAbstractItemModelTester::FailureReportingMode::QtTest);
        QVERIFY(w.fileController()->openFile(example("hollow-sleeve-tailstock.tolturn")));
        QCOMPARE(model->rowCount(), 9);
        QCOMPARE(model->columnCount(), int(ToleranceVerdictModel::ColumnCount));
        const int coaxiality = rowOf(model, QStringLiteral("T5"));
        QCOMPARE(model->index(coaxiality, ToleranceVerdictModel::VerdictColumn).data().toString(),
                 QStringLiteral("not predicted by this model"));
        QVERIFY(model->index(coaxiality, 0).data(Qt::ToolTipRole).toString().contains(QStringLiteral("§V.H")));
        QCOMPARE(
            model->index(coaxiality, ToleranceVerdictModel::VerdictColumn).data(Qt::BackgroundRole).value<QColor>(),
            ToleranceVerdictModel::verdictColor(Verdict::NotPredicted));
        QVERIFY(
            model->index(0, ToleranceVerdictModel::Utilisation).data(ToleranceVerdictModel::UtilisationRole).isValid());
        QVERIFY(w.fileController()->openFile(example("long-shaft-centres.tolturn"))); // model reset under the tester
        // Centres with no published range: the range column has no colour of its own (an invalid
        // colour would be painted black, hiding the text).
        for (int row = 0; row < model->rowCount(); ++row) {
            const QVariant background = model->index(row, ToleranceVerdictModel::RangeColumn).data(Qt::BackgroundRole);
            QVERIFY(!background.isValid() || background.value<QColor>().isValid());
        }
        QCOMPARE(model->rowCount(), 6);
    }

    // A cylindricity of 0.0001 µm on O4 cannot hold: the verdict table shows "needs a profile
    // correction"; undo removes it, redo brings it back; the document is modified until undone.
    void assignedToleranceChangesTheVerdicts()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        ProjectDocument *doc = w.document();
        ToleranceVerdictModel *model = w.tolerancePanel()->model();
        QCOMPARE(model->rowCount(), 8);
        Tolerance t;
        t.id = doc->nextToleranceId();
        QCOMPARE(t.id, QStringLiteral("T9"));
        t.type = ToleranceType::Cylindricity;
        t.featureId = QStringLiteral("O6"); // the Ø40 journal, turned whole
        t.zone_um = 0.0001;
        QVERIFY(doc->addTolerance(t).empty());
        QVERIFY(doc->isModified());
        QCOMPARE(model->rowCount(), 9);
        const int row = rowOf(model, QStringLiteral("T9"));
        QCOMPARE(
            model->index(row, ToleranceVerdictModel::VerdictColumn).data(ToleranceVerdictModel::VerdictRole).toInt(),
            int(Verdict::NeedsProfileCorrection));
        doc->undoStack()->undo();
        QCOMPARE(model->rowCount(), 8);
        QVERIFY(!doc->isModified());
        doc->undoStack()->redo();
        QCOMPARE(model->rowCount(), 9);

        // Loosen it to 8 µm: passes.
        t.zone_um = 8.0;
        QVERIFY(doc->replaceTolerance(8, t).empty());
        QCOMPARE(model->index(8, ToleranceVerdictModel::VerdictColumn).data(ToleranceVerdictModel::VerdictRole).toInt(),
                 int(Verdict::PassesAsProgrammed));
        QVERIFY(doc->removeTolerance(8).empty());
        QCOMPARE(model->rowCount(), 8);
    }

    void invalidEditChangesNothing()
    {
        ProjectDocument doc;
        const ProjectParseResult read = readProjectFile(example("stepped-shaft-chuck.tolturn"));
        doc.load(*read.project, QString());
        Tolerance t;
        t.id = QStringLiteral("T9");
        t.type = ToleranceType::Perpendicularity;
        t.featureId = QStringLiteral("O8");
        t.zone_um = 10.0; // no datum
        const Diagnostics problems = doc.addTolerance(t);
        QCOMPARE(int(problems.size()), 1);
        QVERIFY(problems.front().message.contains(QStringLiteral("relative to a datum")));
        QCOMPARE(int(doc.project().tolerances.size()), 8);
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(!doc.setDatum({QStringLiteral("a"), QStringLiteral("O4")}).empty()); // not a capital letter
        QVERIFY(doc.setDatum({QStringLiteral("B"), QStringLiteral("O9")}).empty());
        QCOMPARE(int(doc.project().datums.size()), 2);
    }

    // The ISO 286 picker on the Ø50 bearing seat O4: h6 is 0/-16 µm (ISO 286-2 Table 2), H7 is a
    // hole class and refused on an outer surface, an unknown letter shows its error as typed, and a
    // class that shares no size with the seat's own h6 is refused.
    void dialogShowsLimitsLiveAndRefusesWhatIsWrong()
    {
        const ProjectParseResult read = readProjectFile(example("stepped-shaft-chuck.tolturn"));
        QVERIFY(read.project);
        Project project = *read.project;
        Tolerance applied;
        int calls = 0;
        auto apply = [&](const Tolerance &t) {
            ++calls;
            Project candidate = project;
            candidate.tolerances.push_back(t);
            ProjectDocument doc;
            doc.load(project, QString());
            Diagnostics d = doc.addTolerance(t);
            if (d.empty())
                applied = t;
            return d;
        };
        Tolerance initial;
        initial.id = QStringLiteral("T9");
        ToleranceDialog dialog(project, QStringLiteral("O4"), initial, apply);
        dialog.setCharacteristic(ToleranceType::Diameter);
        dialog.setIsoClass(QStringLiteral("h6"));
        QVERIFY2(dialog.limitsText().contains(QStringLiteral("upper 0 µm, lower -16 µm (IT6 = 16 µm)")),
                 qPrintable(dialog.limitsText()));
        dialog.setIsoClass(QStringLiteral("q6"));
        QVERIFY2(dialog.limitsText().contains(QStringLiteral("q6")), qPrintable(dialog.limitsText()));
        dialog.setIsoClass(QStringLiteral("H7"));
        QVERIFY(!dialog.tryAccept());
        QVERIFY(dialog.problemsText().contains(QStringLiteral("'H7' is a hole class")));
        // k6 (+2/+18 µm) shares no size with the seat's h6 (0/-16 µm): refused, named; h7 (0/-25) does.
        dialog.setIsoClass(QStringLiteral("k6"));
        QVERIFY(!dialog.tryAccept());
        QVERIFY2(dialog.problemsText().contains(QStringLiteral("feature O4 allow no common size")),
                 qPrintable(dialog.problemsText()));
        dialog.setIsoClass(QStringLiteral("h7"));
        QVERIFY(dialog.tryAccept());
        QCOMPARE(applied.iso286Class, QStringLiteral("h7"));
        QCOMPARE(applied.featureId, QStringLiteral("O4"));
        QCOMPARE(calls, 3);

        ToleranceDialog geometric(project, QStringLiteral("O4"), initial, apply);
        geometric.setCharacteristic(ToleranceType::TotalRadialRunout);
        geometric.setZone(12.5, QStringLiteral("a"));
        QVERIFY(geometric.tryAccept());
        QCOMPARE(applied.zone_um.value(), 12.5);
        QCOMPARE(applied.datums, QStringList{QStringLiteral("A")});
    }

    // Clicking near a feature in the drawing selects it and enables "Add" for it.
    void selectingAFeatureInTheDrawing()
    {
        MainWindow w;
        w.show();
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        ProfileView *view = w.profileView();
        QSignalSpy spy(view, &ProfileView::featureSelected);
        // The middle of O4 (z = 57.5, r = 25) in the upper half: scene point (57.5, -25).
        const QPoint onO4 = view->mapFromScene(QPointF(57.5, -25.0));
        QCOMPARE(view->featureAt(onO4), QStringLiteral("O4"));
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, onO4);
        QCOMPARE(view->selectedFeature(), QStringLiteral("O4"));
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.takeFirst().at(0).toString(), QStringLiteral("O4"));
        // Far from every line: nothing.
        QVERIFY(view->featureAt(view->mapFromScene(QPointF(57.5, -12.0))).isEmpty());
    }
};

QTEST_MAIN(TestToleranceWidgets)
#include "tst_tolerance_widgets.moc"
