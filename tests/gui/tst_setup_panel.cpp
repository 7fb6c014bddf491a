// SPDX-License-Identifier: GPL-3.0-or-later
// The Set-up dock driven as a user drives it: each change is one undoable edit, the deflection
// curves follow it, and a refused value is put back with a message naming the field and value.
#include "tests/examples.h"
#include "tests/gui/screenshot.h"

#include "app/gui/file_controller.h"
#include "app/gui/main_window.h"
#include "core/project/operations.h"
#include "widgets/common/length_spin_box.h"
#include "widgets/document/project_document.h"
#include "widgets/planning/planning_panel.h"
#include "widgets/results/deflection_panel.h"
#include "widgets/setup/operations_dialog.h"
#include "widgets/setup/setup_panel.h"
#include "widgets/setup/stiffness_editor.h"
#include "widgets/tolerances/tolerance_panel.h"

#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QScrollArea>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <cmath>

using namespace tolturn;

namespace {

using tolturn::test::example;

// What a user's choice in a combo box does: select the item, then the box reports it.
void choose(QComboBox *box, const QVariant &data)
{
    const int index = box->findData(data);
    QVERIFY2(index >= 0, qPrintable(data.toString()));
    box->setCurrentIndex(index);
    Q_EMIT box->activated(index);
}

// Radial workpiece deflection at the last tool position of the journal O9 (z = 149 mm, 1 mm
// before the right end face of the stepped shaft).
// Where the part is at the journal's end under the cutting load: the chuck face's motion carried
// to it plus the bending of the part.
double journalEndDeflection_mm(const DeviationResult &result)
{
    for (const FeatureDeviation &f : result.features)
        if (f.featureId == QLatin1String("O9"))
            return f.stations.back().radial.workpiece_mm + f.stations.back().radial.spindleChuck_mm;
    return std::nan("");
}

// The boring bar's radial part of the deviation at the bore's first tool position.
double innerBarDeflection_mm(const DeviationResult &result)
{
    for (const FeatureDeviation &f : result.features)
        if (f.side == ContourSide::Inner)
            return f.stations.front().radial.boringBar_mm;
    return std::nan("");
}

} // namespace

class TestSetupPanel : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void showsTheProject()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        SetupPanel *s = w.setupPanel();
        QCOMPARE(s->materialBox()->currentData().toString(), QStringLiteral("C45E-N"));
        QCOMPARE(s->machineBox()->currentData().toString(), QStringLiteral("haas-st-20"));
        QCOMPARE(s->insertEdit()->text(), QStringLiteral("CNMG 120408"));
        QCOMPARE(s->holderBox()->currentData().toString(), QStringLiteral("PCLNR 2525M12"));
        QCOMPARE(s->clampedLengthBox()->value(), 35.0);
        QCOMPARE(s->passBox(8, 1)->value(), 0.1); // finishing feed
        QVERIFY(w.fileController()->close());
        QVERIFY(!s->isEnabled());
    }

    // The bushing's bore is bored with a bar: the dock shows it with its L/D against the maker's,
    // a longer overhang bends it more, "none" takes it away, and each is one undoable edit.
    void boringBarIsChosenAndUndone()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("bushing-bore-h7.tolturn")));
        SetupPanel *s = w.setupPanel();
        QCOMPARE(s->boringBarBox()->currentData().toString(), QStringLiteral("S25T-PCLNR12"));
        QCOMPARE(s->boringOverhangBox()->millimetres(), 95.0);
        QVERIFY2(s->boringBarSummary()->text().contains(QStringLiteral("L/D 3.8")),
                 qPrintable(s->boringBarSummary()->text()));
        QVERIFY(s->boringBarSummary()->text().contains(QStringLiteral("4 × D")));
        s->resize(460, 700);
        s->findChild<QScrollArea *>()->ensureWidgetVisible(s->boringBarSummary());
        test::saveScreenshot(*s, "setup-boring-bar.png");
        // The pilot hole the program bores from: with it the G-code has the bar's roughing passes;
        // 'not given' leaves the finishing pass and says why; one undoable edit.
        QCOMPARE(s->pilotHoleBox()->millimetres(), 28.0);
        QVERIFY(w.planningPanel()->gcodeText().contains(QStringLiteral("(BORE PASS 3, ROUGHING")));
        QVERIFY(w.planningPanel()->gcodeText().contains(QStringLiteral("T0202")));
        // The warnings under the conditions, one per line, as rich text: no escaped breaks.
        const QString about = w.planningPanel()->findChild<QLabel *>(QStringLiteral("gcodeConditions"))->text();
        QVERIFY2(about.contains(QStringLiteral("<br>")) && !about.contains(QStringLiteral("&lt;br&gt;")),
                 qPrintable(about));
        if (!qEnvironmentVariableIsEmpty("TOLTURN_SCREENSHOTS")) {
            auto *tabs = w.planningPanel()->findChild<QTabWidget *>();
            for (int i = 0; i < tabs->count(); ++i)
                if (tabs->tabText(i).remove(QLatin1Char('&')) == QStringLiteral("G-code"))
                    tabs->setCurrentIndex(i);
            w.findChild<QDockWidget *>(QStringLiteral("planningDock"))->raise();
            w.resize(1366, 768);
            w.show();
            QTest::qWait(50);
            test::saveScreenshot(w, "gcode-boring.png");
        }
        s->pilotHoleBox()->setMillimetres(0.0);
        QVERIFY(!w.document()->project().boringTool->pilotHoleDiameter_mm);
        QVERIFY(!w.planningPanel()->gcodeText().contains(QStringLiteral("(BORE PASS 3, ROUGHING")));
        QVERIFY(w.planningPanel()->gcodeText().contains(QStringLiteral("(BORE PASS 3, FINISHING")));
        QVERIFY(w.planningPanel()->gcodeText().contains(QStringLiteral("PILOT HOLE IS NOT GIVEN")));
        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->project().boringTool->pilotHoleDiameter_mm, std::optional<double>(28.0));
        QCOMPARE(s->pilotHoleBox()->millimetres(), 28.0);
        const double at95 = innerBarDeflection_mm(w.deflectionPanel()->result());
        QVERIFY(at95 > 0.0);
        w.deflectionPanel()->setSide(ContourSide::Inner);
        w.deflectionPanel()->setQuantity(DeflectionPanel::Quantity::RadialContributions);
        test::saveScreenshot(*w.deflectionPanel(), "deflection-boring-bar.png");

        s->boringOverhangBox()->setMillimetres(110.0);
        QCOMPARE(w.document()->project().boringTool->overhang_mm, std::optional<double>(110.0));
        // A cantilever's tip under a tip force: bending grows with L^3, shear with L.
        const double at110 = innerBarDeflection_mm(w.deflectionPanel()->result());
        QVERIFY2(at110 > at95 * std::pow(110.0 / 95.0, 2.5),
                 qPrintable(QStringLiteral("%1 vs %2").arg(at110).arg(at95)));
        QVERIFY(s->boringBarSummary()->text().contains(QStringLiteral("L/D 4.4")));

        choose(s->boringBarBox(), QString());
        QVERIFY(!w.document()->project().boringTool);
        QCOMPARE(innerBarDeflection_mm(w.deflectionPanel()->result()), 0.0);
        QVERIFY(!s->boringOverhangBox()->isEnabled());

        w.document()->undoStack()->undo();
        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->project().boringTool->overhang_mm, std::optional<double>(95.0));
        QCOMPARE(s->boringBarBox()->currentData().toString(), QStringLiteral("S25T-PCLNR12"));
        QCOMPARE(innerBarDeflection_mm(w.deflectionPanel()->result()), at95);
    }

    // Operations are made in their dialog: a second set-up turned end for end that cuts the
    // features ticked for it; without features it is refused with the reason and the dialog stays;
    // applied, it is one undoable edit and the window offers the two set-ups.
    void operationsAreAddedInTheirDialog()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        std::vector<Operation> applied;
        OperationsDialog dialog(w.document()->project(), [&](const std::vector<Operation> &ops) {
            applied = ops;
            return w.document()->setFurtherOperations(ops);
        });
        QCOMPARE(dialog.operationList()->count(), 1);
        dialog.addOperation();
        QCOMPARE(dialog.operationList()->count(), 2);
        QCOMPARE(dialog.operations().front().clamping.heldEnd, PartEnd::Right);
        dialog.accept(); // cuts nothing yet
        QVERIFY2(dialog.messageLabel()->text().contains(QStringLiteral("cuts no feature")),
                 qPrintable(dialog.messageLabel()->text()));
        QVERIFY(w.document()->project().furtherOperations.empty());
        // Tick the left end face and the clamping diameter (O1, O2: in the jaws of OP 10).
        for (int i = 0; i < dialog.featureList()->count(); ++i) {
            QListWidgetItem *item = dialog.featureList()->item(i);
            const QString id = item->data(Qt::UserRole).toString();
            if (id == QLatin1String("O1") || id == QLatin1String("O2"))
                item->setCheckState(Qt::Checked);
        }
        dialog.nameEdit()->setText(QStringLiteral("OP 20 turn over"));
        Q_EMIT dialog.nameEdit()->textEdited(dialog.nameEdit()->text());
        test::saveScreenshot(dialog, "operations-dialog.png");
        dialog.accept();
        QVERIFY2(dialog.messageLabel()->text().isEmpty(), qPrintable(dialog.messageLabel()->text()));
        const Project &p = w.document()->project();
        QCOMPARE(p.furtherOperations.size(), std::size_t(1));
        QCOMPARE(p.furtherOperations.front().name, QStringLiteral("OP 20 turn over"));
        QCOMPARE(p.furtherOperations.front().features, (QStringList{QStringLiteral("O1"), QStringLiteral("O2")}));
        auto *box = w.findChild<QComboBox *>(QStringLiteral("operationBox"));
        QVERIFY(box && box->count() == 2);
        // The first set-up now keeps what no other cuts: not O1 and O2.
        QVERIFY(!operationFeatures(p, 0).contains(QStringLiteral("O2")));
        w.document()->undoStack()->undo();
        QVERIFY(w.document()->project().furtherOperations.empty());
    }

    void tailstockChangesTheCurvesAndUndoes()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        SetupPanel *s = w.setupPanel();
        const double inChuck = journalEndDeflection_mm(w.deflectionPanel()->result());
        QVERIFY(inChuck > 0.0);

        choose(s->clampingBox(), static_cast<int>(ClampingMethod::ChuckTailstock));
        QCOMPARE(w.document()->project().clamping.method, ClampingMethod::ChuckTailstock);
        QCOMPARE(w.document()->project().clamping.clampedLength_mm, 35.0);
        // The centre at z = 150 mm holds the end (a rigid pin: no published tailstock stiffness):
        // 1 mm from it the beam barely moves, while the cantilever deflects most at its free end.
        const double withTailstock = journalEndDeflection_mm(w.deflectionPanel()->result());
        QVERIFY2(std::abs(withTailstock) < 0.1 * inChuck,
                 qPrintable(QStringLiteral("%1 vs %2").arg(withTailstock).arg(inChuck)));

        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->project().clamping.method, ClampingMethod::Chuck);
        QCOMPARE(s->clampingBox()->currentData().toInt(), static_cast<int>(ClampingMethod::Chuck));
        QCOMPARE(journalEndDeflection_mm(w.deflectionPanel()->result()), inChuck);
    }

    // A collet (issue 16) holds the part like the chuck, over the same length, but its stiffness
    // is not published: rigid at its face, the spindle–chuck range no longer applies, so the part
    // deflects less than at the chuck's compliant end, and the banner says the collet is rigid.
    void colletIsOfferedAndSaysItIsTakenAsRigid()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        SetupPanel *s = w.setupPanel();
        const double inChuck = journalEndDeflection_mm(w.deflectionPanel()->result());
        choose(s->clampingBox(), static_cast<int>(ClampingMethod::Collet));
        QCOMPARE(w.document()->project().clamping.method, ClampingMethod::Collet);
        QCOMPARE(w.document()->project().clamping.clampedLength_mm, 35.0);
        QVERIFY(s->clampedLengthBox()->isEnabled());
        const double inCollet = journalEndDeflection_mm(w.deflectionPanel()->result());
        QVERIFY2(inCollet > 0.0 && inCollet < inChuck,
                 qPrintable(QStringLiteral("%1 vs %2").arg(inCollet).arg(inChuck)));
        QVERIFY2(w.tolerancePanel()->banner()->text().contains(QStringLiteral("collet not measured")),
                 qPrintable(w.tolerancePanel()->banner()->text()));
    }

    void betweenCentresReleasesTheJawsAndBack()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        SetupPanel *s = w.setupPanel();
        choose(s->clampingBox(), static_cast<int>(ClampingMethod::BetweenCentres));
        QCOMPARE(w.document()->project().clamping.clampedLength_mm, 0.0);
        QVERIFY(!s->clampedLengthBox()->isEnabled());
        choose(s->clampingBox(), static_cast<int>(ClampingMethod::Chuck));
        QCOMPARE(w.document()->project().clamping.clampedLength_mm, 35.0); // grips where it gripped
        QCOMPARE(w.document()->undoStack()->count(), 2);
    }

    void refusedClampedLengthIsPutBack()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        SetupPanel *s = w.setupPanel();
        s->clampedLengthBox()->setValue(200.0); // the part is 150 mm long
        QVERIFY2(s->message().contains(QStringLiteral("clamping.clamped_length_mm")), qPrintable(s->message()));
        QVERIFY(s->message().contains(QStringLiteral("200")));
        QCOMPARE(w.document()->project().clamping.clampedLength_mm, 35.0);
        QCOMPARE(s->clampedLengthBox()->value(), 35.0);
        QVERIFY(!w.document()->isModified());
        s->clampedLengthBox()->setValue(40.0);
        QVERIFY(s->message().isEmpty());
        QCOMPARE(w.document()->project().clamping.clampedLength_mm, 40.0);
    }

    void badInsertCodeNamesThePosition()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        SetupPanel *s = w.setupPanel();
        s->insertEdit()->setText(QStringLiteral("CNXG 120408"));
        Q_EMIT s->insertEdit()->editingFinished();
        QVERIFY2(s->message().contains(QStringLiteral("tool.insert")), qPrintable(s->message()));
        QCOMPARE(s->insertEdit()->text(), QStringLiteral("CNMG 120408"));
        QCOMPARE(w.document()->project().tool.insertCode, QStringLiteral("CNMG 120408"));

        s->insertEdit()->setText(QStringLiteral("cnmg120404"));
        Q_EMIT s->insertEdit()->editingFinished();
        QVERIFY(s->message().isEmpty());
        QCOMPARE(w.document()->project().tool.insertCode, QStringLiteral("CNMG 120404")); // normalised
    }

    void measuredStiffnessIsOneEditWhenComplete()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        StiffnessEditor *e = w.setupPanel()->stiffnessEditor();
        // Field by field: nothing reaches the project until the row, Lc and the source are there.
        e->box(0, 0)->setValue(1.0e3);
        QVERIFY2(w.setupPanel()->message().contains(QStringLiteral("k1, k2, k3")),
                 qPrintable(w.setupPanel()->message()));
        e->box(0, 1)->setValue(1.0e12);
        e->box(0, 2)->setValue(1.0e12);
        QVERIFY(w.setupPanel()->message().contains(QStringLiteral("Lc")));
        e->pivotBox()->setValue(100.0);
        QVERIFY(w.setupPanel()->message().contains(QStringLiteral("source")));
        QVERIFY(!w.document()->isModified());
        e->sourceEdit()->setText(QStringLiteral("test: k2, k3 stiff so that only k1 yields"));
        Q_EMIT e->sourceEdit()->editingFinished();
        QVERIFY2(w.setupPanel()->message().isEmpty(), qPrintable(w.setupPanel()->message()));
        QCOMPARE(w.document()->undoStack()->count(), 1);
        // With k2, k3 practically rigid the chuck only translates, by Fp / k1, away from the tool
        // (material left, positive) at every station (Valiño et al. 2008 eq. 2 with the rotation
        // terms gone: they add F (Lc + a)^2 / k2, at most 70 N x (215 mm)^2 / 1e12 = 3.2e-6 mm against
        // 0.070 mm, below 1e-4 of it).
        const DeviationResult &r = w.deflectionPanel()->result();
        const double expected_mm = r.inputs->forces.radial_N / 1.0e3;
        for (const FeatureDeviation &f : r.features)
            for (const Station &st : f.stations)
                QVERIFY2(std::abs(st.radial.spindleChuck_mm - expected_mm) < 1e-4 * expected_mm,
                         qPrintable(QStringLiteral("%1 at z %2").arg(st.radial.spindleChuck_mm).arg(st.z_mm)));
        w.document()->undoStack()->undo();
        QVERIFY(!w.document()->project().characterisation.spindleRadial.has_value());
        QCOMPARE(e->box(0, 0)->value(), 0.0);
    }

    // Fit from Test Bar: the deviation the program shows for a bar with known springs, saved as a
    // measurement, gives the springs back as one undoable edit (the closed-form check of the fit is
    // tst_deviation::spindleSpringsFromATestBar).
    void stiffnessFittedFromATestBar()
    {
        MainWindow w;
        QVERIFY(w.fileController()->newProject()); // a plain bar in the chuck
        ProjectDocument &doc = *w.document();
        MachineCharacterisation known;
        known.source = QStringLiteral("test");
        known.pivotDistance_mm = 200.0;
        known.spindleRadial = SpindleSprings{2.0e5, 4.0e9, 1.5e9};
        QVERIFY(doc.setCharacterisation(known).empty());
        QString csv = QStringLiteral("z_mm,radial_um\n");
        for (const FeatureDeviation &f : w.deflectionPanel()->result().features) {
            if (f.side != ContourSide::Outer || f.kind != SegmentKind::Cylinder)
                continue;
            for (const Station &st : f.stations)
                csv +=
                    QStringLiteral("%1,%2\n").arg(st.z_mm, 0, 'g', 15).arg(1000.0 * st.radial.total_mm(), 0, 'g', 15);
        }
        doc.undoStack()->undo();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bar.csv"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(csv.toUtf8());
        file.close();

        SetupPanel *panel = w.setupPanel();
        QVERIFY(!panel->fitStiffnessFromTestBar(path)); // no Lc yet
        QVERIFY(panel->message().contains(QStringLiteral("Enter Lc")));
        panel->stiffnessEditor()->pivotBox()->setValue(200.0); // kept in the box, not yet applied
        QVERIFY(panel->message().contains(QStringLiteral("source")));
        const int edits = doc.undoStack()->index();
        QVERIFY2(panel->fitStiffnessFromTestBar(path), qPrintable(panel->message()));
        QCOMPARE(doc.undoStack()->index(), edits + 1);
        const MachineCharacterisation &c = doc.project().characterisation;
        QVERIFY(c.spindleRadial.has_value());
        if (!c.spindleRadial)
            return;
        QVERIFY(std::abs(c.spindleRadial->k1_N_per_mm / 2.0e5 - 1.0) < 1e-3);
        QVERIFY(std::abs(c.spindleRadial->k2_Nmm_per_rad / 4.0e9 - 1.0) < 1e-3);
        QVERIFY(std::abs(c.spindleRadial->k3_Nmm_per_rad / 1.5e9 - 1.0) < 1e-3);
        QVERIFY(c.source.contains(QStringLiteral("Test bar fit")));
        QCOMPARE(panel->stiffnessEditor()->box(0, 1)->value(), std::round(c.spindleRadial->k2_Nmm_per_rad));

        // A file that is not a measurement: nothing changes, the message names file and line.
        file.open(QIODevice::WriteOnly);
        file.write("z_mm,radial_um\n40,five\n");
        file.close();
        QVERIFY(!panel->fitStiffnessFromTestBar(path));
        QVERIFY2(panel->message().contains(QStringLiteral("bar.csv:2: radial_um")), qPrintable(panel->message()));
        QCOMPARE(doc.undoStack()->index(), edits + 1);
    }

    // The stepped shaft's finishing feed 0.1 mm/rev lies below the 0.17 mm/rev its insert's catalogue
    // range starts at (the example's planning.ranges): the box is marked and says why; a feed inside
    // the range clears it.
    void implausibleConditionsAreMarked()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        SetupPanel *s = w.setupPanel();
        QDoubleSpinBox *feed = s->passBox(8, 1);
        QVERIFY(feed->styleSheet().contains(QStringLiteral("#ffe8a3")));
        QVERIFY2(feed->toolTip().contains(QStringLiteral("outside the insert's published range 0.17–0.399 mm/rev")),
                 qPrintable(feed->toolTip()));
        QVERIFY(s->passBox(8, 0)->styleSheet().isEmpty()); // 250 m/min is inside 201.2–353.6
        feed->setValue(0.2);
        QVERIFY(s->passBox(8, 1)->styleSheet().isEmpty());
        QVERIFY(!s->passBox(8, 1)->toolTip().contains(QStringLiteral("outside")));
    }

    // The drawing number and revision go to the project (and the report's title block) as one
    // undoable edit.
    void drawingNumberIsAnEdit()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        auto *number = w.setupPanel()->findChild<QLineEdit *>(QStringLiteral("drawingNumber"));
        auto *revision = w.setupPanel()->findChild<QLineEdit *>(QStringLiteral("drawingRevision"));
        QCOMPARE(number->text(), QStringLiteral("TT-EX-001"));
        QCOMPARE(revision->text(), QStringLiteral("B"));
        number->setText(QStringLiteral(" 4711-02 "));
        Q_EMIT number->editingFinished();
        QCOMPARE(w.document()->project().part.drawingNumber, QStringLiteral("4711-02"));
        w.document()->undoStack()->undo();
        QCOMPARE(w.document()->project().part.drawingNumber, QStringLiteral("TT-EX-001"));
        QCOMPARE(number->text(), QStringLiteral("TT-EX-001"));
    }

    void cuttingConditionsAndMaterialAreEdits()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        SetupPanel *s = w.setupPanel();
        // Depth 4 mm, feed doubled from 0.1 to 0.2 mm/rev (C45E-N kc1.1 = 1500, mc = 0.22, ISCAR group 2;
        // CNMG 120408 r_n = 0.8 mm, PCLNR kappa_r = 95°). Kienzle at Li & Du's equivalent entering
        // angle (eq. 20): f 0.1: tan(gamma_Le) = -0.044208 + 0.130913 + 0.093080 = 0.179785,
        // kappa_eq = 79.808°, h = 0.098422, b = 4.064131, Fc = 999.24 N; f 0.2: tan = 0.310697,
        // kappa_eq = 72.740°, h = 0.190994, b = 4.188618, Fc = 1727.26 N; ratio 1.72857.
        s->passBox(8, 2)->setValue(4.0);
        QCOMPARE(w.document()->project().passes[8].depthOfCut_mm, 4.0);
        const double fcBefore = w.deflectionPanel()->result().inputs->forces.tangential_N;
        QVERIFY2(std::abs(fcBefore / 999.24 - 1.0) < 1e-5, qPrintable(QString::number(fcBefore)));
        s->passBox(8, 1)->setValue(0.2); // finishing feed doubled
        QCOMPARE(w.document()->project().passes[8].feed_mm_rev, 0.2);
        const double fcAfter = w.deflectionPanel()->result().inputs->forces.tangential_N;
        QVERIFY2(std::abs(fcAfter / fcBefore - 1.72857) < 1e-5, qPrintable(QString::number(fcAfter / fcBefore)));

        choose(s->materialBox(), QStringLiteral("42CrMo4-QT"));
        QCOMPARE(w.document()->project().materialId, QStringLiteral("42CrMo4-QT"));
        QCOMPARE(w.document()->undoStack()->count(), 3);
        w.document()->undoStack()->undo();
        QCOMPARE(s->materialBox()->currentData().toString(), QStringLiteral("C45E-N"));
    }

    // The values a spin box goes through while its arrows are clicked or a number is typed into it
    // are one step in Undo (EXAMPLES.md item 5), back to where the first found the pass; another
    // box, a saved state or a value back where the step began end the step.
    void stepsOfOneBoxAreOneUndoStep()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        SetupPanel *s = w.setupPanel();
        QUndoStack *undo = w.document()->undoStack();
        const CuttingPass finishing = w.document()->project().passes[8];
        QCOMPARE(undo->count(), 0);
        for (const double feed : {0.12, 0.14, 0.16})
            s->passBox(8, 1)->setValue(feed);
        QCOMPARE(w.document()->project().passes[8].feed_mm_rev, 0.16);
        QCOMPARE(undo->count(), 1);
        QCOMPARE(undo->undoText(), QStringLiteral("Change cutting conditions"));
        s->passBox(8, 2)->setValue(finishing.depthOfCut_mm + 0.1); // another box: its own step
        s->passBox(8, 1)->setValue(0.18);                          // and this box again: a new one
        QCOMPARE(undo->count(), 3);
        undo->undo();
        undo->undo();
        undo->undo();
        QCOMPARE(w.document()->project().passes[8], finishing);
        QCOMPARE(s->passBox(8, 1)->value(), finishing.feed_mm_rev);
        // There and back again: no step.
        undo->clear();
        s->passBox(8, 0)->setValue(finishing.cuttingSpeed_m_min + 10.0);
        s->passBox(8, 0)->setValue(finishing.cuttingSpeed_m_min);
        QCOMPARE(undo->count(), 0);
        QVERIFY(!w.document()->isModified());
        // A save ends the step: Undo goes back to the saved value first.
        s->passBox(8, 0)->setValue(finishing.cuttingSpeed_m_min + 10.0);
        undo->setClean();
        s->passBox(8, 0)->setValue(finishing.cuttingSpeed_m_min + 20.0);
        QCOMPARE(undo->count(), 2);
        undo->undo();
        QCOMPARE(w.document()->project().passes[8].cuttingSpeed_m_min, finishing.cuttingSpeed_m_min + 10.0);
        QVERIFY(!w.document()->isModified());
    }

    // Choices in a list are steps of their own, even of one member and back again.
    void choicesAreStepsOfTheirOwn()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        SetupPanel *s = w.setupPanel();
        choose(s->materialBox(), QStringLiteral("42CrMo4-QT"));
        choose(s->materialBox(), QStringLiteral("C45E-N"));
        QCOMPARE(w.document()->undoStack()->count(), 2);
    }
};

QTEST_MAIN(TestSetupPanel)
#include "tst_setup_panel.moc"
