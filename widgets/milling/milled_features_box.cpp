// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/milling/milled_features_box.h"

#include "core/project/keywords.h"
#include "widgets/common/table_cells.h"
#include "widgets/common/worker_threads.h"
#include "widgets/document/project_document.h"
#include "widgets/plot/line_plot.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <algorithm>

namespace tolturn {

namespace {

enum Column { IdColumn, KindColumn, PlaceColumn, ToleranceColumn, VerdictColumn, ColumnCount };

QString toleranceText(const MilledFeature &f)
{
    if (!f.tolerance)
        return MilledFeaturesBox::tr("—");
    const QString type = f.tolerance->type == MilledToleranceType::Flatness ? MilledFeaturesBox::tr("flatness")
                                                                            : MilledFeaturesBox::tr("profile");
    const QString datums = f.tolerance->datums.isEmpty()
                               ? QString()
                               : QStringLiteral(" | %1").arg(f.tolerance->datums.join(QStringLiteral(" | ")));
    return QStringLiteral("%1 %2 µm%3").arg(type).arg(f.tolerance->zone_um).arg(datums);
}

QString verdictText(const MilledFeatureEvaluation &e)
{
    if (!e.missing.isEmpty())
        return MilledFeaturesBox::tr("not evaluated: lacks %1").arg(e.missing.join(QStringLiteral(", ")));
    if (!e.refusal.isEmpty())
        return MilledFeaturesBox::tr("not evaluated: %1").arg(e.refusal);
    return (e.passes ? MilledFeaturesBox::tr("passes, %1 of %2 µm") : MilledFeaturesBox::tr("fails, %1 of %2 µm"))
        .arg(1000.0 * e.formError_mm, 0, 'f', 2)
        .arg(1000.0 * e.tolerance.tolerance_mm, 0, 'g', 4);
}

QColor verdictColour(const MilledFeatureEvaluation &e)
{
    if (!e.evaluated())
        return {150, 150, 150};
    return e.passes ? QColor(46, 125, 50) : QColor(198, 40, 40);
}

} // namespace

MilledFeaturesBox::MilledFeaturesBox(ProjectDocument *document,
                                     std::function<MilledFeature(MilledFeature)> completeFromFields,
                                     std::function<QString()> fieldsProblem, QWidget *parent)
    : QGroupBox(tr("Milled features of the part"), parent)
    , m_document(document)
    , m_completeFromFields(std::move(completeFromFields))
    , m_fieldsProblem(std::move(fieldsProblem))
{
    setObjectName(QStringLiteral("milledFeaturesBox"));
    m_table = new QTableWidget(0, ColumnCount);
    m_table->setObjectName(QStringLiteral("milledFeaturesTable"));
    m_table->setHorizontalHeaderLabels({tr("ID"), tr("Kind"), tr("z [mm]"), tr("Tolerance"), tr("Verdict")});
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    for (const int column : {IdColumn, KindColumn, PlaceColumn, ToleranceColumn})
        m_table->horizontalHeader()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(VerdictColumn, QHeaderView::Stretch);
    m_table->setWordWrap(false);
    m_table->setMinimumHeight(6 * m_table->fontMetrics().lineSpacing());
    m_kind = new QComboBox;
    for (const MilledFeatureKind kind : {MilledFeatureKind::Flat, MilledFeatureKind::Keyway, MilledFeatureKind::Patch})
        m_kind->addItem(displayName(kind), static_cast<int>(kind));
    m_zFrom = new QDoubleSpinBox;
    m_zTo = new QDoubleSpinBox;
    for (QDoubleSpinBox *z : {m_zFrom, m_zTo}) {
        z->setRange(0.0, 100000.0);
        z->setDecimals(2);
        z->setSuffix(tr(" mm"));
    }
    m_coefficientsSource = new QLineEdit;
    m_coefficientsSource->setObjectName(QStringLiteral("coefficientsSource"));
    m_coefficientsSource->setPlaceholderText(tr("where the cutting coefficients come from"));
    m_add = new QPushButton(tr("Add Cut as Feature"));
    m_add->setObjectName(QStringLiteral("addMilledFeature"));
    m_save = new QPushButton(tr("Save Cut to Feature"));
    m_save->setObjectName(QStringLiteral("saveMilledFeature"));
    m_remove = new QPushButton(tr("Remove"));
    m_remove->setObjectName(QStringLiteral("removeMilledFeature"));
    auto *place = new QHBoxLayout;
    place->addWidget(m_zFrom);
    place->addWidget(m_zTo);
    auto *form = new QFormLayout;
    form->addRow(tr("Kind"), m_kind);
    form->addRow(tr("z from, to"), place);
    form->addRow(tr("Coefficients from"), m_coefficientsSource);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_add);
    buttons->addWidget(m_save);
    buttons->addWidget(m_remove);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addLayout(form);
    layout->addLayout(buttons);
    m_pathPlot = new LinePlot;
    m_pathPlot->setObjectName(QStringLiteral("milledPathPlot"));
    m_pathPlot->setAxisLabels(tr("along the path [mm]"), tr("surface-normal error [µm]"));

    connect(m_add, &QPushButton::clicked, this, [this] {
        if (const QString m = addFromFields(); !m.isEmpty())
            Q_EMIT message(m);
    });
    connect(m_save, &QPushButton::clicked, this, [this] {
        if (const QString m = saveToChosen(); !m.isEmpty())
            Q_EMIT message(m);
    });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        if (const QString m = removeChosen(); !m.isEmpty())
            Q_EMIT message(m);
    });
    connect(m_table, &QTableWidget::itemSelectionChanged, this, [this] { choose(chosenRow()); });
    connect(m_document, &ProjectDocument::projectChanged, this, &MilledFeaturesBox::refresh);
    connect(&m_watcher, &QFutureWatcher<std::vector<MilledFeatureEvaluation>>::finished, this, [this] {
        m_evaluations = m_watcher.result();
        if (m_stale) {
            evaluate();
            return;
        }
        showEvaluations();
        Q_EMIT evaluated();
    });
    refresh();
}

// The list after any change of the project. The chosen feature stays chosen by its id, without
// loading it again (the fields may hold edits not saved yet); when it is gone nothing is chosen, so
// that no cut is saved to the feature that took its row.
void MilledFeaturesBox::refresh()
{
    const int chosen = chosenRow();
    const QString chosenId =
        chosen >= 0 && m_table->item(chosen, IdColumn) ? m_table->item(chosen, IdColumn)->text() : QString();
    const std::vector<MilledFeature> &features = m_document->project().milledFeatures;
    const QSignalBlocker blocker(m_table);
    m_table->clearSelection();
    m_table->setRowCount(static_cast<int>(features.size()));
    int again = -1;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const MilledFeature &f = features[static_cast<std::size_t>(row)];
        m_table->setItem(row, IdColumn, readOnlyCell(f.id));
        m_table->setItem(row, KindColumn, readOnlyCell(displayName(f.kind)));
        m_table->setItem(
            row, PlaceColumn,
            readOnlyCell(QStringLiteral("%1–%2").arg(f.zFrom_mm).arg(f.zTo_mm), Qt::AlignRight | Qt::AlignVCenter));
        m_table->setItem(row, ToleranceColumn, readOnlyCell(toleranceText(f)));
        m_table->setItem(row, VerdictColumn, readOnlyCell(tr("evaluating…")));
        m_table->item(row, IdColumn)->setToolTip(f.description);
        if (!chosenId.isEmpty() && f.id == chosenId)
            again = row;
    }
    if (again >= 0)
        m_table->selectRow(again);
    m_zTo->setValue(m_zTo->value() > 0.0 ? m_zTo->value() : m_document->project().part.length_mm());
    m_save->setEnabled(again >= 0);
    m_remove->setEnabled(again >= 0);
    m_evaluations.clear(); // of the project before: shown for no row
    showPath(again);
    evaluate();
}

void MilledFeaturesBox::evaluate()
{
    if (m_watcher.isRunning()) {
        m_stale = true;
        return;
    }
    m_stale = false;
    const Project project = m_document->project();
    m_watcher.setFuture(QtConcurrent::run(workerThreads(), [project] { return evaluateMilledFeatures(project); }));
}

const MilledFeatureEvaluation *MilledFeaturesBox::evaluationOf(int row) const
{
    if (row < 0 || row >= m_table->rowCount() || !m_table->item(row, IdColumn))
        return nullptr;
    const QString id = m_table->item(row, IdColumn)->text();
    const auto found = std::find_if(m_evaluations.begin(), m_evaluations.end(),
                                    [&](const MilledFeatureEvaluation &e) { return e.featureId == id; });
    return found == m_evaluations.end() ? nullptr : &*found;
}

void MilledFeaturesBox::showEvaluations()
{
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const MilledFeatureEvaluation *e = evaluationOf(row);
        if (!e)
            continue;
        QTableWidgetItem *cell = readOnlyCell(verdictText(*e));
        cell->setForeground(verdictColour(*e));
        cell->setToolTip(cell->text());
        m_table->setItem(row, VerdictColumn, cell);
    }
    showPath(chosenRow());
}

// δ_N's range over a revolution at each point of the path, with the zone: t placed where the
// spread sits when it floats, ±t/2 about the programmed surface when it is located.
void MilledFeaturesBox::showPath(int row)
{
    m_pathPlot->clear();
    const MilledFeatureEvaluation *evaluation = evaluationOf(row);
    if (!evaluation || !evaluation->evaluated() || evaluation->path.empty()) {
        m_pathPlot->setTitle(row >= 0 && isEvaluating() ? tr("Evaluating…") : tr("Choose an evaluated feature"));
        m_pathPlot->rescaleAndReplot();
        return;
    }
    const MilledFeatureEvaluation &e = *evaluation;
    QVector<double> s;
    QVector<double> least;
    QVector<double> greatest;
    for (const MilledPathPoint &p : e.path) {
        s.append(p.station.arcLength_mm);
        least.append(1000.0 * p.leastNormal_mm);
        greatest.append(1000.0 * p.greatestNormal_mm);
    }
    const double t_um = 1000.0 * e.tolerance.tolerance_mm;
    const double lower =
        e.tolerance.zone == SurfaceZone::Floating ? *std::min_element(least.begin(), least.end()) : -0.5 * t_um;
    const QVector<double> ends{s.front(), s.back()};
    m_pathPlot->setTitle(tr("%1: %2").arg(e.featureId, verdictText(e)));
    m_pathPlot->addBand(tr("δ_N least"), tr("δ_N over a revolution"), s, least, greatest, QColor(31, 119, 180));
    m_pathPlot->addCurve(tr("zone, lower"), ends, {lower, lower}, QColor(214, 39, 40), Qt::DashLine, 1.0);
    m_pathPlot->addCurve(tr("zone, upper"), ends, {lower + t_um, lower + t_um}, QColor(214, 39, 40), Qt::DashLine, 1.0);
    m_pathPlot->rescaleAndReplot();
}

void MilledFeaturesBox::choose(int row)
{
    m_save->setEnabled(row >= 0);
    m_remove->setEnabled(row >= 0);
    showPath(row);
    const std::vector<MilledFeature> &features = m_document->project().milledFeatures;
    if (row < 0 || row >= static_cast<int>(features.size()))
        return;
    const MilledFeature &f = features[static_cast<std::size_t>(row)];
    m_kind->setCurrentIndex(m_kind->findData(static_cast<int>(f.kind)));
    m_zFrom->setValue(f.zFrom_mm);
    m_zTo->setValue(f.zTo_mm);
    m_coefficientsSource->setText(f.coefficientsSource);
    Q_EMIT featureChosen(f);
}

int MilledFeaturesBox::chosenRow() const
{
    const QList<QTableWidgetItem *> selected = m_table->selectedItems();
    return selected.isEmpty() ? -1 : selected.constFirst()->row();
}

MilledFeature MilledFeaturesBox::propertiesFromFields(MilledFeature feature) const
{
    feature.kind = static_cast<MilledFeatureKind>(m_kind->currentData().toInt());
    feature.zFrom_mm = m_zFrom->value();
    feature.zTo_mm = m_zTo->value();
    feature.coefficientsSource = m_coefficientsSource->text().trimmed();
    return m_completeFromFields(std::move(feature));
}

// The project keeps a source with the coefficients it is the source of: one without them would be
// lost on saving, so it is refused, named.
QString MilledFeaturesBox::sourceWithoutCoefficients(const MilledFeature &f)
{
    if (f.coefficients || f.coefficientsSource.isEmpty())
        return {};
    return tr("Coefficients from: \"%1\" is given but there are no coefficients (Ktc, Krc, Kac, Kte, Kre, Kae) to go "
              "with it; enter them, or clear the field.")
        .arg(f.coefficientsSource);
}

QString MilledFeaturesBox::nextId() const
{
    for (int n = 1;; ++n) {
        QString id = QStringLiteral("M%1").arg(n);
        const auto &features = m_document->project().milledFeatures;
        if (std::none_of(features.begin(), features.end(), [&](const MilledFeature &f) { return f.id == id; }) &&
            !findFeature(m_document->project().part, id))
            return id;
    }
}

QString MilledFeaturesBox::apply(const std::vector<MilledFeature> &features, const QString &description)
{
    const Diagnostics refused = m_document->setMilledFeatures(features, description);
    QStringList lines;
    for (const Diagnostic &d : refused)
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

QString MilledFeaturesBox::addFromFields()
{
    if (QString problem = m_fieldsProblem(); !problem.isEmpty())
        return problem;
    MilledFeature feature;
    feature.id = nextId();
    feature = propertiesFromFields(std::move(feature));
    if (QString problem = sourceWithoutCoefficients(feature); !problem.isEmpty())
        return problem;
    std::vector<MilledFeature> features = m_document->project().milledFeatures;
    features.push_back(feature);
    QString refused = apply(features, tr("Add milled feature %1").arg(feature.id));
    if (refused.isEmpty())
        m_table->selectRow(m_table->rowCount() - 1);
    return refused;
}

QString MilledFeaturesBox::saveToChosen()
{
    const int row = chosenRow();
    if (row < 0)
        return tr("Choose the feature to save the cut to.");
    if (QString problem = m_fieldsProblem(); !problem.isEmpty())
        return problem;
    std::vector<MilledFeature> features = m_document->project().milledFeatures;
    MilledFeature &f = features[static_cast<std::size_t>(row)];
    f = propertiesFromFields(f);
    if (QString problem = sourceWithoutCoefficients(f); !problem.isEmpty())
        return problem;
    return apply(features, tr("Change milled feature %1").arg(f.id));
}

QString MilledFeaturesBox::removeChosen()
{
    const int row = chosenRow();
    if (row < 0)
        return tr("Choose the feature to remove.");
    std::vector<MilledFeature> features = m_document->project().milledFeatures;
    const QString id = features[static_cast<std::size_t>(row)].id;
    features.erase(features.begin() + row);
    return apply(features, tr("Remove milled feature %1").arg(id));
}

} // namespace tolturn
