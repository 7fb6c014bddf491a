// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli learn (docs/cli.md): what the measured parts of a machine teach beyond the physics.
#pragma once

#include "core/learning/machine_learning.h"
#include "core/measurements/measurement_store.h"

#include <QStringList>

#include <optional>

class QTextStream;

namespace tolturn {

int runLearn(const QStringList &args, QTextStream &out, QTextStream &err);

// The newest model learned of `project`'s machine in the store named `store` (empty: the default),
// for the commands' --learned; empty after printing why on `err` (no store, no model, a damaged one,
// one learned against another characterisation of the machine than the project's).
[[nodiscard]] std::optional<LoadedModel> loadLearnedModel(const QString &store, const Project &project,
                                                          const QString &command, QTextStream &err);

} // namespace tolturn
