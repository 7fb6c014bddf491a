// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/deviation/deviation_model.h"
#include "core/tolerance/evaluation.h"

namespace tolturn {

enum class CompensationAction { None, ConstantOffset, ProfileCorrection };

// What the finishing path does for one feature, decided by the worst verdict of its tolerances
// (Valiño et al. 2008 §VII, "compensate only when necessary"; MODEL §3 and §4).
struct FeatureCompensation {
    QString featureId;
    ContourSide side = ContourSide::Outer;
    CompensationAction action = CompensationAction::None;
    QStringList tolerances;                  // ids of the tolerances on the feature
    double offset_um = 0.0;                  // ConstantOffset: change of the programmed diameter
    double residualBefore_um = 0.0;          // largest distance of the predicted radius from its aim, as programmed
    double residualAfter_um = 0.0;           // the same after the compensation
    std::vector<ProfilePoint> correctedPath; // ProfileCorrection: programmed (z, r) at each station
    QString note;
};

struct CompensationPlan {
    std::vector<FeatureCompensation> features;
    [[nodiscard]] const FeatureCompensation *find(const QString &featureId) const;
};

// The programmed radius is moved against the predicted deviation (Li & Du 2002 §3.4: "the CNC codes
// are modified to compensate the error ... with a resolution of 1 µm"): a constant offset when it
// suffices, else every station's radius r - e(z), the diameter rounded to 1 µm. Faces are not
// corrected (that would need a correction in Z), which the note says.
[[nodiscard]] CompensationPlan planCompensation(const Project &project, const DeviationResult &deviation,
                                                const std::vector<ToleranceEvaluation> &verdicts);

// The features whose correction is larger than the finishing depth of cut, with why, one line each:
// the part would spring out of the cut (deviation_model.cpp says so), the model linear in the forces
// of that depth does not hold, and such a correction is not a program to run (it may even cross the
// axis). Empty when every correction is within the cut.
[[nodiscard]] QStringList correctionsBeyondTheCut(const CompensationPlan &plan, double depthOfCut_mm);

[[nodiscard]] QString compensationKeyword(CompensationAction action); // "none", "offset", "profile"

} // namespace tolturn
