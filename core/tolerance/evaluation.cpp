// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/tolerance/evaluation.h"

#include "core/part/profile_geometry.h"
#include "core/project/keywords.h"
#include "core/tolerance/iso286.h"
#include "core/tolerance/target_contour.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {

struct ToleranceVerdicts {
    Q_DECLARE_TR_FUNCTIONS(ToleranceVerdicts)
};

constexpr double kUmPerMm = 1000.0;

// Whether conditions and reasons are written out (evaluateTolerances' `detail`): the optimiser
// calls the evaluation thousands of times per second on several threads and needs only numbers.
thread_local bool t_withText = true;

template <typename Text>
void say(QString &target, Text &&text)
{
    if (t_withText)
        target = text();
}

// A condition of the form "quantity <= t": where it comes from (a figure and equation of Valiño
// et al. 2008) and its left-hand side, each translated where marked with QT_TRANSLATE_NOOP.
struct Rule {
    const char *reference;
    const char *quantity;
};

// The rule as it came out: "Fig. 4c, eq. 16: e_i <= t" when it holds, "... > t" when not.
void sayRule(ToleranceEvaluation &e, const Rule &rule, bool holds)
{
    say(e.condition, [&] {
        const QString reference = QCoreApplication::translate("ToleranceVerdicts", rule.reference);
        const QString quantity = QCoreApplication::translate("ToleranceVerdicts", rule.quantity);
        return holds ? ToleranceVerdicts::tr("%1: %2 <= t").arg(reference, quantity)
                     : ToleranceVerdicts::tr("%1: %2 > t").arg(reference, quantity);
    });
}

const FeatureDeviation *stationsOf(const DeviationResult &r, const QString &id)
{
    for (const FeatureDeviation &f : r.features) {
        if (f.featureId == id && !f.stations.empty())
            return &f;
    }
    return nullptr;
}

const FaceConicity *faceOf(const DeviationResult &r, const QString &id)
{
    for (const FaceConicity &f : r.faces) {
        if (f.featureId == id)
            return &f;
    }
    return nullptr;
}

// Extremes of the radius error along a feature [µm]; not a number when a station's is not finite
// (std::min and std::max would pass over it, and the rest would decide; refuseNonFinite refuses it).
std::pair<double, double> radiusErrorRange_um(const FeatureDeviation &f)
{
    double lo = 1e300;
    double hi = -1e300;
    for (const Station &st : f.stations) {
        if (!std::isfinite(st.radiusError_mm))
            return {std::nan(""), std::nan("")};
        lo = std::min(lo, st.radiusError_mm * kUmPerMm);
        hi = std::max(hi, st.radiusError_mm * kUmPerMm);
    }
    return {lo, hi};
}

void setValue(ToleranceEvaluation &e, double value, double limit)
{
    e.value_um = value;
    e.limit_um = limit;
    e.utilisation_pct = limit > 0.0 ? 100.0 * value / limit : 0.0;
}

void notCut(ToleranceEvaluation &e, const QString &featureId)
{
    e.verdict = Verdict::CannotEvaluate;
    say(e.reason, [&] {
        return QString(ToleranceVerdicts::tr(
                           "feature %1 is not cut in this set-up (it lies in the chuck jaws or outside the supported "
                           "length), so no deviation is predicted for it")
                           .arg(featureId));
    });
}

// Limit deviations of a size tolerance: the ISO 286 class at the nominal size, or explicit limits.
bool sizeLimits(const Tolerance &t, double nominal_mm, ToleranceEvaluation &e)
{
    e.nominal_mm = nominal_mm;
    if (!t.iso286Class.isEmpty()) {
        const iso286::LimitsResult limits = iso286::limits(nominal_mm, t.iso286Class);
        e.diagnostics.insert(e.diagnostics.end(), limits.diagnostics.begin(), limits.diagnostics.end());
        if (!limits.limits) {
            e.verdict = Verdict::CannotEvaluate;
            say(e.reason, [&] {
                return QString(ToleranceVerdicts::tr("the limits of %1 at %2 mm cannot be formed")
                                   .arg(t.iso286Class, formatNumber(nominal_mm)));
            });
            return false;
        }
        e.upper_um = limits.limits->upper_um;
        e.lower_um = limits.limits->lower_um;
        return true;
    }
    e.upper_um = t.upperDeviation_um;
    e.lower_um = t.lowerDeviation_um;
    return e.upper_um && e.lower_um;
}

// Diameter (Fig. 4b): the size must lie within its limits (eq. 13); its form part
// D'_Md - D'_md = 2|delta_TMd - delta_Tmd| (eq. 14) must fit in t (eq. 15). "As programmed" is the
// finishing path programmed to the middle of the tolerance zone, as CNC programs are written; the
// predicted size is that plus twice the radius error.
void evaluateDiameter(const ProgramTargets &targets, const Tolerance &t, const FeatureRef &feature,
                      const DeviationResult &r, ToleranceEvaluation &e)
{
    const FeatureDeviation *f = stationsOf(r, t.featureId);
    if (!f) {
        notCut(e, t.featureId);
        return;
    }
    if (!sizeLimits(t, 2.0 * feature.segment->from.r_mm, e))
        return;
    const auto [lo, hi] = radiusErrorRange_um(*f);
    // What the program aims at (targetContour): the middle of the zone, or of the zone all the
    // feature's diameter tolerances allow; an offset must centre the size in that zone too.
    double aimUpper = *e.upper_um;
    double aimLower = *e.lower_um;
    for (const DiameterTarget &target : targets.diameters) {
        if (target.featureId == t.featureId) {
            aimUpper = target.upper_um;
            aimLower = target.lower_um;
        }
    }
    const double programmed = 0.5 * (aimUpper + aimLower);
    e.predictedMax_um = programmed + 2.0 * hi;
    e.predictedMin_um = programmed + 2.0 * lo;
    const double tolerance = *e.upper_um - *e.lower_um;
    const double form = *e.predictedMax_um - *e.predictedMin_um;
    setValue(e, form, aimUpper - aimLower); // the zone the form must fit: the one all size tolerances allow
    if (*e.predictedMax_um <= *e.upper_um && *e.predictedMin_um >= *e.lower_um) {
        e.verdict = Verdict::PassesAsProgrammed;
        say(e.condition,
            [&] { return QString(ToleranceVerdicts::tr("Fig. 4b, eq. 13: D'_Md <= Dn + dDu and D'_md >= Dn + dDl")); });
    } else if (form <= aimUpper - aimLower) {
        e.verdict = Verdict::PassesAfterOffset;
        e.offset_um = programmed - 0.5 * (*e.predictedMax_um + *e.predictedMin_um);
        say(e.condition, [&] {
            return QString(ToleranceVerdicts::tr(
                "Fig. 4b: eq. 13 fails as programmed, eq. 15 holds: 2|delta_TMd - delta_Tmd| <= t"));
        });
        const bool sharedZone = aimUpper != *e.upper_um || aimLower != *e.lower_um;
        say(e.reason, [&] {
            const QString offset = QString::number(*e.offset_um, 'f', 1);
            if (sharedZone)
                return QString(
                    ToleranceVerdicts::tr("a constant tool offset of %1 µm on the diameter centres the size "
                                          "in the %2 µm zone that all of the feature's size tolerances allow")
                        .arg(offset, formatNumber(aimUpper - aimLower)));
            return QString(ToleranceVerdicts::tr(
                               "a constant tool offset of %1 µm on the diameter centres the size in its tolerance")
                               .arg(offset));
        });
    } else if (form <= tolerance) {
        e.verdict = Verdict::NeedsProfileCorrection;
        say(e.condition, [&] {
            return QString(ToleranceVerdicts::tr("Fig. 4b, eq. 15 holds for this tolerance, but the form does not fit "
                                                 "the %1 µm zone that all of the feature's size tolerances allow")
                               .arg(formatNumber(aimUpper - aimLower)));
        });
    } else {
        e.verdict = Verdict::NeedsProfileCorrection;
        say(e.condition,
            [&] { return QString(ToleranceVerdicts::tr("Fig. 4b, eq. 15: 2|delta_TMd - delta_Tmd| > t")); });
    }
}

// Length between two faces (Fig. 4a): e_i + e_j <= t (eq. 11), e = (D_M - D_m)/2 tan(theta) (eq. 12).
void evaluateLength(const Project &p, const Tolerance &t, const DeviationResult &r, ToleranceEvaluation &e)
{
    const FaceConicity *fi = faceOf(r, t.featureId);
    const FaceConicity *fj = faceOf(r, t.toFeatureId);
    const auto a = findFeature(p.part, t.featureId);
    const auto b = findFeature(p.part, t.toFeatureId);
    if (!a || !b)
        return;
    if (!fi || !fj) {
        notCut(e, fi ? t.toFeatureId : t.featureId);
        return;
    }
    if (!sizeLimits(t, std::abs(b->segment->from.z_mm - a->segment->from.z_mm), e))
        return;
    const double value = (fi->axialRunout_mm + fj->axialRunout_mm) * kUmPerMm;
    setValue(e, value, *e.upper_um - *e.lower_um);
    const bool holds = value <= *e.limit_um;
    e.verdict = holds ? Verdict::PassesAsProgrammed : Verdict::NeedsProfileCorrection;
    sayRule(e, {QT_TRANSLATE_NOOP("ToleranceVerdicts", "Fig. 4a, eq. 11–12"), "e_i + e_j"}, holds);
}

// A face's own conicity against the zone (flatness eq. 16; parallelism eq. 23; perpendicularity
// to the axis eq. 24; total axial run-out §V.J): e <= t.
void evaluateFaceConicity(const Tolerance &t, const DeviationResult &r, ToleranceEvaluation &e, const Rule &rule)
{
    const FaceConicity *f = faceOf(r, t.featureId);
    if (!f) {
        notCut(e, t.featureId);
        return;
    }
    setValue(e, f->axialRunout_mm * kUmPerMm, t.zone_um.value_or(0.0));
    const bool holds = *e.value_um <= *e.limit_um;
    e.verdict = holds ? Verdict::PassesAsProgrammed : Verdict::NeedsProfileCorrection;
    sayRule(e, rule, holds);
}

// Cylindricity (eq. 19) and total radial run-out (§V.J): |delta_TMd - delta_Tmd| <= t.
void evaluateRadialSpread(const Tolerance &t, const DeviationResult &r, ToleranceEvaluation &e, const Rule &rule)
{
    const FeatureDeviation *f = stationsOf(r, t.featureId);
    if (!f) {
        notCut(e, t.featureId);
        return;
    }
    const auto [lo, hi] = radiusErrorRange_um(*f);
    setValue(e, hi - lo, t.zone_um.value_or(0.0));
    const bool holds = *e.value_um <= *e.limit_um;
    e.verdict = holds ? Verdict::PassesAsProgrammed : Verdict::NeedsProfileCorrection;
    sayRule(e, rule, holds);
}

// The s that minimises the largest |d_i - s c_i| over the pairs (d_i, c_i), and that largest value.
// A maximum of absolute values of lines is convex in s: golden-section search over the s that can
// matter (at the best s no term exceeds max |d_i|, its value at s = 0, so |s| max |c_i| <= 2 max |d_i|).
std::pair<double, double> leastLargestShift(const std::vector<std::pair<double, double>> &terms)
{
    double largest = 0.0;
    double largestSlope = 0.0;
    for (const auto &[d, c] : terms) {
        largest = std::max(largest, std::abs(d));
        largestSlope = std::max(largestSlope, std::abs(c));
    }
    if (largestSlope < 1e-12)
        return {0.0, largest}; // no shift changes any term
    const auto worst = [&terms](double shift) {
        double w = 0.0;
        for (const auto &[d, c] : terms)
            w = std::max(w, std::abs(d - shift * c));
        return w;
    };
    double lo = -2.0 * largest / largestSlope;
    double hi = -lo;
    const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int i = 0; i < 200 && hi - lo > 1e-13 * (1.0 + std::abs(hi)); ++i) {
        const double a = hi - ratio * (hi - lo);
        const double b = lo + ratio * (hi - lo);
        if (worst(a) <= worst(b))
            hi = b; // the minimum lies in [lo, b]
        else
            lo = a;
    }
    const double best = 0.5 * (lo + hi);
    return {best, worst(best)};
}

// The width of the narrowest zone of the exact profile that holds every normal deviation when the
// zone may slide along the axis (the only way a surface of revolution's exact profile can move
// without a datum and keep its size; ISO 1101 scales it only with the OZ modifier): a slide dz
// changes the normal distance by dz n_z, so the width is 2 min over dz of max |delta_n - dz n_z|.
// For a cone n_z is constant and this is the spread of delta_n; for a round it is not.
double floatingZoneWidth_um(const std::vector<std::pair<double, double>> &normals)
{
    double largestAxial = 0.0;
    double lowest = 1e300;
    double highest = -1e300;
    double axialLow = 1e300;
    double axialHigh = -1e300;
    for (const auto &[deviation, axial] : normals) {
        largestAxial = std::max(largestAxial, std::abs(axial));
        lowest = std::min(lowest, deviation);
        highest = std::max(highest, deviation);
        axialLow = std::min(axialLow, axial);
        axialHigh = std::max(axialHigh, axial);
    }
    if (normals.empty())
        return 0.0;
    if (axialHigh - axialLow < 1e-12 && largestAxial >= 1e-12)
        return highest - lowest; // a cone or a chamfer: the slide is a constant normal offset
    return 2.0 * leastLargestShift(normals).second;
}

// A constant change dr of the programmed radius moves the surface along its normal by dr cos(alpha)
// at each station (for a cone the same everywhere, on a round not). The dr [µm] that minimises the
// largest |delta_n + dr cos(alpha)|, and that value: what a tool offset can do for a located profile
// zone.
std::pair<double, double> centringRadialShift_um(const std::vector<std::pair<double, double>> &normalAndCos)
{
    std::vector<std::pair<double, double>> terms; // delta_n - dr (-cos(alpha))
    terms.reserve(normalAndCos.size());
    for (const auto &[normal, cosine] : normalAndCos)
        terms.emplace_back(normal, -cosine);
    return leastLargestShift(terms);
}

// The exact profile's slope at z (a central difference inside the segment) and the offset of the
// program's target from it: the program aims at the target contour, which moves a cone or a round
// with its toleranced cylinder, so that shift is part of the deviation from the exact profile.
ProfileStationGeometry profileStationGeometry(const Segment &s, const Contour &target, const QString &featureId,
                                              double z_mm)
{
    const double h = 1e-4 * std::max(1.0, std::abs(s.to.z_mm - s.from.z_mm));
    const double z0 = std::max(s.from.z_mm, z_mm - h);
    const double z1 = std::min(s.to.z_mm, z_mm + h);
    const double nominal = radiusOnSegment(s, z_mm);
    const double aimed = targetRadius_mm(target, featureId, z_mm).value_or(nominal);
    return {z_mm, (radiusOnSegment(s, z1) - radiusOnSegment(s, z0)) / (z1 - z0), aimed - nominal};
}

// The geometry addProfileGeometry() formed for a feature, if it was formed for these stations.
const std::vector<ProfileStationGeometry> *knownGeometry(const ProgramTargets &targets, const QString &featureId,
                                                         const std::vector<Station> &stations)
{
    for (const ProfileGeometry &g : targets.profiles) {
        if (g.featureId != featureId)
            continue;
        if (g.stations.size() != stations.size())
            return nullptr;
        for (std::size_t i = 0; i < stations.size(); ++i)
            if (g.stations[i].z_mm != stations[i].z_mm)
                return nullptr;
        return &g.stations;
    }
    return nullptr;
}

// Profile of a line or surface (ISO 1101:2017 clause 18, definitions of the line and surface profile tolerances; Valiño
// et al. 2008 Fig. 4e). The deviation is taken normal to the surface: the radial one times cos(alpha), alpha the angle
// of the surface to the axis at the station. Without datums, or to a datum axis only (a datum cylinder), the zone may
// slide along the axis. With a datum that fixes a point on the axis (profileZoneIsLocated) the zone is located on the
// theoretically exact profile, which the program follows: every normal deviation lies within ±t/2. The paper's eq. 22,
// delta_TMd + delta_Tmd <= t / cos(alpha), is only necessary for either and is not used (MODEL §3).
void evaluateProfile(const ProgramTargets &targets, const Tolerance &t, const FeatureRef &feature,
                     const DeviationResult &r, bool located, ToleranceEvaluation &e)
{
    const FeatureDeviation *f = stationsOf(r, t.featureId);
    if (!f) {
        notCut(e, t.featureId);
        return;
    }
    const Segment &s = *feature.segment;
    const std::vector<ProfileStationGeometry> *known = knownGeometry(targets, t.featureId, f->stations);
    const Contour &target = feature.side == ContourSide::Outer ? targets.outer : targets.inner;
    double largest = -1e300;
    double smallest = 1e300;
    std::vector<std::pair<double, double>> normals;      // (delta_n [µm], axial part of the surface normal)
    std::vector<std::pair<double, double>> normalAndCos; // (delta_n [µm], cos(alpha))
    for (std::size_t i = 0; i < f->stations.size(); ++i) {
        const Station &st = f->stations[i];
        const ProfileStationGeometry g = known ? (*known)[i] : profileStationGeometry(s, target, t.featureId, st.z_mm);
        const double slope = g.slope;
        const double deviation = st.radiusError_mm + g.targetOffset_mm;
        const double normal = deviation * kUmPerMm / std::sqrt(1.0 + slope * slope); // delta cos(alpha)
        if (!std::isfinite(normal)) {
            setValue(e, normal, t.zone_um.value_or(0.0)); // refuseNonFinite refuses it
            return;
        }
        largest = std::max(largest, normal);
        smallest = std::min(smallest, normal);
        normals.emplace_back(normal, slope / std::sqrt(1.0 + slope * slope));
        normalAndCos.emplace_back(normal, 1.0 / std::sqrt(1.0 + slope * slope));
    }
    const double zone = t.zone_um.value_or(0.0);
    if (!located) {
        const double floating = floatingZoneWidth_um(normals);
        setValue(e, floating, zone);
        const bool holds = floating <= zone;
        e.verdict = holds ? Verdict::PassesAsProgrammed : Verdict::NeedsProfileCorrection;
        const char *spread = QT_TRANSLATE_NOOP("ToleranceVerdicts", "2 min over dz of max |delta_n - dz n_z|");
        sayRule(e,
                t.datums.isEmpty()
                    ? Rule{QT_TRANSLATE_NOOP("ToleranceVerdicts",
                                             "ISO 1101 surface profile, no datum (the zone floats along the axis)"),
                           spread}
                    : Rule{QT_TRANSLATE_NOOP("ToleranceVerdicts",
                                             "ISO 1101 surface profile to a datum axis only (the zone may slide along "
                                             "it)"),
                           spread},
                holds);
        return;
    }
    // Located zone: the deciding value is twice the largest distance from the exact profile.
    const double fromExact = 2.0 * std::max(std::abs(largest), std::abs(smallest));
    setValue(e, fromExact, zone);
    if (fromExact <= zone) {
        e.verdict = Verdict::PassesAsProgrammed;
        say(e.condition, [&] {
            return QString(ToleranceVerdicts::tr(
                "ISO 1101 surface profile, with a datum that locates it along the axis: every delta_n within ±t/2"));
        });
        return;
    }
    // Plain names, not a structured binding: the reasons below capture them (clang 14 refuses that).
    const std::pair<double, double> centring = centringRadialShift_um(normalAndCos);
    const double radialShift = centring.first;
    const double shiftedLargest = centring.second;
    if (2.0 * shiftedLargest <= zone) {
        e.verdict = Verdict::PassesAfterOffset;
        e.offset_um = 2.0 * radialShift; // like a size's: the change of the programmed diameter
        say(e.condition, [&] {
            return QString(ToleranceVerdicts::tr("ISO 1101 surface profile, with datums: a delta_n lies outside "
                                                 "±t/2 as programmed; a constant radial offset brings all within"));
        });
        const bool straight = s.kind == SegmentKind::Cone || s.kind == SegmentKind::Chamfer;
        say(e.reason, [&] {
            const QString diameter = QString::number(*e.offset_um, 'f', 1);
            return straight
                       ? QString(ToleranceVerdicts::tr("a constant offset of %1 µm on the diameter (%2 µm "
                                                       "normal to the surface) centres it in the zone")
                                     .arg(diameter, QString::number(radialShift * normalAndCos.front().second, 'f', 1)))
                       : QString(ToleranceVerdicts::tr("a constant offset of %1 µm on the diameter brings "
                                                       "every delta_n within ±t/2")
                                     .arg(diameter));
        });
    } else {
        e.verdict = Verdict::NeedsProfileCorrection;
        say(e.condition, [&] {
            return QString(ToleranceVerdicts::tr(
                "ISO 1101 surface profile, with datums: no constant offset brings every delta_n within ±t/2"));
        });
    }
}

void notPredicted(ToleranceEvaluation &e, const QString &reason)
{
    e.verdict = Verdict::NotPredicted;
    say(e.reason, [&] { return QString(reason); });
}

ToleranceEvaluation evaluateOne(const Project &p, const ProgramTargets &targets, const Tolerance &t,
                                const DeviationResult &r)
{
    ToleranceEvaluation e;
    e.toleranceId = t.id;
    e.type = t.type;
    e.featureId = t.featureId;
    const auto feature = findFeature(p.part, t.featureId);
    if (!feature) {
        say(e.reason,
            [&] { return QString(ToleranceVerdicts::tr("there is no feature '%1' in the profile").arg(t.featureId)); });
        return e;
    }
    switch (t.type) {
    case ToleranceType::Diameter:
        evaluateDiameter(targets, t, *feature, r, e);
        break;
    case ToleranceType::Length:
        evaluateLength(p, t, r, e);
        break;
    case ToleranceType::Flatness:
        evaluateFaceConicity(t, r, e, {QT_TRANSLATE_NOOP("ToleranceVerdicts", "Fig. 4c, eq. 16"), "e_i"});
        break;
    case ToleranceType::Parallelism:
        evaluateFaceConicity(t, r, e, {QT_TRANSLATE_NOOP("ToleranceVerdicts", "Fig. 4f, eq. 23"), "e_j"});
        break;
    case ToleranceType::TotalAxialRunout:
        evaluateFaceConicity(t, r, e, {QT_TRANSLATE_NOOP("ToleranceVerdicts", "Fig. 4i, §V.J (eq. 16 and 24)"), "e_j"});
        break;
    case ToleranceType::Perpendicularity:
        if (feature->segment->kind == SegmentKind::Face)
            evaluateFaceConicity(
                t, r, e, {QT_TRANSLATE_NOOP("ToleranceVerdicts", "Fig. 4g, eq. 24 (face to the datum axis)"), "e_j"});
        else
            notPredicted(e, ToleranceVerdicts::tr(
                                "Perpendicularity of an axis to a face depends on how the part is aligned in the "
                                "lathe; the axis recovers elastically after cutting, so the cutting-force deflection "
                                "does not decide it (Valiño et al. 2008 §V.G.2)."));
        break;
    case ToleranceType::Cylindricity:
        evaluateRadialSpread(t, r, e,
                             {QT_TRANSLATE_NOOP("ToleranceVerdicts", "Fig. 4d, eq. 19"), "|delta_TMd - delta_Tmd|"});
        break;
    case ToleranceType::TotalRadialRunout:
        evaluateRadialSpread(
            t, r, e, {QT_TRANSLATE_NOOP("ToleranceVerdicts", "Fig. 4h, §V.J (eq. 19)"), "|delta_TMd - delta_Tmd|"});
        break;
    case ToleranceType::Profile:
        evaluateProfile(targets, t, *feature, r, profileZoneIsLocated(p, t), e);
        break;
    case ToleranceType::Coaxiality:
        notPredicted(e, ToleranceVerdicts::tr(
                            "Coaxiality limits how far parts of the axis lie apart; the axis recovers elastically "
                            "after cutting, so the error comes from set-up and alignment, not from the cutting-force "
                            "deflection (Valiño et al. 2008 §V.H)."));
        break;
    case ToleranceType::CircularRadialRunout:
    case ToleranceType::CircularAxialRunout:
        notPredicted(e, ToleranceVerdicts::tr(
                            "The deflection under the cutting force is symmetrical about the axis of rotation and "
                            "leaves no circular run-out; that comes from clamping deformation or misalignment "
                            "(Valiño et al. 2008 §V.I)."));
        break;
    }
    return e;
}

// A deviation that is not finite (an overflow, a station on the axis with no speed limit) decides
// nothing: never a pass.
void refuseNonFinite(ToleranceEvaluation &e)
{
    const std::optional<double> numbers[] = {e.value_um, e.predictedMax_um, e.predictedMin_um, e.offset_um};
    for (const auto &v : numbers) {
        if (v && !std::isfinite(*v)) {
            e.verdict = Verdict::CannotEvaluate;
            e.deviationNotFinite = true;
            e.value_um.reset();
            e.utilisation_pct.reset();
            say(e.reason, [&] {
                return QString(ToleranceVerdicts::tr("the predicted deviation of feature %1 is not finite, so "
                                                     "nothing can be said of it")
                                   .arg(e.featureId));
            });
            return;
        }
    }
}

} // namespace

std::vector<ToleranceEvaluation> evaluateTolerances(const Project &project, const DeviationResult &result,
                                                    EvaluationDetail detail, const ProgramTargets *targets)
{
    struct TextMode {
        bool previous = t_withText;

        explicit TextMode(bool on) { t_withText = on; }

        ~TextMode() { t_withText = previous; }
    } mode(detail == EvaluationDetail::WithText);

    std::vector<ToleranceEvaluation> out;
    out.reserve(project.tolerances.size());
    const ProgramTargets own = targets ? ProgramTargets{} : programTargets(project);
    for (const Tolerance &t : project.tolerances) {
        out.push_back(evaluateOne(project, targets ? *targets : own, t, result));
        refuseNonFinite(out.back());
    }
    return out;
}

void addProfileGeometry(const Project &project, const InfluenceTable &table, ProgramTargets &targets)
{
    for (const Tolerance &t : project.tolerances) {
        if (t.type != ToleranceType::Profile ||
            std::any_of(targets.profiles.begin(), targets.profiles.end(),
                        [&](const ProfileGeometry &g) { return g.featureId == t.featureId; }))
            continue;
        const auto feature = findFeature(project.part, t.featureId);
        const auto stations = std::find_if(table.features.begin(), table.features.end(),
                                           [&](const FeatureInfluence &f) { return f.featureId == t.featureId; });
        if (!feature || stations == table.features.end())
            continue;
        const Contour &target = feature->side == ContourSide::Outer ? targets.outer : targets.inner;
        ProfileGeometry g{t.featureId, {}};
        for (const double z : stations->z_mm)
            g.stations.push_back(profileStationGeometry(*feature->segment, target, t.featureId, z));
        targets.profiles.push_back(std::move(g));
    }
}

bool profileZoneIsLocated(const Project &project, const Tolerance &tolerance)
{
    return std::any_of(project.datums.begin(), project.datums.end(), [&](const Datum &d) {
        if (!tolerance.datums.contains(d.label))
            return false;
        const auto feature = findFeature(project.part, d.featureId);
        return feature && feature->segment->kind != SegmentKind::Cylinder;
    });
}

QString verdictKeyword(Verdict verdict)
{
    switch (verdict) {
    case Verdict::PassesAsProgrammed:
        return QStringLiteral("passes");
    case Verdict::PassesAfterOffset:
        return QStringLiteral("passes_after_offset");
    case Verdict::NeedsProfileCorrection:
        return QStringLiteral("needs_profile_correction");
    case Verdict::NotPredicted:
        return QStringLiteral("not_predicted");
    case Verdict::CannotEvaluate:
        return QStringLiteral("cannot_evaluate");
    }
    return {};
}

QString verdictName(Verdict verdict)
{
    switch (verdict) {
    case Verdict::PassesAsProgrammed:
        return ToleranceVerdicts::tr("passes as programmed");
    case Verdict::PassesAfterOffset:
        return ToleranceVerdicts::tr("passes after a constant offset");
    case Verdict::NeedsProfileCorrection:
        return ToleranceVerdicts::tr("needs a profile correction");
    case Verdict::NotPredicted:
        return ToleranceVerdicts::tr("not predicted by this model");
    case Verdict::CannotEvaluate:
        return ToleranceVerdicts::tr("cannot be evaluated");
    }
    return {};
}

} // namespace tolturn
