// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/profile/profile_view.h"

#include "widgets/profile/profile_scene.h"

#include <QGraphicsPathItem>
#include <QGraphicsScene>
#include <QLineF>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace tolturn {

ProfileView::ProfileView(QWidget *parent) : QGraphicsView(parent), m_scene(new QGraphicsScene(this))
{
    setScene(m_scene);
    setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing);
    setBackgroundBrush(Qt::white);
    setDragMode(QGraphicsView::ScrollHandDrag);
    setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
    setViewportUpdateMode(QGraphicsView::BoundingRectViewportUpdate);
    setMinimumSize(320, 200);
}

void ProfileView::setProfile(const PartProfile &profile)
{
    buildProfileScene(*m_scene, profile);
    m_autoFit = true;
    fitPart();
    const QString previous = m_selected;
    m_selected.clear();
    if (!previous.isEmpty() && findFeature(profile, previous))
        selectFeature(previous); // keep the selection across edits of the same part
    else if (!previous.isEmpty())
        Q_EMIT featureSelected(QString());
}

void ProfileView::selectFeature(const QString &featureId)
{
    const QColor highlight(0xe6, 0x55, 0x0d);
    const QList<QGraphicsItem *> items = m_scene->items();
    for (QGraphicsItem *item : items) {
        auto *path = dynamic_cast<QGraphicsPathItem *>(item);
        if (path == nullptr || !item->data(kDefaultPenData).isValid())
            continue;
        QPen pen = item->data(kDefaultPenData).value<QPen>();
        if (!featureId.isEmpty() && item->data(kFeatureIdData).toString() == featureId) {
            pen.setColor(highlight);
            pen.setWidthF(pen.widthF() + 1.6);
        }
        path->setPen(pen);
    }
    if (m_selected == featureId)
        return;
    m_selected = featureId;
    Q_EMIT featureSelected(featureId);
}

QString ProfileView::featureAt(const QPoint &viewPoint, double pixels) const
{
    const QPointF p = mapToScene(viewPoint);
    const double tolerance = pixels / std::max(transform().m11(), 1e-12); // pixels to scene units
    QString best;
    double bestDistance = tolerance;
    const QList<QGraphicsItem *> items = m_scene->items();
    for (const QGraphicsItem *item : items) {
        const auto *path = dynamic_cast<const QGraphicsPathItem *>(item);
        const QString id = item->data(kFeatureIdData).toString();
        if (path == nullptr || id.isEmpty())
            continue;
        const QPainterPath &shape = path->path();
        for (int i = 1; i < shape.elementCount(); ++i) {
            const QPointF a = shape.elementAt(i - 1);
            const QPointF b = shape.elementAt(i);
            const QLineF ab(a, b);
            const double len2 = ab.dx() * ab.dx() + ab.dy() * ab.dy();
            const double t =
                len2 > 0.0 ? std::clamp(((p.x() - a.x()) * ab.dx() + (p.y() - a.y()) * ab.dy()) / len2, 0.0, 1.0) : 0.0;
            const double d = QLineF(p, a + t * (b - a)).length();
            if (d < bestDistance) {
                bestDistance = d;
                best = id;
            }
        }
    }
    return best;
}

void ProfileView::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton) {
        const QString id = featureAt(event->position().toPoint());
        if (!id.isEmpty()) {
            selectFeature(id);
            event->accept();
            return;
        }
    }
    QGraphicsView::mousePressEvent(event);
}

void ProfileView::clearProfile()
{
    m_scene->clear();
}

void ProfileView::fitPart()
{
    const QRectF bounds = m_scene->itemsBoundingRect();
    if (bounds.isEmpty())
        return;
    const double margin = 0.06 * std::max(bounds.width(), bounds.height());
    m_scene->setSceneRect(bounds.adjusted(-margin, -margin, margin, margin));
    fitInView(m_scene->sceneRect(), Qt::KeepAspectRatio);
}

void ProfileView::resizeEvent(QResizeEvent *event)
{
    QGraphicsView::resizeEvent(event);
    if (m_autoFit)
        fitPart();
}

void ProfileView::wheelEvent(QWheelEvent *event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0.0) {
        QGraphicsView::wheelEvent(event);
        return;
    }
    m_autoFit = false;
    const double factor = std::pow(1.2, steps);
    scale(factor, factor);
    event->accept();
}

void ProfileView::mouseDoubleClickEvent(QMouseEvent *event)
{
    m_autoFit = true;
    fitPart();
    QGraphicsView::mouseDoubleClickEvent(event);
}

} // namespace tolturn
