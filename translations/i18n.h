// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QLocale>

class QCoreApplication;

namespace tolturn {

// Installs TolTurn's and Qt's translators for `locale` (the system locale by default).
// English is the source language and needs none.
void installTranslations(QCoreApplication &app, const QLocale &locale = QLocale());

} // namespace tolturn
