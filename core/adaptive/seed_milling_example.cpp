// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/adaptive/seed_milling_example.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <random>
#include <tuple>
#include <utility>

namespace tolturn {

namespace {

// 004 table 1, simulation 5: the conditions after control, which the paper's network gives 181.1 N at.
constexpr double kCalibrationFeedRate_mm_min = 324.61;
constexpr double kCalibrationSpindle_rpm = 2201.0;
constexpr double kCalibrationForce_N = 181.1;

double resultantOf(const MillingForces &f)
{
    return std::sqrt(f.x_N * f.x_N + f.y_N * f.y_N + f.z_N * f.z_N);
}

double resultantOf(const NetworkOutput &f)
{
    return f.norm();
}

} // namespace

SeedMillingSetup seedMillingSetup()
{
    SeedMillingSetup s;
    // Al7075-T6, cemented carbide, dry: Ktc 767.01, Krc 168.8, Kac 222 N/mm², Kte 27.7, Kre 26.6,
    // Kae 0.7 N/mm ("Milling Force Model for Aviation Aluminum Alloy: Academic Insight and Perspective
    // Analysis", Chinese Journal of Mechanical Engineering, 2021, doi:10.1186/s10033-021-00536-9,
    // table 5, the row of its reference [190]). 004 does not name its work material.
    s.coefficients = {767.01, 168.8, 222.0, 27.7, 26.6, 0.7};
    // 7075-T6: Brinell 150 (ASM Aerospace Specification Metals, data sheet "Aluminum 7075-T6;
    // 7075-T651"). An input of the network that does not change here.
    s.hardness_HB = 150.0;
    // The example's tool and cut (004 names neither): a four-flute Ø16 end mill at half immersion,
    // down milling.
    s.toolDiameter_mm = 16.0;
    s.flutes = 4;
    s.radialDepth_mm = 8.0;
    // The mean forces are proportional to the axial depth: the depth at which the model gives the
    // paper's 181.1 N at its controlled 324.61 mm/min and 2201 1/min.
    s.axialDepth_mm = 1.0;
    s.axialDepth_mm =
        kCalibrationForce_N / resultantOf(seedMillingForces(s, kCalibrationFeedRate_mm_min, kCalibrationSpindle_rpm));
    return s;
}

MillingForces seedMillingForces(const SeedMillingSetup &setup, double feedRate_mm_min, double spindle_rpm)
{
    const double feedPerTooth = feedRate_mm_min / (setup.flutes * spindle_rpm);
    return meanMillingForces(setup.coefficients, downMilling(setup.flutes, setup.toolDiameter_mm, setup.radialDepth_mm,
                                                             setup.axialDepth_mm, feedPerTooth));
}

NetworkInput seedNetworkInput(const SeedMillingSetup &setup, double feedRate_mm_min, double spindle_rpm)
{
    NetworkInput x;
    // 004 §2.3: feed rate, spindle speed, radial and axial depth, material type (a code),
    // hardness, tool diameter, tool geometry (a code).
    x << feedRate_mm_min, spindle_rpm, setup.radialDepth_mm, setup.axialDepth_mm, 1.0, setup.hardness_HB,
        setup.toolDiameter_mm, 1.0;
    return x;
}

std::vector<NetworkSample> seedMillingCutData(const SeedMillingSetup &setup, bool offset)
{
    constexpr int kSteps = 20;
    const double shift = offset ? 0.5 : 0.0;
    std::vector<NetworkSample> samples;
    for (int i = 0; i <= kSteps - (offset ? 1 : 0); ++i) {
        for (int j = 0; j <= kSteps - (offset ? 1 : 0); ++j) {
            const double f = kSeedLowestFeedRate_mm_min +
                             (i + shift) * (kSeedHighestFeedRate_mm_min - kSeedLowestFeedRate_mm_min) / kSteps;
            const double n =
                kSeedLowestSpindle_rpm + (j + shift) * (kSeedHighestSpindle_rpm - kSeedLowestSpindle_rpm) / kSteps;
            const MillingForces m = seedMillingForces(setup, f, n);
            NetworkSample s;
            s.input = seedNetworkInput(setup, f, n);
            s.output << m.x_N, m.y_N, m.z_N;
            samples.push_back(s);
        }
    }
    return samples;
}

namespace {

struct SeedLoop {
    const SeedMillingSetup &setup;
    const ForceNetwork &network;
    const SurfaceControlModels &models;
    const SeedControlSettings &settings;

    [[nodiscard]] double force(double feedRate, double spindle) const
    {
        return resultantOf(network(seedNetworkInput(setup, feedRate, spindle)));
    }

    // x in F ∝ c^x at the programmed conditions, the local slope of the network in logarithms
    // along the feed (the controller's model of the process).
    [[nodiscard]] double chipLoadExponent() const
    {
        constexpr double k = 1.05;
        const double f0 = settings.feedRate_mm_min;
        const double n0 = settings.spindle_rpm;
        return std::log(force(f0 * k, n0) / force(f0 / k, n0)) / (2.0 * std::log(k));
    }

    // The feed and speed overrides of a chip load c* = ratio · c₀: the speed takes the share β,
    // n / n₀ = ratio^(−β), the feed the rest, f / f₀ = ratio · n / n₀. Where the feed reaches its
    // limit, the speed takes over what is left of the chip load, within its own.
    [[nodiscard]] std::pair<double, double> overridesFor(double ratio) const
    {
        constexpr double kLowestSpeed = 0.01; // a spindle override of 0 would stop the cut
        double speed = std::clamp(std::pow(ratio, -settings.speedShare), kLowestSpeed, settings.maxOverride);
        const double feed = std::clamp(ratio * speed, 0.0, settings.maxOverride);
        if (feed < ratio * speed)
            speed = std::clamp(feed / ratio, kLowestSpeed, settings.maxOverride);
        return {feed, speed};
    }

    [[nodiscard]] std::vector<SeedControlSample> run(bool adaptive) const
    {
        const double f0 = settings.feedRate_mm_min;
        const double n0 = settings.spindle_rpm;
        const double c0 = f0 / n0; // chip load per tooth up to the constant number of flutes
        const double x = chipLoadExponent();
        FeedDrive feedDrive(settings.drive, settings.period_s, 1.0);
        FeedDrive spindleDrive(settings.drive, settings.period_s, 1.0);
        std::mt19937 noiseSource(settings.noiseSeed);
        std::normal_distribution<double> noise(0.0, 1.0);
        double feedCommand = 1.0;
        double speedCommand = 1.0;
        std::vector<SeedControlSample> out;
        const auto periods = static_cast<int>(std::lround(settings.duration_s / settings.period_s));
        for (int k = 0; k < periods; ++k) {
            SeedControlSample s;
            s.time_s = k * settings.period_s;
            s.feedRate_mm_min = f0 * feedDrive.actual();
            s.spindle_rpm = n0 * spindleDrive.actual();
            s.force_N = force(s.feedRate_mm_min, s.spindle_rpm);
            s.measuredForce_N = s.force_N * (1.0 + settings.forceNoise * noise(noiseSource));
            s.ra_um = models.roughness.evaluate(s.force_N);
            const double c = s.spindle_rpm > 0.0 ? s.feedRate_mm_min / s.spindle_rpm : 0.0;
            if (adaptive && x > 0.0 && s.measuredForce_N > 0.0 && c > 0.0) {
                const double gain = s.measuredForce_N / std::pow(c, x);
                const double target = std::pow(settings.setForce_N / gain, 1.0 / x); // chip load of the set force
                std::tie(feedCommand, speedCommand) = overridesFor(target / c0);
            }
            s.commandedFeedRate_mm_min = f0 * feedCommand;
            s.commandedSpindle_rpm = n0 * speedCommand;
            out.push_back(s);
            feedDrive.step(feedCommand);
            spindleDrive.step(speedCommand);
        }
        return out;
    }
};

} // namespace

SeedControlResult simulateSeedControl(const SeedMillingSetup &setup, const ForceNetwork &network,
                                      const SurfaceControlModels &models, const SeedControlSettings &settings)
{
    const SeedLoop loop{setup, network, models, settings};
    return {loop.run(true), loop.run(false)};
}

const std::vector<SeedTableRow> &seedTable1()
{
    // 004 table 1, "The simulation results": desired Ra; F, f_c, n_c before; F, f_a, n_a after;
    // the Ra produced.
    static const std::vector<SeedTableRow> rows{
        {0.40, 164.5, 362.85, 2000, 157.5, 264.92, 2350, 0.44}, {0.55, 168.91, 401.92, 1900, 168.0, 287.32, 2310, 0.57},
        {0.66, 172.1, 416.02, 1712, 175.6, 301.88, 2298, 0.68}, {0.74, 174.4, 445.1, 1630, 177.0, 309.43, 2250, 0.76},
        {0.81, 175.0, 430.41, 1610, 181.1, 324.61, 2201, 0.79}, {0.86, 180.1, 469.30, 1501, 183.8, 329.95, 2160, 0.80},
        {1.05, 185.4, 491.93, 1400, 184.8, 352.52, 2007, 0.97}, {1.11, 188.1, 507.75, 1290, 188.1, 355.60, 1921, 0.99}};
    return rows;
}

std::vector<SeedRowResult> reproduceSeedTable(const SeedMillingSetup &setup, const ForceNetwork &network,
                                              const SurfaceControlModels &models, const SeedControlSettings &settings)
{
    std::vector<SeedRowResult> out;
    for (const SeedTableRow &row : seedTable1()) {
        SeedControlSettings s = settings;
        s.setForce_N = row.force_N;
        s.feedRate_mm_min = row.commandFeedRate_mm_min;
        s.spindle_rpm = row.commandSpindle_rpm;
        const SeedControlResult r = simulateSeedControl(setup, network, models, s);
        out.push_back({row, r.adaptive.empty() ? SeedControlSample{} : r.adaptive.back()});
    }
    return out;
}

SeedConditions optimiseSeedConditions(const SeedMillingSetup &setup, const ForceNetwork &network, double allowedForce_N,
                                      TuningMethod method, int maxEvaluations)
{
    const auto at = [](const std::vector<double> &u) {
        return std::pair{kSeedLowestFeedRate_mm_min +
                             std::clamp(u[0], 0.0, 1.0) * (kSeedHighestFeedRate_mm_min - kSeedLowestFeedRate_mm_min),
                         kSeedLowestSpindle_rpm +
                             std::clamp(u[1], 0.0, 1.0) * (kSeedHighestSpindle_rpm - kSeedLowestSpindle_rpm)};
    };
    const auto force = [&](double f, double n) { return resultantOf(network(seedNetworkInput(setup, f, n))); };
    // The largest feed rate (in the box's units) less a penalty of ten per unit of relative excess
    // force: any excess costs more than the feed it buys.
    const auto objective = [&](const std::vector<double> &u) {
        const auto [f, n] = at(u);
        return -u[0] + 10.0 * std::max(0.0, force(f, n) / allowedForce_N - 1.0);
    };
    SeedConditions result;
    result.method = method;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<double> u = minimiseInUnitBox(objective, 2, method, maxEvaluations, result.evaluations);
    result.wallTime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::tie(result.feedRate_mm_min, result.spindle_rpm) = at(u);
    result.force_N = force(result.feedRate_mm_min, result.spindle_rpm);
    return result;
}

ForceNetwork seedForceNetwork(const SeedMillingSetup &setup)
{
    return ForceNetwork::trained(seedMillingCutData(setup, false), NetworkTraining{});
}

SeedExampleResult runSeedExample(const SeedControlSettings &settings)
{
    SeedExampleResult r;
    r.setup = seedMillingSetup();
    r.network = std::make_shared<const ForceNetwork>(seedForceNetwork(r.setup));
    r.unseenError = r.network->rmsRelativeError(seedMillingCutData(r.setup, true));
    for (const TuningMethod m : allTuningMethods())
        r.conditions.push_back(
            optimiseSeedConditions(r.setup, *r.network, settings.setForce_N, m, kSeedOptimiserEvaluations));
    rerunSeedLoop(r, settings);
    return r;
}

void rerunSeedLoop(SeedExampleResult &result, const SeedControlSettings &settings)
{
    result.settings = settings;
    result.loop = simulateSeedControl(result.setup, *result.network, printedSurfaceControlModels(), settings);
    result.table = reproduceSeedTable(result.setup, *result.network, printedSurfaceControlModels(), settings);
}

bool outsideSeedNetworkRange(double feedRate_mm_min, double spindle_rpm)
{
    constexpr double kSlack = 1e-9;
    return feedRate_mm_min < kSeedLowestFeedRate_mm_min - kSlack ||
           feedRate_mm_min > kSeedHighestFeedRate_mm_min + kSlack || spindle_rpm < kSeedLowestSpindle_rpm - kSlack ||
           spindle_rpm > kSeedHighestSpindle_rpm + kSlack;
}

} // namespace tolturn
