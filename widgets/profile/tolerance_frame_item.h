// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/project.h"

#include <QGraphicsItem>
#include <QString>
#include <QStringList>

namespace tolturn {

// Draws the ISO 1101 symbol of a geometric characteristic into `cell` (a square): the symbols
// are drawn as lines, not taken from a font, since common fonts lack several (⌭, ⌰).
// ISO 1101:2017 Table 2 gives the symbols.
void drawToleranceSymbol(QPainter &painter, ToleranceType type, const QRectF &cell);

// A feature control frame (ISO 1101 clause 7): the symbol, the tolerance value (with Ø for a
// cylindrical zone) and the datum letters in a row of boxes, on a vertical leader `leaderPixels`
// long. Anchored where the leader leaves the drawing; drawn in pixels so it reads at any zoom.
class ToleranceFrameItem : public QGraphicsItem {
public:
    ToleranceFrameItem(ToleranceType type, QString value, QStringList datums, double leaderPixels);

    [[nodiscard]] QRectF boundingRect() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

    [[nodiscard]] QString text() const; // "⟂ 0.015 A", for tests and tooltips

private:
    [[nodiscard]] QRectF frameRect() const;

    ToleranceType m_type;
    QString m_value;
    QStringList m_datums;
    double m_leader;
};

// The arrowhead of a leader ending on a feature, pointing down onto it; drawn in pixels.
class LeaderArrowItem : public QGraphicsItem {
public:
    LeaderArrowItem();

    [[nodiscard]] QRectF boundingRect() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
};

// A datum feature indicator (ISO 5459 clause 6): a filled triangle on the feature joined to a
// box with the datum letter. Anchored at the feature's point; drawn in pixels.
class DatumItem : public QGraphicsItem {
public:
    explicit DatumItem(QString label);

    [[nodiscard]] QRectF boundingRect() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

    [[nodiscard]] QString label() const { return m_label; }

private:
    QString m_label;
};

} // namespace tolturn
