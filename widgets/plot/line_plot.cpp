// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/plot/line_plot.h"

#include "widgets/plot/plot_backend.h"

#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

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

void LinePlot::rescaleAndReplot()
{
    m_plot->rescaleAxes();
    QCPRange y = m_plot->yAxis->range();
    y.expand(0.0);
    const double pad = 0.08 * std::max(y.size(), 1e-12);
    m_plot->yAxis->setRange(y.lower - pad, y.upper + pad);
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

void LinePlot::render(QPainter *painter, const QRectF &target, double textScale)
{
    renderPlot(*m_plot, *painter, target, textScale);
}

} // namespace tolturn
