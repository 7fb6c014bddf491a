// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/feed_schedule.h"

#include "core/adaptive/force_control.h"
#include "core/adaptive/pass_depth.h"
#include "core/planning/program_resolution.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <set>

namespace tolturn {

namespace {

struct FeedScheduleText {
    Q_DECLARE_TR_FUNCTIONS(FeedScheduleText)
};

constexpr double kSlack = 1e-9;

// The limits of the finishing pass that change with the feed.
bool feedLimitsHold(const PlanningProblem &problem, const PassConditions &pass, QString *failing)
{
    static const QStringList feedDependent{QStringLiteral("roughness"), QStringLiteral("power"),
                                           QStringLiteral("torque"), QStringLiteral("force")};
    for (const ConstraintValue &c : problem.finishingLimits(pass)) {
        if (feedDependent.contains(c.name) && c.violation() > kSlack) {
            if (failing)
                *failing = c.label();
            return false;
        }
    }
    return true;
}

// A turned feature or face of the outer contour the schedule gives its own feed.
struct Unit {
    QString featureId;
    bool face = false;
    std::size_t index = 0; // in DeviationResult::features or ::faces
};

// The features a tolerance's value depends on: its own, the second face of a length, its datums'.
QStringList featuresOf(const Project &project, const QString &toleranceId)
{
    QStringList out;
    for (const Tolerance &t : project.tolerances) {
        if (t.id != toleranceId)
            continue;
        out << t.featureId;
        if (!t.toFeatureId.isEmpty())
            out << t.toFeatureId;
        for (const Datum &d : project.datums)
            if (t.datums.contains(d.label))
                out << d.featureId;
    }
    return out;
}

class Scheduler {
public:
    Scheduler(const PlanningProblem &problem, const CuttingPass &finishing) : m_problem(problem)
    {
        const ValueRange &range = problem.feedRange();
        std::set<double> feeds{finishing.feed_mm_rev};
        const auto steps = static_cast<int>(std::floor((range.max - range.min) / kProgramFeedStep_mm_rev + 1e-9));
        for (int i = 0; i <= steps; ++i)
            feeds.insert(std::round((range.min + i * kProgramFeedStep_mm_rev) / kProgramFeedStep_mm_rev) *
                         kProgramFeedStep_mm_rev);
        m_feeds.assign(feeds.begin(), feeds.end());
        m_programmed = static_cast<std::size_t>(std::find(m_feeds.begin(), m_feeds.end(), finishing.feed_mm_rev) -
                                                m_feeds.begin());
        for (const double f : m_feeds) {
            const PassConditions pass{finishing.cuttingSpeed_m_min, f, finishing.depthOfCut_mm};
            m_deviations.push_back(problem.finishingDeviation(pass));
            m_limitsHold.push_back(feedLimitsHold(problem, pass, nullptr));
        }
        const DeviationResult &d = m_deviations.front();
        for (std::size_t i = 0; i < d.features.size(); ++i)
            if (d.features[i].side == ContourSide::Outer)
                m_units.push_back({d.features[i].featureId, false, i});
        for (std::size_t i = 0; i < d.faces.size(); ++i)
            if (d.faces[i].side == ContourSide::Outer)
                m_units.push_back({d.faces[i].featureId, true, i});
    }

    FeedSchedule run(const CuttingPass &finishing)
    {
        FeedSchedule s;
        s.programmedFeed_mm_rev = finishing.feed_mm_rev;
        m_index.assign(m_units.size(), 0);
        m_limitedBy.assign(m_units.size(), QString());
        m_pinned.assign(m_units.size(), false);
        chooseConstraints();
        std::size_t top = 0;
        for (std::size_t c = 0; c < m_feeds.size(); ++c)
            if (m_limitsHold[c])
                top = c;
        for (std::size_t u = 0; u < m_units.size(); ++u)
            if (!m_pinned[u])
                m_index[u] = largestAlone(u, top, finishing);
        lowerWhereCoupled();
        s.deviation = spliced(m_index);
        s.tolerances = m_problem.toleranceConstraintsOf(s.deviation);
        for (std::size_t u = 0; u < m_units.size(); ++u)
            s.features.push_back({m_units[u].featureId, m_feeds[m_index[u]], m_limitedBy[u], m_pinned[u]});
        return s;
    }

private:
    // The tolerances the schedule keeps: those the pass holds with every feature at the lowest
    // feed. The features of the others keep the programmed feed (their compensation, if any, is
    // computed at it); a feature kept there can break another tolerance it takes part in (a datum
    // of a run-out), so the choice is made again until it no longer keeps a feature back. Every
    // kept tolerance then holds with the kept-back features at the programmed feed and the others
    // at the lowest, which the search below starts from.
    void chooseConstraints()
    {
        for (bool keptBack = true; keptBack;) {
            keptBack = false;
            m_kept.clear();
            for (const ConstraintValue &c : m_problem.toleranceConstraintsOf(spliced(m_index))) {
                if (c.violation() <= kSlack) {
                    m_kept.push_back(c.subject);
                    continue;
                }
                const QStringList touched = featuresOf(m_problem.project(), c.subject);
                for (std::size_t u = 0; u < m_units.size(); ++u) {
                    if (touched.contains(m_units[u].featureId) && !m_pinned[u]) {
                        m_pinned[u] = true;
                        m_index[u] = m_programmed;
                        m_limitedBy[u] = c.label();
                        keptBack = true;
                    }
                }
            }
        }
    }

    [[nodiscard]] DeviationResult spliced(const std::vector<std::size_t> &index) const
    {
        DeviationResult d = m_deviations[m_programmed];
        for (std::size_t u = 0; u < m_units.size(); ++u) {
            const DeviationResult &from = m_deviations[index[u]];
            if (m_units[u].face)
                d.faces[m_units[u].index] = from.faces[m_units[u].index];
            else
                d.features[m_units[u].index] = from.features[m_units[u].index];
        }
        return d;
    }

    // The first kept tolerance that fails on this deviation and depends on unit u (any unit: -1).
    [[nodiscard]] std::optional<ConstraintValue> failingKept(const DeviationResult &d, std::ptrdiff_t u) const
    {
        for (const ConstraintValue &c : m_problem.toleranceConstraintsOf(d)) {
            if (!m_kept.contains(c.subject) || c.violation() <= kSlack)
                continue;
            if (u < 0 ||
                featuresOf(m_problem.project(), c.subject).contains(m_units[static_cast<std::size_t>(u)].featureId))
                return c;
        }
        return std::nullopt;
    }

    // The largest feed of unit u, the others at their lowest, that holds its tolerances (bisection:
    // a larger feed deflects more).
    std::size_t largestAlone(std::size_t u, std::size_t top, const CuttingPass &finishing)
    {
        std::vector<std::size_t> index(m_units.size(), 0);
        for (std::size_t v = 0; v < m_units.size(); ++v)
            if (m_pinned[v])
                index[v] = m_programmed;
        const auto holds = [&](std::size_t c) {
            index[u] = c;
            return !failingKept(spliced(index), static_cast<std::ptrdiff_t>(u));
        };
        if (holds(top)) {
            QString failing;
            if (top + 1 < m_feeds.size())
                (void)feedLimitsHold(
                    m_problem, {finishing.cuttingSpeed_m_min, m_feeds[top + 1], finishing.depthOfCut_mm}, &failing);
            m_limitedBy[u] = failing.isEmpty() ? FeedScheduleText::tr("top of the feed range") : failing;
            return top;
        }
        std::size_t lo = 0;
        std::size_t hi = top; // holds(lo), !holds(hi)
        while (hi - lo > 1) {
            const std::size_t mid = (lo + hi) / 2;
            (holds(mid) ? lo : hi) = mid;
        }
        index[u] = hi;
        m_limitedBy[u] = failingKept(spliced(index), static_cast<std::ptrdiff_t>(u))->label();
        return lo;
    }

    // A tolerance over several features (coaxiality, run-out, a profile) may fail with each at its
    // own largest feed: lower the fastest of its features a step at a time until it holds.
    void lowerWhereCoupled()
    {
        for (std::size_t guard = 0; guard < m_units.size() * m_feeds.size(); ++guard) {
            const std::optional<ConstraintValue> failing = failingKept(spliced(m_index), -1);
            if (!failing)
                return;
            const QStringList touched = featuresOf(m_problem.project(), failing->subject);
            std::size_t fastest = 0;
            for (std::size_t u = 0; u < m_units.size(); ++u)
                if (!m_pinned[u] && touched.contains(m_units[u].featureId))
                    fastest = std::max(fastest, m_index[u]);
            if (fastest == 0)
                return; // cannot happen: every kept tolerance holds at the lowest feeds (chooseConstraints)
            for (std::size_t u = 0; u < m_units.size(); ++u) {
                if (!m_pinned[u] && touched.contains(m_units[u].featureId) && m_index[u] == fastest) {
                    --m_index[u];
                    m_limitedBy[u] = failing->label();
                }
            }
        }
    }

    const PlanningProblem &m_problem;
    std::vector<double> m_feeds; // candidates, ascending
    std::size_t m_programmed = 0;
    std::vector<DeviationResult> m_deviations;
    std::vector<bool> m_limitsHold;
    std::vector<Unit> m_units;
    std::vector<std::size_t> m_index;
    std::vector<QString> m_limitedBy;
    std::vector<bool> m_pinned;
    QStringList m_kept;
};

} // namespace

QMap<QString, double> FeedSchedule::feedByFeature() const
{
    QMap<QString, double> out;
    for (const ScheduledFeed &f : features)
        out.insert(f.featureId, f.feed_mm_rev);
    return out;
}

FeedSchedule scheduleFinishingFeeds(const PlanningProblem &problem, const CuttingPass &finishing)
{
    if (!(finishing.feed_mm_rev > 0.0)) {
        FeedSchedule s;
        s.diagnostics.push_back(
            makeError(QStringLiteral("passes"), FeedScheduleText::tr("the plan has no finishing pass")));
        return s;
    }
    const std::shared_ptr<const PlanningProblem> pass = problem.forFinishingDepth(finishing.depthOfCut_mm);
    Scheduler scheduler(*pass, finishing);
    FeedSchedule s = scheduler.run(finishing);
    s.notes << FeedScheduleText::tr("Feeds from %1 to %2 mm/rev in steps of %3 mm/rev (the plan's feed range), each "
                                    "feature's the largest that holds its tolerances and the finishing pass's limits; "
                                    "the bores keep the programmed feed.")
                   .arg(QString::number(problem.feedRange().min, 'f', 3),
                        QString::number(problem.feedRange().max, 'f', 3),
                        QString::number(kProgramFeedStep_mm_rev, 'f', 3));
    return s;
}

FeedSchedule scheduleProjectFinishingFeeds(const Project &project, const DataLibrary &data,
                                           std::shared_ptr<const LoadedModel> learned)
{
    FeedSchedule s;
    const auto finishing = std::find_if(project.passes.rbegin(), project.passes.rend(),
                                        [](const CuttingPass &p) { return p.kind == PassKind::Finishing; });
    if (finishing == project.passes.rend()) {
        s.diagnostics.push_back(
            makeError(QStringLiteral("passes"), FeedScheduleText::tr("the plan has no finishing pass")));
        return s;
    }
    PlanningProblem::BuildResult built =
        PlanningProblem::build(project, data, StiffnessEnd::Compliant, std::move(learned));
    if (!built.problem) {
        s.diagnostics = std::move(built.diagnostics);
        return s;
    }
    s = scheduleFinishingFeeds(*built.problem, *finishing);
    s.diagnostics.insert(s.diagnostics.begin(), built.diagnostics.begin(), built.diagnostics.end());
    return s;
}

DeviationResult scheduledDeviation(const FeedSchedule &schedule, const DeviationResult &constantFeed)
{
    DeviationResult d = schedule.deviation;
    d.inputs = constantFeed.inputs; // the program is generated from the same inputs as without the schedule
    d.diagnostics = constantFeed.diagnostics;
    return d;
}

double outerFinishingTime_min(const std::vector<PassSummary> &passes)
{
    double t = 0.0;
    for (const PassSummary &p : passes)
        if (p.kind == PassKind::Finishing && p.side == ContourSide::Outer)
            t += p.time_min;
    return t;
}

double outerRoughingTime_min(const std::vector<PassSummary> &passes)
{
    double t = 0.0;
    for (const PassSummary &p : passes)
        if (p.kind == PassKind::Roughing && p.side == ContourSide::Outer)
            t += p.time_min;
    return t;
}

namespace {

// The largest depth a pass cuts between z0 and z1 (its samples and the ends).
double deepestCut(const PassDepthProfile &pass, double z0, double z1)
{
    const double lo = std::min(z0, z1);
    const double hi = std::max(z0, z1);
    double deepest = std::max(pass.depthAt(lo), pass.depthAt(hi));
    for (std::size_t i = 0; i < pass.z_mm.size(); ++i)
        if (pass.z_mm[i] > lo && pass.z_mm[i] < hi)
            deepest = std::max(deepest, pass.depth_mm[i]);
    return deepest;
}

// The largest feed in [f0, fMax] at which the resultant force at depth a is at most `force_N`.
double feedForForce(const ForceFunction &forces, double a, double force_N, double f0, double fMax)
{
    const auto resultant = [&](double f) { return resultant_N(forces(f, a)); };
    if (resultant(fMax) <= force_N)
        return fMax;
    double lo = f0;
    double hi = fMax;
    for (int i = 0; i < 40; ++i)
        (resultant(0.5 * (lo + hi)) <= force_N ? lo : hi) = 0.5 * (lo + hi);
    return lo;
}

} // namespace

int scheduleRoughingFeeds(const Project &project, const ForceFunction &forces, double maxFeed_mm_rev,
                          std::vector<PassPath> &roughing)
{
    constexpr double kShortestMove_mm = 0.1; // shorter moves along z are corners, not cuts
    const std::vector<PassDepthProfile> depths = passDepthProfiles(project, 0.0, 0.05);
    int scheduled = 0;
    std::size_t profile = 0;
    for (PassPath &pass : roughing) {
        while (profile < depths.size() && depths[profile].conditions.kind != PassKind::Roughing)
            ++profile;
        if (profile >= depths.size())
            break;
        const PassDepthProfile &depth = depths[profile++];
        const double f0 = pass.conditions.feed_mm_rev;
        if (!(maxFeed_mm_rev > f0))
            continue;
        const CuttingForces planned = forces(f0, pass.conditions.depthOfCut_mm);
        const double force = resultant_N(planned);
        std::optional<ProfilePoint> at;
        for (ToolMove &m : pass.moves) {
            const std::optional<ProfilePoint> from = at;
            at = m.to;
            // Along z only: a plunge or a climb (up a cone, over a radius) starts in the full corner.
            if (m.kind != MoveKind::Feed || !from || std::abs(m.to.z_mm - from->z_mm) < kShortestMove_mm ||
                std::abs(m.to.r_mm - from->r_mm) > 1e-3)
                continue;
            const double a = deepestCut(depth, from->z_mm, m.to.z_mm);
            if (a >= pass.conditions.depthOfCut_mm - 1e-9)
                continue; // the full depth: the programmed feed
            const double f = a > 1e-6 ? feedForForce(forces, a, force, f0, maxFeed_mm_rev) : maxFeed_mm_rev;
            const double rounded = std::floor(f / kProgramFeedStep_mm_rev + 1e-9) * kProgramFeedStep_mm_rev;
            if (rounded > f0 + 1e-9) {
                m.feed_mm_rev = rounded;
                ++scheduled;
            }
        }
    }
    return scheduled;
}

} // namespace tolturn
