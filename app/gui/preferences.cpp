// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/preferences.h"

#include <QLocale>
#include <QSettings>

namespace tolturn {

namespace {
const QString kLanguageKey = QStringLiteral("interface/language");
const QString kLengthUnitKey = QStringLiteral("interface/lengthUnit");
const QString kPlannerKey = QStringLiteral("report/planner");
const QString kCurrencyKey = QStringLiteral("planning/currency");
} // namespace

QStringList availableLanguages()
{
    return {QStringLiteral("en"), QStringLiteral("de"), QStringLiteral("es")};
}

Preferences loadPreferences()
{
    const QSettings settings;
    Preferences p;
    p.language = settings.value(kLanguageKey).toString();
    if (!availableLanguages().contains(p.language))
        p.language.clear(); // a language since removed, or a hand-edited value: the system's
    p.lengthUnit = lengthUnitFromKeyword(settings.value(kLengthUnitKey).toString());
    p.planner = settings.value(kPlannerKey).toString().trimmed();
    p.currency = settings.value(kCurrencyKey).toString().trimmed();
    return p;
}

void savePreferences(const Preferences &preferences)
{
    QSettings settings;
    settings.setValue(kLanguageKey, preferences.language);
    settings.setValue(kLengthUnitKey, keyword(preferences.lengthUnit));
    settings.setValue(kPlannerKey, preferences.planner.trimmed());
    settings.setValue(kCurrencyKey, preferences.currency.trimmed());
}

QLocale translationLocale(const Preferences &preferences)
{
    return preferences.language.isEmpty() ? QLocale() : QLocale(preferences.language);
}

} // namespace tolturn
