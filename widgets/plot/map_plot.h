// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <QString>
#include <QWidget>

class QCustomPlot;
class QPainter;

namespace tolturn {

// A map over two variables: an image stretched over the axis ranges, text labels placed in data
// coordinates and point markers. TolTurn's own class over the plotting library, like LinePlot.
class MapPlot : public QWidget {
    Q_OBJECT
public:
    explicit MapPlot(QWidget *parent = nullptr);
    ~MapPlot() override;

    void setTitle(const QString &title);
    void setAxisLabels(const QString &xLabel, const QString &yLabel);
    // The image's column 0 is at xMin, its last column at xMax; row 0 at yMin (drawn at the bottom).
    void setImage(const QImage &image, double xMin, double xMax, double yMin, double yMax);
    void addLabel(double x, double y, const QString &text, const QColor &color = Qt::black);
    // The optimum is a star; the programmed point (the project's own conditions) a ring. Returns
    // false, drawing nothing, when the point lies outside the map.
    enum class Marker { Optimum, Programmed };
    bool addMarker(double x, double y, const QString &text, Marker kind = Marker::Optimum);
    void clear();
    void replot();

    [[nodiscard]] int labelCount() const { return m_labels; }

    [[nodiscard]] QStringList markers() const { return m_markers; } // the texts of the markers drawn

    [[nodiscard]] QString title() const { return m_title; }

    // Writes the plot as PNG, SVG or PDF (by suffix), atomically; returns the error, if any.
    [[nodiscard]] QString exportImage(const QString &path);

    // Draws the plot as vectors into `target` on `painter` (reports, SVG/PDF export); see renderPlot().
    void render(QPainter *painter, const QRectF &target, double textScale = 1.0);

private:
    QCustomPlot *m_plot;
    QString m_title;
    int m_labels = 0;
    QStringList m_markers;
};

} // namespace tolturn
