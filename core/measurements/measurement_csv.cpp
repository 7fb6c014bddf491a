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
    static const std::vector<MeasurementColumn> columns{
        {"feature", true, false, true},      {"z_mm", true, false, false},
        {"diameter_mm", false, true, false}, {"radial_deviation_um", false, false, false},
        {"x_mm", false, false, false},       {"y_mm", false, false, false}};
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
        const bool radial = r[3].has_value();
        const bool cmm = r[4].has_value() || r[5].has_value();
        if (int(diameter) + int(radial) + int(cmm) != 1 || (cmm && !(r[4] && r[5]))) {
            out.push_back(makeError(QStringLiteral("%1:%2").arg(fileName).arg(texts[i].line),
                                    MeasurementCsv::tr("a line needs one of diameter_mm, radial_deviation_um, or "
                                                       "x_mm and y_mm (a CMM point)")));
            ok = false;
            continue;
        }
        const QString feature = texts[i].cells.value(0);
        if (cmm)
            points.push_back(cmmPoint(feature, *r[4], *r[5], *r[1]));
        else
            points.push_back({feature, *r[1], diameter ? MeasuredQuantity::Diameter : MeasuredQuantity::RadialDeviation,
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
                           QStringLiteral("radial_deviation_um"), QStringLiteral("x_mm"), QStringLiteral("y_mm")}) +
                  QLatin1Char('\n');
    for (const MeasuredPart &part : parts) {
        for (const MeasuredPoint &p : part.points) {
            const auto number = [](double v) { return QString::number(v, 'g', 10); };
            const bool cmm = p.quantity == MeasuredQuantity::CmmPoint;
            csv += csvLine({QString::number(part.id), part.machineId,
                            part.measuredAt.toUTC().toString(Qt::ISODateWithMs), p.featureId, number(p.z_mm),
                            p.quantity == MeasuredQuantity::Diameter ? number(p.value_mm) : QString(),
                            p.quantity == MeasuredQuantity::RadialDeviation ? number(1000.0 * p.value_mm) : QString(),
                            cmm ? number(p.x_mm) : QString(), cmm ? number(p.y_mm) : QString()}) +
                   QLatin1Char('\n');
        }
    }
    return csv;
}

} // namespace tolturn
