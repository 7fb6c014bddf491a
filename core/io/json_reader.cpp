// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/json_reader.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>

#include <cmath>
#include <utility>

namespace tolturn {

namespace {

struct JsonReading {
    Q_DECLARE_TR_FUNCTIONS(JsonReading)
};

} // namespace

QString describeJsonValue(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Null:
        return JsonReading::tr("null");
    case QJsonValue::Bool:
        return value.toBool() ? JsonReading::tr("true") : JsonReading::tr("false");
    case QJsonValue::Double:
        // As the file has it, to the last digit: 1.0000000000000002 is not the whole number 1.
        return JsonReading::tr("the number %1").arg(formatNumberExactly(value.toDouble()));
    case QJsonValue::String:
        return JsonReading::tr("the text \"%1\"").arg(value.toString());
    case QJsonValue::Array:
        return JsonReading::tr("a list");
    case QJsonValue::Object:
        return JsonReading::tr("an object");
    case QJsonValue::Undefined:
        break;
    }
    return JsonReading::tr("nothing");
}

QString elementPath(const QString &arrayPath, qsizetype index)
{
    return arrayPath + QStringLiteral("[%1]").arg(index);
}

JsonObjectReader::JsonObjectReader(QJsonObject object, QString path, Diagnostics &out)
    : m_object(std::move(object))
    , m_path(std::move(path))
    , m_out(out)
{
}

QString JsonObjectReader::fieldPath(const QString &key) const
{
    // A key a path cannot hold as it is (empty, or with a dot, bracket or quote) is written as a
    // JSON string in brackets, so that every path names one field: planning[""], part["a.b"].
    static const QRegularExpression plain(QStringLiteral(R"(^[^.\[\]"]+$)"));
    if (!plain.match(key).hasMatch()) {
        const QByteArray quoted = QJsonDocument(QJsonArray{key}).toJson(QJsonDocument::Compact);
        return m_path + QLatin1Char('[') + QString::fromUtf8(quoted.mid(1, quoted.size() - 2)) + QLatin1Char(']');
    }
    return m_path.isEmpty() ? key : m_path + QLatin1Char('.') + key;
}

std::optional<QJsonValue> JsonObjectReader::take(const QString &key, Presence presence)
{
    m_read.insert(key);
    const auto it = m_object.constFind(key);
    if (it == m_object.constEnd()) {
        if (presence == Presence::Required)
            m_out.push_back(makeError(fieldPath(key), JsonReading::tr("this field is required but missing")));
        return std::nullopt;
    }
    return it.value();
}

void JsonObjectReader::typeError(const QString &key, const QString &expected, const QJsonValue &value)
{
    m_out.push_back(
        makeError(fieldPath(key), JsonReading::tr("expected %1, found %2").arg(expected, describeJsonValue(value))));
}

std::optional<double> JsonObjectReader::number(const QString &key, Presence presence)
{
    const auto value = take(key, presence);
    if (!value)
        return std::nullopt;
    if (!value->isDouble()) {
        typeError(key, JsonReading::tr("a number"), *value);
        return std::nullopt;
    }
    return value->toDouble();
}

std::optional<int> JsonObjectReader::integer(const QString &key, Presence presence)
{
    const auto value = take(key, presence);
    if (!value)
        return std::nullopt;
    const double d = value->toDouble(std::nan(""));
    if (!value->isDouble() || d != std::floor(d) || std::abs(d) > 1e9) {
        typeError(key, JsonReading::tr("a whole number"), *value);
        return std::nullopt;
    }
    return static_cast<int>(d);
}

std::optional<QString> JsonObjectReader::text(const QString &key, Presence presence)
{
    const auto value = take(key, presence);
    if (!value)
        return std::nullopt;
    if (!value->isString()) {
        typeError(key, JsonReading::tr("a text"), *value);
        return std::nullopt;
    }
    return value->toString();
}

std::optional<QJsonObject> JsonObjectReader::object(const QString &key, Presence presence)
{
    const auto value = take(key, presence);
    if (!value)
        return std::nullopt;
    if (!value->isObject()) {
        typeError(key, JsonReading::tr("an object"), *value);
        return std::nullopt;
    }
    return value->toObject();
}

std::optional<QJsonArray> JsonObjectReader::array(const QString &key, Presence presence)
{
    const auto value = take(key, presence);
    if (!value)
        return std::nullopt;
    if (!value->isArray()) {
        typeError(key, JsonReading::tr("a list"), *value);
        return std::nullopt;
    }
    return value->toArray();
}

std::optional<QString> JsonObjectReader::keywordText(const QString &key, Presence presence, const QStringList &allowed,
                                                     const QString &what)
{
    auto value = text(key, presence);
    if (!value)
        return std::nullopt;
    if (!allowed.contains(*value)) {
        m_out.push_back(makeError(fieldPath(key), JsonReading::tr("unknown %1 \"%2\"; expected one of: %3")
                                                      .arg(what, *value, allowed.join(QStringLiteral(", ")))));
        return std::nullopt;
    }
    return value;
}

namespace {

// The collector of the CollectUnknown alive on this thread, if any.
thread_local std::vector<std::pair<QString, QJsonValue>> *t_unknownSink = nullptr;

} // namespace

JsonObjectReader::CollectUnknown::CollectUnknown(std::vector<std::pair<QString, QJsonValue>> &sink)
{
    t_unknownSink = &sink;
}

JsonObjectReader::CollectUnknown::~CollectUnknown()
{
    t_unknownSink = nullptr;
}

void JsonObjectReader::finish()
{
    for (auto it = m_object.constBegin(); it != m_object.constEnd(); ++it) {
        if (m_read.contains(it.key()))
            continue;
        m_out.push_back(makeWarning(fieldPath(it.key()), JsonReading::tr("unknown field, kept as it is")));
        if (t_unknownSink)
            t_unknownSink->emplace_back(fieldPath(it.key()), it.value());
    }
}

} // namespace tolturn
