// SPDX-License-Identifier: GPL-3.0-or-later
// The report's set-up sheet: what a machinist needs at the machine (issue 13): the clamping drawn,
// the tool, every pass with its spindle speed, cutting speed, feed, depth, power and time, and the
// program's name and checksum; conditions outside the insert's ranges in words.
#pragma once

#include "core/common/diagnostic.h"
#include "core/planning/planning_report.h"
#include "core/project/project.h"
#include "widgets/report/report_layout.h"

#include <QPainter>
#include <QRectF>
#include <QStringList>

namespace tolturn::report {

// The part's silhouette with the chuck jaws over the clamped length, the centres or the tailstock.
void drawClamping(QPainter &painter, const QRectF &rect, const Project &project);

// The clamping drawing, the passes of the program and the program line.
void setupSheet(Layout &layout, const Project &project, const FinishingOutput &finishing);

// Findings in a machinist's words: "Warning (passes 1–8): cutting speed 200 m/min is outside …" rather
// than "passes[0].cutting_speed_m_min: …", equal findings of several passes given once; other fields
// in brackets the same way: "Warning (boring tool): the part has bores but …".
[[nodiscard]] QStringList findingsInWords(const Diagnostics &findings);

} // namespace tolturn::report
