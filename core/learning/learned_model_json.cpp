// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/learning/learned_model_json.h"

#include "core/learning/rbf_json.h"

#include <QCoreApplication>

#include <cmath>

namespace tolturn {

namespace {

struct LearnedModelJson {
    Q_DECLARE_TR_FUNCTIONS(LearnedModelJson)
};

} // namespace

QJsonObject learnedResidualJson(const LearnedResidual &learned)
{
    QJsonObject json{
        {QStringLiteral("geometric"), QJsonObject{{QStringLiteral("per_diameter"), learned.geometric.perDiameter},
                                                  {QStringLiteral("per_z"), learned.geometric.perZ},
                                                  {QStringLiteral("offset_mm"), learned.geometric.offset_mm}}}};
    if (learned.network) {
        json.insert(QStringLiteral("network"), rbfNetworkJson(*learned.network, QStringLiteral("mm")));
    }
    if (learned.learnedAgainst)
        json.insert(QStringLiteral("learned_against_characterisation"), *learned.learnedAgainst);
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
    if (const QJsonValue basis = json.value(QStringLiteral("learned_against_characterisation")); basis.isObject())
        learned.learnedAgainst = basis.toObject();
    else if (!basis.isUndefined())
        return refuse(QStringLiteral("learned_against_characterisation"));
    if (!json.contains(QStringLiteral("network")))
        return learned;
    constexpr Eigen::Index kInputs = 8; // ResidualSample::inputs
    QString field;
    auto net =
        rbfNetworkFromJson(json.value(QStringLiteral("network")).toObject(), kInputs, QStringLiteral("mm"), field);
    if (!net)
        return refuse(QStringLiteral("network.") + field);
    learned.network = std::move(*net);
    return learned;
}

} // namespace tolturn
