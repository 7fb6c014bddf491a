// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/common/length_spin_box.h"

#include <QSignalBlocker>

namespace tolturn {

LengthSpinBox::LengthSpinBox(double maximum_mm, const QString &toolTip, QWidget *parent)
    : QDoubleSpinBox(parent)
    , m_maximum_mm(maximum_mm)
{
    setToolTip(toolTip);
    setKeyboardTracking(false);
    applyUnits();
    connect(&DisplaySettings::instance(), &DisplaySettings::unitsChanged, this, &LengthSpinBox::applyUnits);
}

double LengthSpinBox::millimetres() const
{
    // The box holds a rounded number (5 decimals of an inch are 0.254 µm); while it still shows
    // the number it showed for the length last set, that length is returned exactly, so that
    // showing a value in other units, or editing a neighbouring field, never changes it.
    return value() == m_shownForSet ? m_value_mm : m_shown.lengthToMm(value());
}

void LengthSpinBox::setMillimetres(double value_mm)
{
    m_value_mm = value_mm;
    setValue(m_shown.lengthFromMm(value_mm));
    m_shownForSet = value(); // as the box rounded it
}

void LengthSpinBox::applyUnits()
{
    const double kept_mm = millimetres();
    m_shown = DisplaySettings::instance().units();
    const QSignalBlocker quiet(this); // the length does not change, only how it is shown
    setDecimals(m_shown.lengthDecimals());
    setRange(0.0, m_shown.lengthFromMm(m_maximum_mm));
    setSuffix(QLatin1Char(' ') + m_shown.lengthSymbol());
    // One step of the arrows or the wheel: 1 mm, or 0.05 in (1.27 mm).
    setSingleStep(m_shown.lengthUnit() == LengthUnit::Inch ? 0.05 : 1.0);
    setMillimetres(kept_mm);
}

} // namespace tolturn
