// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/learning/measured_residuals.h"

#include <QJsonObject>
#include <QString>

#include <optional>

namespace tolturn {

// What was learned of a machine as JSON, to be kept in the measurement store: the geometric
// error's plane and the network (scaling, centres, radii, weights, and its figures).
[[nodiscard]] QJsonObject learnedResidualJson(const LearnedResidual &learned);

// The spans a model was learned at ("learned_from" in its JSON), each key a [min, max] pair:
// spindle_speed_rpm, feed_mm_rev, passive_force_N, time_since_start_min, ambient_C, diameter_mm,
// z_mm.
[[nodiscard]] QJsonObject learnedDomainJson(const LearnedDomain &domain);

// Back from JSON; empty, with `error` naming the field, when a value is missing, not finite or of
// the wrong size.
[[nodiscard]] std::optional<LearnedResidual> learnedResidualFromJson(const QJsonObject &json, QString *error);

} // namespace tolturn
