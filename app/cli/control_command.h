// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli simulate-control and tune-control (docs/cli.md, docs/adaptive.md).
#pragma once

#include <QString>
#include <QStringList>

class QTextStream;

namespace tolturn {

[[nodiscard]] QString simulateControlSynopsis();
[[nodiscard]] QString simulateControlSummary();
int runSimulateControl(const QStringList &args, QTextStream &out, QTextStream &err);

[[nodiscard]] QString tuneControlSynopsis();
[[nodiscard]] QString tuneControlSummary();
int runTuneControl(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
