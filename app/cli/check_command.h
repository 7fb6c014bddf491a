// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli check (docs/cli.md).
#pragma once

#include <QStringList>

class QTextStream;

namespace tolturn {

int runCheck(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
