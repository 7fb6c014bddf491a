// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/force_measurements.h"

#include <QCoreApplication>
#include <QFile>
#include <QRegularExpression>

#include <array>
#include <cmath>

namespace tolturn {

namespace {

struct MeasurementFiles {
    Q_DECLARE_TR_FUNCTIONS(MeasurementFiles)
};

constexpr std::array<const char *, 4> kColumns{"feed_mm_rev", "depth_of_cut_mm", "tangential_N", "axial_N"};

} // namespace

MeasurementsReadResult readForceMeasurements(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        MeasurementsReadResult r;
        r.diagnostics.push_back(makeError(QStringLiteral("file"),
                                          MeasurementFiles::tr("cannot open '%1': %2").arg(path, file.errorString())));
        return r;
    }
    return parseForceMeasurements(QString::fromUtf8(file.readAll()), path);
}

MeasurementsReadResult parseForceMeasurements(const QString &text, const QString &fileName)
{
    MeasurementsReadResult result;
    static const QRegularExpression separator(QStringLiteral("[,;]"));
    std::array<qsizetype, 4> columnOf{-1, -1, -1, -1};
    std::vector<ForceMeasurement> rows;
    const QStringList lines = text.split(QLatin1Char('\n'));
    bool header = true;
    for (qsizetype n = 0; n < lines.size(); ++n) {
        const QString line = lines.at(n).trimmed();
        if (line.isEmpty() || line.startsWith(QLatin1Char('#')))
            continue;
        const QStringList cells = line.split(separator);
        const QString where = QStringLiteral("%1:%2").arg(fileName).arg(n + 1);
        if (header) {
            for (std::size_t c = 0; c < kColumns.size(); ++c) {
                columnOf[c] = cells.indexOf(QLatin1String(kColumns[c]));
                if (columnOf[c] < 0)
                    result.diagnostics.push_back(makeError(
                        where, MeasurementFiles::tr("the header lacks the column \"%1\"; it needs %2")
                                   .arg(QLatin1String(kColumns[c]), QStringLiteral("feed_mm_rev, depth_of_cut_mm, "
                                                                                   "tangential_N, axial_N"))));
            }
            if (hasErrors(result.diagnostics))
                return result;
            header = false;
            continue;
        }
        std::array<double, 4> v{};
        for (std::size_t c = 0; c < kColumns.size(); ++c) {
            bool ok = false;
            const QString cell = cells.value(columnOf[c]).trimmed();
            v[c] = cell.toDouble(&ok);
            if (!ok || !std::isfinite(v[c]) || v[c] <= (c < 2 ? 0.0 : -1e300))
                result.diagnostics.push_back(
                    makeError(where, MeasurementFiles::tr("%1 must be a number%2, not \"%3\"")
                                         .arg(QLatin1String(kColumns[c]),
                                              c < 2 ? MeasurementFiles::tr(" above zero") : QString(), cell)));
        }
        rows.push_back({v[0], v[1], v[2], v[3]});
    }
    if (header)
        result.diagnostics.push_back(makeError(fileName, MeasurementFiles::tr("the file has no header line")));
    else if (rows.empty())
        result.diagnostics.push_back(makeError(fileName, MeasurementFiles::tr("the file has no measurement")));
    if (!hasErrors(result.diagnostics))
        result.measurements = rows;
    return result;
}

} // namespace tolturn
