// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

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

    friend bool operator==(const Preferences &, const Preferences &) = default;
};

// The languages TolTurn is translated into, English (the source language) first.
[[nodiscard]] QStringList availableLanguages();

[[nodiscard]] Preferences loadPreferences();
void savePreferences(const Preferences &preferences);

// The locale to load translations for: the chosen language, or the system's.
[[nodiscard]] QLocale translationLocale(const Preferences &preferences);

} // namespace tolturn
