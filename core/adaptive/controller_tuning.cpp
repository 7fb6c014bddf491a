// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/adaptive/controller_tuning.h"

#include <nlopt.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <pagmo/algorithms/pso.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/types.hpp>
#include <utility>

namespace tolturn {

namespace {

constexpr unsigned kSwarmSize = 20;
constexpr unsigned kSeed = 1;

// The objective in normalised coordinates u ∈ [0, 1]², counting its evaluations.
struct Objective {
    const PassDepthProfile *pass = nullptr;
    const PassProcess *process = nullptr;
    const ForceControlSettings *base = nullptr;
    int *evaluations = nullptr;

    [[nodiscard]] static ControllerGains gainsAt(const double *u)
    {
        const auto between = [](double lo, double hi, double t) { return lo + std::clamp(t, 0.0, 1.0) * (hi - lo); };
        return {between(kLowestGains.estimatorGain, kHighestGains.estimatorGain, u[0]),
                between(kLowestGains.commandGain, kHighestGains.commandGain, u[1])};
    }

    [[nodiscard]] double operator()(const double *u) const
    {
        ++*evaluations;
        return forceTrackingError(*pass, *process, *base, gainsAt(u));
    }
};

// pagmo's user-defined problem: copyable, the objective shared by pointer.
struct SwarmProblem {
    const Objective *objective = nullptr;

    [[nodiscard]] pagmo::vector_double fitness(const pagmo::vector_double &u) const { return {(*objective)(u.data())}; }

    [[nodiscard]] static std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds()
    {
        return {{0.0, 0.0}, {1.0, 1.0}};
    }
};

// Čuš & Župerl's off-line optimiser is a particle swarm (seed 004 §2.1, [18], [19]); the paper
// gives no swarm settings, so pagmo's defaults: constriction (Clerc & Kennedy 2002, ω 0.7298,
// η₁ = η₂ = 2.05), a ring of four neighbours, 20 particles, a fixed seed.
std::vector<double> runSwarm(const Objective &objective, int maxEvaluations)
{
    const auto generations = static_cast<unsigned>(std::max(1, maxEvaluations / static_cast<int>(kSwarmSize) - 1));
    const pagmo::problem problem{SwarmProblem{&objective}};
    pagmo::population population{problem, kSwarmSize, kSeed};
    const pagmo::pso swarm{generations, 0.7298, 2.05, 2.05, 0.5, 5u, 2u, 4u, false, kSeed};
    population = swarm.evolve(population);
    return population.champion_x();
}

nlopt::algorithm nloptAlgorithm(TuningMethod method)
{
    switch (method) {
    case TuningMethod::Cobyla:
        return nlopt::LN_COBYLA;
    case TuningMethod::Bobyqa:
        return nlopt::LN_BOBYQA;
    case TuningMethod::NelderMead:
        return nlopt::LN_NELDERMEAD;
    case TuningMethod::Subplex:
        return nlopt::LN_SBPLX;
    case TuningMethod::DirectL:
        return nlopt::GN_DIRECT_L;
    case TuningMethod::Crs2:
        return nlopt::GN_CRS2_LM;
    case TuningMethod::Isres:
        return nlopt::GN_ISRES;
    case TuningMethod::ParticleSwarm:
        break;
    }
    return nlopt::GN_DIRECT_L;
}

double nloptObjective(unsigned, const double *u, double *, void *data)
{
    return (*static_cast<const Objective *>(data))(u);
}

std::vector<double> runNlopt(const Objective &objective, TuningMethod method, int maxEvaluations)
{
    nlopt::opt opt(nloptAlgorithm(method), 2);
    opt.set_lower_bounds({0.0, 0.0});
    opt.set_upper_bounds({1.0, 1.0});
    opt.set_min_objective(nloptObjective, const_cast<Objective *>(&objective));
    opt.set_maxeval(maxEvaluations);
    opt.set_xtol_rel(1e-4);
    nlopt::srand(kSeed); // CRS2 and ISRES draw their points at random: a run repeats
    std::vector<double> u{0.5, 0.5};
    double value = 0.0;
    try {
        opt.optimize(u, value);
    } catch (const std::exception &) {
        // A method that stops on an error keeps the best point it has, which the caller evaluates.
    }
    return u;
}

} // namespace

std::vector<TuningMethod> allTuningMethods()
{
    return {TuningMethod::ParticleSwarm, TuningMethod::Cobyla,  TuningMethod::Bobyqa, TuningMethod::NelderMead,
            TuningMethod::Subplex,       TuningMethod::DirectL, TuningMethod::Crs2,   TuningMethod::Isres};
}

QString tuningMethodName(TuningMethod method)
{
    switch (method) {
    case TuningMethod::ParticleSwarm:
        return QStringLiteral("pso");
    case TuningMethod::Cobyla:
        return QStringLiteral("cobyla");
    case TuningMethod::Bobyqa:
        return QStringLiteral("bobyqa");
    case TuningMethod::NelderMead:
        return QStringLiteral("neldermead");
    case TuningMethod::Subplex:
        return QStringLiteral("sbplx");
    case TuningMethod::DirectL:
        return QStringLiteral("direct-l");
    case TuningMethod::Crs2:
        return QStringLiteral("crs2");
    case TuningMethod::Isres:
        return QStringLiteral("isres");
    }
    return {};
}

QString tuningMethodLibrary(TuningMethod method)
{
    if (method == TuningMethod::ParticleSwarm)
        return QStringLiteral("pagmo2 pso");
    switch (method) {
    case TuningMethod::Cobyla:
        return QStringLiteral("NLopt LN_COBYLA");
    case TuningMethod::Bobyqa:
        return QStringLiteral("NLopt LN_BOBYQA");
    case TuningMethod::NelderMead:
        return QStringLiteral("NLopt LN_NELDERMEAD");
    case TuningMethod::Subplex:
        return QStringLiteral("NLopt LN_SBPLX");
    case TuningMethod::DirectL:
        return QStringLiteral("NLopt GN_DIRECT_L");
    case TuningMethod::Crs2:
        return QStringLiteral("NLopt GN_CRS2_LM");
    case TuningMethod::Isres:
        return QStringLiteral("NLopt GN_ISRES");
    case TuningMethod::ParticleSwarm:
        break;
    }
    return {};
}

double forceTrackingError(const PassDepthProfile &pass, const PassProcess &process, const ForceControlSettings &base,
                          const ControllerGains &gains)
{
    ForceControlSettings settings = base;
    settings.estimatorGain = gains.estimatorGain;
    settings.commandGain = gains.commandGain;
    const PassControlResult r = simulatePassControl(pass, process, settings, ControlRuns::AdaptiveOnly);
    if (r.adaptive.cutShort || r.setForce_N <= 0.0)
        return std::numeric_limits<double>::max();
    // Where even the highest feed the loop may command gives less than the set force, that force
    // is the target: no gain does better, so it is no error of the controller's.
    const double f0 = pass.conditions.feed_mm_rev;
    const double ceiling = std::min(base.maxOverride * f0, process.maxFeed_mm_rev.value_or(base.maxOverride * f0));
    double sum = 0.0;
    int n = 0;
    for (const ControlSample &s : r.adaptive.samples) {
        if (s.depth_mm <= 0.0)
            continue;
        const double target = std::min(r.setForce_N, resultant_N(process.forces(ceiling, s.depth_mm)));
        const double e = s.force_N / target - 1.0;
        sum += e * e;
        ++n;
    }
    return n > 0 ? std::sqrt(sum / n) : 0.0;
}

TuningResult tuneController(const PassDepthProfile &pass, const PassProcess &process, const ForceControlSettings &base,
                            TuningMethod method, int maxEvaluations)
{
    TuningResult result;
    result.method = method;
    const Objective objective{&pass, &process, &base, &result.evaluations};
    const auto start = std::chrono::steady_clock::now();
    const std::vector<double> u = method == TuningMethod::ParticleSwarm ? runSwarm(objective, maxEvaluations)
                                                                        : runNlopt(objective, method, maxEvaluations);
    result.wallTime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.gains = Objective::gainsAt(u.data());
    result.objective = forceTrackingError(pass, process, base, result.gains);
    return result;
}

} // namespace tolturn
