// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace tolturn {

// A column of a measurement CSV file: its header name, whether every file must have it, whether
// its values must be above zero, and whether it holds text (a feature's id) instead of numbers.
struct MeasurementColumn {
    const char *name;
    bool required = true;
    bool positive = false;
    bool text = false;
};

// One value per column, in the order the columns were given; nullopt where an optional column
// is absent from the file or its cell is empty, and for text columns.
using MeasurementRow = std::vector<std::optional<double>>;

// The line of a row in its file (from 1) and the cells of its text columns, in the order those
// columns were given.
struct MeasurementTexts {
    int line = 0;
    QStringList cells;
};

// Reads a measurement CSV file: a header line naming the columns (in any order, comma or
// semicolon separated), then one measurement per line; '#' starts a comment line. Every bad cell
// is reported with file, line, column name and text; nullopt when there is any error.
// `texts`, when given, receives the text columns of each row.
[[nodiscard]] std::optional<std::vector<MeasurementRow>>
parseMeasurementTable(const QString &text, const QString &fileName, const std::vector<MeasurementColumn> &columns,
                      Diagnostics &out, std::vector<MeasurementTexts> *texts = nullptr);

// The same for a file on disk; a file that cannot be read is reported with its path.
[[nodiscard]] std::optional<std::vector<MeasurementRow>>
readMeasurementTable(const QString &path, const std::vector<MeasurementColumn> &columns, Diagnostics &out,
                     std::vector<MeasurementTexts> *texts = nullptr);

} // namespace tolturn
