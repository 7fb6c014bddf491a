// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli calibrate-stiffness (docs/cli.md): the spindle–chuck springs of a lathe from a
// measured test bar (Valiño et al. 2008 §III).
#pragma once

#include <QStringList>

class QTextStream;

namespace tolturn {

[[nodiscard]] QString calibrateStiffnessSynopsis();
[[nodiscard]] QString calibrateStiffnessSummary();
// Fits k1, k2, k3 to a test bar's measured deviation. args[0] is "tolturn-cli calibrate-stiffness".
int runCalibrateStiffness(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
