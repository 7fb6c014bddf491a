// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/library_info.h"

namespace tolturn {

// The plotting library behind TolTurn's plot classes (QCustomPlot today). Only the files of
// widgets/plot include its headers, so it can be replaced without touching the rest.
[[nodiscard]] LibraryInfo plotBackendInfo();

} // namespace tolturn
