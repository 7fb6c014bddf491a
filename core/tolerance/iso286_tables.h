// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The numbers of ISO 286-1:2010 (Tables 1 to 5) that the limits of a tolerance class are computed from:
// standard tolerances, shaft fundamental deviations, the J-hole values and the Δ values for holes.
// Internal to core/tolerance; use iso286.h.

#include <array>
#include <cstddef>
#include <limits>
#include <optional>

namespace tolturn::iso286::tables {

// Marks a table cell the standard leaves empty ("—"): no value is defined there.
inline constexpr int kNotDefined = std::numeric_limits<int>::min();

// The letters of fundamental deviations, the same for shafts (lower case) and holes (upper case), in the
// order of ISO 286-1:2010 Tables 2 and 3.
enum class Letter { A, B, C, CD, D, E, EF, F, FG, G, H, JS, J, K, M, N, P, R, S, T, U, V, X, Y, Z, ZA, ZB, ZC };

inline constexpr std::size_t kLetterCount = 28;

// Size ranges of the standard tolerances (ISO 286-1:2010 Table 1): "above previous up to and including"
// each of these.
inline constexpr std::size_t kToleranceRangeCount = 21;
inline constexpr std::array<double, kToleranceRangeCount> kToleranceRangeUpper_mm = {
    3, 6, 10, 18, 30, 50, 80, 120, 180, 250, 315, 400, 500, 630, 800, 1000, 1250, 1600, 2000, 2500, 3150};

// The finer ranges of the fundamental deviations (ISO 286-1:2010 Tables 2 and 3 split some ranges: for
// a to c and r to zc, and for all letters above 500 mm).
inline constexpr std::size_t kDeviationRangeCount = 41;
inline constexpr std::array<double, kDeviationRangeCount> kDeviationRangeUpper_mm = {
    3,   6,   10,  14,  18,  24,  30,  40,  50,  65,   80,   100,  120,  140,  160,  180,  200,  225,  250,  280, 315,
    355, 400, 450, 500, 560, 630, 710, 800, 900, 1000, 1120, 1250, 1400, 1600, 1800, 2000, 2240, 2500, 2800, 3150};

// Grade index of the IT table: 0 = IT01, 1 = IT0, 2 = IT1 ... 19 = IT18.
inline constexpr std::size_t kGradeCount = 20;

// Index of the range that holds a nominal size in (0, 3150] mm; a size on a boundary belongs to the lower
// range. No value for sizes outside.
[[nodiscard]] std::optional<std::size_t> toleranceRange(double nominal_mm);
[[nodiscard]] std::optional<std::size_t> deviationRange(double nominal_mm);

// Lower bound ("above ...") of a range, for messages.
[[nodiscard]] double toleranceRangeLower_mm(std::size_t range);
[[nodiscard]] double deviationRangeLower_mm(std::size_t range);

// Standard tolerance in µm for a range and an IT grade (-1 = IT01, 0 = IT0, 1 ... 18); no value where
// the standard gives none (IT01 and IT0 above 500 mm).
[[nodiscard]] std::optional<double> standardTolerance_um(std::size_t toleranceRange, int itGrade);

// Shaft fundamental deviation of a letter in µm, signed as in ISO 286-1:2010 Tables 2 and 3: the upper
// deviation es for a to h, the lower deviation ei for k (grades 4 to 7) and m to zc. kNotDefined where
// the table is empty. Not for js and j (see shaftJ_um).
[[nodiscard]] int shaftDeviation_um(Letter letter, std::size_t deviationRange);

// Lower deviation ei of shafts j5/j6, j7 and j8 (ISO 286-1:2010 Table 2); kNotDefined where not given.
[[nodiscard]] int shaftJ_um(int itGrade, std::size_t deviationRange);

// Upper deviation ES of holes J6, J7 and J8 (ISO 286-1:2010 Table 4); kNotDefined where not given.
[[nodiscard]] int holeJ_um(int itGrade, std::size_t deviationRange);

// Δ = ITn - IT(n-1) in µm for holes K, M, N up to IT8 and P to ZC up to IT7 (ISO 286-1:2010 Tables 4, 5),
// tabulated for IT3 to IT8 and sizes up to 500 mm; no value elsewhere.
[[nodiscard]] std::optional<double> delta_um(std::size_t toleranceRange, int itGrade);

} // namespace tolturn::iso286::tables
