// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/milling/seed_ball_end_cases.h"

#include <numbers>

namespace tolturn {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

SeedBallEndCase row(int number, int flutes, double lead_deg, double tilt_deg, double radialDepth_mm,
                    double axialDepth_mm, double feed_mm_rev, double spindle_rpm)
{
    SeedBallEndCase c;
    c.number = number;
    c.mill = {12.0, flutes, 30.0 * kDegree};
    c.cut.kind = radialDepth_mm > 0.0 ? BallEndCutKind::SideCut : BallEndCutKind::Slot;
    c.cut.direction = MillingDirection::Down;
    c.cut.radialDepth_mm = radialDepth_mm;
    c.cut.axialDepth_mm = axialDepth_mm;
    c.cut.feedPerTooth_mm = feed_mm_rev / flutes;
    c.cut.lead_rad = lead_deg * kDegree;
    c.cut.tilt_rad = tilt_deg * kDegree;
    c.spindle_rpm = spindle_rpm;
    return c;
}

} // namespace

std::vector<SeedBallEndCase> seedBallEndCases()
{
    // 001 table 4: flutes ("tek / çift dişli"), lead and tilt, radial depth ("kanal kesme": a slot),
    // axial depth, feed (mm/rev), spindle speed (rpm).
    return {row(1, 1, 0.0, -15.0, 0.0, 3.0, 0.1, 269.0), row(2, 1, 15.0, 15.0, 0.0, 3.0, 0.1, 269.0),
            row(3, 1, -10.0, 0.0, 4.5962, 3.0, 0.1, 269.0), row(4, 2, 30.0, 30.0, 0.0, 1.5, 0.1, 500.0)};
}

} // namespace tolturn
