// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

class QAbstractItemModel;
class QAbstractItemView;

namespace tolturn {

// A table as CSV: the horizontal headers (with their units), then every row as shown.
[[nodiscard]] QString tableCsv(const QAbstractItemModel &model);

// Gives a table view "Copy Table as CSV" in its context menu and on Ctrl+C (the standard copy
// key), so every table can go to a spreadsheet.
void addCopyAsCsv(QAbstractItemView &view);

} // namespace tolturn
