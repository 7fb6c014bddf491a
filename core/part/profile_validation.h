// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/part/profile.h"

namespace tolturn {

// Checks that a profile describes a real turned part: each contour a continuous left-to-right
// chain, every segment consistent with its kind, the inner contour inside the outer one, and
// the stock large enough. Fields are reported as in the project file ("part.outer[2].to.r_mm").
[[nodiscard]] Diagnostics validateProfile(const PartProfile &profile);

} // namespace tolturn
