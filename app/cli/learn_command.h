// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli learn (docs/cli.md): what the measured parts of a machine teach beyond the physics.
#pragma once

#include <QStringList>

class QTextStream;

namespace tolturn {

int runLearn(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace tolturn
