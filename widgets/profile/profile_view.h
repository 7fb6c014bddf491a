// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/project.h"

#include <QGraphicsView>

#include <optional>

namespace tolturn {

// The half-section drawing of the part. Fits the part to the window until the user zooms
// (mouse wheel, anchored under the cursor) or pans (drag); a double click fits it again.
class ProfileView : public QGraphicsView {
    Q_OBJECT
public:
    explicit ProfileView(QWidget *parent = nullptr);

    // Draws the part, with its tolerances and datums annotated when given.
    void setProfile(const PartProfile &profile, const std::vector<Tolerance> &tolerances = {},
                    const std::vector<Datum> &datums = {});
    // No part drawn; `placeholder` is said instead (by default emptyStateText()).
    void clearProfile(const QString &placeholder = QString());
    // How the part is held, drawn with it (jaws, centres, tailstock); unset: not drawn.
    void setClamping(const std::optional<Clamping> &clamping);
    void fitPart();

    // The selected feature (segment id), or empty. Selecting draws it highlighted in both halves.
    [[nodiscard]] QString selectedFeature() const { return m_selected; }

    void selectFeature(const QString &featureId);
    // The grid a dragged corner snaps to in millimetres (0.5 mm; Shift: 0.01 mm), and in inches
    // when the settings show inches (0.02 in; Shift: 0.0005 in).
    static constexpr double kSnapGrid_mm = 0.5;
    static constexpr double kFineSnapGrid_mm = 0.01;
    static constexpr double kSnapGrid_in = 0.02;
    static constexpr double kFineSnapGrid_in = 0.0005;

    // The feature drawn nearest to a point of the view, within `pixels`; empty if none.
    [[nodiscard]] QString featureAt(const QPoint &viewPoint, double pixels = 8.0) const;

    // The text shown while no part is open.
    [[nodiscard]] static QString emptyStateText();

Q_SIGNALS:
    void featureSelected(const QString &featureId);
    // A corner of the selected feature was dragged to `to` (snapped); one edit per drag.
    // atSegmentEnd: the handle is the end of the selected feature (at the solid between two
    // bores, vertex k is two points).
    void vertexDragged(tolturn::ContourSide side, int vertex, tolturn::ProfilePoint to, bool atSegmentEnd);

protected:
    void resizeEvent(QResizeEvent *event) override;
    void showEvent(QShowEvent *event) override;
    // With no part open: what to do to get one (the empty state of the main window).
    void drawForeground(QPainter *painter, const QRectF &rect) override;
    void wheelEvent(QWheelEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;

private:
    void showVertexHandles();
    void spaceDimensionRows();
    [[nodiscard]] QGraphicsItem *handleAt(const QPoint &viewPoint) const;
    [[nodiscard]] ProfilePoint snappedPoint(const QPoint &viewPoint, Qt::KeyboardModifiers modifiers) const;

    void redraw();
    void redrawKeepingSelection();
    [[nodiscard]] double snapGrid_mm(bool fine) const;

    QGraphicsScene *m_scene;
    PartProfile m_profile;
    std::vector<Tolerance> m_tolerances;
    std::vector<Datum> m_datums;
    QGraphicsItem *m_dragged = nullptr; // the vertex handle being dragged
    ProfilePoint m_dragTo;
    bool m_autoFit = true;
    bool m_rowsToSpace = false; // drawn while hidden: the rows are spaced when the view is shown
    std::optional<Clamping> m_clamping;
    double m_rowPitch_mm = 0.0; // between rows of length dimensions, for their labels at this zoom
    QString m_selected;
    QString m_placeholder;
};

} // namespace tolturn
