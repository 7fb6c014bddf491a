// SPDX-License-Identifier: GPL-3.0-or-later
// check's findings on a project's milled features (milled_features.h, docs/milling.md).
#include "core/milling/milled_features.h"
#include "core/project/keywords.h"

#include <QCoreApplication>
#include <QSet>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tolturn {

namespace {

struct MilledFeatureCheck {
    Q_DECLARE_TR_FUNCTIONS(MilledFeatureCheck)
};

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

void addErrors(const std::vector<std::string> &problems, const QString &field, Diagnostics &out)
{
    for (const std::string &p : problems)
        out.push_back(makeError(field, QString::fromStdString(p)));
}

void checkIdentity(const Project &p, const MilledFeature &f, const QString &path, QSet<QString> &ids, Diagnostics &out)
{
    if (f.id.trimmed().isEmpty())
        out.push_back(makeError(path + QStringLiteral("id"), MilledFeatureCheck::tr("a milled feature needs an id")));
    else if (ids.contains(f.id))
        out.push_back(makeError(path + QStringLiteral("id"),
                                MilledFeatureCheck::tr("id '%1' is already another milled feature's").arg(f.id)));
    else if (findFeature(p.part, f.id))
        out.push_back(makeError(path + QStringLiteral("id"),
                                MilledFeatureCheck::tr("id '%1' is already a feature of the profile").arg(f.id)));
    ids.insert(f.id);
    const double length = p.part.length_mm();
    if (!(f.zFrom_mm >= 0.0 && f.zFrom_mm <= f.zTo_mm && f.zTo_mm <= length))
        out.push_back(
            makeError(path + QStringLiteral("z_from_mm"),
                      MilledFeatureCheck::tr("z from %1 mm to %2 mm is not a range within the part, 0 to %3 mm")
                          .arg(formatNumber(f.zFrom_mm), formatNumber(f.zTo_mm), formatNumber(length))));
}

void checkTool(const MilledFeature &f, const QString &path, Diagnostics &out)
{
    const BallEndTool &t = *f.tool;
    const BallEndMill mill{t.diameter_mm, t.flutes, t.helix_deg * kRadPerDeg};
    if (!(t.diameter_mm > 0.0))
        out.push_back(makeError(path + QStringLiteral("tool.diameter_mm"),
                                MilledFeatureCheck::tr("tool diameter: %1 mm is not positive").arg(t.diameter_mm)));
    if (t.flutes < 1 || t.flutes > 12)
        out.push_back(makeError(path + QStringLiteral("tool.flutes"),
                                MilledFeatureCheck::tr("flutes: %1 is not 1 to 12").arg(t.flutes)));
    if (!(t.helix_deg >= 0.0 && t.helix_deg < 60.0))
        out.push_back(makeError(path + QStringLiteral("tool.helix_deg"),
                                MilledFeatureCheck::tr("helix angle: %1° is not 0 to 60°").arg(t.helix_deg)));
    // Springs not given are reported as missing (below), not as a zero out of range: any positive
    // value stands in for them here, and only the other fields are judged.
    const BallEndToolStructure structure{
        t.overhang_mm, t.equivalentDiameter_mm, t.youngsModulus_N_mm2.value_or(kCarbideModulus_N_mm2),
        t.holderStiffness_N_mm.value_or(1.0), t.holderRotational_N_mm_rad.value_or(1.0)};
    addErrors(validateToolStructure(structure, mill), path + QStringLiteral("tool"), out);
}

void checkCut(const MilledFeature &f, const QString &path, Diagnostics &out)
{
    const BallEndTool tool = f.tool.value_or(BallEndTool{});
    const MillingConditions &c = *f.conditions;
    const BallEndMill mill{tool.diameter_mm, tool.flutes, tool.helix_deg * kRadPerDeg};
    BallEndCut cut{c.cut,
                   c.direction,
                   c.axialDepth_mm,
                   c.radialDepth_mm,
                   c.feedPerTooth_mm,
                   c.lead_deg * kRadPerDeg,
                   c.tilt_deg * kRadPerDeg};
    if (!(c.spindle_rpm > 0.0))
        out.push_back(makeError(path + QStringLiteral("conditions.spindle_rpm"),
                                MilledFeatureCheck::tr("spindle speed: %1 rpm is not positive").arg(c.spindle_rpm)));
    if (!f.tool)
        return; // the cut is judged on the tool it is cut with
    if (f.kind != MilledFeatureKind::Patch) {
        addErrors(validateBallEndCut(mill, cut, {}), path + QStringLiteral("conditions"), out);
        return;
    }
    try {
        const std::vector<PathStation> stations = pathStations(f.path, 0.5 * mill.diameter_mm);
        for (std::size_t i = 0; i < stations.size(); ++i) {
            cut.lead_rad = stations[i].angles.lead_rad;
            cut.tilt_rad = stations[i].angles.tilt_rad;
            const std::vector<std::string> problems = validateBallEndCut(mill, cut, {});
            if (!problems.empty()) {
                addErrors(problems, path + QStringLiteral("path[%1]").arg(i), out);
                return; // one point says it: the same cut fails at the next ones
            }
        }
    } catch (const std::invalid_argument &) {
        return; // checkPath names it
    }
}

// A patch's path on its own, whether or not its tool and cut are given yet.
void checkPath(const MilledFeature &f, const QString &path, Diagnostics &out)
{
    if (f.kind != MilledFeatureKind::Patch || f.path.size() < 2)
        return;
    try {
        (void)pathStations(f.path, f.tool ? 0.5 * f.tool->diameter_mm : 0.0);
    } catch (const std::invalid_argument &refused) {
        out.push_back(makeError(path + QStringLiteral("path"), QString::fromStdString(refused.what())));
    }
}

void checkCoefficients(const MilledFeature &f, const QString &path, Diagnostics &out)
{
    const MillingForceCoefficients &k = *f.coefficients;
    const std::pair<const char *, double> values[] = {
        {"Ktc_N_mm2", k.tangentialCutting_N_mm2}, {"Krc_N_mm2", k.radialCutting_N_mm2},
        {"Kac_N_mm2", k.axialCutting_N_mm2},      {"Kte_N_mm", k.tangentialEdge_N_mm},
        {"Kre_N_mm", k.radialEdge_N_mm},          {"Kae_N_mm", k.axialEdge_N_mm}};
    for (const auto &[key, v] : values) {
        if (!(std::abs(v) <= kMaxMillingCoefficient))
            out.push_back(makeError(path + QStringLiteral("coefficients.") + QLatin1String(key),
                                    MilledFeatureCheck::tr("%1 is beyond ±%2 (TolTurn's bound)")
                                        .arg(formatNumber(v), formatNumber(kMaxMillingCoefficient))));
    }
    if (!(k.tangentialCutting_N_mm2 > 0.0))
        out.push_back(
            makeError(path + QStringLiteral("coefficients.Ktc_N_mm2"),
                      MilledFeatureCheck::tr("K_tc: %1 N/mm² is not positive").arg(k.tangentialCutting_N_mm2)));
    if (f.coefficientsSource.trimmed().isEmpty())
        out.push_back(
            makeWarning(path + QStringLiteral("coefficients.source"),
                        MilledFeatureCheck::tr("the cutting coefficients have no source: the verdict rests on "
                                               "numbers nobody can trace")));
}

void checkTolerance(const Project &p, const MilledFeature &f, const QString &path, Diagnostics &out)
{
    const MilledTolerance &t = *f.tolerance;
    if (!(t.zone_um > 0.0))
        out.push_back(makeError(path + QStringLiteral("tolerance.value_um"),
                                MilledFeatureCheck::tr("tolerance zone: %1 µm is not positive").arg(t.zone_um)));
    if (t.type == MilledToleranceType::Flatness && !t.datums.isEmpty())
        out.push_back(makeError(path + QStringLiteral("tolerance.datums"),
                                MilledFeatureCheck::tr("a flatness has no datums (ISO 1101), found %1")
                                    .arg(t.datums.join(QStringLiteral(", ")))));
    QSet<QString> labels;
    for (const Datum &d : p.datums)
        labels.insert(d.label);
    for (qsizetype j = 0; j < t.datums.size(); ++j) {
        if (!labels.contains(t.datums.at(j)))
            out.push_back(
                makeError(path + QStringLiteral("tolerance.datums[%1]").arg(j),
                          MilledFeatureCheck::tr("there is no datum '%1' in the project").arg(t.datums.at(j))));
    }
}

void checkOne(const Project &p, const MilledFeature &f, const QString &path, QSet<QString> &ids, Diagnostics &out)
{
    checkIdentity(p, f, path, ids, out);
    checkPath(f, path, out);
    if (f.kind != MilledFeatureKind::Patch && !f.path.empty())
        out.push_back(makeWarning(
            path + QStringLiteral("path"),
            MilledFeatureCheck::tr("a %1 is one straight cut: its CL points are not used").arg(keyword(f.kind))));
    if (f.tool)
        checkTool(f, path, out);
    if (f.conditions)
        checkCut(f, path, out);
    if (f.coefficients)
        checkCoefficients(f, path, out);
    if (f.tolerance)
        checkTolerance(p, f, path, out);
    QStringList missing;
    if (!milledFeatureInputs(f, missing))
        out.push_back(
            makeWarning(path.chopped(1), MilledFeatureCheck::tr("milled feature %1 is not evaluated: it lacks %2")
                                             .arg(f.id, missing.join(QStringLiteral(", ")))));
}

} // namespace

void checkMilledFeatures(const Project &project, Diagnostics &out)
{
    QSet<QString> ids;
    for (std::size_t i = 0; i < project.milledFeatures.size(); ++i)
        checkOne(project, project.milledFeatures[i], QStringLiteral("milled_features[%1].").arg(i), ids, out);
}

} // namespace tolturn
