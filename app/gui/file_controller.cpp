// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/file_controller.h"

#include "app/gui/recent_files.h"
#include "core/io/project_file.h"
#include "widgets/document/project_document.h"

#include <QDir>
#include <QFileInfo>

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
}

QString FileController::fileFilter()
{
    return tr("TolTurn projects (*.tolturn *.json);;All files (*)");
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
    if (!result.project) {
        m_prompts.showError(tr("Cannot open %1").arg(QFileInfo(readPath).fileName()),
                            tr("The file was not opened; the current project is unchanged.\n\n%1")
                                .arg(joinDiagnostics(result.diagnostics)));
        return false;
    }
    m_document.load(std::move(*result.project), documentPath);
    Q_EMIT statusMessage(tr("Opened %1").arg(QDir::toNativeSeparators(readPath)));
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

bool FileController::saveTo(const QString &path)
{
    if (!m_document.hasProject())
        return false;
    const WriteResult result = writeProjectFile(path, m_document.project());
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
