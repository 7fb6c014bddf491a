// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/project/project.h"

namespace tolturn {

// Every check of a project that does not need the data libraries: the profile, the clamping,
// the tool codes present, the passes, the datums and the tolerances with the features they name.
[[nodiscard]] Diagnostics validateProject(const Project &project);

// Whether a tolerance of this type can sit on a feature of this kind (Valiño et al. 2008, §V).
[[nodiscard]] bool toleranceFitsFeature(ToleranceType type, SegmentKind kind);

} // namespace tolturn
