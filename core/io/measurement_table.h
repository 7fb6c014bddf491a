// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"

#include <QString>

#include <optional>
#include <vector>

namespace tolturn {

// A column of a measurement CSV file: its header name, whether every file must have it, and
// whether its values must be above zero.
struct MeasurementColumn {
    const char *name;
    bool required = true;
    bool positive = false;
};

// One value per column, in the order the columns were given; nullopt where an optional column
// is absent from the file or its cell is empty.
using MeasurementRow = std::vector<std::optional<double>>;

// Reads a measurement CSV file: a header line naming the columns (in any order, comma or
// semicolon separated), then one measurement per line; '#' starts a comment line. Every bad cell
// is reported with file, line, column name and text; nullopt when there is any error.
[[nodiscard]] std::optional<std::vector<MeasurementRow>>
parseMeasurementTable(const QString &text, const QString &fileName, const std::vector<MeasurementColumn> &columns,
                      Diagnostics &out);

// The same for a file on disk; a file that cannot be read is reported with its path.
[[nodiscard]] std::optional<std::vector<MeasurementRow>>
readMeasurementTable(const QString &path, const std::vector<MeasurementColumn> &columns, Diagnostics &out);

} // namespace tolturn
