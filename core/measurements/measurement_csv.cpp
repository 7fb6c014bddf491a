// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/measurements/measurement_csv.h"

#include "core/common/csv.h"
#include "core/io/measurement_table.h"

#include <QCoreApplication>

namespace tolturn {

namespace {

struct MeasurementCsv {
    Q_DECLARE_TR_FUNCTIONS(MeasurementCsv)
};

const std::vector<MeasurementColumn> &pointColumns()
{
    static const std::vector<MeasurementColumn> columns{{"feature", true, false, true},
                                                        {"z_mm", true, false, false},
                                                        {"diameter_mm", false, true, false},
                                                        {"radial_deviation_um", false, false, false}};
    return columns;
}

std::optional<std::vector<MeasuredPoint>> pointsOf(const std::optional<std::vector<MeasurementRow>> &rows,
                                                   const std::vector<MeasurementTexts> &texts, const QString &fileName,
                                                   Diagnostics &out)
{
    if (!rows)
        return std::nullopt;
    std::vector<MeasuredPoint> points;
    bool ok = true;
    for (std::size_t i = 0; i < rows->size(); ++i) {
        const MeasurementRow &r = (*rows)[i];
        const bool diameter = r[2].has_value();
        if (diameter == r[3].has_value()) {
            out.push_back(makeError(QStringLiteral("%1:%2").arg(fileName).arg(texts[i].line),
                                    MeasurementCsv::tr("a line needs either diameter_mm or radial_deviation_um, "
                                                       "and one only")));
            ok = false;
            continue;
        }
        points.push_back({texts[i].cells.value(0), *r[1],
                          diameter ? MeasuredQuantity::Diameter : MeasuredQuantity::RadialDeviation,
                          diameter ? *r[2] : *r[3] / 1000.0});
    }
    if (!ok)
        return std::nullopt;
    return points;
}

} // namespace

std::optional<std::vector<MeasuredPoint>> parseMeasuredPoints(const QString &text, const QString &fileName,
                                                              Diagnostics &out)
{
    std::vector<MeasurementTexts> texts;
    const auto rows = parseMeasurementTable(text, fileName, pointColumns(), out, &texts);
    return pointsOf(rows, texts, fileName, out);
}

std::optional<std::vector<MeasuredPoint>> readMeasuredPoints(const QString &path, Diagnostics &out)
{
    std::vector<MeasurementTexts> texts;
    const auto rows = readMeasurementTable(path, pointColumns(), out, &texts);
    return pointsOf(rows, texts, path, out);
}

QString measuredPointsCsv(const std::vector<MeasuredPart> &parts)
{
    QString csv = csvLine({QStringLiteral("part"), QStringLiteral("machine"), QStringLiteral("measured_at"),
                           QStringLiteral("feature"), QStringLiteral("z_mm"), QStringLiteral("diameter_mm"),
                           QStringLiteral("radial_deviation_um")}) +
                  QLatin1Char('\n');
    for (const MeasuredPart &part : parts) {
        for (const MeasuredPoint &p : part.points) {
            const bool diameter = p.quantity == MeasuredQuantity::Diameter;
            csv +=
                csvLine({QString::number(part.id), part.machineId, part.measuredAt.toUTC().toString(Qt::ISODateWithMs),
                         p.featureId, QString::number(p.z_mm, 'g', 10),
                         diameter ? QString::number(p.value_mm, 'g', 10) : QString(),
                         diameter ? QString() : QString::number(1000.0 * p.value_mm, 'g', 10)}) +
                QLatin1Char('\n');
        }
    }
    return csv;
}

} // namespace tolturn
