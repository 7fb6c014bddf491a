// SPDX-License-Identifier: GPL-3.0-or-later
#include "translations/i18n.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QTranslator>

namespace tolturn {

void installTranslations(QCoreApplication &app, const QLocale &locale)
{
    auto *qtTranslator = new QTranslator(&app);
    if (qtTranslator->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                           QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qtTranslator);
    // English plural forms first: the last translator installed is asked first, so the locale's
    // own catalogue (when there is one) takes precedence.
    auto *plurals = new QTranslator(&app);
    if (plurals->load(QStringLiteral(":/i18n/tolturn_en.qm")))
        QCoreApplication::installTranslator(plurals);
    auto *translator = new QTranslator(&app);
    if (locale.language() != QLocale::English &&
        translator->load(locale, QStringLiteral("tolturn"), QStringLiteral("_"), QStringLiteral(":/i18n")))
        QCoreApplication::installTranslator(translator);
}

} // namespace tolturn
