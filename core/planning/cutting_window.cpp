// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/cutting_window.h"

#include <algorithm>
#include <atomic>
#include <map>
#include <memory>
#include <thread>

namespace tolturn {

std::vector<std::pair<QString, int>> CuttingWindow::boundaries() const
{
    std::map<QString, int> count;
    for (const WindowCell &c : cells) {
        if (!c.feasible)
            ++count[c.bindingLabel];
    }
    std::vector<std::pair<QString, int>> out(count.begin(), count.end());
    std::sort(out.begin(), out.end(), [](const auto &a, const auto &b) { return a.second > b.second; });
    return out;
}

namespace {

double lerp(const ValueRange &r, int i, int n)
{
    return n <= 1 ? r.min : r.min + (r.max - r.min) * static_cast<double>(i) / static_cast<double>(n - 1);
}

void fillColumns(const PlanningProblem &problem, CuttingWindow &w, int firstColumn, int step,
                 const WindowOptions &options, std::atomic<int> &done, std::atomic<bool> &cancel)
{
    for (int column = firstColumn; column < w.columns && !cancel; column += step) {
        const double feed = lerp(w.feed, column, w.columns);
        // In the feed–speed plane the tolerance constraints depend on the feed only, unless the
        // thermal drift or a learned residual brings in the spindle speed: then once per column.
        const bool perColumn = w.plane == WindowPlane::FeedSpeed && !problem.tolerancesDependOnCuttingSpeed();
        std::vector<ConstraintValue> tolerances;
        if (perColumn) {
            PassConditions pass = w.base.finishing;
            pass.feed_mm_rev = feed;
            tolerances = problem.toleranceConstraints(pass);
        }
        for (int row = 0; row < w.rows; ++row) {
            PlanCandidate c = w.base;
            c.finishing.feed_mm_rev = feed;
            const double y = lerp(w.other, row, w.rows);
            if (w.plane == WindowPlane::FeedSpeed)
                c.finishing.cuttingSpeed_m_min = y;
            else
                c.finishing.depthOfCut_mm = y;
            const CandidateEvaluation e = problem.evaluate(c, perColumn ? &tolerances : nullptr);
            WindowCell &cell = w.cells[static_cast<std::size_t>(row) * static_cast<std::size_t>(w.columns) +
                                       static_cast<std::size_t>(column)];
            cell.x = feed;
            cell.y = y;
            cell.objective = e.objective;
            cell.feasible = e.feasible(1e-9);
            if (!cell.feasible) {
                const ConstraintValue *worst = e.mostViolated();
                cell.binding = worst->name;
                cell.bindingLabel = worst->label();
            }
        }
        const int finished = ++done;
        if (firstColumn == 0 && !options.progress.report(double(finished) / w.columns))
            cancel = true;
    }
}

} // namespace

CuttingWindow cuttingWindow(const PlanningProblem &problem, WindowPlane plane, const PlanCandidate &base,
                            const WindowOptions &options)
{
    CuttingWindow w;
    w.plane = plane;
    w.columns = std::max(options.columns, 2);
    w.rows = std::max(options.rows, 2);
    w.feed = problem.feedRange();
    w.other = plane == WindowPlane::FeedSpeed ? problem.speedRange() : problem.depthRange();
    w.base = base;
    w.cells.resize(static_cast<std::size_t>(w.columns) * static_cast<std::size_t>(w.rows));
    // In the feed–speed plane every point cuts at the base's depth: its tolerances on the section
    // that depth leaves, as the optimum's are (optimiser.cpp, checkAtItsOwnDepth). The feed–depth
    // plane keeps the search's table of the smallest depth.
    std::shared_ptr<const PlanningProblem> atDepth;
    if (plane == WindowPlane::FeedSpeed)
        atDepth = problem.forFinishingDepth(base.finishing.depthOfCut_mm);
    const PlanningProblem &judged = atDepth ? *atDepth : problem;
    std::atomic<int> done{0};
    std::atomic<bool> cancel{false};
    const int threads = std::max(1, options.threads);
    std::vector<std::thread> workers;
    for (int t = 1; t < threads; ++t)
        workers.emplace_back(fillColumns, std::cref(judged), std::ref(w), t, threads, std::cref(options),
                             std::ref(done), std::ref(cancel));
    fillColumns(judged, w, 0, threads, options, done, cancel);
    for (std::thread &t : workers)
        t.join();
    w.cancelled = cancel;
    return w;
}

} // namespace tolturn
