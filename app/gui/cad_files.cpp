// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/cad_files.h"

#include "core/cad/step_export.h"
#include "core/project/project_defaults.h"
#include "widgets/document/project_document.h"

#include <QDir>
#include <QFileInfo>
#include <QScopeGuard>

#include <utility>

namespace tolturn {

namespace {

QString joined(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics)
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

} // namespace

CadFileController::CadFileController(ProjectDocument &document, FileController &files, CadPrompts &prompts,
                                     QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_files(files)
    , m_prompts(prompts)
{
    connect(&m_reader, &CadReaderProcess::finished, this, &CadFileController::readFinished);
    connect(&m_reader, &CadReaderProcess::progress, this, [this](double fraction) {
        Q_EMIT importProgress(static_cast<int>(100.0 * fraction));
        if (m_progress && !m_progress->update(fraction))
            cancelReading();
    });
}

CadFileController::~CadFileController() = default; // the reader ends its child process

void CadFileController::importCad()
{
    const QString start =
        m_document.filePath().isEmpty() ? QDir::homePath() : QFileInfo(m_document.filePath()).absolutePath();
    const QString path = m_prompts.chooseCadFile(start);
    if (!path.isEmpty())
        importFile(path);
}

void CadFileController::importFile(const QString &path)
{
    if (isImporting())
        return;
    m_path = path;
    m_confirmed = false;
    startReading({});
}

void CadFileController::cancelReading()
{
    m_cancelRequested = true; // also when the child has already finished and its result waits
    m_reader.cancel();
}

void CadFileController::startReading(const CadImportOptions &options)
{
    m_cancelRequested = false;
    showProgress(tr("Reading %1…").arg(QFileInfo(m_path).fileName()));
    m_reader.start(m_path, options);
}

void CadFileController::showProgress(const QString &label)
{
    m_progress = m_prompts.startProgress(label);
    if (m_progress)
        m_progress->onCancel([this] { cancelReading(); }); // the child process ends at once
}

void CadFileController::readFinished()
{
    m_progress.reset();
    // Unless another body, axis or end is asked of it below, the reader is done with the file.
    const auto closeReader = qScopeGuard([this] {
        if (!m_reader.isRunning())
            m_reader.close();
    });
    const CadImportResult result = m_reader.result();
    const QString name = QFileInfo(m_path).fileName();
    if (result.cancelled || m_cancelRequested) {
        Q_EMIT statusMessage(tr("Import of %1 cancelled; the project is unchanged.").arg(name));
        Q_EMIT importFinished(false, tr("Import of %1 cancelled.").arg(name), {});
        return;
    }
    if (!result.profile || hasErrors(result.diagnostics)) {
        m_prompts.showError(
            tr("Cannot import %1").arg(name),
            tr("The part was not imported; the current project is unchanged.\n\n%1").arg(joined(result.diagnostics)));
        Q_EMIT importFinished(false, tr("%1 could not be imported:").arg(name), result.diagnostics);
        return;
    }
    if (m_confirmed) {
        openImported(result);
        return;
    }
    const std::optional<CadImportChoice> choice = m_prompts.confirmImport(name, result);
    if (!choice) {
        Q_EMIT importFinished(false, tr("Import of %1 cancelled.").arg(name), {});
        return;
    }
    if (choice->solid == result.chosenSolid && choice->axis == result.chosenAxis && !choice->flip) {
        openImported(result);
        return;
    }
    // Another body, axis or end: extracted from what the reader has read (the file is not parsed
    // again).
    m_confirmed = true;
    CadImportOptions options;
    options.solidIndex = choice->solid;
    options.axisIndex = choice->axis;
    options.flip = choice->flip;
    m_cancelRequested = false;
    showProgress(tr("Extracting the part from %1…").arg(name));
    m_reader.choose(options);
}

void CadFileController::openImported(const CadImportResult &result)
{
    const QString name = QFileInfo(m_path).fileName();
    if (!m_files.maybeSave()) {
        Q_EMIT importFinished(false, tr("Import of %1 cancelled.").arg(name), {});
        return;
    }
    PartProfile part = *result.profile;
    if (part.name.isEmpty())
        part.name = QFileInfo(m_path).completeBaseName();
    // A new project: the milled features are those of the file (the open project's go with it).
    Project project = projectForPart(std::move(part));
    project.milledFeatures = result.milledFeatures;
    m_document.load(std::move(project), QString());
    const int warnings = countOf(result.diagnostics, Severity::Warning);
    Q_EMIT statusMessage(tr("Imported %1: %2 outer and %3 inner features, %4 warning(s); set material, machine, "
                            "tool and clamping, then save.")
                             .arg(name)
                             .arg(m_document.project().part.outer.segments.size())
                             .arg(m_document.project().part.inner.segments.size())
                             .arg(warnings));
    Q_EMIT importFinished(true, tr("Imported from %1; left out or noted:").arg(name), result.diagnostics);
}

bool CadFileController::exportStep()
{
    if (!m_document.hasProject())
        return false;
    const QString path = m_prompts.chooseStepExportFile(suggestedExportPath(m_document, QStringLiteral("step")));
    return !path.isEmpty() && exportStepTo(withDefaultSuffix(path, QStringLiteral("step")));
}

bool CadFileController::exportStepTo(const QString &path)
{
    if (!m_document.hasProject())
        return false;
    const StepExportResult result = exportProfileToStep(m_document.project().part, path);
    if (!result.ok) {
        m_prompts.showError(tr("Cannot export %1").arg(QFileInfo(path).fileName()), result.error);
        return false;
    }
    Q_EMIT statusMessage(tr("Exported the part as a revolved solid to %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

} // namespace tolturn
