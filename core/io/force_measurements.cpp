// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/force_measurements.h"

#include "core/io/measurement_table.h"

namespace tolturn {

namespace {

const std::vector<MeasurementColumn> &forceColumns()
{
    static const std::vector<MeasurementColumn> columns{{"feed_mm_rev", true, true},
                                                        {"depth_of_cut_mm", true, true},
                                                        {"tangential_N", true, false},
                                                        {"axial_N", true, false}};
    return columns;
}

MeasurementsReadResult forceMeasurements(const std::optional<std::vector<MeasurementRow>> &rows,
                                         Diagnostics diagnostics)
{
    MeasurementsReadResult result;
    result.diagnostics = std::move(diagnostics);
    if (!rows)
        return result;
    std::vector<ForceMeasurement> cuts;
    for (const MeasurementRow &r : *rows)
        cuts.push_back({r[0].value_or(0.0), r[1].value_or(0.0), r[2].value_or(0.0), r[3].value_or(0.0)});
    result.measurements = std::move(cuts);
    return result;
}

} // namespace

MeasurementsReadResult readForceMeasurements(const QString &path)
{
    Diagnostics diagnostics;
    const auto rows = readMeasurementTable(path, forceColumns(), diagnostics);
    return forceMeasurements(rows, std::move(diagnostics));
}

MeasurementsReadResult parseForceMeasurements(const QString &text, const QString &fileName)
{
    Diagnostics diagnostics;
    const auto rows = parseMeasurementTable(text, fileName, forceColumns(), diagnostics);
    return forceMeasurements(rows, std::move(diagnostics));
}

} // namespace tolturn
