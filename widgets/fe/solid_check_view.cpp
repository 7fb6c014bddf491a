// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/fe/solid_check_view.h"

#include "widgets/common/table_cells.h"
#include "widgets/common/table_copy.h"
#include "widgets/plot/line_plot.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {

constexpr double kUmPerMm = 1000.0;
const QColor kBeamColor(0x1f, 0x77, 0xb4);
const QColor kSolidColor(0xd6, 0x27, 0x28);

// Decimals that give the largest deflection of the table three significant digits (deflections of
// a stiff part are hundredths of a micrometre, those of a slender one tens of micrometres).
int deflectionDecimals(const std::vector<SolidCheckStation> &stations, const DisplayUnits &units)
{
    double largest = 0.0;
    for (const SolidCheckStation &s : stations)
        for (const double v : {s.beamRadial_mm, s.solidRadial_mm, s.beamTangential_mm, s.solidTangential_mm})
            largest = std::max(largest, std::abs(units.deviationFromUm(v * kUmPerMm)));
    if (!(largest > 0.0))
        return 1;
    return std::clamp(2 - static_cast<int>(std::floor(std::log10(largest))), 0, 4);
}

} // namespace

SolidCheckView::SolidCheckView(QWidget *parent)
    : QWidget(parent)
    , m_table(new QTableWidget(this))
    , m_plot(new LinePlot(this))
    , m_summary(new QLabel(this))
    , m_notes(new QLabel(this))
{
    m_table->setObjectName(QStringLiteral("solidCheckTable"));
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->viewport()->installEventFilter(this);
    addCopyAsCsv(*m_table);
    m_summary->setObjectName(QStringLiteral("solidCheckSummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_notes->setObjectName(QStringLiteral("solidCheckNotes"));
    m_notes->setWordWrap(true);
    m_notes->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_notes->setStyleSheet(QStringLiteral("color: #555;"));
    auto *splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_plot);
    splitter->addWidget(m_table);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    splitter->setChildrenCollapsible(false);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(splitter, 1);
    layout->addWidget(m_summary);
    layout->addWidget(m_notes);
    connect(&DisplaySettings::instance(), &DisplaySettings::unitsChanged, this, &SolidCheckView::redraw);
    clear();
}

void SolidCheckView::showResult(const SolidCheckResult &result, double partLength_mm, const QString &clampingName)
{
    m_result = result;
    m_partLength_mm = partLength_mm;
    m_clamping = clampingName;
    redraw();
}

void SolidCheckView::clear()
{
    m_result.reset();
    m_clamping.clear();
    redraw();
}

QString SolidCheckView::summaryText() const
{
    return m_summary->text();
}

QString SolidCheckView::notesText() const
{
    return m_notes->text();
}

void SolidCheckView::redraw()
{
    const DisplayUnits units = DisplaySettings::instance().units();
    fillTable(units);
    drawPlot(units);
    m_summary->setText(m_result ? summary(units) : QString());
    m_notes->setText(m_result ? QStringLiteral("• ") + m_result->notes.join(QStringLiteral("\n• ")) : QString());
    m_table->setVisible(m_result.has_value()); // an empty table would say nothing
    m_summary->setVisible(m_result.has_value());
    m_notes->setVisible(m_result.has_value() && !m_result->notes.isEmpty());
}

void SolidCheckView::fillTable(const DisplayUnits &units)
{
    const QString length = units.lengthSymbol();
    const QString deflection = units.deviationSymbol();
    m_table->clear();
    m_table->setColumnCount(8);
    m_table->setHorizontalHeaderLabels(
        {tr("z [%1]").arg(length), tr("Ø [%1]").arg(length), tr("beam radial [%1]").arg(deflection),
         tr("solid radial [%1]").arg(deflection), tr("beam − solid [%]"), tr("beam tangential [%1]").arg(deflection),
         tr("solid tangential [%1]").arg(deflection), tr("Timoshenko radial [%1]").arg(deflection)});
    m_table->horizontalHeaderItem(0)->setToolTip(tr("The tool position, from the end the set-up holds"));
    m_table->horizontalHeaderItem(4)->setToolTip(
        tr("(beam − solid) / solid of the radial deflection: positive where the beam is the softer"));
    m_table->horizontalHeaderItem(7)->setToolTip(
        tr("The beam without its corrections for the root in the jaws and the shoulders (docs/solid-fe.md)"));
    const std::vector<SolidCheckStation> stations = m_result ? m_result->stations : std::vector<SolidCheckStation>{};
    m_table->setRowCount(static_cast<int>(stations.size()));
    const int decimals = deflectionDecimals(stations, units);
    const auto shown = [&units, decimals](double value_mm) {
        return QString::number(units.deviationFromUm(value_mm * kUmPerMm), 'f', decimals);
    };
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const SolidCheckStation &s = stations[static_cast<std::size_t>(row)];
        const QStringList texts{units.lengthText(s.z_mm),
                                units.lengthText(2.0 * s.contactRadius_mm),
                                shown(s.beamRadial_mm),
                                shown(s.solidRadial_mm),
                                QString::number(s.radialDifference_pct(), 'f', 1),
                                shown(s.beamTangential_mm),
                                shown(s.solidTangential_mm),
                                shown(s.timoshenkoRadial_mm)};
        for (int column = 0; column < texts.size(); ++column)
            m_table->setItem(row, column, readOnlyCell(texts[column], Qt::AlignRight | Qt::AlignVCenter));
    }
    fitColumns();
}

bool SolidCheckView::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_table->viewport() && event->type() == QEvent::Resize)
        fitColumns();
    return QWidget::eventFilter(watched, event);
}

void SolidCheckView::fitColumns()
{
    QHeaderView *header = m_table->horizontalHeader();
    m_table->resizeColumnsToContents();
    const int columns = m_table->columnCount();
    int used = 0;
    for (int c = 0; c < columns; ++c)
        used += header->sectionSize(c);
    const int spare = m_table->viewport()->width() - used;
    if (columns == 0 || spare <= 0)
        return;
    for (int c = 0; c < columns; ++c)
        header->resizeSection(c, header->sectionSize(c) + spare / columns);
}

void SolidCheckView::drawPlot(const DisplayUnits &units)
{
    m_plot->clear();
    m_plot->setVisible(m_result.has_value());
    if (!m_result) {
        m_plot->rescaleAndReplot();
        return;
    }
    QVector<double> z;
    QVector<double> beam;
    QVector<double> solid;
    QVector<double> timoshenko;
    for (const SolidCheckStation &s : m_result->stations) {
        z << units.lengthFromMm(s.z_mm);
        beam << units.deviationFromUm(s.beamRadial_mm * kUmPerMm);
        solid << units.deviationFromUm(s.solidRadial_mm * kUmPerMm);
        timoshenko << units.deviationFromUm(s.timoshenkoRadial_mm * kUmPerMm);
    }
    m_plot->setTitle(tr("Radial deflection of the part under the cutting force"));
    m_plot->setAxisLabels(tr("z from the held end [%1]").arg(units.lengthSymbol()),
                          tr("radial deflection [%1]").arg(units.deviationSymbol()));
    if (m_result->beamCorrections)
        m_plot->addCurve(tr("beam without corrections"), z, timoshenko, kBeamColor, Qt::DashLine, 1.0);
    m_plot->addMarkedCurve(m_result->beamCorrections ? tr("beam (corrected)") : tr("beam"), z, beam, kBeamColor);
    m_plot->addPoints(tr("solid (CalculiX)"), z, solid, kSolidColor);
    m_plot->rescaleAndReplot();
    if (m_partLength_mm > 0.0) // the stations on the whole part, none at the plot's edge
        m_plot->setXRange(0.0, units.lengthFromMm(m_partLength_mm));
}

QString SolidCheckView::summary(const DisplayUnits &units) const
{
    const SolidCheckResult &r = *m_result;
    const QString mesh = tr("Mesh: C3D10 tetrahedra of at most %1 %2, %3 nodes, %4 elements, %5 degrees of freedom · "
                            "gmsh %6 s, CalculiX %7 s")
                             .arg(units.lengthText(r.meshSize_mm), units.lengthSymbol())
                             .arg(r.nodes)
                             .arg(r.elements)
                             .arg(r.degreesOfFreedom)
                             .arg(QString::number(r.meshSeconds, 'f', 1), QString::number(r.solveSeconds, 'f', 1));
    const QString load =
        tr("Held: %1 · E = %2 MPa, ν = %3 · force at each station: Fc %4 N, Ff %5 N, Fp %6 N")
            .arg(m_clamping, QString::number(r.youngsModulus_MPa, 'f', 0), QString::number(r.poissonRatio, 'g', 3),
                 QString::number(r.forces.tangential_N, 'f', 0), QString::number(r.forces.axial_N, 'f', 0),
                 QString::number(r.forces.radial_N, 'f', 0));
    return mesh + QLatin1Char('\n') + load;
}

} // namespace tolturn
