// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli verify-fe (docs/cli.md, docs/solid-fe.md).
#pragma once

#include <QString>
#include <QStringList>

class QTextStream;

namespace tolturn {

[[nodiscard]] QString verifyFeSynopsis();
[[nodiscard]] QString verifyFeSummary();
int runVerifyFe(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
