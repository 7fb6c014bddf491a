// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Öztürk & Budak's experiments (seed 001 §5): a DMU 50 Evolution, Ø12 mm ball-end mills with a 30°
// helix, Ti6Al4V, the cuts of table 4. They are TolTurn's bundled ball-end examples.

#include "core/milling/ball_end_forces.h"

#include <vector>

namespace tolturn {

struct SeedBallEndCase {
    int number = 0; // table 4's row, 1–4
    BallEndMill mill;
    BallEndCut cut;
    double spindle_rpm = 0.0;
};

// Table 4. The feed is printed per revolution; the feed per tooth is it over the flutes. 001 does
// not say whether case 3 was down or up milling: it is given here as down milling.
[[nodiscard]] std::vector<SeedBallEndCase> seedBallEndCases();

// The springs that hold 001's tool in its holder, calibrated for forces under 1000 N (001 §4):
// k = 6306 N/mm and k_θ = 1.656·10⁷ N·mm/rad. They hold for that tool and holder only.
inline constexpr double kSeedHolderStiffness_N_mm = 6306.0;
inline constexpr double kSeedHolderRotational_N_mm_rad = 1.656e7;

} // namespace tolturn
