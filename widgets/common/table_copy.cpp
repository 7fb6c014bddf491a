// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/common/table_copy.h"

#include "core/common/csv.h"

#include <QAbstractItemModel>
#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QClipboard>

namespace tolturn {

QString tableCsv(const QAbstractItemModel &model)
{
    QStringList header;
    for (int c = 0; c < model.columnCount(); ++c)
        header << model.headerData(c, Qt::Horizontal, Qt::DisplayRole).toString();
    QStringList lines{csvLine(header)};
    for (int r = 0; r < model.rowCount(); ++r) {
        QStringList row;
        for (int c = 0; c < model.columnCount(); ++c)
            row << model.index(r, c).data(Qt::DisplayRole).toString();
        lines << csvLine(row);
    }
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

void addCopyAsCsv(QAbstractItemView &view)
{
    auto *copy = new QAction(QApplication::translate("TableCopy", "Copy Table as CSV"), &view);
    copy->setShortcut(QKeySequence::Copy);
    copy->setShortcutContext(Qt::WidgetShortcut);
    QObject::connect(copy, &QAction::triggered, &view, [&view] {
        if (view.model() != nullptr)
            QApplication::clipboard()->setText(tableCsv(*view.model()));
    });
    view.addAction(copy);
    view.setContextMenuPolicy(Qt::ActionsContextMenu);
}

} // namespace tolturn
