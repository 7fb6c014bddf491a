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
const QString kShopDatabaseKey = QStringLiteral("measurements/shopDatabase");
const QString kShopHostKey = QStringLiteral("measurements/host");
const QString kShopPortKey = QStringLiteral("measurements/port");
const QString kShopDatabaseNameKey = QStringLiteral("measurements/database");
const QString kShopUserKey = QStringLiteral("measurements/user");
constexpr int kPostgresPort = 5432;
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
    p.shopDatabase = settings.value(kShopDatabaseKey, false).toBool();
    p.shopHost = settings.value(kShopHostKey).toString().trimmed();
    bool ok = false;
    p.shopPort = settings.value(kShopPortKey, kPostgresPort).toInt(&ok);
    if (!ok || p.shopPort < 1 || p.shopPort > 65535)
        p.shopPort = kPostgresPort;
    p.shopDatabaseName = settings.value(kShopDatabaseNameKey).toString().trimmed();
    p.shopUser = settings.value(kShopUserKey).toString().trimmed();
    return p;
}

void savePreferences(const Preferences &preferences)
{
    QSettings settings;
    settings.setValue(kLanguageKey, preferences.language);
    settings.setValue(kLengthUnitKey, keyword(preferences.lengthUnit));
    settings.setValue(kPlannerKey, preferences.planner.trimmed());
    settings.setValue(kCurrencyKey, preferences.currency.trimmed());
    settings.setValue(kShopDatabaseKey, preferences.shopDatabase);
    settings.setValue(kShopHostKey, preferences.shopHost.trimmed());
    settings.setValue(kShopPortKey, preferences.shopPort);
    settings.setValue(kShopDatabaseNameKey, preferences.shopDatabaseName.trimmed());
    settings.setValue(kShopUserKey, preferences.shopUser.trimmed());
}

StoreLocation measurementStoreLocation(const Preferences &preferences)
{
    if (!preferences.shopDatabase)
        return defaultStoreLocation();
    StoreLocation l;
    l.kind = StoreLocation::Kind::PostgreSQL;
    l.host = preferences.shopHost;
    l.port = preferences.shopPort;
    l.database = preferences.shopDatabaseName;
    l.user = preferences.shopUser;
    return l;
}

QLocale translationLocale(const Preferences &preferences)
{
    return preferences.language.isEmpty() ? QLocale() : QLocale(preferences.language);
}

} // namespace tolturn
