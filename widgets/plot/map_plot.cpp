// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/plot/map_plot.h"

#include "widgets/plot/plot_backend.h"

#include <QVBoxLayout>
#include <qcustomplot.h>

namespace tolturn {

MapPlot::MapPlot(QWidget *parent) : QWidget(parent), m_plot(new QCustomPlot(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    m_plot->setMinimumHeight(220);
    m_plot->plotLayout()->insertRow(0);
    m_plot->plotLayout()->addElement(0, 0,
                                     new QCPTextElement(m_plot, QString(), QFont(font().family(), 10, QFont::Bold)));
    addPlotContextMenu(*m_plot, {});
}

MapPlot::~MapPlot() = default;

void MapPlot::setTitle(const QString &title)
{
    m_title = title;
    if (auto *element = qobject_cast<QCPTextElement *>(m_plot->plotLayout()->element(0, 0)))
        element->setText(title);
}

void MapPlot::setAxisLabels(const QString &xLabel, const QString &yLabel)
{
    m_plot->xAxis->setLabel(xLabel);
    m_plot->yAxis->setLabel(yLabel);
}

void MapPlot::clear()
{
    m_plot->clearItems();
    m_plot->clearGraphs();
    m_labels = 0;
    m_markers.clear();
}

void MapPlot::setImage(const QImage &image, double xMin, double xMax, double yMin, double yMax)
{
    // Cells are centred on their grid points: stretch the image half a cell beyond the first and last.
    const double dx = image.width() > 1 ? (xMax - xMin) / (image.width() - 1) : 1.0;
    const double dy = image.height() > 1 ? (yMax - yMin) / (image.height() - 1) : 1.0;
    auto *pixmap = new QCPItemPixmap(m_plot);
    pixmap->setPixmap(QPixmap::fromImage(image.mirrored(false, true)));
    pixmap->setScaled(true, Qt::IgnoreAspectRatio, Qt::FastTransformation);
    pixmap->topLeft->setCoords(xMin - 0.5 * dx, yMax + 0.5 * dy);
    pixmap->bottomRight->setCoords(xMax + 0.5 * dx, yMin - 0.5 * dy);
    pixmap->setLayer(QStringLiteral("background"));
    m_plot->xAxis->setRange(xMin - 0.5 * dx, xMax + 0.5 * dx);
    m_plot->yAxis->setRange(yMin - 0.5 * dy, yMax + 0.5 * dy);
}

void MapPlot::addLabel(double x, double y, const QString &text, const QColor &color)
{
    auto *label = new QCPItemText(m_plot);
    label->position->setCoords(x, y);
    label->setText(text);
    label->setColor(color);
    label->setBrush(QColor(255, 255, 255, 200));
    label->setPadding(QMargins(3, 1, 3, 1));
    ++m_labels;
}

bool MapPlot::addMarker(double x, double y, const QString &text, Marker kind)
{
    const QCPRange xr = m_plot->xAxis->range();
    const QCPRange yr = m_plot->yAxis->range();
    if (!xr.contains(x) || !yr.contains(y))
        return false;
    // The symbol is an item, not a graph, so that a point on the window's edge is drawn whole.
    auto *symbol = new QCPItemText(m_plot);
    symbol->position->setCoords(x, y);
    symbol->setPositionAlignment(Qt::AlignCenter);
    symbol->setClipToAxisRect(false);
    symbol->setText(kind == Marker::Optimum ? QStringLiteral("\u2605") : QStringLiteral("\u25ef"));
    symbol->setColor(kind == Marker::Optimum ? QColor(Qt::black) : QColor(0x80, 0x00, 0x26));
    symbol->setFont(QFont(font().family(), font().pointSize() + 5, QFont::Bold));
    auto *label = new QCPItemText(m_plot);
    label->setClipToAxisRect(false);
    label->position->setCoords(x, y);
    // Beside the point, on the side towards the middle of the map so that it is not clipped.
    label->setPositionAlignment((x > xr.center() ? Qt::AlignRight : Qt::AlignLeft) |
                                (y > yr.center() ? Qt::AlignTop : Qt::AlignBottom));
    label->setText(QStringLiteral("  ") + text + QStringLiteral("  "));
    label->setFont(QFont(font().family(), font().pointSize(), QFont::Bold));
    m_markers << text;
    return true;
}

void MapPlot::replot()
{
    m_plot->replot();
}

QString MapPlot::exportImage(const QString &path)
{
    return exportPlot(*m_plot, path);
}

void MapPlot::render(QPainter *painter, const QRectF &target, double textScale)
{
    renderPlot(*m_plot, *painter, target, textScale);
}

} // namespace tolturn
