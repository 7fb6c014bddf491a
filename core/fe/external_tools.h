// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The external engines of the solid check (docs/solid-fe.md): gmsh meshes, CalculiX solves.
// Each is looked up on PATH, or where an environment variable points (for a build of one's own,
// and for the tests of a missing engine).

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <functional>

namespace tolturn {

struct ExternalTool {
    QString name;        // "gmsh", "CalculiX"
    QString executable;  // what is looked for: "gmsh", "ccx"
    QString package;     // the Debian package that has it
    QString envVariable; // overrides the search: TOLTURN_GMSH, TOLTURN_CCX
    QString path;        // where it was found; empty: not found

    [[nodiscard]] bool found() const { return !path.isEmpty(); }

    // What to do when it is missing, naming where it was looked for and how to install it.
    [[nodiscard]] QString missingMessage() const;
};

[[nodiscard]] ExternalTool findGmsh();
[[nodiscard]] ExternalTool findCalculix();

struct ProcessRun {
    bool cancelled = false;
    bool crashed = false; // did not start, or ended by a signal
    int exitCode = 0;
    QByteArray output; // standard output and error, merged
};

// Runs `program` in `workingDirectory` with `environment` ("NAME=value") added to this process's,
// and waits for it, calling `keepGoing` with each piece of output as it comes (and every 100 ms);
// when that returns false the process is killed and the run is `cancelled`.
[[nodiscard]] ProcessRun runExternal(const QString &program, const QStringList &arguments,
                                     const QString &workingDirectory, const QStringList &environment,
                                     const std::function<bool(const QByteArray &)> &keepGoing);

} // namespace tolturn
