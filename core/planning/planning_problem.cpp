// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/planning_problem.h"

#include "core/cutting/cutting_quantities.h"
#include "core/part/profile_geometry.h"
#include "core/planning/gcode.h"
#include "core/planning/post_processor.h"
#include "core/tolerance/evaluation.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tolturn {

namespace {

struct Planning {
    Q_DECLARE_TR_FUNCTIONS(Planning)
};

constexpr double kPi = std::numbers::pi;
constexpr int kStations = 11; // tool positions per feature for tolerances and times

// The passes of a plan are one finishing pass and k equal roughing passes, each within the insert's
// range of depth of cut [a_min, a_max] (planBox): k + 1 passes take a radial stock from
// (k + 1) a_min to (k + 1) a_max. A stock outside every such span, or needing more passes than
// the optimiser plans, has no plan; said here, with the numbers, instead of an empty plan.
std::optional<Diagnostic> uncuttableStock(double stock_mm, const ValueRange &depth)
{
    const QString field = QStringLiteral("part.stock_diameter_mm");
    constexpr double kSlack = 1e-9;
    if (stock_mm < depth.min - kSlack)
        return makeError(field, Planning::tr("the stock leaves %1 mm to remove on the radius of the outer profile, "
                                             "less than the insert's smallest depth of cut (%2 mm, "
                                             "planning.ranges.depth_of_cut_mm): no pass can take it")
                                    .arg(formatNumber(stock_mm), formatNumber(depth.min)));
    // As roughingPassRange() counts them, before its cap: the finishing pass at the largest depth.
    const double fewest = std::ceil((stock_mm - depth.max) / depth.max - 1e-9);
    if (fewest > kMaxRoughingPasses)
        return makeError(
            field,
            Planning::tr("the stock leaves %1 mm to remove on the radius: at least %2 roughing passes at the insert's "
                         "largest depth of cut (%3 mm), and the optimiser plans up to %4; turn from a smaller bar")
                .arg(formatNumber(stock_mm))
                .arg(formatNumber(fewest))
                .arg(formatNumber(depth.max))
                .arg(kMaxRoughingPasses));
    // The fewest passes that can take it (fewest + 1 with the finishing pass) must not be too many
    // at the smallest depth.
    const int passes = static_cast<int>(std::max(fewest, 0.0)) + 1;
    if (stock_mm < passes * depth.min - kSlack)
        return makeError(field, Planning::tr("the stock leaves %1 mm to remove on the radius, between what %2 and %3 "
                                             "passes at depths of cut from %4 to %5 mm "
                                             "(planning.ranges.depth_of_cut_mm) can take: at most %6 mm, at least "
                                             "%7 mm")
                                    .arg(formatNumber(stock_mm))
                                    .arg(passes - 1)
                                    .arg(passes)
                                    .arg(formatNumber(depth.min), formatNumber(depth.max),
                                         formatNumber((passes - 1) * depth.max), formatNumber(passes * depth.min)));
    return std::nullopt;
}

} // namespace

bool constraintHasLimit(const Project &project, const DataLibrary &data, const QString &constraint)
{
    const PlanningSettings &s = project.planning;
    const MachineData *machine = data.machine(project.machineId);
    const auto machineHas = [machine](const char *key) {
        return machine != nullptr && machine->limits.count(QLatin1String(key)) > 0;
    };
    if (constraint == QLatin1String("roughness"))
        return s.maxRa_um || s.maxRz_um;
    if (constraint == QLatin1String("power"))
        return s.maxPower_kW || machineHas("power_kW");
    if (constraint == QLatin1String("torque"))
        return s.maxTorque_Nm.has_value();
    if (constraint == QLatin1String("force"))
        return s.maxForce_N.has_value();
    if (constraint == QLatin1String("spindle_speed"))
        return s.maxSpindleSpeed_rpm || machineHas("max_speed_rpm");
    if (constraint == QLatin1String("tool_life"))
        return s.minToolLife_min && s.taylorC_m_min && s.taylorN;
    if (constraint == QLatin1String("bar_overhang")) {
        const HolderData *bar = project.boringTool ? data.holder(project.boringTool->holderCode) : nullptr;
        return bar != nullptr && data.boringBarMaterial(*bar) != nullptr;
    }
    return true; // tolerances and the roughing depth always have theirs
}

QString ConstraintValue::label() const
{
    if (name == QLatin1String("tolerances"))
        return Planning::tr("tolerance %1").arg(subject);
    // As the Planning dock's switches name it: "roughing depth", not the keyword "roughing_depth".
    return QStringLiteral("%1 (%2)").arg(QString(name).replace(QLatin1Char('_'), QLatin1Char(' ')), subject);
}

QString ConstraintValue::violatedBy() const
{
    if (!std::isfinite(value))
        return Planning::tr("with a predicted value that is not finite");
    return Planning::tr("by %1 %").arg(QString::number(100.0 * violation(), 'g', 4));
}

bool CandidateEvaluation::feasible(double slack) const
{
    return std::all_of(constraints.begin(), constraints.end(),
                       [slack](const ConstraintValue &c) { return c.violation() <= slack; });
}

const ConstraintValue *CandidateEvaluation::mostViolated() const
{
    const ConstraintValue *worst = nullptr;
    for (const ConstraintValue &c : constraints) {
        if (worst == nullptr || c.violation() > worst->violation())
            worst = &c;
    }
    return worst;
}

double CandidateEvaluation::totalViolation() const
{
    double sum = 0.0;
    for (const ConstraintValue &c : constraints)
        sum += std::max(0.0, c.violation());
    return sum;
}

PlanningProblem::BuildResult PlanningProblem::build(const Project &project, const DataLibrary &data, StiffnessEnd end,
                                                    std::shared_ptr<const LoadedModel> learned)
{
    BuildResult result;
    Diagnostics &out = result.diagnostics;
    const PlanningSettings &s = project.planning;
    if (!s.cuttingSpeed_m_min || !s.feed_mm_rev || !s.depthOfCut_mm) {
        out.push_back(
            makeError(QStringLiteral("planning.ranges"),
                      Planning::tr("the optimiser needs the insert's ranges of cutting speed, feed and depth of cut "
                                   "(from its maker's catalogue), with their source")));
        return result;
    }
    // Without the rate a part would cost its inserts alone, or nothing: a plan at no cost would be
    // chosen at random (docs/planning.md §1).
    if (s.objective == PlanningObjective::Cost && !(s.machineRate_per_min > 0.0)) {
        out.push_back(makeError(QStringLiteral("planning.machine_rate_per_min"),
                                Planning::tr("least cost needs the machine and operator rate per minute, but it is %1")
                                    .arg(QString::number(s.machineRate_per_min))));
        return result;
    }
    DeviationOptions options;
    options.stationsPerFeature = kStations;
    options.stiffnessEnd = learned ? StiffnessEnd::Compliant : end;
    Project withPass = project;
    if (withPass.passes.empty())
        withPass.passes.push_back(
            {PassKind::Finishing, s.cuttingSpeed_m_min->min, s.feed_mm_rev->min, s.depthOfCut_mm->min});
    InputsResult inputs = resolveTurningInputs(withPass, data, options);
    out.insert(out.end(), inputs.diagnostics.begin(), inputs.diagnostics.end());
    auto forces = projectForceModel(withPass, data, out);
    std::optional<ForceFunction> boringForces;
    if (project.boringTool && inputs.inputs) {
        Project boringView = withPass;
        boringView.tool = *project.boringTool;
        boringForces = projectForceModel(boringView, data, out);
    }
    if (!inputs.inputs || !forces || (project.boringTool && !boringForces))
        return result;

    auto problem = std::shared_ptr<PlanningProblem>(new PlanningProblem);
    PlanningProblem &p = *problem;
    p.m_project = withPass;
    p.m_inputs = *inputs.inputs;
    p.m_forceModel = *forces;
    if (boringForces)
        p.m_boringForceModel = *boringForces;
    p.m_speed = *s.cuttingSpeed_m_min;
    p.m_feed = *s.feed_mm_rev;
    p.m_depth = *s.depthOfCut_mm;
    p.m_notes = p.m_inputs.notes;
    if (learned)
        p.m_notes << Planning::tr("The tolerance constraints include what was learned of the machine from its measured "
                                  "parts (%1); parts not learned from were predicted to %2 µm RMS.")
                         .arg(learned->provenance(), QString::number(1000.0 * learned->uncertainty_mm(), 'f', 1));
    p.m_learned = std::move(learned);
    // The finishing pass's deflection with the thinnest stock it may leave on the uncut side
    // (the smallest depth): the least stiff section, so the tolerance constraints err on the safe side.
    p.m_table = buildInfluenceTable(project.part, p.m_inputs, kStations, p.m_depth.min);
    p.m_targets = programTargets(withPass);
    addProfileGeometry(withPass, p.m_table, p.m_targets);
    // The roughness limit holds for every surface: the bores' with the boring bar's insert.
    p.m_roughnessNoseRadius_mm = p.m_inputs.noseRadius_mm;
    p.m_roughnessInserts.push_back({project.tool.insertCode, p.m_inputs.noseRadius_mm});
    if (p.m_inputs.boring && std::any_of(p.m_table.features.begin(), p.m_table.features.end(),
                                         [](const FeatureInfluence &f) { return f.side == ContourSide::Inner; })) {
        p.m_roughnessNoseRadius_mm = std::min(p.m_roughnessNoseRadius_mm, p.m_inputs.boring->noseRadius_mm);
        p.m_roughnessInserts.push_back({Planning::tr("%1, the boring bar's insert").arg(project.boringTool->insertCode),
                                        p.m_inputs.boring->noseRadius_mm});
    }
    p.m_maxPower_kW = s.maxPower_kW ? s.maxPower_kW : p.m_inputs.maxPower_kW;
    p.m_maxTorque_Nm = s.maxTorque_Nm;
    p.m_maxSpeed_rpm = s.maxSpindleSpeed_rpm ? s.maxSpindleSpeed_rpm : p.m_inputs.maxSpindleSpeed_rpm;
    p.m_stockDiameter_mm = project.part.stockDiameter_mm;
    const double stockRadius = 0.5 * project.part.stockDiameter_mm;
    for (const FeatureInfluence &f : p.m_table.features) {
        for (std::size_t i = 0; i < f.z_mm.size(); ++i) {
            p.m_largestCutDiameter_mm = std::max(p.m_largestCutDiameter_mm, 2.0 * f.nominalRadius_mm[i]);
            if (f.side == ContourSide::Inner)
                p.m_largestBoreDiameter_mm = std::max(p.m_largestBoreDiameter_mm, 2.0 * f.nominalRadius_mm[i]);
            if (f.side == ContourSide::Outer) {
                p.m_outerProfile.emplace_back(f.z_mm[i], f.nominalRadius_mm[i]);
                p.m_radialStock_mm = std::max(p.m_radialStock_mm, stockRadius - f.nominalRadius_mm[i]);
            }
        }
    }
    p.timeFinishingPasses(finishingPasses(withPass, p.m_inputs));
    if (std::optional<Diagnostic> uncuttable = uncuttableStock(p.m_radialStock_mm, p.m_depth)) {
        out.push_back(std::move(*uncuttable));
        return result;
    }
    if (!s.taylorC_m_min || !s.taylorN)
        p.m_notes << Planning::tr(
            "No Taylor constants in the project's planning data: tool life and tool cost are not in the "
            "objective, and there is no tool-life constraint.");
    if (!p.m_maxTorque_Nm)
        p.m_notes << Planning::tr("No spindle torque limit given (planning.max_torque_Nm): torque is not constrained.");
    if (!p.m_maxPower_kW)
        p.m_notes << Planning::tr("No spindle power limit known (machine data or planning.max_power_kW): power is not "
                                  "constrained.");
    if (!p.m_maxSpeed_rpm)
        p.m_notes << Planning::tr("No spindle speed limit known (machine data or planning.max_spindle_speed_rpm): "
                                  "spindle speed is not constrained.");
    p.noteUnconstrainedTolerances();
    result.problem = problem;
    return result;
}

QString leftOutText(const std::vector<ToleranceLeftOut> &tolerances)
{
    QStringList texts;
    for (const ToleranceLeftOut &t : tolerances)
        texts << t.text();
    return texts.join(QStringLiteral("; "));
}

// The tolerances that cannot be among the constraints, each with why (a feature in the jaws or
// beyond the supports, limits that cannot be formed), once at the smallest conditions of the
// ranges: a plan that leaves one out says so where the plan is read.
void PlanningProblem::noteUnconstrainedTolerances()
{
    if (!isEnabled(QStringLiteral("tolerances")))
        return;
    const PassConditions smallest{m_speed.min, m_feed.min, m_depth.min};
    for (const ToleranceEvaluation &e :
         evaluateTolerances(m_project, finishingDeviation(smallest), EvaluationDetail::WithText, &m_targets)) {
        if (e.verdict != Verdict::CannotEvaluate || e.deviationNotFinite)
            continue; // held to, or one the cutting forces do not decide (NotPredicted: the verdicts say why)
        m_unconstrained.push_back({e.toleranceId, e.reason});
    }
    if (!m_unconstrained.empty())
        m_notes << Planning::tr("Not among the plan's constraints: %1.").arg(leftOutText(m_unconstrained));
}

std::vector<CuttingPass> PlanningProblem::passesOf(const PlanCandidate &c) const
{
    std::vector<CuttingPass> passes;
    passes.reserve(static_cast<std::size_t>(std::max(c.roughingPasses, 0)) + 1);
    const double roughDepth =
        c.roughingPasses > 0 ? (m_radialStock_mm - c.finishing.depthOfCut_mm) / c.roughingPasses : 0.0;
    for (int i = 0; i < c.roughingPasses; ++i)
        passes.push_back({PassKind::Roughing, c.roughing.cuttingSpeed_m_min, c.roughing.feed_mm_rev, roughDepth});
    passes.push_back(
        {PassKind::Finishing, c.finishing.cuttingSpeed_m_min, c.finishing.feed_mm_rev, c.finishing.depthOfCut_mm});
    return passes;
}

bool PlanningProblem::isEnabled(const QString &constraint) const
{
    return !m_project.planning.disabledConstraints.contains(constraint);
}

CuttingForces PlanningProblem::forces(double feed_mm_rev, double depth_mm) const
{
    return m_forceModel(feed_mm_rev, depth_mm);
}

std::optional<double> PlanningProblem::toolLife_min(double cuttingSpeed_m_min) const
{
    const PlanningSettings &s = m_project.planning;
    if (!s.taylorC_m_min || !s.taylorN)
        return std::nullopt;
    return std::pow(*s.taylorC_m_min / cuttingSpeed_m_min, 1.0 / *s.taylorN); // Taylor (1907): v T^n = C
}

void PlanningProblem::timeFinishingPasses(const std::vector<PassPath> &passes)
{
    m_speedLimitingDiameter_mm = std::numeric_limits<double>::infinity();
    std::vector<FeedStep> finishingSteps;
    for (const PassPath &pass : passes) {
        const std::vector<FeedStep> steps = feedSteps(pass);
        finishingSteps.insert(finishingSteps.end(), steps.begin(), steps.end());
        if (const double d = speedLimitingDiameter_mm(pass); d > 0.0)
            m_speedLimitingDiameter_mm = std::min(m_speedLimitingDiameter_mm, d);
    }
    m_finishingTimes = FeedTimeTable(finishingSteps);
    if (finishingSteps.empty())
        m_notes << Planning::tr("The program has no finishing moves (see the G-code's warnings): the finishing time is "
                                "taken as zero.");
    const bool bores = std::any_of(m_table.features.begin(), m_table.features.end(),
                                   [](const FeatureInfluence &f) { return f.side == ContourSide::Inner; });
    if (bores && passes.size() < 2)
        m_notes << Planning::tr("The bores are not in the finishing time: the program does not bore them (see the "
                                "G-code's notes).");
    if (passes.size() >= 2)
        keepTheBoredProfile(passes[1]);
}

// The bore the boring bar bores (the inner contour, as deep as its finishing pass cuts), out of
// the pilot hole, for the roughing volume; without a pilot hole the program takes the bore as
// roughed before it, so there is nothing to keep.
void PlanningProblem::keepTheBoredProfile(const PassPath &boring)
{
    const std::optional<double> pilot =
        m_project.boringTool ? m_project.boringTool->pilotHoleDiameter_mm : std::optional<double>();
    if (!pilot)
        return;
    double deepest = std::numeric_limits<double>::infinity();
    for (const ToolMove &m : boring.moves)
        if (m.kind != MoveKind::Rapid && !m.featureId.isEmpty())
            deepest = std::min(deepest, m.to.z_mm);
    m_pilotRadius_mm = 0.5 * *pilot;
    const auto keep = [&](double z, double r) {
        m_boredProfile.emplace_back(z, r);
        m_boreRadialStock_mm = std::max(m_boreRadialStock_mm, r - m_pilotRadius_mm);
    };
    for (const Segment &segment : m_project.part.inner.segments) {
        const std::vector<ProfilePoint> points = samplePoints(segment);
        for (std::size_t i = 0; i < points.size(); ++i) {
            const ProfilePoint &q = points[i];
            if (i > 0 && points[i - 1].z_mm < deepest && q.z_mm > deepest) { // where the bar stops
                const double t = (deepest - points[i - 1].z_mm) / (q.z_mm - points[i - 1].z_mm);
                keep(deepest, points[i - 1].r_mm + t * (q.r_mm - points[i - 1].r_mm));
            }
            if (q.z_mm >= deepest)
                keep(q.z_mm, q.r_mm);
        }
    }
}

// Time of the finishing passes as the program cuts them (pass_time.h): every feed move, faces,
// cones and arcs at their length, at constant cutting speed (G96) under the spindle limit the
// program sets, the speed v_f needs on the speed-limiting diameter or the machine's if lower
// (post_processor.h; a roughing pass at a higher speed could raise the program's limit, which
// only shortens a face's run to the axis, so this time is not less than the program's).
double PlanningProblem::finishingTime_min(const PassConditions &pass) const
{
    double limit_rpm = std::numeric_limits<double>::infinity();
    if (std::isfinite(m_speedLimitingDiameter_mm))
        limit_rpm = std::ceil(spindleSpeed_rpm(pass.cuttingSpeed_m_min, m_speedLimitingDiameter_mm));
    if (m_maxSpeed_rpm)
        limit_rpm = std::min(limit_rpm, *m_maxSpeed_rpm);
    return m_finishingTimes.time_min(pass.cuttingSpeed_m_min, pass.feed_mm_rev, limit_rpm);
}

namespace {

// The integral of area(r) dz along stations (z, r) in z order, trapezoidal; a step back in z (the
// next feature) adds nothing.
double volumeAlong(const std::vector<std::pair<double, double>> &stations, const std::function<double(double)> &area)
{
    double volume = 0.0;
    for (std::size_t i = 1; i < stations.size(); ++i) {
        const double dz = stations[i].first - stations[i - 1].first;
        if (dz > 0.0)
            volume += 0.5 * dz * (area(stations[i].second) + area(stations[i - 1].second));
    }
    return volume;
}

} // namespace

// Material the roughing passes remove: the bar down to the finishing allowance over every outer
// turned feature, V = integral of pi ((D_s/2)^2 - (r + a_f)^2) dz, and the bores out from the pilot
// hole r_p to their finishing allowance, V = integral of pi ((r - a_f)^2 - r_p^2) dz where
// r - a_f > r_p (the boring bar roughs at the roughing passes' depths, boring_toolpath.h).
double PlanningProblem::roughingVolume_mm3(double finishingDepth_mm) const
{
    const double rs = 0.5 * m_stockDiameter_mm;
    const double outer = volumeAlong(m_outerProfile, [&](double r) {
        const double rf = std::min(r + finishingDepth_mm, rs);
        return kPi * (rs * rs - rf * rf);
    });
    const double bores = volumeAlong(m_boredProfile, [&](double r) {
        const double rf = std::max(r - finishingDepth_mm, m_pilotRadius_mm);
        return kPi * (rf * rf - m_pilotRadius_mm * m_pilotRadius_mm);
    });
    return outer + bores;
}

std::pair<int, int> PlanningProblem::roughingPassRange(double finishingDepth_mm) const
{
    const double left = m_radialStock_mm - finishingDepth_mm;
    if (left <= 1e-9)
        return {0, 0};
    // In double first: a stock of metres over a depth of microns would overflow an int.
    const double fewestPasses = std::ceil(left / m_depth.max - 1e-9);
    const double mostPasses = std::floor(left / m_depth.min + 1e-9);
    const int fewest = static_cast<int>(std::clamp(fewestPasses, 1.0, kMaxRoughingPasses + 1.0));
    const int most = std::max(fewest, static_cast<int>(std::min(mostPasses, double(kMaxRoughingPasses))));
    return {fewest, most};
}

void PlanningProblem::addPassLimits(const QString &subject, const PassConditions &pass, const CuttingForces &f,
                                    double largestDiameter_mm, std::vector<ConstraintValue> &out,
                                    ToolLife toolLife) const
{
    if (isEnabled(QStringLiteral("power")) && m_maxPower_kW)
        out.push_back({QStringLiteral("power"), subject, cuttingPower_kW(f.tangential_N, pass.cuttingSpeed_m_min),
                       *m_maxPower_kW, QStringLiteral("kW")});
    if (isEnabled(QStringLiteral("torque")) && m_maxTorque_Nm)
        out.push_back({QStringLiteral("torque"), subject, spindleTorque_Nm(f.tangential_N, largestDiameter_mm),
                       *m_maxTorque_Nm, QStringLiteral("N·m")});
    if (isEnabled(QStringLiteral("force")) && m_project.planning.maxForce_N)
        out.push_back(
            {QStringLiteral("force"), subject, f.tangential_N, *m_project.planning.maxForce_N, QStringLiteral("N")});
    // The speed the cutting speed asks for on the largest diameter cut must be reachable.
    if (isEnabled(QStringLiteral("spindle_speed")) && m_maxSpeed_rpm)
        out.push_back({QStringLiteral("spindle_speed"), subject,
                       spindleSpeed_rpm(pass.cuttingSpeed_m_min, largestDiameter_mm), *m_maxSpeed_rpm,
                       QStringLiteral("rpm")});
    if (toolLife == ToolLife::SameAsTurning)
        return;
    const auto life = toolLife_min(pass.cuttingSpeed_m_min);
    if (isEnabled(QStringLiteral("tool_life")) && life && m_project.planning.minToolLife_min)
        out.push_back({QStringLiteral("tool_life"), subject, *m_project.planning.minToolLife_min, *life,
                       QStringLiteral("min")}); // T_min <= T
}

std::vector<ConstraintValue> PlanningProblem::toleranceConstraints(const PassConditions &pass) const
{
    if (!isEnabled(QStringLiteral("tolerances")) || m_project.tolerances.empty())
        return {};
    return toleranceConstraintsOf(finishingDeviation(pass));
}

std::shared_ptr<const PlanningProblem> PlanningProblem::forFinishingDepth(double depth_mm) const
{
    std::shared_ptr<PlanningProblem> p(new PlanningProblem(*this));
    p->m_table = buildInfluenceTable(m_project.part, m_inputs, DeviationOptions{}.stationsPerFeature, depth_mm);
    p->m_targets.profiles.clear(); // the stations may differ; formed again for them
    addProfileGeometry(m_project, p->m_table, p->m_targets);
    return p;
}

DeviationResult PlanningProblem::finishingDeviation(const PassConditions &pass) const
{
    TurningInputs in = m_inputs;
    in.forces = forces(pass.feed_mm_rev, pass.depthOfCut_mm);
    if (in.boring && m_boringForceModel)
        in.boring->forces = m_boringForceModel(pass.feed_mm_rev, pass.depthOfCut_mm);
    in.pass.cuttingSpeed_m_min = pass.cuttingSpeed_m_min;
    in.pass.feed_mm_rev = pass.feed_mm_rev;
    in.pass.depthOfCut_mm = pass.depthOfCut_mm;
    DeviationResult deviation = evaluateInfluenceTable(m_project.part, m_table, in);
    if (m_learned)
        addLearnedResidual(m_project, deviation, m_learned->model, m_targets);
    return deviation;
}

std::vector<ConstraintValue> PlanningProblem::toleranceConstraintsOf(const DeviationResult &deviation) const
{
    std::vector<ConstraintValue> out;
    if (!isEnabled(QStringLiteral("tolerances")))
        return out;
    for (const ToleranceEvaluation &e :
         evaluateTolerances(m_project, deviation, EvaluationDetail::ValuesOnly, &m_targets)) {
        // A deviation that is not finite at these conditions violates the tolerance without
        // bound: dropping it would let the search take the conditions that overflow as feasible,
        // and would change the number of constraints NLopt was given.
        const double value = e.deviationNotFinite ? std::numeric_limits<double>::infinity() : e.value_um.value_or(0.0);
        const double limit = e.limit_um.value_or(0.0);
        if ((e.value_um || e.deviationNotFinite) && limit > 0.0)
            out.push_back({QStringLiteral("tolerances"), e.toleranceId, value, limit, QStringLiteral("µm")});
    }
    return out;
}

std::vector<ConstraintValue> PlanningProblem::finishingLimits(const PassConditions &pass) const
{
    std::vector<ConstraintValue> out;
    addFinishingLimits(pass, forces(pass.feed_mm_rev, pass.depthOfCut_mm), out);
    return out;
}

void PlanningProblem::addFinishingLimits(const PassConditions &pass, const CuttingForces &f,
                                         std::vector<ConstraintValue> &out) const
{
    const PlanningSettings &s = m_project.planning;
    if (isEnabled(QStringLiteral("roughness"))) {
        if (s.maxRa_um)
            out.push_back({QStringLiteral("roughness"), QStringLiteral("Ra"),
                           theoreticalRa_um(pass.feed_mm_rev, m_roughnessNoseRadius_mm), *s.maxRa_um,
                           QStringLiteral("µm")});
        if (s.maxRz_um)
            out.push_back({QStringLiteral("roughness"), QStringLiteral("Rz"),
                           theoreticalRz_um(pass.feed_mm_rev, m_roughnessNoseRadius_mm), *s.maxRz_um,
                           QStringLiteral("µm")});
    }
    addPassLimits(QStringLiteral("finishing"), pass, f, m_largestCutDiameter_mm, out);
    if (!m_inputs.boring || !m_boringForceModel)
        return;
    // The boring bar's own insert and forces in the bores, and the maker's longest overhang.
    addPassLimits(QStringLiteral("boring"), pass, m_boringForceModel(pass.feed_mm_rev, pass.depthOfCut_mm),
                  m_largestBoreDiameter_mm, out, ToolLife::SameAsTurning);
    const BoringInputs &b = *m_inputs.boring;
    if (isEnabled(QStringLiteral("bar_overhang")) && b.maxOverhangRatio)
        out.push_back({QStringLiteral("bar_overhang"), b.holderCode, b.bar.overhangRatio(), b.maxOverhangRatio->value,
                       QStringLiteral("×D")});
}

// The boring bar roughs the bores out of the pilot hole at the roughing passes' feed, speed and
// depth (boring_toolpath.h): its deepest cut is a_r, or the bore's stock above the finishing
// allowance where that is less. Its own insert's forces at that cut, on the largest bore, are
// checked against the same limits as the turning tool's (power, torque, force, spindle speed; its
// tool life is the roughing pass's). Where the finishing allowance leaves the bar nothing to rough the same constraints
// are there, met (value 0): every plan of a search has the same list, which NLopt's constraint
// function needs (optimiser.cpp).
void PlanningProblem::addBoreRoughingLimits(const PassConditions &roughing, double finishingDepth_mm,
                                            std::vector<ConstraintValue> &out) const
{
    if (!m_boringForceModel || m_boreRadialStock_mm <= 0.0)
        return;
    const double leftInBores = m_boreRadialStock_mm - finishingDepth_mm;
    const bool roughs = leftInBores > 1e-9;
    PassConditions bar = roughing;
    bar.depthOfCut_mm = std::min(roughing.depthOfCut_mm, leftInBores);
    const std::size_t first = out.size();
    addPassLimits(QStringLiteral("boring roughing"), bar,
                  roughs ? m_boringForceModel(bar.feed_mm_rev, bar.depthOfCut_mm) : CuttingForces{},
                  m_largestBoreDiameter_mm, out, ToolLife::SameAsTurning);
    if (!roughs)
        for (std::size_t i = first; i < out.size(); ++i)
            out[i].value = 0.0;
}

CandidateEvaluation PlanningProblem::evaluate(const PlanCandidate &c,
                                              const std::vector<ConstraintValue> *tolerances) const
{
    CandidateEvaluation e;
    e.constraints = tolerances ? *tolerances : toleranceConstraints(c.finishing);
    e.finishingForces = forces(c.finishing.feed_mm_rev, c.finishing.depthOfCut_mm);
    addFinishingLimits(c.finishing, e.finishingForces, e.constraints);
    e.finishingTime_min = finishingTime_min(c.finishing);
    const double leftForRoughing = m_radialStock_mm - c.finishing.depthOfCut_mm;
    PassConditions roughing = c.roughing;
    if (c.roughingPasses > 0 && leftForRoughing > 0.0) {
        roughing.depthOfCut_mm = leftForRoughing / c.roughingPasses;
        e.roughingForces = forces(roughing.feed_mm_rev, roughing.depthOfCut_mm);
        // Cutting time of the roughing passes: removed volume over the removal rate 1000 v f a_p [mm³/min].
        e.roughingTime_min = roughingVolume_mm3(c.finishing.depthOfCut_mm) /
                             (1000.0 * roughing.cuttingSpeed_m_min * roughing.feed_mm_rev * roughing.depthOfCut_mm);
        addPassLimits(QStringLiteral("roughing"), roughing, e.roughingForces, m_stockDiameter_mm, e.constraints);
        addBoreRoughingLimits(roughing, c.finishing.depthOfCut_mm, e.constraints);
        if (isEnabled(QStringLiteral("roughing_depth"))) {
            e.constraints.push_back({QStringLiteral("roughing_depth"), QStringLiteral("roughing"),
                                     roughing.depthOfCut_mm, m_depth.max, QStringLiteral("mm")});
            e.constraints.push_back({QStringLiteral("roughing_depth"), QStringLiteral("roughing"), m_depth.min,
                                     roughing.depthOfCut_mm, QStringLiteral("mm")}); // a_min <= a_r
        }
    } else if (isEnabled(QStringLiteral("roughing_depth"))) {
        // No roughing pass but stock left: the finishing pass would have to take it all (a search
        // of no roughing pass fixes a_f, so these do not come and go within it).
        if (leftForRoughing > 1e-9)
            e.constraints.push_back({QStringLiteral("roughing_depth"), QStringLiteral("roughing"), leftForRoughing, 0.0,
                                     QStringLiteral("mm")});
        if (const double leftInBores = m_boreRadialStock_mm - c.finishing.depthOfCut_mm; leftInBores > 1e-9)
            e.constraints.push_back(
                {QStringLiteral("roughing_depth"), QStringLiteral("boring"), leftInBores, 0.0, QStringLiteral("mm")});
    }
    const auto lifeFinishing = toolLife_min(c.finishing.cuttingSpeed_m_min);
    const auto lifeRoughing = toolLife_min(roughing.cuttingSpeed_m_min);
    if (lifeFinishing)
        e.toolEdgesPerPart = e.finishingTime_min / *lifeFinishing +
                             (e.roughingTime_min > 0.0 && lifeRoughing ? e.roughingTime_min / *lifeRoughing : 0.0);
    // Time and cost per part (classic machining economics, e.g. Kalpakjian & Schmid §21.12):
    //   t = t_handling + t_cut + t_change (t_cut/T);   C = M t + C_edge (t_cut/T)
    const PlanningSettings &s = m_project.planning;
    e.time_min =
        s.handlingTime_min + e.finishingTime_min + e.roughingTime_min + s.toolChangeTime_min * e.toolEdgesPerPart;
    e.cost = s.machineRate_per_min * e.time_min + s.toolCostPerEdge * e.toolEdgesPerPart;
    e.objective = s.objective == PlanningObjective::Time ? e.time_min : e.cost;
    return e;
}

} // namespace tolturn
