// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/deviation/deviation_model.h"
#include "core/project/project.h"
#include "core/tolerance/target_contour.h"

#include <QString>

#include <optional>
#include <vector>

namespace tolturn {

// The ladder of Valiño et al. (2008) §V and §VII, "compensate only when necessary" (MODEL §3).
enum class Verdict {
    PassesAsProgrammed,     // the predicted part is inside the tolerance as the path is programmed
    PassesAfterOffset,      // a constant tool offset puts it inside (a size whose form part fits)
    NeedsProfileCorrection, // the form error itself exceeds the tolerance: the path must follow the deflection
    NotPredicted,           // the characteristic does not depend on the cutting-force deflection (§V.G–I)
    CannotEvaluate,         // the feature is not cut in this set-up, or its limits cannot be formed
};

struct ToleranceEvaluation {
    QString toleranceId;
    ToleranceType type = ToleranceType::Diameter;
    QString featureId;
    Verdict verdict = Verdict::CannotEvaluate;
    std::optional<double> value_um;        // the predicted value of the deciding quantity
    std::optional<double> limit_um;        // what it is compared with
    std::optional<double> utilisation_pct; // value / limit
    QString condition;                     // the condition of Fig. 4 and its equation that decided
    QString reason;                        // why, for people; always set for NotPredicted and CannotEvaluate
    // Size tolerances (diameter, length): nominal and limit deviations, and the predicted extreme
    // deviations of the size from nominal, with the path programmed to the middle of the zone.
    std::optional<double> nominal_mm;
    std::optional<double> upper_um;
    std::optional<double> lower_um;
    std::optional<double> predictedMax_um;
    std::optional<double> predictedMin_um;
    std::optional<double> offset_um; // constant change of the size that centres it (PassesAfterOffset)
    // The deviation predicted for the feature is not finite (an overflow): CannotEvaluate, yet
    // the tolerance still binds the conditions, so the optimiser counts it as violated.
    bool deviationNotFinite = false;
    Diagnostics diagnostics;
};

enum class EvaluationDetail {
    WithText,   // conditions and reasons written out, for people
    ValuesOnly, // numbers and verdicts only, for the optimiser
};

// Evaluates every tolerance of `project` against the predicted deviation `result` (computeDeviation,
// or any curves with the same structure), with the acceptance conditions of Valiño et al. (2008),
// Fig. 4 and eq. 9–24.
// `targets`, when given, are programTargets(project) formed before: the optimiser evaluates one
// project thousands of times.
[[nodiscard]] std::vector<ToleranceEvaluation> evaluateTolerances(const Project &project, const DeviationResult &result,
                                                                  EvaluationDetail detail = EvaluationDetail::WithText,
                                                                  const ProgramTargets *targets = nullptr);

// Adds to `targets` the geometry of every profile tolerance's feature at the stations of `table`
// (the slope of the exact profile and the target's offset from it), which evaluateTolerances
// then takes instead of working it out per plan. A deviation whose stations are not those of
// the table is evaluated as without it.
void addProfileGeometry(const Project &project, const InfluenceTable &table, ProgramTargets &targets);

// Whether a profile tolerance's zone is located along the axis (ISO 1101:2017 clause 18; ISO 5459:2011,
// the invariance classes of datum features): a datum on a face (a plane), a cone, a chamfer or a round
// (which each fix a point on the axis) holds the zone where the exact profile is. A datum on a
// cylinder is only an axis: the zone may still slide along it, as without a datum.
[[nodiscard]] bool profileZoneIsLocated(const Project &project, const Tolerance &tolerance);

[[nodiscard]] QString verdictKeyword(Verdict verdict); // "passes", "passes_after_offset", ...
[[nodiscard]] QString verdictName(Verdict verdict);    // for people, translated

} // namespace tolturn
