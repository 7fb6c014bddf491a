// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/learning/learned_model_json.h"

#include "core/learning/rbf_json.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <array>
#include <cmath>
#include <utility>

namespace tolturn {

namespace {

struct LearnedModelJson {
    Q_DECLARE_TR_FUNCTIONS(LearnedModelJson)
};

// The keys of LearnedDomain in the model's "learned_from" object, each a [min, max] pair.
constexpr std::array<std::pair<const char *, LearnedDomain::Span LearnedDomain::*>, 7> kDomainKeys{{
    {"spindle_speed_rpm", &LearnedDomain::spindleSpeed_rpm},
    {"feed_mm_rev", &LearnedDomain::feed_mm_rev},
    {"passive_force_N", &LearnedDomain::passiveForce_N},
    {"time_since_start_min", &LearnedDomain::timeSinceStart_min},
    {"ambient_C", &LearnedDomain::ambient_C},
    {"diameter_mm", &LearnedDomain::diameter_mm},
    {"z_mm", &LearnedDomain::z_mm},
}};

// Empty with `field` naming the key that is not a [min, max] pair of finite numbers, min <= max.
std::optional<LearnedDomain> domainFromJson(const QJsonObject &json, QString &field)
{
    LearnedDomain domain;
    for (const auto &[key, span] : kDomainKeys) {
        const QJsonArray pair = json.value(QLatin1String(key)).toArray();
        const double min = pair.at(0).toDouble(std::nan(""));
        const double max = pair.at(1).toDouble(std::nan(""));
        if (pair.size() != 2 || !std::isfinite(min) || !std::isfinite(max) || min > max) {
            field = QLatin1String(key);
            return std::nullopt;
        }
        domain.*span = {min, max};
    }
    return domain;
}

} // namespace

QJsonObject learnedDomainJson(const LearnedDomain &domain)
{
    QJsonObject json;
    for (const auto &[key, span] : kDomainKeys)
        json.insert(QLatin1String(key), QJsonArray{(domain.*span).min, (domain.*span).max});
    return json;
}

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
    if (learned.learnedFrom)
        json.insert(QStringLiteral("learned_from"), learnedDomainJson(*learned.learnedFrom));
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
    if (const QJsonValue from = json.value(QStringLiteral("learned_from")); !from.isUndefined()) {
        QString key;
        learned.learnedFrom = domainFromJson(from.toObject(), key);
        if (!learned.learnedFrom)
            return refuse(QStringLiteral("learned_from.") + key);
    }
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
