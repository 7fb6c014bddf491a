// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the five-axis ball-end force model (issue 19), results recorded in docs/benchmarks.md:
// the forces over one revolution at 1° with 200 axial slices, for each of Öztürk & Budak's four
// cuts (001 table 4), alone and with the tool's deflection; the lead–tilt window of 64 × 64 on two
// threads for case 4's cut, at the window's resolution (100 slices, 2°) and at the full one.
// Run: build/<preset>/benchmarks/bench_milling
#include "benchmarks/bench_timing.h"

#include "core/milling/ball_end_deflection.h"
#include "core/milling/ball_end_planning.h"
#include "core/milling/seed_ball_end_cases.h"

#include <cstdio>

using namespace tolturn;
using tolturn::bench::medianMilliseconds;

int main()
{
    // Benchmark coefficients of the order of a titanium alloy's, not data: the time does not depend
    // on their values, only on which elements cut.
    const MillingForceCoefficients k{2000.0, 700.0, 400.0, 25.0, 40.0, 8.0};
    const BallEndToolStructure tool{40.0, 9.6, 630000.0, kSeedHolderStiffness_N_mm, kSeedHolderRotational_N_mm_rad};
    const BallEndResolution resolution{200, 360};
    std::printf("case  flutes  forces [ms]  forces + deflection [ms]\n");
    for (const SeedBallEndCase &c : seedBallEndCases()) {
        double sink = 0.0;
        const double forces = medianMilliseconds(
            201, [&] { sink += summarise(ballEndForces(c.mill, k, c.cut, resolution)).meanTorque_N_mm; });
        const double deflection = medianMilliseconds(
            201, [&] { sink += ballEndDeflection(c.mill, tool, k, c.cut, resolution).greatestSurfaceNormal_mm; });
        std::printf("%4d  %6d  %11.3f  %24.3f   (%g)\n", c.number, c.mill.flutes, forces, deflection,
                    sink > 0 ? 1.0 : 0.0);
    }
    const SeedBallEndCase c4 = seedBallEndCases().back();
    constexpr double kDegree = 3.14159265358979323846 / 180.0;
    BallEndPlanSettings settings;
    settings.leadLowest_rad = settings.tiltLowest_rad = -40.0 * kDegree;
    settings.leadHighest_rad = settings.tiltHighest_rad = 40.0 * kDegree;
    settings.highestFeedPerTooth_mm = 0.3;
    for (const BallEndResolution r : {settings.windowResolution, BallEndResolution{200, 360}}) {
        settings.windowResolution = r;
        const double ms = medianMilliseconds(5, [&] {
            (void)leadTiltWindow(c4.mill, tool, k, c4.cut, {0.010, SurfaceZone::Floating}, settings);
        });
        std::printf("window 64 x 64, %d slices x %d angles, %d threads: %.0f ms\n", r.axialSlices,
                    r.anglesPerRevolution, settings.threads, ms);
    }
    return 0;
}
