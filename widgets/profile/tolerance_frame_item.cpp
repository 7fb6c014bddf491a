// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/profile/tolerance_frame_item.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <cmath>
#include <utility>

namespace tolturn {

namespace {

constexpr double kCell = 18.0;         // frame height and symbol cell width, pixels
constexpr double kFrameOffset = -10.0; // the frame's left edge relative to the leader
const QColor kAnnotationColor(0x1f, 0x4e, 0x9a);

QFont frameFont()
{
    QFont f(QStringLiteral("DejaVu Sans"));
    f.setPixelSize(11);
    return f;
}

// A line ending in an open arrowhead at `to`.
void arrow(QPainter &p, QPointF from, QPointF to)
{
    p.drawLine(from, to);
    const QPointF d = (to - from) / std::hypot(to.x() - from.x(), to.y() - from.y());
    const QPointF n(-d.y(), d.x());
    p.drawLine(to, to - 4.0 * d + 2.0 * n);
    p.drawLine(to, to - 4.0 * d - 2.0 * n);
}

bool cylindricalZone(ToleranceType type)
{
    return type == ToleranceType::Coaxiality; // the zone is a cylinder: the value takes Ø
}

} // namespace

void drawToleranceSymbol(QPainter &p, ToleranceType type, const QRectF &cell)
{
    const QRectF r = cell.adjusted(3.5, 3.5, -3.5, -3.5);
    const double cx = r.center().x(), cy = r.center().y(), w = r.width(), h = r.height();
    switch (type) {
    case ToleranceType::Flatness: // ⏥ a parallelogram
        p.drawPolygon(QPolygonF{{r.left() + 0.3 * w, cy - 0.2 * h},
                                {r.right(), cy - 0.2 * h},
                                {r.right() - 0.3 * w, cy + 0.2 * h},
                                {r.left(), cy + 0.2 * h}});
        break;
    case ToleranceType::Cylindricity: // ⌭ a circle between two slanted tangents
        p.drawEllipse(QPointF(cx, cy), 0.3 * w, 0.3 * h);
        p.drawLine(QPointF(r.left() + 0.1 * w, r.bottom()), QPointF(r.left() + 0.45 * w, r.top()));
        p.drawLine(QPointF(r.left() + 0.55 * w, r.bottom()), QPointF(r.right() - 0.1 * w, r.top()));
        break;
    case ToleranceType::Profile: { // ⌓ a half circle closed by its diameter
        QPainterPath path;
        path.moveTo(r.left(), cy + 0.25 * h);
        path.arcTo(QRectF(r.left(), cy + 0.25 * h - 0.5 * w, w, w), 180.0, -180.0);
        path.closeSubpath();
        p.drawPath(path);
        break;
    }
    case ToleranceType::Parallelism: // ∥ two slanted parallel lines
        p.drawLine(QPointF(r.left() + 0.15 * w, r.bottom()), QPointF(r.left() + 0.5 * w, r.top()));
        p.drawLine(QPointF(r.left() + 0.5 * w, r.bottom()), QPointF(r.left() + 0.85 * w, r.top()));
        break;
    case ToleranceType::Perpendicularity: // ⟂ a vertical on a base line
        p.drawLine(QPointF(r.left(), r.bottom()), QPointF(r.right(), r.bottom()));
        p.drawLine(QPointF(cx, r.bottom()), QPointF(cx, r.top()));
        break;
    case ToleranceType::Coaxiality: // ◎ two concentric circles
        p.drawEllipse(QPointF(cx, cy), 0.5 * w, 0.5 * h);
        p.drawEllipse(QPointF(cx, cy), 0.22 * w, 0.22 * h);
        break;
    case ToleranceType::CircularRadialRunout: // ↗ one slanted arrow
    case ToleranceType::CircularAxialRunout:
        arrow(p, QPointF(r.left() + 0.2 * w, r.bottom()), QPointF(r.right() - 0.1 * w, r.top()));
        break;
    case ToleranceType::TotalRadialRunout: // ⌰ two slanted arrows on a base line
    case ToleranceType::TotalAxialRunout:
        p.drawLine(QPointF(r.left(), r.bottom()), QPointF(r.left() + 0.55 * w, r.bottom()));
        arrow(p, QPointF(r.left(), r.bottom()), QPointF(r.left() + 0.45 * w, r.top()));
        arrow(p, QPointF(r.left() + 0.55 * w, r.bottom()), QPointF(r.right(), r.top()));
        break;
    case ToleranceType::Length:
    case ToleranceType::Diameter:
        break; // sizes are written on their dimension, not in a frame
    }
}

ToleranceFrameItem::ToleranceFrameItem(ToleranceType type, QString value, QStringList datums, double leaderPixels)
    : m_type(type)
    , m_value(std::move(value))
    , m_datums(std::move(datums))
    , m_leader(leaderPixels)
{
    setFlag(ItemIgnoresTransformations);
    setToolTip(text());
}

QString ToleranceFrameItem::text() const
{
    QStringList parts{m_value};
    parts << m_datums;
    return parts.join(QLatin1Char(' '));
}

QRectF ToleranceFrameItem::frameRect() const
{
    const QFontMetricsF metrics(frameFont());
    const QString value = (cylindricalZone(m_type) ? QStringLiteral("Ø") : QString()) + m_value;
    const double width = kCell + metrics.horizontalAdvance(value) + 8.0 + kCell * static_cast<double>(m_datums.size());
    return {kFrameOffset, -m_leader - kCell, width, kCell};
}

QRectF ToleranceFrameItem::boundingRect() const
{
    return frameRect().united(QRectF(-3, -m_leader, 6, m_leader)).adjusted(-1, -1, 1, 1);
}

void ToleranceFrameItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setPen(QPen(kAnnotationColor, 1.0));
    painter->setBrush(Qt::NoBrush);
    painter->drawLine(QPointF(0, -m_leader), QPointF(0, 0));
    const QRectF frame = frameRect();
    painter->fillRect(frame, Qt::white);
    painter->drawRect(frame);
    QRectF cell(frame.left(), frame.top(), kCell, kCell);
    drawToleranceSymbol(*painter, m_type, cell);
    painter->setFont(frameFont());
    const QString value = (cylindricalZone(m_type) ? QStringLiteral("Ø") : QString()) + m_value;
    const double valueWidth = QFontMetricsF(frameFont()).horizontalAdvance(value) + 8.0;
    painter->drawLine(cell.topRight(), cell.bottomRight());
    cell = QRectF(cell.right(), frame.top(), valueWidth, kCell);
    painter->drawText(cell, Qt::AlignCenter, value);
    for (const QString &datum : m_datums) {
        painter->drawLine(cell.topRight(), cell.bottomRight());
        cell = QRectF(cell.right(), frame.top(), kCell, kCell);
        painter->drawText(cell, Qt::AlignCenter, datum);
    }
}

LeaderArrowItem::LeaderArrowItem()
{
    setFlag(ItemIgnoresTransformations);
}

QRectF LeaderArrowItem::boundingRect() const
{
    return {-4.0, -8.0, 8.0, 9.0};
}

void LeaderArrowItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setPen(QPen(kAnnotationColor, 1.0));
    arrow(*painter, QPointF(0, -7), QPointF(0, 0));
}

DatumItem::DatumItem(QString label) : m_label(std::move(label))
{
    setFlag(ItemIgnoresTransformations);
    setToolTip(QObject::tr("Datum %1").arg(m_label));
}

QRectF DatumItem::boundingRect() const
{
    return {-kCell / 2.0 - 6.0, -2.0 * kCell - 12.0, kCell + 12.0, 2.0 * kCell + 14.0};
}

void DatumItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    // Filled triangle with its base on the feature, a line up, the letter in a square box.
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setPen(QPen(kAnnotationColor, 1.0));
    painter->setBrush(kAnnotationColor);
    painter->drawPolygon(QPolygonF{{-5.0, 0.0}, {5.0, 0.0}, {0.0, -7.0}});
    painter->drawLine(QPointF(0, -7), QPointF(0, -kCell - 4.0));
    const QRectF box(-kCell / 2.0, -2.0 * kCell - 4.0, kCell, kCell);
    painter->setBrush(Qt::white);
    painter->drawRect(box);
    painter->setFont(frameFont());
    painter->drawText(box, Qt::AlignCenter, m_label);
}

} // namespace tolturn
