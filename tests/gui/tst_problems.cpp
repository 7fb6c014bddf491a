// SPDX-License-Identifier: GPL-3.0-or-later
// A project file with a wrong value opens to be repaired (issue 13): the problem listed, its field
// focused and marked, nothing computed until it is repaired, edits elsewhere still possible.
#include "app/gui/file_controller.h"
#include "app/gui/main_window.h"
#include "app/gui/problem_navigator.h"
#include "widgets/common/diagnostics_panel.h"
#include "widgets/common/length_spin_box.h"
#include "widgets/document/project_document.h"
#include "widgets/planning/planning_panel.h"
#include "widgets/profile/feature_panel.h"
#include "widgets/results/deflection_panel.h"
#include "widgets/setup/force_model_editor.h"
#include "widgets/setup/setup_panel.h"
#include "widgets/tolerances/tolerance_panel.h"
#include "widgets/tolerances/tolerance_verdict_model.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QSettings>
#include <QStandardPaths>
#include <QTableView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace tolturn;

namespace {

// The bundled stepped shaft with `from` replaced by `to` in its text: one wrong value.
QString exampleWith(const QTemporaryDir &dir, const QByteArray &from, const QByteArray &to)
{
    QFile in(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/stepped-shaft-chuck.tolturn"));
    if (!in.open(QIODevice::ReadOnly))
        qFatal("cannot read the example");
    QByteArray text = in.readAll();
    const qsizetype at = text.indexOf(from);
    if (at < 0)
        qFatal("'%s' is not in the example", from.constData());
    text.replace(at, from.size(), to);
    QString path = dir.filePath(QStringLiteral("with-a-problem.tolturn"));
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly) || out.write(text) != text.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

// Shows the window and opens the example with one value replaced in it.
bool openWith(MainWindow &w, const QTemporaryDir &dir, const QByteArray &from, const QByteArray &to)
{
    w.show();
    return w.fileController()->openFile(exampleWith(dir, from, to));
}

QString deflectionSummary(const MainWindow &w)
{
    return w.deflectionPanel()->findChild<QLabel *>(QStringLiteral("deflectionSummary"))->text();
}

bool exportEnabled(const MainWindow &w)
{
    return w.findChild<QAction *>(QStringLiteral("exportReportAction"))->isEnabled();
}

QStringList listedFields(const MainWindow &w)
{
    QStringList fields;
    const QTableWidget *table = w.problems()->panel()->table();
    for (int row = 0; row < table->rowCount(); ++row)
        fields << table->item(row, 1)->text();
    return fields;
}

} // namespace

class TestProblems : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("TolTurnTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_problems"));
        QSettings().clear();
    }

    void badFeedOpensWithItsFieldFocused()
    {
        QTemporaryDir dir;
        // The finishing pass (the ninth) of the example has f = 0.1 mm/rev; make it negative.
        MainWindow w;
        QVERIFY(openWith(w, dir, "\"feed_mm_rev\": 0.1", "\"feed_mm_rev\": -0.1"));
        QVERIFY(w.document()->hasProject());
        QCOMPARE(listedFields(w), QStringList{QStringLiteral("passes[8].feed_mm_rev")});
        QDoubleSpinBox *feed = w.setupPanel()->passBox(8, 1);
        QTRY_COMPARE(w.focusWidget(), feed);
        QVERIFY(!feed->styleSheet().isEmpty());                                                  // marked
        QVERIFY2(feed->toolTip().contains(QStringLiteral("-0.1")), qPrintable(feed->toolTip())); // with the reason
        // Nothing computed from a wrong value, and the places say why.
        QVERIFY2(deflectionSummary(w).startsWith(QStringLiteral("Not computed")), qPrintable(deflectionSummary(w)));
        QVERIFY(!exportEnabled(w));
        QCOMPARE(w.planningPanel()->planText(), PlanningPanel::problemsText());
        QCOMPARE(w.tolerancePanel()->model()->rowCount(), 8); // the tolerances stay editable

        // Another value can be edited while the problem stands; a second problem cannot be added.
        w.setupPanel()->passBox(0, 0)->setValue(180.0);
        QCOMPARE(w.document()->project().passes[0].cuttingSpeed_m_min, 180.0);
        QCOMPARE(w.document()->project().passes[8].feed_mm_rev, -0.1); // not the box's clamped value
        QCOMPARE(w.document()->problems().size(), std::size_t{1});
        w.setupPanel()->clampedLengthBox()->setMillimetres(-5.0);
        QVERIFY(w.document()->project().clamping.clampedLength_mm > 0.0);
        QVERIFY(!w.setupPanel()->message().isEmpty());

        // Repaired: computed again.
        feed->setValue(0.1);
        QVERIFY(w.document()->problems().empty());
        QVERIFY(listedFields(w).isEmpty());
        QVERIFY(!feed->toolTip().contains(QStringLiteral("-0.1"))); // no longer marked with it
        QVERIFY(!deflectionSummary(w).startsWith(QStringLiteral("Not computed")));
        QVERIFY(exportEnabled(w));
        QCOMPARE(w.planningPanel()->planText(), PlanningPanel::notRunText());
    }

    // A problem on a feature of the profile selects the feature and focuses its entry field.
    void badCornerSelectsItsFeature()
    {
        QTemporaryDir dir;
        // The stock is Ø60 mm around a part of Ø56 at most; Ø50 is too small for it.
        MainWindow w;
        QVERIFY(openWith(w, dir, "\"stock_diameter_mm\": 60", "\"stock_diameter_mm\": 50"));
        const Diagnostics problems = w.document()->problems();
        QVERIFY(!problems.empty());
        QCOMPARE(problems.front().field, QStringLiteral("part.stock_diameter_mm"));
        QTRY_COMPARE(w.focusWidget(), w.setupPanel()->findChild<QWidget *>(QStringLiteral("stockDiameter")));
        // Going to a corner of the profile from the list.
        QVERIFY(w.problems()->focusField(QStringLiteral("part.outer[2].to.r_mm")));
        QCOMPARE(w.featurePanel()->feature(), w.document()->project().part.outer.segments[2].id);
        QCOMPARE(w.focusWidget(), w.featurePanel()->endDiameterBox());
        // And to a tolerance: its row selected.
        QVERIFY(w.problems()->focusField(QStringLiteral("tolerances[3].upper_um")));
        QCOMPARE(w.tolerancePanel()->findChild<QTableView *>()->currentIndex().row(), 3);
    }

    // A value that could not be read is left at its default and listed until the field is given
    // a value.
    void unreadableValueIsListedUntilEntered()
    {
        QTemporaryDir dir;
        MainWindow w;
        QVERIFY(openWith(w, dir, "\"stock_diameter_mm\": 60", "\"stock_diameter_mm\": \"60 mm\""));
        QStringList fields = listedFields(w);
        QVERIFY2(fields.count(QStringLiteral("part.stock_diameter_mm")) == 2, qPrintable(fields.join(u',')));
        auto *stock = w.setupPanel()->findChild<LengthSpinBox *>(QStringLiteral("stockDiameter"));
        stock->setMillimetres(60.0);
        QVERIFY2(w.document()->problems().empty(), qPrintable(listedFields(w).join(u',')));
        QVERIFY(exportEnabled(w));
    }

    // Values without an editor of their own before (the force model, the shop conditions) can be
    // repaired too, and set back to "not given".
    void shopConditionsCanBeRepaired()
    {
        QTemporaryDir dir;
        const QString path =
            exampleWith(dir, "\"passes\": [", "\"environment\": {\"time_since_start_min\": -5}, \"passes\": [");
        MainWindow w;
        w.show();
        QVERIFY(w.fileController()->openFile(path));
        QCOMPARE(listedFields(w), QStringList{QStringLiteral("environment.time_since_start_min")});
        QDoubleSpinBox *sinceStart = w.setupPanel()->forceModelEditor()->box(ForceModelEditor::TimeSinceStart);
        QTRY_COMPARE(w.focusWidget(), sinceStart);
        sinceStart->setValue(30.0);
        QVERIFY(w.document()->problems().empty());
        QCOMPARE(w.document()->project().environment.timeSinceStart_min, std::optional<double>(30.0));
        // A Kienzle force ratio set, then back to the material's.
        QDoubleSpinBox *feedRatio = w.setupPanel()->forceModelEditor()->box(ForceModelEditor::FeedRatio);
        feedRatio->setValue(0.45);
        QCOMPARE(w.document()->project().cuttingModel.feedToCuttingRatio, std::optional<double>(0.45));
        feedRatio->setValue(feedRatio->minimum());
        QVERIFY(!w.document()->project().cuttingModel.feedToCuttingRatio);
        QCOMPARE(feedRatio->text(), QStringLiteral("material's"));
        QCOMPARE(w.document()->project().environment.timeSinceStart_min, std::optional<double>(30.0)); // kept
    }

    // Only a file that is not a TolTurn project is refused (tst_main_window: unknown version).
};

QTEST_MAIN(TestProblems)
#include "tst_problems.moc"
