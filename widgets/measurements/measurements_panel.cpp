// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/measurements/measurements_panel.h"

#include "core/common/atomic_file.h"
#include "core/data/data_library.h"
#include "core/measurements/measurement_csv.h"
#include "widgets/common/display_units.h"
#include "widgets/common/worker_threads.h"
#include "widgets/measurements/measured_parts_model.h"
#include "widgets/measurements/measurement_entry_dialog.h"
#include "widgets/plot/line_plot.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFutureWatcher>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace tolturn {

namespace {

constexpr double kUmPerMm = 1000.0;
constexpr int kFilterDelay_ms = 250;
constexpr int kProgressPoll_ms = 100;

// Calls `done` with the future's result in `context`'s thread once it is ready; nothing when
// `context` is gone by then (the worker keeps running to its end, on its own connection).
template <typename T, typename Done>
void whenReady(QObject *context, QFuture<T> future, Done done)
{
    auto *watcher = new QFutureWatcher<T>(context);
    QObject::connect(watcher, &QFutureWatcherBase::finished, context, [watcher, done] {
        done(watcher->result());
        watcher->deleteLater();
    });
    watcher->setFuture(std::move(future));
}

struct Listing {
    std::vector<MeasuredPartSummary> parts;
    QString error;
};

struct Reply {
    bool ok = false;
    QString message;
};

struct ModelReading {
    std::optional<LoadedModel> model;
    QString error;
};

struct Comparison {
    std::optional<MeasuredPart> part;
    std::shared_ptr<const LoadedModel> model; // the one compared with, if any
    PartComparison comparison;
    QString error;
};

struct LearningOutcome {
    MachineLearning run;
    std::optional<LoadedModel> kept;
    QString error;
};

} // namespace

MeasurementsPanel::MeasurementsPanel(QWidget *parent)
    : QWidget(parent)
    , m_location(defaultStoreLocation())
    , m_parts(new MeasuredPartsModel(this))
{
    setObjectName(QStringLiteral("measurementsPanel"));
    buildUi();
    connect(&DisplaySettings::instance(), &DisplaySettings::unitsChanged, this, [this] {
        if (const MeasuredPartSummary *p = m_parts->partAt(m_view->currentIndex().row()))
            comparePart(p->id);
    });
    setProject(nullptr);
}

MeasurementsPanel::~MeasurementsPanel()
{
    cancelLearning();
}

void MeasurementsPanel::buildUi()
{
    m_store = new QLabel;
    m_store->setObjectName(QStringLiteral("measurementStore"));
    m_store->setWordWrap(true);
    m_store->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_useLocal = new QPushButton(tr("Use the &Local Store"));
    m_useLocal->setToolTip(tr("Work with the measurement store on this computer until the shop database can be "
                              "reached again (Preferences keep the shop database)."));
    m_useLocal->setObjectName(QStringLiteral("useLocalStore"));
    m_useLocal->hide();
    connect(m_useLocal, &QPushButton::clicked, this, &MeasurementsPanel::useLocalStore);
    m_scope = new QComboBox;
    m_scope->addItem(tr("This project's machine"));
    m_scope->addItem(tr("All machines"));
    connect(m_scope, &QComboBox::currentIndexChanged, this, [this] { startListing(); });
    m_filter = new QLineEdit;
    m_filter->setPlaceholderText(tr("Filter by part, who measured or method"));
    m_filter->setClearButtonEnabled(true);
    m_filterDelay = new QTimer(this);
    m_filterDelay->setSingleShot(true);
    m_filterDelay->setInterval(kFilterDelay_ms);
    connect(m_filter, &QLineEdit::textChanged, m_filterDelay, qOverload<>(&QTimer::start));
    connect(m_filterDelay, &QTimer::timeout, this, &MeasurementsPanel::startListing);
    auto *top = new QHBoxLayout;
    top->addWidget(m_scope);
    top->addWidget(m_filter, 1);

    m_view = new QTableView;
    m_view->setObjectName(QStringLiteral("measuredParts"));
    m_view->setModel(m_parts);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed); // uniform rows: 10⁵ rows scroll at once
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
        updateButtons();
        if (const MeasuredPartSummary *p = m_parts->partAt(m_view->currentIndex().row()))
            comparePart(p->id);
    });

    m_add = new QPushButton(tr("&Add Measured Part…"));
    m_add->setToolTip(tr("Type in (or read from CSV) the measured points of a part cut from the open project."));
    m_remove = new QPushButton(tr("&Remove"));
    m_export = new QPushButton(tr("&Export CSV…"));
    connect(m_add, &QPushButton::clicked, this, [this] { promptAdd(); });
    connect(m_remove, &QPushButton::clicked, this, &MeasurementsPanel::promptRemove);
    connect(m_export, &QPushButton::clicked, this, &MeasurementsPanel::promptExport);
    auto *partButtons = new QHBoxLayout;
    partButtons->addWidget(m_add);
    partButtons->addWidget(m_remove);
    partButtons->addWidget(m_export);
    partButtons->addStretch();

    auto *learned = new QGroupBox(tr("What was learned of the machine"));
    m_modelLabel = new QLabel;
    m_modelLabel->setObjectName(QStringLiteral("learnedModel"));
    m_modelLabel->setWordWrap(true);
    m_modelLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_learn = new QPushButton(tr("L&earn"));
    m_learn->setToolTip(tr("Learn the machine's error beyond the physics from all its measured parts (Li & Du 2022: "
                           "geometric error by regression, the rest by a hybrid RBF network), check it by leaving "
                           "one part out, and keep it."));
    m_cancel = new QPushButton(tr("Cancel"));
    m_cancel->hide();
    m_progress = new QProgressBar;
    m_progress->hide();
    m_progressPoll = new QTimer(this);
    m_progressPoll->setInterval(kProgressPoll_ms);
    connect(m_progressPoll, &QTimer::timeout, this, [this] {
        if (m_learning) {
            m_progress->setMaximum(std::max(1, m_learning->total.load()));
            m_progress->setValue(m_learning->done.load());
        }
    });
    connect(m_learn, &QPushButton::clicked, this, &MeasurementsPanel::learn);
    connect(m_cancel, &QPushButton::clicked, this, &MeasurementsPanel::cancelLearning);
    m_use = new QCheckBox(tr("&Use in the predictions (verdicts, curves, plan, program, report)"));
    m_use->setObjectName(QStringLiteral("useLearned"));
    connect(m_use, &QCheckBox::toggled, this, [this] { Q_EMIT learnedModelChanged(); });
    auto *learnRow = new QHBoxLayout;
    learnRow->addWidget(m_learn);
    learnRow->addWidget(m_cancel);
    learnRow->addWidget(m_progress, 1);
    learnRow->addStretch();
    auto *learnedLayout = new QVBoxLayout(learned);
    learnedLayout->addWidget(m_modelLabel);
    learnedLayout->addLayout(learnRow);
    learnedLayout->addWidget(m_use);

    m_plot = new LinePlot;
    m_plot->setMinimumHeight(160);
    m_comparisonNote = new QLabel;
    m_comparisonNote->setWordWrap(true);
    m_comparisonNote->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *listPart = new QWidget;
    auto *listLayout = new QVBoxLayout(listPart);
    listLayout->setContentsMargins(0, 0, 0, 0);
    listLayout->addWidget(m_store);
    listLayout->addWidget(m_useLocal, 0, Qt::AlignLeft);
    listLayout->addLayout(top);
    listLayout->addWidget(m_view, 1);
    listLayout->addLayout(partButtons);
    listLayout->addWidget(learned);
    auto *plotPart = new QWidget;
    auto *plotLayout = new QVBoxLayout(plotPart);
    plotLayout->setContentsMargins(0, 0, 0, 0);
    plotLayout->addWidget(m_plot, 1);
    plotLayout->addWidget(m_comparisonNote);
    auto *splitter = new QSplitter(Qt::Horizontal);
    splitter->addWidget(listPart);
    splitter->addWidget(plotPart);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 1);
    plotPart->setMinimumWidth(360);
    m_view->setMinimumWidth(240);
    splitter->setSizes({1, 1}); // half and half when shown
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(splitter);
}

void MeasurementsPanel::setStoreLocation(const StoreLocation &location)
{
    m_location = location;
    const bool had = m_model != nullptr;
    m_model.reset();
    ++m_compareGeneration;
    m_storeError.clear();
    reload();
    loadModel();
    if (had && useLearned())
        Q_EMIT learnedModelChanged();
}

void MeasurementsPanel::setProject(const Project *project)
{
    const QString before = machineId();
    const bool first = project && !m_project;
    m_project = project ? std::optional<Project>(*project) : std::nullopt;
    if (first)
        m_scope->setCurrentIndex(0); // a project opened: its machine's parts
    m_scope->setItemText(0, project ? tr("Machine %1").arg(project->machineId) : tr("This project's machine"));
    m_scope->setEnabled(project != nullptr);
    if (!project)
        m_scope->setCurrentIndex(1);
    updateButtons();
    if (machineId() != before) {
        startListing();
        loadModel();
    }
}

QString MeasurementsPanel::machineId() const
{
    return m_project ? m_project->machineId : QString();
}

bool MeasurementsPanel::useLearned() const
{
    return m_use->isChecked();
}

void MeasurementsPanel::setUseLearned(bool use)
{
    m_use->setChecked(use);
}

std::shared_ptr<const LoadedModel> MeasurementsPanel::activeModel() const
{
    if (!useLearned() || !m_model || !m_project || m_model->record.machineId != m_project->machineId)
        return nullptr;
    return m_model;
}

void MeasurementsPanel::setFilterText(const QString &text)
{
    m_filter->setText(text);
    m_filterDelay->stop();
    startListing();
}

void MeasurementsPanel::setAllMachines(bool all)
{
    m_scope->setCurrentIndex(all || !m_project ? 1 : 0);
    startListing();
}

void MeasurementsPanel::reload()
{
    startListing();
}

void MeasurementsPanel::startListing()
{
    PartFilter filter;
    filter.machineId = m_scope->currentIndex() == 0 ? machineId() : QString();
    filter.text = m_filter->text().trimmed();
    const quint64 generation = ++m_listGeneration;
    const StoreLocation location = m_location;
    m_store->setText(tr("Reading %1…").arg(location.describe()));
    whenReady(this,
              QtConcurrent::run(workerThreads(),
                                [location, filter] {
                                    Listing out;
                                    const auto store = MeasurementStore::open(location, &out.error);
                                    if (store) {
                                        if (auto parts = store->list(filter, &out.error))
                                            out.parts = std::move(*parts);
                                    }
                                    return out;
                                }),
              [this, generation](const Listing &listing) {
                  if (generation != m_listGeneration)
                      return; // a newer listing was asked for meanwhile
                  if (!listing.error.isEmpty()) {
                      m_parts->setParts({});
                      showStoreError(listing.error);
                      Q_EMIT listingFinished(false);
                      return;
                  }
                  m_storeError.clear();
                  m_useLocal->hide();
                  m_total = static_cast<qint64>(listing.parts.size());
                  m_parts->setParts(listing.parts);
                  m_view->resizeColumnsToContents(); // the header's precision: the first 1000 rows
                  m_store->setStyleSheet(QString());
                  m_store->setText(statusText());
                  updateButtons();
                  Q_EMIT listingFinished(true);
              });
}

QString MeasurementsPanel::statusText() const
{
    if (!m_storeError.isEmpty())
        return m_storeError;
    const QString scope =
        m_scope->currentIndex() == 0 && m_project ? tr("of %1").arg(m_project->machineId) : tr("of all machines");
    return tr("%n measured part(s) %1 in %2", nullptr, static_cast<int>(m_total)).arg(scope, m_location.describe());
}

void MeasurementsPanel::showStoreError(const QString &error)
{
    m_storeError = error;
    m_store->setStyleSheet(QStringLiteral("color: #b00020;"));
    m_store->setText(error);
    m_useLocal->setVisible(m_location.kind == StoreLocation::Kind::PostgreSQL);
    updateButtons();
}

void MeasurementsPanel::useLocalStore()
{
    setStoreLocation(defaultStoreLocation());
}

void MeasurementsPanel::updateButtons()
{
    const bool reachable = m_storeError.isEmpty();
    const bool selected = !selectedIds().empty();
    m_add->setEnabled(reachable && m_project.has_value());
    m_remove->setEnabled(reachable && selected);
    m_export->setEnabled(reachable && selected);
    m_learn->setEnabled(reachable && m_project.has_value() && !m_learning);
}

std::vector<qint64> MeasurementsPanel::selectedIds() const
{
    std::set<int> rows;
    for (const QModelIndex &index : m_view->selectionModel()->selectedRows())
        rows.insert(index.row());
    std::vector<qint64> ids;
    for (const int row : rows) {
        if (const MeasuredPartSummary *p = m_parts->partAt(row))
            ids.push_back(p->id);
    }
    return ids;
}

void MeasurementsPanel::loadModel()
{
    const QString machine = machineId();
    const quint64 generation = ++m_modelGeneration;
    if (machine.isEmpty()) {
        m_model.reset();
        showModel();
        return;
    }
    const StoreLocation location = m_location;
    whenReady(this,
              QtConcurrent::run(workerThreads(),
                                [location, machine] {
                                    ModelReading out;
                                    const auto store = MeasurementStore::open(location, &out.error);
                                    if (store)
                                        out.model = latestModelOf(*store, machine, &out.error);
                                    return out;
                                }),
              [this, generation](const ModelReading &reading) {
                  if (generation != m_modelGeneration)
                      return;
                  const qint64 before = m_model ? m_model->record.id : 0;
                  m_model = reading.model ? std::make_shared<const LoadedModel>(*reading.model) : nullptr;
                  showModel();
                  if (!reading.error.isEmpty())
                      m_modelLabel->setText(reading.error);
                  if ((m_model ? m_model->record.id : 0) != before && useLearned())
                      Q_EMIT learnedModelChanged();
              });
}

QString MeasurementsPanel::modelText() const
{
    if (!m_project)
        return tr("Open a project to learn its machine from the parts measured on it.");
    if (!m_model)
        return tr("Nothing has been learned of %1 yet. Learn needs at least two measured parts; the more parts, "
                  "conditions and times of day they cover, the better.")
            .arg(m_project->machineId);
    const LearnedModelRecord &r = m_model->record;
    QString text = tr("Model %1, learned %2 from %3 parts (%4 points). Parts not learned from (leave one part out): "
                      "physics alone %5 µm RMS, physics + learned %6 µm RMS.")
                       .arg(r.id)
                       .arg(QLocale().toString(r.trainedAt.toLocalTime(), QLocale::ShortFormat))
                       .arg(r.parts)
                       .arg(r.points)
                       .arg(QString::number(r.physicsRms_mm * kUmPerMm, 'f', 1),
                            QString::number(r.learnedRms_mm * kUmPerMm, 'f', 1));
    if (const QString worse = learnedWorseThanPhysics(r.physicsRms_mm, r.learnedRms_mm); !worse.isEmpty())
        text += QLatin1Char(' ') + worse + QLatin1Char('.');
    // Where it holds: away from these conditions what was learned is extrapolated.
    if (m_model->model.learnedFrom)
        text += QLatin1Char(' ') + tr("Learned at %1.").arg(learnedDomainText(*m_model->model.learnedFrom));
    return text;
}

void MeasurementsPanel::showModel()
{
    m_modelLabel->setText(modelText());
    m_use->setEnabled(m_model != nullptr);
}

void MeasurementsPanel::promptAdd(const std::optional<MeasuredPart> &typed)
{
    if (!m_project)
        return;
    MeasurementEntryDialog dialog(*m_project, m_measuredBy, this);
    if (typed)
        dialog.setPart(*typed); // what the store refused, to be stored again, nothing typed lost
    if (dialog.exec() != QDialog::Accepted)
        return;
    m_typedPart = dialog.part();
    addPart(*m_typedPart);
}

void MeasurementsPanel::addPart(const MeasuredPart &part)
{
    const StoreLocation location = m_location;
    whenReady(
        this,
        QtConcurrent::run(
            workerThreads(),
            [location, part] {
                Reply out;
                const auto store = MeasurementStore::open(location, &out.message);
                if (!store)
                    return out;
                Diagnostics problems;
                const auto id = store->add(part, problems);
                out.ok = id.has_value();
                QStringList lines;
                for (const Diagnostic &d : problems)
                    lines << d.toString();
                out.message =
                    out.ok
                        ? tr("Part %1 stored with %n point(s).", nullptr, static_cast<int>(part.points.size())).arg(*id)
                        : lines.join(QLatin1Char('\n'));
                return out;
            }),
        [this](const Reply &reply) {
            const std::optional<MeasuredPart> typed = std::exchange(m_typedPart, std::nullopt);
            if (reply.ok)
                startListing();
            else
                QMessageBox::warning(this, tr("Measured Part Not Stored"), reply.message);
            Q_EMIT operationFinished(reply.ok, reply.message);
            if (!reply.ok && typed)
                promptAdd(typed); // the typed part back in its dialog
        });
}

void MeasurementsPanel::promptRemove()
{
    const std::vector<qint64> ids = selectedIds();
    if (ids.empty())
        return;
    const auto answer = QMessageBox::question(
        this, tr("Remove Measured Parts"),
        tr("Remove %n measured part(s) and their points from %1? Models learned before keep what they learned.",
           nullptr, static_cast<int>(ids.size()))
            .arg(m_location.describe()));
    if (answer == QMessageBox::Yes)
        removeParts(ids);
}

void MeasurementsPanel::removeParts(const std::vector<qint64> &ids)
{
    const StoreLocation location = m_location;
    whenReady(this,
              QtConcurrent::run(workerThreads(),
                                [location, ids] {
                                    Reply out;
                                    const auto store = MeasurementStore::open(location, &out.message);
                                    if (!store)
                                        return out;
                                    for (const qint64 id : ids) {
                                        if (!store->remove(id, &out.message))
                                            return out;
                                    }
                                    out.ok = true;
                                    out.message = tr("%n part(s) removed.", nullptr, static_cast<int>(ids.size()));
                                    return out;
                                }),
              [this](const Reply &reply) {
                  startListing();
                  if (!reply.ok)
                      QMessageBox::warning(this, tr("Not Removed"), reply.message);
                  Q_EMIT operationFinished(reply.ok, reply.message);
              });
}

void MeasurementsPanel::promptExport()
{
    const std::vector<qint64> ids = selectedIds();
    if (ids.empty())
        return;
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Measured Parts"),
                                                      QStringLiteral("measured-parts.csv"), tr("CSV files (*.csv)"));
    if (!path.isEmpty())
        exportParts(ids, path);
}

void MeasurementsPanel::exportParts(const std::vector<qint64> &ids, const QString &path)
{
    const StoreLocation location = m_location;
    whenReady(this,
              QtConcurrent::run(workerThreads(),
                                [location, ids, path] {
                                    Reply out;
                                    const auto store = MeasurementStore::open(location, &out.message);
                                    if (!store)
                                        return out;
                                    const auto parts = store->parts(ids, &out.message);
                                    if (!parts)
                                        return out;
                                    out.message = writeFileAtomically(path, measuredPointsCsv(*parts).toUtf8());
                                    out.ok = out.message.isEmpty();
                                    if (out.ok)
                                        out.message =
                                            tr("%n part(s) written to %1.", nullptr, static_cast<int>(parts->size()))
                                                .arg(QDir::toNativeSeparators(path));
                                    return out;
                                }),
              [this](const Reply &reply) {
                  if (!reply.ok)
                      QMessageBox::warning(this, tr("Not Exported"), reply.message);
                  Q_EMIT operationFinished(reply.ok, reply.message);
              });
}

void MeasurementsPanel::learn()
{
    if (m_learning || !m_project)
        return;
    m_learning = std::make_shared<LearningState>();
    const std::shared_ptr<LearningState> state = m_learning;
    const StoreLocation location = m_location;
    const QString machine = m_project->machineId;
    m_learn->setEnabled(false);
    m_cancel->show();
    m_progress->setValue(0);
    m_progress->show();
    m_progressPoll->start();
    m_modelLabel->setText(tr("Learning %1 from its measured parts…").arg(machine));
    whenReady(this,
              QtConcurrent::run(workerThreads(),
                                [location, machine, state] {
                                    LearningOutcome out;
                                    const auto store = MeasurementStore::open(location, &out.error);
                                    if (!store)
                                        return out;
                                    const auto parts = storedPartsOf(*store, machine, &out.error);
                                    if (!parts)
                                        return out;
                                    LearningControl control;
                                    control.cancelled = [state] { return state->cancel.load(); };
                                    control.progress = [state](int done, int total) {
                                        state->total = total;
                                        state->done = done;
                                    };
                                    out.run =
                                        learnMachine(*parts, DataLibrary::builtIn(), RbfTrainingOptions{}, control);
                                    if (!out.run.ok())
                                        return out;
                                    LearnedModelRecord record = learnedModelRecord(machine, out.run);
                                    const auto id = store->addLearnedModel(record, &out.error);
                                    if (id) {
                                        record.id = *id;
                                        out.kept = LoadedModel{record, *out.run.learned};
                                    }
                                    return out;
                                }),
              [this, machine, store = location.describe()](const LearningOutcome &outcome) {
                  // Kept in the store it was learned in; shown only if that store and machine are
                  // still the dock's.
                  const bool current = store == m_location.describe() && machine == machineId();
                  finishLearning(
                      outcome.run, current ? outcome.kept : std::nullopt,
                      current ? outcome.error
                              : tr("the store or the machine changed meanwhile; the model was kept in %1").arg(store));
              });
}

void MeasurementsPanel::finishLearning(const MachineLearning &run, const std::optional<LoadedModel> &kept,
                                       const QString &error)
{
    m_learning.reset();
    m_progressPoll->stop();
    m_progress->hide();
    m_cancel->hide();
    updateButtons();
    QString message = !error.isEmpty() ? error : run.error;
    const bool ok = kept.has_value() && !run.cancelled;
    if (ok) {
        ++m_modelGeneration; // a model read still on its way is older
        ++m_compareGeneration;
        m_model = std::make_shared<const LoadedModel>(*kept);
        message = tr("Learned and kept as model %1.").arg(kept->record.id);
    }
    showModel();
    if (!ok)
        m_modelLabel->setText(run.cancelled
                                  ? tr("Learning cancelled; the model before is kept.") + QLatin1Char(' ') + modelText()
                                  : tr("Nothing learned: %1").arg(message));
    QStringList warnings;
    for (const Diagnostic &d : run.warnings)
        warnings << d.toString();
    if (!warnings.isEmpty())
        m_modelLabel->setText(m_modelLabel->text() + QLatin1Char('\n') + warnings.join(QLatin1Char('\n')));
    if (ok)
        Q_EMIT learnedModelChanged();
    Q_EMIT learningFinished(ok, message);
    if (const MeasuredPartSummary *p = m_parts->partAt(m_view->currentIndex().row()))
        comparePart(p->id);
}

void MeasurementsPanel::cancelLearning()
{
    if (m_learning)
        m_learning->cancel = true;
}

void MeasurementsPanel::comparePart(qint64 id)
{
    const quint64 generation = ++m_compareGeneration;
    const StoreLocation location = m_location;
    std::shared_ptr<const LoadedModel> model = m_model;
    whenReady(this,
              QtConcurrent::run(workerThreads(),
                                [location, id, model] {
                                    Comparison out;
                                    const auto store = MeasurementStore::open(location, &out.error);
                                    if (!store)
                                        return out;
                                    out.part = store->part(id, &out.error);
                                    if (!out.part)
                                        return out;
                                    const bool sameMachine = model && model->record.machineId == out.part->machineId;
                                    if (sameMachine)
                                        out.model = model;
                                    out.comparison =
                                        tolturn::comparePart(*out.part, DataLibrary::builtIn(), out.model.get());
                                    return out;
                                }),
              [this, generation](const Comparison &c) {
                  if (generation != m_compareGeneration)
                      return;
                  if (!c.part || !c.comparison.error.isEmpty()) {
                      m_plot->clear();
                      m_plot->rescaleAndReplot();
                      m_comparisonNote->setText(c.error.isEmpty() ? c.comparison.error : c.error);
                      Q_EMIT comparisonShown(false);
                      return;
                  }
                  showComparison(*c.part, c.comparison, c.model.get());
                  Q_EMIT comparisonShown(true);
              });
}

void MeasurementsPanel::showComparison(const MeasuredPart &part, const PartComparison &comparison,
                                       const LoadedModel *model)
{
    const DisplayUnits units = DisplaySettings::instance().units();
    const double gap = std::numeric_limits<double>::quiet_NaN();
    QVector<double> x;
    QVector<double> physics;
    QVector<double> learned;
    for (const PartComparison::Feature &f : comparison.features) {
        for (std::size_t i = 0; i < f.z_mm.size(); ++i) {
            x << units.lengthFromMm(f.z_mm[i]);
            physics << units.deviationFromUm(f.physics_mm[i] * kUmPerMm);
            learned << (i < f.learned_mm.size() ? units.deviationFromUm(f.learned_mm[i] * kUmPerMm) : gap);
        }
        if (!f.z_mm.empty()) {
            x << units.lengthFromMm(f.z_mm.back());
            physics << gap;
            learned << gap;
        }
    }
    QVector<double> mz;
    QVector<double> measured;
    for (const ResidualSample &s : comparison.measured) {
        mz << units.lengthFromMm(s.z_mm);
        measured << units.deviationFromUm(s.measured_mm * kUmPerMm);
    }
    m_plot->clear();
    m_plot->setTitle(tr("Part %1: measured and predicted radius error").arg(part.id));
    m_plot->setAxisLabels(tr("z from the part's left end [%1]").arg(units.lengthSymbol()),
                          tr("machined − programmed radius [%1]").arg(units.deviationSymbol()));
    m_plot->addCurve(tr("physics"), x, physics, QColor(0x1f, 0x77, 0xb4), Qt::DashLine, 1.8);
    const bool withModel =
        model != nullptr && std::any_of(comparison.features.begin(), comparison.features.end(),
                                        [](const PartComparison::Feature &f) { return !f.learned_mm.empty(); });
    if (withModel) {
        const double u = units.deviationFromUm(model->uncertainty_mm() * kUmPerMm);
        QVector<double> lower;
        QVector<double> upper;
        for (const double v : learned) {
            lower << v - u;
            upper << v + u;
        }
        const QString rms = QString::number(model->uncertainty_mm() * kUmPerMm, 'f', 1);
        m_plot->addBand(tr("physics + learned − %1 µm").arg(rms), tr("physics + learned + %1 µm").arg(rms), x, lower,
                        upper, QColor(0x20, 0x20, 0x20));
        m_plot->addCurve(tr("physics + learned"), x, learned, QColor(0x20, 0x20, 0x20), Qt::SolidLine, 2.2);
    }
    m_plot->addPoints(tr("measured"), mz, measured, QColor(0xd6, 0x27, 0x28));
    m_plot->rescaleAndReplot();
    QStringList notes;
    notes << tr("Measured %1 by %2 (%3), %n point(s) compared.", nullptr, static_cast<int>(comparison.measured.size()))
                 .arg(QLocale().toString(part.measuredAt.toLocalTime(), QLocale::ShortFormat), part.measuredBy,
                      part.method);
    if (!withModel)
        notes << tr("No model of %1 to compare with: Learn, then select the part again.").arg(part.machineId);
    for (const Diagnostic &d : comparison.warnings)
        notes << d.toString();
    m_comparisonNote->setText(notes.join(QLatin1Char('\n')));
}

} // namespace tolturn
