// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/profile/profile_view.h"

#include "widgets/profile/profile_scene.h"

#include <QGraphicsScene>
#include <QWheelEvent>

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
