// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Planning a five-axis ball-end cut against the tolerance of the surface it leaves (issue 19;
// docs/milling.md): the surface error along the normal over a revolution (Öztürk & Budak §4), its
// form error against a flatness or profile tolerance (ISO 1101), the largest feed per tooth that
// holds it at each lead and tilt (the lead–tilt window), and the lead, tilt and feed of least
// machining time (NLopt).

#include "core/milling/ball_end_deflection.h"

#include <vector>

namespace tolturn {

// How the tolerance zone sits (ISO 1101): a flatness or a profile without datums floats, so the
// spread of the normal error must fit in t; a profile with datums is located on the programmed
// surface, so every normal error must lie within ±t/2.
enum class SurfaceZone { Floating, Located };

struct MilledSurfaceTolerance {
    double tolerance_mm = 0.0;
    SurfaceZone zone = SurfaceZone::Floating;
};

// δ_N over a revolution as an affine function of the feed per tooth: base + f · perFeed.
struct SurfaceErrorLine {
    std::vector<double> base_mm;
    std::vector<double> perFeed_mm_mm;
};

[[nodiscard]] SurfaceErrorLine surfaceErrorLine(const BallEndDeflection &deflection, const BallEndCut &cut);

// What the tolerance is compared with, at a feed per tooth: the spread max δ_N − min δ_N for a
// floating zone, 2 max |δ_N| for a located one; within tolerance when it is at most t.
[[nodiscard]] double formError_mm(const SurfaceErrorLine &line, double feedPerTooth_mm, SurfaceZone zone);

// The largest feed per tooth up to `highestFeed_mm` whose form error is within the tolerance; 0 when
// no feed up to it holds. The form error is convex in the feed (a maximum of affine functions), so
// the feeds that hold are an interval, which need not start at 0: the edge forces' error and the
// cutting forces' can offset each other.
[[nodiscard]] double largestFeedPerTooth_mm(const SurfaceErrorLine &line, const MilledSurfaceTolerance &tolerance,
                                            double highestFeed_mm);

struct BallEndPlanSettings {
    double leadLowest_rad = 0.0;
    double leadHighest_rad = 0.0;
    double tiltLowest_rad = 0.0;
    double tiltHighest_rad = 0.0;
    double highestFeedPerTooth_mm = 0.0; // what the tool's maker allows
    int columns = 64;                    // leads
    int rows = 64;                       // tilts
    BallEndResolution windowResolution{100, 180};
    BallEndResolution planResolution{200, 360};
    int threads = 2;
    int maxEvaluations = 200; // of the NLopt refinement
};

struct LeadTiltCell {
    double lead_rad = 0.0;
    double tilt_rad = 0.0;
    bool onBall = true;          // false: the axial depth reaches the shank at this inclination
    double largestFeed_mm = 0.0; // 0: no feed holds the tolerance
    double formError_mm = 0.0;   // at that feed
};

struct LeadTiltWindow {
    int columns = 0;
    int rows = 0;
    std::vector<LeadTiltCell> cells; // row-major: tilt by tilt, lead by lead

    [[nodiscard]] LeadTiltCell &at(int column, int row)
    {
        return cells[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                     static_cast<std::size_t>(column)];
    }

    [[nodiscard]] const LeadTiltCell &at(int column, int row) const
    {
        return cells[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                     static_cast<std::size_t>(column)];
    }
};

// The largest feed per tooth that holds the tolerance at each lead and tilt of a grid, at the
// window's resolution, on `threads` threads. The cut's own lead, tilt and feed are not used. Throws
// std::invalid_argument, before any thread starts, for what the model does not take.
[[nodiscard]] LeadTiltWindow leadTiltWindow(const BallEndMill &mill, const BallEndToolStructure &tool,
                                            const MillingForceCoefficients &coefficients, const BallEndCut &cut,
                                            const MilledSurfaceTolerance &tolerance,
                                            const BallEndPlanSettings &settings);

struct BallEndPlan {
    bool feasible = false;
    BallEndCut cut;            // the planned lead, tilt and feed per tooth
    double formError_mm = 0.0; // at the plan's resolution
    double feedRate_mm_min = 0.0;
    int evaluations = 0; // of the NLopt refinement
    LeadTiltWindow window;
    QStringList warnings; // where the planned cut lies beyond 001's validity (ballEndValidityWarnings)
};

// The lead, tilt and feed per tooth of least machining time, which at a given spindle speed is the
// largest feed rate f N n: the best cell of the window, refined by NLopt's Subplex within the
// bounds, then checked at the plan's resolution, where its largest feed is found again (it can differ
// a little from the window's; rarely none holds there where the window found one).
[[nodiscard]] BallEndPlan planBallEndCut(const BallEndMill &mill, const BallEndToolStructure &tool,
                                         const MillingForceCoefficients &coefficients, const BallEndCut &cut,
                                         double spindle_rpm, const MilledSurfaceTolerance &tolerance,
                                         const BallEndPlanSettings &settings);

} // namespace tolturn
