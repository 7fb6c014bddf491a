// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/planning/end_milling_example_dialog.h"

#include "widgets/common/table_cells.h"
#include "widgets/plot/line_plot.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <functional>

namespace tolturn {

namespace {

enum class Quantity { Force, FeedRate, Spindle, Roughness };

// 004 table 1, simulation 5, after control: what the paper reports for the run shown.
struct PaperValue {
    double value;
    QString what;
};

} // namespace

EndMillingExampleDialog::EndMillingExampleDialog(QWidget *parent)
    : QDialog(parent)
    , m_quantity(new QComboBox(this))
    , m_noise(new QDoubleSpinBox(this))
    , m_speedShare(new QDoubleSpinBox(this))
    , m_plot(new LinePlot(this))
    , m_summary(new QLabel(this))
    , m_table(new QTableWidget(this))
{
    setWindowTitle(tr("Čuš & Župerl end-milling example"));
    setObjectName(QStringLiteral("endMillingExampleDialog"));
    m_quantity->setObjectName(QStringLiteral("endMillingQuantity"));
    m_quantity->addItem(tr("Force [N]"), static_cast<int>(Quantity::Force));
    m_quantity->addItem(tr("Feed rate [mm/min]"), static_cast<int>(Quantity::FeedRate));
    m_quantity->addItem(tr("Spindle speed [1/min]"), static_cast<int>(Quantity::Spindle));
    m_quantity->addItem(tr("Roughness Ra, M5 [µm]"), static_cast<int>(Quantity::Roughness));
    m_noise->setObjectName(QStringLiteral("endMillingNoise"));
    m_noise->setRange(0.0, 50.0);
    m_noise->setSuffix(QStringLiteral(" %"));
    m_noise->setKeyboardTracking(false); // a run takes most of a second: not at every key
    m_speedShare->setKeyboardTracking(false);
    m_noise->setToolTip(tr("Machine noise: standard deviation of the measured force (004 gives no level)"));
    m_speedShare->setRange(0.0, 1.0);
    m_speedShare->setSingleStep(0.1);
    m_speedShare->setValue(0.5);
    m_speedShare->setToolTip(tr("Share of a change of chip load the spindle speed takes (0: the feed alone)"));
    auto *controls = new QHBoxLayout;
    controls->addWidget(m_quantity);
    controls->addWidget(new QLabel(tr("Noise"), this));
    controls->addWidget(m_noise);
    controls->addWidget(new QLabel(tr("Speed share"), this));
    controls->addWidget(m_speedShare);
    controls->addStretch();
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_table->setObjectName(QStringLiteral("endMillingTable"));
    m_table->setColumnCount(7);
    m_table->setHorizontalHeaderLabels({tr("Force [N]"), tr("Feed rate [mm/min]"), tr("Paper"), tr("Speed [1/min]"),
                                        tr("Paper"), tr("Ra, M5 [µm]"), tr("Paper")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->verticalHeader()->hide();
    auto *splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_plot);
    splitter->addWidget(m_table);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addWidget(splitter, 1);
    layout->addWidget(m_summary);
    layout->addWidget(buttons);
    resize(900, 680); // fits a 1366 × 768 screen
    connect(m_quantity, &QComboBox::currentIndexChanged, this, &EndMillingExampleDialog::showRun);
    connect(m_noise, &QDoubleSpinBox::valueChanged, this, &EndMillingExampleDialog::simulate);
    connect(m_speedShare, &QDoubleSpinBox::valueChanged, this, &EndMillingExampleDialog::simulate);
    simulate();
}

void EndMillingExampleDialog::simulate()
{
    SeedControlSettings settings;
    settings.forceNoise = m_noise->value() / 100.0;
    settings.speedShare = m_speedShare->value();
    if (m_result.network)
        rerunSeedLoop(m_result, settings); // the network and the conditions do not change
    else
        m_result = runSeedExample(settings);
    showRun();
    showTable();
}

void EndMillingExampleDialog::showRun()
{
    const auto q = static_cast<Quantity>(m_quantity->currentData().toInt());
    const std::function<double(const SeedControlSample &)> value = [q](const SeedControlSample &s) {
        switch (q) {
        case Quantity::Force:
            return s.force_N;
        case Quantity::FeedRate:
            return s.feedRate_mm_min;
        case Quantity::Spindle:
            return s.spindle_rpm;
        case Quantity::Roughness:
            return s.ra_um;
        }
        return 0.0;
    };
    const PaperValue paper = q == Quantity::Force      ? PaperValue{181.1, tr("paper: 181.1 N held")}
                             : q == Quantity::FeedRate ? PaperValue{324.61, tr("paper: 324.61 mm/min after control")}
                             : q == Quantity::Spindle  ? PaperValue{2201.0, tr("paper: 2201 1/min after control")}
                                                       : PaperValue{0.79, tr("paper: Ra 0.79 µm produced")};
    m_plot->clear();
    m_plot->setTitle(tr("Table 1, simulation 5: from 430.41 mm/min and 1610 1/min to 181.1 N"));
    m_plot->setAxisLabels(tr("t [s]"), m_quantity->currentText());
    QVector<double> t;
    QVector<double> adaptive;
    QVector<double> uncontrolled;
    for (std::size_t k = 0; k < m_result.loop.adaptive.size(); ++k) {
        t << m_result.loop.adaptive[k].time_s;
        adaptive << value(m_result.loop.adaptive[k]);
        uncontrolled << value(m_result.loop.uncontrolled[k]);
    }
    m_plot->addCurve(tr("without control"), t, uncontrolled, QColor(0x99, 0x99, 0x99));
    m_plot->addCurve(tr("adaptive"), t, adaptive, QColor(0x1f, 0x77, 0xb4), Qt::SolidLine, 2.0);
    if (!t.isEmpty())
        m_plot->addCurve(paper.what, {t.front(), t.back()}, {paper.value, paper.value}, QColor(0xd6, 0x27, 0x28),
                         Qt::DashLine);
    m_plot->rescaleAndReplot();
}

void EndMillingExampleDialog::showTable()
{
    m_table->setRowCount(static_cast<int>(m_result.table.size()));
    int row = 0;
    for (const SeedRowResult &r : m_result.table) {
        const bool outside = outsideSeedNetworkRange(r.settled.feedRate_mm_min, r.settled.spindle_rpm);
        const QStringList cells{QString::number(r.paper.force_N, 'f', 1),
                                QString::number(r.settled.feedRate_mm_min, 'f', 1),
                                QString::number(r.paper.feedRate_mm_min, 'f', 2),
                                QString::number(r.settled.spindle_rpm, 'f', 0) +
                                    (outside ? QStringLiteral(" *") : QString()),
                                QString::number(r.paper.spindle_rpm, 'f', 0),
                                QString::number(r.settled.ra_um, 'f', 3),
                                QString::number(r.paper.producedRa_um, 'f', 2)};
        for (int c = 0; c < cells.size(); ++c)
            m_table->setItem(row, c, readOnlyCell(cells[c], Qt::AlignRight | Qt::AlignVCenter));
        ++row;
    }
    const SeedConditions &swarm = m_result.conditions.front();
    m_summary->setText(
        tr("Force network 8–15–3 (ArcTangent, back-propagation) trained on the mean forces of the linear edge-force "
           "model for Al7075-T6 (004's cut data are not published): %1 % RMS error on cut data it has not seen. "
           "Tool Ø%2 mm, %3 flutes, down milling %4 mm wide, %5 mm deep (the depth at which the model gives the "
           "paper's 181.1 N at its controlled conditions). PSO-NN off line: %6 mm/min at %7 1/min within %8 N. "
           "Ra from the printed M5 (eq. 6), which does not reproduce the paper's table; the spindle follows the feed "
           "drive's eq. 1 (004 gives no spindle model). * outside the network's training range.")
            .arg(100.0 * m_result.unseenError, 0, 'f', 2)
            .arg(m_result.setup.toolDiameter_mm)
            .arg(m_result.setup.flutes)
            .arg(m_result.setup.radialDepth_mm)
            .arg(m_result.setup.axialDepth_mm, 0, 'f', 2)
            .arg(swarm.feedRate_mm_min, 0, 'f', 1)
            .arg(swarm.spindle_rpm, 0, 'f', 0)
            .arg(m_result.settings.setForce_N));
}

} // namespace tolturn
