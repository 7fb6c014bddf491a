// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/learning/machine_learning.h"
#include "core/project/project.h"
#include "widgets/common/job_runner.h"
#include "widgets/report/report_writer.h"

#include <QDateTime>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>

namespace tolturn {

class ProjectDocument;
class RecentFiles;

// The progress of a task as the user sees it, for as long as the object lives. The task runs
// elsewhere (a worker thread, a child process); the window's own event loop draws the progress and
// delivers Cancel, so update() never runs the event loop.
class TaskProgress {
public:
    virtual ~TaskProgress() = default;
    // `fraction` done (0…1); false once the user has asked to cancel.
    [[nodiscard]] virtual bool update(double fraction) = 0;

    // Called as soon as the user asks to cancel, for a task that would only learn of it at its
    // next update.
    virtual void onCancel(const std::function<void()> &handler) { Q_UNUSED(handler); }
};

// What file commands need from the user: a path chosen, an error shown. The main window answers
// with dialogs; tests answer with fixed paths and record the errors.
class FilePrompts {
public:
    enum class SaveChoice { Save, Discard, Cancel };

    virtual ~FilePrompts() = default;
    // Asked before a modified document is replaced or closed.
    [[nodiscard]] virtual SaveChoice askToSaveChanges(const QString &documentName) = 0;
    [[nodiscard]] virtual QString chooseFileToOpen(const QString &startFolder) = 0;
    [[nodiscard]] virtual QString chooseFileToSave(const QString &suggestedPath) = 0;
    [[nodiscard]] virtual QString chooseReportFile(const QString &suggestedPath) = 0;
    virtual void showError(const QString &title, const QString &text) = 0;
    // Asked at start for each copy a crashed session left: true to recover it, false to discard it.
    [[nodiscard]] virtual bool askToRecover(const QString &documentName, const QDateTime &savedAt) = 0;

    // Shown while a long task runs (the report's computations); none by default.
    [[nodiscard]] virtual std::unique_ptr<TaskProgress> startProgress(const QString &label)
    {
        Q_UNUSED(label);
        return nullptr;
    }
};

// Where an export of the document is offered: beside its project file (else in the home folder),
// named after it with `suffix` ("pdf", "step").
[[nodiscard]] QString suggestedExportPath(const ProjectDocument &document, const QString &suffix);
// `path` as chosen, with ".suffix" added when it has none.
[[nodiscard]] QString withDefaultSuffix(const QString &path, const QString &suffix);

// File > Open, Save, Save As, Export Report and the recent-file list. Choosing a path and writing a file are
// separate steps; a failed open leaves the document as it was, a failed save leaves both the
// document (still modified) and the file on disk as they were.
class FileController : public QObject {
    Q_OBJECT
public:
    FileController(ProjectDocument &document, RecentFiles &recentFiles, FilePrompts &prompts,
                   QObject *parent = nullptr);

    // A new project: a plain bar held in a chuck, to be shaped in the editor.
    bool newProject();
    bool open();
    bool openFile(const QString &path);
    // Closes the document, after asking to save unsaved changes; false when the user cancels.
    bool close();
    // Asks to save a modified document: true when it may now be replaced or closed.
    bool maybeSave();
    // Opens a bundled example (a Qt resource path) as a new, unsaved document.
    bool openExample(const QString &resourcePath);
    bool save();
    bool saveAs();
    bool saveTo(const QString &path);
    // Offers the autosave copies crashed sessions left in `folder`; true when one was recovered.
    bool offerRecovery(const QString &autosaveFolder);
    // File > Export Report: the PDF report of the document as it is now (saved or not). Its
    // computations run off the window's thread, with progress and cancel; it is drawn and written
    // on it, and reportFinished() follows. False when none was started: no document, a report
    // already being written, no file chosen.
    bool exportReport();
    bool exportReportTo(const QString &pdfPath);

    [[nodiscard]] bool isWritingReport() const { return m_reportJob.isRunning(); }

    void cancelReport()
    {
        m_reportCancelled = true; // also when the computations have ended and their result waits
        m_reportJob.cancel();
    }

    // The operation (set-up) the report is of, for a project of several (docs/operations.md).
    void setOperation(int index) { m_operation = index; }

    // What was learned of the machine, when the planner uses it: the report then rests on it.
    void setLearnedModelSource(std::function<std::shared_ptr<const LoadedModel>()> source)
    {
        m_learnedModel = std::move(source);
    }

    // The project File > New starts from.
    [[nodiscard]] static Project newBar();

    // File name filter for dialogs.
    [[nodiscard]] static QString fileFilter();

    [[nodiscard]] static QString fileSuffix() { return QStringLiteral("tolturn"); }

Q_SIGNALS:
    void statusMessage(const QString &message);
    // A TolTurn project with wrong values was opened to be repaired (ProjectDocument::problems()).
    void openedWithProblems();
    // `written`: the report is on disk. Otherwise it was cancelled (said in statusMessage()) or
    // could not be written (the error shown).
    void reportFinished(bool written);

private:
    int m_operation = 0;
    bool loadFrom(const QString &readPath, const QString &documentPath);
    void reportComputed(const Project &project, const ReportHeader &header, const QString &pdfPath,
                        const std::shared_ptr<const ReportData> &data);
    void reportFailed(const QString &what);

    ProjectDocument &m_document;
    RecentFiles &m_recentFiles;
    FilePrompts &m_prompts;
    std::function<std::shared_ptr<const LoadedModel>()> m_learnedModel;
    JobRunner m_reportJob;
    std::unique_ptr<TaskProgress> m_reportProgress; // shown while m_reportJob runs
    bool m_reportCancelled = false;
};

} // namespace tolturn
