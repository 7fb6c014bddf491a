// SPDX-License-Identifier: GPL-3.0-or-later
// The one owner of the set-up's predictions: what it hands the panels for a project, a set-up of
// several, one with problems and none, against the core's own evaluations of the same set-up.
#include "tests/core/test_support.h"

#include "core/planning/finished_extent.h"
#include "core/project/keywords.h"
#include "core/project/operations.h"
#include "widgets/document/project_analysis.h"
#include "widgets/document/project_document.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <vector>

using namespace tolturn;

class TestProjectAnalysis : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void nothingWithoutAProject()
    {
        ProjectDocument document;
        ProjectAnalysis analysis(document);
        QSignalSpy predicted(&analysis, &ProjectAnalysis::predicted);
        QSignalSpy notPredicted(&analysis, &ProjectAnalysis::notPredicted);
        analysis.recompute();
        QCOMPARE(predicted.count(), 0);
        QCOMPARE(notPredicted.count(), 1);
        QVERIFY(notPredicted.constFirst().constFirst().toString().isEmpty());
    }

    // The verdicts and curves over the machine's range: those evaluateOverStiffnessRange gives.
    void predictsTheSetUpOverTheStiffnessRange()
    {
        ProjectDocument document;
        document.load(test::exampleProject("stepped-shaft-chuck.tolturn"), QString());
        ProjectAnalysis analysis(document);
        QSignalSpy predicted(&analysis, &ProjectAnalysis::predicted);
        analysis.recompute();
        QCOMPARE(predicted.count(), 1);
        const auto prediction = predicted.constFirst().at(1).value<SetupPrediction>();
        // The verdicts over the range, with what the program leaves unfinished (the seat O4 at the jaws).
        RangeEvaluation range = evaluateOverStiffnessRange(document.project(), DataLibrary::builtIn());
        addWhatTheProgramLeaves(document.project(), range);
        QCOMPARE(prediction.range.tolerances.size(), range.tolerances.size());
        QVERIFY(!prediction.range.tolerances.empty());
        for (std::size_t i = 0; i < range.tolerances.size(); ++i) {
            QCOMPARE(prediction.range.tolerances[i].compliant.value_um, range.tolerances[i].compliant.value_um);
            QCOMPARE(prediction.range.tolerances[i].compliant.verdict, range.tolerances[i].compliant.verdict);
            QCOMPARE(prediction.range.tolerances[i].range, range.tolerances[i].range);
        }
        QCOMPARE(prediction.deviation.features.size(), range.compliant.features.size());
        QVERIFY(!prediction.deviation.features.empty());
        QCOMPARE(prediction.deviation.features.front().stations.back().radiusError_mm,
                 range.compliant.features.front().stations.back().radiusError_mm);
        QCOMPARE(prediction.stiffEnd.has_value(), range.stiff.has_value());
        QCOMPARE(prediction.assumption, machineAssumptionText(range, DataLibrary::builtIn()));
        QVERIFY(!prediction.learned);
    }

    // The second set-up of two: its own view, and the banner names it and the end it holds.
    void predictsTheSetUpShown()
    {
        ProjectDocument document;
        document.load(test::exampleProject("bushing-two-setups.tolturn"), QString());
        ProjectAnalysis analysis(document);
        QSignalSpy predicted(&analysis, &ProjectAnalysis::predicted);
        analysis.setOperation(1);
        analysis.recompute();
        QCOMPARE(predicted.count(), 1);
        const auto project = predicted.constFirst().at(0).value<Project>();
        QCOMPARE(project, operationView(document.project(), 1));
        const auto prediction = predicted.constFirst().at(1).value<SetupPrediction>();
        QVERIFY2(
            prediction.assumption.startsWith(
                QStringLiteral("OP 20 (set-up 2 of 2, the %1 end held): ").arg(displayName(project.clamping.heldEnd))),
            qPrintable(prediction.assumption));
        analysis.setOperation(7); // a set-up the project does not have: its last
        analysis.recompute();
        QCOMPARE(predicted.last().at(0).value<Project>(), operationView(document.project(), 1));
    }

    void saysWhyAProjectWithProblemsIsNotPredicted()
    {
        ProjectDocument document;
        Project broken = test::exampleProject("stepped-shaft-chuck.tolturn");
        broken.part.stockDiameter_mm = 1.0; // thinner than the part
        document.load(broken, QString());
        QVERIFY(document.hasProblems());
        ProjectAnalysis analysis(document);
        QSignalSpy predicted(&analysis, &ProjectAnalysis::predicted);
        QSignalSpy notPredicted(&analysis, &ProjectAnalysis::notPredicted);
        analysis.recompute();
        QCOMPARE(predicted.count(), 0);
        QCOMPARE(notPredicted.count(), 1);
        QCOMPARE(notPredicted.constFirst().constFirst().toString(),
                 ProjectAnalysis::notComputedText(static_cast<int>(document.problems().size())));
        QVERIFY(notPredicted.constFirst().constFirst().toString().startsWith(QStringLiteral("Not computed")));
    }

    // One projectChanged() per user action (EXAMPLES.md item 6), so that the analysis runs once:
    // per edit, per merged step of a spin box, and once for a jump of five steps back in Undo.
    void oneChangeNoticePerAction()
    {
        ProjectDocument document;
        const Project original = test::exampleProject("stepped-shaft-chuck.tolturn");
        document.load(original, QString());
        QSignalSpy changed(&document, &ProjectDocument::projectChanged);
        std::vector<CuttingPass> passes = original.passes;
        QVERIFY(!passes.empty());
        for (int i = 1; i <= 5; ++i) {
            passes.back().feed_mm_rev = original.passes.back().feed_mm_rev + 0.01 * i;
            QVERIFY(document.setPasses(passes, QStringLiteral("Change cutting conditions")).empty());
            QCOMPARE(changed.count(), i);
        }
        QCOMPARE(document.undoStack()->count(), 5);
        document.undoStack()->setIndex(0); // five commands undone
        QCOMPARE(changed.count(), 6);
        QCOMPARE(document.project(), original);
        document.undoStack()->redo();
        QCOMPARE(changed.count(), 7);
        QCOMPARE(document.project().passes.back().feed_mm_rev, original.passes.back().feed_mm_rev + 0.01);
        QObject box; // a spin box stepped twice: one step in Undo, a notice per value
        {
            const ProjectDocument::RepeatedEdits steps(document, &box);
            passes.back().feed_mm_rev = 0.31;
            QVERIFY(document.setPasses(passes, QStringLiteral("Change cutting conditions")).empty());
            passes.back().feed_mm_rev = 0.32;
            QVERIFY(document.setPasses(passes, QStringLiteral("Change cutting conditions")).empty());
        }
        QCOMPARE(changed.count(), 9);
        QCOMPARE(document.project().passes.back().feed_mm_rev, 0.32);
    }
};

QTEST_GUILESS_MAIN(TestProjectAnalysis)
#include "tst_project_analysis.moc"
