// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "widgets/common/display_units.h"

#include <QDoubleSpinBox>

namespace tolturn {

// A spin box for a length held in millimetres and shown in the display units of the settings
// (mm or in), with the unit as suffix. Changing the units keeps the length, not the number.
class LengthSpinBox : public QDoubleSpinBox {
    Q_OBJECT
public:
    explicit LengthSpinBox(double maximum_mm, const QString &toolTip = QString(), QWidget *parent = nullptr);

    // The length shown, in mm: exactly the one last set unless the user has changed it.
    [[nodiscard]] double millimetres() const;
    void setMillimetres(double value_mm);

private:
    void applyUnits();

    double m_maximum_mm;
    DisplayUnits m_shown;       // the units the value is in now
    double m_value_mm = 0.0;    // the length last set, unrounded
    double m_shownForSet = 0.0; // the number shown for it
};

} // namespace tolturn
