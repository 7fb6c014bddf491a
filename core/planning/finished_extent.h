// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/deviation/deviation_model.h"
#include "core/project/project.h"
#include "core/tolerance/range_verdicts.h"

#include <vector>

namespace tolturn {

// A stretch of a feature's target contour that a set-up's program does not finish, in the
// set-up's coordinates, in the order the contour runs.
struct UnfinishedStretch {
    QString featureId;
    ProfilePoint from;
    ProfilePoint to;
};

// The stretches of the features a set-up cuts (outside: right of the jaws) that its finishing passes
// (finishingPasses(): the outer contour's, the bore's where a boring bar bores it) do not pass
// along: the tool's stop short of the jaws or a centre, a fall its trailing edge rides over, an end
// face held by a centre, a bore without a boring bar or beyond the bar's reach. With the control's
// nose compensation the program's contour is the finished one: a point of the target contour
// counts as finished where a finishing move of the program passes within 2 µm of it. What lies
// inside the pilot hole of a bore's bottom face is not asked of the program.
[[nodiscard]] std::vector<UnfinishedStretch> unfinishedStretches(const Project &project, const TurningInputs &inputs);

// For people: "z 35.000–37.750 mm of O4", "O9 from r 0.000 to 19.000 mm".
[[nodiscard]] QString unfinishedText(const UnfinishedStretch &s);

// Every tolerance whose feature (or a length's second face) the program leaves partly unfinished
// cannot be judged as programmed: its verdict becomes CannotEvaluate (range: NotFinished), its
// reason names the stretches and what the verdict was on what the program turns. Needs the
// range's compliant inputs; without them it changes nothing.
void addWhatTheProgramLeaves(const Project &project, RangeEvaluation &range);

} // namespace tolturn
