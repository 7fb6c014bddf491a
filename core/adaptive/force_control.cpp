// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/adaptive/force_control.h"

#include "core/cutting/cutting_quantities.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace tolturn {

namespace {

constexpr double kAirDepth_mm = 1e-4;        // below this the tool is taken as cutting air
constexpr std::size_t kMaxPeriods = 1000000; // 5.6 hours at 20 ms: a set force the feed cannot reach

// x in F ∝ f^x, the local slope of the force model in logarithms at the nominal conditions: for
// Kienzle's law without a nose radius x = 1 − m_c exactly.
double feedExponent(const PassProcess &process, double feed, double depth)
{
    constexpr double k = 1.05;
    const double up = resultant_N(process.forces(feed * k, depth));
    const double down = resultant_N(process.forces(feed / k, depth));
    if (up <= 0.0 || down <= 0.0)
        return 1.0;
    return std::log(up / down) / (2.0 * std::log(k));
}

struct Loop {
    const PassDepthProfile &pass;
    const PassProcess &process;
    const ForceControlSettings &settings;
    double setForce_N;
    double exponent;

    [[nodiscard]] double spindle_rpm(double z) const
    {
        const double d = std::max(pass.cutDiameterAt(z), 1e-3);
        const double n = spindleSpeed_rpm(process.cuttingSpeed_m_min, d);
        return process.maxSpindleSpeed_rpm ? std::min(n, *process.maxSpindleSpeed_rpm) : n;
    }

    // One pass from the right end to the left; `adaptive` false holds the programmed feed.
    [[nodiscard]] ControlRun run(bool adaptive) const
    {
        const double f0 = pass.conditions.feed_mm_rev;
        FeedDrive drive(settings.drive, settings.period_s, 1.0); // override ratio, in steady state at 100 %
        std::mt19937 noiseSource(settings.noiseSeed);
        std::normal_distribution<double> noise(0.0, 1.0);
        double command = 1.0;
        double actual = 1.0;
        std::optional<double> gain; // K in F = K f^x, estimated on line
        ControlRun out;
        const double ceiling =
            std::min(settings.maxOverride, process.maxFeed_mm_rev.value_or(settings.maxOverride * f0) / f0);
        double z = pass.z_mm.front();
        const double zEnd = pass.z_mm.back();
        out.smallestDeviation_um = 1e300;
        out.largestDeviation_um = -1e300;
        for (std::size_t k = 0; z > zEnd && k < kMaxPeriods; ++k) {
            // Where the pass has nothing to cut the program moves on in rapid (toolpath.h): no
            // period passes, and the drive keeps its state.
            if (pass.depthAt(z) <= kAirDepth_mm) {
                z = pass.nextCut_mm(z, kAirDepth_mm);
                if (!(z > zEnd))
                    break;
            }
            ControlSample s;
            s.time_s = static_cast<double>(k) * settings.period_s;
            s.z_mm = z;
            s.depth_mm = pass.depthAt(z);
            s.spindle_rpm = spindle_rpm(z);
            s.feed_mm_rev = f0 * actual;
            const bool cutting = s.depth_mm > kAirDepth_mm; // false only at the very end
            const CuttingForces f = cutting ? process.forces(s.feed_mm_rev, s.depth_mm) : CuttingForces{};
            s.force_N = resultant_N(f);
            s.radialForce_N = f.radial_N;
            s.measuredForce_N = s.force_N * (1.0 + settings.forceNoise * noise(noiseSource));
            if (adaptive && cutting && s.measuredForce_N > 0.0 && s.feed_mm_rev > 1e-9) {
                const double estimate = s.measuredForce_N / std::pow(s.feed_mm_rev, exponent);
                gain = gain ? (1.0 - settings.estimatorGain) * *gain + settings.estimatorGain * estimate : estimate;
                // The feed at which the estimated process gives the set force, approached by the
                // command gain's share of the step.
                const double target = std::pow(setForce_N / *gain, 1.0 / exponent) / f0;
                command = std::clamp(command + settings.commandGain * (target - command), settings.minOverride,
                                     std::max(ceiling, settings.minOverride));
            }
            s.commandedFeed_mm_rev = f0 * command;
            s.ra_um = theoreticalRa_um(s.feed_mm_rev, process.noseRadius_mm);
            if (cutting && process.radialDeviation_mm) {
                s.deviation_um = 1000.0 * process.radialDeviation_mm(z, f);
                out.smallestDeviation_um = std::min(out.smallestDeviation_um, s.deviation_um);
                out.largestDeviation_um = std::max(out.largestDeviation_um, s.deviation_um);
            }
            if (cutting)
                out.peakForce_N = std::max(out.peakForce_N, s.force_N);
            out.samples.push_back(s);
            const double before = actual;
            actual = drive.step(command);
            // Feed rate v_f = f n [mm/min], the mean of the period's ends (trapezoid).
            z -= 0.5 * (before + actual) * f0 * s.spindle_rpm * settings.period_s / 60.0;
        }
        out.time_s = static_cast<double>(out.samples.size()) * settings.period_s;
        out.cutShort = z > zEnd && out.samples.size() >= kMaxPeriods;
        if (out.largestDeviation_um < out.smallestDeviation_um)
            out.smallestDeviation_um = out.largestDeviation_um = 0.0;
        return out;
    }
};

} // namespace

double resultant_N(const CuttingForces &f)
{
    return std::sqrt(f.tangential_N * f.tangential_N + f.axial_N * f.axial_N + f.radial_N * f.radial_N);
}

PassControlResult simulatePassControl(const PassDepthProfile &pass, const PassProcess &process,
                                      const ForceControlSettings &settings, ControlRuns runs)
{
    PassControlResult result;
    result.pass = pass;
    if (pass.z_mm.size() < 2 || pass.conditions.feed_mm_rev <= 0.0 || !process.forces)
        return result;
    const double f0 = pass.conditions.feed_mm_rev;
    const double a0 = pass.conditions.depthOfCut_mm;
    result.feedExponent = feedExponent(process, f0, a0);
    result.setForce_N = settings.setForce_N.value_or(resultant_N(process.forces(f0, a0)));
    const Loop loop{pass, process, settings, result.setForce_N, result.feedExponent};
    result.adaptive = loop.run(true);
    if (runs == ControlRuns::AdaptiveAndConstantFeed)
        result.constantFeed = loop.run(false);
    return result;
}

} // namespace tolturn
