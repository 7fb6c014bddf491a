// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/data/data_library.h"
#include "core/deviation/deviation_model.h"
#include "core/learning/machine_learning.h"
#include "core/planning/pass_time.h"
#include "core/project/project.h"
#include "core/tolerance/target_contour.h"

#include <QString>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace tolturn {

struct PassConditions {
    double cuttingSpeed_m_min = 0.0;
    double feed_mm_rev = 0.0;
    double depthOfCut_mm = 0.0;
};

// A tolerance a plan cannot hold to (its feature in the jaws or beyond the supports, limits that
// cannot be formed), and why, in words.
struct ToleranceLeftOut {
    QString toleranceId;
    QString reason;

    [[nodiscard]] QString text() const { return QStringLiteral("%1 (%2)").arg(toleranceId, reason); } // "T3 (why)"
};

// "T3 (why); T5 (why)".
[[nodiscard]] QString leftOutText(const std::vector<ToleranceLeftOut> &tolerances);

// A plan: the finishing pass over the finishing allowance, and `roughingPasses` equal roughing
// passes that take the rest of the stock (docs/planning.md §1).
struct PlanCandidate {
    PassConditions finishing;
    PassConditions roughing; // depthOfCut_mm follows from the stock and the number of passes
    int roughingPasses = 0;
};

// One constraint at one candidate: satisfied when value <= limit (a lower bound is written as
// limit/value). `name` is the constraint keyword, `subject` what it applies to ("finishing",
// "roughing", or a tolerance id).
struct ConstraintValue {
    QString name;
    QString subject;
    double value = 0.0;
    double limit = 0.0;
    QString unit;

    // g = value/limit - 1: <= 0 satisfied; the relative violation when positive.
    [[nodiscard]] double violation() const { return limit > 0.0 ? value / limit - 1.0 : (value > 0.0 ? 1e9 : -1.0); }

    [[nodiscard]] QString label() const; // "tolerance T1", "power (finishing)"
    // How far it is violated, for people: "by 12.5 %", or that the value is not finite (a
    // deviation that overflows at these conditions, PlanningProblem::toleranceConstraintsOf).
    [[nodiscard]] QString violatedBy() const;
};

struct CandidateEvaluation {
    double objective = 0.0; // minutes or money per part, as the project's objective says
    double time_min = 0.0;
    double cost = 0.0;
    double finishingTime_min = 0.0;
    double roughingTime_min = 0.0;
    double toolEdgesPerPart = 0.0; // 0 when no tool life is given
    std::vector<ConstraintValue> constraints;
    CuttingForces finishingForces;
    CuttingForces roughingForces;

    [[nodiscard]] bool feasible(double slack = 1e-9) const;
    [[nodiscard]] const ConstraintValue *mostViolated() const;
    [[nodiscard]] double totalViolation() const;
};

// Whether a planning constraint has a limit to check against (planning data, or the machine's
// published limits): a constraint without one is not checked, and the planner is told so.
[[nodiscard]] bool constraintHasLimit(const Project &project, const DataLibrary &data, const QString &constraint);

// Everything the optimiser, the cutting window and the clamping advisor need about one project,
// prepared once: the resolved inputs, the influence table of the finishing pass, the turned
// lengths and the stock to remove.
// The most roughing passes a plan has: a program limit (a stock that needs more is refused when
// the problem is built, and smaller depths are not searched beyond it), not a machining rule.
inline constexpr int kMaxRoughingPasses = 100;

class PlanningProblem {
public:
    struct BuildResult {
        std::shared_ptr<const PlanningProblem> problem;
        Diagnostics diagnostics;
    };

    // On a machine that was not measured the tolerance constraints use the deflection at `end` of
    // the chuck's published stiffness range: the compliant end, so that the plan holds on any
    // machine in it, unless told otherwise.
    // With `learned`, the tolerance constraints add what was learned of the machine from its
    // measured parts to the physics of every candidate (docs/learning.md): the machine's measured
    // behaviour, so its stiffness is taken as it was when the model was learned (the compliant end).
    static BuildResult build(const Project &project, const DataLibrary &data,
                             StiffnessEnd end = StiffnessEnd::Compliant,
                             std::shared_ptr<const LoadedModel> learned = nullptr);

    // `tolerances`, when given, are the tolerance constraints of this finishing feed and depth,
    // computed before (they do not depend on the cutting speed): the window maps reuse them.
    [[nodiscard]] CandidateEvaluation evaluate(const PlanCandidate &candidate,
                                               const std::vector<ConstraintValue> *tolerances = nullptr) const;
    // The tolerance constraints of a finishing pass (the deviation it leaves against each tolerance).
    [[nodiscard]] std::vector<ConstraintValue> toleranceConstraints(const PassConditions &pass) const;

    // Whether those constraints change with the cutting speed (the spindle speed's thermal drift,
    // a learned residual): when they do not, a window may compute them once per feed.
    [[nodiscard]] bool tolerancesDependOnCuttingSpeed() const
    {
        return m_inputs.thermal.has_value() || m_learned != nullptr;
    }

    // The same problem for a finishing pass of a fixed depth, its deviation on the stations and the
    // in-process section the verdicts use (computeDeviation): the optimiser's table is built for the
    // smallest depth of the range, which is safe while the depth is searched but not what a given
    // pass leaves. For a feed schedule of the plan's own finishing pass.
    [[nodiscard]] std::shared_ptr<const PlanningProblem> forFinishingDepth(double depth_mm) const;
    // The deviation a finishing pass at these conditions leaves (with what was learned of the
    // machine, when there is a model), and the tolerance constraints of any such deviation: a feed
    // schedule evaluates deviations put together feature by feature from several feeds.
    [[nodiscard]] DeviationResult finishingDeviation(const PassConditions &pass) const;
    [[nodiscard]] std::vector<ConstraintValue> toleranceConstraintsOf(const DeviationResult &deviation) const;
    // The limits of the finishing pass itself at these conditions (roughness, power, torque, force,
    // spindle speed, tool life, the boring bar's): what evaluate() adds to the tolerances.
    [[nodiscard]] std::vector<ConstraintValue> finishingLimits(const PassConditions &pass) const;

    // The cutting passes of a plan, as a project holds them: the roughing passes, equal, taking
    // the stock above the finishing allowance, then the finishing pass.
    [[nodiscard]] std::vector<CuttingPass> passesOf(const PlanCandidate &candidate) const;

    [[nodiscard]] const Project &project() const { return m_project; }

    [[nodiscard]] const TurningInputs &inputs() const { return m_inputs; }

    [[nodiscard]] const ValueRange &speedRange() const { return m_speed; }

    [[nodiscard]] const ValueRange &feedRange() const { return m_feed; }

    [[nodiscard]] const ValueRange &depthRange() const { return m_depth; }

    // The inserts that cut the surfaces the roughness limits hold for (the turning insert, and the
    // boring bar's where there are bores), for people, with their nose radii; the limits are
    // checked with the smallest radius.
    struct RoughnessInsert {
        QString insert;
        double noseRadius_mm = 0.0;
    };

    [[nodiscard]] const std::vector<RoughnessInsert> &roughnessInserts() const { return m_roughnessInserts; }

    [[nodiscard]] double roughnessNoseRadius_mm() const { return m_roughnessNoseRadius_mm; }

    // Whether the planning data give Taylor constants: without them tool life, edges per part and
    // tool changes are not known (shown so, never as zero).
    [[nodiscard]] bool knowsToolLife() const
    {
        return m_project.planning.taylorC_m_min.has_value() && m_project.planning.taylorN.has_value();
    }

    // Radial stock between the bar and the deepest turned feature [mm].
    [[nodiscard]] double radialStock_mm() const { return m_radialStock_mm; }

    // Roughing passes that can take the stock left by a finishing allowance in [min, max] depth range.
    [[nodiscard]] std::pair<int, int> roughingPassRange(double finishingDepth_mm) const;
    [[nodiscard]] bool isEnabled(const QString &constraint) const;

    [[nodiscard]] QStringList notes() const { return m_notes; }

    // The tolerances that cannot be constraints of the plan, each with why.
    [[nodiscard]] const std::vector<ToleranceLeftOut> &unconstrainedTolerances() const { return m_unconstrained; }

    [[nodiscard]] const std::shared_ptr<const LoadedModel> &learned() const { return m_learned; }

private:
    PlanningProblem() = default;
    [[nodiscard]] CuttingForces forces(double feed_mm_rev, double depth_mm) const;
    void timeFinishingPasses(const std::vector<PassPath> &passes);
    void keepTheBoredProfile(const PassPath &boring);
    void noteUnconstrainedTolerances();
    [[nodiscard]] double finishingTime_min(const PassConditions &pass) const;
    [[nodiscard]] double roughingVolume_mm3(double finishingDepth_mm) const;
    // The boring bar's passes run at the turning passes' speeds and the Taylor constants are the
    // planning data's, so their tool life is the turning passes' and is not checked twice.
    enum class ToolLife { Checked, SameAsTurning };
    void addPassLimits(const QString &subject, const PassConditions &pass, const CuttingForces &f,
                       double largestDiameter_mm, std::vector<ConstraintValue> &out,
                       ToolLife toolLife = ToolLife::Checked) const;
    void addFinishingLimits(const PassConditions &pass, const CuttingForces &f,
                            std::vector<ConstraintValue> &out) const;
    void addBoreRoughingLimits(const PassConditions &roughing, double finishingDepth_mm,
                               std::vector<ConstraintValue> &out) const;
    [[nodiscard]] std::optional<double> toolLife_min(double cuttingSpeed_m_min) const;

    Project m_project;
    TurningInputs m_inputs;
    InfluenceTable m_table;
    ProgramTargets m_targets; // what the finishing program aims at, for the tolerance constraints
    std::shared_ptr<const LoadedModel> m_learned;
    std::function<CuttingForces(double, double)> m_forceModel;
    std::function<CuttingForces(double, double)> m_boringForceModel; // empty without a boring bar
    ValueRange m_speed, m_feed, m_depth;
    double m_radialStock_mm = 0.0;
    double m_largestCutDiameter_mm = 0.0;
    double m_largestBoreDiameter_mm = 0.0;
    double m_roughnessNoseRadius_mm = 0.0; // the smaller nose radius of the tools that cut the features
    std::vector<RoughnessInsert> m_roughnessInserts;
    double m_stockDiameter_mm = 0.0;
    std::optional<double> m_maxPower_kW, m_maxTorque_Nm, m_maxSpeed_rpm;
    QStringList m_notes;
    std::vector<ToleranceLeftOut> m_unconstrained; // noteUnconstrainedTolerances()
    // The feed moves of the finishing passes the program cuts (pass_time.h), for their time, and
    // the diameter on which they need their highest spindle speed (the program's G50 at v_f).
    FeedTimeTable m_finishingTimes;
    double m_speedLimitingDiameter_mm = 0.0;
    // Outer stations (z, radius) for the roughing volume, and the bored ones out of the pilot hole.
    std::vector<std::pair<double, double>> m_outerProfile;
    std::vector<std::pair<double, double>> m_boredProfile;
    double m_pilotRadius_mm = 0.0;
    double m_boreRadialStock_mm = 0.0; // the most the boring bar takes off a radius: bore less pilot hole
};

} // namespace tolturn
