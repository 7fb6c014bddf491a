// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/compensation.h"

#include "core/tolerance/target_contour.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {

struct Compensation {
    Q_DECLARE_TR_FUNCTIONS(Compensation)
};

constexpr double kUmPerMm = 1000.0;

// Rounds a programmed radius so that the diameter is a whole micrometre (the path's resolution).
double toResolution(double radius_mm)
{
    return std::round(2.0 * radius_mm * kUmPerMm) / (2.0 * kUmPerMm);
}

int severity(Verdict v)
{
    switch (v) {
    case Verdict::NeedsProfileCorrection:
        return 2;
    case Verdict::PassesAfterOffset:
        return 1;
    default:
        return 0;
    }
}

} // namespace

const FeatureCompensation *CompensationPlan::find(const QString &featureId) const
{
    for (const FeatureCompensation &f : features) {
        if (f.featureId == featureId)
            return &f;
    }
    return nullptr;
}

QStringList correctionsBeyondTheCut(const CompensationPlan &plan, double depthOfCut_mm)
{
    QStringList out;
    for (const FeatureCompensation &c : plan.features) {
        if (c.action == CompensationAction::None || c.residualBefore_um <= depthOfCut_mm * 1000.0)
            continue;
        out << Compensation::tr("%1: the correction, %2 µm, is larger than the finishing depth of cut "
                                "%3 mm: the prediction, made for that depth, does not hold there and the "
                                "correction is not a program to run; support the part (tailstock, steady rest), "
                                "cut less or check the machine's data")
                   .arg(c.featureId, QString::number(c.residualBefore_um, 'f', 1), formatNumber(depthOfCut_mm));
    }
    return out;
}

QString compensationKeyword(CompensationAction action)
{
    switch (action) {
    case CompensationAction::None:
        return QStringLiteral("none");
    case CompensationAction::ConstantOffset:
        return QStringLiteral("offset");
    case CompensationAction::ProfileCorrection:
        return QStringLiteral("profile");
    }
    return {};
}

CompensationPlan planCompensation(const Project &project, const DeviationResult &deviation,
                                  const std::vector<ToleranceEvaluation> &verdicts)
{
    CompensationPlan plan;
    const Contour targets[] = {targetContour(project, ContourSide::Outer), targetContour(project, ContourSide::Inner)};
    for (const FeatureDeviation &f : deviation.features) {
        const Contour &target = targets[f.side == ContourSide::Outer ? 0 : 1];
        FeatureCompensation c;
        c.featureId = f.featureId;
        c.side = f.side;
        int worst = 0;
        double offset = 0.0;
        bool locatedProfile = false; // its zone lies on the exact profile, not on the program's target
        for (std::size_t i = 0; i < project.tolerances.size() && i < verdicts.size(); ++i) {
            const Tolerance &t = project.tolerances[i];
            if (t.featureId != f.featureId)
                continue;
            c.tolerances << t.id;
            locatedProfile = locatedProfile || (t.type == ToleranceType::Profile && profileZoneIsLocated(project, t));
            const int s = severity(verdicts[i].verdict);
            if (s > worst)
                worst = s;
            if (verdicts[i].offset_um)
                offset = *verdicts[i].offset_um;
        }
        // What the feature is to be cut to: the middle of its zone (the target contour), or the exact
        // profile for a located profile; the error from it as the plain program would cut [mm].
        const auto aim = [&](const Station &st) {
            return locatedProfile ? st.nominalRadius_mm
                                  : targetRadius_mm(target, f.featureId, st.z_mm).value_or(st.nominalRadius_mm);
        };
        const auto errorFromAim = [&](const Station &st) {
            return st.radiusError_mm + targetRadius_mm(target, f.featureId, st.z_mm).value_or(st.nominalRadius_mm) -
                   aim(st);
        };
        double before = 0.0;
        for (const Station &st : f.stations)
            before = std::max(before, std::abs(errorFromAim(st)));
        c.residualBefore_um = before * kUmPerMm;
        c.residualAfter_um = c.residualBefore_um;
        if (worst == 1) {
            // A constant offset of the diameter; the radius errors shift by half of it.
            c.action = CompensationAction::ConstantOffset;
            c.offset_um = offset;
            double after = 0.0;
            for (const Station &st : f.stations)
                after = std::max(after, std::abs(errorFromAim(st) * kUmPerMm + 0.5 * offset));
            c.residualAfter_um = after;
        } else if (worst == 2) {
            c.action = CompensationAction::ProfileCorrection;
            // The aim against the deviation: the machined radius is the programmed one plus the
            // radius error (a bore's is the negative of its material left).
            double residual = 0.0;
            for (const Station &st : f.stations) {
                const double programmed = toResolution(aim(st) - st.radiusError_mm);
                c.correctedPath.push_back({st.z_mm, programmed});
                residual = std::max(residual, std::abs(programmed + st.radiusError_mm - aim(st)));
            }
            c.residualAfter_um = residual * kUmPerMm;
        }
        plan.features.push_back(c);
    }
    for (std::size_t i = 0; i < project.tolerances.size() && i < verdicts.size(); ++i) {
        const Tolerance &t = project.tolerances[i];
        const auto feature = findFeature(project.part, t.featureId);
        if (feature && feature->segment->kind == SegmentKind::Face &&
            verdicts[i].verdict == Verdict::NeedsProfileCorrection) {
            FeatureCompensation c;
            c.featureId = t.featureId;
            c.side = feature->side;
            c.tolerances << t.id;
            c.note = Compensation::tr(
                "the face's conicity needs a correction along Z, which TolTurn does not generate: reduce the "
                "feed or change the clamping");
            plan.features.push_back(c);
        }
    }
    return plan;
}

} // namespace tolturn
