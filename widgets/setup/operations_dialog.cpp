// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/setup/operations_dialog.h"

#include "core/project/keywords.h"
#include "core/project/operations.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace tolturn {

namespace {

QString featureText(const Segment &s, ContourSide side)
{
    return QStringLiteral("%1  %2 (%3, %4)")
        .arg(s.id, s.name.isEmpty() ? displayName(s.kind) : s.name, displayName(s.kind), contourName(side));
}

} // namespace

OperationsDialog::OperationsDialog(const Project &project, Apply apply, QWidget *parent)
    : QDialog(parent)
    , m_project(project)
    , m_apply(std::move(apply))
    , m_operations(project.furtherOperations)
    , m_list(new QListWidget)
    , m_features(new QListWidget)
    , m_name(new QLineEdit)
    , m_remove(new QPushButton(tr("&Remove")))
    , m_message(new QLabel)
{
    setWindowTitle(tr("Operations"));
    setObjectName(QStringLiteral("operationsDialog"));
    m_list->setObjectName(QStringLiteral("operationList"));
    m_features->setObjectName(QStringLiteral("operationFeatures"));
    m_name->setObjectName(QStringLiteral("operationName"));
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: #b00020;"));
    auto *add = new QPushButton(tr("&Add Operation"));
    add->setToolTip(tr("A set-up after the others: the part turned end for end in the chuck, with this project's "
                       "tool and passes; tick the features it cuts"));
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(add);
    buttons->addWidget(m_remove);
    buttons->addStretch();
    auto *left = new QVBoxLayout;
    left->addWidget(new QLabel(tr("Set-ups, in order:")));
    left->addWidget(m_list, 1);
    left->addLayout(buttons);
    auto *form = new QFormLayout;
    form->addRow(tr("&Name:"), m_name);
    auto *right = new QVBoxLayout;
    right->addLayout(form);
    right->addWidget(new QLabel(tr("Features it cuts (the first set-up cuts every feature no other ticks):")));
    right->addWidget(m_features, 1);
    auto *columns = new QHBoxLayout;
    columns->addLayout(left, 1);
    columns->addLayout(right, 2);
    auto *box = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(columns, 1);
    layout->addWidget(new QLabel(tr("Clamping, tools and passes of each set-up are edited in the Set-up dock with "
                                    "the set-up chosen in the toolbar (docs/operations.md).")));
    layout->addWidget(m_message);
    layout->addWidget(box);
    for (const ContourSide side : {ContourSide::Outer, ContourSide::Inner}) {
        for (const Segment &s : project.part.contour(side).segments) {
            auto *item = new QListWidgetItem(featureText(s, side), m_features);
            item->setData(Qt::UserRole, s.id);
            item->setCheckState(Qt::Unchecked);
        }
    }
    connect(add, &QPushButton::clicked, this, &OperationsDialog::addOperation);
    connect(m_remove, &QPushButton::clicked, this, &OperationsDialog::removeOperation);
    connect(m_list, &QListWidget::currentRowChanged, this, &OperationsDialog::showOperation);
    connect(m_features, &QListWidget::itemChanged, this,
            [this](QListWidgetItem *item) { featureToggled(m_features->row(item)); });
    connect(m_name, &QLineEdit::textEdited, this, [this](const QString &text) {
        const int row = m_list->currentRow();
        if (row <= 0)
            return;
        m_operations[static_cast<std::size_t>(row - 1)].name = text.trimmed();
        m_list->item(row)->setText(text.trimmed());
    });
    connect(box, &QDialogButtonBox::accepted, this, &OperationsDialog::accept);
    connect(box, &QDialogButtonBox::rejected, this, &QDialog::reject);
    refreshList();
    m_list->setCurrentRow(0);
    resize(720, 420);
}

void OperationsDialog::refreshList()
{
    const int row = m_list->currentRow();
    m_list->clear();
    m_list->addItem(operationName(m_project, 0));
    for (const Operation &op : m_operations)
        m_list->addItem(op.name);
    m_list->setCurrentRow(std::min(std::max(row, 0), m_list->count() - 1));
}

// The first set-up shows what it keeps (read only); a later one its own ticks.
void OperationsDialog::showOperation(int row)
{
    if (row < 0)
        return;
    m_showing = true;
    Project current = m_project;
    current.furtherOperations = m_operations;
    m_name->setEnabled(row > 0);
    m_remove->setEnabled(row > 0);
    m_name->setText(row > 0 ? m_operations[static_cast<std::size_t>(row - 1)].name : operationName(current, 0));
    const QStringList cut = operationFeatures(current, row);
    for (int i = 0; i < m_features->count(); ++i) {
        QListWidgetItem *item = m_features->item(i);
        const QString id = item->data(Qt::UserRole).toString();
        item->setCheckState(cut.contains(id) ? Qt::Checked : Qt::Unchecked);
        Qt::ItemFlags flags = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
        if (row > 0)
            flags |= Qt::ItemIsUserCheckable;
        item->setFlags(flags);
    }
    m_showing = false;
}

// A feature ticked for one set-up leaves any other; unticked, it goes back to the first.
void OperationsDialog::featureToggled(int featureRow)
{
    const int row = m_list->currentRow();
    if (m_showing || row <= 0 || featureRow < 0)
        return;
    const QListWidgetItem *item = m_features->item(featureRow);
    const QString id = item->data(Qt::UserRole).toString();
    for (Operation &op : m_operations)
        op.features.removeAll(id);
    if (item->checkState() == Qt::Checked)
        m_operations[static_cast<std::size_t>(row - 1)].features << id;
}

void OperationsDialog::addOperation()
{
    Operation op;
    op.name = QStringLiteral("OP %1").arg(10 * (static_cast<int>(m_operations.size()) + 2));
    op.clamping = m_project.clamping;
    op.clamping.heldEnd = m_project.clamping.heldEnd == PartEnd::Left ? PartEnd::Right : PartEnd::Left;
    op.tool = m_project.tool;
    op.boringTool = m_project.boringTool;
    op.passes = m_project.passes;
    m_operations.push_back(op);
    refreshList();
    m_list->setCurrentRow(m_list->count() - 1);
}

void OperationsDialog::removeOperation()
{
    const int row = m_list->currentRow();
    if (row <= 0)
        return;
    m_operations.erase(m_operations.begin() + (row - 1));
    refreshList();
    m_list->setCurrentRow(row - 1);
}

void OperationsDialog::accept()
{
    const Diagnostics refused = m_apply(m_operations);
    if (refused.empty()) {
        m_message->clear();
        QDialog::accept();
        return;
    }
    QStringList lines;
    for (const Diagnostic &d : refused)
        lines << d.toString();
    m_message->setText(lines.join(QLatin1Char('\n')));
}

} // namespace tolturn
