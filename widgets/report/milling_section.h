// SPDX-License-Identifier: GPL-3.0-or-later
// The report's section on the milled features of a mill-turn part (issue 19; docs/milling.md): a
// table of every feature with its tool, conditions, tolerance, predicted form error and verdict,
// what each verdict rests on, and the surface error along each evaluated feature's path between
// the limits of its tolerance zone.
#pragma once

#include "core/common/progress.h"
#include "core/milling/milled_features.h"
#include "core/project/project.h"
#include "widgets/report/report_layout.h"

#include <QString>

#include <optional>
#include <vector>

namespace tolturn::report {

// Each milled feature of `project` evaluated (evaluateMilledFeature, up to seconds for a long
// path), in order; `progress` (0…1) is told after each. nullopt when it was stopped. Needs no
// widget: it can run off the window's thread.
[[nodiscard]] std::optional<std::vector<MilledFeatureEvaluation>> evaluateMilledFeatures(const Project &project,
                                                                                         const Progress &progress = {});

// The section under `heading`, when the project has milled features (nothing otherwise), with
// their `evaluations` (as evaluateMilledFeatures gives them).
void milledFeaturesSection(Layout &layout, const Project &project, const QString &heading,
                           const std::vector<MilledFeatureEvaluation> &evaluations);

} // namespace tolturn::report
