// SPDX-License-Identifier: GPL-3.0-or-later
// File > Import STEP/IGES and Export STEP, offscreen: the file is read off the GUI thread, the
// planner's choice of chuck end is applied, the part opens as a new project; a bad file or a
// cancel leaves the open project as it was.
#include "tests/examples.h"
#include "tests/gui/modal.h"
#include "tests/gui/screenshot.h"

#include "app/gui/cad_files.h"
#include "app/gui/cad_reader_process.h"
#include "app/gui/file_controller.h"
#include "app/gui/import_dialog.h"
#include "app/gui/main_window.h"
#include "app/gui/recent_files.h"
#include "core/cad/step_export.h"
#include "core/cad/step_import.h"
#include "core/io/project_file.h"
#include "widgets/common/diagnostics_panel.h"
#include "widgets/document/project_document.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace tolturn;

namespace {

using tolturn::test::example;

// Answers with a fixed file and choice; records what it was shown.
class CannedPrompts
    : public FilePrompts
    , public CadPrompts {
public:
    QString file;
    std::optional<CadImportChoice> choice = CadImportChoice{};
    QString error;
    int confirmations = 0;
    QString removeOnConfirm;

    SaveChoice askToSaveChanges(const QString &) override { return SaveChoice::Discard; }

    QString chooseFileToOpen(const QString &) override { return {}; }

    QString chooseFileToSave(const QString &) override { return {}; }

    QString chooseReportFile(const QString &) override { return {}; }

    bool askToRecover(const QString &, const QDateTime &) override { return false; }

    QString chooseCadFile(const QString &) override { return file; }

    QString chooseStepExportFile(const QString &) override { return file; }

    void showError(const QString &title, const QString &text) override { error = title + QLatin1Char('\n') + text; }

    // A progress whose Cancel is pressed at its first update; the fractions it was shown.
    bool cancelOnUpdate = false;
    std::vector<double> shownProgress;

    std::unique_ptr<TaskProgress> startProgress(const QString &) override
    {
        if (!cancelOnUpdate)
            return nullptr;

        struct Progress : TaskProgress {
            CannedPrompts *owner = nullptr;

            bool update(double fraction) override
            {
                owner->shownProgress.push_back(fraction);
                return false;
            }
        };

        auto progress = std::make_unique<Progress>();
        progress->owner = this;
        return progress;
    }

    std::optional<CadImportChoice> confirmImport(const QString &, const CadImportResult &read) override
    {
        ++confirmations;
        if (!removeOnConfirm.isEmpty()) // what follows must not need the file again
            QFile::remove(removeOnConfirm);
        if (choice) {
            choice->solid = read.chosenSolid;
            choice->axis = read.chosenAxis;
        }
        return choice;
    }
};

struct Fixture {
    ProjectDocument document;
    RecentFiles recent;
    CannedPrompts prompts;
    FileController files{document, recent, prompts};
    CadFileController cad{document, files, prompts};
};

// Imports and waits; the `ok` the controller reported.
bool runImport(Fixture &f, const QString &path)
{
    QSignalSpy finished(&f.cad, &CadFileController::importFinished);
    f.prompts.file = path;
    f.cad.importCad();
    if (finished.isEmpty() && !finished.wait(30000))
        return false;
    // A second read (another end) reports once more.
    while (f.cad.isImporting())
        finished.wait(30000);
    return finished.last().constFirst().toBool();
}

PartProfile stepped()
{
    return readProjectFile(example("stepped-shaft-chuck.tolturn")).project->part;
}

// A stand-in for tolturn-cli: a shell script in `dir` with `body`.
QString fakeReader(const QTemporaryDir &dir, const QByteArray &body)
{
    QString path = dir.filePath(QStringLiteral("fake-reader.sh"));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write("#!/bin/sh\n" + body + "\n");
    file.close();
    file.setPermissions(file.permissions() | QFileDevice::ExeOwner);
    return path;
}

// Sets the reader for a test and the real one back afterwards.
struct ReaderProgram {
    explicit ReaderProgram(const QString &program) { CadReaderProcess::setDefaultProgram(program); }

    ~ReaderProgram() { CadReaderProcess::setDefaultProgram(QStringLiteral(TOLTURN_CLI_PATH)); }

    ReaderProgram(const ReaderProgram &) = delete;
    ReaderProgram &operator=(const ReaderProgram &) = delete;
};

bool near(ProfilePoint a, ProfilePoint b)
{
    return std::abs(a.z_mm - b.z_mm) < 1e-3 && std::abs(a.r_mm - b.r_mm) < 1e-3;
}

} // namespace

class TestCadImport : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        // The test runs from the build tree's tests folder, not beside tolturn-cli.
        CadReaderProcess::setDefaultProgram(QStringLiteral(TOLTURN_CLI_PATH));
    }

    // The example shaft written as a solid comes back corner for corner (to 1 µm) as a new,
    // unsaved project with the default set-up around it.
    void importOpensThePart()
    {
        QTemporaryDir dir;
        const QString step = dir.filePath(QStringLiteral("shaft.step"));
        QVERIFY(exportProfileToStep(stepped(), step).ok);
        Fixture f;
        QVERIFY(runImport(f, step));
        QCOMPARE(f.prompts.confirmations, 1);
        QVERIFY(f.document.hasProject());
        QVERIFY(f.document.filePath().isEmpty());
        const PartProfile &got = f.document.project().part;
        const PartProfile want = stepped();
        QCOMPARE(got.outer.segments.size(), want.outer.segments.size());
        for (std::size_t i = 0; i < want.outer.segments.size(); ++i) {
            QCOMPARE(got.outer.segments[i].kind, want.outer.segments[i].kind);
            QVERIFY2(near(got.outer.segments[i].to, want.outer.segments[i].to), qPrintable(QString::number(i)));
        }
        QCOMPARE(f.document.project().clamping.clampedLength_mm, 30.0);
        QCOMPARE(f.document.project().clamping.method, ClampingMethod::Chuck);
    }

    // Chuck at the other end: the Ø56 clamping diameter (z 0 … 35 in the model) ends up at
    // z 115 … 150, the Ø30 journal at the left. The other end comes from what was read: the file is
    // gone once the planner has chosen.
    void flipPutsTheOtherEndInTheChuck()
    {
        QTemporaryDir dir;
        const QString step = dir.filePath(QStringLiteral("shaft.step"));
        QVERIFY(exportProfileToStep(stepped(), step).ok);
        Fixture f;
        f.prompts.choice = CadImportChoice{0, 0, true};
        f.prompts.removeOnConfirm = step;
        QVERIFY(runImport(f, step));
        const PartProfile &got = f.document.project().part;
        bool clampingDiameterAtRight = false;
        for (const Segment &s : got.outer.segments)
            clampingDiameterAtRight =
                clampingDiameterAtRight || (s.kind == SegmentKind::Cylinder && std::abs(s.from.r_mm - 28.0) < 1e-3 &&
                                            std::abs(s.to.z_mm - 150.0) < 1e-3 && std::abs(s.from.z_mm - 115.0) < 1e-3);
        QVERIFY(clampingDiameterAtRight);
    }

    // The reader ends when told there are no more choices (its input closed); a choice made after
    // that reads the file again, in a new reader, and gives the same part as reading it with that
    // choice at once (importCadFile, in this process). A wrapper logs each reader's start and end.
    void choiceAfterTheReaderEndedReadsAgain()
    {
        QTemporaryDir dir;
        const QString step = dir.filePath(QStringLiteral("shaft.step"));
        QVERIFY(exportProfileToStep(stepped(), step).ok);
        const QString log = dir.filePath(QStringLiteral("readers.log"));
        const ReaderProgram logged(fakeReader(dir, "echo start >> '" + log.toUtf8() +
                                                       "'\n'" TOLTURN_CLI_PATH "' \"$@\"\necho end >> '" +
                                                       log.toUtf8() + "'"));
        const auto logLines = [&] {
            QFile file(log);
            return file.open(QIODevice::ReadOnly)
                       ? QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts)
                       : QStringList();
        };
        CadReaderProcess reader;
        QSignalSpy finished(&reader, &CadReaderProcess::finished);
        reader.start(step, {});
        QVERIFY(finished.wait(30000));
        QVERIFY(reader.result().profile);
        const PartProfile firstRead = *reader.result().profile;
        QCOMPARE(logLines(), QStringList{QStringLiteral("start")});

        reader.close();
        QTRY_COMPARE_WITH_TIMEOUT(logLines(), (QStringList{QStringLiteral("start"), QStringLiteral("end")}), 10000);

        CadImportOptions flipped;
        flipped.flip = true;
        reader.choose(flipped);
        QVERIFY(reader.isRunning());
        QVERIFY(finished.wait(30000));
        QTRY_COMPARE_WITH_TIMEOUT(logLines().size(), 3, 10000); // start, end, start: a second reader
        QCOMPARE(logLines().last(), QStringLiteral("start"));
        const CadImportResult direct = importCadFile(step, flipped);
        QVERIFY(direct.profile && reader.result().profile);
        const std::vector<Segment> &want = direct.profile->outer.segments;
        const std::vector<Segment> &got = reader.result().profile->outer.segments;
        QCOMPARE(got.size(), want.size());
        for (std::size_t i = 0; i < want.size(); ++i)
            QVERIFY2(near(got[i].from, want[i].from) && near(got[i].to, want[i].to), qPrintable(QString::number(i)));
        // The other end at z = 0: the end face rises to another diameter than in the first read.
        QVERIFY(!near(got.front().to, firstRead.outer.segments.front().to));
    }

    // Not a STEP file: an error naming it, and the open project untouched.
    void badFileLeavesTheProject()
    {
        QTemporaryDir dir;
        const QString bad = dir.filePath(QStringLiteral("drawing.step"));
        QFile file(bad);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("this is not ISO 10303-21\n");
        file.close();
        Fixture f;
        QVERIFY(f.files.openFile(example("hollow-sleeve-tailstock.tolturn")));
        const Project before = f.document.project();
        QVERIFY(!runImport(f, bad));
        QVERIFY2(f.prompts.error.contains(QStringLiteral("drawing.step")), qPrintable(f.prompts.error));
        QCOMPARE(f.document.project(), before);
        QCOMPARE(f.prompts.confirmations, 0);
    }

    // A model OpenCascade used to crash on (issue 14: one EDGE_LOOP line deleted), imported in the
    // child process as the window does: an error naming the file, the project as it was, and the
    // program still here to import a good file afterwards.
    void malformedModelLeavesTheProgramRunning()
    {
        QTemporaryDir dir;
        QFile seed(QStringLiteral(TOLTURN_SOURCE_DIR "/fuzz/corpus/cad/slender-pin.step"));
        QVERIFY(seed.open(QIODevice::ReadOnly));
        QList<QByteArray> lines = seed.readAll().split('\n');
        const auto loop =
            std::find_if(lines.begin(), lines.end(), [](const QByteArray &l) { return l.contains("EDGE_LOOP"); });
        QVERIFY(loop != lines.end());
        lines.erase(loop);
        const QString bad = dir.filePath(QStringLiteral("broken.step"));
        QFile file(bad);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(lines.join('\n'));
        file.close();
        Fixture f;
        QVERIFY(f.files.openFile(example("hollow-sleeve-tailstock.tolturn")));
        const Project before = f.document.project();
        QVERIFY(!runImport(f, bad));
        QVERIFY2(f.prompts.error.contains(QStringLiteral("broken.step")), qPrintable(f.prompts.error));
        QCOMPARE(f.document.project(), before);
        QVERIFY(runImport(f, QStringLiteral(TOLTURN_SOURCE_DIR "/fuzz/corpus/cad/slender-pin.step")));
    }

    // Whatever a file makes OpenCascade do, it does it in the child: a reader that dies of a
    // segmentation fault gives an error naming the file, the project stays as it was, and the next
    // import works.
    void crashingReaderLeavesTheProgramRunning()
    {
        QTemporaryDir dir;
        Fixture f;
        QVERIFY(f.files.openFile(example("hollow-sleeve-tailstock.tolturn")));
        const Project before = f.document.project();
        {
            const ReaderProgram crashing(fakeReader(dir, "echo 'progress 0.10' >&2\nkill -SEGV $$"));
            QVERIFY(!runImport(f, dir.filePath(QStringLiteral("damaged.step"))));
        }
        QVERIFY2(f.prompts.error.contains(QStringLiteral("damaged.step")) &&
                     f.prompts.error.contains(QStringLiteral("abnormally")),
                 qPrintable(f.prompts.error));
        QCOMPARE(f.document.project(), before);
        QVERIFY(runImport(f, QStringLiteral(TOLTURN_SOURCE_DIR "/fuzz/corpus/cad/slender-pin.step")));
    }

    // A reader that never finishes (OpenCascade's parser has no cancel of its own) ends at once on
    // Cancel.
    void cancelEndsAReaderThatHangs()
    {
        QTemporaryDir dir;
        const ReaderProgram hanging(fakeReader(dir, "echo 'progress 0.05' >&2\nexec sleep 600"));
        Fixture f;
        QSignalSpy progress(&f.cad, &CadFileController::importProgress);
        QSignalSpy finished(&f.cad, &CadFileController::importFinished);
        f.cad.importFile(dir.filePath(QStringLiteral("huge.step")));
        QVERIFY(progress.wait(10000));
        QCOMPARE(progress.last().constFirst().toInt(), 5);
        QElapsedTimer clock;
        clock.start();
        f.cad.cancelImport();
        QVERIFY(finished.wait(10000));
        QVERIFY2(clock.elapsed() < 5000, qPrintable(QString::number(clock.elapsed())));
        QVERIFY(finished.last().at(1).toString().contains(QStringLiteral("cancelled")));
        QVERIFY(!f.document.hasProject());
    }

    // The progress shown is told the reader's progress, and its Cancel ends the reader.
    void cancelInTheProgressEndsTheReader()
    {
        QTemporaryDir dir;
        const ReaderProgram hanging(fakeReader(dir, "echo 'progress 0.05' >&2\nexec sleep 600"));
        Fixture f;
        f.prompts.cancelOnUpdate = true;
        QSignalSpy finished(&f.cad, &CadFileController::importFinished);
        f.cad.importFile(dir.filePath(QStringLiteral("huge.step")));
        QVERIFY(finished.wait(10000));
        QCOMPARE(f.prompts.shownProgress, std::vector<double>{0.05});
        QVERIFY(finished.last().at(1).toString().contains(QStringLiteral("cancelled")));
        QVERIFY(!f.document.hasProject());
    }

    // No reader beside the program: an error that names it and says what to do.
    void missingReaderIsNamed()
    {
        const ReaderProgram missing(QStringLiteral("/nonexistent/tolturn-cli"));
        Fixture f;
        QVERIFY(!runImport(f, QStringLiteral(TOLTURN_SOURCE_DIR "/fuzz/corpus/cad/slender-pin.step")));
        QVERIFY2(f.prompts.error.contains(QStringLiteral("/nonexistent/tolturn-cli")), qPrintable(f.prompts.error));
        QVERIFY(!f.document.hasProject());
    }

    // Cancelled (here in the confirmation): nothing changes.
    void cancelLeavesTheProject()
    {
        QTemporaryDir dir;
        const QString step = dir.filePath(QStringLiteral("shaft.step"));
        QVERIFY(exportProfileToStep(stepped(), step).ok);
        Fixture f;
        QVERIFY(f.files.openFile(example("long-shaft-centres.tolturn")));
        const Project before = f.document.project();
        f.prompts.choice.reset();
        QSignalSpy finished(&f.cad, &CadFileController::importFinished);
        QVERIFY(!runImport(f, step));
        QCOMPARE(f.document.project(), before);
        QVERIFY(finished.last().at(1).toString().contains(QStringLiteral("cancelled")));
    }

    // Cancelled while the file is read (the reader checks at its first progress report).
    void cancelWhileReading()
    {
        QTemporaryDir dir;
        const QString step = dir.filePath(QStringLiteral("shaft.step"));
        QVERIFY(exportProfileToStep(stepped(), step).ok);
        Fixture f;
        QSignalSpy finished(&f.cad, &CadFileController::importFinished);
        f.cad.importFile(step);
        QVERIFY(f.cad.isImporting());
        f.cad.cancelImport();
        QVERIFY(finished.wait(30000));
        QVERIFY(!finished.last().constFirst().toBool());
        QVERIFY(finished.last().at(1).toString().contains(QStringLiteral("cancelled")));
        QCOMPARE(f.prompts.confirmations, 0);
        QVERIFY(!f.document.hasProject());
    }

    // Export: a STEP file that reads back; a folder that does not exist gives an error naming it.
    void exportWritesAStepFile()
    {
        QTemporaryDir dir;
        Fixture f;
        QVERIFY(f.files.openFile(example("hollow-sleeve-tailstock.tolturn")));
        const QString step = dir.filePath(QStringLiteral("sleeve.step"));
        QVERIFY(f.cad.exportStepTo(step));
        const CadImportResult back = importCadFile(step);
        QVERIFY(back.profile.has_value());
        QCOMPARE(back.profile->inner.segments.size(), f.document.project().part.inner.segments.size());
        QVERIFY(!f.cad.exportStepTo(QStringLiteral("/nonexistent-folder/x.step")));
        QVERIFY(f.prompts.error.contains(QStringLiteral("x.step")));
    }

    // The confirmation shows what was read and proposes the first body and axis, chuck on the left.
    void dialogProposesTheDefaults()
    {
        QTemporaryDir dir;
        const QString step = dir.filePath(QStringLiteral("shaft.step"));
        QVERIFY(exportProfileToStep(stepped(), step).ok);
        const CadImportResult read = importCadFile(step);
        QVERIFY(read.profile.has_value());
        ImportDialog dialog(QStringLiteral("shaft.step"), read);
        const CadImportChoice choice = dialog.choice();
        QCOMPARE(choice.solid, read.chosenSolid);
        QCOMPARE(choice.axis, read.chosenAxis);
        QVERIFY(!choice.flip);
        dialog.show();
        test::saveScreenshot(dialog, "import-dialog.png");
    }

    // In the window: the menu action, and the messages dock after an import.
    void windowShowsTheImportMessages()
    {
        MainWindow w;
        QVERIFY(w.findChild<QAction *>(QStringLiteral("importCadAction")) != nullptr);
        const auto *exportStep = w.findChild<QAction *>(QStringLiteral("exportStepAction"));
        if (exportStep == nullptr)
            QFAIL("no Export STEP action");
        QCOMPARE(exportStep->isEnabled(), w.document()->hasProject()); // nothing to export without a part
        QTemporaryDir dir;
        const QString bad = dir.filePath(QStringLiteral("empty.step"));
        QFile file(bad);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.close();
        const QAbstractItemModelTester messagesModel(w.importMessages()->table()->model(),
                                                     QAbstractItemModelTester::FailureReportingMode::QtTest);
        QSignalSpy finished(w.cadFiles(), &CadFileController::importFinished);
        QString shown;
        test::closeNextMessageBox(&shown); // the error dialog is modal
        w.cadFiles()->importFile(bad);
        QVERIFY(finished.wait(30000) || !finished.isEmpty());
        QVERIFY(shown.contains(QStringLiteral("empty.step")));
        QVERIFY(w.importMessages()->heading().contains(QStringLiteral("empty.step")));
        QVERIFY(w.importMessages()->table()->rowCount() >= 1);
    }
};

QTEST_MAIN(TestCadImport)
#include "tst_cad_import.moc"
