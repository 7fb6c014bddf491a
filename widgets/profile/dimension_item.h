// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QGraphicsItem>
#include <QPen>
#include <QPointF>
#include <QString>

class QGraphicsSimpleTextItem;

class QGraphicsScene;

namespace tolturn {

// A linear dimension as drawn on an engineering drawing (ISO 129-1): extension lines from the
// two measured points, a dimension line with arrowheads at `offset` from them, and the value
// written above its middle. Geometry is in scene units; the text keeps its screen size.
class DimensionItem : public QGraphicsItem {
public:
    // `offset` moves the dimension line along the left normal of from -> to (scene units);
    // `labelAt` places the text along the line, 0 at `from`, 1 at `to`.
    DimensionItem(QPointF from, QPointF to, double offset, const QString &text, double arrowLength,
                  double labelAt = 0.5, QGraphicsItem *parent = nullptr);

    [[nodiscard]] QRectF boundingRect() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

    [[nodiscard]] QString text() const { return m_text; }

    void setPen(const QPen &pen);

    // Moves the label (which keeps its size on screen) `along` pixels along the dimension line and
    // `lift` pixels further off it; (0, 0) is its place centred above the line.
    void shiftLabel(double along, double lift);
    // The label's bounding box in device coordinates under `sceneToDevice`.
    [[nodiscard]] QRectF labelRect(const QTransform &sceneToDevice) const;
    [[nodiscard]] QSizeF labelSize() const;
    // A dimension drawn across the part (a diameter), rather than along it.
    [[nodiscard]] bool isAcross() const;

private:
    [[nodiscard]] QPointF normal() const;

    QPointF m_from;
    QPointF m_to;
    double m_offset;
    double m_angle = 0.0; // of the label, degrees
    QString m_text;
    double m_arrowLength;
    QPen m_pen;
    QGraphicsSimpleTextItem *m_label;
};

// Lays the labels of every dimension in `scene` out so that none overlaps another, as drawn under
// `sceneToDevice` (a view's viewport transform, or the scale of a report drawing): a label that
// collides moves off its line, then beside its arrows, then further off (ISO 129-1 allows a value
// outside short dimensions). Returns the number of labels that still overlap.
int declutterDimensionLabels(QGraphicsScene &scene, const QTransform &sceneToDevice);

} // namespace tolturn
