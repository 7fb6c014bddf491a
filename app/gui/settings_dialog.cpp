// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/settings_dialog.h"

#include "widgets/common/worker_threads.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <QtConcurrent>

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
    layout->addWidget(createStoreGroup(current));
    layout->addWidget(buttons);
}

QWidget *SettingsDialog::createStoreGroup(const Preferences &current)
{
    auto *group = new QGroupBox(tr("Measurement store"));
    m_local = new QRadioButton(tr("On this &computer: %1").arg(defaultStoreLocation().describe()));
    m_shop = new QRadioButton(tr("&Shop database (PostgreSQL), shared by every planner"));
    m_host = new QLineEdit(current.shopHost);
    m_host->setPlaceholderText(tr("server name, or the folder of its socket (/var/run/postgresql)"));
    m_port = new QSpinBox;
    m_port->setRange(1, 65535);
    m_port->setValue(current.shopPort);
    m_database = new QLineEdit(current.shopDatabaseName);
    m_user = new QLineEdit(current.shopUser);
    m_connection = new QLabel;
    m_connection->setWordWrap(true);
    m_connection->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto *test = new QPushButton(tr("&Test Connection"));
    connect(test, &QPushButton::clicked, this, &SettingsDialog::testConnection);
    (current.shopDatabase ? m_shop : m_local)->setChecked(true);
    connect(m_shop, &QRadioButton::toggled, this, &SettingsDialog::updateStoreFields);
    auto *password = new QLabel(tr("TolTurn keeps no password: libpq reads it from ~/.pgpass, or the server needs "
                                   "none (peer authentication)."));
    password->setWordWrap(true);
    auto *shopForm = new QFormLayout;
    shopForm->addRow(tr("&Host:"), m_host);
    shopForm->addRow(tr("P&ort:"), m_port);
    shopForm->addRow(tr("&Database:"), m_database);
    shopForm->addRow(tr("&User:"), m_user);
    shopForm->addRow(QString(), password);
    shopForm->addRow(test, m_connection);
    auto *layout = new QVBoxLayout(group);
    layout->addWidget(m_local);
    layout->addWidget(m_shop);
    layout->addLayout(shopForm);
    updateStoreFields();
    return group;
}

void SettingsDialog::updateStoreFields()
{
    for (QWidget *w : std::initializer_list<QWidget *>{m_host, m_port, m_database, m_user})
        w->setEnabled(m_shop->isChecked());
}

void SettingsDialog::accept()
{
    if (m_shop->isChecked()) {
        QStringList missing;
        if (m_host->text().trimmed().isEmpty())
            missing << tr("host");
        if (m_database->text().trimmed().isEmpty())
            missing << tr("database");
        if (m_user->text().trimmed().isEmpty())
            missing << tr("user");
        if (!missing.isEmpty()) {
            m_connection->setText(tr("The shop database needs its %1.").arg(missing.join(QStringLiteral(", "))));
            return;
        }
    }
    QDialog::accept();
}

void SettingsDialog::testConnection()
{
    const StoreLocation location = measurementStoreLocation(preferences());
    m_connection->setText(tr("Connecting to %1…").arg(location.describe()));
    auto *watcher = new QFutureWatcher<QString>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, location] {
        const QString error = watcher->result();
        watcher->deleteLater();
        m_connection->setText(error.isEmpty() ? tr("Connected to %1.").arg(location.describe()) : error);
        Q_EMIT connectionTested(error.isEmpty());
    });
    watcher->setFuture(QtConcurrent::run(workerThreads(), [location] {
        QString error;
        return MeasurementStore::open(location, &error) ? QString() : error;
    }));
}

Preferences SettingsDialog::preferences() const
{
    Preferences p;
    p.language = m_language->currentData().toString();
    p.lengthUnit = static_cast<LengthUnit>(m_unit->currentData().toInt());
    p.planner = m_planner->text().trimmed();
    p.currency = m_currency->text().trimmed();
    p.shopDatabase = m_shop->isChecked();
    p.shopHost = m_host->text().trimmed();
    p.shopPort = m_port->value();
    p.shopDatabaseName = m_database->text().trimmed();
    p.shopUser = m_user->text().trimmed();
    return p;
}

} // namespace tolturn
