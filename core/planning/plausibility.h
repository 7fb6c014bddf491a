// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/data/data_library.h"
#include "core/project/project.h"

namespace tolturn {

// What a project asks of its data and its machine, checked against the data library
// (docs/planning.md, "Plausibility"): an unknown material or machine, or a holder whose entering
// angle cannot be found, is an error; cutting conditions outside the insert's published ranges
// (planning.ranges) or needing more spindle speed or power than the machine's published limits are
// warnings. Each names the field (passes[i].feed_mm_rev, ...) and the value.
[[nodiscard]] Diagnostics checkPlausibility(const Project &project, const DataLibrary &data);

} // namespace tolturn
