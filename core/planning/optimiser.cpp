// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/optimiser.h"

#include "core/common/diagnostic.h"
#include "core/planning/program_resolution.h"
#include "core/planning/remedies.h"

#include <QCoreApplication>
#include <nlopt.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace tolturn {

namespace {

struct Optimiser {
    Q_DECLARE_TR_FUNCTIONS(Optimiser)
};

constexpr double kPenalty = 1000.0;
// What an overflowing objective or violation is taken as: worse than any real plan (minutes or
// currency per part, relative violations), and small enough that NLopt's arithmetic on it stays
// finite: COBYLA loops for ever inside its own linear algebra on values near the double range.
constexpr double kWorstObjective = 1e12;
// The longest search that may be asked for: an hour.
constexpr double kMaxTimeLimit_s = 3600.0;

double finiteOrWorst(double v)
{
    return std::isfinite(v) ? std::min(v, kWorstObjective) : kWorstObjective;
}

using Clock = std::chrono::steady_clock;

struct Context {
    Context(const PlanningProblem &p, int k, const PlanBox &box, Progress part, Clock::time_point end)
        : problem(&p)
        , roughingPasses(k)
        , lower(box.lower)
        , upper(box.upper)
        , progress(std::move(part))
        , deadline(end)
    {
    }

    const PlanningProblem *problem;
    int roughingPasses;
    std::vector<double> lower, upper;
    Progress progress; // this search's part of the whole run
    Clock::time_point deadline;
    int evaluations = 0;
    int budget = 1;
    bool cancelled = false;
    bool timedOut = false;

    [[nodiscard]] std::vector<double> denormalise(const double *u) const
    {
        std::vector<double> x(lower.size());
        for (std::size_t i = 0; i < x.size(); ++i)
            x[i] = lower[i] + u[i] * (upper[i] - lower[i]);
        return x;
    }

    CandidateEvaluation evaluate(const double *u)
    {
        ++evaluations;
        if (evaluations % 64 == 0 && !progress.report(double(evaluations) / budget)) {
            cancelled = true;
            throw nlopt::forced_stop();
        }
        // NLopt's own count is not a bound for every algorithm: COBYLA can go on for ever on
        // an objective that overflows. The search stops here at its budget, whatever it does.
        if (evaluations > budget)
            throw nlopt::forced_stop();
        if (Clock::now() >= deadline) {
            timedOut = true;
            throw nlopt::forced_stop();
        }
        CandidateEvaluation e = problem->evaluate(candidateAt(denormalise(u), roughingPasses));
        // An overflowing cost or violation (degenerate tool-life data, say) ranks last, finitely.
        e.objective = finiteOrWorst(e.objective);
        return e;
    }
};

double penalised(unsigned n, const double *u, double *, void *data)
{
    (void)n;
    auto *c = static_cast<Context *>(data);
    const CandidateEvaluation e = c->evaluate(u);
    return finiteOrWorst(e.objective * (1.0 + kPenalty * e.totalViolation()));
}

double objectiveOnly(unsigned, const double *u, double *, void *data)
{
    auto *c = static_cast<Context *>(data);
    return c->evaluate(u).objective;
}

double violationOnly(unsigned, const double *u, double *, void *data)
{
    auto *c = static_cast<Context *>(data);
    return finiteOrWorst(c->evaluate(u).totalViolation());
}

void constraints(unsigned m, double *result, unsigned, const double *u, double *, void *data)
{
    auto *c = static_cast<Context *>(data);
    const CandidateEvaluation e = c->evaluate(u);
    // A constraint this candidate does not have (no roughing stock left, say) does not apply
    // to it: satisfied, never the garbage NLopt's buffer holds.
    for (unsigned i = 0; i < m; ++i)
        result[i] = i < e.constraints.size() ? finiteOrWorst(e.constraints[i].violation()) : -1.0;
}

std::vector<double> runSearch(nlopt::algorithm algorithm, Context &context, std::vector<double> start, int evaluations,
                              nlopt::func objective, bool withConstraints)
{
    const auto n = static_cast<unsigned>(start.size());
    nlopt::opt opt(algorithm, n);
    opt.set_lower_bounds(std::vector<double>(n, 0.0));
    opt.set_upper_bounds(std::vector<double>(n, 1.0));
    opt.set_min_objective(objective, &context);
    opt.set_maxeval(evaluations);
    if (withConstraints) {
        std::vector<double> u(start);
        const auto count = context.problem->evaluate(candidateAt(context.denormalise(u.data()), context.roughingPasses))
                               .constraints.size();
        if (count > 0)
            opt.add_inequality_mconstraint(constraints, &context, std::vector<double>(count, 1e-9));
        opt.set_xtol_rel(1e-7);
    }
    double value = 0.0;
    try {
        opt.optimize(start, value);
    } catch (const nlopt::forced_stop &) {
    } catch (const std::exception &) {
        // A failed local refinement leaves the start point, which the caller evaluates itself.
    }
    return start;
}

} // namespace

bool PlanBox::empty() const
{
    for (std::size_t i = 0; i < lower.size(); ++i) {
        if (lower[i] > upper[i] + 1e-12)
            return true;
    }
    return lower.empty();
}

PlanBox planBox(const PlanningProblem &p, int k)
{
    const ValueRange &v = p.speedRange();
    const ValueRange &f = p.feedRange();
    const ValueRange &a = p.depthRange();
    const double stock = p.radialStock_mm();
    PlanBox box;
    double apLow = a.min;
    double apHigh = std::min(a.max, stock);
    if (k == 0) {
        apLow = apHigh = stock; // the finishing pass takes all the stock
        if (stock < a.min || stock > a.max)
            apLow = apHigh + 1.0;
    } else {
        // k passes of depth (stock - a_f)/k within [a.min, a.max]
        apLow = std::max(apLow, stock - k * a.max);
        apHigh = std::min(apHigh, stock - k * a.min);
    }
    box.lower = {v.min, f.min, apLow, v.min, f.min};
    box.upper = {v.max, f.max, apHigh, v.max, f.max};
    return box;
}

PlanCandidate candidateAt(const std::vector<double> &x, int roughingPasses)
{
    PlanCandidate c;
    c.finishing = {x[0], x[1], x[2]};
    c.roughing = {x[3], x[4], 0.0};
    c.roughingPasses = roughingPasses;
    return c;
}

namespace {

struct SearchOutcome {
    PlanCandidate candidate;
    CandidateEvaluation evaluation;
};

// A search's end: its evaluations, stop and time-out added to the run's, and the plan at the point
// it ended on, evaluated by the problem it searched.
SearchOutcome finishSearch(const Context &c, const std::vector<double> &u, PlanResult &result)
{
    result.evaluations += c.evaluations;
    result.cancelled = result.cancelled || c.cancelled;
    result.timedOut = result.timedOut || c.timedOut;
    SearchOutcome outcome;
    outcome.candidate = candidateAt(c.denormalise(u.data()), c.roughingPasses);
    outcome.evaluation = c.problem->evaluate(outcome.candidate);
    return outcome;
}

// Global search (penalised DIRECT-L) and, when `localEvaluations` > 0, a local refinement with
// the constraints (COBYLA), for one number of roughing passes.
SearchOutcome searchPasses(const PlanningProblem &problem, int k, int globalEvaluations, int localEvaluations,
                           const Progress &part, PlanResult &result, Clock::time_point deadline)
{
    const PlanBox box = planBox(problem, k);
    Context c(problem, k, box, part, deadline);
    c.budget = globalEvaluations + localEvaluations;
    std::vector<double> u =
        runSearch(nlopt::GN_DIRECT_L, c, std::vector<double>(5, 0.5), globalEvaluations, penalised, false);
    if (!c.cancelled && !c.timedOut && localEvaluations > 0)
        u = runSearch(nlopt::LN_COBYLA, c, u, localEvaluations, objectiveOnly, true);
    return finishSearch(c, u, result);
}

// The speeds and feeds searched again with the finishing depth fixed at `depth_mm`, on the
// influence table of the section that depth leaves (PlanningProblem::forFinishingDepth): from
// `start` with the constraints (COBYLA) when it is given, else a global search first.
SearchOutcome searchAtDepth(const PlanningProblem &atDepth, int k, double depth_mm, int evaluations, PlanResult &result,
                            const Progress &progress, Clock::time_point deadline,
                            const std::optional<PlanCandidate> &start = std::nullopt)
{
    PlanBox box = planBox(atDepth, k);
    box.lower[2] = box.upper[2] = depth_mm;
    Context c(atDepth, k, box, progress, deadline);
    c.budget = 2 * evaluations;
    std::vector<double> u(5, 0.5);
    if (start) {
        const std::vector<double> x{start->finishing.cuttingSpeed_m_min, start->finishing.feed_mm_rev, depth_mm,
                                    start->roughing.cuttingSpeed_m_min, start->roughing.feed_mm_rev};
        for (std::size_t i = 0; i < u.size(); ++i)
            u[i] = box.upper[i] > box.lower[i]
                       ? std::clamp((x[i] - box.lower[i]) / (box.upper[i] - box.lower[i]), 0.0, 1.0)
                       : 0.0;
    } else {
        u = runSearch(nlopt::GN_DIRECT_L, c, u, evaluations, penalised, false);
    }
    if (!c.timedOut)
        u = runSearch(nlopt::LN_COBYLA, c, u, evaluations, objectiveOnly, true);
    return finishSearch(c, u, result);
}

// Plans in order of merit: a feasible one before any infeasible one; feasible ones by their
// objective, infeasible ones by how much they violate (a number added to a huge one would not
// tell them apart).
struct Rank {
    bool infeasible = true;
    double value = std::numeric_limits<double>::infinity();

    friend bool operator<(const Rank &a, const Rank &b)
    {
        return a.infeasible != b.infeasible ? !a.infeasible : a.value < b.value;
    }
};

Rank rank(const CandidateEvaluation &e)
{
    const bool feasible = e.feasible(1e-6);
    return {!feasible, feasible ? e.objective : e.totalViolation()};
}

} // namespace

namespace {

// The searches evaluate the tolerances on the influence table of the smallest finishing depth
// (the thinnest section left, docs/planning.md §3). That errs on the safe side for a size, but a
// form's spread (cylindricity, a profile without datums) can grow with a stiffer section. So the
// optimum's speeds and feeds are searched again on the table of its own depth, as `evaluate`
// judges the plan: a plan held there keeps the better of the two; when a tolerance is violated
// there and the search at that depth finds nothing feasible, the search goes on at the smallest
// depth (on its table with the stations `evaluate` uses) for every number of roughing passes
// that allows it.
void checkAtItsOwnDepth(const PlanningProblem &problem, const std::vector<int> &counts,
                        const OptimisationOptions &options, PlanResult &result, Clock::time_point deadline)
{
    const int k = result.candidate.roughingPasses;
    const double depth = result.candidate.finishing.depthOfCut_mm;
    const auto atDepth = problem.forFinishingDepth(depth);
    const Progress afterTheRun(options.progress, 1.0, 1.0); // a stop still cancels
    result.evaluation = atDepth->evaluate(result.candidate);
    if (result.evaluation.feasible(1e-6)) {
        const SearchOutcome best = searchAtDepth(*atDepth, k, depth, options.localEvaluations, result, afterTheRun,
                                                 deadline, result.candidate);
        // Held there too, with the slack the smallest depth's table kept: the search at this depth
        // takes it up, so a tolerance that binds is at its limit on the section that is cut.
        if (rank(best.evaluation) < rank(result.evaluation)) {
            result.candidate = best.candidate;
            result.evaluation = best.evaluation;
        }
        return;
    }
    const ConstraintValue violated = *result.evaluation.mostViolated();
    // The plan as judged at its own depth stays unless a search does better (one stopped at the
    // time limit may not).
    SearchOutcome best{result.candidate, result.evaluation};
    const auto keepIfBetter = [&best](const SearchOutcome &o) {
        if (rank(o.evaluation) < rank(best.evaluation))
            best = o;
    };
    keepIfBetter(searchAtDepth(*atDepth, k, depth, options.localEvaluations, result, afterTheRun, deadline));
    const double smallest = problem.depthRange().min;
    const auto atSmallest = problem.forFinishingDepth(smallest); // with the stations `evaluate` judges at
    for (const int passes : counts) {
        if (best.evaluation.feasible(1e-6) || result.timedOut || result.cancelled)
            break;
        const PlanBox box = planBox(problem, passes);
        if (box.empty() || box.lower[2] > smallest + 1e-9)
            continue;
        keepIfBetter(
            searchAtDepth(*atSmallest, passes, smallest, options.localEvaluations, result, afterTheRun, deadline));
    }
    result.notes << Optimiser::tr("On the section its own finishing depth (%1 mm) leaves, the plan the search found "
                                  "violated %2 %3; the speeds and feeds were searched again at depth %4 mm.")
                        .arg(formatFixed(depth, 3), violated.label(), violated.violatedBy(),
                             formatFixed(best.candidate.finishing.depthOfCut_mm, 3));
    result.feasible = best.evaluation.feasible(1e-6);
    result.candidate = best.candidate;
    result.evaluation = best.evaluation;
}

// The values a variable of the plan may take on its program step (program_resolution.h): the
// step below and the step above that lie in its box, or the value itself where no step does (a
// depth the stock fixes, a range narrower than a step).
std::vector<double> onStep(double x, double step, double lo, double hi)
{
    std::vector<double> values;
    for (const double v : {std::floor(x / step + 1e-9) * step, std::ceil(x / step - 1e-9) * step}) {
        if (v >= lo - 1e-9 && v <= hi + 1e-9 && (values.empty() || std::abs(v - values.front()) > 1e-12))
            values.push_back(v);
    }
    if (values.empty())
        values.push_back(x);
    return values;
}

// The first variable whose range holds no value on its step (a speed range of 201.2–201.8 m/min),
// kept as the search found it: said, since the program rounds it (perhaps out of the range).
void sayWhereNoStepFits(const std::array<double, 5> &x, const std::array<double, 5> &step,
                        const std::array<std::vector<double>, 5> &values, const PlanBox &box, QStringList &notes)
{
    const std::array<QString, 5> unit{QStringLiteral("m/min"), QStringLiteral("mm/rev"), QStringLiteral("mm"),
                                      QStringLiteral("m/min"), QStringLiteral("mm/rev")};
    for (std::size_t i = 0; i < x.size(); ++i) {
        const bool onItsStep = std::abs(x[i] / step[i] - std::round(x[i] / step[i])) < 1e-6;
        const bool keptAsItIs = values[i].size() == 1 && std::abs(values[i].front() - x[i]) < 1e-12;
        if (keptAsItIs && !onItsStep && box.upper[i] - box.lower[i] > 1e-9) {
            notes << Optimiser::tr("The range %1–%2 %5 holds no value on the step a program states (%3 %5): the plan "
                                   "keeps %4 %5, which the program rounds.")
                         .arg(formatNumber(box.lower[i]), formatNumber(box.upper[i]), formatNumber(step[i]),
                              formatNumber(x[i]), unit[i]);
            return;
        }
    }
}

// The plan found, stated as the program states it: each of the five variables on its step, below
// or above, the best of the combinations as `evaluate` judges them (on the section the finishing
// depth leaves). A search optimum on a binding constraint lies between steps; its nearest
// settable neighbour may break the constraint by a hair, so every neighbour is judged. A feasible
// plan stays at full precision, said in a note, when none of its neighbours holds.
void stateOnProgramSteps(const PlanningProblem &problem, PlanResult &result)
{
    const PlanCandidate &c = result.candidate;
    const PlanBox box = planBox(problem, c.roughingPasses);
    const std::array<double, 5> x{c.finishing.cuttingSpeed_m_min, c.finishing.feed_mm_rev, c.finishing.depthOfCut_mm,
                                  c.roughing.cuttingSpeed_m_min, c.roughing.feed_mm_rev};
    const std::array<double, 5> step{kProgramSpeedStep_m_min, kProgramFeedStep_mm_rev, kProgramDepthStep_mm,
                                     kProgramSpeedStep_m_min, kProgramFeedStep_mm_rev};
    std::array<std::vector<double>, 5> values;
    for (std::size_t i = 0; i < x.size(); ++i)
        values[i] = onStep(x[i], step[i], box.lower[i], box.upper[i]);
    std::map<double, std::shared_ptr<const PlanningProblem>> atDepth;
    std::optional<SearchOutcome> best;
    for (unsigned pick = 0; pick < 32U; ++pick) {
        std::vector<double> y(x.size());
        bool exists = true;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const std::size_t choice = (pick >> i) & 1U;
            exists = exists && choice < values[i].size();
            y[i] = values[i][std::min(choice, values[i].size() - 1)];
        }
        if (!exists)
            continue;
        auto &judge = atDepth[y[2]];
        if (!judge)
            judge = problem.forFinishingDepth(y[2]);
        SearchOutcome o;
        o.candidate = candidateAt(y, c.roughingPasses);
        o.evaluation = judge->evaluate(o.candidate);
        if (!best || rank(o.evaluation) < rank(best->evaluation))
            best = o;
    }
    sayWhereNoStepFits(x, step, values, box, result.notes);
    if (result.feasible && !best->evaluation.feasible(1e-6)) {
        result.notes << Optimiser::tr("Stated on the steps a program gives them (%1 m/min, %2 mm/rev, %3 mm), the "
                                      "plan breaks a constraint: it is kept at full precision, and the program "
                                      "rounds it.")
                            .arg(formatFixed(kProgramSpeedStep_m_min, 0), formatFixed(kProgramFeedStep_mm_rev, 3),
                                 formatFixed(kProgramDepthStep_mm, 3));
        return;
    }
    result.candidate = best->candidate;
    result.evaluation = best->evaluation;
    result.feasible = best->evaluation.feasible(1e-6);
}

} // namespace

PlanResult optimisePlan(const PlanningProblem &problem, const OptimisationOptions &options)
{
    PlanResult result;
    result.notes = problem.notes();
    const auto started = Clock::now();
    const auto deadline = started + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                                        std::clamp(options.timeLimit_s, 0.0, kMaxTimeLimit_s)));
    auto goOn = [&result] { return !result.cancelled && !result.timedOut; };
    // Every number of roughing passes some finishing allowance in the insert's depth range allows.
    const int fewest = problem.roughingPassRange(problem.depthRange().max).first;
    const int most = problem.roughingPassRange(problem.depthRange().min).second;
    std::vector<int> counts;
    for (int k = fewest; k <= most; ++k) {
        if (!planBox(problem, k).empty())
            counts.push_back(k);
    }
    // A coarse look at every number of passes, then the full search where it looks best. The best
    // plan seen so far is kept for a search stopped at its time limit.
    constexpr int kCoarse = 120;
    constexpr std::size_t kRefined = 2;
    std::optional<SearchOutcome> bestSeen;
    auto keepIfBetter = [&bestSeen](const SearchOutcome &o) {
        if (!bestSeen || rank(o.evaluation) < rank(bestSeen->evaluation))
            bestSeen = o;
    };
    std::vector<std::pair<Rank, int>> ranked;
    for (std::size_t i = 0; i < counts.size() && goOn(); ++i) {
        // The coarse searches share the first 30 % of the run, the refinements the rest.
        const auto n = static_cast<double>(counts.size());
        const Progress part(options.progress, 0.3 * static_cast<double>(i) / n, 0.3 * static_cast<double>(i + 1) / n);
        const SearchOutcome coarse = searchPasses(problem, counts[i], kCoarse, 0, part, result, deadline);
        keepIfBetter(coarse);
        ranked.emplace_back(rank(coarse.evaluation), counts[i]);
    }
    std::sort(ranked.begin(), ranked.end(),
              [](const std::pair<Rank, int> &a, const std::pair<Rank, int> &b) { return a.first < b.first; });
    double leastViolation = std::numeric_limits<double>::infinity();
    PlanCandidate leastViolating;
    const std::size_t refined = std::min(kRefined, ranked.size());
    for (std::size_t i = 0; i < refined && goOn(); ++i) {
        const auto n = static_cast<double>(refined);
        const Progress part(options.progress, 0.3 + 0.7 * static_cast<double>(i) / n,
                            0.3 + 0.7 * static_cast<double>(i + 1) / n);
        const SearchOutcome o = searchPasses(problem, ranked[i].second, options.globalEvaluations,
                                             options.localEvaluations, part, result, deadline);
        keepIfBetter(o);
        if (!o.evaluation.feasible(1e-6) && o.evaluation.totalViolation() < leastViolation) {
            leastViolation = o.evaluation.totalViolation();
            leastViolating = o.candidate;
        }
    }
    if (bestSeen) {
        result.feasible = bestSeen->evaluation.feasible(1e-6);
        result.candidate = bestSeen->candidate;
        result.evaluation = bestSeen->evaluation;
    }
    if (!result.feasible && !counts.empty() && goOn()) {
        // Nothing feasible: the plan that violates the constraints least, and what it violates.
        const int k = leastViolating.roughingPasses;
        const PlanBox box = planBox(problem, k);
        Context c(problem, k, box, Progress(options.progress, 1.0, 1.0), deadline); // after the run's end
        c.budget = options.globalEvaluations;
        std::vector<double> u = runSearch(nlopt::GN_DIRECT_L, c, std::vector<double>(5, 0.5), options.globalEvaluations,
                                          violationOnly, false);
        result.evaluations += c.evaluations;
        result.timedOut = result.timedOut || c.timedOut;
        const PlanCandidate least = candidateAt(c.denormalise(u.data()), k);
        const CandidateEvaluation e = problem.evaluate(least);
        // A search stopped at the time limit may end worse than a plan already seen.
        if (!bestSeen || rank(e) < rank(bestSeen->evaluation)) {
            result.candidate = least;
            result.evaluation = e;
        }
    }
    if (result.feasible && goOn())
        checkAtItsOwnDepth(problem, counts, options, result, deadline);
    if (!counts.empty() && !result.cancelled)
        stateOnProgramSteps(problem, result);
    if (!result.feasible) {
        for (const ConstraintValue &v : result.evaluation.constraints) {
            if (v.violation() <= 1e-6)
                continue;
            result.conflicts.push_back(v);
            // The same remedy once: a tool life short on the finishing and the roughing pass alike.
            if (const QString remedy = whatItWouldTake(problem, v);
                !remedy.isEmpty() && !result.remedies.contains(remedy))
                result.remedies << remedy;
        }
    }
    if (result.timedOut)
        result.notes << Optimiser::tr("The search stopped at its time limit of %1 s after %2 plans: the plan shown is "
                                      "the best found by then, not necessarily the optimum.")
                            .arg(options.timeLimit_s)
                            .arg(result.evaluations);
    for (const ConstraintValue &v : result.evaluation.constraints) {
        if (std::abs(v.violation()) <= 0.01)
            result.binding.push_back(v);
    }
    return result;
}

} // namespace tolturn
