// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli report (docs/cli.md).
#pragma once

#include <QStringList>

class QTextStream;

namespace tolturn {

int runReport(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
