// SPDX-License-Identifier: GPL-3.0-or-later
// With TOLTURN_SCREENSHOTS=DIR, GUI tests save the views they drive as DIR/NAME (PNG); the
// images of the README and docs/ come from tools/screenshots.sh, which runs them under Xvfb.
#pragma once

#include <QString>
#include <QWidget>

namespace tolturn::test {

inline void saveScreenshot(QWidget &w, const char *name)
{
    const QString dir = qEnvironmentVariable("TOLTURN_SCREENSHOTS");
    if (!dir.isEmpty())
        w.grab().save(dir + QLatin1Char('/') + QString::fromLatin1(name));
}

} // namespace tolturn::test
