// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/milling/ball_end_planning.h"

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <stdexcept>
#include <thread>

namespace tolturn {

namespace {

// Bisection steps for the largest feed: 2⁻⁶⁰ of the feed range, well below any feed a machine takes.
constexpr int kBisectionSteps = 60;

struct CellResult {
    bool onBall = false;
    double largestFeed_mm = 0.0;
    double formError_mm = 0.0; // at that feed
};

CellResult evaluateCell(const BallEndMill &mill, const BallEndToolStructure &tool, const MillingForceCoefficients &k,
                        BallEndCut cut, double lead_rad, double tilt_rad, const MilledSurfaceTolerance &tolerance,
                        double highestFeed_mm, const BallEndResolution &resolution)
{
    cut.lead_rad = lead_rad;
    cut.tilt_rad = tilt_rad;
    cut.feedPerTooth_mm = highestFeed_mm; // any feed: the error line does not depend on it
    CellResult r;
    if (cut.axialDepth_mm > deepestCutOnBall_mm(mill.diameter_mm, lead_rad, tilt_rad))
        return r;
    r.onBall = true;
    const SurfaceErrorLine line = surfaceErrorLine(ballEndDeflection(mill, tool, k, cut, resolution), cut);
    r.largestFeed_mm = largestFeedPerTooth_mm(line, tolerance, highestFeed_mm);
    r.formError_mm = formError_mm(line, r.largestFeed_mm, tolerance.zone);
    return r;
}

// The planning objective, to be minimised: the feed as a share of the highest, less; then, between
// equal feeds (at the highest), the form error as a share of the tolerance, a thousandth as much.
double planObjective(const CellResult &r, const MilledSurfaceTolerance &tolerance, double highestFeed_mm)
{
    if (!r.onBall)
        return 1.0;
    return -r.largestFeed_mm / highestFeed_mm + 1e-3 * r.formError_mm / tolerance.tolerance_mm;
}

void fillRows(const BallEndMill &mill, const BallEndToolStructure &tool, const MillingForceCoefficients &k,
              const BallEndCut &cut, const MilledSurfaceTolerance &tolerance, const BallEndPlanSettings &settings,
              LeadTiltWindow &window, int firstRow, std::exception_ptr &failure)
{
    try {
        for (int row = firstRow; row < window.rows; row += std::max(1, settings.threads))
            for (int column = 0; column < window.columns; ++column) {
                LeadTiltCell &cell = window.at(column, row);
                const CellResult r = evaluateCell(mill, tool, k, cut, cell.lead_rad, cell.tilt_rad, tolerance,
                                                  settings.highestFeedPerTooth_mm, settings.windowResolution);
                cell.onBall = r.onBall;
                cell.largestFeed_mm = r.largestFeed_mm;
                cell.formError_mm = r.formError_mm;
            }
    } catch (...) {
        failure = std::current_exception(); // rethrown by the caller once every thread has joined
    }
}

using LeadTiltObjective = std::function<double(const std::vector<double> &)>;

// NLopt's Subplex from `start` within the settings' bounds; the start stands unless it finds better.
std::vector<double> refineLeadTilt(const LeadTiltObjective &objective, const std::vector<double> &start,
                                   double startValue, const BallEndPlanSettings &settings, int &evaluations)
{
    struct Counted {
        const LeadTiltObjective &objective;
        int &evaluations;
    } counted{objective, evaluations};

    nlopt::opt opt(nlopt::LN_SBPLX, 2);
    opt.set_lower_bounds({settings.leadLowest_rad, settings.tiltLowest_rad});
    opt.set_upper_bounds({settings.leadHighest_rad, settings.tiltHighest_rad});
    opt.set_maxeval(settings.maxEvaluations);
    opt.set_xtol_abs(1e-4);
    opt.set_initial_step({(settings.leadHighest_rad - settings.leadLowest_rad) / settings.columns,
                          (settings.tiltHighest_rad - settings.tiltLowest_rad) / settings.rows});
    opt.set_min_objective(
        [](unsigned, const double *x, double *, void *data) {
            auto *c = static_cast<Counted *>(data);
            ++c->evaluations;
            return c->objective({x[0], x[1]});
        },
        &counted);
    std::vector<double> x = start;
    double value = startValue;
    try {
        opt.optimize(x, value);
    } catch (const std::exception &) {
        return start; // NLopt stops on a round-off or budget error: the start stands
    }
    return value < startValue ? x : start;
}

// The index-th of `count` values from `lowest` to `highest`, the last exactly `highest` (rounding must
// not carry it past a bound the model checks).
double gridValue(double lowest, double highest, int index, int count)
{
    return index >= count - 1 ? highest : lowest + (highest - lowest) * index / std::max(1, count - 1);
}

// What the window cannot take, before any thread starts: a problem in a worker would end the program.
void validateWindowInputs(const BallEndMill &mill, const BallEndToolStructure &tool, const BallEndCut &cut,
                          const MilledSurfaceTolerance &tolerance, const BallEndPlanSettings &settings)
{
    constexpr double kSixtyDegrees = 1.0471975511965976;
    const bool bounds = settings.leadLowest_rad >= -kSixtyDegrees && settings.leadHighest_rad <= kSixtyDegrees &&
                        settings.tiltLowest_rad >= -kSixtyDegrees && settings.tiltHighest_rad <= kSixtyDegrees &&
                        settings.leadLowest_rad <= settings.leadHighest_rad &&
                        settings.tiltLowest_rad <= settings.tiltHighest_rad;
    if (!(tolerance.tolerance_mm > 0.0) || !(settings.highestFeedPerTooth_mm > 0.0) || settings.columns < 2 ||
        settings.rows < 2 || settings.threads < 1 || settings.maxEvaluations < 1 || !bounds)
        throw std::invalid_argument("leadTiltWindow: a positive tolerance and highest feed, a 2 × 2 grid at least, "
                                    "a thread, an evaluation, and lead and tilt bounds within ±60°");
    // The cut as every cell takes it, at the inclination where the ball reaches deepest.
    BallEndCut probe = cut;
    probe.lead_rad = probe.tilt_rad = 0.0;
    probe.feedPerTooth_mm = settings.highestFeedPerTooth_mm;
    probe.axialDepth_mm = std::min(cut.axialDepth_mm, 0.5 * mill.diameter_mm);
    for (const BallEndResolution &r : {settings.windowResolution, settings.planResolution})
        if (const auto problems = validateBallEndCut(mill, probe, r); !problems.empty())
            throw std::invalid_argument(problems.front());
    if (const auto problems = validateToolStructure(tool, mill); !problems.empty())
        throw std::invalid_argument(problems.front());
}

} // namespace

SurfaceErrorLine surfaceErrorLine(const BallEndDeflection &deflection, const BallEndCut &cut)
{
    // δ_N is the N row of T times δ (001 §4); δ = δ(f_t) + (f − f_t) · δ per feed.
    const Eigen::RowVector3d normalRow = leadTiltTransform(cut.lead_rad, cut.tilt_rad).row(2);
    SurfaceErrorLine line;
    line.base_mm.reserve(deflection.forces.size());
    line.perFeed_mm_mm.reserve(deflection.forces.size());
    for (const BallEndForceSample &s : deflection.forces) {
        const double perFeed = normalRow.dot(s.deflectionPerFeed_mm_mm);
        line.perFeed_mm_mm.push_back(perFeed);
        line.base_mm.push_back(normalRow.dot(s.deflection_mm) - cut.feedPerTooth_mm * perFeed);
    }
    return line;
}

double formError_mm(const SurfaceErrorLine &line, double feedPerTooth_mm, SurfaceZone zone)
{
    if (line.base_mm.empty())
        return 0.0;
    double least = line.base_mm.front() + feedPerTooth_mm * line.perFeed_mm_mm.front();
    double greatest = least;
    for (std::size_t m = 0; m < line.base_mm.size(); ++m) {
        const double v = line.base_mm[m] + feedPerTooth_mm * line.perFeed_mm_mm[m];
        if (!std::isfinite(v))
            return std::nan(""); // decides nothing: std::min and std::max would pass over it
        least = std::min(least, v);
        greatest = std::max(greatest, v);
    }
    // ISO 1101: a floating zone takes the spread, a located one ±t/2 about the programmed surface.
    return zone == SurfaceZone::Floating ? greatest - least : 2.0 * std::max(std::abs(least), std::abs(greatest));
}

double largestFeedPerTooth_mm(const SurfaceErrorLine &line, const MilledSurfaceTolerance &tolerance,
                              double highestFeed_mm)
{
    const auto error = [&](double feed) { return formError_mm(line, feed, tolerance.zone); };
    const auto holds = [&](double feed) { return error(feed) <= tolerance.tolerance_mm; };
    if (holds(highestFeed_mm))
        return highestFeed_mm;
    // The feeds that hold are an interval (the error is convex in the feed). Where the edge forces'
    // error and the cutting forces' offset each other it does not start at 0: its least error is
    // found first (ternary search on the convex error), then its upper end by bisection.
    double low = 0.0;
    double high = highestFeed_mm;
    for (int i = 0; i < kBisectionSteps; ++i) {
        const double a = low + (high - low) / 3.0;
        const double b = high - (high - low) / 3.0;
        const bool leftLower = error(a) <= error(b);
        (leftLower ? high : low) = leftLower ? b : a;
    }
    const double least = holds(0.0) ? 0.0 : 0.5 * (low + high);
    if (!holds(least))
        return 0.0;
    low = least;
    high = highestFeed_mm;
    for (int i = 0; i < kBisectionSteps; ++i) {
        const double middle = 0.5 * (low + high);
        (holds(middle) ? low : high) = middle;
    }
    return low;
}

LeadTiltWindow leadTiltWindow(const BallEndMill &mill, const BallEndToolStructure &tool,
                              const MillingForceCoefficients &coefficients, const BallEndCut &cut,
                              const MilledSurfaceTolerance &tolerance, const BallEndPlanSettings &settings)
{
    validateWindowInputs(mill, tool, cut, tolerance, settings);
    LeadTiltWindow window;
    window.columns = settings.columns;
    window.rows = settings.rows;
    window.cells.resize(static_cast<std::size_t>(window.columns) * static_cast<std::size_t>(window.rows));
    for (int row = 0; row < window.rows; ++row)
        for (int column = 0; column < window.columns; ++column) {
            LeadTiltCell &cell = window.at(column, row);
            cell.lead_rad = gridValue(settings.leadLowest_rad, settings.leadHighest_rad, column, window.columns);
            cell.tilt_rad = gridValue(settings.tiltLowest_rad, settings.tiltHighest_rad, row, window.rows);
        }
    std::vector<std::exception_ptr> failures(static_cast<std::size_t>(settings.threads));
    std::vector<std::thread> workers;
    for (int t = 1; t < settings.threads; ++t)
        workers.emplace_back(fillRows, std::cref(mill), std::cref(tool), std::cref(coefficients), std::cref(cut),
                             std::cref(tolerance), std::cref(settings), std::ref(window), t,
                             std::ref(failures[static_cast<std::size_t>(t)]));
    fillRows(mill, tool, coefficients, cut, tolerance, settings, window, 0, failures.front());
    for (std::thread &t : workers)
        t.join();
    for (const std::exception_ptr &failure : failures)
        if (failure)
            std::rethrow_exception(failure);
    return window;
}

BallEndPlan planBallEndCut(const BallEndMill &mill, const BallEndToolStructure &tool,
                           const MillingForceCoefficients &coefficients, const BallEndCut &cut, double spindle_rpm,
                           const MilledSurfaceTolerance &tolerance, const BallEndPlanSettings &settings)
{
    BallEndPlan plan;
    plan.window = leadTiltWindow(mill, tool, coefficients, cut, tolerance, settings);
    const double highest = settings.highestFeedPerTooth_mm;
    const auto cellObjective = [&](const LeadTiltCell &c) {
        const double value = planObjective({c.onBall, c.largestFeed_mm, c.formError_mm}, tolerance, highest);
        return std::isnan(value) ? std::numeric_limits<double>::infinity() : value; // keeps min_element's order
    };
    const auto best = std::min_element(
        plan.window.cells.begin(), plan.window.cells.end(),
        [&](const LeadTiltCell &a, const LeadTiltCell &b) { return cellObjective(a) < cellObjective(b); });
    std::vector<double> angles{best->lead_rad, best->tilt_rad};
    if (best->onBall && best->largestFeed_mm > 0.0) {
        const LeadTiltObjective objective = [&](const std::vector<double> &x) {
            return planObjective(
                evaluateCell(mill, tool, coefficients, cut, x[0], x[1], tolerance, highest, settings.windowResolution),
                tolerance, highest);
        };
        angles = refineLeadTilt(objective, angles, cellObjective(*best), settings, plan.evaluations);
    }
    plan.cut = cut;
    plan.cut.lead_rad = angles[0];
    plan.cut.tilt_rad = angles[1];
    const CellResult checked =
        evaluateCell(mill, tool, coefficients, cut, angles[0], angles[1], tolerance, highest, settings.planResolution);
    plan.feasible = checked.onBall && checked.largestFeed_mm > 0.0;
    plan.cut.feedPerTooth_mm = checked.largestFeed_mm;
    plan.formError_mm = checked.formError_mm;
    plan.feedRate_mm_min = checked.largestFeed_mm * mill.flutes * spindle_rpm;
    if (plan.feasible)
        plan.warnings = ballEndValidityWarnings(
            mill, tool, plan.cut, ballEndDeflection(mill, tool, coefficients, plan.cut, settings.planResolution));
    return plan;
}

} // namespace tolturn
