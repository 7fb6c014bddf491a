// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Tuning the constant-force controller (force_control.h) on a pass: the estimator's gain and the
// command gain that keep the force closest to its set value, found by the particle swarm of
// Čuš & Župerl (seed 004 §2.1, after Shi & Eberhart 1998; pagmo2's implementation) and by
// NLopt's algorithms on the same objective, for comparison (docs/adaptive.md §8).

#include "core/adaptive/force_control.h"

#include <QString>

#include <functional>
#include <vector>

namespace tolturn {

enum class TuningMethod {
    ParticleSwarm, // pagmo::pso
    Cobyla,        // NLopt LN_COBYLA
    Bobyqa,        // NLopt LN_BOBYQA
    NelderMead,    // NLopt LN_NELDERMEAD
    Subplex,       // NLopt LN_SBPLX
    DirectL,       // NLopt GN_DIRECT_L
    Crs2,          // NLopt GN_CRS2_LM
    Isres,         // NLopt GN_ISRES
};

[[nodiscard]] std::vector<TuningMethod> allTuningMethods();
[[nodiscard]] QString tuningMethodName(TuningMethod method);    // "pso", "cobyla", ... (the CLI's words)
[[nodiscard]] QString tuningMethodLibrary(TuningMethod method); // "pagmo2 pso", "NLopt LN_COBYLA", ...

// The two settings tuned, and their bounds.
struct ControllerGains {
    double estimatorGain = 1.0;
    double commandGain = 1.0;
};

// The command c_k = c_(k-1) + g (f* - c_(k-1)) leaves the error (1 - g)^k of the first: above g = 1
// it changes sign every period (the feed commanded alternates about f*, at g = 2 for ever), which
// the objective, scored on the force behind the feed drive's lag, hardly sees. g stays within 1.
constexpr ControllerGains kLowestGains{0.02, 0.1};
constexpr ControllerGains kHighestGains{1.0, 1.0};

// The objective: the root mean square of the relative force error F / F_target − 1 over the
// periods the adaptive run cuts, with the true force (the noise is in what the controller
// measures, not in what the tool and the part take). F_target is the set force, or where the
// highest feed the loop may command cannot reach it, the force at that feed. The set force and the
// rest of the loop are `base`'s.
[[nodiscard]] double forceTrackingError(const PassDepthProfile &pass, const PassProcess &process,
                                        const ForceControlSettings &base, const ControllerGains &gains);

struct TuningResult {
    TuningMethod method = TuningMethod::ParticleSwarm;
    ControllerGains gains;
    double objective = 0.0; // forceTrackingError at `gains`
    int evaluations = 0;    // simulations of the pass the method asked for
    double wallTime_s = 0.0;
};

// The smallest budget every method keeps to: the swarm's 20 particles and one generation.
constexpr int kLeastTuningEvaluations = 40;

// The least of `objective` over the unit box [0, 1]^dimensions by one method, from the middle of
// the box (local methods) or over it (global ones), with at most `maxEvaluations` evaluations
// (at least kLeastTuningEvaluations; counted in `evaluations`); the swarm has 20 particles and a
// fixed seed, so a run repeats.
[[nodiscard]] std::vector<double> minimiseInUnitBox(const std::function<double(const std::vector<double> &)> &objective,
                                                    int dimensions, TuningMethod method, int maxEvaluations,
                                                    int &evaluations);

// One method, from the middle of the bounds (local methods) or over them (global ones), with at
// most `maxEvaluations` simulations; the swarm has 20 particles and a fixed seed, so a run repeats.
[[nodiscard]] TuningResult tuneController(const PassDepthProfile &pass, const PassProcess &process,
                                          const ForceControlSettings &base, TuningMethod method, int maxEvaluations);

} // namespace tolturn
