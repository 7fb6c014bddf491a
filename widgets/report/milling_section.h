// SPDX-License-Identifier: GPL-3.0-or-later
// The report's section on the milled features of a mill-turn part (issue 19; docs/milling.md): a
// table of every feature with its tool, conditions, tolerance, predicted form error and verdict,
// what each verdict rests on, and the surface error along each evaluated feature's path between
// the limits of its tolerance zone.
#pragma once

#include "core/common/progress.h"
#include "core/project/project.h"
#include "widgets/report/report_layout.h"

#include <QString>

#include <functional>

namespace tolturn::report {

// The section under `heading`, when the project has milled features (nothing otherwise). Each
// feature is evaluated once (evaluateMilledFeature, which takes up to seconds for a long path);
// `progress` (0…1 of the section) is told after each, and a stop cancels: the function then
// returns false and lays out nothing.
[[nodiscard]] bool milledFeaturesSection(Layout &layout, const Project &project, const QString &heading,
                                         const Progress &progress = {});

} // namespace tolturn::report
