// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QColor>
#include <QString>
#include <QVector>
#include <QWidget>

class QCustomPlot;
class QPainter;

namespace tolturn {

// A plot of curves y(x) with axes that carry their units and a legend. TolTurn's own class: the
// plotting library behind it (QCustomPlot) is not visible to its users, so it can be replaced.
// A gap in a curve is a NaN in y.
class LinePlot : public QWidget {
    Q_OBJECT
public:
    explicit LinePlot(QWidget *parent = nullptr);
    ~LinePlot() override;

    void setTitle(const QString &title);
    void setAxisLabels(const QString &xLabel, const QString &yLabel);
    void clear();
    void addCurve(const QString &name, const QVector<double> &x, const QVector<double> &y, const QColor &color,
                  Qt::PenStyle style = Qt::SolidLine, double width = 1.5);
    // A band between two curves over the same x (a result over a range of machines), its area
    // filled translucent; each edge keeps its own name for the read-out and the CSV.
    void addBand(const QString &lowerName, const QString &upperName, const QVector<double> &x,
                 const QVector<double> &lower, const QVector<double> &upper, const QColor &color);
    // Values at separate positions (one per face, say): a stem from zero up to each, with a dot.
    void addStems(const QString &name, const QVector<double> &x, const QVector<double> &y, const QColor &color);
    // Values measured at separate positions (points of a measured part): a marker each, no line.
    void addPoints(const QString &name, const QVector<double> &x, const QVector<double> &y, const QColor &color);
    // Values computed at separate positions and joined for the eye: a line through a dot at each.
    void addMarkedCurve(const QString &name, const QVector<double> &x, const QVector<double> &y, const QColor &color);
    // Fits the axes to the data (y always includes zero) and redraws.
    void rescaleAndReplot();
    // Shows x from `lower` to `upper` (the whole part, say, where the data are at a few stations)
    // and redraws; call after rescaleAndReplot().
    void setXRange(double lower, double upper);

    [[nodiscard]] int curveCount() const;
    [[nodiscard]] QString curveName(int index) const;

    [[nodiscard]] QString title() const { return m_title; }

    // Where the legend is drawn, and the space it needs, in the widget's pixels (for tests: the
    // legend is never clipped).
    [[nodiscard]] QRect legendRect() const;
    [[nodiscard]] QSize legendNeeds() const;

    // The curves as CSV: one column per curve when they share their x values, else one row per
    // point (curve, x, y). The header carries the axis labels with their units; gaps are empty.
    [[nodiscard]] QString csvText() const;
    // The values of every curve at the point nearest to `x`, with the axes' units (the hover
    // read-out): "z = 35 mm", "total: 12.4 µm".
    [[nodiscard]] QString readoutAt(double x) const;
    // Writes the plot as PNG, SVG or PDF (by suffix), atomically; returns the error, if any.
    [[nodiscard]] QString exportImage(const QString &path);

    // Draws the plot as vectors into `target` on `painter` (reports, SVG/PDF export); see renderPlot().
    void render(QPainter *painter, const QRectF &target, double textScale = 1.0);

private:
    void showReadout(const QPoint &position);

    QCustomPlot *m_plot;
    QString m_title;
};

} // namespace tolturn
