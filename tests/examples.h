// SPDX-License-Identifier: GPL-3.0-or-later
// The bundled examples (resources/examples) as the tests open them: their path, their bytes, and
// their JSON to edit before a test writes it elsewhere. Shared by the core, CLI and GUI tests.
#pragma once

#include <QByteArray>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

namespace tolturn::test {

inline QString example(const char *name)
{
    return QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/") + QString::fromLatin1(name);
}

// What the example holds; the test stops when it cannot be read.
[[nodiscard]] inline QByteArray exampleBytes(const char *name)
{
    QFile file(example(name));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", name);
    return file.readAll();
}

// The example's project as JSON; the test stops when it is not a JSON object.
[[nodiscard]] inline QJsonObject exampleJson(const char *name)
{
    const QJsonDocument document = QJsonDocument::fromJson(exampleBytes(name));
    if (!document.isObject())
        qFatal("%s is not a JSON object", name);
    return document.object();
}

} // namespace tolturn::test
