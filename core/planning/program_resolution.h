// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace tolturn {

// The steps in which a program states the cutting conditions, as post_processor.cpp writes them
// for every dialect it knows (Fanuc / Haas, Sinumerik, LinuxCNC): the surface speed of G96 in
// whole m/min, the feed to three decimals of a millimetre per revolution, coordinates to three
// decimals of a millimetre. A plan is stated on these steps so that the project, the program and
// the verdicts describe the same cut.
inline constexpr double kProgramSpeedStep_m_min = 1.0;
inline constexpr double kProgramFeedStep_mm_rev = 0.001;
inline constexpr double kProgramDepthStep_mm = 0.001;

} // namespace tolturn
