// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/common/diagnostics_panel.h"

#include "widgets/common/table_copy.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace tolturn {

DiagnosticsPanel::DiagnosticsPanel(QWidget *parent) : QWidget(parent), m_heading(new QLabel), m_table(new QTableWidget)
{
    setObjectName(QStringLiteral("diagnosticsPanel"));
    m_heading->setWordWrap(true);
    m_table->setColumnCount(3);
    m_table->setHorizontalHeaderLabels({tr("Severity"), tr("Where"), tr("Message")});
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setWordWrap(true);
    addCopyAsCsv(*m_table);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_heading);
    layout->addWidget(m_table, 1);
    connect(m_table, &QTableWidget::itemActivated, this, [this](const QTableWidgetItem *item) {
        if (const QTableWidgetItem *where = m_table->item(item->row(), 1); where && !where->text().isEmpty())
            Q_EMIT fieldActivated(where->text());
    });
}

void DiagnosticsPanel::showDiagnostics(const QString &heading, const Diagnostics &diagnostics)
{
    m_heading->setText(heading);
    m_table->setRowCount(static_cast<int>(diagnostics.size()));
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const Diagnostic &d = diagnostics[static_cast<std::size_t>(row)];
        const bool error = d.severity == Severity::Error;
        auto *severity = new QTableWidgetItem(error ? tr("error") : tr("warning"));
        severity->setForeground(error ? QColor(0xb0, 0x00, 0x20) : QColor(0x9a, 0x60, 0x00));
        m_table->setItem(row, 0, severity);
        m_table->setItem(row, 1, new QTableWidgetItem(d.field));
        auto *message = new QTableWidgetItem(d.message);
        message->setToolTip(d.message);
        m_table->setItem(row, 2, message);
    }
    m_table->resizeColumnToContents(0);
    m_table->resizeColumnToContents(1);
    m_table->resizeRowsToContents();
}

QString DiagnosticsPanel::heading() const
{
    return m_heading->text();
}

} // namespace tolturn
