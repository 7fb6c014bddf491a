// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/planning/adaptive_tab.h"

#include "core/planning/planning_report.h"
#include "widgets/common/table_cells.h"
#include "widgets/common/table_copy.h"
#include "widgets/plot/line_plot.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>
#include <limits>

namespace tolturn {

namespace {

enum class Quantity { Force, Feed, Deviation, Roughness, Depth };

QString number(double v, int decimals)
{
    return QString::number(v, 'f', decimals);
}

double valueOf(const ControlSample &s, Quantity q)
{
    switch (q) {
    case Quantity::Force:
        return s.force_N;
    case Quantity::Feed:
        return s.feed_mm_rev;
    case Quantity::Deviation:
        return s.deviation_um;
    case Quantity::Roughness:
        return s.ra_um;
    case Quantity::Depth:
        return s.depth_mm;
    }
    return 0.0;
}

// The run along z, with a gap where the tool cuts air.
void addRun(LinePlot &plot, const QString &name, const ControlRun &run, Quantity q, const QColor &color,
            Qt::PenStyle style)
{
    QVector<double> z;
    QVector<double> y;
    z.reserve(static_cast<qsizetype>(run.samples.size()));
    y.reserve(static_cast<qsizetype>(run.samples.size()));
    double previous = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = run.samples.size(); i-- > 0;) { // z ascending
        const ControlSample &s = run.samples[i];
        if (s.z_mm - previous > 0.5) { // a stretch crossed in rapid
            z << 0.5 * (s.z_mm + previous);
            y << std::numeric_limits<double>::quiet_NaN();
        }
        z << s.z_mm;
        y << valueOf(s, q);
        previous = s.z_mm;
    }
    plot.addCurve(name, z, y, color, style);
}

} // namespace

AdaptiveTab::AdaptiveTab(QWidget *parent)
    : QWidget(parent)
    , m_pass(new QComboBox(this))
    , m_quantity(new QComboBox(this))
    , m_noise(new QDoubleSpinBox(this))
    , m_plot(new LinePlot(this))
    , m_controlSummary(new QLabel(this))
    , m_table(new QTableWidget(this))
    , m_scheduleSummary(new QLabel(this))
{
    m_pass->setObjectName(QStringLiteral("adaptivePass"));
    m_pass->setToolTip(tr("The pass of the plan simulated under constant-force control"));
    m_quantity->setObjectName(QStringLiteral("adaptiveQuantity"));
    m_quantity->addItem(tr("Force [N]"), static_cast<int>(Quantity::Force));
    m_quantity->addItem(tr("Feed [mm/rev]"), static_cast<int>(Quantity::Feed));
    m_quantity->addItem(tr("Deviation [µm]"), static_cast<int>(Quantity::Deviation));
    m_quantity->addItem(tr("Roughness Ra [µm]"), static_cast<int>(Quantity::Roughness));
    m_quantity->addItem(tr("Depth of cut [mm]"), static_cast<int>(Quantity::Depth));
    m_noise->setObjectName(QStringLiteral("adaptiveNoise"));
    m_noise->setRange(0.0, 50.0);
    m_noise->setDecimals(1);
    m_noise->setSuffix(QStringLiteral(" %"));
    m_noise->setToolTip(tr("Machine noise (Čuš & Župerl §2.4): the standard deviation of the measured force. The "
                           "paper states no level; none unless given."));
    auto *top = new QHBoxLayout;
    top->addWidget(m_pass);
    top->addWidget(m_quantity);
    top->addWidget(new QLabel(tr("Machine noise:"), this));
    top->addWidget(m_noise);
    top->addStretch();
    m_controlSummary->setObjectName(QStringLiteral("adaptiveSummary"));
    m_controlSummary->setWordWrap(true);
    m_controlSummary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_table->setObjectName(QStringLiteral("feedSchedule"));
    m_table->setColumnCount(4);
    m_table->setHorizontalHeaderLabels(
        {tr("Feature"), tr("Scheduled f [mm/rev]"), tr("Programmed f [mm/rev]"), tr("Limited by")});
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setToolTip(tr("The finishing pass feature by feature: the largest feed of the plan's feed range that "
                           "holds the feature's tolerances and the pass's roughness, power and force limits"));
    addCopyAsCsv(*m_table);
    m_scheduleSummary->setObjectName(QStringLiteral("scheduleSummary"));
    m_scheduleSummary->setWordWrap(true);
    m_scheduleSummary->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *upper = new QWidget(this);
    auto *upperLayout = new QVBoxLayout(upper);
    upperLayout->setContentsMargins(0, 0, 0, 0);
    upperLayout->addLayout(top);
    upperLayout->addWidget(m_plot, 1);
    upperLayout->addWidget(m_controlSummary);
    auto *lower = new QWidget(this);
    auto *lowerLayout = new QVBoxLayout(lower);
    lowerLayout->setContentsMargins(0, 0, 0, 0);
    lowerLayout->addWidget(new QLabel(tr("<b>Feed schedule of the finishing pass</b>"), this));
    lowerLayout->addWidget(m_table, 1);
    lowerLayout->addWidget(m_scheduleSummary);
    auto *split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(upper);
    split->addWidget(lower);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(split);

    connect(m_pass, &QComboBox::currentIndexChanged, this, &AdaptiveTab::showRun);
    connect(m_quantity, &QComboBox::currentIndexChanged, this, &AdaptiveTab::showRun);
    connect(m_noise, &QDoubleSpinBox::valueChanged, this, &AdaptiveTab::simulate);
}

void AdaptiveTab::setProject(const Project &project, std::shared_ptr<const LoadedModel> learned)
{
    m_project = project;
    m_learned = std::move(learned);
    m_hasProject = true;
    simulate();
    m_schedule = scheduleProjectFinishingFeeds(m_project, DataLibrary::builtIn(), m_learned);
    m_constantTime_s = m_scheduledTime_s = 0.0;
    if (m_schedule.ok()) {
        GCodeOptions options;
        m_constantTime_s =
            60.0 * outerFinishingTime_min(finishingOutput(m_project, DataLibrary::builtIn(), options).nominal.passes);
        options.finishingFeeds_mm_rev = m_schedule.feedByFeature();
        m_scheduledTime_s =
            60.0 * outerFinishingTime_min(finishingOutput(m_project, DataLibrary::builtIn(), options).nominal.passes);
    }
    showSchedule();
}

void AdaptiveTab::clear(const QString &why)
{
    m_hasProject = false;
    m_control = {};
    m_schedule = {};
    m_pass->clear();
    m_plot->clear();
    m_plot->rescaleAndReplot();
    m_table->setRowCount(0);
    m_controlSummary->setText(why);
    m_scheduleSummary->setText(why);
}

void AdaptiveTab::simulate()
{
    if (!m_hasProject)
        return;
    ProjectControlOptions options;
    options.control.forceNoise = m_noise->value() / 100.0;
    m_control = simulateProjectControl(m_project, DataLibrary::builtIn(), options);
    const int chosen = m_pass->currentIndex();
    {
        const QSignalBlocker block(m_pass);
        m_pass->clear();
        for (const PassControlResult &p : m_control.passes)
            m_pass->addItem(p.pass.conditions.kind == PassKind::Roughing
                                ? tr("Pass %1 (roughing)").arg(p.pass.passIndex + 1)
                                : tr("Pass %1 (finishing)").arg(p.pass.passIndex + 1));
        m_pass->setCurrentIndex(chosen >= 0 && chosen < m_pass->count() ? chosen : 0);
    }
    showRun();
}

void AdaptiveTab::showRun()
{
    m_plot->clear();
    const int i = m_pass->currentIndex();
    if (!m_control.ok() || i < 0 || i >= static_cast<int>(m_control.passes.size())) {
        QStringList problems;
        for (const Diagnostic &d : m_control.diagnostics)
            problems << d.toString();
        m_controlSummary->setText(problems.isEmpty() ? tr("No pass to simulate.") : problems.join(QLatin1Char('\n')));
        m_plot->rescaleAndReplot();
        return;
    }
    const PassControlResult &p = m_control.passes[static_cast<std::size_t>(i)];
    const auto q = static_cast<Quantity>(m_quantity->currentData().toInt());
    m_plot->setTitle(m_pass->currentText());
    m_plot->setAxisLabels(tr("z [mm]"), m_quantity->currentText());
    if (q == Quantity::Depth) {
        addRun(*m_plot, tr("depth of cut"), p.constantFeed, q, QColor(0x2b, 0x8c, 0xbe), Qt::SolidLine);
    } else {
        addRun(*m_plot, tr("programmed feed"), p.constantFeed, q, QColor(0x88, 0x88, 0x88), Qt::DashLine);
        addRun(*m_plot, tr("adaptive"), p.adaptive, q, QColor(0xd9, 0x5f, 0x0e), Qt::SolidLine);
    }
    m_plot->rescaleAndReplot();
    const double saved =
        p.constantFeed.time_s > 0.0 ? 100.0 * (p.constantFeed.time_s - p.adaptive.time_s) / p.constantFeed.time_s : 0.0;
    m_controlSummary->setText(
        tr("Set force %1 N (the programmed feed's at a_p %2 mm). In the cut %3 s at the programmed feed, %4 s "
           "adaptive (%5 % saved); peak force %6 N and %7 N; deviation %8–%9 µm and %10–%11 µm.")
            .arg(number(p.setForce_N, 0), number(p.pass.conditions.depthOfCut_mm, 2), number(p.constantFeed.time_s, 1),
                 number(p.adaptive.time_s, 1), number(saved, 1), number(p.constantFeed.peakForce_N, 0),
                 number(p.adaptive.peakForce_N, 0), number(p.constantFeed.smallestDeviation_um, 1),
                 number(p.constantFeed.largestDeviation_um, 1))
            .arg(number(p.adaptive.smallestDeviation_um, 1), number(p.adaptive.largestDeviation_um, 1)) +
        QLatin1Char('\n') + m_control.notes.mid(0, 2).join(QLatin1Char(' ')));
    m_controlSummary->setToolTip(m_control.notes.join(QLatin1Char('\n')));
}

void AdaptiveTab::showSchedule()
{
    m_table->setRowCount(0);
    if (!m_schedule.ok()) {
        QStringList problems;
        for (const Diagnostic &d : m_schedule.diagnostics)
            if (d.severity == Severity::Error)
                problems << d.toString();
        m_scheduleSummary->setText(tr("No feed schedule: %1").arg(problems.join(QStringLiteral("; "))));
        return;
    }
    m_table->setRowCount(static_cast<int>(m_schedule.features.size()));
    for (int r = 0; r < m_table->rowCount(); ++r) {
        const ScheduledFeed &f = m_schedule.features[static_cast<std::size_t>(r)];
        m_table->setItem(r, 0, readOnlyCell(f.featureId));
        m_table->setItem(r, 1, readOnlyCell(number(f.feed_mm_rev, 3)));
        m_table->setItem(r, 2, readOnlyCell(number(m_schedule.programmedFeed_mm_rev, 3)));
        m_table->setItem(
            r, 3,
            readOnlyCell(f.held ? tr("kept: %1 is not held at any feed of the range").arg(f.limitedBy) : f.limitedBy));
    }
    m_table->resizeColumnsToContents();
    const double change =
        m_constantTime_s > 0.0 ? 100.0 * (m_scheduledTime_s - m_constantTime_s) / m_constantTime_s : 0.0;
    m_scheduleSummary->setText(
        tr("Finishing pass: %1 s at the programmed feed, %2 s scheduled (%3 %). Tick Feed "
           "schedule on the G-code tab to program it.")
            .arg(number(m_constantTime_s, 1), number(m_scheduledTime_s, 1), QString::asprintf("%+.1f", change)));
}

} // namespace tolturn
