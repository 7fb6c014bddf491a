// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/input_bounds.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QRegularExpression>

#include <cmath>

namespace tolturn {

namespace {

struct InputBounds {
    Q_DECLARE_TR_FUNCTIONS(InputBounds)
};

// 10 m long and 5 m across: TolTurn's largest part. The cutting conditions are the entry limits
// of the Set-up dock, above every insert maker's range; the rest bound the numbers so that
// products of them (forces, stiffness, costs) stay far inside the range of a double.
constexpr double kMaxLength_mm = 10000.0;
constexpr double kMaxRadius_mm = 2500.0;

std::vector<InputBound> makeBounds()
{
    const QString mm = QStringLiteral("mm");
    // Regular expressions over the field path, list indices written "[]".
    return {
        {QStringLiteral(R"(part\.stock_diameter_mm)"), 2.0 * kMaxRadius_mm, mm},
        {QStringLiteral(R"(part\.(outer|inner)\[\]\.(from|to)\.z_mm)"), kMaxLength_mm, mm},
        {QStringLiteral(R"(part\.(outer|inner)\[\]\.((from|to)\.r_mm|radius_mm))"), kMaxRadius_mm, mm},
        {QStringLiteral(
             R"((further_operations\[\]\.)?clamping\.clamped_length_mm|characterisation\.pivot_distance_mm)"),
         kMaxLength_mm, mm},
        {QStringLiteral(R"((further_operations\[\]\.)?(boring_)?tool\.(overhang|edge_offset)_mm)"), 1000.0, mm},
        {QStringLiteral(R"((further_operations\[\]\.)?(boring_)?tool\.pilot_hole_diameter_mm)"), 2.0 * kMaxRadius_mm,
         mm},
        {QStringLiteral(R"((further_operations\[\]\.)?(boring_)?tool\.(rake|inclination)_deg)"), 90.0,
         QStringLiteral("°")},
        {QStringLiteral(
             R"(((further_operations\[\]\.)?passes\[\]|planning\.ranges)\.cutting_speed_m_min(\.min|\.max)?)"),
         2000.0, QStringLiteral("m/min")},
        {QStringLiteral(R"(((further_operations\[\]\.)?passes\[\]|planning\.ranges)\.feed_mm_rev(\.min|\.max)?)"), 5.0,
         QStringLiteral("mm/rev")},
        {QStringLiteral(R"(((further_operations\[\]\.)?passes\[\]|planning\.ranges)\.depth_of_cut_mm(\.min|\.max)?)"),
         50.0, mm},
        {QStringLiteral(R"(tolerances\[\]\.(upper|lower|value)_um)"), 100000.0, QStringLiteral("µm")},
        {QStringLiteral(R"(cutting_model\.(feed|passive)_to_cutting_ratio)"), 5.0, QString()},
        {QStringLiteral(R"(cutting_model\.normal_pressure_MPa)"), 100000.0, QStringLiteral("MPa")},
        {QStringLiteral(R"(cutting_model\.friction_ratio)"), 10.0, QString()},
        {QStringLiteral(R"(.*temperature_C)"), 1000.0, QStringLiteral("°C")},
        {QStringLiteral(R"(planning\.tool_life\.n)"), 1.0, QString()},
        {QStringLiteral(R"(.*)"), 1e12, QString()},
    };
}

// "part.outer[3].to.z_mm" as the patterns write it: "part.outer[].to.z_mm".
QString withoutIndices(const QString &path)
{
    static const QRegularExpression index(QStringLiteral("\\[\\d+\\]"));
    return QString(path).replace(index, QStringLiteral("[]"));
}

const InputBound &boundFor(const QString &path)
{
    static const std::vector<QRegularExpression> patterns = [] {
        std::vector<QRegularExpression> compiled;
        for (const InputBound &b : inputBounds())
            compiled.emplace_back(QStringLiteral("^(?:%1)$").arg(b.pattern));
        return compiled;
    }();
    const QString generic = withoutIndices(path);
    for (std::size_t i = 0; i < patterns.size(); ++i) {
        if (patterns[i].match(generic).hasMatch())
            return inputBounds()[i];
    }
    return inputBounds().back();
}

// The most entries a list may hold: a contour of a thousand segments is far beyond a drawn part
// (the examples have up to 11) and keeps the deflection computation, which grows with the square
// of the segments, to seconds; the plan has at most 100 roughing passes and one finishing pass.
qsizetype longestList(const QString &path)
{
    if (path == QLatin1String("part.outer") || path == QLatin1String("part.inner") ||
        path == QLatin1String("tolerances") || path == QLatin1String("datums"))
        return 1000;
    if (path == QLatin1String("passes") || path.endsWith(QLatin1String(".passes")))
        return 101;
    if (path == QLatin1String("further_operations"))
        return 100;
    return 10000;
}

void check(const QJsonValue &v, const QString &path, Diagnostics &out)
{
    if (v.isDouble()) {
        const double x = v.toDouble();
        const InputBound &b = boundFor(path);
        if (!std::isfinite(x) || std::abs(x) > b.max)
            out.push_back(makeError(path, InputBounds::tr("%1 is beyond what TolTurn computes with: at most %2%3")
                                              .arg(formatNumberExactly(x), formatNumber(b.max),
                                                   b.unit.isEmpty() ? QString() : QStringLiteral(" ") + b.unit)));
    } else if (v.isArray()) {
        const QJsonArray array = v.toArray();
        if (const qsizetype most = longestList(path); array.size() > most) {
            out.push_back(makeError(path, InputBounds::tr("holds %1 entries, more than the %2 TolTurn computes with")
                                              .arg(array.size())
                                              .arg(most)));
            return;
        }
        for (qsizetype i = 0; i < array.size(); ++i)
            check(array.at(i), QStringLiteral("%1[%2]").arg(path).arg(i), out);
    } else if (v.isObject()) {
        const QJsonObject object = v.toObject();
        for (auto it = object.begin(); it != object.end(); ++it)
            check(it.value(), path.isEmpty() ? it.key() : path + QLatin1Char('.') + it.key(), out);
    }
}

} // namespace

const std::vector<InputBound> &inputBounds()
{
    static const std::vector<InputBound> bounds = makeBounds();
    return bounds;
}

void checkInputBounds(const QJsonObject &project, Diagnostics &out)
{
    check(project, QString(), out);
}

} // namespace tolturn
