// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli evaluate (docs/cli.md).
#pragma once

#include <QStringList>

class QTextStream;

namespace tolturn {

int runEvaluate(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
