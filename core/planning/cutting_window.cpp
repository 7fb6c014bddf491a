// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/cutting_window.h"

#include <algorithm>
#include <atomic>
#include <functional>
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

void fillCell(const PlanningProblem &problem, CuttingWindow &w, int column, int row,
              const std::vector<ConstraintValue> *tolerances)
{
    PlanCandidate c = w.base;
    c.finishing.feed_mm_rev = lerp(w.feed, column, w.columns);
    const double y = lerp(w.other, row, w.rows);
    if (w.plane == WindowPlane::FeedSpeed)
        c.finishing.cuttingSpeed_m_min = y;
    else
        c.finishing.depthOfCut_mm = y;
    const CandidateEvaluation e = problem.evaluate(c, tolerances);
    WindowCell &cell =
        w.cells[static_cast<std::size_t>(row) * static_cast<std::size_t>(w.columns) + static_cast<std::size_t>(column)];
    cell.x = c.finishing.feed_mm_rev;
    cell.y = y;
    cell.objective = e.objective;
    cell.feasible = e.feasible(1e-9);
    if (!cell.feasible) {
        const ConstraintValue *worst = e.mostViolated();
        cell.binding = worst->name;
        cell.bindingLabel = worst->label();
    }
}

// The feed–speed plane, a column (one feed) at a time: every point cuts at the base's depth, so
// its tolerances on the section that depth leaves (`atDepth`), as the optimum's are
// (optimiser.cpp, checkAtItsOwnDepth). They depend on the feed only, unless the thermal drift or a
// learned residual brings in the spindle speed: then once per column.
void fillFeedSpeedColumn(const PlanningProblem &atDepth, CuttingWindow &w, int column)
{
    const bool perColumn = !atDepth.tolerancesDependOnCuttingSpeed();
    std::vector<ConstraintValue> tolerances;
    if (perColumn) {
        PassConditions pass = w.base.finishing;
        pass.feed_mm_rev = lerp(w.feed, column, w.columns);
        tolerances = atDepth.toleranceConstraints(pass);
    }
    for (int row = 0; row < w.rows; ++row)
        fillCell(atDepth, w, column, row, perColumn ? &tolerances : nullptr);
}

// The feed–depth plane, a row (one depth) at a time: each depth judged on the section it leaves.
void fillFeedDepthRow(const PlanningProblem &problem, CuttingWindow &w, int row)
{
    const std::shared_ptr<const PlanningProblem> atDepth = problem.forFinishingDepth(lerp(w.other, row, w.rows));
    for (int column = 0; column < w.columns; ++column)
        fillCell(*atDepth, w, column, row, nullptr);
}

// Lines (columns or rows) first, first + step, …: one worker's share; the first reports progress.
void fillLines(const std::function<void(int)> &fillLine, int lines, int first, int step, const Progress &progress,
               std::atomic<int> &done, std::atomic<bool> &cancel)
{
    for (int line = first; line < lines && !cancel; line += step) {
        fillLine(line);
        const int finished = ++done;
        if (first == 0 && !progress.report(double(finished) / lines))
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
    std::shared_ptr<const PlanningProblem> atDepth;
    std::function<void(int)> fillLine;
    int lines = w.rows;
    if (plane == WindowPlane::FeedSpeed) {
        atDepth = problem.forFinishingDepth(base.finishing.depthOfCut_mm);
        fillLine = [&](int column) { fillFeedSpeedColumn(*atDepth, w, column); };
        lines = w.columns;
    } else {
        fillLine = [&](int row) { fillFeedDepthRow(problem, w, row); };
    }
    std::atomic<int> done{0};
    std::atomic<bool> cancel{false};
    const int threads = std::max(1, options.threads);
    std::vector<std::thread> workers;
    for (int t = 1; t < threads; ++t)
        workers.emplace_back(fillLines, std::cref(fillLine), lines, t, threads, std::cref(options.progress),
                             std::ref(done), std::ref(cancel));
    fillLines(fillLine, lines, 0, threads, options.progress, done, cancel);
    for (std::thread &t : workers)
        t.join();
    w.cancelled = cancel;
    return w;
}

} // namespace tolturn
