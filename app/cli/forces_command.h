// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli forces (docs/cli.md).
#pragma once

#include <QStringList>

class QTextStream;

namespace tolturn {

int runCalibrateForces(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
