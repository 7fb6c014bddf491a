// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli control-example: Čuš & Župerl's end-milling system rebuilt (docs/cli.md,
// docs/adaptive.md §9).
#pragma once

#include <QString>
#include <QStringList>

class QTextStream;

namespace tolturn {

[[nodiscard]] QString controlExampleSynopsis();
[[nodiscard]] QString controlExampleSummary();
int runControlExample(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
