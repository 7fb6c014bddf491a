// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli measurements (docs/cli.md): the measurement history of the machines.
#pragma once

#include <QString>
#include <QStringList>

class QTextStream;

namespace tolturn {

[[nodiscard]] QString measurementsSynopsis();
[[nodiscard]] QString measurementsSummary();
int runMeasurements(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
