// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QGraphicsItem>
#include <QPen>
#include <QPointF>
#include <QString>

class QGraphicsSimpleTextItem;

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

private:
    [[nodiscard]] QPointF normal() const;

    QPointF m_from;
    QPointF m_to;
    double m_offset;
    QString m_text;
    double m_arrowLength;
    QPen m_pen;
    QGraphicsSimpleTextItem *m_label;
};

} // namespace tolturn
