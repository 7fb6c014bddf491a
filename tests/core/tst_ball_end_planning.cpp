// SPDX-License-Identifier: GPL-3.0-or-later
// Planning a five-axis ball-end cut against the tolerance of its surface (issue 19,
// docs/milling.md): the form error of a floating and a located zone (ISO 1101) by hand, the
// largest feed per tooth in closed form, and the lead–tilt window and plan against the model run
// again at what they return.
#include "core/milling/ball_end_planning.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace tolturn;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

// Test coefficients of the order of a titanium alloy's; the tool of 001 with its holder springs, a
// Ø9.6 mm carbide cylinder 40 mm out.
const MillingForceCoefficients kCoefficients{2000.0, 700.0, 400.0, 25.0, 40.0, 8.0};
const BallEndToolStructure kTool{40.0, 9.6, 630000.0, 6306.0, 1.656e7};
const BallEndMill kMill{12.0, 2, 30.0 * kDegree};

BallEndCut stepOverCut()
{
    BallEndCut cut;
    cut.kind = BallEndCutKind::StepOver;
    cut.radialDepth_mm = 1.0;
    cut.axialDepth_mm = 0.5;
    cut.feedPerTooth_mm = 0.05;
    return cut;
}

BallEndPlanSettings settings(int cells)
{
    BallEndPlanSettings s;
    s.leadLowest_rad = -40.0 * kDegree;
    s.leadHighest_rad = 40.0 * kDegree;
    s.tiltLowest_rad = -40.0 * kDegree;
    s.tiltHighest_rad = 40.0 * kDegree;
    s.highestFeedPerTooth_mm = 0.3;
    s.columns = cells;
    s.rows = cells;
    s.windowResolution = {60, 120};
    s.planResolution = {200, 360};
    return s;
}

// The normal error the model gives at a cut, recomputed from scratch: N row of T times δ.
std::vector<double> normalErrors(const BallEndCut &cut, const BallEndResolution &resolution)
{
    std::vector<double> errors;
    for (const BallEndDeflectionSample &d : ballEndDeflection(kMill, kTool, kCoefficients, cut, resolution).deflection)
        errors.push_back(d.surfaceNormal_mm());
    return errors;
}

double spread(const std::vector<double> &v)
{
    return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
}

} // namespace

class TestBallEndPlanning : public QObject {
    Q_OBJECT

private Q_SLOTS:

    // Where a cut lies beyond 001, said beside its result. The tip cuts where the engaged band
    // reaches it: θ ≤ γ, θ = acos(cos lead cos tilt), γ = acos(1 − a/R_o) = acos(1 − 0.5/6) = 23.6°;
    // at lead 10°, tilt 10° (θ = 14.1°) it does, at 30°, 0° it does not. A negative lead drills
    // (001 §5). 001's holder springs hold under 1000 N of lateral force (001 §4): the peak of
    // hypot(F_x, F_y) over the revolution, taken here from the forces, decides; at a feed of 0.3
    // mm/tooth in a 3 mm slot it is above, at 0.02 mm/tooth in the 0.5 mm step-over below, and
    // another holder's springs carry no such limit.
    void cutsBeyond001AreSaid()
    {
        const auto warnings = [](const BallEndToolStructure &tool, const BallEndCut &cut) {
            const BallEndDeflection d = ballEndDeflection(kMill, tool, kCoefficients, cut, {60, 120});
            double peak = 0.0;
            for (const BallEndForceSample &f : d.forces)
                peak = std::max(peak, std::hypot(f.toolFrame_N.x(), f.toolFrame_N.y()));
            return std::make_pair(ballEndValidityWarnings(kMill, tool, cut, d).join(QLatin1Char('\n')), peak);
        };
        BallEndCut cut = stepOverCut();
        cut.feedPerTooth_mm = 0.02;
        cut.lead_rad = 10.0 * kDegree;
        cut.tilt_rad = 10.0 * kDegree;
        const auto [tip, lowPeak] = warnings(kTool, cut);
        QVERIFY2(tip.contains(QStringLiteral("the tip of the ball")), qPrintable(tip));
        QVERIFY(!tip.contains(QStringLiteral("lead is negative")));
        QVERIFY(lowPeak < 1000.0 && !tip.contains(QStringLiteral("1000 N")));
        cut.lead_rad = 30.0 * kDegree;
        cut.tilt_rad = 0.0;
        QVERIFY(warnings(kTool, cut).first.isEmpty());
        cut.lead_rad = -30.0 * kDegree;
        QVERIFY(warnings(kTool, cut).first.contains(QStringLiteral("the lead is negative (-30.0°)")));

        BallEndCut slot;
        slot.kind = BallEndCutKind::Slot;
        slot.axialDepth_mm = 3.0;
        slot.feedPerTooth_mm = 0.3;
        slot.lead_rad = 30.0 * kDegree;
        const auto [heavy, highPeak] = warnings(kTool, slot);
        QVERIFY2(highPeak > 1000.0, qPrintable(QString::number(highPeak)));
        QVERIFY2(heavy.contains(QStringLiteral("beyond the 1000 N")), qPrintable(heavy));
        BallEndToolStructure ownHolder = kTool;
        ownHolder.holderStiffness_N_mm = 2.0e4;
        QVERIFY(!warnings(ownHolder, slot).first.contains(QStringLiteral("1000 N")));
    }

    // δ_N = base + f · perFeed at f = 0.1: {1 + 0.1·10, −2 + 0.1·20, 0.5 − 0.1·30} = {2, 0, −2.5} µm.
    // Floating: the spread 2 − (−2.5) = 4.5 µm; located: 2 · max |δ_N| = 5 µm.
    void formErrorByHand()
    {
        const SurfaceErrorLine line{{1e-3, -2e-3, 0.5e-3}, {10e-3, 20e-3, -30e-3}};
        QVERIFY(std::abs(formError_mm(line, 0.1, SurfaceZone::Floating) - 4.5e-3) < 1e-15);
        QVERIFY(std::abs(formError_mm(line, 0.1, SurfaceZone::Located) - 5e-3) < 1e-15);
    }

    // base = {1, −1} µm, perFeed = {40, −60} µm/mm: the spread is 2 + 100 f µm, within 10 µm up to
    // f = 0.08 mm; located, 2 max(|1 + 40 f|, |−1 − 60 f|) = 2 + 120 f ≤ 10 up to
    // f = 1/15 mm. A tolerance under the
    // edge forces' own 2 µm spread holds at no feed; a loose one holds at the highest.
    void largestFeedInClosedForm()
    {
        const SurfaceErrorLine line{{1e-3, -1e-3}, {40e-3, -60e-3}};
        const double floating = largestFeedPerTooth_mm(line, {10e-3, SurfaceZone::Floating}, 0.3);
        QVERIFY2(std::abs(floating - 0.08) < 1e-12, qPrintable(QString::number(floating, 'g', 15)));
        QVERIFY(std::abs(largestFeedPerTooth_mm(line, {10e-3, SurfaceZone::Located}, 0.3) - 1.0 / 15.0) < 1e-12);
        QCOMPARE(largestFeedPerTooth_mm(line, {1.5e-3, SurfaceZone::Floating}, 0.3), 0.0);
        QCOMPARE(largestFeedPerTooth_mm(line, {1.0, SurfaceZone::Floating}, 0.3), 0.3);

        // Edge and cutting parts that offset: base = {3, −3} µm, perFeed = {−40, 40} µm/mm, spread
        // |6 − 80 f| µm, within 2 µm for f in [0.05, 0.1] only: the largest is 0.1 mm though f = 0
        // fails; under a highest feed of 0.07 mm, 0.07 mm; 0.1 µm holds only for f in [0.07375, 0.07625],
        // above a highest of 0.07 mm: none.
        const SurfaceErrorLine offsetting{{3e-3, -3e-3}, {-40e-3, 40e-3}};
        const double offset = largestFeedPerTooth_mm(offsetting, {2e-3, SurfaceZone::Floating}, 0.3);
        QVERIFY2(std::abs(offset - 0.1) < 1e-9, qPrintable(QString::number(offset, 'g', 15)));
        QCOMPARE(largestFeedPerTooth_mm(offsetting, {2e-3, SurfaceZone::Floating}, 0.07), 0.07);
        QCOMPARE(largestFeedPerTooth_mm(offsetting, {1e-4, SurfaceZone::Floating}, 0.07), 0.0);
    }

    // What the window does not take is refused before any thread starts, as an exception the caller
    // can catch (in a worker thread it would end the program); bounds of exactly ±60° are taken,
    // the last column exactly at 60°.
    void windowRefusesBadInputs()
    {
        const MilledSurfaceTolerance tolerance{0.010, SurfaceZone::Floating};
        BallEndPlanSettings wide = settings(64);
        wide.leadHighest_rad = 70.0 * kDegree;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 (void)leadTiltWindow(kMill, kTool, kCoefficients, stepOverCut(), tolerance, wide));
        BallEndToolStructure noOverhang = kTool;
        noOverhang.overhang_mm = 0.0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)leadTiltWindow(kMill, noOverhang, kCoefficients,
                                                                             stepOverCut(), tolerance, settings(4)));
        BallEndPlanSettings sixty = settings(64);
        sixty.leadLowest_rad = sixty.tiltLowest_rad = -std::numbers::pi / 3.0;
        sixty.leadHighest_rad = sixty.tiltHighest_rad = std::numbers::pi / 3.0;
        sixty.windowResolution = {4, 8};
        BallEndCut shallow = stepOverCut();
        shallow.axialDepth_mm = 0.2;
        shallow.feedPerTooth_mm = 0.0; // not used by the window
        const LeadTiltWindow w = leadTiltWindow(kMill, kTool, kCoefficients, shallow, tolerance, sixty);
        QCOMPARE(w.at(63, 63).lead_rad, std::numbers::pi / 3.0);
        QCOMPARE(w.at(63, 63).tilt_rad, std::numbers::pi / 3.0);
    }

    // Cells of the window against the model run again at their largest feed: the spread of δ_N is
    // the tolerance where the feed is bound, and 2 % more feed breaks it. Off the ball: a 40°/40°
    // tool is inclined θ = acos(cos² 40°) = 54.1°, so the ball reaches 6 (1 − sin θ) = 1.14 mm deep,
    // short of a 1.5 mm cut.
    void windowCellsHoldTheTolerance()
    {
        BallEndCut cut = stepOverCut();
        cut.axialDepth_mm = 1.5;
        const MilledSurfaceTolerance tolerance{0.020, SurfaceZone::Floating};
        const LeadTiltWindow window = leadTiltWindow(kMill, kTool, kCoefficients, cut, tolerance, settings(5));
        QCOMPARE(window.cells.size(), std::size_t(25));
        int bound = 0;
        for (const LeadTiltCell &cell : window.cells) {
            const double inclination = std::acos(std::cos(cell.lead_rad) * std::cos(cell.tilt_rad));
            QCOMPARE(cell.onBall, 1.5 <= 6.0 * (1.0 - std::sin(inclination)));
            if (!cell.onBall || cell.largestFeed_mm <= 0.0 || cell.largestFeed_mm >= 0.3)
                continue;
            BallEndCut at = cut;
            at.lead_rad = cell.lead_rad;
            at.tilt_rad = cell.tilt_rad;
            at.feedPerTooth_mm = cell.largestFeed_mm;
            QVERIFY(std::abs(spread(normalErrors(at, {60, 120})) - 0.020) < 1e-9);
            at.feedPerTooth_mm *= 1.02;
            QVERIFY(spread(normalErrors(at, {60, 120})) > 0.020);
            ++bound;
        }
        QVERIFY(bound > 0);
        QVERIFY(!window.cells.front().onBall); // lead −40°, tilt −40°
    }

    // The plan: its feed holds the tolerance at the plan's resolution, run again from scratch, and
    // no cell of the window offers a larger feed (a thousandth for the resolutions' difference).
    // A located zone of the same t asks at least as much as a floating one: its feed is no larger.
    void planIsTheFastestThatHolds()
    {
        const BallEndCut cut = stepOverCut();
        const MilledSurfaceTolerance tolerance{0.010, SurfaceZone::Floating};
        const BallEndPlan plan = planBallEndCut(kMill, kTool, kCoefficients, cut, 3000.0, tolerance, settings(9));
        QVERIFY(plan.feasible);
        QVERIFY(plan.cut.feedPerTooth_mm > 0.0);
        QVERIFY(spread(normalErrors(plan.cut, {200, 360})) <= 0.010 + 1e-12);
        QVERIFY(std::abs(plan.feedRate_mm_min - plan.cut.feedPerTooth_mm * 2 * 3000.0) < 1e-9);
        for (const LeadTiltCell &cell : plan.window.cells)
            QVERIFY2(cell.largestFeed_mm <= plan.cut.feedPerTooth_mm * 1.01,
                     qPrintable(QStringLiteral("cell %1°, %2°: %3 mm against the plan's %4 mm")
                                    .arg(cell.lead_rad / kDegree)
                                    .arg(cell.tilt_rad / kDegree)
                                    .arg(cell.largestFeed_mm)
                                    .arg(plan.cut.feedPerTooth_mm)));
        const BallEndPlan located =
            planBallEndCut(kMill, kTool, kCoefficients, cut, 3000.0, {0.010, SurfaceZone::Located}, settings(9));
        QVERIFY(located.cut.feedPerTooth_mm <= plan.cut.feedPerTooth_mm * 1.001);
        const std::vector<double> errors = normalErrors(located.cut, {200, 360});
        for (const double e : errors)
            QVERIFY(std::abs(e) <= 0.005 + 1e-12);
    }

    // The refinement: from a 3 × 3 grid, Subplex reaches within 1 % of the best feed a 21 × 21 grid
    // of the same bounds finds, where the 3 × 3 grid's own best cell is short of it. The bounds keep
    // away from lead = tilt = 0, where the bending is all in the F–C plane and only the tool's
    // compression moves the surface: every feed holds there.
    void refinementFindsWhatTheGridMisses()
    {
        const BallEndCut cut = stepOverCut();
        const MilledSurfaceTolerance tolerance{0.004, SurfaceZone::Floating};
        const auto bestFeed = [](const LeadTiltWindow &w) {
            double best = 0.0;
            for (const LeadTiltCell &c : w.cells)
                best = std::max(best, c.largestFeed_mm);
            return best;
        };
        const auto within = [](int cells) {
            BallEndPlanSettings s = settings(cells);
            s.leadLowest_rad = 5.0 * kDegree;
            s.tiltLowest_rad = 5.0 * kDegree;
            s.planResolution = s.windowResolution;
            return s;
        };
        const BallEndPlan plan = planBallEndCut(kMill, kTool, kCoefficients, cut, 3000.0, tolerance, within(3));
        const double fine = bestFeed(leadTiltWindow(kMill, kTool, kCoefficients, cut, tolerance, within(21)));
        QVERIFY2(bestFeed(plan.window) < 0.99 * fine,
                 qPrintable(QStringLiteral("%1 %2").arg(bestFeed(plan.window)).arg(fine)));
        QVERIFY2(plan.cut.feedPerTooth_mm >= 0.99 * fine,
                 qPrintable(QStringLiteral("plan %1 mm, 21 × 21 grid %2 mm after %3 evaluations")
                                .arg(plan.cut.feedPerTooth_mm)
                                .arg(fine)
                                .arg(plan.evaluations)));
    }
};

QTEST_GUILESS_MAIN(TestBallEndPlanning)
#include "tst_ball_end_planning.moc"
