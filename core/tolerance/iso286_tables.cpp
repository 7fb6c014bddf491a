// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/tolerance/iso286_tables.h"

#include <algorithm>
#include <cmath>

namespace tolturn::iso286::tables {

namespace {

constexpr int ND = kNotDefined;
constexpr double NA = -1.0; // IT01 and IT0 above 500 mm: not given

// Standard tolerance values IT in µm (ISO 286-1:2010, Table 1 "Numerical values of standard tolerance
// grades IT for nominal sizes up to 3 150 mm", IT1 to IT18; IT01 and IT0 from the same part's table of
// IT01 and IT0 values (ISO 286-1:1988 Annex A, Table 5), which gives them for sizes up to 500 mm only).
// Table 1 notes: IT1 to IT5 above 500 mm are included for experimental use; IT14 to IT18 shall not be
// used for nominal sizes up to and including 1 mm. Columns: IT01, IT0, IT1 ... IT18.
constexpr double kIt_um[kToleranceRangeCount][kGradeCount] = {
    // clang-format off
    /*    0-   3 */ {0.3, 0.5, 0.8, 1.2, 2, 3, 4, 6, 10, 14, 25, 40, 60, 100, 140, 250, 400, 600, 1000, 1400},
    /*    3-   6 */ {0.4, 0.6, 1, 1.5, 2.5, 4, 5, 8, 12, 18, 30, 48, 75, 120, 180, 300, 480, 750, 1200, 1800},
    /*    6-  10 */ {0.4, 0.6, 1, 1.5, 2.5, 4, 6, 9, 15, 22, 36, 58, 90, 150, 220, 360, 580, 900, 1500, 2200},
    /*   10-  18 */ {0.5, 0.8, 1.2, 2, 3, 5, 8, 11, 18, 27, 43, 70, 110, 180, 270, 430, 700, 1100, 1800, 2700},
    /*   18-  30 */ {0.6, 1, 1.5, 2.5, 4, 6, 9, 13, 21, 33, 52, 84, 130, 210, 330, 520, 840, 1300, 2100, 3300},
    /*   30-  50 */ {0.6, 1, 1.5, 2.5, 4, 7, 11, 16, 25, 39, 62, 100, 160, 250, 390, 620, 1000, 1600, 2500, 3900},
    /*   50-  80 */ {0.8, 1.2, 2, 3, 5, 8, 13, 19, 30, 46, 74, 120, 190, 300, 460, 740, 1200, 1900, 3000, 4600},
    /*   80- 120 */ {1, 1.5, 2.5, 4, 6, 10, 15, 22, 35, 54, 87, 140, 220, 350, 540, 870, 1400, 2200, 3500, 5400},
    /*  120- 180 */ {1.2, 2, 3.5, 5, 8, 12, 18, 25, 40, 63, 100, 160, 250, 400, 630, 1000, 1600, 2500, 4000, 6300},
    /*  180- 250 */ {2, 3, 4.5, 7, 10, 14, 20, 29, 46, 72, 115, 185, 290, 460, 720, 1150, 1850, 2900, 4600, 7200},
    /*  250- 315 */ {2.5, 4, 6, 8, 12, 16, 23, 32, 52, 81, 130, 210, 320, 520, 810, 1300, 2100, 3200, 5200, 8100},
    /*  315- 400 */ {3, 5, 7, 9, 13, 18, 25, 36, 57, 89, 140, 230, 360, 570, 890, 1400, 2300, 3600, 5700, 8900},
    /*  400- 500 */ {4, 6, 8, 10, 15, 20, 27, 40, 63, 97, 155, 250, 400, 630, 970, 1550, 2500, 4000, 6300, 9700},
    /*  500- 630 */ {NA, NA, 9, 11, 16, 22, 32, 44, 70, 110, 175, 280, 440, 700, 1100, 1750, 2800, 4400, 7000, 11000},
    /*  630- 800 */ {NA, NA, 10, 13, 18, 25, 36, 50, 80, 125, 200, 320, 500, 800, 1250, 2000, 3200, 5000, 8000, 12500},
    /*  800-1000 */ {NA, NA, 11, 15, 21, 28, 40, 56, 90, 140, 230, 360, 560, 900, 1400, 2300, 3600, 5600, 9000, 14000},
    /* 1000-1250 */ {NA, NA, 13, 18, 24, 33, 47, 66, 105, 165, 260, 420, 660, 1050, 1650, 2600, 4200,
                    6600, 10500, 16500},
    /* 1250-1600 */ {NA, NA, 15, 21, 29, 39, 55, 78, 125, 195, 310, 500, 780, 1250, 1950, 3100, 5000,
                    7800, 12500, 19500},
    /* 1600-2000 */ {NA, NA, 18, 25, 35, 46, 65, 92, 150, 230, 370, 600, 920, 1500, 2300, 3700, 6000,
                    9200, 15000, 23000},
    /* 2000-2500 */ {NA, NA, 22, 30, 41, 55, 78, 110, 175, 280, 440, 700, 1100, 1750, 2800, 4400, 7000,
                    11000, 17500, 28000},
    /* 2500-3150 */ {NA, NA, 26, 36, 50, 68, 96, 135, 210, 330, 540, 860, 1350, 2100, 3300, 5400, 8600,
                    13500, 21000, 33000},
    // clang-format on
};

using Row = std::array<int, kDeviationRangeCount>;

// Ranges of the rows below, in the order of kDeviationRangeUpper_mm:
//   0-3 3-6 6-10 10-14 14-18 18-24 24-30 30-40 40-50 50-65 65-80 80-100 100-120 120-140 140-160 160-180
//   180-200 200-225 225-250 250-280 280-315 315-355 355-400 400-450 450-500 | 500-560 560-630 630-710
//   710-800 800-900 900-1000 1000-1120 1120-1250 1250-1400 1400-1600 1600-1800 1800-2000 2000-2240
//   2240-2500 2500-2800 2800-3150

// Shaft fundamental deviations in µm (ISO 286-1:2010, Table 2 "Values for the fundamental deviations of
// shafts a to j" (upper deviation es, all grades) and Table 3 "... shafts k to zc" (lower deviation ei);
// the same values as ISO 286-1:1988, Table 2).
// Table notes: a and b shall not be used for nominal sizes up to and including 1 mm (applied in
// iso286.cpp); cd, ef and fg are given up to 10 mm only; a, b, c and v to zc up to 500 mm only; t from
// above 24 mm, v from above 14 mm, y from above 18 mm. Row K holds the k column "IT4 to IT7" (k is 0 for
// grades up to IT3 and above IT7, and 0 for all grades above 500 mm). JS and J are not in this table.
// clang-format off
constexpr Row kShaft[kLetterCount] = {
    /* a  */ {-270, -270, -280, -290, -290, -300, -300, -310, -320, -340, -360, -380, -410, -460, -520, -580,
              -660, -740, -820, -920, -1050, -1200, -1350, -1500, -1650,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* b  */ {-140, -140, -150, -150, -150, -160, -160, -170, -180, -190, -200, -220, -240, -260, -280, -310,
              -340, -380, -420, -480, -540, -600, -680, -760, -840,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* c  */ {-60, -70, -80, -95, -95, -110, -110, -120, -130, -140, -150, -170, -180, -200, -210, -230,
              -240, -260, -280, -300, -330, -360, -400, -440, -480,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* cd */ {-34, -46, -56, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND,
              ND, ND, ND, ND, ND, ND, ND, ND, ND,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* d  */ {-20, -30, -40, -50, -50, -65, -65, -80, -80, -100, -100, -120, -120, -145, -145, -145,
              -170, -170, -170, -190, -190, -210, -210, -230, -230,
              -260, -260, -290, -290, -320, -320, -350, -350, -390, -390, -430, -430, -480, -480, -520, -520},
    /* e  */ {-14, -20, -25, -32, -32, -40, -40, -50, -50, -60, -60, -72, -72, -85, -85, -85,
              -100, -100, -100, -110, -110, -125, -125, -135, -135,
              -145, -145, -160, -160, -170, -170, -195, -195, -220, -220, -240, -240, -260, -260, -290, -290},
    /* ef */ {-10, -14, -18, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND,
              ND, ND, ND, ND, ND, ND, ND, ND, ND,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* f  */ {-6, -10, -13, -16, -16, -20, -20, -25, -25, -30, -30, -36, -36, -43, -43, -43,
              -50, -50, -50, -56, -56, -62, -62, -68, -68,
              -76, -76, -80, -80, -86, -86, -98, -98, -110, -110, -120, -120, -130, -130, -145, -145},
    /* fg */ {-4, -6, -8, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND,
              ND, ND, ND, ND, ND, ND, ND, ND, ND,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* g  */ {-2, -4, -5, -6, -6, -7, -7, -9, -9, -10, -10, -12, -12, -14, -14, -14,
              -15, -15, -15, -17, -17, -18, -18, -20, -20,
              -22, -22, -24, -24, -26, -26, -28, -28, -30, -30, -32, -32, -34, -34, -38, -38},
    /* h  */ {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
              0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    /* js */ {ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* j  */ {ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* k  */ {0, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 3, 3, 3, 3, 3,
              4, 4, 4, 4, 4, 4, 4, 5, 5,
              0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    /* m  */ {2, 4, 6, 7, 7, 8, 8, 9, 9, 11, 11, 13, 13, 15, 15, 15,
              17, 17, 17, 20, 20, 21, 21, 23, 23,
              26, 26, 30, 30, 34, 34, 40, 40, 48, 48, 58, 58, 68, 68, 76, 76},
    /* n  */ {4, 8, 10, 12, 12, 15, 15, 17, 17, 20, 20, 23, 23, 27, 27, 27,
              31, 31, 31, 34, 34, 37, 37, 40, 40,
              44, 44, 50, 50, 56, 56, 66, 66, 78, 78, 92, 92, 110, 110, 135, 135},
    /* p  */ {6, 12, 15, 18, 18, 22, 22, 26, 26, 32, 32, 37, 37, 43, 43, 43,
              50, 50, 50, 56, 56, 62, 62, 68, 68,
              78, 78, 88, 88, 100, 100, 120, 120, 140, 140, 170, 170, 195, 195, 240, 240},
    /* r  */ {10, 15, 19, 23, 23, 28, 28, 34, 34, 41, 43, 51, 54, 63, 65, 68,
              77, 80, 84, 94, 98, 108, 114, 126, 132,
              150, 155, 175, 185, 210, 220, 250, 260, 300, 330, 370, 400, 440, 460, 550, 580},
    /* s  */ {14, 19, 23, 28, 28, 35, 35, 43, 43, 53, 59, 71, 79, 92, 100, 108,
              122, 130, 140, 158, 170, 190, 208, 232, 252,
              280, 310, 340, 380, 430, 470, 520, 580, 640, 720, 820, 920, 1000, 1100, 1250, 1400},
    /* t  */ {ND, ND, ND, ND, ND, ND, 41, 48, 54, 66, 75, 91, 104, 122, 134, 146,
              166, 180, 196, 218, 240, 268, 294, 330, 360,
              400, 450, 500, 560, 620, 680, 780, 840, 960, 1050, 1200, 1350, 1500, 1650, 1900, 2100},
    /* u  */ {18, 23, 28, 33, 33, 41, 48, 60, 70, 87, 102, 124, 144, 170, 190, 210,
              236, 258, 284, 315, 350, 390, 435, 490, 540,
              600, 660, 740, 840, 940, 1050, 1150, 1300, 1450, 1600, 1850, 2000, 2300, 2500, 2900, 3200},
    /* v  */ {ND, ND, ND, ND, 39, 47, 55, 68, 81, 102, 120, 146, 172, 202, 228, 252,
              284, 310, 340, 385, 425, 475, 530, 595, 660,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* x  */ {20, 28, 34, 40, 45, 54, 64, 80, 97, 122, 146, 178, 210, 248, 280, 310,
              350, 385, 425, 475, 525, 590, 660, 740, 820,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* y  */ {ND, ND, ND, ND, ND, 63, 75, 94, 114, 144, 174, 214, 254, 300, 340, 380,
              425, 470, 520, 580, 650, 730, 820, 920, 1000,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* z  */ {26, 35, 42, 50, 60, 73, 88, 112, 136, 172, 210, 258, 310, 365, 415, 465,
              520, 575, 640, 710, 790, 900, 1000, 1100, 1250,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* za */ {32, 42, 52, 64, 77, 98, 118, 148, 180, 226, 274, 335, 400, 470, 535, 600,
              670, 740, 820, 920, 1000, 1150, 1300, 1450, 1600,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* zb */ {40, 50, 67, 90, 108, 136, 160, 200, 242, 300, 360, 445, 525, 620, 700, 780,
              880, 960, 1050, 1200, 1300, 1500, 1650, 1850, 2100,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
    /* zc */ {60, 80, 97, 130, 150, 188, 218, 274, 325, 405, 480, 585, 690, 800, 900, 1000,
              1150, 1250, 1350, 1550, 1700, 1900, 2100, 2400, 2600,
              ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND, ND},
};
// clang-format on

// Shaft j: lower deviation ei in µm for IT5 and IT6, IT7, IT8 (ISO 286-1:2010, Table 2, column j;
// ISO 286-1:1988, Table 2). j8 is
// given only up to 3 mm, and j not at all above 500 mm. Per tolerance range (0-3 ... 400-500).
constexpr int kShaftJ_um[13][3] = {
    // clang-format off
    /*   0 -   3 */ {-2, -4, -6},
    /*   3 -   6 */ {-2, -4, ND},
    /*   6 -  10 */ {-2, -5, ND},
    /*  10 -  18 */ {-3, -6, ND},
    /*  18 -  30 */ {-4, -8, ND},
    /*  30 -  50 */ {-5, -10, ND},
    /*  50 -  80 */ {-7, -12, ND},
    /*  80 - 120 */ {-9, -15, ND},
    /* 120 - 180 */ {-11, -18, ND},
    /* 180 - 250 */ {-13, -21, ND},
    /* 250 - 315 */ {-16, -26, ND},
    /* 315 - 400 */ {-18, -28, ND},
    /* 400 - 500 */ {-20, -32, ND},
    // clang-format on
};

// Hole J: upper deviation ES in µm for IT6, IT7 and IT8 (ISO 286-1:2010, Table 4 "Values for the
// fundamental deviations of holes A to M", column J; ISO 286-1:1988, Table 3), sizes up to 500 mm. Per
// tolerance range.
constexpr int kHoleJ_um[13][3] = {
    // clang-format off
    /*   0 -   3 */ {2, 4, 6},
    /*   3 -   6 */ {5, 6, 10},
    /*   6 -  10 */ {5, 8, 12},
    /*  10 -  18 */ {6, 10, 15},
    /*  18 -  30 */ {8, 12, 20},
    /*  30 -  50 */ {10, 14, 24},
    /*  50 -  80 */ {13, 18, 28},
    /*  80 - 120 */ {16, 22, 34},
    /* 120 - 180 */ {18, 26, 41},
    /* 180 - 250 */ {22, 30, 47},
    /* 250 - 315 */ {25, 36, 55},
    /* 315 - 400 */ {29, 39, 60},
    /* 400 - 500 */ {33, 43, 66},
    // clang-format on
};

// Δ in µm for IT3, IT4, IT5, IT6, IT7, IT8 (ISO 286-1:2010, Tables 4 and 5 (holes A to M, N to ZC), the
// columns "values for Δ"; ISO 286-1:1988, Table 3, right-hand columns: "for determining K, M and N up
// to IT8 and P to ZC up to IT7, take the Δ values"). Δ = ITn - IT(n-1). Per tolerance range up to 500 mm.
constexpr double kDelta_um[13][6] = {
    // clang-format off
    /*   0 -   3 */ {0, 0, 0, 0, 0, 0},
    /*   3 -   6 */ {1, 1.5, 1, 3, 4, 6},
    /*   6 -  10 */ {1, 1.5, 2, 3, 6, 7},
    /*  10 -  18 */ {1, 2, 3, 3, 7, 9},
    /*  18 -  30 */ {1.5, 2, 3, 4, 8, 12},
    /*  30 -  50 */ {1.5, 3, 4, 5, 9, 14},
    /*  50 -  80 */ {2, 3, 5, 6, 11, 16},
    /*  80 - 120 */ {2, 4, 5, 7, 13, 19},
    /* 120 - 180 */ {3, 4, 6, 7, 15, 23},
    /* 180 - 250 */ {3, 4, 6, 9, 17, 26},
    /* 250 - 315 */ {4, 4, 7, 9, 20, 29},
    /* 315 - 400 */ {4, 5, 7, 11, 21, 32},
    /* 400 - 500 */ {5, 5, 7, 13, 23, 34},
    // clang-format on
};

constexpr std::size_t kRangesUpTo500 = 13;

template <std::size_t N>
std::optional<std::size_t> rangeOf(const std::array<double, N> &upper, double nominal_mm)
{
    if (!std::isfinite(nominal_mm) || nominal_mm <= 0.0 || nominal_mm > upper.back())
        return std::nullopt;
    const auto it = std::lower_bound(upper.begin(), upper.end(), nominal_mm);
    return static_cast<std::size_t>(it - upper.begin());
}

// Index 0 .. 19 of an IT grade -1 (IT01) ... 18 in the columns of kIt_um.
std::optional<std::size_t> gradeColumn(int itGrade)
{
    if (itGrade < -1 || itGrade > 18)
        return std::nullopt;
    return static_cast<std::size_t>(itGrade + 1);
}

} // namespace

std::optional<std::size_t> toleranceRange(double nominal_mm)
{
    return rangeOf(kToleranceRangeUpper_mm, nominal_mm);
}

std::optional<std::size_t> deviationRange(double nominal_mm)
{
    return rangeOf(kDeviationRangeUpper_mm, nominal_mm);
}

double toleranceRangeLower_mm(std::size_t range)
{
    return range == 0 ? 0.0 : kToleranceRangeUpper_mm.at(range - 1);
}

double deviationRangeLower_mm(std::size_t range)
{
    return range == 0 ? 0.0 : kDeviationRangeUpper_mm.at(range - 1);
}

std::optional<double> standardTolerance_um(std::size_t toleranceRange, int itGrade)
{
    const auto column = gradeColumn(itGrade);
    if (!column || toleranceRange >= kToleranceRangeCount)
        return std::nullopt;
    const double value = kIt_um[toleranceRange][*column];
    if (value <= 0.0)
        return std::nullopt;
    return value;
}

int shaftDeviation_um(Letter letter, std::size_t deviationRange)
{
    const auto row = static_cast<std::size_t>(letter);
    if (row >= kLetterCount || deviationRange >= kDeviationRangeCount)
        return kNotDefined;
    return kShaft[row].at(deviationRange);
}

namespace {

// The tolerance range (0-3 ... 400-500) that contains a deviation range, or no value above 500 mm.
std::optional<std::size_t> rangeUpTo500(std::size_t deviationRange)
{
    if (deviationRange >= kDeviationRangeCount)
        return std::nullopt;
    const double upper = kDeviationRangeUpper_mm.at(deviationRange);
    const auto range = toleranceRange(upper);
    if (!range || *range >= kRangesUpTo500)
        return std::nullopt;
    return range;
}

} // namespace

int shaftJ_um(int itGrade, std::size_t deviationRange)
{
    const auto range = rangeUpTo500(deviationRange);
    if (!range)
        return kNotDefined;
    switch (itGrade) {
    case 5:
    case 6:
        return kShaftJ_um[*range][0];
    case 7:
        return kShaftJ_um[*range][1];
    case 8:
        return kShaftJ_um[*range][2];
    default:
        return kNotDefined;
    }
}

int holeJ_um(int itGrade, std::size_t deviationRange)
{
    const auto range = rangeUpTo500(deviationRange);
    if (!range || itGrade < 6 || itGrade > 8)
        return kNotDefined;
    return kHoleJ_um[*range][static_cast<std::size_t>(itGrade - 6)];
}

std::optional<double> delta_um(std::size_t toleranceRange, int itGrade)
{
    if (toleranceRange >= kRangesUpTo500 || itGrade < 3 || itGrade > 8)
        return std::nullopt;
    return kDelta_um[toleranceRange][static_cast<std::size_t>(itGrade - 3)];
}

} // namespace tolturn::iso286::tables
