// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/measurements/measured_part.h"

#include "core/io/project_json.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {

struct MeasuredParts {
    Q_DECLARE_TR_FUNCTIONS(MeasuredParts)
};

// Bounds of a measured value (docs/learning.md): a radial deviation of a turned part beyond a
// millimetre is a wrong entry or a wrong part, not an error to learn from; the time since start
// spans a week of running; the temperature a workshop's range with margin.
constexpr double kMaxRadialDeviation_mm = 1.0;
constexpr double kMaxTimeSinceStart_min = 7 * 24 * 60.0;
constexpr double kMinAmbient_C = -10.0;
constexpr double kMaxAmbient_C = 50.0;

const Segment *segmentWithId(const PartProfile &part, const QString &id)
{
    for (const Contour *c : {&part.outer, &part.inner}) {
        const auto it =
            std::find_if(c->segments.begin(), c->segments.end(), [&id](const Segment &s) { return s.id == id; });
        if (it != c->segments.end())
            return &*it;
    }
    return nullptr;
}

void checkPoint(const MeasuredPoint &p, const PartProfile &part, const QString &field, Diagnostics &out)
{
    const Segment *s = segmentWithId(part, p.featureId);
    if (s == nullptr) {
        out.push_back(makeError(field + QStringLiteral(".feature"),
                                MeasuredParts::tr("the part's profile has no feature \"%1\"").arg(p.featureId)));
        return;
    }
    const double zMin = std::min(s->from.z_mm, s->to.z_mm);
    const double zMax = std::max(s->from.z_mm, s->to.z_mm);
    if (!std::isfinite(p.z_mm) || p.z_mm < zMin - 1e-9 || p.z_mm > zMax + 1e-9)
        out.push_back(makeError(field + QStringLiteral(".z_mm"),
                                MeasuredParts::tr("z = %1 mm is not on feature %2 (z from %3 to %4 mm)")
                                    .arg(formatNumber(p.z_mm), p.featureId, formatNumber(zMin), formatNumber(zMax))));
    if (p.quantity == MeasuredQuantity::CmmPoint) {
        const double rMin = std::min(s->from.r_mm, s->to.r_mm);
        const double rMax = std::max(s->from.r_mm, s->to.r_mm);
        if (!std::isfinite(p.x_mm) || !std::isfinite(p.y_mm))
            out.push_back(makeError(field + QStringLiteral(".x_mm"),
                                    MeasuredParts::tr("a CMM point needs finite x and y (x = %1, y = %2 mm)")
                                        .arg(formatNumber(p.x_mm), formatNumber(p.y_mm))));
        else if (!(std::abs(p.value_mm - std::hypot(p.x_mm, p.y_mm)) <=
                   1e-9 * std::max(1.0, std::hypot(p.x_mm, p.y_mm))))
            out.push_back(makeError(field + QStringLiteral(".value_mm"),
                                    MeasuredParts::tr("a CMM point's radius %1 mm is not √(x² + y²) = %2 mm")
                                        .arg(formatNumber(p.value_mm), formatNumber(std::hypot(p.x_mm, p.y_mm)))));
        else if (p.value_mm > rMax + kMaxRadialDeviation_mm || p.value_mm < rMin - kMaxRadialDeviation_mm)
            out.push_back(
                makeError(field + QStringLiteral(".x_mm"),
                          MeasuredParts::tr("a CMM point at radius %1 mm is not on feature %2 (R%3 to R%4 mm)")
                              .arg(formatNumber(p.value_mm), p.featureId, formatNumber(rMin), formatNumber(rMax))));
    } else if (p.quantity == MeasuredQuantity::Diameter) {
        // Against the feature's own diameters: a measured size a millimetre off is another part.
        const double d = 2.0 * std::max(s->from.r_mm, s->to.r_mm) + 2.0 * kMaxRadialDeviation_mm;
        if (!std::isfinite(p.value_mm) || p.value_mm <= 0.0 || p.value_mm > d ||
            p.value_mm < 2.0 * std::min(s->from.r_mm, s->to.r_mm) - 2.0 * kMaxRadialDeviation_mm)
            out.push_back(makeError(field + QStringLiteral(".value_mm"),
                                    MeasuredParts::tr("a diameter of %1 mm does not fit feature %2 (Ø%3 to Ø%4 mm)")
                                        .arg(formatNumber(p.value_mm), p.featureId,
                                             formatNumber(2.0 * std::min(s->from.r_mm, s->to.r_mm)),
                                             formatNumber(2.0 * std::max(s->from.r_mm, s->to.r_mm)))));
    } else if (!std::isfinite(p.value_mm) || std::abs(p.value_mm) > kMaxRadialDeviation_mm) {
        out.push_back(makeError(field + QStringLiteral(".value_mm"),
                                MeasuredParts::tr("a radial deviation of %1 mm is beyond the ±%2 mm of a turned part")
                                    .arg(formatNumber(p.value_mm), formatNumber(kMaxRadialDeviation_mm))));
    }
}

} // namespace

MeasuredPoint cmmPoint(const QString &featureId, double x_mm, double y_mm, double z_mm)
{
    return {featureId, z_mm, MeasuredQuantity::CmmPoint, std::hypot(x_mm, y_mm), x_mm, y_mm};
}

QString keyword(MeasuredQuantity quantity)
{
    switch (quantity) {
    case MeasuredQuantity::Diameter:
        return QStringLiteral("diameter");
    case MeasuredQuantity::RadialDeviation:
        return QStringLiteral("radial_deviation");
    case MeasuredQuantity::CmmPoint:
        return QStringLiteral("cmm_point");
    }
    return {};
}

std::optional<MeasuredQuantity> measuredQuantityFromKeyword(const QString &text)
{
    if (text == QLatin1String("diameter"))
        return MeasuredQuantity::Diameter;
    if (text == QLatin1String("radial_deviation"))
        return MeasuredQuantity::RadialDeviation;
    if (text == QLatin1String("cmm_point"))
        return MeasuredQuantity::CmmPoint;
    return std::nullopt;
}

Diagnostics validateMeasuredPart(const MeasuredPart &part)
{
    Diagnostics out;
    if (part.machineId.trimmed().isEmpty())
        out.push_back(
            makeError(QStringLiteral("machine"), MeasuredParts::tr("the machine the part was cut on is not given")));
    if (!part.measuredAt.isValid())
        out.push_back(
            makeError(QStringLiteral("measured_at"), MeasuredParts::tr("the time of measurement is not given")));
    if (part.timeSinceStart_min && (!std::isfinite(*part.timeSinceStart_min) || *part.timeSinceStart_min < 0.0 ||
                                    *part.timeSinceStart_min > kMaxTimeSinceStart_min))
        out.push_back(
            makeError(QStringLiteral("time_since_start_min"),
                      MeasuredParts::tr("the time since start must be from 0 to %1 min, not %2")
                          .arg(formatNumber(kMaxTimeSinceStart_min), formatNumber(*part.timeSinceStart_min))));
    if (part.ambient_C &&
        (!std::isfinite(*part.ambient_C) || *part.ambient_C < kMinAmbient_C || *part.ambient_C > kMaxAmbient_C))
        out.push_back(makeError(
            QStringLiteral("ambient_C"),
            MeasuredParts::tr("the ambient temperature must be from %1 to %2 °C, not %3")
                .arg(formatNumber(kMinAmbient_C), formatNumber(kMaxAmbient_C), formatNumber(*part.ambient_C))));
    const ProjectParseResult snapshot = parseProjectJson(part.projectJson);
    if (!snapshot.project) {
        out.push_back(makeError(QStringLiteral("project"),
                                MeasuredParts::tr("the project the part was cut from is not a valid project%1")
                                    .arg(snapshot.diagnostics.empty()
                                             ? QString()
                                             : QStringLiteral(": ") + snapshot.diagnostics.front().toString())));
        return out;
    }
    // The snapshot is computed as it was planned, on its own machine: a part cut on another
    // machine would be learned against the wrong machine's physics.
    if (!part.machineId.trimmed().isEmpty() && snapshot.project->machineId != part.machineId)
        out.push_back(makeError(QStringLiteral("machine"),
                                MeasuredParts::tr("the part was cut on %1, but its project is planned for %2: set the "
                                                  "project's machine to %1 as it was cut, then store the part")
                                    .arg(part.machineId, snapshot.project->machineId)));
    if (part.drive) {
        const Diagnostics drive = validateDriveReading(*part.drive, QStringLiteral("drive"));
        out.insert(out.end(), drive.begin(), drive.end());
    }
    if (part.points.empty())
        out.push_back(makeError(QStringLiteral("points"), MeasuredParts::tr("the part has no measured point")));
    for (std::size_t i = 0; i < part.points.size(); ++i)
        checkPoint(part.points[i], snapshot.project->part, QStringLiteral("points[%1]").arg(i), out);
    return out;
}

} // namespace tolturn
