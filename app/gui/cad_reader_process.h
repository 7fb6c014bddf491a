// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/cad/step_import.h"

#include <QObject>
#include <QProcess>
#include <QTemporaryDir>

#include <memory>
#include <optional>

namespace tolturn {

// Reads a STEP or IGES file in a child process: `tolturn-cli import --json --progress --choose`, the
// part written to a temporary project file and read back. OpenCascade's translators run on data they
// trust; whatever a file makes them do (a fault the signal guard cannot turn into an error, a
// loop, memory without end), it happens in the child, and the window, the document and the
// unsaved work go on. Cancel ends the child at once, in any phase of the import. The child keeps
// what it read until close(): choose() extracts another body, axis or end without parsing the file
// again (EXAMPLES.md item 3).
class CadReaderProcess : public QObject {
    Q_OBJECT
public:
    explicit CadReaderProcess(QObject *parent = nullptr);
    ~CadReaderProcess() override;

    // The reader: tolturn-cli beside the running program (both are installed in one folder).
    [[nodiscard]] static QString defaultProgram();
    // For a program that is not installed beside tolturn-cli (the tests).
    static void setDefaultProgram(const QString &program);

    // Starts reading `path` with `options` (their progress callback is not used: see progress()).
    void start(const QString &path, const CadImportOptions &options);
    // After finished(): the body, axis and end of `options` from the file already read (read
    // again when the child has ended). finished() follows.
    void choose(const CadImportOptions &options);
    // No more choices: the child ends.
    void close();
    void cancel();
    // From start() or choose() until finished().
    [[nodiscard]] bool isRunning() const;

    // The result once finished() was emitted.
    [[nodiscard]] const CadImportResult &result() const { return m_result; }

Q_SIGNALS:
    void progress(double fraction);
    void finished();

private:
    void retireProcess();
    [[nodiscard]] bool childAlive() const;
    void readProgress();
    // Each line of standard output is the result of a read or a choice.
    void readResults();
    void takeResult(const QByteArray &json, int exitCode);
    void processFinished(int exitCode, QProcess::ExitStatus status);
    void failed(const QString &message);
    // The part from the project file the child wrote, or why there is none.
    void takeWrittenPart(bool written);
    [[nodiscard]] QString stderrText() const;

    std::unique_ptr<QProcess> m_process;
    std::unique_ptr<QTemporaryDir> m_folder;
    QString m_path;
    QByteArray m_stderr;                      // every line but the progress ones, for the message when the child fails
    QByteArray m_pending;                     // an incomplete line of standard error
    QByteArray m_results;                     // standard output not yet taken
    bool m_busy = false;                      // a read or a choice runs
    std::optional<CadImportOptions> m_choice; // the choice sent to the child and not answered yet
    bool m_cancelled = false;
    CadImportResult m_result;
};

} // namespace tolturn
