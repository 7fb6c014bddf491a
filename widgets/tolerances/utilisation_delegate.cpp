// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/tolerances/utilisation_delegate.h"

#include "widgets/tolerances/tolerance_verdict_model.h"

#include <QPainter>

#include <algorithm>

namespace tolturn {

void UtilisationDelegate::paint(QPainter *painter, const QStyleOptionViewItem &option, const QModelIndex &index) const
{
    const QVariant value = index.data(ToleranceVerdictModel::UtilisationRole);
    if (value.isValid()) {
        const double percent = value.toDouble();
        const QColor color = percent <= 80.0    ? QColor(0x74, 0xc4, 0x76)
                             : percent <= 100.0 ? QColor(0xfd, 0xae, 0x6b)
                                                : QColor(0xde, 0x2d, 0x26);
        QRectF bar = QRectF(option.rect).adjusted(2, 3, -2, -3);
        bar.setWidth(bar.width() * std::clamp(percent / 100.0, 0.0, 1.0));
        painter->save();
        painter->setPen(Qt::NoPen);
        painter->setBrush(color);
        painter->drawRect(bar);
        painter->restore();
    }
    QStyledItemDelegate::paint(painter, option, index);
}

} // namespace tolturn
