// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Constant-force adaptive control of a turning pass, after Čuš & Župerl (seed 004, §2): every
// control period the measured resultant force is compared with the set force and a feed override
// is commanded through the feed drive's dynamics (eq. 1), so that the force, and with it the
// deflection and the roughness, stays constant while the depth of cut changes along the pass.
// docs/adaptive.md gives the method, the controller and its limits.

#include "core/adaptive/feed_drive.h"
#include "core/adaptive/pass_depth.h"
#include "core/cutting/cutting_forces.h"

#include <functional>
#include <optional>
#include <vector>

namespace tolturn {

struct ForceControlSettings {
    FeedDriveModel drive;     // 004 eq. 1
    double period_s = 0.020;  // 004 §2: the force is available to the controller every 20 ms
    double minOverride = 0.0; // 004 §3: "allowable adjusting rate [0 – 250 %]"
    double maxOverride = 2.5;
    // Weight of each period's estimate of the process gain (1: the last measurement alone; less
    // smooths noise at the price of a slower answer). A setting of the controller, not a datum.
    double estimatorGain = 1.0;
    // Share of the step from the last command to the feed of the set force taken each period
    // (1: the whole step; less damps the answer; more would make the command alternate about the
    // target, controller_tuning.h). A setting of the controller, not a datum: controller_tuning.h
    // finds it with the estimator's gain.
    double commandGain = 1.0;
    // Machine noise (004 §2.4): relative standard deviation of the measured force, Gaussian, with
    // a fixed seed so that a run can be repeated. 004 states no level: none unless given.
    double forceNoise = 0.0;
    unsigned noiseSeed = 1;
    std::optional<double> setForce_N; // default: the force of the programmed feed at the pass's nominal depth
};

// What the loop needs of the process, resolved once by the caller.
struct PassProcess {
    // The forces at a feed [mm/rev] and a radial depth of cut [mm] (TolTurn's force model).
    std::function<CuttingForces(double feed_mm_rev, double depth_mm)> forces;
    // The radial deviation of the surface the pass leaves at z under the forces [mm] (the deviation
    // model's influence coefficients, docs/model.md §6). Empty: not computed.
    std::function<double(double z_mm, const CuttingForces &)> radialDeviation_mm;
    double cuttingSpeed_m_min = 0.0; // G96 constant surface speed
    std::optional<double> maxSpindleSpeed_rpm;
    double noseRadius_mm = 0.0; // the kinematic roughness
    // The largest feed the pass may run at whatever the force allows [mm/rev]: the insert's range,
    // the roughness a finished surface must have. None: the override's limit alone.
    std::optional<double> maxFeed_mm_rev;
};

struct ControlSample {
    double time_s = 0.0;
    double z_mm = 0.0;
    double depth_mm = 0.0;
    double commandedFeed_mm_rev = 0.0;
    double feed_mm_rev = 0.0; // actual, after the drive
    double spindle_rpm = 0.0;
    double force_N = 0.0;         // resultant of the model's three components
    double measuredForce_N = 0.0; // with the machine noise
    double radialForce_N = 0.0;
    double ra_um = 0.0;        // kinematic, f² / (32 r_e)
    double deviation_um = 0.0; // radial deviation of the surface left (0 when not computed)
};

struct ControlRun {
    std::vector<ControlSample> samples;
    double time_s = 0.0;      // in the cut (the program crosses what a pass does not cut in rapid)
    double peakForce_N = 0.0; // largest resultant while cutting
    double largestDeviation_um = 0.0;
    double smallestDeviation_um = 0.0;
    bool cutShort = false; // stopped after its longest simulated time before the end of the pass
};

struct PassControlResult {
    PassDepthProfile pass;
    double setForce_N = 0.0;
    double feedExponent = 0.0; // x in F ∝ f^x at the nominal depth, the controller's model
    ControlRun adaptive;
    ControlRun constantFeed; // the programmed feed throughout, the same noise
};

enum class ControlRuns { AdaptiveAndConstantFeed, AdaptiveOnly };

// The pass simulated twice on the same depth profile and noise: with the adaptive loop and at the
// programmed feed (or the adaptive run alone, for tuning). The tool starts at the right end at the
// programmed feed, in steady state.
[[nodiscard]] PassControlResult simulatePassControl(const PassDepthProfile &pass, const PassProcess &process,
                                                    const ForceControlSettings &settings,
                                                    ControlRuns runs = ControlRuns::AdaptiveAndConstantFeed);

// The resultant of the three force components.
[[nodiscard]] double resultant_N(const CuttingForces &f);

} // namespace tolturn
