// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/cutting/cutting_forces.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <optional>

class QCommandLineParser;
class QTextStream;

namespace tolturn {

// What every tolturn-cli command shares.
[[nodiscard]] QString programName();

// Parses the options of the command `name` and handles --help (usage `synopsis`, then the
// options). Returns -1 to go on, or the exit code when the command must stop here.
[[nodiscard]] int parseCommand(QCommandLineParser &parser, const QString &name, const QString &synopsis,
                               const QString &summary, const QStringList &args, QTextStream &out, QTextStream &err);

// The forces of --load: "Fr,Ft,Fa" in newtons (radial, tangential, axial); nullopt if malformed.
[[nodiscard]] std::optional<CuttingForces> parseLoad(const QString &text);

// A finding as JSON: {"severity": "error" | "warning", "field": …, "message": …}.
[[nodiscard]] QJsonObject diagnosticJson(const Diagnostic &d);

} // namespace tolturn
