// SPDX-License-Identifier: GPL-3.0-or-later
// The desktop program's main window, offscreen: open an example, see its drawing, survive bad
// files with a dialog and the document untouched, save, recent files, About.
#include "tests/examples.h"
#include "tests/gui/milled_features_fixture.h"
#include "tests/gui/modal.h"
#include "tests/gui/screenshot.h"

#include "app/gui/file_controller.h"
#include "app/gui/main_window.h"
#include "app/gui/recent_files.h"
#include "core/project/project_validation.h"
#include "resources/bundled.h"
#include "widgets/common/length_spin_box.h"
#include "widgets/common/worker_threads.h"
#include "widgets/dialogs/about_dialog.h"
#include "widgets/dialogs/help_browser.h"
#include "widgets/document/project_document.h"
#include "widgets/milling/milled_features_box.h"
#include "widgets/planning/planning_panel.h"
#include "widgets/plot/line_plot.h"
#include "widgets/profile/dimension_item.h"
#include "widgets/profile/profile_scene.h"
#include "widgets/profile/profile_view.h"
#include "widgets/profile/tolerance_frame_item.h"
#include "widgets/results/deflection_panel.h"
#include "widgets/setup/setup_panel.h"
#include "widgets/tolerances/tolerance_panel.h"
#include "widgets/tolerances/tolerance_verdict_model.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QGraphicsItem>
#include <QGraphicsRectItem>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QWidgetAction>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <functional>
#include <future>
#include <utility>
#include <vector>

using namespace tolturn;
using tolturn::test::closeNextMessageBox;

namespace {

using tolturn::test::example;

QList<QGraphicsItem *> itemsOfKind(const MainWindow &w, const QString &kind)
{
    QList<QGraphicsItem *> found;
    const QList<QGraphicsItem *> all = w.profileView()->scene()->items();
    for (QGraphicsItem *item : all) {
        if (item->data(kItemKindData).toString() == kind)
            found << item;
    }
    return found;
}

QStringList dimensionTexts(const MainWindow &w)
{
    QStringList texts;
    for (QGraphicsItem *item : itemsOfKind(w, profile_item::kDimension))
        texts << static_cast<DimensionItem *>(item)->text();
    return texts;
}

// Where Qt draws each dimension text of the view, from the text items themselves (not from
// DimensionItem's own arithmetic, which the layout uses).
std::vector<QRectF> dimensionLabelBoxes(const ProfileView &view)
{
    std::vector<QRectF> labels;
    for (QGraphicsItem *item : view.scene()->items())
        if (const auto *text = dynamic_cast<QGraphicsSimpleTextItem *>(item);
            text && dynamic_cast<DimensionItem *>(text->parentItem()))
            labels.push_back(text->deviceTransform(view.viewportTransform()).mapRect(text->boundingRect()));
    return labels;
}

// The first two dimension texts that overlap, as "i and j"; empty if none do.
QString overlappingLabels(const std::vector<QRectF> &labels)
{
    for (std::size_t i = 0; i < labels.size(); ++i)
        for (std::size_t j = i + 1; j < labels.size(); ++j)
            if (labels[i].intersects(labels[j]))
                return QStringLiteral("labels %1 and %2").arg(i).arg(j);
    return {};
}

// The part drawn twice its size: every length, radius and the stock doubled.
PartProfile twiceTheSize(PartProfile part)
{
    part.stockDiameter_mm *= 2.0;
    for (Contour *contour : {&part.outer, &part.inner})
        for (Segment &segment : contour->segments) {
            segment.from = {2.0 * segment.from.z_mm, 2.0 * segment.from.r_mm};
            segment.to = {2.0 * segment.to.z_mm, 2.0 * segment.to.r_mm};
            segment.arcRadius_mm *= 2.0;
        }
    return part;
}

// Answers the next "unsaved changes" question with `button` and records that it was asked.
void answerNextSavePrompt(QMessageBox::StandardButton button, bool *asked)
{
    QTimer::singleShot(0, [button, asked] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (box == nullptr) {
            answerNextSavePrompt(button, asked);
            return;
        }
        *asked = true;
        box->button(button)->click();
    });
}

// Prompts that answer nothing; the progress they show records what it is told, and pressCancel()
// presses its Cancel.
class CancellingPrompts : public FilePrompts {
public:
    std::vector<double> reported;
    std::function<void()> cancel;

    SaveChoice askToSaveChanges(const QString &) override { return SaveChoice::Cancel; }

    QString chooseFileToOpen(const QString &) override { return {}; }

    QString chooseFileToSave(const QString &) override { return {}; }

    QString chooseReportFile(const QString &) override { return {}; }

    void showError(const QString &, const QString &) override {}

    bool askToRecover(const QString &, const QDateTime &) override { return false; }

    void pressCancel() const { cancel(); }

    std::unique_ptr<TaskProgress> startProgress(const QString &) override
    {
        struct Progress : TaskProgress {
            CancellingPrompts *owner = nullptr;

            bool update(double fraction) override
            {
                owner->reported.push_back(fraction);
                return true;
            }

            void onCancel(const std::function<void()> &handler) override { owner->cancel = handler; }
        };

        auto progress = std::make_unique<Progress>();
        progress->owner = this;
        return progress;
    }
};

// Holds both worker threads until release(), so that a job started meanwhile waits.
class WorkersHeld {
public:
    WorkersHeld()
    {
        for (int i = 0; i < 2; ++i)
            m_held.push_back(QtConcurrent::run(workerThreads(), [gate = m_gate] { gate.wait(); }));
    }

    ~WorkersHeld() { release(); }

    void release()
    {
        if (!std::exchange(m_released, true))
            m_open.set_value();
        for (QFuture<void> &f : m_held)
            f.waitForFinished();
    }

private:
    std::promise<void> m_open;
    std::shared_future<void> m_gate = m_open.get_future().share();
    std::vector<QFuture<void>> m_held;
    bool m_released = false;
};

// File > Export Report on the stepped shaft, without a window: the prompts record the progress and
// can press Cancel; `pdf` is where the report goes.
struct ReportFixture {
    ProjectDocument document;
    RecentFiles recent;
    CancellingPrompts prompts;
    FileController files{document, recent, prompts};
    QSignalSpy finished{&files, &FileController::reportFinished};
    QTemporaryDir dir;
    QString pdf = dir.filePath(QStringLiteral("shaft.pdf"));

    ReportFixture()
    {
        if (!files.openFile(example("stepped-shaft-chuck.tolturn")))
            qFatal("cannot open the stepped shaft");
    }
};

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("TolTurnTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_main_window"));
        QSettings().clear();
    }

    // The first layout (no saved one) gives the verdict table 42 % of the window's width, sized
    // once the window has its real width, not the share the layout scales a request down to.
    // A layout saved by an older version (saveState's default version 0) is not restored over it.
    void verdictTableHasItsShareOfTheWidth()
    {
        QSettings().clear();
        {
            MainWindow older;
            older.resize(1600, 1000);
            QSettings().setValue(QStringLiteral("window/state"), older.saveState());
        }
        MainWindow w;
        w.resize(1600, 1000);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const auto *tolerances = w.findChild<QDockWidget *>(QStringLiteral("tolerancesDock"));
        QVERIFY2(tolerances->width() >= 1600 * 42 / 100 - 10, qPrintable(QString::number(tolerances->width())));
    }

    // A laptop screen (1366 x 768, less a panel) holds the whole window with every dock: its
    // minimum size fits, and the screenshots of docs/images show it at both sizes.
    void windowFitsALaptopScreen()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        w.show();
        const QSize minimum = w.minimumSizeHint().expandedTo(w.minimumSize());
        QVERIFY2(minimum.width() <= 1366 && minimum.height() <= 740,
                 qPrintable(QStringLiteral("minimum %1 x %2").arg(minimum.width()).arg(minimum.height())));
        w.resize(1366, 740);
        QTest::qWait(50);
        // No two dimension texts of the drawing overlap at this size (ISO 129-1 legibility).
        const std::vector<QRectF> labels = dimensionLabelBoxes(*w.profileView());
        QVERIFY(labels.size() >= 10);
        QVERIFY2(overlappingLabels(labels).isEmpty(), qPrintable(overlappingLabels(labels)));
        // The deflection plot's legend lies inside the plot widget with room for every entry.
        LinePlot *plot = w.findChild<DeflectionPanel *>()->plot();
        QVERIFY2(plot->rect().contains(plot->legendRect()), qPrintable(QStringLiteral("legend %1,%2 %3x%4 in %5x%6")
                                                                           .arg(plot->legendRect().x())
                                                                           .arg(plot->legendRect().y())
                                                                           .arg(plot->legendRect().width())
                                                                           .arg(plot->legendRect().height())
                                                                           .arg(plot->width())
                                                                           .arg(plot->height())));
        QVERIFY(plot->legendRect().width() >= plot->legendNeeds().width());
        QVERIFY(plot->legendRect().height() >= plot->legendNeeds().height());
        test::saveScreenshot(w, "window-1366x768.png");
        w.resize(1600, 1000);
        QTest::qWait(50);
        test::saveScreenshot(w, "window-1600x1000.png");
    }

    // The drawing is fitted to the view once it is shown, whatever was done to the document before:
    // edits made before the window opens (a script, a restored session) leave the same zoom as none.
    void drawingDoesNotDependOnEditsBeforeShow()
    {
        const auto zoomAfterShow = [](int editsBefore) {
            MainWindow w;
            if (!w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")))
                return 0.0;
            for (int i = 0; i < editsBefore; ++i)
                (void)w.document()->setMilledFeatures(test::flatAndImportedKeyway(QStringLiteral("edit %1").arg(i)),
                                                      QStringLiteral("features"));
            w.resize(1366, 740);
            w.show();
            if (!QTest::qWaitForWindowExposed(&w))
                return 0.0;
            QTest::qWait(50);
            return w.findChild<ProfileView *>(QStringLiteral("profileView"))->transform().m11();
        };
        const double unedited = zoomAfterShow(0);
        const double edited = zoomAfterShow(3);
        QVERIFY(unedited > 0.0);
        QVERIFY2(std::abs(edited - unedited) <= 0.01 * unedited,
                 qPrintable(QStringLiteral("%1 px/mm after edits, %2 without").arg(edited).arg(unedited)));
    }

    // A part changed while the window is hidden is drawn, once the window is shown again, as if it
    // had been changed in sight: same zoom, and no two dimension texts overlap.
    void drawingChangedWhileHiddenIsSpacedWhenShown()
    {
        const auto shownAfterEdit = [](bool hiddenDuringEdit, std::vector<QRectF> *labels) {
            MainWindow w;
            if (!w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")))
                return 0.0;
            w.resize(1366, 740);
            w.show();
            if (!QTest::qWaitForWindowExposed(&w))
                return 0.0;
            if (hiddenDuringEdit)
                w.hide();
            if (!w.document()->setPart(twiceTheSize(w.document()->project().part), QStringLiteral("size")).empty())
                return 0.0;
            w.show();
            if (!QTest::qWaitForWindowExposed(&w))
                return 0.0;
            QTest::qWait(50);
            *labels = dimensionLabelBoxes(*w.profileView());
            return w.profileView()->transform().m11();
        };
        std::vector<QRectF> inSight;
        std::vector<QRectF> hidden;
        const double zoomInSight = shownAfterEdit(false, &inSight);
        const double zoomHidden = shownAfterEdit(true, &hidden);
        QVERIFY(zoomInSight > 0.0);
        QVERIFY2(std::abs(zoomHidden - zoomInSight) <= 0.01 * zoomInSight,
                 qPrintable(QStringLiteral("%1 px/mm edited hidden, %2 in sight").arg(zoomHidden).arg(zoomInSight)));
        QVERIFY(hidden.size() >= 10);
        QVERIFY2(overlappingLabels(hidden).isEmpty(), qPrintable(overlappingLabels(hidden)));
    }

    // The Milling dock of an open project lists its milled features, and at a laptop's size the
    // list shows each of them with its verdict (the dock's inputs scroll).
    void millingDockListsTheMilledFeatures()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        auto *dock = w.findChild<QDockWidget *>(QStringLiteral("millingDock"));
        QVERIFY(dock);
        dock->raise();
        w.resize(1366, 740);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.document()
                    ->setMilledFeatures(test::flatAndImportedKeyway(QStringLiteral("made up for the picture")),
                                        QStringLiteral("features"))
                    .empty());
        auto *box = dock->findChild<MilledFeaturesBox *>();
        QVERIFY(box);
        QTRY_VERIFY_WITH_TIMEOUT(!box->evaluations().empty() && !box->isEvaluating(), 10000);
        QTest::qWait(50);
        QTableWidget *table = box->table();
        QCOMPARE(table->rowCount(), 2);
        const QRect lastRow = table->visualItemRect(table->item(1, 0));
        QVERIFY2(
            table->viewport()->rect().contains(lastRow),
            qPrintable(
                QStringLiteral("row at %1, viewport %2 high").arg(lastRow.bottom()).arg(table->viewport()->height())));
        test::saveScreenshot(w, "window-milling-1366x768.png");
    }

    // The first start says what to do: the empty drawing area lists the ways to a part, and the Plan
    // tab says how to run the optimisation.
    void firstStartSaysWhatToDo()
    {
        MainWindow w;
        w.resize(1366, 740);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto *view = w.findChild<ProfileView *>(QStringLiteral("profileView"));
        QVERIFY(view);
        const QImage empty = view->viewport()->grab().toImage();
        const QRgb background = empty.pixel(2, 2);
        int drawn = 0;
        for (int y = 0; y < empty.height(); ++y)
            for (int x = 0; x < empty.width(); ++x)
                drawn += empty.pixel(x, y) != background ? 1 : 0;
        QVERIFY2(drawn > 500, qPrintable(QString::number(drawn))); // the text is there
        test::saveScreenshot(w, "empty-state.png");
        QVERIFY(ProfileView::emptyStateText().contains(QStringLiteral("File > Open Example")));
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        QCOMPARE(w.findChild<PlanningPanel *>()->planText(), PlanningPanel::notRunText());
        QVERIFY(PlanningPanel::notRunText().contains(QStringLiteral("F5")));
    }

    // F1 opens the user guide shipped in the program at the page of the dock with the focus; every
    // dock has its page, and every link of the guide leads to a page of it.
    void userGuideOpensAtTheDockInUse()
    {
        MainWindow w;
        w.show();
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        auto *planning = w.findChild<QDockWidget *>(QStringLiteral("planningDock"));
        planning->raise();
        planning->widget()->findChild<QPushButton *>()->setFocus();
        QApplication::setActiveWindow(&w);
        w.findChild<QAction *>(QStringLiteral("userGuideAction"))->trigger();
        auto *guide = w.findChild<HelpBrowser *>(QStringLiteral("helpBrowser"));
        QVERIFY(guide && guide->isVisible());
        QCOMPARE(guide->currentPage(), QStringLiteral("planning.html"));
        QVERIFY(guide->pageText().contains(QStringLiteral("Cutting Window")));
        for (QDockWidget *dock : w.findChildren<QDockWidget *>())
            QVERIFY2(HelpBrowser::pageForDock(dock->objectName()) != QStringLiteral("index.html"),
                     qPrintable(dock->objectName()));
        static const QRegularExpression link(QStringLiteral("href=\"([^\"#]+)\""));
        for (const QString &page : HelpBrowser::pages()) {
            QFile file(QStringLiteral(":/help/") + page);
            QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(page));
            const QString html = QString::fromUtf8(file.readAll());
            auto it = link.globalMatch(html);
            while (it.hasNext()) {
                const QString target = it.next().captured(1);
                QVERIFY2(QFile::exists(QStringLiteral(":/help/") + target),
                         qPrintable(page + QStringLiteral(" -> ") + target));
            }
        }
    }

    // The drawing shows how the part is held: the jaws over the clamped length, the centres, the
    // tailstock centre.
    void drawingShowsTheClamping()
    {
        MainWindow w;
        w.show();
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        const QList<QGraphicsItem *> jaws = itemsOfKind(w, profile_item::kClamping);
        QCOMPARE(jaws.size(), 1);
        // Over z 0–35 (the clamped length), above the Ø56 collar (r 28): scene x = z, y = -r.
        const auto *jawItem = qgraphicsitem_cast<QGraphicsRectItem *>(jaws.constFirst());
        QVERIFY(jawItem);
        const QRectF jaw = jawItem->rect();
        QVERIFY2(std::abs(jaw.left() - 0.0) < 0.5 && std::abs(jaw.right() - 35.0) < 0.5 &&
                     std::abs(jaw.bottom() + 28.0) < 0.5,
                 qPrintable(QStringLiteral("%1 %2 %3").arg(jaw.left()).arg(jaw.right()).arg(jaw.bottom())));
        QVERIFY(w.fileController()->openFile(example("long-shaft-centres.tolturn")));
        QCOMPARE(itemsOfKind(w, profile_item::kClamping).size(), 2); // two centres
        QVERIFY(w.fileController()->openFile(example("hollow-sleeve-tailstock.tolturn")));
        QCOMPARE(itemsOfKind(w, profile_item::kClamping).size(), 2); // jaws and the tailstock centre
    }

    void opensExampleAndDrawsProfile()
    {
        MainWindow w;
        w.show();
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        QCOMPARE(itemsOfKind(w, profile_item::kAxis).size(), 1);
        QCOMPARE(itemsOfKind(w, profile_item::kSection).size(), 1);
        QCOMPARE(itemsOfKind(w, profile_item::kOuterContour).size(), 11);
        QCOMPARE(itemsOfKind(w, profile_item::kInnerContour).size(), 0);
        // Each outer feature is its own item, tagged with its id.
        QStringList ids;
        for (QGraphicsItem *item : itemsOfKind(w, profile_item::kOuterContour))
            ids << item->data(kFeatureIdData).toString();
        ids.sort();
        QCOMPARE(ids,
                 (QStringList{QStringLiteral("O1"), QStringLiteral("O10"), QStringLiteral("O11"), QStringLiteral("O2"),
                              QStringLiteral("O3"), QStringLiteral("O4"), QStringLiteral("O5"), QStringLiteral("O6"),
                              QStringLiteral("O7"), QStringLiteral("O8"), QStringLiteral("O9")}));
        // Diameters of the four cylinders; the chain of lengths between the faces at 0, 35, 120 and
        // 150 and the cone from 80 to 90 (drawing of the example: 35 + 45 + 10 + 30 + 30 = 150);
        // the overall length.
        QStringList dims = dimensionTexts(w);
        dims.sort();
        QCOMPARE(dims, (QStringList{QStringLiteral("10"), QStringLiteral("150"), QStringLiteral("30"),
                                    QStringLiteral("30"), QStringLiteral("35"), QStringLiteral("45"),
                                    QString::fromUtf8("85 ±0.05"), // T7: O3 (z 35) to O8 (z 120), ±50 µm
                                    QString::fromUtf8("Ø30"), QString::fromUtf8("Ø40 g6"), QString::fromUtf8("Ø50 h6"),
                                    QString::fromUtf8("Ø56")}));
        QVERIFY(w.windowTitle().startsWith(QStringLiteral("stepped-shaft-chuck.tolturn")));
    }

    void tolerancesAreDrawnOnTheirFeatures()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        // Five geometric tolerances (T2 cylindricity, T3 profile, T5 perpendicularity to A, T6
        // total run-out to A, T8 flatness), each a feature control frame on its feature.
        QStringList frames;
        for (QGraphicsItem *item : itemsOfKind(w, profile_item::kToleranceFrame))
            if (const auto *frame = dynamic_cast<ToleranceFrameItem *>(item))
                frames << item->data(kFeatureIdData).toString() + QLatin1Char(':') + frame->text();
        frames.sort();
        QCOMPARE(frames, (QStringList{QStringLiteral("O11:0.01"), QStringLiteral("O4:0.008"), QStringLiteral("O5:0.02"),
                                      QStringLiteral("O8:0.015 A"), QStringLiteral("O9:0.02 A")}));
        const QList<QGraphicsItem *> datums = itemsOfKind(w, profile_item::kDatum);
        QCOMPARE(datums.size(), 1);
        QCOMPARE(datums.constFirst()->data(kFeatureIdData).toString(), QStringLiteral("O4"));
    }

    void hollowPartHasBoreAndHiddenLines()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("hollow-sleeve-tailstock.tolturn")));
        QCOMPARE(itemsOfKind(w, profile_item::kInnerContour).size(), 3);
        QCOMPARE(itemsOfKind(w, profile_item::kHiddenLine).size(), 3);
        const QStringList dims = dimensionTexts(w);
        QVERIFY(dims.contains(QStringLiteral("Ø40 H7"))); // the bores carry their ISO 286 classes
        QVERIFY(dims.contains(QStringLiteral("Ø45 H8")));
        QVERIFY(dims.contains(QStringLiteral("400")));
    }

    void failedOpenShowsDialogAndKeepsDocument()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("long-shaft-centres.tolturn")));
        const Project before = w.document()->project();
        const QString pathBefore = w.document()->filePath();

        QTemporaryDir dir;
        const QString bad = dir.filePath(QStringLiteral("bad.tolturn"));
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{\"format\": \"tolturn-project\", \"version\": 7}");
        f.close();

        QString shown;
        closeNextMessageBox(&shown);
        QVERIFY(!w.fileController()->openFile(bad));
        QVERIFY2(shown.contains(QStringLiteral("version: unknown format version 7")), qPrintable(shown));
        QVERIFY(shown.contains(QStringLiteral("current project is unchanged")));
        QVERIFY(w.document()->project() == before);
        QCOMPARE(w.document()->filePath(), pathBefore);
        QCOMPARE(itemsOfKind(w, profile_item::kOuterContour).size(), 9);
    }

    void saveAsWritesFileAndRemembersIt()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openExample(bundledExamplePaths().constFirst()));
        QVERIFY(w.document()->filePath().isEmpty());
        QTemporaryDir dir;
        const QString target = dir.filePath(QStringLiteral("saved.tolturn"));
        QVERIFY(w.fileController()->saveTo(target));
        QCOMPARE(w.document()->filePath(), target);
        QVERIFY(!w.document()->isModified());
        QCOMPARE(RecentFiles().files().constFirst(), target);

        MainWindow reopened;
        QVERIFY(reopened.fileController()->openFile(target));
        QVERIFY(reopened.document()->project() == w.document()->project());
    }

    void failedSaveShowsDialog()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        QString shown;
        closeNextMessageBox(&shown);
        QVERIFY(!w.fileController()->saveTo(QStringLiteral("/nonexistent-folder/x.tolturn")));
        QVERIFY2(shown.contains(QStringLiteral("/nonexistent-folder/x.tolturn")), qPrintable(shown));
        QVERIFY(shown.contains(QStringLiteral("file on disk is unchanged")));
    }

    // Every action is enabled when what it needs is there (EXAMPLES.md item 11): a project, one
    // that can be computed, no planning run going, a selected feature.
    void actionsAreEnabledWhenTheyCanRun()
    {
        MainWindow w;
        const auto action = [&w](const char *name) {
            const auto *a = w.findChild<QAction *>(QLatin1String(name));
            return a && a->isEnabled();
        };
        const std::vector<const char *> projectActions{"saveAction",         "saveAsAction",       "fitPartAction",
                                                       "operationsAction",   "planningDataAction", "optimiseAction",
                                                       "exportReportAction", "exportStepAction",   "solidCheckAction"};
        for (const char *name : projectActions)
            QVERIFY2(w.findChild<QAction *>(QLatin1String(name)), name);
        QVERIFY(w.fileController()->close());
        for (const char *name : projectActions)
            QVERIFY2(!action(name), name);
        QVERIFY(!action("deleteFeatureAction"));
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        for (const char *name : projectActions)
            QVERIFY2(action(name), name);
        QVERIFY(!action("deleteFeatureAction")); // nothing selected
        w.profileView()->selectFeature(QStringLiteral("O4"));
        QVERIFY(action("deleteFeatureAction"));
        w.profileView()->selectFeature(QString());
        QVERIFY(!action("deleteFeatureAction"));
        // While the optimiser runs, Optimise waits for it.
        QSignalSpy finished(w.planningPanel(), &PlanningPanel::finished);
        w.findChild<QAction *>(QStringLiteral("optimiseAction"))->trigger();
        QVERIFY(w.planningPanel()->isRunning());
        QVERIFY(!action("optimiseAction"));
        QVERIFY(action("exportReportAction"));
        QVERIFY(finished.wait(60000));
        QVERIFY(action("optimiseAction"));
    }

    void exportReportFromTheFileMenu()
    {
        MainWindow w;
        auto *action = w.findChild<QAction *>(QStringLiteral("exportReportAction"));
        QVERIFY(action);
        QVERIFY(w.fileController()->close());
        QVERIFY(!action->isEnabled()); // nothing to report without a document
        QVERIFY(w.fileController()->openFile(example("hollow-sleeve-tailstock.tolturn")));
        QVERIFY(action->isEnabled());
        QTemporaryDir dir;
        const QString pdf = dir.filePath(QStringLiteral("sleeve.pdf"));
        QSignalSpy finished(w.fileController(), &FileController::reportFinished);
        QVERIFY(w.fileController()->exportReportTo(pdf));
        QVERIFY(finished.wait(60000));
        QVERIFY(finished.last().constFirst().toBool());
        QFile file(pdf);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(file.read(5) == "%PDF-");
        QVERIFY(!w.document()->isModified()); // exporting does not touch the document

        QString shown;
        closeNextMessageBox(&shown);
        QVERIFY(w.fileController()->exportReportTo(QStringLiteral("/nonexistent-folder/r.pdf")));
        QVERIFY(finished.wait(60000));
        QVERIFY(!finished.last().constFirst().toBool());
        QVERIFY2(shown.contains(QStringLiteral("/nonexistent-folder/r.pdf")), qPrintable(shown));
    }

    // The progress of a long task: a window-modal dialog once it has run 300 ms, with its bar, and a
    // Cancel that reaches the task at once and at its next update.
    void progressDialogShowsAndCancels()
    {
        MainWindow w;
        w.resize(1000, 700);
        w.show();
        const std::unique_ptr<TaskProgress> progress = w.startProgress(QStringLiteral("Reading shaft.step…"));
        bool cancelled = false;
        progress->onCancel([&cancelled] { cancelled = true; });
        auto *dialog = w.findChild<QDialog *>(QStringLiteral("progressDialog"));
        QVERIFY(dialog);
        QTest::qWait(100);
        QVERIFY(!dialog->isVisible()); // a quick task shows nothing
        QVERIFY(progress->update(0.4));
        QTRY_VERIFY_WITH_TIMEOUT(dialog->isVisible(), 5000);
        QCOMPARE(dialog->windowModality(), Qt::WindowModal);
        QCOMPARE(dialog->findChild<QProgressBar *>()->value(), 40);
        test::saveScreenshot(*dialog, "progress-dialog.png");
        auto *buttons = dialog->findChild<QDialogButtonBox *>();
        QVERIFY(buttons);
        buttons->button(QDialogButtonBox::Cancel)->click();
        QVERIFY(cancelled);
        QVERIFY(!progress->update(0.5));
    }

    // The report is computed off the window's thread: its progress is shown up to the end.
    void reportProgressIsShown()
    {
        ReportFixture f;
        QVERIFY(f.files.exportReportTo(f.pdf));
        QVERIFY(f.files.isWritingReport());
        QVERIFY(!f.files.exportReportTo(f.pdf)); // one report at a time
        QVERIFY(f.finished.wait(60000));
        QVERIFY(f.finished.last().constFirst().toBool());
        QVERIFY(QFileInfo::exists(f.pdf));
        QVERIFY(!f.prompts.reported.empty());
        QVERIFY(std::is_sorted(f.prompts.reported.begin(), f.prompts.reported.end()));
        QCOMPARE(f.prompts.reported.back(), 1.0);
    }

    // Cancelling the report while it is computed: nothing on disk, the user told.
    void cancellingTheReportWritesNothing()
    {
        ReportFixture f;
        QSignalSpy messages(&f.files, &FileController::statusMessage);
        WorkersHeld held; // the report cannot end before Cancel is pressed
        QVERIFY(f.files.exportReportTo(f.pdf));
        QVERIFY(f.prompts.cancel); // the progress shown can cancel the report
        f.prompts.pressCancel();
        held.release();
        QVERIFY(f.finished.wait(60000));
        QVERIFY(!f.finished.last().constFirst().toBool());
        QVERIFY(!QFileInfo::exists(f.pdf));
        QVERIFY(messages.last().constFirst().toString().contains(QStringLiteral("cancelled")));
        QVERIFY(!f.files.isWritingReport());
    }

    // Cancel pressed once the computations have ended but before their result is drawn: still
    // nothing on disk.
    void cancelAfterTheComputationsWritesNothing()
    {
        ReportFixture f;
        QVERIFY(f.files.exportReportTo(f.pdf));
        QVERIFY(workerThreads()->waitForDone(60000)); // computed; the result waits in the event queue
        f.prompts.pressCancel();
        QVERIFY(f.finished.wait(60000));
        QVERIFY(!f.finished.last().constFirst().toBool());
        QVERIFY(!QFileInfo::exists(f.pdf));
    }

    // The toolbar's icons are TolTurn's SVGs, drawn sharp at twice the size (High-DPI).
    void toolbarIconsAreScalable()
    {
        MainWindow w;
        auto *toolBar = w.findChild<QToolBar *>(QStringLiteral("mainToolBar"));
        QVERIFY(toolBar);
        int icons = 0;
        const QList<QAction *> actions = toolBar->actions();
        for (const QAction *action : actions) {
            if (action->isSeparator() || qobject_cast<const QWidgetAction *>(action) != nullptr)
                continue; // a widget in the toolbar (the set-up choice) has no icon
            const QImage image = action->icon().pixmap(QSize(48, 48)).toImage();
            QVERIFY2(!image.isNull() && image.width() == 48, qPrintable(action->text()));
            // Not blank: an SVG that failed to load would give a transparent or empty image.
            bool drawn = false;
            for (int y = 0; y < image.height() && !drawn; ++y)
                for (int x = 0; x < image.width() && !drawn; ++x)
                    drawn = qAlpha(image.pixel(x, y)) > 0;
            QVERIFY2(drawn, qPrintable(action->text()));
            ++icons;
        }
        QVERIFY(icons >= 8);
        QVERIFY(w.findChild<QAction *>(QStringLiteral("optimiseAction")) != nullptr);
        QVERIFY(w.findChild<QAction *>(QStringLiteral("fitPartAction")) != nullptr);
    }

    void bundledExamplesAllOpen()
    {
        const QStringList paths = bundledExamplePaths();
        QVERIFY(paths.size() >= 3);
        for (const QString &path : paths) {
            MainWindow w;
            QVERIFY2(w.fileController()->openExample(path), qPrintable(path));
            QVERIFY(!itemsOfKind(w, profile_item::kOuterContour).isEmpty());
        }
    }

    // Issue 16: the valve body bored from both ends, solid between z 45 and 75. OP 10 bores the
    // port bore I4 from the right end and judges its H8 (T2); OP 20 the spool bore I1 (T1). The
    // bottom of the left bore dragged from z 45 to z 50 deepens that bore only: at the break of the
    // inner contour, the corner is the end of I2, not the start of I3.
    void boresFromBothEndsAreDrawnAndJudgedPerSetUp()
    {
        MainWindow w;
        w.show();
        QVERIFY(w.fileController()->openFile(example("valve-body-two-bores.tolturn")));
        ToleranceVerdictModel *model = w.tolerancePanel()->model();
        QVERIFY(model->rangeVerdict(1).compliant.value_um.has_value()); // T2 on I4, OP 10
        QVERIFY(model->rangeVerdict(0).compliant.reason.contains(QStringLiteral("I1 is cut in OP 20")));
        QTest::qWait(50);
        test::saveScreenshot(w, "bores-both-ends.png");
        Q_EMIT w.profileView()->vertexDragged(ContourSide::Inner, 2, ProfilePoint{50.0, 0.0}, true);
        const Project &deeper = w.document()->project();
        QCOMPARE(deeper.part.inner.segments[0].to, (ProfilePoint{50.0, 16.0}));
        QCOMPARE(deeper.part.inner.segments[1].to, (ProfilePoint{50.0, 0.0}));
        QCOMPARE(deeper.part.inner.segments[2].from, (ProfilePoint{75.0, 0.0}));
        w.document()->undoStack()->undo();
        auto *box = w.findChild<QComboBox *>(QStringLiteral("operationBox"));
        box->setCurrentIndex(1);
        Q_EMIT box->activated(1);
        QVERIFY(model->rangeVerdict(0).compliant.value_um.has_value()); // T1 on I1, OP 20
        QTest::qWait(50);
        test::saveScreenshot(w, "bores-both-ends-op20.png");
    }

    // A project of two set-ups: the toolbar offers them; each shows its own part as held, its
    // verdicts and its program (docs/operations.md).
    void operationsAreShownOneAtATime()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("bushing-two-setups.tolturn")));
        auto *box = w.findChild<QComboBox *>(QStringLiteral("operationBox"));
        QVERIFY(box);
        QCOMPARE(box->count(), 2);
        QVERIFY(box->itemText(1).startsWith(QStringLiteral("OP 20")));
        // Every tolerance is listed; those of OP 20's features say where they are judged.
        ToleranceVerdictModel *model = w.tolerancePanel()->model();
        QCOMPARE(model->rowCount(), 6);
        QCOMPARE(model->rangeVerdict(0).compliant.verdict == Verdict::CannotEvaluate, false); // T1 on I5: OP 10
        QVERIFY(model->rangeVerdict(1).compliant.reason.contains(QStringLiteral("I1 is cut in OP 20")));
        QVERIFY(w.tolerancePanel()->banner()->text().contains(QStringLiteral("OP 10")));
        box->setCurrentIndex(1);
        Q_EMIT box->activated(1);
        QVERIFY(model->rangeVerdict(0).compliant.reason.contains(QStringLiteral("I5 is cut in OP 10")));
        QCOMPARE(model->rangeVerdict(1).compliant.toleranceId, QStringLiteral("T2"));
        QVERIFY(model->rangeVerdict(1).compliant.value_um.has_value());
        QVERIFY(w.tolerancePanel()->banner()->text().contains(QStringLiteral("OP 20")));
        const DeviationResult &r = w.deflectionPanel()->result();
        QVERIFY(std::any_of(r.features.begin(), r.features.end(),
                            [](const FeatureDeviation &f) { return f.featureId == QLatin1String("O2"); }));
        QVERIFY(std::none_of(r.features.begin(), r.features.end(),
                             [](const FeatureDeviation &f) { return f.featureId == QLatin1String("O4"); }));
        QVERIFY2(w.planningPanel()->gcodeText().contains(QStringLiteral("OP 20, OPERATION 2 OF 2")),
                 qPrintable(w.planningPanel()->gcodeText().left(400)));
        test::saveScreenshot(w, "operations.png");
        // A corner dragged in the set-up turned end for end moves the drawing's corner: the view's
        // corner 3 at z' = 65 (Ø62 shoulder) is the drawing's corner 2 at z = 120 - 65 = 55.
        Q_EMIT w.profileView()->vertexDragged(ContourSide::Outer, 3, ProfilePoint{63.0, 31.0}, false);
        const Project &moved = w.document()->project();
        QCOMPARE(moved.part.outer.segments[1].to, (ProfilePoint{57.0, 31.0}));
        QCOMPARE(moved.part.outer.segments[2].from, (ProfilePoint{57.0, 31.0}));
        // Another file, of one set-up: the set-up chosen before is gone, and the Set-up dock edits
        // the one there is.
        w.document()->undoStack()->undo(); // unmodified again: closing asks nothing
        QVERIFY(w.fileController()->close());
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        QVERIFY(!box->isVisible());
        w.setupPanel()->clampedLengthBox()->setValue(36.0);
        QCOMPARE(w.document()->project().clamping.clampedLength_mm, 36.0);
    }

    // The deflection curves appear for the open part, per contribution, and follow the project.
    void deflectionCurvesFollowTheProject()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        DeflectionPanel *panel = w.deflectionPanel();
        QVERIFY(panel->result().inputs.has_value());
        // Five contributions at the compliant end of the chuck's range, and the total over the
        // range as a band (its two edges).
        QCOMPARE(panel->plot()->curveCount(), 5 + 2);
        QCOMPARE(panel->plot()->curveName(0), QStringLiteral("total"));
        QCOMPARE(panel->plot()->curveName(5), QStringLiteral("total, compliant end of the machine range"));
        QCOMPARE(panel->plot()->curveName(6), QStringLiteral("total over the machine's stiffness range"));
        QVERIFY(panel->stiffEnd().has_value());
        QVERIFY(panel->summaryText().contains(QStringLiteral("Forces (Kienzle)")));
        const double shaftFc = panel->result().inputs->forces.tangential_N;

        panel->setQuantity(DeflectionPanel::Quantity::TangentialContributions);
        QCOMPARE(panel->plot()->curveCount(), 3 + 2); // toolpost and thermal act radially only
        panel->setQuantity(DeflectionPanel::Quantity::DiameterError);
        QCOMPARE(panel->plot()->curveCount(), 1 + 2);
        // One stem per face of the outer contour, at the face's z, of height e (eq. 12).
        panel->setQuantity(DeflectionPanel::Quantity::FaceConicity);
        QCOMPARE(panel->plot()->curveCount(), 1);
        const std::vector<FaceConicity> &faces = panel->result().faces;
        const auto o3 = std::find_if(faces.begin(), faces.end(),
                                     [](const FaceConicity &f) { return f.featureId == QStringLiteral("O3"); });
        QVERIFY(o3 != faces.end());
        const FaceConicity &shoulder = *o3; // z 35, from r 28 down to r 25
        QCOMPARE(shoulder.z_mm, 35.0);
        QVERIFY(std::abs(shoulder.axialRunout_mm - 3.0 * std::abs(shoulder.tanTheta)) < 1e-15);
        const QStringList rows = panel->plot()->csvText().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(rows.size() - 1, static_cast<int>(faces.size()));
        QVERIFY(rows.filter(QRegularExpression(QStringLiteral("^35,"))).size() == 1);

        QVERIFY(w.fileController()->openFile(example("hollow-sleeve-tailstock.tolturn")));
        QVERIFY(panel->result().inputs->forces.tangential_N != shaftFc);
        panel->setSide(ContourSide::Inner);
        QCOMPARE(panel->plot()->curveCount(), 1);
        bool bore = false;
        for (const FeatureDeviation &f : panel->result().features)
            bore = bore || f.side == ContourSide::Inner;
        QVERIFY(bore);
    }

    void newProjectIsAValidBar()
    {
        MainWindow w;
        QVERIFY(w.fileController()->newProject());
        QVERIFY(w.document()->hasProject());
        QVERIFY(validateProject(w.document()->project()).empty());
        QCOMPARE(itemsOfKind(w, profile_item::kOuterContour).size(), 3);
        QVERIFY(w.document()->filePath().isEmpty());
    }

    // A modified document is not replaced or closed without asking; Cancel keeps it, Discard lets go.
    void unsavedChangesAreAskedFor()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        Tolerance t;
        t.id = QStringLiteral("T9");
        t.type = ToleranceType::Flatness;
        t.featureId = QStringLiteral("O8");
        t.zone_um = 5.0;
        QVERIFY(w.document()->addTolerance(t).empty());
        QVERIFY(w.document()->isModified());
        QVERIFY(w.windowTitle().contains(QStringLiteral("[*]")) || w.isWindowModified());

        bool asked = false;
        answerNextSavePrompt(QMessageBox::Cancel, &asked);
        QVERIFY(!w.fileController()->openFile(example("long-shaft-centres.tolturn")));
        QVERIFY(asked);
        QCOMPARE(w.document()->project().part.name, QStringLiteral("Stepped shaft"));
        QVERIFY(w.document()->isModified());

        asked = false;
        answerNextSavePrompt(QMessageBox::Discard, &asked);
        QVERIFY(w.fileController()->close());
        QVERIFY(asked);
        QVERIFY(!w.document()->hasProject());
        QVERIFY(itemsOfKind(w, profile_item::kOuterContour).isEmpty());

        // An unmodified document closes without a question.
        QVERIFY(w.fileController()->openFile(example("long-shaft-centres.tolturn")));
        QVERIFY(w.fileController()->close());
    }

    void aboutNamesEveryLibraryWithVersionAndLicence()
    {
        const QString html = AboutDialog::aboutHtml();
        for (const char *text : {"GPL-3.0-or-later", "Qt", "Open CASCADE Technology", "7.6", "NLopt", "Eigen",
                                 "MPL-2.0", "QCustomPlot", "2.1.0"})
            QVERIFY2(html.contains(QString::fromLatin1(text)), text);
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_main_window.moc"
