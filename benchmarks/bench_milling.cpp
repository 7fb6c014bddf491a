// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the five-axis ball-end force model (issue 19), results recorded in docs/benchmarks.md:
// the forces over one revolution at 1° with 200 axial slices, for each of Öztürk & Budak's four
// cuts (001 table 4), alone and with the tool's deflection.
// Run: build/<preset>/benchmarks/bench_milling
#include "benchmarks/bench_timing.h"

#include "core/milling/ball_end_deflection.h"
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
    return 0;
}
