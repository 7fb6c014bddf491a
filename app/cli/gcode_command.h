// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli gcode (docs/cli.md): the turning program of a project for a lathe control.
#pragma once

#include <QStringList>

class QTextStream;

namespace tolturn {

[[nodiscard]] QString gcodeSynopsis();
[[nodiscard]] QString gcodeSummary();
// Writes the program of a project. args[0] is "tolturn-cli gcode".
int runGCode(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
