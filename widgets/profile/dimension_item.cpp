// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/profile/dimension_item.h"

#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QLineF>
#include <QPainter>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace tolturn {

DimensionItem::DimensionItem(QPointF from, QPointF to, double offset, const QString &text, double arrowLength,
                             double labelAt, QGraphicsItem *parent)
    : QGraphicsItem(parent)
    , m_from(from)
    , m_to(to)
    , m_offset(offset)
    , m_text(text)
    , m_arrowLength(arrowLength)
    , m_pen(QColor(0x1f, 0x4e, 0x9a), 0.0)
    , m_label(new QGraphicsSimpleTextItem(text, this))
{
    m_pen.setCosmetic(true);
    m_label->setBrush(m_pen.color());
    m_label->setFlag(QGraphicsItem::ItemIgnoresTransformations);
    // Text centred on its place above the dimension line, turned to read along it (from below
    // or from the right, ISO 129-1).
    const QPointF n = normal();
    m_label->setPos(m_from + (m_to - m_from) * labelAt + n * m_offset);
    const QLineF line(m_from, m_to);
    m_angle = -line.angle(); // QLineF::angle is counter-clockwise in y-up terms
    if (m_angle < -90.0 || m_angle > 90.0)
        m_angle += 180.0;
    shiftLabel(0.0, 0.0);
}

void DimensionItem::shiftLabel(double along, double lift)
{
    const QRectF box = m_label->boundingRect();
    QTransform t;
    t.rotate(m_angle);
    t.translate(-box.width() / 2.0 + along, -box.height() - 1.0 - lift);
    m_label->setTransform(t);
}

QRectF DimensionItem::labelRect(const QTransform &sceneToDevice) const
{
    // The label ignores the scene's scale: Qt's device transform maps its anchor and applies its
    // own offset and turn in pixels.
    return m_label->deviceTransform(sceneToDevice).mapRect(m_label->boundingRect());
}

bool DimensionItem::isAcross() const
{
    return std::abs(m_to.x() - m_from.x()) < std::abs(m_to.y() - m_from.y());
}

QSizeF DimensionItem::labelSize() const
{
    return m_label->boundingRect().size();
}

int declutterDimensionLabels(QGraphicsScene &scene, const QTransform &sceneToDevice)
{
    std::vector<DimensionItem *> dimensions;
    for (QGraphicsItem *item : scene.items())
        if (auto *d = dynamic_cast<DimensionItem *>(item))
            dimensions.push_back(d);
    // Diameters (drawn across the part) stay where they are and are obstacles; lengths are placed
    // longest first: an overall length keeps its place, the short spans of a chain give way.
    const auto across = [](const DimensionItem *d) { return d->isAcross(); };
    std::stable_partition(dimensions.begin(), dimensions.end(), across);
    const auto lengths = std::find_if_not(dimensions.begin(), dimensions.end(), across);
    std::stable_sort(lengths, dimensions.end(), [](const DimensionItem *a, const DimensionItem *b) {
        return a->boundingRect().width() > b->boundingRect().width();
    });
    std::vector<QRectF> placed;
    int overlapping = 0;
    for (DimensionItem *d : dimensions) {
        if (d->isAcross()) {
            placed.push_back(d->labelRect(sceneToDevice));
            continue;
        }
        const QSizeF size = d->labelSize();
        const double beside = 0.5 * size.width() + 10.0;
        const double step = size.height() + 2.0;
        const std::pair<double, double> candidates[] = {{0.0, 0.0},  {beside * 2.0, 0.0}, {-beside * 2.0, 0.0},
                                                        {0.0, step}, {0.0, -step - 2.0},  {0.0, 2.0 * step}};
        bool free = false;
        for (const auto &[along, lift] : candidates) {
            d->shiftLabel(along, lift);
            const QRectF r = d->labelRect(sceneToDevice).adjusted(-1.0, -1.0, 1.0, 1.0);
            free = std::none_of(placed.begin(), placed.end(), [&r](const QRectF &p) { return p.intersects(r); });
            if (free)
                break;
        }
        if (!free) {
            d->shiftLabel(0.0, 0.0);
            ++overlapping;
        }
        placed.push_back(d->labelRect(sceneToDevice));
    }
    return overlapping;
}

QPointF DimensionItem::normal() const
{
    const QLineF line(m_from, m_to);
    const double length = line.length();
    if (length <= 0.0)
        return {0.0, -1.0};
    return {line.dy() / length, -line.dx() / length};
}

QRectF DimensionItem::boundingRect() const
{
    const QPointF shift = normal() * m_offset;
    QRectF r = QRectF(m_from, m_to).normalized();
    r |= QRectF(m_from + shift, m_to + shift).normalized();
    return r.adjusted(-m_arrowLength, -m_arrowLength, m_arrowLength, m_arrowLength);
}

void DimensionItem::setPen(const QPen &pen)
{
    m_pen = pen;
    m_label->setBrush(pen.color());
    update();
}

void DimensionItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const QPointF n = normal();
    const QPointF shift = n * m_offset;
    const QPointF overshoot = n * (m_offset >= 0.0 ? 1.0 : -1.0) * 0.4 * m_arrowLength;
    const QPointF a = m_from + shift;
    const QPointF b = m_to + shift;
    painter->setPen(m_pen);
    if (std::abs(m_offset) > 0.0) {
        painter->drawLine(m_from, a + overshoot);
        painter->drawLine(m_to, b + overshoot);
    }
    painter->drawLine(a, b);

    // Filled arrowheads, 15 degrees half-angle, pointing outwards to the extension lines.
    const QLineF line(a, b);
    if (line.length() <= 0.0)
        return;
    const QPointF u = (b - a) / line.length();
    const QPointF side(-u.y(), u.x());
    const double halfWidth = m_arrowLength * std::tan(std::numbers::pi / 12.0);
    painter->setBrush(m_pen.color());
    painter->drawPolygon(
        QPolygonF{a, a + u * m_arrowLength + side * halfWidth, a + u * m_arrowLength - side * halfWidth});
    painter->drawPolygon(
        QPolygonF{b, b - u * m_arrowLength + side * halfWidth, b - u * m_arrowLength - side * halfWidth});
}

} // namespace tolturn
