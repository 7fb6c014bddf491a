// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The constant-force loop (force_control.h) on the passes of a project: the depth of cut each
// pass meets from the stock to the profile, TolTurn's own force model, the spindle speed of G96
// at the diameter cut, and the deviation of the surface each pass leaves from the deviation
// model's influence coefficients (docs/adaptive.md §3).

#include "core/adaptive/force_control.h"
#include "core/common/diagnostic.h"
#include "core/data/data_library.h"
#include "core/deviation/turning_inputs.h"
#include "core/project/project.h"

#include <QStringList>

#include <optional>
#include <vector>

namespace tolturn {

struct ProjectControlOptions {
    ForceControlSettings control;
    std::optional<int> passIndex; // one pass of Project::passes; all when absent
    StiffnessEnd stiffnessEnd = StiffnessEnd::Compliant;
    double depthStep_mm = 0.05; // sampling of the depth of cut along z
};

struct ProjectControlResult {
    std::vector<PassControlResult> passes;
    Diagnostics diagnostics;
    QStringList notes; // what the result rests on: the force model, the machine, the noise

    [[nodiscard]] bool ok() const { return !hasErrors(diagnostics) && !passes.empty(); }
};

// A pass of the project ready for the loop: its depth of cut along z and the process it meets.
struct PassSetup {
    PassDepthProfile pass;
    PassProcess process;
};

struct ProjectControlSetup {
    std::vector<PassSetup> passes;
    Diagnostics diagnostics;
    QStringList notes;

    [[nodiscard]] bool ok() const { return !hasErrors(diagnostics) && !passes.empty(); }
};

// The passes (options.passIndex, or all) resolved once against the data library, for
// simulateProjectControl and for tuning the controller on them (controller_tuning.h).
[[nodiscard]] ProjectControlSetup prepareProjectControl(const Project &project, const DataLibrary &data,
                                                        const ProjectControlOptions &options);

[[nodiscard]] ProjectControlResult simulateProjectControl(const Project &project, const DataLibrary &data,
                                                          const ProjectControlOptions &options);

} // namespace tolturn
