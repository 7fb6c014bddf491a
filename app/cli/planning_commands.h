// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli planning (docs/cli.md).
#pragma once

#include <QStringList>

class QTextStream;

namespace tolturn {

int runOptimize(const QStringList &args, QTextStream &out, QTextStream &err);
int runWindow(const QStringList &args, QTextStream &out, QTextStream &err);
int runAdviseClamping(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
