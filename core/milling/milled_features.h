// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The milled features of a project (core/project/milled_feature.h) through the ball-end model
// (issue 19; docs/milling.md "Milled features"): what the model needs of a feature, the lead and
// tilt of a patch's path point by point, the surface error along the path against the feature's
// tolerance, the plan of least time, and the checks of `check`.

#include "core/common/diagnostic.h"
#include "core/milling/ball_end_planning.h"
#include "core/project/project.h"

#include <QStringList>

#include <optional>
#include <vector>

namespace tolturn {

// A feature's inputs to the model, in its units.
struct MilledFeatureInputs {
    BallEndMill mill;
    BallEndToolStructure structure;
    bool carbideAssumed = false; // the tool's modulus was not given: kCarbideModulus_N_mm2
    MillingForceCoefficients coefficients;
    BallEndCut cut;
    double spindle_rpm = 0.0;
    MilledSurfaceTolerance tolerance;
};

// The inputs, or nullopt with what is missing (translated names: "the holder's springs k and k_θ").
[[nodiscard]] std::optional<MilledFeatureInputs> milledFeatureInputs(const MilledFeature &feature,
                                                                     QStringList &missing);

// The tool axis as lead and tilt from a surface normal, for a feed direction (001 eq. 6): the axis
// T·(0, 0, 1) in the frame F (feed, projected on the surface), C = N × F, N.
struct LeadTilt {
    double lead_rad = 0.0;
    double tilt_rad = 0.0;
};

[[nodiscard]] LeadTilt leadTiltOfAxis(const std::array<double, 3> &toolAxis, const std::array<double, 3> &normal,
                                      const std::array<double, 3> &feedDirection);

// One point of a path: where along it, and the tool axis there as lead and tilt.
struct PathStation {
    double arcLength_mm = 0.0;
    LeadTilt angles;
};

// The most CL points of a patch: each distinct tool axis is a force and deflection run of about a
// millisecond (docs/benchmarks.md), so a path of this many takes seconds.
inline constexpr std::size_t kMostPathPoints = 5000;

// The stations of a patch's path, for a ball of radius `ballRadius_mm`: the ball's centre (the tip
// plus R along the axis) moves with the contact point, so the feed direction at a point is the
// centre's step towards the next point (at the last, from the one before) and the arc length is the
// centre's. Throws std::invalid_argument, naming the point, for a path the model cannot take: fewer
// than two points or more than kMostPathPoints, a zero axis or normal, two centres at the same
// place, a feed along the normal, an axis not above the surface.
[[nodiscard]] std::vector<PathStation> pathStations(const std::vector<ClPoint> &path, double ballRadius_mm);

// The stations a feature is evaluated at: a patch's, or the straight cut of a flat or a keyway at
// the feature's lead and tilt from z_from to z_to.
[[nodiscard]] std::vector<PathStation> featureStations(const MilledFeature &feature, const BallEndMill &mill,
                                                       const BallEndCut &cut);

struct MilledPathPoint {
    PathStation station;
    double leastNormal_mm = 0.0; // the range of δ_N over a revolution at this point
    double greatestNormal_mm = 0.0;
};

struct MilledFeatureEvaluation {
    QString featureId;
    QStringList missing; // inputs not given: nothing was computed
    QString refusal;     // the model's refusal of the inputs, naming the value
    bool carbideAssumed = false;
    std::vector<MilledPathPoint> path;
    MilledSurfaceTolerance tolerance;
    double formError_mm = 0.0; // the spread along the path (floating), or twice the largest |δ_N| (located)
    bool passes = false;
    double margin_mm = 0.0; // t − form error; negative when it fails
    // The largest feed per tooth up to the planned one at which the whole path holds (0: none).
    double holdingFeedPerTooth_mm = 0.0;
    BallEndForceSummary forces; // at the point of the largest resultant
    double spindlePower_W = 0.0;

    [[nodiscard]] bool evaluated() const { return missing.isEmpty() && refusal.isEmpty(); }
};

// The surface error along the feature's path at its conditions, and its verdict. Never throws: what
// is missing or refused is in the result.
[[nodiscard]] MilledFeatureEvaluation evaluateMilledFeature(const MilledFeature &feature,
                                                            const BallEndResolution &resolution = {});

// Every milled feature of a project, in order.
[[nodiscard]] std::vector<MilledFeatureEvaluation> evaluateMilledFeatures(const Project &project);

struct MilledFeaturePlan {
    bool leadTiltPlanned = false; // a flat or keyway: lead, tilt and feed; a patch: the feed only
    BallEndPlan plan;             // for a patch: its cut's feed, form error and feed rate; no window
};

// The plan of least time for a feature: for a flat or a keyway, planBallEndCut; for a patch, whose
// tool axes its path gives, the largest feed per tooth up to settings.highestFeedPerTooth_mm at
// which the whole path holds. Throws std::invalid_argument with what is missing or refused.
[[nodiscard]] MilledFeaturePlan planMilledFeature(const MilledFeature &feature, const BallEndPlanSettings &settings);

// check's findings on the milled features: bad values are errors naming the field; a feature not
// yet complete is a warning naming what it lacks.
void checkMilledFeatures(const Project &project, Diagnostics &out);

} // namespace tolturn
