// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Čuš & Župerl's own system rebuilt (seed 004 §2–4): end milling on a Heller bea 01 with a
// neural-network force model, the constant-force loop overriding feed and spindle speed every
// 20 ms through the drives, and the printed roughness model; its results beside the paper's
// table 1. The paper's cut data are not published, so the network is trained on the mean forces of
// the linear edge-force model (end_milling.h) for a stated material and tool. docs/adaptive.md §9.

#include "core/adaptive/controller_tuning.h"
#include "core/adaptive/end_milling.h"
#include "core/adaptive/feed_drive.h"
#include "core/adaptive/force_network.h"
#include "core/adaptive/surface_control_models.h"

#include <memory>
#include <vector>

namespace tolturn {

// The set-up of the example (docs/adaptive.md §9 gives the sources).
struct SeedMillingSetup {
    MillingForceCoefficients coefficients; // Al7075-T6, carbide, dry
    double hardness_HB = 0.0;
    double toolDiameter_mm = 0.0;
    int flutes = 0;
    double radialDepth_mm = 0.0;
    double axialDepth_mm = 0.0; // calibrated: the paper's 181.1 N at 324.61 mm/min and 2201 1/min
};

[[nodiscard]] SeedMillingSetup seedMillingSetup();

// The mean forces of the set-up at a feed rate [mm/min] and a spindle speed [1/min].
[[nodiscard]] MillingForces seedMillingForces(const SeedMillingSetup &setup, double feedRate_mm_min,
                                              double spindle_rpm);

// The network's input for the set-up at a feed rate and a speed (the other six inputs fixed, as the
// paper's simulator holds them).
[[nodiscard]] NetworkInput seedNetworkInput(const SeedMillingSetup &setup, double feedRate_mm_min, double spindle_rpm);

// Cut data for the network: the set-up's mean forces on a grid of feed rates 200–700 mm/min and
// speeds 1200–2600 1/min (table 1's ranges with a margin); `offset` true puts the points between
// the grid's, for testing the trained network on what it has not seen.
[[nodiscard]] std::vector<NetworkSample> seedMillingCutData(const SeedMillingSetup &setup, bool offset);

struct SeedControlSettings {
    FeedDriveModel drive;            // eq. 1, for the feed and (004 gives no other) for the spindle
    double period_s = 0.020;         // 004 §2
    double setForce_N = 181.1;       // table 1, simulation 5: the force the loop held
    double feedRate_mm_min = 430.41; // table 1, simulation 5: the pre-programmed conditions
    double spindle_rpm = 1610.0;
    double maxOverride = 2.5; // 004 §3: 0–250 %
    // The share of a change of chip load taken by the speed, n ∝ (c₀ / c)^β: 0 overrides the feed
    // alone, 1 the speed alone. 0.5 splits it evenly in logarithms; table 1's rows give 0.34–0.53.
    double speedShare = 0.5;
    double duration_s = 3.0;
    double forceNoise = 0.0; // relative standard deviation of the measured force (004 §2.4)
    unsigned noiseSeed = 1;
};

struct SeedControlSample {
    double time_s = 0.0;
    double commandedFeedRate_mm_min = 0.0;
    double feedRate_mm_min = 0.0;
    double commandedSpindle_rpm = 0.0;
    double spindle_rpm = 0.0;
    double force_N = 0.0; // resultant of the network's three components
    double measuredForce_N = 0.0;
    double ra_um = 0.0; // M5 (eq. 6) at the force
};

struct SeedControlResult {
    std::vector<SeedControlSample> adaptive;
    std::vector<SeedControlSample> uncontrolled; // the pre-programmed conditions throughout, the same noise
};

// The loop on the network: every period the process gain K of F = K c^x (c the chip load per tooth)
// is estimated from the measured force and the drives' actual feed and speed, the chip load of the
// set force commanded, split between feed and speed by `speedShare`, both overrides within
// 0–`maxOverride`.
[[nodiscard]] SeedControlResult simulateSeedControl(const SeedMillingSetup &setup, const ForceNetwork &network,
                                                    const SurfaceControlModels &models,
                                                    const SeedControlSettings &settings);

// A row of 004 table 1.
struct SeedTableRow {
    double desiredRa_um = 0.0;
    double initialForce_N = 0.0; // the reference force before simulation
    double commandFeedRate_mm_min = 0.0;
    double commandSpindle_rpm = 0.0;
    double force_N = 0.0; // after control
    double feedRate_mm_min = 0.0;
    double spindle_rpm = 0.0;
    double producedRa_um = 0.0;
};

[[nodiscard]] const std::vector<SeedTableRow> &seedTable1();

struct SeedRowResult {
    SeedTableRow paper;
    SeedControlSample settled; // the last period of a run from the row's conditions to its force
};

// Every row of table 1 simulated: from the row's pre-programmed feed and speed, holding the row's
// force after control, for `settings.duration_s`.
[[nodiscard]] std::vector<SeedRowResult> reproduceSeedTable(const SeedMillingSetup &setup, const ForceNetwork &network,
                                                            const SurfaceControlModels &models,
                                                            const SeedControlSettings &settings);

// The off-line PSO-NN optimisation (004 §2.1): the largest feed rate whose force, by the network,
// stays within the allowed force, the feed rate and the speed within the range the network was
// trained on (outside it the network extrapolates). The swarm flies over the network's force
// surface; NLopt's algorithms solve the same penalised problem.
struct SeedConditions {
    TuningMethod method = TuningMethod::ParticleSwarm;
    double feedRate_mm_min = 0.0;
    double spindle_rpm = 0.0;
    double force_N = 0.0;
    int evaluations = 0;
    double wallTime_s = 0.0;
};

constexpr double kSeedLowestFeedRate_mm_min = 200.0;
constexpr double kSeedHighestFeedRate_mm_min = 700.0;
constexpr double kSeedLowestSpindle_rpm = 1200.0;
constexpr double kSeedHighestSpindle_rpm = 2600.0;

[[nodiscard]] SeedConditions optimiseSeedConditions(const SeedMillingSetup &setup, const ForceNetwork &network,
                                                    double allowedForce_N, TuningMethod method, int maxEvaluations);

// The network of the example: trained on seedMillingCutData(setup, false) with 004's training
// settings.
[[nodiscard]] ForceNetwork seedForceNetwork(const SeedMillingSetup &setup);

// Everything the example shows (the CLI's control-example, the GUI's Tools > end-milling example),
// computed once: the set-up, the trained network's error on the cut data between its training
// points, the PSO-NN conditions by every method, the loop of table 1 simulation 5 and every row.
struct SeedExampleResult {
    SeedMillingSetup setup;
    std::shared_ptr<const ForceNetwork> network; // trained once; the loop reruns on it
    double unseenError = 0.0;
    std::vector<SeedConditions> conditions;
    SeedControlSettings settings;
    SeedControlResult loop;
    std::vector<SeedRowResult> table;
};

constexpr int kSeedOptimiserEvaluations = 400;

[[nodiscard]] SeedExampleResult runSeedExample(const SeedControlSettings &settings);

// The loop and the table again with other settings of the loop (noise, speed share, duration) on
// the network already trained; the conditions, which depend on the set force alone, stay.
void rerunSeedLoop(SeedExampleResult &result, const SeedControlSettings &settings);

// True where a feed rate and a speed lie outside the range the network was trained on (it then
// extrapolates).
[[nodiscard]] bool outsideSeedNetworkRange(double feedRate_mm_min, double spindle_rpm);

} // namespace tolturn
