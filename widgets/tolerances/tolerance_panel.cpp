// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/tolerances/tolerance_panel.h"

#include "widgets/common/project_fields.h"
#include "widgets/common/table_copy.h"
#include "widgets/document/project_document.h"
#include "widgets/tolerances/tolerance_dialog.h"
#include "widgets/tolerances/tolerance_verdict_model.h"
#include "widgets/tolerances/utilisation_delegate.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

namespace tolturn {

TolerancePanel::TolerancePanel(ProjectDocument &document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_model(new ToleranceVerdictModel(this))
    , m_table(new QTableView(this))
    , m_banner(new QLabel(this))
    , m_add(new QPushButton(tr("Add…"), this))
    , m_edit(new QPushButton(tr("Edit…"), this))
    , m_remove(new QPushButton(tr("Remove"), this))
    , m_datum(new QPushButton(tr("Set Datum…"), this))
{
    setObjectName(QStringLiteral("tolerancePanel"));
    m_table->setModel(m_model);
    m_table->setItemDelegateForColumn(ToleranceVerdictModel::Utilisation, new UtilisationDelegate(m_table));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    addCopyAsCsv(*m_table);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setAlternatingRowColors(true);
    m_add->setToolTip(tr("Add a tolerance on the feature selected in the drawing"));
    m_datum->setToolTip(tr("Make the feature selected in the drawing a datum (ISO 5459)"));
    auto *buttons = new QHBoxLayout;
    for (QPushButton *b : {m_add, m_edit, m_remove, m_datum})
        buttons->addWidget(b);
    buttons->addStretch();
    m_banner->setObjectName(QStringLiteral("machineAssumptionBanner"));
    m_banner->setWordWrap(true);
    m_banner->setMargin(6);
    m_banner->hide();
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(buttons);
    layout->addWidget(m_banner);
    layout->addWidget(m_table);
    connect(m_add, &QPushButton::clicked, this, &TolerancePanel::addTolerance);
    connect(m_edit, &QPushButton::clicked, this, &TolerancePanel::editTolerance);
    connect(m_remove, &QPushButton::clicked, this, &TolerancePanel::removeTolerance);
    connect(m_datum, &QPushButton::clicked, this, &TolerancePanel::setDatum);
    connect(m_table, &QTableView::doubleClicked, this, &TolerancePanel::editTolerance);
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this, [this](const QModelIndex &index) {
        updateButtons();
        if (index.isValid())
            Q_EMIT featureActivated(index.data(ToleranceVerdictModel::FeatureIdRole).toString());
    });
    setProjectField(*m_table, QStringLiteral("tolerances"));
    setProjectField(*m_datum, QStringLiteral("datums"));
    updateButtons();
}

void TolerancePanel::showVerdicts(std::vector<ToleranceEvaluation> verdicts)
{
    std::vector<ToleranceRangeEvaluation> rows;
    rows.reserve(verdicts.size());
    for (ToleranceEvaluation &e : verdicts) {
        ToleranceRangeEvaluation r;
        r.compliant = std::move(e);
        rows.push_back(std::move(r));
    }
    showVerdicts(std::move(rows), QString(), false);
}

void TolerancePanel::showVerdicts(std::vector<ToleranceRangeEvaluation> verdicts, const QString &assumption,
                                  bool optimistic)
{
    // A banner, not a grey note: what the verdicts rest on is part of the verdict.
    m_banner->setVisible(!assumption.isEmpty());
    m_banner->setText(tr("<b>Machine:</b> %1").arg(assumption.toHtmlEscaped()));
    m_banner->setStyleSheet(optimistic ? QStringLiteral("background: #fde3c8; border: 1px solid #d08a3c;")
                                       : QStringLiteral("background: #e4ecf7; border: 1px solid #8aa2c8;"));
    const int row = currentRow();
    m_model->setVerdicts(m_document.project(), std::move(verdicts));
    m_table->resizeColumnsToContents();
    if (row >= 0 && row < m_model->rowCount())
        m_table->selectRow(row);
    updateButtons();
}

void TolerancePanel::showPrediction(const Project &project, const SetupPrediction &prediction)
{
    Q_UNUSED(project); // the rows are the document's tolerances
    // What was learned replaces the range: no support is then taken as rigid.
    showVerdicts(prediction.range.tolerances, prediction.assumption,
                 !prediction.learned && prediction.range.someSupportRigid);
}

void TolerancePanel::showNotPredicted(const QString &why)
{
    if (why.isEmpty() || !m_document.hasProject()) {
        showVerdicts(std::vector<ToleranceEvaluation>{});
        return;
    }
    const std::vector<Tolerance> &tolerances = m_document.project().tolerances;
    std::vector<ToleranceRangeEvaluation> rows(tolerances.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        rows[i].compliant.toleranceId = tolerances[i].id;
        rows[i].compliant.type = tolerances[i].type;
        rows[i].compliant.featureId = tolerances[i].featureId;
        rows[i].compliant.reason = why;
    }
    showVerdicts(std::move(rows), QString(), false);
}

void TolerancePanel::selectTolerance(int index)
{
    if (index >= 0 && index < m_model->rowCount())
        m_table->selectRow(index);
}

void TolerancePanel::setSelectedFeature(const QString &featureId)
{
    m_selectedFeature = featureId;
    updateButtons();
}

int TolerancePanel::currentRow() const
{
    const QModelIndex index = m_table->currentIndex();
    return index.isValid() ? index.row() : -1;
}

void TolerancePanel::updateButtons()
{
    const bool hasProject = m_document.hasProject();
    m_add->setEnabled(hasProject && !m_selectedFeature.isEmpty());
    m_datum->setEnabled(hasProject && !m_selectedFeature.isEmpty());
    m_edit->setEnabled(currentRow() >= 0);
    m_remove->setEnabled(currentRow() >= 0);
}

void TolerancePanel::addTolerance()
{
    if (m_selectedFeature.isEmpty())
        return;
    Tolerance initial;
    initial.id = m_document.nextToleranceId();
    initial.featureId = m_selectedFeature;
    ToleranceDialog dialog(
        m_document.project(), m_selectedFeature, initial,
        [this](const Tolerance &t) { return m_document.addTolerance(t); }, this);
    dialog.exec();
}

void TolerancePanel::editTolerance()
{
    const int row = currentRow();
    if (row < 0)
        return;
    const Tolerance t = m_document.project().tolerances[static_cast<std::size_t>(row)];
    ToleranceDialog dialog(
        m_document.project(), t.featureId, t,
        [this, row](const Tolerance &edited) { return m_document.replaceTolerance(row, edited); }, this);
    dialog.exec();
}

void TolerancePanel::removeTolerance()
{
    const int row = currentRow();
    if (row >= 0)
        (void)m_document.removeTolerance(row);
}

void TolerancePanel::setDatum()
{
    if (m_selectedFeature.isEmpty())
        return;
    QString suggestion = QStringLiteral("A");
    for (char c = 'A'; c <= 'Z'; ++c) {
        bool used = false;
        for (const Datum &d : m_document.project().datums)
            used = used || d.label == QLatin1Char(c);
        if (!used) {
            suggestion = QLatin1Char(c);
            break;
        }
    }
    bool ok = false;
    const QString label = QInputDialog::getText(this, tr("Set Datum"),
                                                tr("Datum letter for feature %1 (ISO 5459):").arg(m_selectedFeature),
                                                QLineEdit::Normal, suggestion, &ok)
                              .trimmed()
                              .toUpper();
    if (!ok || label.isEmpty())
        return;
    const Diagnostics problems = m_document.setDatum({label, m_selectedFeature});
    if (!problems.empty())
        QMessageBox::warning(this, tr("Set Datum"), problems.front().toString());
}

} // namespace tolturn
