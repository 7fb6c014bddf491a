// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/common/display_units.h"

#include <QLocale>

namespace tolturn {

namespace {

// Fixed decimals, then trailing zeros removed (a drawing shows "50", not "50.000").
QString trimmedNumber(double value, int decimals)
{
    QString text = QLocale::c().toString(value, 'f', decimals);
    while (text.contains(QLatin1Char('.')) && (text.endsWith(QLatin1Char('0')) || text.endsWith(QLatin1Char('.'))))
        text.chop(1);
    return text == QStringLiteral("-0") ? QStringLiteral("0") : text;
}

bool inInches(const DisplayUnits &units)
{
    return units.lengthUnit() == LengthUnit::Inch;
}

} // namespace

QString DisplayUnits::lengthSymbol() const
{
    return inInches(*this) ? QStringLiteral("in") : QStringLiteral("mm");
}

double DisplayUnits::lengthFromMm(double value_mm) const
{
    return inInches(*this) ? value_mm / kMillimetresPerInch : value_mm;
}

double DisplayUnits::lengthToMm(double shown) const
{
    return inInches(*this) ? shown * kMillimetresPerInch : shown;
}

int DisplayUnits::lengthDecimals() const
{
    return inInches(*this) ? 5 : 3;
}

QString DisplayUnits::lengthText(double value_mm) const
{
    return trimmedNumber(lengthFromMm(value_mm), inInches(*this) ? 4 : 3);
}

QString DisplayUnits::deviationSymbol() const
{
    return inInches(*this) ? QStringLiteral("µin") : QStringLiteral("µm");
}

double DisplayUnits::deviationFromUm(double value_um) const
{
    // 1 µm = 1e-3 mm = 1e-3 / 25.4 in = 1000 / 25.4 µin.
    return inInches(*this) ? value_um * 1000.0 / kMillimetresPerInch : value_um;
}

QString DisplayUnits::deviationText(double value_um) const
{
    return trimmedNumber(deviationFromUm(value_um), inInches(*this) ? 0 : 1);
}

QString keyword(LengthUnit unit)
{
    return unit == LengthUnit::Inch ? QStringLiteral("in") : QStringLiteral("mm");
}

LengthUnit lengthUnitFromKeyword(const QString &text)
{
    return text == QStringLiteral("in") ? LengthUnit::Inch : LengthUnit::Millimetre;
}

DisplaySettings &DisplaySettings::instance()
{
    static DisplaySettings settings;
    return settings;
}

void DisplaySettings::setUnits(DisplayUnits units)
{
    if (units == m_units)
        return;
    m_units = units;
    Q_EMIT unitsChanged();
}

} // namespace tolturn
