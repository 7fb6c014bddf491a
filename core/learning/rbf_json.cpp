// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/learning/rbf_json.h"

#include <QJsonArray>

#include <cmath>

namespace tolturn {

namespace {

QJsonArray matrixJson(const Eigen::MatrixXd &m)
{
    QJsonArray rows;
    for (Eigen::Index r = 0; r < m.rows(); ++r)
        rows.append(vectorJson(m.row(r).transpose()));
    return rows;
}

std::optional<Eigen::MatrixXd> matrixFrom(const QJsonValue &value, Eigen::Index rows, Eigen::Index cols)
{
    if (!value.isArray())
        return std::nullopt;
    const QJsonArray a = value.toArray();
    if (a.size() != rows)
        return std::nullopt;
    Eigen::MatrixXd m(rows, cols);
    for (Eigen::Index r = 0; r < rows; ++r) {
        const auto row = vectorFromJson(a.at(r), cols);
        if (!row)
            return std::nullopt;
        m.row(r) = row->transpose();
    }
    return m;
}

} // namespace

QJsonArray vectorJson(const Eigen::VectorXd &v)
{
    QJsonArray a;
    for (Eigen::Index i = 0; i < v.size(); ++i)
        a.append(v[i]);
    return a;
}

std::optional<Eigen::VectorXd> vectorFromJson(const QJsonValue &value, Eigen::Index size)
{
    if (!value.isArray())
        return std::nullopt;
    const QJsonArray a = value.toArray();
    if (a.size() != size)
        return std::nullopt;
    Eigen::VectorXd v(size);
    for (Eigen::Index i = 0; i < size; ++i) {
        if (!a.at(i).isDouble() || !std::isfinite(a.at(i).toDouble()))
            return std::nullopt;
        v[i] = a.at(i).toDouble();
    }
    return v;
}

QJsonObject rbfNetworkJson(const RbfNetwork &n, const QString &rmsUnit)
{
    return {{QStringLiteral("input_min"), vectorJson(n.inputMin)},
            {QStringLiteral("input_span"), vectorJson(n.inputSpan)},
            {QStringLiteral("centres"), matrixJson(n.centres)},
            {QStringLiteral("radii"), matrixJson(n.radii)},
            {QStringLiteral("weights"), vectorJson(n.weights)},
            {QStringLiteral("radius_scale"), n.radiusScale},
            {QStringLiteral("tree_nodes"), n.treeNodes},
            {QStringLiteral("criterion"), n.criterion},
            {QStringLiteral("training_rms_") + rmsUnit, n.trainingRms},
            {QStringLiteral("leave_one_out_rms_") + rmsUnit, n.leaveOneOutRms}};
}

std::optional<RbfNetwork> rbfNetworkFromJson(const QJsonObject &n, Eigen::Index inputs, const QString &rmsUnit,
                                             QString &field)
{
    const auto fail = [&field](const char *name) -> std::optional<RbfNetwork> {
        field = QLatin1String(name);
        return std::nullopt;
    };
    const QJsonValue w = n.value(QStringLiteral("weights"));
    const auto m = static_cast<Eigen::Index>(w.toArray().size());
    const auto inputMin = vectorFromJson(n.value(QStringLiteral("input_min")), inputs);
    const auto inputSpan = vectorFromJson(n.value(QStringLiteral("input_span")), inputs);
    const auto centres = matrixFrom(n.value(QStringLiteral("centres")), m, inputs);
    const auto radii = matrixFrom(n.value(QStringLiteral("radii")), m, inputs);
    const auto weights = vectorFromJson(w, m);
    if (!inputMin)
        return fail("input_min");
    if (!inputSpan || (inputSpan->array() <= 0.0).any())
        return fail("input_span");
    if (!centres)
        return fail("centres");
    if (!radii || (radii->array() <= 0.0).any())
        return fail("radii");
    if (m < 1 || !weights)
        return fail("weights");
    RbfNetwork net;
    net.inputMin = *inputMin;
    net.inputSpan = *inputSpan;
    net.centres = *centres;
    net.radii = *radii;
    net.weights = *weights;
    // The network's figures: informational, not needed to predict.
    net.radiusScale = n.value(QStringLiteral("radius_scale")).toDouble();
    net.treeNodes = n.value(QStringLiteral("tree_nodes")).toInt();
    net.criterion = n.value(QStringLiteral("criterion")).toDouble();
    net.trainingRms = n.value(QStringLiteral("training_rms_") + rmsUnit).toDouble();
    net.leaveOneOutRms = n.value(QStringLiteral("leave_one_out_rms_") + rmsUnit).toDouble();
    return net;
}

} // namespace tolturn
