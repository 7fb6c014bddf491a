// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/milled_feature_output.h"

#include "core/project/keywords.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QTextStream>

#include <numbers>

namespace tolturn {

namespace {

struct MilledFeatureOutput {
    Q_DECLARE_TR_FUNCTIONS(MilledFeatureOutput)
};

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

const MilledFeature *featureById(const Project &project, const QString &id)
{
    for (const MilledFeature &f : project.milledFeatures) {
        if (f.id == id)
            return &f;
    }
    return nullptr;
}

QString zoneKeyword(SurfaceZone zone)
{
    return zone == SurfaceZone::Located ? QStringLiteral("located") : QStringLiteral("floating");
}

QJsonArray pathJson(const std::vector<MilledPathPoint> &path)
{
    QJsonArray points;
    for (const MilledPathPoint &p : path)
        points.append(QJsonObject{{QStringLiteral("arc_length_mm"), p.station.arcLength_mm},
                                  {QStringLiteral("lead_deg"), p.station.angles.lead_rad * kDegPerRad},
                                  {QStringLiteral("tilt_deg"), p.station.angles.tilt_rad * kDegPerRad},
                                  {QStringLiteral("least_normal_um"), 1000.0 * p.leastNormal_mm},
                                  {QStringLiteral("greatest_normal_um"), 1000.0 * p.greatestNormal_mm}});
    return points;
}

QJsonObject evaluationJson(const MilledFeature *feature, const MilledFeatureEvaluation &e)
{
    QJsonObject o{{QStringLiteral("id"), e.featureId}, {QStringLiteral("evaluated"), e.evaluated()}};
    if (feature)
        o.insert(QStringLiteral("kind"), keyword(feature->kind));
    if (!e.missing.isEmpty())
        o.insert(QStringLiteral("missing"), QJsonArray::fromStringList(e.missing));
    if (!e.refusal.isEmpty())
        o.insert(QStringLiteral("refusal"), e.refusal);
    if (!e.evaluated())
        return o;
    o.insert(QStringLiteral("tolerance_um"), 1000.0 * e.tolerance.tolerance_mm);
    o.insert(QStringLiteral("zone"), zoneKeyword(e.tolerance.zone));
    o.insert(QStringLiteral("form_error_um"), 1000.0 * e.formError_mm);
    o.insert(QStringLiteral("margin_um"), 1000.0 * e.margin_mm);
    o.insert(QStringLiteral("passes"), e.passes);
    o.insert(QStringLiteral("holding_feed_per_tooth_mm"), e.holdingFeedPerTooth_mm);
    o.insert(QStringLiteral("peak_force_N"), e.forces.peakResultant_N);
    o.insert(QStringLiteral("mean_torque_N_mm"), e.forces.meanTorque_N_mm);
    o.insert(QStringLiteral("spindle_power_W"), e.spindlePower_W);
    o.insert(QStringLiteral("carbide_modulus_assumed"), e.carbideAssumed);
    o.insert(QStringLiteral("path"), pathJson(e.path));
    return o;
}

QString verdictLine(const MilledFeatureEvaluation &e)
{
    if (!e.missing.isEmpty())
        return MilledFeatureOutput::tr("not evaluated: it lacks %1").arg(e.missing.join(QStringLiteral(", ")));
    if (!e.refusal.isEmpty())
        return MilledFeatureOutput::tr("not evaluated: %1").arg(e.refusal);
    const QString zone = e.tolerance.zone == SurfaceZone::Located ? MilledFeatureOutput::tr("located")
                                                                  : MilledFeatureOutput::tr("floating");
    const QString head = MilledFeatureOutput::tr("form error %1 µm of %2 µm (%3 zone): ")
                             .arg(1000.0 * e.formError_mm, 0, 'f', 2)
                             .arg(1000.0 * e.tolerance.tolerance_mm, 0, 'f', 1)
                             .arg(zone);
    if (e.passes)
        return head + MilledFeatureOutput::tr("passes by %1 µm").arg(1000.0 * e.margin_mm, 0, 'f', 2);
    const QString fails = head + MilledFeatureOutput::tr("fails by %1 µm").arg(-1000.0 * e.margin_mm, 0, 'f', 2);
    if (e.holdingFeedPerTooth_mm > 0.0)
        return fails + MilledFeatureOutput::tr("; holds at a feed per tooth up to %1 mm")
                           .arg(e.holdingFeedPerTooth_mm, 0, 'f', 4);
    return fails + MilledFeatureOutput::tr("; no feed up to the planned one holds");
}

} // namespace

QJsonArray milledFeaturesJson(const Project &project, const std::vector<MilledFeatureEvaluation> &evaluations)
{
    QJsonArray list;
    for (const MilledFeatureEvaluation &e : evaluations)
        list.append(evaluationJson(featureById(project, e.featureId), e));
    return list;
}

void printMilledFeatures(const Project &project, const std::vector<MilledFeatureEvaluation> &evaluations,
                         QTextStream &out)
{
    if (evaluations.empty())
        return;
    out << '\n' << MilledFeatureOutput::tr("Milled features (five-axis ball-end model, Öztürk & Budak):") << '\n';
    for (const MilledFeatureEvaluation &e : evaluations) {
        const MilledFeature *f = featureById(project, e.featureId);
        out << QStringLiteral("%1 %2 ").arg(e.featureId, -10).arg(f ? displayName(f->kind) : QString(), -14);
        if (f)
            out << MilledFeatureOutput::tr("z %1–%2 mm  ").arg(f->zFrom_mm).arg(f->zTo_mm);
        out << verdictLine(e) << '\n';
        if (e.carbideAssumed)
            out << QStringLiteral("           ")
                << MilledFeatureOutput::tr("the tool's modulus is not given: carbide's %1 N/mm² (MakeItFrom)")
                       .arg(kCarbideModulus_N_mm2)
                << '\n';
    }
}

} // namespace tolturn
