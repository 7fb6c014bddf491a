// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStyledItemDelegate>

namespace tolturn {

// Draws the utilisation of a tolerance (ToleranceVerdictModel::UtilisationRole, percent) as a bar
// behind its text: green up to 80 %, amber up to 100 %, red beyond; the bar is full at 100 %.
class UtilisationDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    using QStyledItemDelegate::QStyledItemDelegate;
    void paint(QPainter *painter, const QStyleOptionViewItem &option, const QModelIndex &index) const override;
};

} // namespace tolturn
