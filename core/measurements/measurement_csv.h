// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/measurements/measured_part.h"

#include <QString>

#include <optional>
#include <vector>

namespace tolturn {

// The points of a measured part from a CSV file (docs/learning.md): a header naming the columns
// `feature` (the profile segment's id, "O4"), `z_mm`, and on each line one of `diameter_mm`,
// `radial_deviation_um`, or `x_mm` and `y_mm` (a CMM point in the part's frame); the file may have
// all these columns, a line fills one. Comma
// or semicolon separated, '#' starts a comment line. Every bad cell is named with its line and
// column; nullopt when there is any error.
[[nodiscard]] std::optional<std::vector<MeasuredPoint>> parseMeasuredPoints(const QString &text,
                                                                            const QString &fileName, Diagnostics &out);
[[nodiscard]] std::optional<std::vector<MeasuredPoint>> readMeasuredPoints(const QString &path, Diagnostics &out);

// Stored parts as CSV, one line a point: part, machine, measured_at (UTC, ISO 8601), feature,
// z_mm, diameter_mm, radial_deviation_um, x_mm, y_mm (what was measured filled), the header first.
[[nodiscard]] QString measuredPointsCsv(const std::vector<MeasuredPart> &parts);

} // namespace tolturn
