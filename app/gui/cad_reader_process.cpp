// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/cad_reader_process.h"

#include "core/io/cad_import_json.h"
#include "core/io/project_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QStandardPaths>

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {

QString &programOverride()
{
    static QString program;
    return program;
}

// A document of results is far below this; more is not an import's output.
constexpr qint64 kMaxOutputBytes = 16LL * 1024 * 1024;

} // namespace

CadReaderProcess::CadReaderProcess(QObject *parent) : QObject(parent) {}

CadReaderProcess::~CadReaderProcess()
{
    if (m_process) {
        m_process->disconnect(this);
        if (childAlive()) {
            m_process->kill();
            m_process->waitForFinished(5000);
        }
    }
}

QString CadReaderProcess::defaultProgram()
{
    if (!programOverride().isEmpty())
        return programOverride();
    const QString found =
        QStandardPaths::findExecutable(QStringLiteral("tolturn-cli"), {QCoreApplication::applicationDirPath()});
    return found.isEmpty() ? QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("tolturn-cli"))
                           : found;
}

void CadReaderProcess::setDefaultProgram(const QString &program)
{
    programOverride() = program;
}

bool CadReaderProcess::isRunning() const
{
    return m_busy;
}

bool CadReaderProcess::childAlive() const
{
    return m_process && m_process->state() != QProcess::NotRunning;
}

void CadReaderProcess::retireProcess()
{
    if (!m_process)
        return;
    m_process->disconnect(this);
    if (m_process->state() != QProcess::NotRunning) {
        m_process->kill();
        m_process->waitForFinished(5000);
    }
    m_process.release()->deleteLater();
}

void CadReaderProcess::start(const QString &path, const CadImportOptions &options)
{
    m_path = path;
    m_choice.reset();
    m_result = {};
    m_busy = true;
    m_cancelled = false;
    m_stderr.clear();
    m_pending.clear();
    m_results.clear();
    m_folder = std::make_unique<QTemporaryDir>();
    const QString program = defaultProgram();
    if (!QFileInfo(program).isExecutable()) {
        failed(tr("The CAD reader '%1' is missing: TolTurn reads STEP and IGES files with tolturn-cli, which is "
                  "installed beside it. Install TolTurn again.")
                   .arg(QDir::toNativeSeparators(program)));
        return;
    }
    if (!m_folder->isValid()) {
        failed(tr("No temporary folder for the import: %1").arg(m_folder->errorString()));
        return;
    }
    QStringList args{QStringLiteral("import"),     QStringLiteral("--json"),
                     QStringLiteral("--progress"), QStringLiteral("--choose"),
                     QStringLiteral("-o"),         m_folder->filePath(QStringLiteral("imported.tolturn"))};
    if (options.solidIndex >= 0)
        args << QStringLiteral("--solid") << QString::number(options.solidIndex);
    if (options.axisIndex >= 0)
        args << QStringLiteral("--axis") << QString::number(options.axisIndex);
    if (options.flip)
        args << QStringLiteral("--flip");
    args << QStringLiteral("--") << path;
    // The previous child's QProcess may be the sender of the finished() this is called from (a
    // second read with the planner's choice): let it go once control is back in the event loop.
    retireProcess();
    m_process = std::make_unique<QProcess>();
    connect(m_process.get(), &QProcess::readyReadStandardError, this, &CadReaderProcess::readProgress);
    connect(m_process.get(), &QProcess::readyReadStandardOutput, this, &CadReaderProcess::readResults);
    connect(m_process.get(), &QProcess::finished, this, &CadReaderProcess::processFinished);
    connect(m_process.get(), &QProcess::errorOccurred, this, [this](QProcess::ProcessError error) {
        if (error == QProcess::FailedToStart && m_cancelled) {
            m_busy = false;
            m_result = {};
            m_result.cancelled = true;
            QMetaObject::invokeMethod(this, &CadReaderProcess::finished, Qt::QueuedConnection);
        } else if (error == QProcess::FailedToStart)
            failed(tr("The CAD reader '%1' could not be started: %2")
                       .arg(QDir::toNativeSeparators(m_process->program()), m_process->errorString()));
    });
    m_process->start(program, args);
}

void CadReaderProcess::choose(const CadImportOptions &options)
{
    if (m_busy)
        return;
    if (!childAlive()) { // it ended (or was never asked to wait): read the file again
        start(m_path, options);
        return;
    }
    m_result = {};
    m_busy = true;
    m_cancelled = false;
    m_stderr.clear();
    m_choice = options;
    const QByteArray line = QByteArray::number(options.solidIndex) + ' ' + QByteArray::number(options.axisIndex) + ' ' +
                            (options.flip ? "1" : "0") + '\n';
    m_process->write(line);
}

void CadReaderProcess::close()
{
    if (childAlive() && !m_busy)
        m_process->closeWriteChannel(); // the child ends at the end of its input
}

void CadReaderProcess::cancel()
{
    if (!m_busy || !childAlive())
        return;
    m_cancelled = true;
    m_process->kill(); // finished() follows
}

void CadReaderProcess::readProgress()
{
    m_pending += m_process->readAllStandardError();
    if (m_pending.size() > kMaxOutputBytes) // a line without end: not the reader's output
        m_pending = m_pending.right(kMaxOutputBytes);
    qsizetype end = 0;
    while ((end = m_pending.indexOf('\n')) >= 0) {
        const QByteArray line = m_pending.left(end).trimmed();
        m_pending.remove(0, end + 1);
        bool ok = false;
        const double fraction = line.startsWith("progress ") ? line.mid(9).toDouble(&ok) : 0.0;
        if (ok && std::isfinite(fraction))
            Q_EMIT progress(std::clamp(fraction, 0.0, 1.0));
        else if (m_stderr.size() < kMaxOutputBytes)
            m_stderr += line + '\n';
    }
}

QString CadReaderProcess::stderrText() const
{
    return QString::fromUtf8(m_stderr + m_pending).trimmed();
}

void CadReaderProcess::failed(const QString &message)
{
    m_busy = false;
    m_result = {};
    m_result.diagnostics.push_back(makeError(QStringLiteral("file"), message));
    // Always after start() has returned, as for a child that runs.
    QMetaObject::invokeMethod(this, &CadReaderProcess::finished, Qt::QueuedConnection);
}

void CadReaderProcess::takeWrittenPart(bool written)
{
    if (!written) {
        // Refused after the import itself (the project could not be written): say why.
        if (!hasErrors(m_result.diagnostics))
            m_result.diagnostics.push_back(makeError(QStringLiteral("file"), stderrText()));
        return;
    }
    const ProjectParseResult project = readProjectFile(m_folder->filePath(QStringLiteral("imported.tolturn")));
    if (project.project)
        m_result.profile = project.project->part;
    else
        m_result.diagnostics.insert(m_result.diagnostics.end(), project.diagnostics.begin(), project.diagnostics.end());
}

void CadReaderProcess::readResults()
{
    m_results += m_process->readAllStandardOutput();
    if (m_results.size() > kMaxOutputBytes) { // not the reader's output
        m_process->kill();
        return;
    }
    qsizetype end = 0;
    while (m_busy && (end = m_results.indexOf('\n')) >= 0) {
        const QByteArray line = m_results.left(end);
        m_results.remove(0, end + 1);
        takeResult(line, 0);
    }
}

void CadReaderProcess::takeResult(const QByteArray &json, int exitCode)
{
    QJsonParseError error{};
    const QJsonDocument document = QJsonDocument::fromJson(json, &error);
    QString problem;
    std::optional<CadImportResult> read;
    if (error.error == QJsonParseError::NoError && document.isObject())
        read = cadImportResultFromJson(document.object(), &problem);
    if (!read) {
        failed(tr("The CAD reader gave no result for %1 (exit code %2): %3 %4")
                   .arg(QFileInfo(m_path).fileName())
                   .arg(exitCode)
                   .arg(problem.isEmpty() ? error.errorString() : problem, stderrText()));
        return;
    }
    m_busy = false;
    m_choice.reset();
    m_result = std::move(*read);
    takeWrittenPart(document.object().value(QStringLiteral("written")).toBool());
    Q_EMIT finished();
}

void CadReaderProcess::processFinished(int exitCode, QProcess::ExitStatus status)
{
    readProgress();
    if (!m_busy) // it ended after its last result: at the end of its input, or on its own
        return;
    readResults();
    if (!m_busy)
        return;
    const QString name = QFileInfo(m_path).fileName();
    if (m_cancelled) {
        m_busy = false;
        m_result = {};
        m_result.cancelled = true;
        Q_EMIT finished();
        return;
    }
    if (status == QProcess::CrashExit) {
        failed(tr("Reading %1 ended the CAD reader (OpenCascade) abnormally; the program and the project are not "
                  "affected. The file is probably damaged: check it in the CAD system that wrote it.%2")
                   .arg(name, stderrText().isEmpty() ? QString() : QStringLiteral("\n") + stderrText()));
        return;
    }
    if (m_choice && m_results.trimmed().isEmpty() && exitCode == 0) {
        // It ended before it read the choice (its input closed, or it stopped on its own): read
        // the file again with the choice.
        const CadImportOptions choice = *m_choice;
        m_busy = false;
        start(m_path, choice);
        return;
    }
    takeResult(m_results, exitCode); // a reader that wrote its result without an end of line
}

} // namespace tolturn
