// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/report/milling_section.h"

#include "core/common/diagnostic.h"
#include "core/milling/milled_features.h"
#include "core/project/keywords.h"
#include "widgets/plot/line_plot.h"
#include "widgets/profile/profile_scene.h"
#include "widgets/tolerances/tolerance_verdict_model.h"

#include <QCoreApplication>

#include <algorithm>
#include <vector>

namespace tolturn::report {

namespace {

struct MillingReport {
    Q_DECLARE_TR_FUNCTIONS(MillingReport)
};

constexpr double kUmPerMm = 1000.0;
constexpr double kPlotHeight = 190.0; // as the deviation plots: room for the legend's four entries

// 630000 as "630 000": thousands apart, as the docs write the modulus.
QString grouped(double value)
{
    QString digits = QString::number(value, 'f', 0);
    for (qsizetype at = digits.size() - 3; at > (digits.startsWith(QLatin1Char('-')) ? 1 : 0); at -= 3)
        digits.insert(at, QLatin1Char(' '));
    return digits;
}

QString toolText(const MilledFeature &f)
{
    if (!f.tool)
        return QStringLiteral("—");
    const BallEndTool &t = *f.tool;
    return t.flutes == 1 ? MillingReport::tr("Ø%1 mm, 1 flute, helix %2°")
                               .arg(formatNumber(t.diameter_mm), formatNumber(t.helix_deg))
                         : MillingReport::tr("Ø%1 mm, %2 flutes, helix %3°")
                               .arg(formatNumber(t.diameter_mm))
                               .arg(t.flutes)
                               .arg(formatNumber(t.helix_deg));
}

QString conditionsText(const MilledFeature &f)
{
    if (!f.conditions)
        return QStringLiteral("—");
    const MillingConditions &c = *f.conditions;
    QString text =
        QStringLiteral("%1, %2; a %3 mm")
            .arg(displayName(c.cut), c.direction == MillingDirection::Down ? MillingReport::tr("down milling")
                                                                           : MillingReport::tr("up milling"))
            .arg(formatNumber(c.axialDepth_mm));
    if (c.cut != BallEndCutKind::Slot)
        text += MillingReport::tr(", s %1 mm").arg(formatNumber(c.radialDepth_mm));
    text +=
        MillingReport::tr("; f_z %1 mm; %2 rpm; ").arg(formatNumber(c.feedPerTooth_mm), formatNumber(c.spindle_rpm));
    text += f.kind == MilledFeatureKind::Patch
                ? MillingReport::tr("lead and tilt from the path")
                : MillingReport::tr("lead %1°, tilt %2°").arg(formatNumber(c.lead_deg), formatNumber(c.tilt_deg));
    return text;
}

// ISO 1101: a flatness, and a profile without datums, float; a profile with datums is located.
QString toleranceText(const MilledFeature &f)
{
    if (!f.tolerance)
        return QStringLiteral("—");
    const MilledTolerance &t = *f.tolerance;
    const bool profile = t.type == MilledToleranceType::Profile;
    const QString type = profile ? MillingReport::tr("profile") : MillingReport::tr("flatness");
    const QString zone = profile && !t.datums.isEmpty()
                             ? MillingReport::tr("located, datums %1").arg(t.datums.join(QStringLiteral(", ")))
                             : MillingReport::tr("floating");
    return MillingReport::tr("%1 %2 µm, %3").arg(type, formatNumber(t.zone_um), zone);
}

QString verdictText(const MilledFeatureEvaluation &e)
{
    if (!e.missing.isEmpty())
        return MillingReport::tr("not evaluated: lacks %1").arg(e.missing.join(QStringLiteral(", ")));
    if (!e.refusal.isEmpty())
        return MillingReport::tr("refused: %1").arg(e.refusal);
    if (e.passes)
        return MillingReport::tr("passes by %1 µm").arg(num(kUmPerMm * e.margin_mm, 1));
    // The feeds that hold are an interval that need not start at zero (docs/milling.md): the largest
    // is named, not a range below it.
    const QString holding =
        e.holdingFeedPerTooth_mm > 0.0
            ? MillingReport::tr("largest f_z that holds: %1 mm").arg(num(e.holdingFeedPerTooth_mm, 4))
            : MillingReport::tr("no f_z up to the planned one holds");
    return MillingReport::tr("fails by %1 µm; %2").arg(num(-kUmPerMm * e.margin_mm, 1), holding);
}

void featureTable(Layout &l, const Project &p, const std::vector<MilledFeatureEvaluation> &evaluations)
{
    std::vector<QStringList> rows{{MillingReport::tr("ID"), MillingReport::tr("Kind"), MillingReport::tr("z [mm]"),
                                   MillingReport::tr("Tool"), MillingReport::tr("Conditions"),
                                   MillingReport::tr("Tolerance"), MillingReport::tr("Form error [µm]"),
                                   MillingReport::tr("Verdict")}};
    for (std::size_t i = 0; i < p.milledFeatures.size(); ++i) {
        const MilledFeature &f = p.milledFeatures[i];
        const MilledFeatureEvaluation &e = evaluations[i];
        rows.push_back({f.id, displayName(f.kind),
                        QStringLiteral("%1–%2").arg(dimensionText(f.zFrom_mm), dimensionText(f.zTo_mm)), toolText(f),
                        conditionsText(f), toleranceText(f),
                        e.evaluated() ? num(kUmPerMm * e.formError_mm, 1) : QStringLiteral("—"), verdictText(e)});
    }
    l.table(rows, {24, 38, 42, 64, 112, 70, 40, kWidth - 390}, [&](int row, int column) {
        const MilledFeatureEvaluation &e = evaluations[static_cast<std::size_t>(row - 1)];
        if (column != 7 || !e.evaluated())
            return QColor();
        return ToleranceVerdictModel::verdictColor(e.passes ? Verdict::PassesAsProgrammed
                                                            : Verdict::NeedsProfileCorrection);
    });
}

// What a feature's verdict rests on beyond its own values: carbide's modulus when the tool's is not
// given, and the planner's cutting coefficients (none are bundled: docs/milling.md).
void assumptionLines(Layout &l, const Project &p, const std::vector<MilledFeatureEvaluation> &evaluations)
{
    for (std::size_t i = 0; i < p.milledFeatures.size(); ++i) {
        const MilledFeature &f = p.milledFeatures[i];
        QStringList notes;
        if (evaluations[i].carbideAssumed)
            notes << MillingReport::tr("E of the tool not given: carbide's %1 N/mm² (MakeItFrom)")
                         .arg(grouped(kCarbideModulus_N_mm2));
        if (f.coefficients)
            notes << (f.coefficientsSource.trimmed().isEmpty()
                          ? MillingReport::tr("coefficients without a source")
                          : MillingReport::tr("coefficients: %1").arg(f.coefficientsSource.trimmed()));
        if (!notes.isEmpty())
            l.paragraph(QStringLiteral("%1: %2.").arg(f.id, notes.join(QStringLiteral("; "))), 8.0);
    }
}

// δ_N's range along the path between the limits of the tolerance zone: a floating zone of width t
// centred on the middle of the spread (where it fits best), a located one at ±t/2.
void errorPlot(Layout &l, const MilledFeature &f, const MilledFeatureEvaluation &e)
{
    if (e.path.empty())
        return;
    QVector<double> x;
    QVector<double> least;
    QVector<double> greatest;
    for (const MilledPathPoint &point : e.path) {
        x << point.station.arcLength_mm;
        least << kUmPerMm * point.leastNormal_mm;
        greatest << kUmPerMm * point.greatestNormal_mm;
    }
    const double t_um = kUmPerMm * e.tolerance.tolerance_mm;
    const double centre = e.tolerance.zone == SurfaceZone::Floating
                              ? 0.5 * (*std::min_element(least.begin(), least.end()) +
                                       *std::max_element(greatest.begin(), greatest.end()))
                              : 0.0;
    const QVector<double> ends{x.front(), x.back()};
    LinePlot plot;
    plot.addCurve(MillingReport::tr("δ_N, least"), x, least, QColor(31, 119, 180));
    plot.addCurve(MillingReport::tr("δ_N, greatest"), x, greatest, QColor(255, 127, 14));
    const QColor zone(214, 39, 40);
    plot.addCurve(MillingReport::tr("zone, lower"), ends, {centre - 0.5 * t_um, centre - 0.5 * t_um}, zone,
                  Qt::DashLine, 1.0);
    plot.addCurve(MillingReport::tr("zone, upper"), ends, {centre + 0.5 * t_um, centre + 0.5 * t_um}, zone,
                  Qt::DashLine, 1.0);
    plot.setAxisLabels(MillingReport::tr("arc length along the path [mm]"),
                       MillingReport::tr("surface-normal error δ_N [µm]"));
    plot.rescaleAndReplot();
    l.ensure(kPlotHeight + 22);
    l.caption(MillingReport::tr("%1: surface-normal error along the path (%2 zone)")
                  .arg(f.id, e.tolerance.zone == SurfaceZone::Floating ? MillingReport::tr("floating")
                                                                       : MillingReport::tr("located")));
    l.block(kPlotHeight, [&](QPainter &painter, const QRectF &r) { plot.render(&painter, r, kPlotTextScale); });
    l.paragraph(MillingReport::tr("%1: largest force on the tool %2 N, mean torque %3 N·m, spindle power %4 W.")
                    .arg(f.id, num(e.forces.peakResultant_N, 0), num(e.forces.meanTorque_N_mm / 1000.0, 2),
                         num(e.spindlePower_W, 0)),
                8.0);
}

} // namespace

std::optional<std::vector<MilledFeatureEvaluation>> evaluateMilledFeatures(const Project &project,
                                                                           const Progress &progress)
{
    std::vector<MilledFeatureEvaluation> evaluations;
    const auto count = static_cast<double>(project.milledFeatures.size());
    for (const MilledFeature &f : project.milledFeatures) {
        evaluations.push_back(evaluateMilledFeature(f));
        if (!progress.report(static_cast<double>(evaluations.size()) / count))
            return std::nullopt;
    }
    return evaluations;
}

void milledFeaturesSection(Layout &layout, const Project &project, const QString &heading,
                           const std::vector<MilledFeatureEvaluation> &evaluations)
{
    if (project.milledFeatures.empty())
        return;
    layout.ensure(160); // the heading, the paragraph and the table's first row together
    layout.heading(heading);
    layout.paragraph(
        MillingReport::tr("Each milled feature is evaluated with Öztürk & Budak's ball-end model [9]: the forces "
                          "bend the tool and leave the surface-normal error δ_N (its range over a "
                          "revolution at each point of the path). The form error is the spread of δ_N "
                          "along the path for a floating zone, twice its largest magnitude for a located "
                          "one (ISO 1101 [6])."),
        8.5);
    featureTable(layout, project, evaluations);
    assumptionLines(layout, project, evaluations);
    for (std::size_t i = 0; i < evaluations.size(); ++i)
        if (evaluations[i].evaluated())
            errorPlot(layout, project.milledFeatures[i], evaluations[i]);
}

} // namespace tolturn::report
