// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The milled features of a project as `evaluate` prints them (docs/cli.md, docs/milling.md): the
// verdict of each against its tolerance, the surface error along its path, what it lacks.

#include "core/milling/milled_features.h"

#include <QJsonArray>

#include <vector>

class QTextStream;

namespace tolturn {

[[nodiscard]] QJsonArray milledFeaturesJson(const Project &project,
                                            const std::vector<MilledFeatureEvaluation> &evaluations);

void printMilledFeatures(const Project &project, const std::vector<MilledFeatureEvaluation> &evaluations,
                         QTextStream &out);

} // namespace tolturn
