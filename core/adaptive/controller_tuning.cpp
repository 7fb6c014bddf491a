// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/adaptive/controller_tuning.h"

#include <nlopt.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <pagmo/algorithms/pso.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/types.hpp>
#include <utility>

namespace tolturn {

namespace {

constexpr unsigned kSwarmSize = 20;
constexpr unsigned kSeed = 1;

using UnitBoxObjective = std::function<double(const std::vector<double> &)>;

ControllerGains gainsAt(const std::vector<double> &u)
{
    const auto between = [](double lo, double hi, double t) { return lo + std::clamp(t, 0.0, 1.0) * (hi - lo); };
    return {between(kLowestGains.estimatorGain, kHighestGains.estimatorGain, u[0]),
            between(kLowestGains.commandGain, kHighestGains.commandGain, u[1])};
}

// pagmo's user-defined problem: copyable, the objective shared by pointer.
struct SwarmProblem {
    const UnitBoxObjective *objective = nullptr;
    int dimensions = 0;

    [[nodiscard]] pagmo::vector_double fitness(const pagmo::vector_double &u) const { return {(*objective)(u)}; }

    [[nodiscard]] std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const
    {
        const auto n = static_cast<std::size_t>(dimensions);
        return {pagmo::vector_double(n, 0.0), pagmo::vector_double(n, 1.0)};
    }
};

// Čuš & Župerl's off-line optimiser is a particle swarm (seed 004 §2.1, [18], [19]); the paper
// gives no swarm settings, so pagmo's defaults: constriction (Clerc & Kennedy 2002, ω 0.7298,
// η₁ = η₂ = 2.05), a ring of four neighbours, 20 particles, a fixed seed.
std::vector<double> runSwarm(const UnitBoxObjective &objective, int dimensions, int maxEvaluations)
{
    const auto generations = static_cast<unsigned>(std::max(1, maxEvaluations / static_cast<int>(kSwarmSize) - 1));
    const pagmo::problem problem{SwarmProblem{&objective, dimensions}};
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

double nloptObjective(unsigned n, const double *u, double *, void *data)
{
    return (*static_cast<const UnitBoxObjective *>(data))(std::vector<double>(u, u + n));
}

std::vector<double> runNlopt(const UnitBoxObjective &objective, int dimensions, TuningMethod method, int maxEvaluations)
{
    const auto n = static_cast<unsigned>(dimensions);
    nlopt::opt opt(nloptAlgorithm(method), n);
    opt.set_lower_bounds(std::vector<double>(n, 0.0));
    opt.set_upper_bounds(std::vector<double>(n, 1.0));
    opt.set_min_objective(nloptObjective, const_cast<UnitBoxObjective *>(&objective));
    opt.set_maxeval(std::max(1, maxEvaluations)); // NLopt reads 0 as no limit
    opt.set_xtol_rel(1e-4);
    nlopt::srand(kSeed); // CRS2 and ISRES draw their points at random: a run repeats
    std::vector<double> u(n, 0.5);
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
    switch (method) {
    case TuningMethod::ParticleSwarm:
        return QStringLiteral("pagmo2 pso");
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
    // A run that does not reach the end of the pass is worse than any that does; a finite value
    // keeps the local methods' models finite.
    constexpr double kNoRun = 1e3;
    if (r.adaptive.cutShort || r.setForce_N <= 0.0)
        return kNoRun;
    // Where even the highest feed the loop may command gives less than the set force, that force
    // is the target: no gain does better, so it is no error of the controller's.
    const double f0 = pass.conditions.feed_mm_rev;
    const double ceiling = std::min(base.maxOverride * f0, process.maxFeed_mm_rev.value_or(base.maxOverride * f0));
    double sum = 0.0;
    int n = 0;
    for (const ControlSample &s : r.adaptive.samples) {
        if (s.force_N <= 0.0)
            continue; // the tool in air at the very end of the pass
        const double target = std::min(r.setForce_N, resultant_N(process.forces(ceiling, s.depth_mm)));
        const double e = s.force_N / target - 1.0;
        sum += e * e;
        ++n;
    }
    return n > 0 ? std::sqrt(sum / n) : 0.0;
}

std::vector<double> minimiseInUnitBox(const std::function<double(const std::vector<double> &)> &objective,
                                      int dimensions, TuningMethod method, int maxEvaluations, int &evaluations)
{
    const UnitBoxObjective counted = [&](const std::vector<double> &u) {
        ++evaluations;
        return objective(u);
    };
    return method == TuningMethod::ParticleSwarm ? runSwarm(counted, dimensions, maxEvaluations)
                                                 : runNlopt(counted, dimensions, method, maxEvaluations);
}

TuningResult tuneController(const PassDepthProfile &pass, const PassProcess &process, const ForceControlSettings &base,
                            TuningMethod method, int maxEvaluations)
{
    TuningResult result;
    result.method = method;
    const auto objective = [&](const std::vector<double> &u) {
        return forceTrackingError(pass, process, base, gainsAt(u));
    };
    const auto start = std::chrono::steady_clock::now();
    const std::vector<double> u = minimiseInUnitBox(objective, 2, method, maxEvaluations, result.evaluations);
    result.wallTime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.gains = gainsAt(u);
    result.objective = forceTrackingError(pass, process, base, result.gains);
    return result;
}

} // namespace tolturn
