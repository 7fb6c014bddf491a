// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/preferences.h"

#include <QDialog>

class QComboBox;
class QLabel;
class QLineEdit;
class QRadioButton;
class QSpinBox;

namespace tolturn {

// Edit > Preferences: the language of the interface and the units lengths and deviations are
// shown in, the planner's name and currency, and the measurement store. The units and the store
// apply at once; a language at the next start.
class SettingsDialog : public QDialog {
    Q_OBJECT
public:
    explicit SettingsDialog(const Preferences &current, QWidget *parent = nullptr);

    [[nodiscard]] Preferences preferences() const;

    [[nodiscard]] QComboBox *languageBox() const { return m_language; }

    [[nodiscard]] QComboBox *unitBox() const { return m_unit; }

    [[nodiscard]] QLineEdit *plannerEdit() const { return m_planner; }

    [[nodiscard]] QLineEdit *currencyEdit() const { return m_currency; }

    [[nodiscard]] QRadioButton *shopDatabaseButton() const { return m_shop; }

    [[nodiscard]] QLineEdit *shopHostEdit() const { return m_host; }

    [[nodiscard]] QLineEdit *shopDatabaseEdit() const { return m_database; }

    [[nodiscard]] QLineEdit *shopUserEdit() const { return m_user; }

    [[nodiscard]] QSpinBox *shopPortBox() const { return m_port; }

    [[nodiscard]] QLabel *connectionResult() const { return m_connection; }

    // Opens the store the dialog names, in the background; the result in connectionResult().
    void testConnection();

    // Refuses a shop database without its host, database and user, naming what is missing.
    void accept() override;

Q_SIGNALS:
    void connectionTested(bool ok);

private:
    QWidget *createStoreGroup(const Preferences &current);
    void updateStoreFields();

    QComboBox *m_language;
    QComboBox *m_unit;
    QLineEdit *m_planner;
    QLineEdit *m_currency;
    QRadioButton *m_local = nullptr;
    QRadioButton *m_shop = nullptr;
    QLineEdit *m_host = nullptr;
    QSpinBox *m_port = nullptr;
    QLineEdit *m_database = nullptr;
    QLineEdit *m_user = nullptr;
    QLabel *m_connection = nullptr;
};

} // namespace tolturn
