// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli deflect (docs/cli.md).
#pragma once

#include <QStringList>

class QTextStream;

namespace tolturn {

int runDeflect(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
