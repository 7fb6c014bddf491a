// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli mill-forces, mill-deflect and mill-optimize: five-axis ball-end milling after Öztürk & Budak
// (docs/cli.md, docs/milling.md).
#pragma once

#include <QString>
#include <QStringList>

class QTextStream;

namespace tolturn {

[[nodiscard]] QString millForcesSynopsis();
[[nodiscard]] QString millForcesSummary();
int runMillForces(const QStringList &args, QTextStream &out, QTextStream &err);

[[nodiscard]] QString millDeflectSynopsis();
[[nodiscard]] QString millDeflectSummary();
int runMillDeflect(const QStringList &args, QTextStream &out, QTextStream &err);

[[nodiscard]] QString millOptimizeSynopsis();
[[nodiscard]] QString millOptimizeSummary();
int runMillOptimize(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
