// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QTableWidgetItem>

namespace tolturn {

// A cell of a result table: read, not edited; numbers right-aligned where the caller asks.
[[nodiscard]] inline QTableWidgetItem *readOnlyCell(const QString &text, Qt::Alignment alignment = {})
{
    auto *item = new QTableWidgetItem(text);
    item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    if (alignment != Qt::Alignment{})
        item->setTextAlignment(alignment);
    return item;
}

} // namespace tolturn
