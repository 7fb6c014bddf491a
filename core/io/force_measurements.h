// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/cutting/cutting_forces.h"

#include <QString>

#include <optional>
#include <vector>

namespace tolturn {

struct MeasurementsReadResult {
    std::optional<std::vector<ForceMeasurement>> measurements;
    Diagnostics diagnostics;
};

// Reads measured cutting forces from a CSV file with the header
//   feed_mm_rev,depth_of_cut_mm,tangential_N,axial_N
// (columns in any order, comma or semicolon separated, '#' starts a comment line). Each bad cell
// is reported with its line, column name and text.
[[nodiscard]] MeasurementsReadResult readForceMeasurements(const QString &path);
[[nodiscard]] MeasurementsReadResult parseForceMeasurements(const QString &text, const QString &fileName);

} // namespace tolturn
