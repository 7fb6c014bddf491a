// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/clamping_advisor.h"

#include "core/project/keywords.h"
#include "core/project/operations.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace tolturn {

namespace {

struct ClampingAdvice {
    Q_DECLARE_TR_FUNCTIONS(ClampingAdvice)
};

// Length a chuck can grip: the project's own, or the first outer cylinder (at most a third of the
// part). z runs from the held end: an operation's view of a part held at its right end is mirrored
// (operationView).
std::optional<double> gripLength(const Project &p)
{
    if (p.clamping.method != ClampingMethod::BetweenCentres && p.clamping.clampedLength_mm > 0.0)
        return p.clamping.clampedLength_mm;
    for (const Segment &s : p.part.outer.segments) {
        if (s.kind == SegmentKind::Face || s.kind == SegmentKind::Chamfer || s.kind == SegmentKind::Radius)
            continue; // the end face and its edge break
        if (s.kind != SegmentKind::Cylinder)
            return std::nullopt;
        return proposedGripLength_mm(s.to.z_mm, p.part.length_mm());
    }
    return std::nullopt;
}

// The tolerance nearest its limit at the plan (value / limit), which tells equal plans apart.
std::optional<ConstraintValue> tightestTolerance(const CandidateEvaluation &e)
{
    std::optional<ConstraintValue> tightest;
    for (const ConstraintValue &c : e.constraints)
        if (c.name == QLatin1String("tolerances") && c.limit > 0.0 &&
            (!tightest || c.value / c.limit > tightest->value / tightest->limit))
            tightest = c;
    return tightest;
}

double tightestUtilisation(const CandidateEvaluation &e)
{
    const auto t = tightestTolerance(e);
    return t ? t->value / t->limit : 0.0;
}

QString describe(const ClampingOption &o, const Project &p)
{
    if (!o.possible)
        return o.reason;
    const CandidateEvaluation &e = o.plan.evaluation;
    if (o.plan.feasible) {
        // A tolerance the plan cannot be held to is no constraint of it: "every constraint" would
        // read as every tolerance (rankClampingOptions puts such options after those that hold all).
        QString text = (o.tolerancesNotHeld.empty()
                            ? ClampingAdvice::tr("meets every constraint: %1 %2 per part")
                            : ClampingAdvice::tr("meets every constraint it can check, but not every tolerance is "
                                                 "one: %1 %2 per part"))
                           .arg(QString::number(e.objective, 'f', 3), p.planning.objective == PlanningObjective::Time
                                                                          ? ClampingAdvice::tr("min")
                                                                          : ClampingAdvice::tr("cost"));
        if (const auto t = tightestTolerance(e))
            text += ClampingAdvice::tr("; deciding: %1, %2 of %3 %4 (%5 % used)")
                        .arg(t->label(), QString::number(t->value, 'f', 1), QString::number(t->limit, 'f', 1), t->unit,
                             QString::number(100.0 * t->value / t->limit, 'f', 0));
        return text;
    }
    QStringList violated;
    for (const ConstraintValue &c : o.plan.conflicts)
        violated << QStringLiteral("%1 %2").arg(c.label(), c.violatedBy());
    return ClampingAdvice::tr("no plan meets every constraint: %1").arg(violated.join(QStringLiteral(", ")));
}

} // namespace

std::vector<ClampingOption> adviseClamping(const Project &project, const DataLibrary &data,
                                           const OptimisationOptions &options)
{
    std::vector<ClampingOption> out;
    const auto grip = gripLength(project);
    constexpr std::array methods{ClampingMethod::Chuck, ClampingMethod::BetweenCentres, ClampingMethod::ChuckTailstock};
    for (const ClampingMethod method : methods) {
        ClampingOption o;
        o.method = method;
        const bool chuck = method != ClampingMethod::BetweenCentres;
        if (chuck && !grip) {
            o.reason = project.clamping.heldEnd == PartEnd::Right
                           ? ClampingAdvice::tr("no cylinder at the right end of the part for the chuck jaws to grip")
                           : ClampingAdvice::tr("no cylinder at the left end of the part for the chuck jaws to grip");
            out.push_back(o);
            continue;
        }
        Project p = project;
        p.clamping.method = method;
        p.clamping.clampedLength_mm = chuck ? *grip : 0.0;
        o.clampedLength_mm = p.clamping.clampedLength_mm;
        const PlanningProblem::BuildResult built = PlanningProblem::build(p, data);
        if (!built.problem) {
            o.reason = built.diagnostics.empty() ? ClampingAdvice::tr("cannot be planned")
                                                 : built.diagnostics.front().toString();
            out.push_back(o);
            continue;
        }
        o.possible = true;
        // Each method its third of the progress, in turn.
        const auto third = static_cast<double>(out.size()) / static_cast<double>(methods.size());
        OptimisationOptions part = options;
        part.progress = Progress(options.progress, third, third + 1.0 / static_cast<double>(methods.size()));
        o.plan = optimisePlan(*built.problem, part);
        o.tolerancesNotHeld = built.problem->unconstrainedTolerances();
        o.reason = describe(o, p);
        if (!o.tolerancesNotHeld.empty())
            o.reason += ClampingAdvice::tr("; not held to: %1").arg(leftOutText(o.tolerancesNotHeld));
        if (!holdsOneEndOnly(method)) // the toolpath does not face an end a centre holds
            o.reason += ClampingAdvice::tr("; the right end face is held by a centre: it is faced and centred before "
                                           "the set-up, not in this time");
        out.push_back(o);
    }
    rankClampingOptions(out);
    return out;
}

void rankClampingOptions(std::vector<ClampingOption> &options)
{
    std::stable_sort(options.begin(), options.end(), [](const ClampingOption &a, const ClampingOption &b) {
        enum Group { HoldsAll, LeavesSome, Infeasible, NotPossible };
        auto group = [](const ClampingOption &o) {
            if (!o.possible)
                return NotPossible;
            if (!o.plan.feasible)
                return Infeasible;
            return o.tolerancesNotHeld.empty() ? HoldsAll : LeavesSome;
        };
        if (group(a) != group(b))
            return group(a) < group(b);
        if (group(a) == NotPossible)
            return false;
        if (group(a) == Infeasible)
            return a.plan.evaluation.totalViolation() < b.plan.evaluation.totalViolation();
        // Objectives to the millionth of a minute or of the currency: equal there is equal, which
        // keeps the order strict and weak (a tolerance of 1e-6 between neighbours would chain).
        const double ea = std::round(a.plan.evaluation.objective * 1e6);
        const double eb = std::round(b.plan.evaluation.objective * 1e6);
        if (ea != eb)
            return ea < eb;
        // Equal times or costs: the plan with more margin on its tightest tolerance first.
        return tightestUtilisation(a.plan.evaluation) < tightestUtilisation(b.plan.evaluation);
    });
}

} // namespace tolturn
