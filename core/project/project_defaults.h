// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/project.h"

namespace tolturn {

// The set-up a part starts with when it has none yet (File > New, an imported STEP part,
// `tolturn-cli import`): a common steel (C45E, normalised) on a mid-size turning centre, a
// CNMG 120408 insert in a PCLNR holder, held in the chuck over 30 mm (a third of a part shorter
// than 90 mm, so that most of it sticks out), one finishing pass at vc 200 m/min, f 0.2 mm/rev,
// ap 0.5 mm (inside the insert maker's usual range for steel). The planner then sets the real
// ones; nothing here is a measured value.
inline constexpr const char *kDefaultMaterialId = "C45E-N";
inline constexpr const char *kDefaultMachineId = "haas-st-20";
inline constexpr double kDefaultClampedLength_mm = 30.0;

[[nodiscard]] Project projectForPart(PartProfile part);

} // namespace tolturn
