// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/planning/planning_panel.h"

#include "core/common/atomic_file.h"
#include "core/common/diagnostic.h"
#include "core/deviation/deviation_model.h"
#include "core/planning/gcode.h"
#include "core/planning/planning_problem.h"
#include "core/project/keywords.h"
#include "core/project/operations.h"
#include "widgets/common/project_fields.h"
#include "widgets/common/table_cells.h"
#include "widgets/common/table_copy.h"
#include "widgets/document/project_document.h"
#include "widgets/planning/adaptive_tab.h"
#include "widgets/planning/planning_data_dialog.h"
#include "widgets/plot/map_plot.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <map>

namespace tolturn {

namespace {

// A colour per constraint for the infeasible points of the window map.
QColor constraintColor(const QString &keyword)
{
    static const std::map<QString, QColor> colors{{QStringLiteral("tolerances"), QColor(0xd6, 0x27, 0x28)},
                                                  {QStringLiteral("roughness"), QColor(0x94, 0x67, 0xbd)},
                                                  {QStringLiteral("power"), QColor(0xff, 0x7f, 0x0e)},
                                                  {QStringLiteral("torque"), QColor(0x8c, 0x56, 0x4b)},
                                                  {QStringLiteral("force"), QColor(0xe3, 0x77, 0xc2)},
                                                  {QStringLiteral("spindle_speed"), QColor(0x17, 0xbe, 0xcf)},
                                                  {QStringLiteral("tool_life"), QColor(0xbc, 0xbd, 0x22)},
                                                  {QStringLiteral("roughing_depth"), QColor(0x7f, 0x7f, 0x7f)},
                                                  {QStringLiteral("bar_overhang"), QColor(0x1f, 0x77, 0xb4)}};
    const auto it = colors.find(keyword);
    return it == colors.end() ? QColor(Qt::gray) : it->second;
}

void setupTable(QTableWidget *table, const QStringList &headers)
{
    table->setColumnCount(static_cast<int>(headers.size()));
    table->setHorizontalHeaderLabels(headers);
    table->verticalHeader()->hide();
    table->horizontalHeader()->setStretchLastSection(true);
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    addCopyAsCsv(*table);
}

QString number(double v, int decimals)
{
    return formatFixed(v, decimals);
}

} // namespace

PlanningPanel::PlanningPanel(ProjectDocument &document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_objective(new QComboBox(this))
    , m_plane(new QComboBox(this))
    , m_run(new QPushButton(tr("Optimise"), this))
    , m_cancel(new QPushButton(tr("Cancel"), this))
    , m_apply(new QPushButton(tr("Apply to Passes"), this))
    , m_data(new QPushButton(tr("Planning Data…"), this))
    , m_progress(new QProgressBar(this))
    , m_tabs(new QTabWidget(this))
    , m_plan(new QLabel(this))
    , m_map(new MapPlot(this))
    , m_legend(new QLabel(this))
    , m_clamping(new QTableWidget(this))
    , m_compensation(new QTableWidget(this))
    , m_compensated(new QCheckBox(tr("Compensated"), this))
    , m_scheduled(new QCheckBox(tr("Feed schedule"), this))
    , m_adaptive(new AdaptiveTab(this))
    , m_dialect(new QComboBox(this))
    , m_nose(new QComboBox(this))
    , m_gcodeConditions(new QLabel(this))
    , m_gcode(new QPlainTextEdit(this))
    , m_export(new QPushButton(tr("Export G-code…"), this))
{
    setObjectName(QStringLiteral("planningPanel"));
    m_apply->setObjectName(QStringLiteral("applyPlan"));
    buildControls();
    connect(&m_runner, &JobRunner::progressChanged, this,
            [this](double fraction) { m_progress->setValue(static_cast<int>(100.0 * fraction)); });
    connect(&m_runner, &JobRunner::failed, this, [this](const QString &what) {
        m_run->setEnabled(!m_document.hasProblems());
        m_cancel->setEnabled(false);
        m_progress->setValue(0);
        m_plan->setText(tr("The optimisation failed: %1").arg(what));
        Q_EMIT finished();
    });
    showProjectOutputs();
}

PlanningPanel::~PlanningPanel() = default; // the runner stops the job and waits for it

void PlanningPanel::buildControls()
{
    m_objective->addItem(tr("Least time per part"), static_cast<int>(PlanningObjective::Time));
    m_objective->addItem(tr("Least cost per part"), static_cast<int>(PlanningObjective::Cost));
    m_plane->addItem(tr("Window: feed – cutting speed"), static_cast<int>(WindowPlane::FeedSpeed));
    m_plane->addItem(tr("Window: feed – depth of cut"), static_cast<int>(WindowPlane::FeedDepth));
    m_cancel->setEnabled(false);
    m_apply->setEnabled(false);
    m_progress->setRange(0, 100);
    m_progress->setValue(0);
    auto *top = new QHBoxLayout;
    for (QWidget *w :
         std::initializer_list<QWidget *>{m_data, m_objective, m_plane, m_run, m_cancel, m_progress, m_apply})
        top->addWidget(w);
    // Two rows of switches, so that the dock stays narrow enough for a laptop screen.
    auto *constraints = new QGridLayout;
    constraints->addWidget(new QLabel(tr("Constraints:"), this), 0, 0);
    const auto perRow = static_cast<int>((planningConstraintKeywords().size() + 1) / 2);
    for (const QString &keyword : planningConstraintKeywords()) {
        auto *box = new QCheckBox(QString(keyword).replace(QLatin1Char('_'), QLatin1Char(' ')), this);
        box->setProperty("constraint", keyword);
        box->setToolTip(tr("Switch the %1 constraint on or off (docs/planning.md §2)").arg(keyword));
        connect(box, &QCheckBox::toggled, this, &PlanningPanel::settingsEdited);
        const auto index = static_cast<int>(m_constraints.size());
        constraints->addWidget(box, index / perRow, 1 + index % perRow);
        m_constraints.push_back(box);
    }
    constraints->setColumnStretch(perRow + 1, 1);
    m_plan->setWordWrap(true);
    m_plan->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_plan->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_legend->setWordWrap(true);
    m_legend->setObjectName(QStringLiteral("windowLegend"));
    auto *windowTab = new QWidget(this);
    auto *windowLayout = new QVBoxLayout(windowTab);
    windowLayout->addWidget(m_map, 1);
    windowLayout->addWidget(m_legend);
    setupTable(m_clamping, {tr("Rank"), tr("Clamping"), tr("Result")});
    setupTable(m_compensation, {tr("Feature"), tr("Tolerances"), tr("Action"), tr("Offset Ø [µm]"),
                                tr("Residual before [µm]"), tr("Residual after [µm]"), tr("Note")});
    m_gcode->setReadOnly(true);
    m_gcode->setFont(QFont(QStringLiteral("monospace")));
    auto *gcodeTab = new QWidget(this);
    auto *gcodeLayout = new QVBoxLayout(gcodeTab);
    auto *gcodeTop = new QHBoxLayout;
    m_dialect->setObjectName(QStringLiteral("gcodeDialect"));
    m_dialect->addItem(tr("Machine's control"));
    for (const ControlDialect d : {ControlDialect::FanucHaas, ControlDialect::Sinumerik, ControlDialect::LinuxCnc})
        m_dialect->addItem(displayName(d), static_cast<int>(d));
    m_dialect->setToolTip(tr("The control the program is written for"));
    m_nose->setObjectName(QStringLiteral("gcodeNose"));
    m_nose->addItem(tr("Nose radius: G41/G42 by the control"), static_cast<int>(NoseHandling::ControlCompensation));
    m_nose->addItem(tr("Nose radius: tip path by TolTurn"), static_cast<int>(NoseHandling::TipPath));
    m_nose->setToolTip(tr("G42: the program is the contour and the control offsets it by the nose radius in its "
                          "tool data. Tip path: TolTurn offsets it, for controls without compensation."));
    m_compensated->setObjectName(QStringLiteral("gcodeCompensated"));
    gcodeTop->addWidget(m_compensated);
    m_scheduled->setObjectName(QStringLiteral("gcodeFeedSchedule"));
    m_scheduled->setToolTip(tr("Cut each feature of the finishing pass at its feed of the Adaptive tab's schedule "
                               "(compensated too: the features no feed holds keep the programmed feed and are "
                               "compensated at it)"));
    gcodeTop->addWidget(m_scheduled);
    gcodeTop->addWidget(m_dialect);
    gcodeTop->addWidget(m_nose);
    gcodeTop->addStretch();
    gcodeTop->addWidget(m_export);
    m_gcodeConditions->setObjectName(QStringLiteral("gcodeConditions"));
    m_gcodeConditions->setWordWrap(true);
    m_gcodeConditions->setTextFormat(Qt::RichText);
    gcodeLayout->addLayout(gcodeTop);
    gcodeLayout->addWidget(m_gcodeConditions);
    gcodeLayout->addWidget(m_gcode);
    m_planPasses = new QTableWidget(this);
    m_planPasses->setObjectName(QStringLiteral("planPasses"));
    setupTable(m_planPasses, {tr("Pass"), tr("Kind"), tr("n [rpm]"), tr("vc [m/min]"), tr("f [mm/rev]"), tr("ap [mm]"),
                              tr("Power [kW]"), tr("Time [min]")});
    m_planPasses->setToolTip(tr("The optimal passes as the program would cut them: the spindle speed range under "
                                "G96 and the spindle limit, the cutting power Fc·vc and the time along the tool path"));
    auto *planTab = new QWidget(this);
    auto *planLayout = new QVBoxLayout(planTab);
    planLayout->addWidget(m_plan);
    planLayout->addWidget(m_planPasses, 1);
    m_tabs->addTab(planTab, tr("Plan"));
    m_tabs->addTab(windowTab, tr("Cutting Window"));
    // Below the ranking: the split into operations where the jaws cover features (docs/operations.md).
    auto *clampingTab = new QWidget(this);
    auto *clampingLayout = new QVBoxLayout(clampingTab);
    clampingLayout->setContentsMargins(0, 0, 0, 0);
    clampingLayout->addWidget(m_clamping, 1);
    m_split = new QLabel(clampingTab);
    m_split->setObjectName(QStringLiteral("splitProposal"));
    m_split->setWordWrap(true);
    m_applySplit = new QPushButton(tr("Make These Operations"), clampingTab);
    m_applySplit->setObjectName(QStringLiteral("applySplit"));
    m_applySplit->setToolTip(tr("Add the proposed set-up to the project (undoable); Edit > Operations… changes it"));
    auto *splitRow = new QHBoxLayout;
    splitRow->addWidget(m_split, 1);
    splitRow->addWidget(m_applySplit);
    clampingLayout->addLayout(splitRow);
    connect(m_applySplit, &QPushButton::clicked, this, &PlanningPanel::applySplit);
    m_tabs->addTab(clampingTab, tr("Clamping"));
    m_tabs->addTab(m_compensation, tr("Compensation"));
    m_tabs->addTab(m_adaptive, tr("Adaptive"));
    m_tabs->addTab(gcodeTab, tr("G-code"));
    constraints->setVerticalSpacing(0);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    layout->addLayout(top);
    layout->addLayout(constraints);
    layout->addWidget(m_tabs, 1);

    connect(m_run, &QPushButton::clicked, this, &PlanningPanel::optimise);
    connect(m_cancel, &QPushButton::clicked, this, &PlanningPanel::cancel);
    connect(m_apply, &QPushButton::clicked, this, &PlanningPanel::applyPlan);
    setProjectField(*m_data, QStringLiteral("planning")); // its values are edited in the dialog it opens
    m_data->setToolTip(tr("Rates, tool life, the insert's cutting ranges and the part's limits the optimiser "
                          "works with"));
    connect(m_data, &QPushButton::clicked, this, &PlanningPanel::editPlanningData);
    connect(m_objective, &QComboBox::currentIndexChanged, this, &PlanningPanel::settingsEdited);
    connect(m_compensated, &QCheckBox::toggled, this, &PlanningPanel::showFinishing);
    connect(m_scheduled, &QCheckBox::toggled, this, &PlanningPanel::showFinishing);
    connect(m_dialect, &QComboBox::currentIndexChanged, this, &PlanningPanel::showFinishing);
    connect(m_nose, &QComboBox::currentIndexChanged, this, &PlanningPanel::showFinishing);
    connect(m_export, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export G-code"), QString(),
                                                          tr("G-code (*.nc *.ngc *.tap);;All files (*)"));
        if (path.isEmpty())
            return;
        const QString error = exportGCode(path);
        if (!error.isEmpty())
            QMessageBox::critical(this, tr("Export G-code"), error);
    });
}

void PlanningPanel::showProjectOutputs()
{
    if (!m_document.hasProject())
        return;
    const bool computable = !m_document.hasProblems();
    m_run->setEnabled(computable && !isRunning());
    m_export->setEnabled(computable);
    if (!computable) {
        m_report.reset(); // a plan of the project as it was before the problem
        m_apply->setEnabled(false);
        m_plan->setText(problemsText());
        m_compensation->setRowCount(0);
        m_gcodeConditions->setText(problemsText());
        m_gcode->clear();
        m_adaptive->clear(problemsText());
        return;
    }
    showSplit();
    const PlanningSettings &s = m_document.project().planning;
    m_updatingControls = true;
    m_objective->setCurrentIndex(m_objective->findData(static_cast<int>(s.objective)));
    for (QCheckBox *box : m_constraints) {
        // A constraint with no limit to check against is never shown as active (issue: no
        // constraint silently dropped): unticked, greyed, and saying why.
        const QString keyword = box->property("constraint").toString();
        const QString label = QString(keyword).replace(QLatin1Char('_'), QLatin1Char(' '));
        const bool known = constraintHasLimit(m_document.project(), DataLibrary::builtIn(), keyword);
        box->setEnabled(known);
        box->setChecked(known && !s.disabledConstraints.contains(keyword));
        box->setText(known ? label : tr("%1: no limit known").arg(label));
        box->setToolTip(known ? tr("Switch the %1 constraint on or off (docs/planning.md §2)").arg(keyword)
                              : tr("No %1 limit is known for this machine and project: it is not checked. Enter one "
                                   "in Planning Data….")
                                    .arg(label));
    }
    m_updatingControls = false;
    if (!m_report && !isRunning())
        m_plan->setText(notRunText());
    m_adaptive->setProject(operationProject(), learnedFor(operationProject()));
    showFinishing();
}

QString PlanningPanel::problemsText()
{
    return tr("The project has problems (listed under Problems): nothing is planned or programmed until they are "
              "repaired.");
}

QString PlanningPanel::notRunText()
{
    return tr("Not optimised yet. Press F5 (or Optimise) to find the cutting conditions that hold every tolerance "
              "at least time or cost; the cutting window, the clamping ranking and the compensation follow. "
              "Planning Data… holds the rates, tool life and the insert's ranges the optimiser works with.");
}

void PlanningPanel::settingsEdited()
{
    if (m_updatingControls || !m_document.hasProject())
        return;
    PlanningSettings s = m_document.project().planning;
    s.objective = static_cast<PlanningObjective>(m_objective->currentData().toInt());
    const QStringList before = s.disabledConstraints;
    s.disabledConstraints.clear();
    for (QCheckBox *box : m_constraints) {
        // A greyed box (no limit known) keeps whatever the project said of it.
        const QString keyword = box->property("constraint").toString();
        if (box->isEnabled() ? !box->isChecked() : before.contains(keyword))
            s.disabledConstraints << keyword;
    }
    (void)m_document.setPlanning(s);
}

void PlanningPanel::editPlanningData()
{
    if (!m_document.hasProject())
        return;
    const Project &project = m_document.project();
    PlanningDataDialog dialog(
        project.planning, DataLibrary::builtIn(), project.materialId,
        [this](const PlanningSettings &s) { return m_document.setPlanning(s); }, this);
    dialog.exec();
}

bool PlanningPanel::isRunning() const
{
    return m_runner.isRunning();
}

void PlanningPanel::optimise()
{
    if (isRunning() || !m_document.hasProject() || m_document.hasProblems())
        return;
    m_runOperation = m_operation;
    PlanningJobOptions options;
    options.plane = static_cast<WindowPlane>(m_plane->currentData().toInt());
    options.learned = learnedFor(operationProject());
    m_run->setEnabled(false);
    m_cancel->setEnabled(true);
    m_progress->setValue(0);
    const Project project = operationProject(); // a copy: the worker never touches the document
    m_runner.start(
        [project, options](const Progress &progress) mutable {
            options.progress = progress;
            return runPlanningJob(project, DataLibrary::builtIn(), options);
        },
        [this](PlanningReport report) { planFinished(std::move(report)); });
    Q_EMIT started();
}

void PlanningPanel::planFinished(PlanningReport report)
{
    m_run->setEnabled(!m_document.hasProblems());
    m_cancel->setEnabled(false);
    if (m_runOperation != m_operation) { // planned for a set-up no longer shown: not this one's
        m_progress->setValue(0);
        Q_EMIT finished();
        return;
    }
    m_report = std::make_unique<PlanningReport>(std::move(report));
    m_progress->setValue(m_report->cancelled ? 0 : 100);
    showReport();
    Q_EMIT finished();
}

void PlanningPanel::cancel()
{
    m_runner.cancel();
}

void PlanningPanel::applyPlan()
{
    if (!m_report || !m_report->problem || !m_report->plan.feasible)
        return;
    const std::vector<CuttingPass> passes = m_report->problem->passesOf(m_report->plan.candidate);
    const Diagnostics problems = m_document.setOperationPasses(m_operation, passes, tr("Apply optimal passes"));
    if (!problems.empty())
        QMessageBox::warning(this, tr("Apply to Passes"), problems.front().toString());
}

void PlanningPanel::setOperation(int index)
{
    if (index == m_operation)
        return;
    m_operation = index;
    cancel();         // a run for the set-up shown before ends, and its result is not shown
    m_report.reset(); // a plan is of one set-up
    m_plan->setText(notRunText());
    m_apply->setEnabled(false);
    showProjectOutputs();
}

Project PlanningPanel::operationProject() const
{
    const Project &project = m_document.project();
    return operationView(project, std::min(m_operation, operationCount(project) - 1));
}

QString PlanningPanel::planText() const
{
    return m_plan->text();
}

void PlanningPanel::showReport()
{
    m_apply->setEnabled(m_report && m_report->plan.feasible && !m_report->cancelled);
    QStringList lines;
    if (!m_report->problem) {
        for (const Diagnostic &d : m_report->diagnostics)
            lines << d.toString();
        m_plan->setText(lines.join(QLatin1Char('\n')));
        return;
    }
    if (m_report->cancelled) {
        m_plan->setText(tr("Cancelled."));
        return;
    }
    const PlanResult &r = m_report->plan;
    const CandidateEvaluation &e = r.evaluation;
    lines << (r.feasible ? tr("Optimal plan") : tr("No plan meets every constraint; the least-violating one:"));
    const QString cost = m_currency.isEmpty() ? tr("%1 (no currency set in Preferences)").arg(number(e.cost, 2))
                                              : QStringLiteral("%1 %2").arg(number(e.cost, 2), m_currency);
    const PlanningSettings &s = m_report->problem->project().planning;
    const bool toolLifeKnown = m_report->problem->knowsToolLife();
    lines << tr("Time per part %1 min (finishing %2 min, roughing %3 min, handling %4 min, tool changes %5); "
                "cost %6; %7")
                 .arg(number(e.time_min, 3), number(e.finishingTime_min, 3), number(e.roughingTime_min, 3),
                      number(s.handlingTime_min, 3),
                      toolLifeKnown ? tr("%1 min").arg(number(s.toolChangeTime_min * e.toolEdgesPerPart, 3))
                                    : tr("not known"),
                      cost,
                      toolLifeKnown ? tr("tool edges %1 per part").arg(number(e.toolEdgesPerPart, 3))
                                    : tr("tool edges not known (no tool life)"));
    lines << tr("Finishing: vc %1 m/min, f %2 mm/rev, ap %3 mm")
                 .arg(number(r.candidate.finishing.cuttingSpeed_m_min, 0), number(r.candidate.finishing.feed_mm_rev, 3),
                      number(r.candidate.finishing.depthOfCut_mm, 3));
    if (r.candidate.roughingPasses > 0)
        lines << tr("Roughing: %n pass(es) at vc %1 m/min, f %2 mm/rev", nullptr, r.candidate.roughingPasses)
                     .arg(number(r.candidate.roughing.cuttingSpeed_m_min, 0),
                          number(r.candidate.roughing.feed_mm_rev, 3));
    for (const ConstraintValue &c : r.binding)
        lines << tr("Binding: %1 (%2 of %3 %4)")
                     .arg(c.label(), QString::number(c.value, 'g', 4), QString::number(c.limit, 'g', 4), c.unit);
    for (const ConstraintValue &c : r.conflicts)
        lines << tr("Violated: %1 %2").arg(c.label(), c.violatedBy());
    for (const QString &remedy : r.remedies)
        lines << tr("To meet it: ") + remedy;
    for (const QString &n : r.notes)
        lines << tr("Note: ") + n;
    m_plan->setText(lines.join(QLatin1Char('\n')));
    showPlanPasses();
    showWindow();
    showClamping();
}

void PlanningPanel::setCurrency(const QString &currency)
{
    m_currency = currency.trimmed();
    if (m_report && m_report->problem && !m_report->cancelled)
        showReport();
}

// The optimal plan as the program would cut it: the project with the plan's passes, its tool path,
// and per pass the spindle speeds, power and time (passSummaries).
void PlanningPanel::showPlanPasses()
{
    m_planPasses->setRowCount(0);
    if (!m_report || !m_report->problem || m_report->cancelled)
        return;
    Project planned = operationProject();
    planned.passes = m_report->problem->passesOf(m_report->plan.candidate);
    const DeviationResult deviation = computeDeviation(planned, DataLibrary::builtIn(), {});
    if (!deviation.inputs)
        return;
    const TurningProgram program = turningProgram(planned, DataLibrary::builtIn(), *deviation.inputs, {});
    m_planPasses->setRowCount(static_cast<int>(program.passes.size()));
    for (int i = 0; i < m_planPasses->rowCount(); ++i) {
        const PassSummary &p = program.passes[static_cast<std::size_t>(i)];
        const QStringList cells{QString::number(p.number),
                                passKindText(p),
                                spanText(number(p.lowestSpeed_rpm, 0), number(p.highestSpeed_rpm, 0)),
                                number(p.conditions.cuttingSpeed_m_min, 0),
                                number(p.conditions.feed_mm_rev, 3),
                                number(p.conditions.depthOfCut_mm, 3),
                                p.power_kW ? number(*p.power_kW, 2) : tr("—"),
                                number(p.time_min, 2)};
        for (int c = 0; c < static_cast<int>(cells.size()); ++c)
            m_planPasses->setItem(i, c, readOnlyCell(cells.at(c)));
    }
    m_planPasses->resizeColumnsToContents();
}

void PlanningPanel::showWindow()
{
    const CuttingWindow &w = m_report->window;
    m_map->clear();
    if (w.cells.empty())
        return;
    // Feasible points shaded by the objective (darker green is better), the others coloured by the
    // constraint they violate most.
    double lo = 1e300;
    double hi = -1e300;
    for (const WindowCell &c : w.cells) {
        if (c.feasible) {
            lo = std::min(lo, c.objective);
            hi = std::max(hi, c.objective);
        }
    }
    QImage image(w.columns, w.rows, QImage::Format_RGB32);
    std::map<QString, std::pair<double, std::pair<double, int>>> centroids; // label -> (sum x, (sum y, n))
    for (int row = 0; row < w.rows; ++row) {
        for (int column = 0; column < w.columns; ++column) {
            const WindowCell &c = w.at(column, row);
            QColor color;
            if (c.feasible) {
                const double t = hi > lo ? (c.objective - lo) / (hi - lo) : 0.0;
                color = QColor::fromRgbF(static_cast<float>(0.30 + 0.55 * t), static_cast<float>(0.62 + 0.30 * t),
                                         static_cast<float>(0.32 + 0.50 * t));
            } else {
                color = constraintColor(c.binding).lighter(150);
                auto &acc = centroids[c.bindingLabel];
                acc.first += c.x;
                acc.second.first += c.y;
                acc.second.second += 1;
            }
            image.setPixel(column, row, color.rgb());
        }
    }
    m_map->setImage(image, w.feed.min, w.feed.max, w.other.min, w.other.max);
    QStringList legend{tr("<b>Green</b>: feasible, darker is better.")};
    for (const auto &[label, acc] : centroids) {
        const int n = acc.second.second;
        QString keyword;
        for (const WindowCell &c : w.cells) {
            if (c.bindingLabel == label) {
                keyword = c.binding;
                break;
            }
        }
        m_map->addLabel(acc.first / n, acc.second.first / n, label, constraintColor(keyword).darker(160));
        legend << QStringLiteral("<span style='color:%1'>■</span> %2").arg(constraintColor(keyword).name(), label);
    }
    const bool speed = w.plane == WindowPlane::FeedSpeed;
    if (m_report->plan.feasible)
        m_map->addMarker(w.base.finishing.feed_mm_rev,
                         speed ? w.base.finishing.cuttingSpeed_m_min : w.base.finishing.depthOfCut_mm, tr("optimum"));
    // The project's own finishing pass, so that the planner sees where the program stands.
    const std::vector<CuttingPass> passes = operationProject().passes;
    if (!passes.empty()) {
        const CuttingPass &programmed = passes.back();
        const double y = speed ? programmed.cuttingSpeed_m_min : programmed.depthOfCut_mm;
        if (!m_map->addMarker(programmed.feed_mm_rev, y, tr("programmed"), MapPlot::Marker::Programmed))
            legend << tr("programmed (f %1 mm/rev, %2 %3) lies outside this window")
                          .arg(formatNumber(programmed.feed_mm_rev), speed ? tr("vc") : tr("ap"), formatNumber(y));
    }
    m_map->setTitle(speed ? tr("Cutting window of the finishing pass: feed – cutting speed")
                          : tr("Cutting window of the finishing pass: feed – depth of cut"));
    m_map->setAxisLabels(tr("feed f [mm/rev]"), speed ? tr("cutting speed vc [m/min]") : tr("depth of cut ap [mm]"));
    m_map->replot();
    m_legend->setText(legend.join(QStringLiteral(" &nbsp; ")));
}

void PlanningPanel::showClamping()
{
    m_clamping->setRowCount(static_cast<int>(m_report->clamping.size()));
    for (int i = 0; i < m_clamping->rowCount(); ++i) {
        const ClampingOption &o = m_report->clamping[static_cast<std::size_t>(i)];
        m_clamping->setItem(i, 0, readOnlyCell(QString::number(i + 1)));
        m_clamping->setItem(i, 1, readOnlyCell(displayName(o.method)));
        m_clamping->setItem(i, 2, readOnlyCell(o.reason));
        // Grey: not possible; green: holds every tolerance; amber: feasible, but leaves a tolerance
        // to another set-up (a feature in the jaws); red: no plan meets every constraint.
        QColor background(0xfc, 0xae, 0x91);
        if (!o.possible)
            background = QColor(0xee, 0xee, 0xee);
        else if (o.plan.feasible)
            background = o.tolerancesNotHeld.empty() ? QColor(0xc7, 0xe9, 0xc0) : QColor(0xfd, 0xe3, 0xc8);
        for (int c = 0; c < 3; ++c)
            m_clamping->item(i, c)->setBackground(background);
    }
    m_clamping->resizeColumnsToContents();
    showSplit();
}

void PlanningPanel::showSplit()
{
    const std::optional<SplitProposal> split =
        m_document.hasProject() ? proposeSplit(m_document.project()) : std::nullopt;
    m_split->setText(split ? tr("Split into operations: %1.").arg(split->reason) : QString());
    m_split->setVisible(split.has_value());
    m_applySplit->setVisible(split.has_value());
}

void PlanningPanel::applySplit()
{
    if (!m_document.hasProject())
        return;
    const std::optional<SplitProposal> split = proposeSplit(m_document.project());
    if (!split)
        return;
    const Diagnostics refused = m_document.setFurtherOperations({split->second});
    if (!refused.empty())
        QMessageBox::warning(this, tr("Make These Operations"), refused.front().toString());
}

// The learned model where it was learned against this project's physics, else none (the banner
// above the verdicts says why, predictSetup).
std::shared_ptr<const LoadedModel> PlanningPanel::learnedFor(const Project &project) const
{
    return m_learned && learnedPhysicsMismatch(project, *m_learned).isEmpty() ? m_learned : nullptr;
}

void PlanningPanel::setLearnedModel(std::shared_ptr<const LoadedModel> model)
{
    if (model == m_learned)
        return;
    m_learned = std::move(model);
    if (m_document.hasProject() && !m_document.hasProblems())
        m_adaptive->setProject(operationProject(), learnedFor(operationProject()));
    showFinishing();
}

void PlanningPanel::showFinishing()
{
    if (!m_document.hasProject() || m_document.hasProblems())
        return;
    GCodeOptions options;
    if (m_dialect->currentData().isValid())
        options.dialect = static_cast<ControlDialect>(m_dialect->currentData().toInt());
    options.nose = static_cast<NoseHandling>(m_nose->currentData().toInt());
    if (m_scheduled->isChecked() && m_adaptive->schedule().ok()) {
        options.finishingFeeds_mm_rev = m_adaptive->schedule().feedByFeature();
        options.roughingFeedSchedule = true;
    }
    const Project project = operationProject();
    DeviationResult deviation = computeDeviation(project, DataLibrary::builtIn(), {});
    if (const auto learned = learnedFor(project))
        deviation = withLearnedResidual(project, std::move(deviation), learned->model, learned->provenance());
    // A scheduled program is compensated from the scheduled pass's deviation.
    if (!options.finishingFeeds_mm_rev.isEmpty())
        deviation = scheduledDeviation(m_adaptive->schedule(), deviation);
    m_finishing = finishingOutputFor(project, DataLibrary::builtIn(), std::move(deviation), options);
    const auto &features = m_finishing.compensation.features;
    m_compensation->setRowCount(static_cast<int>(features.size()));
    for (int i = 0; i < m_compensation->rowCount(); ++i) {
        const FeatureCompensation &f = features[static_cast<std::size_t>(i)];
        const QString action = f.action == CompensationAction::None             ? tr("none")
                               : f.action == CompensationAction::ConstantOffset ? tr("constant offset")
                                                                                : tr("profile correction");
        m_compensation->setItem(i, 0, readOnlyCell(f.featureId));
        m_compensation->setItem(i, 1, readOnlyCell(f.tolerances.join(QStringLiteral(", "))));
        m_compensation->setItem(i, 2, readOnlyCell(action));
        m_compensation->setItem(
            i, 3, readOnlyCell(f.action == CompensationAction::ConstantOffset ? number(f.offset_um, 1) : QString()));
        m_compensation->setItem(i, 4, readOnlyCell(number(f.residualBefore_um, 3)));
        m_compensation->setItem(i, 5, readOnlyCell(number(f.residualAfter_um, 3)));
        m_compensation->setItem(i, 6, readOnlyCell(f.note));
    }
    m_compensation->resizeColumnsToContents();
    const TurningProgram &program = m_compensated->isChecked() ? m_finishing.compensated : m_finishing.nominal;
    QString about =
        tr("The project's passes: %1. Dialect: %2. Program %3, checksum %4.")
            .arg(program.conditions, program.dialectReason, programNumberWord(program.programNumber), program.checksum);
    about = about.toHtmlEscaped();
    QStringList warnings = program.warnings();
    if (m_compensated->isChecked() && m_finishing.deviation.inputs)
        warnings += correctionsBeyondTheCut(m_finishing.compensation,
                                            m_finishing.deviation.inputs->pass.depthOfCut_mm); // not exported
    for (QString &w : warnings)
        w = w.toHtmlEscaped(); // each line escaped, the breaks between them not
    if (!warnings.isEmpty())
        about += QStringLiteral("<br><span style='color:#a50f15'>") + warnings.join(QStringLiteral("<br>")) +
                 QStringLiteral("</span>");
    m_gcodeConditions->setText(about);
    m_gcode->setPlainText(program.text);
}

QString PlanningPanel::gcodeText() const
{
    return m_gcode->toPlainText();
}

QString PlanningPanel::exportGCode(const QString &path) const
{
    if (m_compensated->isChecked() && m_finishing.deviation.inputs) {
        const QStringList beyond =
            correctionsBeyondTheCut(m_finishing.compensation, m_finishing.deviation.inputs->pass.depthOfCut_mm);
        if (!beyond.isEmpty())
            return beyond.join(QLatin1Char('\n'));
    }
    return writeFileAtomically(path, gcodeText().toUtf8());
}

} // namespace tolturn
