// SPDX-License-Identifier: GPL-3.0-or-later
// Runs tolturn-cli (or another program) as a user does: the real binary, its output streams and
// exit code. Shared by the command-line tests.
#pragma once

#include "tests/examples.h"

#include <QFile>
#include <QProcess>
#include <QString>
#include <QStringList>

namespace tolturn::test {

struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

inline Run runProgram(const QString &program, const QStringList &args)
{
    QProcess process;
    process.start(program, args);
    if (!process.waitForFinished(60000))
        qFatal("%s did not finish", qPrintable(program));
    return {process.exitCode(), QString::fromUtf8(process.readAllStandardOutput()),
            QString::fromUtf8(process.readAllStandardError())};
}

inline Run runCli(const QStringList &args)
{
    return runProgram(QStringLiteral(TOLTURN_CLI_PATH), args);
}

// Writes `content` to `path`; false when the file cannot be written.
[[nodiscard]] inline bool writeFile(const QString &path, const QByteArray &content)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(content) == content.size();
}

// What `path` holds; empty when it cannot be read (compare with a file's bytes before a command).
[[nodiscard]] inline QByteArray fileBytes(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace tolturn::test
