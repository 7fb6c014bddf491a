// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/measurements/measurement_store.h"
#include "widgets/common/display_units.h"

#include <QString>
#include <QStringList>

namespace tolturn {

// The user's choices that outlive a session (QSettings, group "interface").
struct Preferences {
    QString language;                               // "en", "de", "es"; empty: the system's language
    LengthUnit lengthUnit = LengthUnit::Millimetre; // of lengths (mm | in) and deviations (µm | µin)
    QString planner;                                // the name the report's title block gives
    QString currency;                               // of costs (machine rate, tool edge), e.g. "EUR"
    // The measurement store (docs/learning.md): this computer's SQLite file, or a shop's shared
    // PostgreSQL database. No password is kept: libpq reads it from ~/.pgpass (or peer
    // authentication needs none).
    bool shopDatabase = false;
    QString shopHost; // a host name, or the folder of the server's Unix socket
    int shopPort = 5432;
    QString shopDatabaseName;
    QString shopUser;

    friend bool operator==(const Preferences &, const Preferences &) = default;
};

// The languages TolTurn is translated into, English (the source language) first.
[[nodiscard]] QStringList availableLanguages();

[[nodiscard]] Preferences loadPreferences();
// Where the Measurements dock reads and writes: the shop database when chosen, else the per-user file.
[[nodiscard]] StoreLocation measurementStoreLocation(const Preferences &preferences);
void savePreferences(const Preferences &preferences);

// The locale to load translations for: the chosen language, or the system's.
[[nodiscard]] QLocale translationLocale(const Preferences &preferences);

} // namespace tolturn
