// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/plot/line_plot.h"

#include "core/common/csv.h"
#include "widgets/plot/plot_backend.h"

#include <QRegularExpression>
#include <QToolTip>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace tolturn {

LinePlot::LinePlot(QWidget *parent) : QWidget(parent), m_plot(new QCustomPlot(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot->setMinimumHeight(160);
    // Layout: title above, the legend in a narrow column right of the axes, never over the curves.
    m_plot->legend->setVisible(true);
    m_plot->legend->setFont(font());
    m_plot->axisRect()->insetLayout()->take(m_plot->legend);
    m_plot->plotLayout()->addElement(0, 1, m_plot->legend);
    m_plot->plotLayout()->setColumnStretchFactor(1, 0.001);
    m_plot->legend->setMargins(QMargins(6, 6, 6, 6));
    m_plot->plotLayout()->insertRow(0);
    auto *title = new QCPTextElement(m_plot, QString(), QFont(font().family(), 10, QFont::Bold));
    m_plot->plotLayout()->addElement(0, 0, title);
    addPlotContextMenu(*m_plot, [this] { return csvText(); });
    connect(m_plot, &QCustomPlot::mouseMove, this, [this](QMouseEvent *event) { showReadout(event->pos()); });
}

LinePlot::~LinePlot() = default;

void LinePlot::setTitle(const QString &title)
{
    m_title = title;
    if (auto *element = qobject_cast<QCPTextElement *>(m_plot->plotLayout()->element(0, 0)))
        element->setText(title);
}

void LinePlot::setAxisLabels(const QString &xLabel, const QString &yLabel)
{
    m_plot->xAxis->setLabel(xLabel);
    m_plot->yAxis->setLabel(yLabel);
}

void LinePlot::clear()
{
    m_plot->clearGraphs();
}

void LinePlot::addCurve(const QString &name, const QVector<double> &x, const QVector<double> &y, const QColor &color,
                        Qt::PenStyle style, double width)
{
    QCPGraph *graph = m_plot->addGraph();
    graph->setName(name);
    QPen pen(color, width, style);
    graph->setPen(pen);
    graph->setData(x, y, true);
}

void LinePlot::addBand(const QString &lowerName, const QString &upperName, const QVector<double> &x,
                       const QVector<double> &lower, const QVector<double> &upper, const QColor &color)
{
    QCPGraph *low = m_plot->addGraph();
    low->setName(lowerName);
    low->setPen(QPen(color, 1.0, Qt::DotLine));
    low->setData(x, lower, true);
    QCPGraph *high = m_plot->addGraph();
    high->setName(upperName);
    high->setPen(QPen(color, 1.0, Qt::DotLine));
    QColor fill = color;
    fill.setAlpha(50);
    high->setBrush(fill);
    high->setChannelFillGraph(low);
    high->setData(x, upper, true);
    low->removeFromLegend();
}

void LinePlot::addStems(const QString &name, const QVector<double> &x, const QVector<double> &y, const QColor &color)
{
    QCPGraph *graph = m_plot->addGraph();
    graph->setName(name);
    graph->setPen(QPen(color, 2.0));
    graph->setLineStyle(QCPGraph::lsImpulse);
    graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, color, color, 7));
    graph->setData(x, y, true);
}

void LinePlot::addPoints(const QString &name, const QVector<double> &x, const QVector<double> &y, const QColor &color)
{
    QCPGraph *graph = m_plot->addGraph();
    graph->setName(name);
    graph->setPen(QPen(color, 1.5));
    graph->setLineStyle(QCPGraph::lsNone);
    graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCrossCircle, color, 8));
    graph->setData(x, y, false);
}

void LinePlot::addMarkedCurve(const QString &name, const QVector<double> &x, const QVector<double> &y,
                              const QColor &color)
{
    QCPGraph *graph = m_plot->addGraph();
    graph->setName(name);
    graph->setPen(QPen(color, 1.5));
    graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, color, color, 7));
    graph->setData(x, y, false);
}

void LinePlot::rescaleAndReplot()
{
    m_plot->rescaleAxes();
    QCPRange y = m_plot->yAxis->range();
    y.expand(0.0);
    const double pad = 0.08 * std::max(y.size(), 1e-12);
    m_plot->yAxis->setRange(y.lower - pad, y.upper + pad);
    m_plot->replot();
}

void LinePlot::setXRange(double lower, double upper)
{
    m_plot->xAxis->setRange(lower, upper);
    m_plot->replot();
}

int LinePlot::curveCount() const
{
    return m_plot->graphCount();
}

QString LinePlot::curveName(int index) const
{
    return m_plot->graph(index)->name();
}

namespace {

QString csvNumber(double v)
{
    return std::isfinite(v) ? QString::number(v, 'g', 10) : QString();
}

bool sameKeys(const QCPGraph &a, const QCPGraph &b)
{
    if (a.data()->size() != b.data()->size())
        return false;
    auto j = b.data()->constBegin();
    for (auto i = a.data()->constBegin(); i != a.data()->constEnd(); ++i, ++j)
        if (i->key != j->key)
            return false;
    return true;
}

} // namespace

QString LinePlot::csvText() const
{
    bool shared = m_plot->graphCount() > 0;
    for (int g = 1; g < m_plot->graphCount() && shared; ++g)
        shared = sameKeys(*m_plot->graph(0), *m_plot->graph(g));
    QStringList lines;
    if (shared) {
        QStringList header{csvField(m_plot->xAxis->label())};
        for (int g = 0; g < m_plot->graphCount(); ++g)
            header << csvField(m_plot->graph(g)->name() + QStringLiteral(" — ") + m_plot->yAxis->label());
        lines << header.join(QLatin1Char(','));
        for (int i = 0; i < m_plot->graph(0)->data()->size(); ++i) {
            QStringList row{csvNumber(m_plot->graph(0)->data()->at(i)->key)};
            for (int g = 0; g < m_plot->graphCount(); ++g)
                row << csvNumber(m_plot->graph(g)->data()->at(i)->value);
            lines << row.join(QLatin1Char(','));
        }
    } else {
        lines << QStringList{QStringLiteral("curve"), csvField(m_plot->xAxis->label()),
                             csvField(m_plot->yAxis->label())}
                     .join(QLatin1Char(','));
        for (int g = 0; g < m_plot->graphCount(); ++g)
            for (auto p = m_plot->graph(g)->data()->constBegin(); p != m_plot->graph(g)->data()->constEnd(); ++p)
                lines << QStringList{csvField(m_plot->graph(g)->name()), csvNumber(p->key), csvNumber(p->value)}.join(
                    QLatin1Char(','));
    }
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

QRect LinePlot::legendRect() const
{
    return m_plot->legend->outerRect().translated(m_plot->pos());
}

QSize LinePlot::legendNeeds() const
{
    return m_plot->legend->minimumOuterSizeHint();
}

namespace {

// "z [mm]" as its quantity "z" and unit "mm"; a label without a unit in brackets is all quantity.
std::pair<QString, QString> quantityAndUnit(const QString &label)
{
    static const QRegularExpression withUnit(QStringLiteral("^(.*?)\\s*\\[([^\\]]*)\\]\\s*$"));
    const QRegularExpressionMatch m = withUnit.match(label);
    return m.hasMatch() ? std::pair{m.captured(1), m.captured(2)} : std::pair{label, QString()};
}

QString withUnit(const QString &number, const QString &unit)
{
    return unit.isEmpty() ? number : number + QChar(0x2009) + unit; // a thin space between number and unit
}

} // namespace

QString LinePlot::readoutAt(double x) const
{
    const auto [xName, xUnit] = quantityAndUnit(m_plot->xAxis->label());
    const QString yUnit = quantityAndUnit(m_plot->yAxis->label()).second;
    QStringList lines;
    for (int g = 0; g < m_plot->graphCount(); ++g) {
        const QCPGraph *graph = m_plot->graph(g);
        if (graph->data()->isEmpty())
            continue;
        auto it = graph->data()->findBegin(x, false);
        if (it != graph->data()->constBegin() &&
            (it == graph->data()->constEnd() || std::abs((it - 1)->key - x) < std::abs(it->key - x)))
            --it;
        if (lines.isEmpty())
            lines << QStringLiteral("%1 = %2").arg(xName, withUnit(QString::number(it->key, 'g', 5), xUnit));
        lines << QStringLiteral("%1: %2").arg(graph->name(), std::isfinite(it->value)
                                                                 ? withUnit(QString::number(it->value, 'g', 4), yUnit)
                                                                 : QStringLiteral("—"));
    }
    return lines.join(QLatin1Char('\n'));
}

void LinePlot::showReadout(const QPoint &position)
{
    if (!m_plot->axisRect()->rect().contains(position)) {
        QToolTip::hideText();
        return;
    }
    QToolTip::showText(m_plot->mapToGlobal(position), readoutAt(m_plot->xAxis->pixelToCoord(position.x())), m_plot);
}

QString LinePlot::exportImage(const QString &path)
{
    return exportPlot(*m_plot, path);
}

void LinePlot::render(QPainter *painter, const QRectF &target, double textScale)
{
    renderPlot(*m_plot, *painter, target, textScale);
}

} // namespace tolturn
