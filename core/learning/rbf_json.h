// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/learning/hybrid_rbf.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QString>

#include <optional>

namespace tolturn {

// A hybrid RBF network as JSON (the learned residual's, the current–force model's): its scaling,
// centres, radii and weights, and its figures, the RMS values named with the unit of the network's
// output (`rmsUnit`: "mm" gives "training_rms_mm" and "leave_one_out_rms_mm").
[[nodiscard]] QJsonObject rbfNetworkJson(const RbfNetwork &network, const QString &rmsUnit);

// Back from JSON, for a network of `inputs` inputs; empty with `field` set to the bad field
// ("weights", "input_span", …) when one is missing, not finite, of the wrong size, or a span or
// radius is not positive.
[[nodiscard]] std::optional<RbfNetwork> rbfNetworkFromJson(const QJsonObject &json, Eigen::Index inputs,
                                                           const QString &rmsUnit, QString &field);

// A vector as a JSON array, and back (empty when not an array of `size` finite numbers).
[[nodiscard]] QJsonArray vectorJson(const Eigen::VectorXd &v);
[[nodiscard]] std::optional<Eigen::VectorXd> vectorFromJson(const QJsonValue &value, Eigen::Index size);

} // namespace tolturn
