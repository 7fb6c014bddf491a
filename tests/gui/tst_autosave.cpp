// SPDX-License-Identifier: GPL-3.0-or-later
// Autosave and recovery: a copy exists only while there are unsaved changes, a running session's
// copy is never offered, and a copy a crash left is offered at the next start and recovered as
// a modified document belonging to its original file.
#include "tests/examples.h"

#include "app/gui/autosave.h"
#include "app/gui/file_controller.h"
#include "app/gui/main_window.h"
#include "core/io/project_file.h"
#include "widgets/document/project_document.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QStandardPaths>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

using namespace tolturn;

namespace {

using tolturn::test::example;

// Clicks "Recover" or "Discard" in the next recovery question.
void answerNextRecoverPrompt(bool recover)
{
    QTimer::singleShot(0, [recover] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (box == nullptr) {
            answerNextRecoverPrompt(recover);
            return;
        }
        const QString wanted = recover ? QStringLiteral("&Recover") : QStringLiteral("&Discard");
        for (QAbstractButton *b : box->buttons())
            if (b->text() == wanted)
                b->click();
    });
}

// What a crash leaves: the session's copy without a lock held by a running process.
void simulateCrash(const Autosave &autosave)
{
    const QString base = autosave.copyPath().chopped(8);
    const QString crashed = QDir(MainWindow::autosaveFolder()).filePath(QStringLiteral("crashed"));
    QVERIFY(QFile::copy(base + QStringLiteral(".tolturn"), crashed + QStringLiteral(".tolturn")));
    QVERIFY(QFile::copy(base + QStringLiteral(".json"), crashed + QStringLiteral(".json")));
}

Clamping tailstock()
{
    return {ClampingMethod::ChuckTailstock, 35.0};
}

} // namespace

class TestAutosave : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void init() { QDir(MainWindow::autosaveFolder()).removeRecursively(); }

    void copyExistsOnlyWhileModified()
    {
        MainWindow w;
        QVERIFY(w.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
        QVERIFY(w.autosave()->saveNow());
        QVERIFY(!QFile::exists(w.autosave()->copyPath())); // nothing unsaved

        QVERIFY(w.document()->setClamping(tailstock()).empty());
        QVERIFY(w.autosave()->saveNow());
        const ProjectParseResult copy = readProjectFile(w.autosave()->copyPath());
        QVERIFY(copy.project.has_value());
        QVERIFY(*copy.project == w.document()->project());
        QVERIFY(Autosave::leftOver(MainWindow::autosaveFolder()).empty()); // this session is alive

        w.document()->undoStack()->undo(); // back to the file's state
        QVERIFY(!QFile::exists(w.autosave()->copyPath()));
    }

    void crashCopyIsRecovered()
    {
        Project edited;
        {
            MainWindow crashed;
            QVERIFY(crashed.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
            QVERIFY(crashed.document()->setClamping(tailstock()).empty());
            QVERIFY(crashed.autosave()->saveNow());
            edited = crashed.document()->project();
            simulateCrash(*crashed.autosave());
        }
        const std::vector<Autosave::Copy> left = Autosave::leftOver(MainWindow::autosaveFolder());
        QCOMPARE(left.size(), std::size_t{1});
        QCOMPARE(left.front().originalPath, example("stepped-shaft-chuck.tolturn"));

        MainWindow w;
        answerNextRecoverPrompt(true);
        QVERIFY(w.fileController()->offerRecovery(MainWindow::autosaveFolder()));
        QVERIFY(w.document()->project() == edited);
        QCOMPARE(w.document()->filePath(), example("stepped-shaft-chuck.tolturn"));
        QVERIFY(w.document()->isModified()); // differs from the file until saved
        QVERIFY(Autosave::leftOver(MainWindow::autosaveFolder()).empty());
    }

    void declinedCopyIsDeleted()
    {
        {
            MainWindow crashed;
            QVERIFY(crashed.fileController()->openFile(example("stepped-shaft-chuck.tolturn")));
            QVERIFY(crashed.document()->setClamping(tailstock()).empty());
            QVERIFY(crashed.autosave()->saveNow());
            simulateCrash(*crashed.autosave());
        }
        MainWindow w;
        answerNextRecoverPrompt(false);
        QVERIFY(!w.fileController()->offerRecovery(MainWindow::autosaveFolder()));
        QVERIFY(!w.document()->hasProject() || !w.document()->isModified());
        QVERIFY(Autosave::leftOver(MainWindow::autosaveFolder()).empty());
    }
};

QTEST_MAIN(TestAutosave)
#include "tst_autosave.moc"
