// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/data/data_library.h"
#include "core/deviation/deviation_model.h"
#include "core/learning/machine_learning.h"
#include "core/project/project.h"
#include "core/tolerance/range_verdicts.h"

#include <QString>

#include <optional>
#include <vector>

namespace tolturn {

// What was learned of the machine from its measured parts, drawn beside the physics
// (docs/learning.md): the learned correction to the radius error at every station of the result
// (learnedAtStations), and the RMS error of parts not learned from as its uncertainty.
struct LearnedCurves {
    std::vector<std::vector<double>> atStations; // mm of radius, per feature and station
    double uncertainty_mm = 0.0;
    QString provenance;
};

// What the window and the report show of one set-up: the tolerance verdicts, the deviation curves
// and the line saying what they rest on.
struct SetupPrediction {
    // The verdicts (range.tolerances) over the machine's stiffness range, or on physics + what was
    // learned; with the re-clamping notes of a set-up of several.
    RangeEvaluation range;
    // What the curves draw: the compliant end of the range, or the physics alone beside `learned`.
    DeviationResult deviation;
    std::optional<DeviationResult> stiffEnd; // the range's stiff end, drawn as a band
    std::optional<LearnedCurves> learned;
    // For the banner above the verdicts and the report's first page: the machine's range or what
    // was learned, and for a set-up of several, which one and which end it holds.
    QString assumption;
};

// The prediction of `project` (one set-up, as operationView gives it) with `learned` when the
// planner uses what was learned of the machine (nullptr: over the stiffness range).
[[nodiscard]] SetupPrediction predictSetup(const Project &project, const DataLibrary &data, const LoadedModel *learned);

} // namespace tolturn
