// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/cad_import_json.h"

#include "core/io/json_reader.h"
#include "core/io/project_json.h"

#include <QCoreApplication>
#include <QJsonArray>

namespace tolturn {

namespace {

struct CadImportJson {
    Q_DECLARE_TR_FUNCTIONS(CadImportJson)
};

QJsonArray vectorJson(const double (&v)[3])
{
    return {v[0], v[1], v[2]};
}

bool readVector(const QJsonValue &value, double (&v)[3])
{
    const QJsonArray a = value.toArray();
    if (a.size() != 3)
        return false;
    for (int i = 0; i < 3; ++i) {
        if (!a.at(i).isDouble())
            return false;
        v[i] = a.at(i).toDouble();
    }
    return true;
}

// The features of "milled_features" as the project file holds them (absent: none); the first
// finding of the project reader, empty when there is none.
QString readMilledFeatures(const QJsonValue &value, std::vector<MilledFeature> &features)
{
    const QString key = QStringLiteral("milled_features");
    if (value.isUndefined())
        return {};
    if (!value.isArray())
        return CadImportJson::tr("%1: expected an array, found %2").arg(key, describeJsonValue(value));
    const QJsonArray list = value.toArray();
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString path = elementPath(key, i);
        if (!list.at(i).isObject())
            return CadImportJson::tr("%1: expected an object, found %2").arg(path, describeJsonValue(list.at(i)));
        Diagnostics problems;
        features.push_back(milledFeatureFromJson(list.at(i).toObject(), path, problems));
        if (!problems.empty())
            return problems.front().toString();
    }
    return {};
}

} // namespace

QJsonObject cadImportJson(const CadImportResult &r)
{
    QJsonArray solids;
    for (const CadSolidInfo &s : r.solids)
        solids.append(
            QJsonObject{{QStringLiteral("volume_mm3"), s.volume_mm3}, {QStringLiteral("faces"), s.faceCount}});
    QJsonArray axes;
    for (const CadAxisInfo &a : r.axes)
        axes.append(QJsonObject{{QStringLiteral("origin_mm"), vectorJson(a.origin_mm)},
                                {QStringLiteral("direction"), vectorJson(a.direction)},
                                {QStringLiteral("revolved_area_mm2"), a.revolvedArea_mm2},
                                {QStringLiteral("faces"), a.faceCount}});
    QJsonArray diagnostics;
    for (const Diagnostic &d : r.diagnostics)
        diagnostics.append(diagnosticJson(d));
    QJsonArray milled;
    for (const MilledFeature &f : r.milledFeatures)
        milled.append(milledFeatureJson(f));
    return {{QStringLiteral("solids"), solids},
            {QStringLiteral("chosen_solid"), r.chosenSolid},
            {QStringLiteral("axes"), axes},
            {QStringLiteral("chosen_axis"), r.chosenAxis},
            {QStringLiteral("milled_features"), milled},
            {QStringLiteral("diagnostics"), diagnostics}};
}

std::optional<CadImportResult> cadImportResultFromJson(const QJsonObject &json, QString *error)
{
    const auto refuse = [error](const QString &key) {
        if (error)
            *error = CadImportJson::tr("the import's result has no valid \"%1\"").arg(key);
        return std::nullopt;
    };
    CadImportResult r;
    for (const char *key : {"solids", "axes", "diagnostics"}) {
        if (!json.value(QLatin1String(key)).isArray())
            return refuse(QLatin1String(key));
    }
    for (const auto &v : json.value(QStringLiteral("solids")).toArray())
        r.solids.push_back({v[QStringLiteral("volume_mm3")].toDouble(), v[QStringLiteral("faces")].toInt()});
    for (const auto &v : json.value(QStringLiteral("axes")).toArray()) {
        CadAxisInfo a;
        if (!readVector(v[QStringLiteral("origin_mm")], a.origin_mm) ||
            !readVector(v[QStringLiteral("direction")], a.direction))
            return refuse(QStringLiteral("axes"));
        a.revolvedArea_mm2 = v[QStringLiteral("revolved_area_mm2")].toDouble();
        a.faceCount = v[QStringLiteral("faces")].toInt();
        r.axes.push_back(a);
    }
    for (const auto &v : json.value(QStringLiteral("diagnostics")).toArray())
        r.diagnostics.push_back(diagnosticFromJson(v.toObject()));
    if (const QString problem = readMilledFeatures(json.value(QStringLiteral("milled_features")), r.milledFeatures);
        !problem.isEmpty()) {
        if (error)
            *error = CadImportJson::tr("the import's result has no valid \"milled_features\": %1").arg(problem);
        return std::nullopt;
    }
    r.chosenSolid = json.value(QStringLiteral("chosen_solid")).toInt(-1);
    r.chosenAxis = json.value(QStringLiteral("chosen_axis")).toInt(-1);
    if (r.chosenSolid >= static_cast<int>(r.solids.size()))
        return refuse(QStringLiteral("chosen_solid"));
    if (r.chosenAxis >= static_cast<int>(r.axes.size()))
        return refuse(QStringLiteral("chosen_axis"));
    return r;
}

} // namespace tolturn
