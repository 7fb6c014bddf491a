// SPDX-License-Identifier: GPL-3.0-or-later
#include "resources/bundled.h"

#include <QDir>

namespace tolturn {

QStringList bundledExamplePaths()
{
    QStringList paths;
    const QDir dir(QStringLiteral(":/examples"));
    for (const QString &name : dir.entryList({QStringLiteral("*.tolturn")}, QDir::Files, QDir::Name))
        paths << dir.filePath(name);
    return paths;
}

QString applicationIconPath()
{
    return QStringLiteral(":/icons/tolturn.svg");
}

} // namespace tolturn
