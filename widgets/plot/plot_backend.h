// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/library_info.h"

#include <QString>

#include <functional>

class QCustomPlot;
class QPainter;
class QRectF;

namespace tolturn {

// The plotting library behind TolTurn's plot classes (QCustomPlot today). Only the files of
// widgets/plot include its headers, so it can be replaced without touching the rest.
[[nodiscard]] LibraryInfo plotBackendInfo();

// Draws `plot` as vectors into `target` on `painter` (reports, PDF/SVG export). The plot is laid
// out on a canvas `textScale` times larger than `target` and scaled down, so its screen fonts
// come out `textScale` times smaller relative to the page.
void renderPlot(QCustomPlot &plot, QPainter &painter, const QRectF &target, double textScale = 1.0);

// Writes the plot as it is on screen to `path`, atomically, in the format its suffix names: PNG
// (at twice the screen resolution), SVG or PDF (vectors). Returns the error, empty on success.
[[nodiscard]] QString exportPlot(QCustomPlot &plot, const QString &path);

// File-dialog filter for exportPlot().
[[nodiscard]] QString plotExportFilter();

// The right-click menu of a plot: "Copy Data as CSV" (when `csv` is given) and "Export Image…".
void addPlotContextMenu(QCustomPlot &plot, const std::function<QString()> &csv);

} // namespace tolturn
