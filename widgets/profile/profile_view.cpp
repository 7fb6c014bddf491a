// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/profile/profile_view.h"

#include "widgets/common/display_units.h"
#include "widgets/profile/dimension_item.h"
#include "widgets/profile/profile_scene.h"

#include <QFontMetricsF>
#include <QGraphicsPathItem>
#include <QGraphicsRectItem>
#include <QGraphicsScene>
#include <QLineF>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
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
    connect(&DisplaySettings::instance(), &DisplaySettings::unitsChanged, this, [this] {
        redraw();
        if (!m_selected.isEmpty() && findFeature(m_profile, m_selected))
            selectFeature(m_selected); // highlight and corner handles again, in the new scene
    });
}

void ProfileView::setProfile(const PartProfile &profile, const std::vector<Tolerance> &tolerances,
                             const std::vector<Datum> &datums)
{
    if (profile.name != m_profile.name || m_profile.outer.empty())
        m_autoFit = true; // another part: show it whole; edits of this one keep the user's zoom
    m_profile = profile;
    m_tolerances = tolerances;
    m_datums = datums;
    redraw();
    if (m_autoFit)
        fitPart();
    const QString previous = m_selected;
    m_selected.clear();
    if (!previous.isEmpty() && findFeature(profile, previous))
        selectFeature(previous); // keep the selection across edits of the same part
    else if (!previous.isEmpty())
        Q_EMIT featureSelected(QString());
}

void ProfileView::redrawKeepingSelection()
{
    const QString selected = m_selected;
    redraw();
    m_selected.clear();
    if (!selected.isEmpty())
        selectFeature(selected);
}

// Builds the drawing anew (a new profile, or other display units), keeping the zoom; the
// caller selects again.
void ProfileView::redraw()
{
    buildProfileScene(*m_scene, m_profile, m_tolerances, m_datums, DisplaySettings::instance().units(), m_rowPitch_mm);
    if (m_clamping)
        addClamping(*m_scene, m_profile, *m_clamping);
    m_dragged = nullptr;
}

double ProfileView::snapGrid_mm(bool fine) const
{
    if (DisplaySettings::instance().units().lengthUnit() == LengthUnit::Inch)
        return (fine ? kFineSnapGrid_in : kSnapGrid_in) * kMillimetresPerInch;
    return fine ? kFineSnapGrid_mm : kSnapGrid_mm;
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
    const bool changed = m_selected != featureId;
    m_selected = featureId;
    showVertexHandles();
    if (changed)
        Q_EMIT featureSelected(featureId);
}

void ProfileView::showVertexHandles()
{
    const QList<QGraphicsItem *> items = m_scene->items();
    for (QGraphicsItem *item : items)
        if (item->data(kItemKindData).toString() == profile_item::kVertexHandle)
            delete item;
    const std::optional<FeatureRef> ref = findFeature(m_profile, m_selected);
    if (!ref)
        return;
    const std::pair<int, ProfilePoint> ends[] = {{ref->index, ref->segment->from}, {ref->index + 1, ref->segment->to}};
    for (const auto &[vertex, point] : ends) {
        auto *handle = m_scene->addRect(QRectF(-4, -4, 8, 8), QPen(QColor(0xe6, 0x55, 0x0d), 0), QBrush(Qt::white));
        handle->setFlag(QGraphicsItem::ItemIgnoresTransformations); // 8 pixels at any zoom
        handle->setPos(point.z_mm, -point.r_mm);
        handle->setZValue(10);
        handle->setCursor(Qt::SizeAllCursor);
        const DisplayUnits units = DisplaySettings::instance().units();
        handle->setToolTip(
            tr("Drag to move this corner (snaps to %1 %3; Shift: %2 %3)")
                .arg(units.lengthText(snapGrid_mm(false)), units.lengthText(snapGrid_mm(true)), units.lengthSymbol()));
        handle->setData(kItemKindData, profile_item::kVertexHandle);
        handle->setData(kVertexData, vertex);
        handle->setData(kSideData, static_cast<int>(ref->side));
        handle->setData(kSegmentEndData, vertex != ref->index);
    }
}

QGraphicsItem *ProfileView::handleAt(const QPoint &viewPoint) const
{
    const QList<QGraphicsItem *> items = m_scene->items();
    for (QGraphicsItem *item : items) {
        if (item->data(kItemKindData).toString() != profile_item::kVertexHandle)
            continue;
        if ((mapFromScene(item->pos()) - viewPoint).manhattanLength() <= 8)
            return item;
    }
    return nullptr;
}

ProfilePoint ProfileView::snappedPoint(const QPoint &viewPoint, Qt::KeyboardModifiers modifiers) const
{
    const double grid = snapGrid_mm((modifiers & Qt::ShiftModifier) != 0);
    const QPointF p = mapToScene(viewPoint);
    const auto snap = [grid](double v) { return std::round(v / grid) * grid; };
    return {snap(p.x()), std::max(0.0, snap(-p.y()))};
}

void ProfileView::mouseMoveEvent(QMouseEvent *event)
{
    if (m_dragged == nullptr) {
        QGraphicsView::mouseMoveEvent(event);
        return;
    }
    m_dragTo = snappedPoint(event->position().toPoint(), event->modifiers());
    m_dragged->setPos(m_dragTo.z_mm, -m_dragTo.r_mm);
    const DisplayUnits units = DisplaySettings::instance().units();
    QToolTip::showText(
        event->globalPosition().toPoint(),
        tr("z %1 %3, Ø %2 %3")
            .arg(units.lengthText(m_dragTo.z_mm), units.lengthText(2.0 * m_dragTo.r_mm), units.lengthSymbol()),
        this);
    event->accept();
}

void ProfileView::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_dragged == nullptr || event->button() != Qt::LeftButton) {
        QGraphicsView::mouseReleaseEvent(event);
        return;
    }
    const auto side = static_cast<ContourSide>(m_dragged->data(kSideData).toInt());
    const int vertex = m_dragged->data(kVertexData).toInt();
    const bool atSegmentEnd = m_dragged->data(kSegmentEndData).toBool();
    m_dragged = nullptr;
    QToolTip::hideText();
    event->accept();
    Q_EMIT vertexDragged(side, vertex, m_dragTo, atSegmentEnd); // the document redraws the part, or refuses
    showVertexHandles();                                        // a refused drag puts the handle back
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
        if (QGraphicsItem *handle = handleAt(event->position().toPoint())) {
            m_dragged = handle;
            m_dragTo = {handle->pos().x(), -handle->pos().y()};
            event->accept();
            return;
        }
        const QString id = featureAt(event->position().toPoint());
        if (!id.isEmpty()) {
            selectFeature(id);
            event->accept();
            return;
        }
    }
    QGraphicsView::mousePressEvent(event);
}

QString ProfileView::emptyStateText()
{
    return tr("No part is open.\n\n"
              "Open an example part: File > Open Example\n"
              "Import a turned part from STEP or IGES: File > Import STEP/IGES… (Ctrl+I)\n"
              "Draw a new part: File > New (Ctrl+N), then edit its features\n"
              "Open a project: File > Open… (Ctrl+O)");
}

void ProfileView::drawForeground(QPainter *painter, const QRectF &rect)
{
    QGraphicsView::drawForeground(painter, rect);
    if (!m_profile.outer.empty())
        return;
    painter->save();
    painter->resetTransform();
    painter->setPen(palette().color(QPalette::PlaceholderText));
    QFont font = painter->font();
    font.setPointSizeF(font.pointSizeF() * 1.1);
    painter->setFont(font);
    painter->drawText(viewport()->rect().adjusted(24, 24, -24, -24), Qt::AlignCenter | Qt::TextWordWrap,
                      m_placeholder.isEmpty() ? emptyStateText() : m_placeholder);
    painter->restore();
}

void ProfileView::setClamping(const std::optional<Clamping> &clamping)
{
    if (clamping == m_clamping)
        return;
    m_clamping = clamping;
    redrawKeepingSelection();
}

void ProfileView::clearProfile(const QString &placeholder)
{
    m_placeholder = placeholder;
    m_dragged = nullptr;
    m_profile = PartProfile{};
    m_tolerances.clear();
    m_datums.clear();
    m_scene->clear();
    viewport()->update();
}

void ProfileView::fitPart()
{
    const QRectF bounds = m_scene->itemsBoundingRect();
    if (bounds.isEmpty())
        return;
    const double margin = 0.06 * std::max(bounds.width(), bounds.height());
    m_scene->setSceneRect(bounds.adjusted(-margin, -margin, margin, margin));
    fitInView(m_scene->sceneRect(), Qt::KeepAspectRatio);
    spaceDimensionRows();
}

// Rows of length dimensions far enough apart for their labels at this zoom: the drawing is built
// again with the pitch the labels need until the rows are at least that far apart at the zoom the
// pitch gives (at most four times), then labels that still collide are moved
// (declutterDimensionLabels).
void ProfileView::spaceDimensionRows()
{
    m_rowsToSpace = !isVisible();
    if (m_rowsToSpace)
        return; // a hidden view has no zoom to space the rows for: showEvent does it
    const double labelHeight = QFontMetricsF(font()).height();
    for (int pass = 0; pass < 4; ++pass) {
        const double needed = dimensionRowPitch_mm(labelHeight, transform().m11());
        if (m_rowPitch_mm >= needed && m_rowPitch_mm <= 1.25 * needed)
            break;
        // A little above what this zoom needs: wider rows make the fit smaller, which needs wider rows.
        m_rowPitch_mm = 1.1 * needed;
        redrawKeepingSelection();
        if (!m_autoFit)
            continue; // the user's zoom stays
        const QRectF bounds = m_scene->itemsBoundingRect();
        const double margin = 0.06 * std::max(bounds.width(), bounds.height());
        m_scene->setSceneRect(bounds.adjusted(-margin, -margin, margin, margin));
        fitInView(m_scene->sceneRect(), Qt::KeepAspectRatio);
    }
    declutterDimensionLabels(*m_scene, viewportTransform());
}

void ProfileView::resizeEvent(QResizeEvent *event)
{
    QGraphicsView::resizeEvent(event);
    if (m_autoFit)
        fitPart();
}

void ProfileView::showEvent(QShowEvent *event)
{
    QGraphicsView::showEvent(event);
    if (!m_rowsToSpace)
        return;
    if (m_autoFit)
        fitPart();
    else
        spaceDimensionRows();
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
    spaceDimensionRows();
    event->accept();
}

void ProfileView::mouseDoubleClickEvent(QMouseEvent *event)
{
    m_autoFit = true;
    fitPart();
    QGraphicsView::mouseDoubleClickEvent(event);
}

} // namespace tolturn
