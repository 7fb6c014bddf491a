// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli import and export-step (docs/cli.md): STEP/IGES in, revolved STEP solid out.
#pragma once

#include <QStringList>

class QTextStream;

namespace tolturn {

[[nodiscard]] QString importSynopsis();
[[nodiscard]] QString importSummary();
// Imports a STEP or IGES file into a new project file. args[0] is "tolturn-cli import".
int runImport(const QStringList &args, QTextStream &out, QTextStream &err);

[[nodiscard]] QString exportStepSynopsis();
[[nodiscard]] QString exportStepSummary();
// Writes a project's part as a revolved solid to STEP. args[0] is "tolturn-cli export-step".
int runExportStep(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
