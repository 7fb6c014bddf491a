// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/milling/milled_features.h"

#include "core/milling/ball_end_geometry.h"

#include <Eigen/Geometry>
#include <QCoreApplication>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

namespace tolturn {

namespace {

struct MilledFeatures {
    Q_DECLARE_TR_FUNCTIONS(MilledFeatures)
};

constexpr double kRadPerDeg = std::numbers::pi / 180.0;
// A path's axes and normals are directions: shorter than this they are no direction at all.
constexpr double kShortestDirection = 1e-9;

Eigen::Vector3d vec(const std::array<double, 3> &v)
{
    return {v[0], v[1], v[2]};
}

std::invalid_argument pathError(std::size_t point, const QString &what)
{
    return std::invalid_argument(MilledFeatures::tr("path point %1: %2").arg(point + 1).arg(what).toStdString());
}

} // namespace

std::optional<MilledFeatureInputs> milledFeatureInputs(const MilledFeature &feature, QStringList &missing)
{
    missing.clear();
    if (!feature.tool)
        missing << MilledFeatures::tr("the ball-end tool");
    else if (!feature.tool->holderStiffness_N_mm || !feature.tool->holderRotational_N_mm_rad)
        missing << MilledFeatures::tr("the holder's springs k and k_θ");
    if (!feature.conditions)
        missing << MilledFeatures::tr("the cutting conditions");
    if (!feature.coefficients)
        missing << MilledFeatures::tr("the cutting coefficients");
    if (!feature.tolerance)
        missing << MilledFeatures::tr("the tolerance");
    if (feature.kind == MilledFeatureKind::Patch && feature.path.size() < 2)
        missing << MilledFeatures::tr("the tool path (at least two CL points)");
    if (!missing.isEmpty())
        return std::nullopt;
    MilledFeatureInputs in;
    const BallEndTool &t = *feature.tool;
    in.mill = {t.diameter_mm, t.flutes, t.helix_deg * kRadPerDeg};
    in.carbideAssumed = !t.youngsModulus_N_mm2.has_value();
    in.structure = {t.overhang_mm, t.equivalentDiameter_mm, t.youngsModulus_N_mm2.value_or(kCarbideModulus_N_mm2),
                    *t.holderStiffness_N_mm, *t.holderRotational_N_mm_rad};
    in.coefficients = *feature.coefficients;
    const MillingConditions &c = *feature.conditions;
    in.cut = {c.cut,
              c.direction,
              c.axialDepth_mm,
              c.radialDepth_mm,
              c.feedPerTooth_mm,
              c.lead_deg * kRadPerDeg,
              c.tilt_deg * kRadPerDeg};
    in.spindle_rpm = c.spindle_rpm;
    // ISO 1101: a flatness, and a profile without datums, float; a profile with datums is located.
    const bool located =
        feature.tolerance->type == MilledToleranceType::Profile && !feature.tolerance->datums.isEmpty();
    in.tolerance = {feature.tolerance->zone_um / 1000.0, located ? SurfaceZone::Located : SurfaceZone::Floating};
    return in;
}

// T·(0, 0, 1) = (sin λ, −sin τ cos λ, cos τ cos λ) in F, C, N (001 eq. 6, the third column of T):
// λ = asin a_F, τ = atan2(−a_C, a_N).
LeadTilt leadTiltOfAxis(const std::array<double, 3> &toolAxis, const std::array<double, 3> &normal,
                        const std::array<double, 3> &feedDirection)
{
    const Eigen::Vector3d n = vec(normal).normalized();
    const Eigen::Vector3d f = (vec(feedDirection) - vec(feedDirection).dot(n) * n).normalized();
    const Eigen::Vector3d c = n.cross(f);
    const Eigen::Vector3d a = vec(toolAxis).normalized();
    return {std::asin(std::clamp(a.dot(f), -1.0, 1.0)), std::atan2(-a.dot(c), a.dot(n))};
}

std::vector<PathStation> pathStations(const std::vector<ClPoint> &path, double ballRadius_mm)
{
    if (path.size() < 2 || path.size() > kMostPathPoints)
        throw std::invalid_argument(MilledFeatures::tr("a tool path has 2 to %1 CL points, this one %2")
                                        .arg(kMostPathPoints)
                                        .arg(path.size())
                                        .toStdString());
    std::vector<Eigen::Vector3d> centres;
    centres.reserve(path.size());
    for (std::size_t i = 0; i < path.size(); ++i) {
        const Eigen::Vector3d axis = vec(path[i].toolAxis);
        if (!(axis.norm() >= kShortestDirection))
            throw pathError(i, MilledFeatures::tr("the tool axis is zero"));
        centres.emplace_back(vec(path[i].position_mm) + ballRadius_mm * axis.normalized());
    }
    std::vector<PathStation> stations;
    stations.reserve(path.size());
    double arcLength = 0.0;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const ClPoint &p = path[i];
        const Eigen::Vector3d normal = vec(p.surfaceNormal);
        if (!(normal.norm() >= kShortestDirection))
            throw pathError(i, MilledFeatures::tr("the surface normal is zero"));
        if (!(vec(p.toolAxis).dot(normal) > 0.0))
            throw pathError(i, MilledFeatures::tr("the tool axis points into the surface"));
        const std::size_t from = i + 1 < path.size() ? i : i - 1;
        const Eigen::Vector3d step = centres[from + 1] - centres[from];
        if (!(step.norm() >= kShortestDirection))
            throw pathError(from + 1, MilledFeatures::tr("the ball is where it was at the point before"));
        const Eigen::Vector3d along = step - step.dot(normal.normalized()) * normal.normalized();
        if (along.norm() < 1e-6 * step.norm())
            throw pathError(i, MilledFeatures::tr("the feed runs along the surface normal"));
        if (i > 0)
            arcLength += (centres[i] - centres[i - 1]).norm();
        stations.push_back({arcLength, leadTiltOfAxis(p.toolAxis, p.surfaceNormal, {step.x(), step.y(), step.z()})});
    }
    return stations;
}

std::vector<PathStation> featureStations(const MilledFeature &feature, const BallEndMill &mill, const BallEndCut &cut)
{
    if (feature.kind == MilledFeatureKind::Patch)
        return pathStations(feature.path, 0.5 * mill.diameter_mm);
    // A flat or a keyway is one straight cut at one lead and tilt: the error is the same at both ends.
    const LeadTilt angles{cut.lead_rad, cut.tilt_rad};
    return {{0.0, angles}, {std::abs(feature.zTo_mm - feature.zFrom_mm), angles}};
}

namespace {

struct StationResult {
    MilledPathPoint point;
    SurfaceErrorLine line;
};

// Every station's δ_N range and forces at the feature's feed into the evaluation, and the error
// lines of all stations one after the other: the form error of the whole path at a feed is
// formError_mm of that line (the spread, or the largest |δ_N|, over all of them). A tool axis met
// before is not computed again.
SurfaceErrorLine evaluateStations(const MilledFeatureInputs &in, const std::vector<PathStation> &stations,
                                  const BallEndResolution &resolution, MilledFeatureEvaluation &e)
{
    SurfaceErrorLine whole;
    std::map<std::pair<double, double>, StationResult> byAngles;
    for (const PathStation &s : stations) {
        const std::pair<double, double> key{s.angles.lead_rad, s.angles.tilt_rad};
        auto found = byAngles.find(key);
        if (found == byAngles.end()) {
            BallEndCut cut = in.cut;
            cut.lead_rad = s.angles.lead_rad;
            cut.tilt_rad = s.angles.tilt_rad;
            const BallEndDeflection d = ballEndDeflection(in.mill, in.structure, in.coefficients, cut, resolution);
            const BallEndForceSummary forces = summarise(d.forces);
            if (forces.peakResultant_N > e.forces.peakResultant_N) {
                e.forces = forces;
                e.spindlePower_W = spindlePower_W(forces.meanTorque_N_mm, in.spindle_rpm);
            }
            found = byAngles
                        .emplace(key, StationResult{{{}, d.leastSurfaceNormal_mm, d.greatestSurfaceNormal_mm},
                                                    surfaceErrorLine(d, cut)})
                        .first;
        }
        MilledPathPoint point = found->second.point;
        point.station = s;
        e.path.push_back(point);
        const SurfaceErrorLine &line = found->second.line;
        whole.base_mm.insert(whole.base_mm.end(), line.base_mm.begin(), line.base_mm.end());
        whole.perFeed_mm_mm.insert(whole.perFeed_mm_mm.end(), line.perFeed_mm_mm.begin(), line.perFeed_mm_mm.end());
    }
    return whole;
}

} // namespace

MilledFeatureEvaluation evaluateMilledFeature(const MilledFeature &feature, const BallEndResolution &resolution)
{
    MilledFeatureEvaluation e;
    e.featureId = feature.id;
    const std::optional<MilledFeatureInputs> in = milledFeatureInputs(feature, e.missing);
    if (!in)
        return e;
    e.carbideAssumed = in->carbideAssumed;
    e.tolerance = in->tolerance;
    try {
        const SurfaceErrorLine line = evaluateStations(*in, featureStations(feature, in->mill, in->cut), resolution, e);
        e.formError_mm = formError_mm(line, in->cut.feedPerTooth_mm, in->tolerance.zone);
        if (!std::isfinite(e.formError_mm))
            throw std::domain_error(MilledFeatures::tr("the predicted deflection is not finite: the tool's data "
                                                       "lie beyond what the model computes")
                                        .toStdString());
        e.margin_mm = in->tolerance.tolerance_mm - e.formError_mm;
        e.passes = e.margin_mm >= 0.0;
        e.holdingFeedPerTooth_mm = largestFeedPerTooth_mm(line, in->tolerance, in->cut.feedPerTooth_mm);
    } catch (const std::exception &refused) { // what the model refuses; nothing escapes a worker thread
        e.refusal = QString::fromStdString(refused.what());
        e.path.clear();
        e.forces = {};
    }
    return e;
}

std::vector<MilledFeatureEvaluation> evaluateMilledFeatures(const Project &project)
{
    std::vector<MilledFeatureEvaluation> evaluations;
    evaluations.reserve(project.milledFeatures.size());
    for (const MilledFeature &f : project.milledFeatures)
        evaluations.push_back(evaluateMilledFeature(f));
    return evaluations;
}

MilledFeaturePlan planMilledFeature(const MilledFeature &feature, const BallEndPlanSettings &settings)
{
    QStringList missing;
    const std::optional<MilledFeatureInputs> in = milledFeatureInputs(feature, missing);
    if (!in)
        throw std::invalid_argument(MilledFeatures::tr("milled feature %1 lacks %2")
                                        .arg(feature.id, missing.join(QStringLiteral(", ")))
                                        .toStdString());
    MilledFeaturePlan result;
    if (feature.kind != MilledFeatureKind::Patch) {
        result.leadTiltPlanned = true;
        result.plan = planBallEndCut(in->mill, in->structure, in->coefficients, in->cut, in->spindle_rpm, in->tolerance,
                                     settings);
        return result;
    }
    if (!(settings.highestFeedPerTooth_mm > 0.0))
        throw std::invalid_argument(MilledFeatures::tr("highest feed per tooth: %1 mm is not positive")
                                        .arg(settings.highestFeedPerTooth_mm)
                                        .toStdString());
    MilledFeatureEvaluation scratch;
    const SurfaceErrorLine line =
        evaluateStations(*in, featureStations(feature, in->mill, in->cut), settings.planResolution, scratch);
    BallEndPlan &plan = result.plan;
    plan.cut = in->cut;
    plan.cut.feedPerTooth_mm = largestFeedPerTooth_mm(line, in->tolerance, settings.highestFeedPerTooth_mm);
    plan.feasible = plan.cut.feedPerTooth_mm > 0.0;
    plan.formError_mm = formError_mm(line, plan.cut.feedPerTooth_mm, in->tolerance.zone);
    plan.feedRate_mm_min = plan.cut.feedPerTooth_mm * in->mill.flutes * in->spindle_rpm;
    return result;
}

} // namespace tolturn
