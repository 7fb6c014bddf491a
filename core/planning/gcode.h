// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/planning/compensation.h"
#include "core/project/project.h"

#include <QString>

namespace tolturn {

struct GCodeOptions {
    CuttingPass finishing;                          // speed and feed of the finishing pass
    const CompensationPlan *compensation = nullptr; // nullptr: the nominal path
    std::optional<double> maxSpindleSpeed_rpm;      // G92 limit for G96
    int tool = 1;
    int programNumber = 1000;
};

// The finishing path of the outer contour as an ISO 6983-style program: G18 G21 G90, diameter
// programming, G96 with a G92 speed limit, G95 feed per revolution, a tool call, comments naming
// the part and the compensation. The tool feeds towards the chuck, from the right end face over
// every outer feature to the chuck face. Z0 is the right end face of the part, Z negative towards
// the chuck; X is the diameter; G02/G03 are as seen with Z to the right and X upwards. The path
// is the target contour (targetContour(): every toleranced diameter at the middle of its zone,
// which is what the verdicts assume, MODEL §3). Features with a profile correction are written as
// G01 moves through their corrected stations, features with an offset with the offset applied on
// top of the target, the others as aimed at.
[[nodiscard]] QString finishingProgram(const Project &project, const GCodeOptions &options);

} // namespace tolturn
