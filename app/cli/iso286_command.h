// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli iso286 (docs/cli.md).
#pragma once

#include <QStringList>

class QTextStream;

namespace tolturn {

int runIso286(const QStringList &args, QTextStream &out, QTextStream &err);
int runFit(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
