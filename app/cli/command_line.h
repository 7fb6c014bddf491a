// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>

class QTextStream;

namespace tolturn {

// Exit codes of tolturn-cli (docs/cli.md).
enum CliExit : int {
    kExitOk = 0,
    kExitProblems = 1, // the input was read but has errors (validation failed)
    kExitUsage = 2,    // the command line itself is wrong
};

// The synopsis and one-line summary of a command of the table (for its --help).
struct CommandHelp {
    QString synopsis;
    QString summary;
};

[[nodiscard]] CommandHelp commandHelp(const QString &name);

// Runs tolturn-cli with `arguments` (arguments[0] is the program name). Results go to `out`,
// messages and problems to `err`. Needs a QCoreApplication.
int runCommandLine(const QStringList &arguments, QTextStream &out, QTextStream &err);

} // namespace tolturn
