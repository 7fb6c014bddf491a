// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/preferences.h"

#include <QDialog>

class QComboBox;
class QLineEdit;

namespace tolturn {

// Edit > Preferences: the language of the interface and the units lengths and deviations are
// shown in. The units apply at once; a language at the next start.
class SettingsDialog : public QDialog {
    Q_OBJECT
public:
    explicit SettingsDialog(const Preferences &current, QWidget *parent = nullptr);

    [[nodiscard]] Preferences preferences() const;

    [[nodiscard]] QComboBox *languageBox() const { return m_language; }

    [[nodiscard]] QComboBox *unitBox() const { return m_unit; }

    [[nodiscard]] QLineEdit *plannerEdit() const { return m_planner; }

    [[nodiscard]] QLineEdit *currencyEdit() const { return m_currency; }

private:
    QComboBox *m_language;
    QComboBox *m_unit;
    QLineEdit *m_planner;
    QLineEdit *m_currency;
};

} // namespace tolturn
