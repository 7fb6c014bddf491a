// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>

namespace tolturn {

// The unit lengths and deviations are shown and typed in. The core always computes in
// millimetres and micrometres; these convert only at the screen.
enum class LengthUnit { Millimetre, Inch };

// 1 in = 25.4 mm exactly (the international inch, NIST SP 811 §B.8 / ISO 80000-3 annex).
inline constexpr double kMillimetresPerInch = 25.4;

class DisplayUnits {
public:
    DisplayUnits() = default;

    explicit DisplayUnits(LengthUnit length) : m_length(length) {}

    [[nodiscard]] LengthUnit lengthUnit() const { return m_length; }

    // Lengths, diameters and positions along z: mm, or in.
    [[nodiscard]] QString lengthSymbol() const;
    [[nodiscard]] double lengthFromMm(double value_mm) const;
    [[nodiscard]] double lengthToMm(double shown) const;
    // Decimals for entry and exact display: 0.001 mm, or 0.00001 in (0.254 µm), so that a
    // value typed in either unit survives the round trip to the core's millimetres.
    [[nodiscard]] int lengthDecimals() const;
    // A drawing's dimension text: 3 decimals in mm, 4 in inches (0.0001 in, the inch shop's
    // "tenth"), no trailing zeros.
    [[nodiscard]] QString lengthText(double value_mm) const;

    // Deviations and tolerance zones: µm, or µin (1 µm = 1000 / 25.4 µin).
    [[nodiscard]] QString deviationSymbol() const;
    [[nodiscard]] double deviationFromUm(double value_um) const;
    [[nodiscard]] QString deviationText(double value_um) const;

    friend bool operator==(const DisplayUnits &, const DisplayUnits &) = default;

private:
    LengthUnit m_length = LengthUnit::Millimetre;
};

// Keywords of the units in settings ("mm", "in"); unknown text is millimetres.
[[nodiscard]] QString keyword(LengthUnit unit);
[[nodiscard]] LengthUnit lengthUnitFromKeyword(const QString &text);

// The units chosen in the settings, for the whole program. Views redraw on unitsChanged.
// Reports and files are not affected: they are always in millimetres and micrometres.
class DisplaySettings : public QObject {
    Q_OBJECT

public:
    static DisplaySettings &instance();

    [[nodiscard]] DisplayUnits units() const { return m_units; }

    void setUnits(DisplayUnits units);

Q_SIGNALS:
    void unitsChanged();

private:
    DisplaySettings() = default;
    DisplayUnits m_units;
};

} // namespace tolturn
