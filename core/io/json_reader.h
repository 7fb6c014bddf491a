// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QSet>
#include <QString>

#include <optional>
#include <utility>
#include <vector>

namespace tolturn {

enum class Presence { Required, Optional };

// Reads the fields of one JSON object with type checks. Every problem becomes a diagnostic that
// names the full path of the field and the offending value; fields never read are reported as
// unknown (a warning) by finish().
class JsonObjectReader {
public:
    // While one is alive, finish() also collects every unknown field, with its path and value, in
    // `sink` (the project reader keeps them to write them back).
    class CollectUnknown {
    public:
        explicit CollectUnknown(std::vector<std::pair<QString, QJsonValue>> &sink);
        ~CollectUnknown();
        CollectUnknown(const CollectUnknown &) = delete;
        CollectUnknown &operator=(const CollectUnknown &) = delete;
    };

    JsonObjectReader(QJsonObject object, QString path, Diagnostics &out);

    [[nodiscard]] std::optional<double> number(const QString &key, Presence presence);
    [[nodiscard]] std::optional<int> integer(const QString &key, Presence presence);
    [[nodiscard]] std::optional<QString> text(const QString &key, Presence presence);
    [[nodiscard]] std::optional<QJsonObject> object(const QString &key, Presence presence);
    [[nodiscard]] std::optional<QJsonArray> array(const QString &key, Presence presence);

    // A string that must be one of `allowed`; `what` names it in the message ("clamping method").
    [[nodiscard]] std::optional<QString> keywordText(const QString &key, Presence presence, const QStringList &allowed,
                                                     const QString &what);

    [[nodiscard]] QString fieldPath(const QString &key) const;
    void finish();

private:
    std::optional<QJsonValue> take(const QString &key, Presence presence);
    void typeError(const QString &key, const QString &expected, const QJsonValue &value);

    QJsonObject m_object;
    QString m_path;
    Diagnostics &m_out;
    QSet<QString> m_read;
};

// "the string \"abc\"", "the number 5", "an object", ...: how a JSON value is named in messages.
[[nodiscard]] QString describeJsonValue(const QJsonValue &value);

// Path of an element of an array field: "part.outer" + 2 -> "part.outer[2]".
[[nodiscard]] QString elementPath(const QString &arrayPath, qsizetype index);

} // namespace tolturn
