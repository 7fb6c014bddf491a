// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/settings_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QVBoxLayout>

namespace tolturn {

SettingsDialog::SettingsDialog(const Preferences &current, QWidget *parent)
    : QDialog(parent)
    , m_language(new QComboBox)
    , m_unit(new QComboBox)
    , m_planner(new QLineEdit)
    , m_currency(new QLineEdit)
{
    setObjectName(QStringLiteral("settingsDialog"));
    setWindowTitle(tr("Preferences"));
    m_language->addItem(tr("System language"), QString());
    for (const QString &code : availableLanguages()) {
        // Each language in its own name, so that it can be found whatever is shown now.
        const QString name = QLocale(code).nativeLanguageName();
        m_language->addItem(name.left(1).toUpper() + name.mid(1), code);
    }
    m_language->setCurrentIndex(std::max(0, m_language->findData(current.language)));
    m_unit->addItem(tr("Millimetres (lengths in mm, deviations in µm)"), static_cast<int>(LengthUnit::Millimetre));
    m_unit->addItem(tr("Inches (lengths in in, deviations in µin)"), static_cast<int>(LengthUnit::Inch));
    m_unit->setCurrentIndex(std::max(0, m_unit->findData(static_cast<int>(current.lengthUnit))));
    m_unit->setToolTip(tr("Lengths on the drawing, in the feature and set-up panels and in the plots; deviations in "
                          "the plots and the verdict table. Files, reports, cutting data and the ISO 286 tables "
                          "stay in millimetres and micrometres."));

    auto *note = new QLabel(tr("A new language is used when TolTurn is next started."));
    note->setWordWrap(true);
    auto *form = new QFormLayout;
    form->addRow(tr("&Language:"), m_language);
    form->addRow(QString(), note);
    form->addRow(tr("&Units:"), m_unit);
    m_planner->setText(current.planner);
    m_planner->setPlaceholderText(tr("name in the report's title block"));
    form->addRow(tr("&Planner:"), m_planner);
    m_currency->setText(current.currency);
    m_currency->setPlaceholderText(tr("e.g. EUR, of the machine rate and tool costs"));
    form->addRow(tr("&Currency:"), m_currency);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

Preferences SettingsDialog::preferences() const
{
    Preferences p;
    p.language = m_language->currentData().toString();
    p.lengthUnit = static_cast<LengthUnit>(m_unit->currentData().toInt());
    p.planner = m_planner->text().trimmed();
    p.currency = m_currency->text().trimmed();
    return p;
}

} // namespace tolturn
