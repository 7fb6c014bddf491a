// SPDX-License-Identifier: GPL-3.0-or-later
// The JSON of the results tolturn-cli prints (docs/cli.md), next to the project file's own
// (project_json.h): the deviation of `deflect`, the verdicts of `evaluate`, the plan of `optimize`,
// the ISO 286 limits of `iso286`. Lengths in mm, deviations in µm, as the keys say.
#pragma once

#include "core/deviation/deviation_model.h"
#include "core/planning/optimiser.h"
#include "core/planning/planning_problem.h"
#include "core/project/project.h"
#include "core/tolerance/evaluation.h"
#include "core/tolerance/iso286.h"
#include "core/tolerance/range_verdicts.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QString>

#include <vector>

namespace tolturn {

inline constexpr double kUmPerMm = 1000.0;

// `deflect --json`: the inputs used (pass, forces, force model, notes), the limits reached, and
// every station of every feature with its contributions; the face conicities; the boring bar.
[[nodiscard]] QJsonObject deviationJson(const QString &file, const Project &project, const DeviationResult &r);

// One verdict of `evaluate --json`; the numbers only where the verdict has them.
[[nodiscard]] QJsonObject evaluationJson(const ToleranceEvaluation &e);
// The same over the machine's stiffness range: the range verdict, the stiff end, and the chuck and
// tailstock stiffness the tolerance needs, in N/µm.
[[nodiscard]] QJsonObject rangeEvaluationJson(const ToleranceRangeEvaluation &e);

// `optimize --json`.
[[nodiscard]] QJsonObject passJson(const PassConditions &p);
[[nodiscard]] QJsonArray constraintsJson(const std::vector<ConstraintValue> &list);
[[nodiscard]] QJsonObject planJson(const PlanResult &r, const PlanningProblem &problem);
// The roughing pass of a plan, with its depth: the radial stock left after the finishing depth,
// shared equally by the roughing passes.
[[nodiscard]] PassConditions roughingPassOf(const PlanResult &r, const PlanningProblem &problem);

// `iso286 --json`: one tolerance class's limits (ISO 286-1).
[[nodiscard]] QJsonObject classLimitsJson(const iso286::ClassLimits &l);

} // namespace tolturn
