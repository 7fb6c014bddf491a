// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/file_controller.h"

#include "app/gui/autosave.h"
#include "app/gui/preferences.h"
#include "app/gui/recent_files.h"
#include "core/io/project_file.h"
#include "core/project/operations.h"
#include "core/project/project_defaults.h"
#include "widgets/document/project_document.h"
#include "widgets/report/report_writer.h"

#include <QCursor>
#include <QDir>
#include <QFileInfo>
#include <QGuiApplication>
#include <QLocale>

namespace tolturn {

namespace {

QString joinDiagnostics(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics) {
        if (d.severity == Severity::Error)
            lines << (d.field.isEmpty() ? d.message : d.field + QStringLiteral(": ") + d.message);
    }
    return lines.join(QLatin1Char('\n'));
}

} // namespace

FileController::FileController(ProjectDocument &document, RecentFiles &recentFiles, FilePrompts &prompts,
                               QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_recentFiles(recentFiles)
    , m_prompts(prompts)
{
    connect(&m_reportJob, &JobRunner::progressChanged, this, [this](double fraction) {
        if (m_reportProgress && !m_reportProgress->update(fraction))
            cancelReport();
    });
    connect(&m_reportJob, &JobRunner::failed, this, &FileController::reportFailed);
}

QString FileController::fileFilter()
{
    return tr("TolTurn projects (*.tolturn *.json);;All files (*)");
}

Project FileController::newBar()
{
    auto seg = [](const char *id, SegmentKind kind, ProfilePoint a, ProfilePoint b) {
        Segment s;
        s.id = QString::fromLatin1(id);
        s.kind = kind;
        s.from = a;
        s.to = b;
        return s;
    };
    PartProfile bar;
    bar.name = tr("New part");
    bar.stockDiameter_mm = 45.0;
    bar.outer.segments = {seg("O1", SegmentKind::Face, {0, 0}, {0, 20}),
                          seg("O2", SegmentKind::Cylinder, {0, 20}, {120, 20}),
                          seg("O3", SegmentKind::Face, {120, 20}, {120, 0})};
    return projectForPart(std::move(bar));
}

bool FileController::maybeSave()
{
    if (!m_document.hasProject() || !m_document.isModified())
        return true;
    switch (m_prompts.askToSaveChanges(m_document.displayName())) {
    case FilePrompts::SaveChoice::Save:
        return save();
    case FilePrompts::SaveChoice::Discard:
        return true;
    case FilePrompts::SaveChoice::Cancel:
        return false;
    }
    return false;
}

bool FileController::newProject()
{
    if (!maybeSave())
        return false;
    m_document.load(newBar(), QString());
    Q_EMIT statusMessage(tr("New project: a plain bar to shape"));
    return true;
}

bool FileController::close()
{
    if (!maybeSave())
        return false;
    m_document.clear();
    return true;
}

bool FileController::open()
{
    const QString start =
        m_document.filePath().isEmpty() ? QDir::homePath() : QFileInfo(m_document.filePath()).absolutePath();
    const QString path = m_prompts.chooseFileToOpen(start);
    return !path.isEmpty() && openFile(path);
}

bool FileController::openFile(const QString &path)
{
    const bool ok = loadFrom(path, QFileInfo(path).absoluteFilePath());
    if (ok)
        m_recentFiles.add(path);
    else if (!QFileInfo::exists(path))
        m_recentFiles.remove(path);
    return ok;
}

bool FileController::openExample(const QString &resourcePath)
{
    return loadFrom(resourcePath, QString());
}

bool FileController::loadFrom(const QString &readPath, const QString &documentPath)
{
    ProjectParseResult result = readProjectFile(readPath);
    if (!result.project && !result.repairable) {
        m_prompts.showError(tr("Cannot open %1").arg(QFileInfo(readPath).fileName()),
                            tr("The file was not opened; the current project is unchanged.\n\n%1")
                                .arg(joinDiagnostics(result.diagnostics)));
        return false;
    }
    if (!maybeSave()) // only once the new file is known to be a TolTurn project
        return false;
    if (result.project) {
        m_document.load(std::move(*result.project), documentPath);
        Q_EMIT statusMessage(tr("Opened %1").arg(QDir::toNativeSeparators(readPath)));
        return true;
    }
    m_document.load(std::move(*result.repairable), documentPath, result.diagnostics);
    Q_EMIT statusMessage(tr("Opened %1 with %n problem(s) to repair before it can be computed", nullptr,
                            static_cast<int>(m_document.problems().size()))
                             .arg(QDir::toNativeSeparators(readPath)));
    Q_EMIT openedWithProblems();
    return true;
}

bool FileController::save()
{
    if (m_document.filePath().isEmpty())
        return saveAs();
    return saveTo(m_document.filePath());
}

bool FileController::saveAs()
{
    QString suggested = m_document.filePath();
    if (suggested.isEmpty())
        suggested = QDir::home().filePath(m_document.displayName() + QLatin1Char('.') + fileSuffix());
    QString path = m_prompts.chooseFileToSave(suggested);
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QLatin1Char('.') + fileSuffix();
    return saveTo(path);
}

bool FileController::offerRecovery(const QString &autosaveFolder)
{
    for (const Autosave::Copy &copy : Autosave::leftOver(autosaveFolder)) {
        const QString name = copy.originalPath.isEmpty() ? tr("the unsaved project \"%1\"").arg(copy.partName)
                                                         : QFileInfo(copy.originalPath).fileName();
        if (!m_prompts.askToRecover(name, copy.savedAt.toLocalTime())) {
            Autosave::remove(copy);
            continue;
        }
        ProjectParseResult read = readProjectFile(copy.autosavePath);
        if (!read.project && !read.repairable) {
            QStringList problems;
            for (const Diagnostic &d : read.diagnostics)
                problems << d.toString();
            m_prompts.showError(tr("Cannot recover %1").arg(name), tr("The copy %1 cannot be read; it is kept.\n\n%2")
                                                                       .arg(QDir::toNativeSeparators(copy.autosavePath),
                                                                            problems.join(QLatin1Char('\n'))));
            continue;
        }
        if (read.project)
            m_document.load(std::move(*read.project), copy.originalPath);
        else
            m_document.load(std::move(*read.repairable), copy.originalPath, read.diagnostics);
        m_document.markRecovered();
        Autosave::remove(copy);
        Q_EMIT statusMessage(tr("Recovered %1 as it was at %2; save it to keep it.")
                                 .arg(name, QLocale().toString(copy.savedAt.toLocalTime(), QLocale::ShortFormat)));
        return true;
    }
    return false;
}

QString suggestedExportPath(const ProjectDocument &document, const QString &suffix)
{
    const QFileInfo project(document.filePath());
    const QString folder = project.filePath().isEmpty() ? QDir::homePath() : project.absolutePath();
    return QDir(folder).filePath(QFileInfo(document.displayName()).completeBaseName() + QLatin1Char('.') + suffix);
}

QString withDefaultSuffix(const QString &path, const QString &suffix)
{
    return QFileInfo(path).suffix().isEmpty() ? path + QLatin1Char('.') + suffix : path;
}

bool FileController::exportReport()
{
    if (!m_document.hasProject() || isWritingReport())
        return false;
    const QString path = m_prompts.chooseReportFile(suggestedExportPath(m_document, QStringLiteral("pdf")));
    return !path.isEmpty() && exportReportTo(withDefaultSuffix(path, QStringLiteral("pdf")));
}

bool FileController::exportReportTo(const QString &pdfPath)
{
    if (!m_document.hasProject() || isWritingReport())
        return false;
    // Copies: the worker never touches the document, which the planner may go on editing.
    const Project project =
        operationView(m_document.project(), std::min(m_operation, operationCount(m_document.project()) - 1));
    const ReportHeader header{m_document.displayName(), loadPreferences().planner,
                              m_learnedModel ? m_learnedModel() : nullptr};
    m_reportCancelled = false;
    m_reportJob.start([project, header](const Progress &progress) { return computeReport(project, header, progress); },
                      [this, project, header, pdfPath](const std::shared_ptr<const ReportData> &data) {
                          reportComputed(project, header, pdfPath, data);
                      });
    m_reportProgress = m_prompts.startProgress(tr("Writing the report…"));
    if (m_reportProgress) // after start(): Cancel stops this job
        m_reportProgress->onCancel([this] { cancelReport(); });
    return true;
}

void FileController::reportComputed(const Project &project, const ReportHeader &header, const QString &pdfPath,
                                    const std::shared_ptr<const ReportData> &data)
{
    m_reportProgress.reset();
    if (!data || m_reportCancelled) {
        Q_EMIT statusMessage(tr("Report cancelled; nothing was written."));
        Q_EMIT reportFinished(false);
        return;
    }
    // The plots are widgets: drawn here, in about a tenth of a second (docs/benchmarks.md).
    QGuiApplication::setOverrideCursor(QCursor(Qt::WaitCursor));
    const ReportResult result = writeReport(project, header, *data, pdfPath);
    QGuiApplication::restoreOverrideCursor();
    if (!result.ok) {
        m_prompts.showError(tr("Cannot export the report"), result.error);
        Q_EMIT reportFinished(false);
        return;
    }
    Q_EMIT statusMessage(
        tr("Report written to %1 (%n page(s))", nullptr, result.pages).arg(QDir::toNativeSeparators(pdfPath)));
    Q_EMIT reportFinished(true);
}

void FileController::reportFailed(const QString &what)
{
    m_reportProgress.reset();
    m_prompts.showError(tr("Cannot export the report"), tr("Computing the report failed: %1").arg(what));
    Q_EMIT reportFinished(false);
}

bool FileController::saveTo(const QString &path)
{
    if (!m_document.hasProject())
        return false;
    // A project with problems is saved as it is: it opens again to be repaired, nothing is lost.
    const WriteResult result = writeProjectFile(path, m_document.project(), WriteCheck::KeepProblems);
    if (!result.ok) {
        m_prompts.showError(tr("Cannot save %1").arg(QFileInfo(path).fileName()),
                            tr("The project was not saved; the file on disk is unchanged.\n\n%1").arg(result.error));
        return false;
    }
    m_document.markSaved(QFileInfo(path).absoluteFilePath());
    m_recentFiles.add(path);
    Q_EMIT statusMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

} // namespace tolturn
