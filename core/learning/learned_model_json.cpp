// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/learning/learned_model_json.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <cmath>

namespace tolturn {

namespace {

struct LearnedModelJson {
    Q_DECLARE_TR_FUNCTIONS(LearnedModelJson)
};

QJsonArray vectorJson(const Eigen::VectorXd &v)
{
    QJsonArray a;
    for (Eigen::Index i = 0; i < v.size(); ++i)
        a.append(v[i]);
    return a;
}

QJsonArray matrixJson(const Eigen::MatrixXd &m)
{
    QJsonArray rows;
    for (Eigen::Index r = 0; r < m.rows(); ++r)
        rows.append(vectorJson(m.row(r).transpose()));
    return rows;
}

std::optional<Eigen::VectorXd> vectorFrom(const QJsonValue &value, Eigen::Index size)
{
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

std::optional<Eigen::MatrixXd> matrixFrom(const QJsonValue &value, Eigen::Index rows, Eigen::Index cols)
{
    const QJsonArray a = value.toArray();
    if (a.size() != rows)
        return std::nullopt;
    Eigen::MatrixXd m(rows, cols);
    for (Eigen::Index r = 0; r < rows; ++r) {
        const auto row = vectorFrom(a.at(r), cols);
        if (!row)
            return std::nullopt;
        m.row(r) = row->transpose();
    }
    return m;
}

} // namespace

QJsonObject learnedResidualJson(const LearnedResidual &learned)
{
    QJsonObject json{
        {QStringLiteral("geometric"), QJsonObject{{QStringLiteral("per_diameter"), learned.geometric.perDiameter},
                                                  {QStringLiteral("per_z"), learned.geometric.perZ},
                                                  {QStringLiteral("offset_mm"), learned.geometric.offset_mm}}}};
    if (learned.network) {
        const RbfNetwork &n = *learned.network;
        json.insert(QStringLiteral("network"), QJsonObject{{QStringLiteral("input_min"), vectorJson(n.inputMin)},
                                                           {QStringLiteral("input_span"), vectorJson(n.inputSpan)},
                                                           {QStringLiteral("centres"), matrixJson(n.centres)},
                                                           {QStringLiteral("radii"), matrixJson(n.radii)},
                                                           {QStringLiteral("weights"), vectorJson(n.weights)},
                                                           {QStringLiteral("radius_scale"), n.radiusScale},
                                                           {QStringLiteral("tree_nodes"), n.treeNodes},
                                                           {QStringLiteral("criterion"), n.criterion},
                                                           {QStringLiteral("training_rms_mm"), n.trainingRms},
                                                           {QStringLiteral("leave_one_out_rms_mm"), n.leaveOneOutRms}});
    }
    return json;
}

std::optional<LearnedResidual> learnedResidualFromJson(const QJsonObject &json, QString *error)
{
    const auto refuse = [error](const QString &field) -> std::optional<LearnedResidual> {
        if (error)
            *error = LearnedModelJson::tr("the learned model has no valid \"%1\"").arg(field);
        return std::nullopt;
    };
    LearnedResidual learned;
    const QJsonObject g = json.value(QStringLiteral("geometric")).toObject();
    for (const char *key : {"per_diameter", "per_z", "offset_mm"}) {
        if (!g.value(QLatin1String(key)).isDouble() || !std::isfinite(g.value(QLatin1String(key)).toDouble()))
            return refuse(QStringLiteral("geometric.") + QLatin1String(key));
    }
    learned.geometric = {g.value(QStringLiteral("per_diameter")).toDouble(),
                         g.value(QStringLiteral("per_z")).toDouble(), g.value(QStringLiteral("offset_mm")).toDouble()};
    if (!json.contains(QStringLiteral("network")))
        return learned;
    const QJsonObject n = json.value(QStringLiteral("network")).toObject();
    constexpr Eigen::Index kInputs = 8; // ResidualSample::inputs
    const auto m = static_cast<Eigen::Index>(n.value(QStringLiteral("weights")).toArray().size());
    RbfNetwork net;
    const auto inputMin = vectorFrom(n.value(QStringLiteral("input_min")), kInputs);
    const auto inputSpan = vectorFrom(n.value(QStringLiteral("input_span")), kInputs);
    const auto centres = matrixFrom(n.value(QStringLiteral("centres")), m, kInputs);
    const auto radii = matrixFrom(n.value(QStringLiteral("radii")), m, kInputs);
    const auto weights = vectorFrom(n.value(QStringLiteral("weights")), m);
    if (!inputMin)
        return refuse(QStringLiteral("network.input_min"));
    if (!inputSpan || (inputSpan->array() <= 0.0).any())
        return refuse(QStringLiteral("network.input_span"));
    if (!centres)
        return refuse(QStringLiteral("network.centres"));
    if (!radii || (radii->array() <= 0.0).any())
        return refuse(QStringLiteral("network.radii"));
    if (m < 1 || !weights)
        return refuse(QStringLiteral("network.weights"));
    net.inputMin = *inputMin;
    net.inputSpan = *inputSpan;
    net.centres = *centres;
    net.radii = *radii;
    net.weights = *weights;
    net.radiusScale = n.value(QStringLiteral("radius_scale")).toDouble();
    net.treeNodes = n.value(QStringLiteral("tree_nodes")).toInt();
    net.criterion = n.value(QStringLiteral("criterion")).toDouble();
    net.trainingRms = n.value(QStringLiteral("training_rms_mm")).toDouble();
    net.leaveOneOutRms = n.value(QStringLiteral("leave_one_out_rms_mm")).toDouble();
    learned.network = std::move(net);
    return learned;
}

} // namespace tolturn
