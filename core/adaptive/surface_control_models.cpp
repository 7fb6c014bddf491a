// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/adaptive/surface_control_models.h"

#include "core/io/json_reader.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>

#include <array>
#include <cmath>
#include <utility>

namespace tolturn {

namespace {

struct ModelFiles {
    Q_DECLARE_TR_FUNCTIONS(ModelFiles)
};

constexpr std::array kForms{std::pair{ProcessModelForm::Polynomial, "polynomial"},
                            std::pair{ProcessModelForm::Exponential, "exponential"},
                            std::pair{ProcessModelForm::CuttingDynamics, "cutting_dynamics"}};

// How many coefficients a form takes: at least one for a polynomial, exactly 2 and 4 for the others.
bool coefficientCountFits(ProcessModelForm form, std::size_t n)
{
    switch (form) {
    case ProcessModelForm::Polynomial:
        return n >= 1;
    case ProcessModelForm::Exponential:
        return n == 2;
    case ProcessModelForm::CuttingDynamics:
        return n == 4;
    }
    return false;
}

std::optional<ProcessModel> readModel(JsonObjectReader &parent, const QString &key, Diagnostics &out)
{
    const std::optional<QJsonObject> o = parent.object(key, Presence::Required);
    if (!o)
        return std::nullopt;
    JsonObjectReader r(*o, parent.fieldPath(key), out);
    QStringList formNames;
    for (const auto &[form, name] : kForms)
        formNames << QString::fromLatin1(name);
    const std::optional<QString> formName =
        r.keywordText(QStringLiteral("form"), Presence::Required, formNames, ModelFiles::tr("model form"));
    const std::optional<QString> equation = r.text(QStringLiteral("equation"), Presence::Optional);
    const std::optional<QJsonArray> values = r.array(QStringLiteral("coefficients"), Presence::Required);
    r.finish();
    if (!formName || !values)
        return std::nullopt;
    ProcessModel model;
    model.form = kForms.at(static_cast<std::size_t>(formNames.indexOf(*formName))).first;
    model.equation = equation.value_or(QString());
    const QString path = r.fieldPath(QStringLiteral("coefficients"));
    for (qsizetype i = 0; i < values->size(); ++i) {
        const QJsonValue v = values->at(i);
        if (!v.isDouble() || !std::isfinite(v.toDouble())) {
            out.push_back(
                makeError(elementPath(path, i),
                          ModelFiles::tr("a coefficient must be a number, not %1").arg(describeJsonValue(v))));
            return std::nullopt;
        }
        model.coefficients.push_back(v.toDouble());
    }
    if (!coefficientCountFits(model.form, model.coefficients.size())) {
        out.push_back(makeError(path, ModelFiles::tr("a %1 model does not take %n coefficient(s)", nullptr,
                                                     static_cast<int>(model.coefficients.size()))
                                          .arg(*formName)));
        return std::nullopt;
    }
    return model;
}

} // namespace

double ProcessModel::evaluate(double x, double y) const
{
    const std::vector<double> &c = coefficients;
    switch (form) {
    case ProcessModelForm::Polynomial: {
        double sum = 0.0; // Horner
        for (std::size_t i = c.size(); i-- > 0;)
            sum = sum * x + c[i];
        return sum;
    }
    case ProcessModelForm::Exponential:
        return c[0] * std::exp(c[1] * x); // 004 eq. 4
    case ProcessModelForm::CuttingDynamics:
        return c[0] * (1.0 - c[1] * x * x * x - c[2] / y * std::log(c[3] * y)); // 004 eq. 5
    }
    return 0.0;
}

SurfaceControlModelsResult parseSurfaceControlModels(const QJsonObject &root)
{
    SurfaceControlModelsResult result;
    Diagnostics &out = result.diagnostics;
    JsonObjectReader r(root, QString(), out);
    (void)r.keywordText(QStringLiteral("format"), Presence::Required,
                        {QStringLiteral("tolturn-surface-control-models")}, ModelFiles::tr("file format"));
    const std::optional<int> version = r.integer(QStringLiteral("version"), Presence::Required);
    if (version && *version != 1)
        out.push_back(makeError(QStringLiteral("version"),
                                ModelFiles::tr("version %1 is not one this TolTurn reads (1)").arg(*version)));
    SurfaceControlModels m;
    m.source = r.text(QStringLiteral("source"), Presence::Required).value_or(QString());
    const std::optional<ProcessModel> m1 = readModel(r, QStringLiteral("force_for_roughness"), out);
    const std::optional<ProcessModel> m2 = readModel(r, QStringLiteral("feed_command"), out);
    const std::optional<ProcessModel> m3 = readModel(r, QStringLiteral("speed_command"), out);
    const std::optional<ProcessModel> m4 = readModel(r, QStringLiteral("cutting_force"), out);
    const std::optional<ProcessModel> m5 = readModel(r, QStringLiteral("roughness"), out);
    r.finish();
    if (hasErrors(out) || !m1 || !m2 || !m3 || !m4 || !m5)
        return result;
    m.forceForRoughness = *m1;
    m.feedCommand = *m2;
    m.speedCommand = *m3;
    m.cuttingForce = *m4;
    m.roughness = *m5;
    result.models = m;
    return result;
}

SurfaceControlModelsResult readSurfaceControlModels(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {std::nullopt, {makeError(path, ModelFiles::tr("cannot be read: %1").arg(file.errorString()))}};
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &parseError);
    if (parseError.error != QJsonParseError::NoError || !doc.isObject())
        return {std::nullopt,
                {makeError(path, ModelFiles::tr("not a valid JSON object: %1").arg(parseError.errorString()))}};
    SurfaceControlModelsResult result = parseSurfaceControlModels(doc.object());
    for (Diagnostic &d : result.diagnostics)
        d.field = path + QLatin1Char(':') + d.field;
    return result;
}

const SurfaceControlModels &printedSurfaceControlModels()
{
    static const SurfaceControlModels models = [] {
        SurfaceControlModelsResult r = readSurfaceControlModels(QStringLiteral(":/data/surface-control-models.json"));
        Q_ASSERT_X(r.models, "printedSurfaceControlModels", "the shipped models file does not read");
        return r.models.value_or(SurfaceControlModels{});
    }();
    return models;
}

} // namespace tolturn
