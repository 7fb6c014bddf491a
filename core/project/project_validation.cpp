// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/project_validation.h"

#include "core/milling/milled_features.h"
#include "core/part/profile_validation.h"
#include "core/project/keywords.h"
#include "core/project/operations.h"
#include "core/tolerance/iso286.h"
#include "core/tolerance/target_contour.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QSet>

#include <cmath>

namespace tolturn {

namespace {

struct ProjectValidation {
    Q_DECLARE_TR_FUNCTIONS(ProjectValidation)
};

// The values checked here are the file's: quoted as written (5.0000000001 is not 5).
QString num(double v)
{
    return formatNumberExactly(v);
}

void requireText(const QString &value, const QString &field, const QString &what, Diagnostics &out)
{
    if (value.trimmed().isEmpty())
        out.push_back(makeError(field, ProjectValidation::tr("%1 is missing (empty)").arg(what)));
}

// A clamping of the part; `prefix` is where it stands in the file ("", "further_operations[0].").
void checkClamping(const Clamping &clamping, double length, const QString &prefix, Diagnostics &out)
{
    const double clamped = clamping.clampedLength_mm;
    const QString field = prefix + QStringLiteral("clamping.clamped_length_mm");
    if (!std::isfinite(clamped) || clamped < 0.0) {
        out.push_back(makeError(field, ProjectValidation::tr("must be zero or more, but is %1 mm").arg(num(clamped))));
        return;
    }
    switch (clamping.method) {
    case ClampingMethod::Chuck:
    case ClampingMethod::ChuckTailstock:
    case ClampingMethod::Collet:
        if (clamped <= 0.0)
            out.push_back(makeError(
                field, ProjectValidation::tr("a part held in a chuck needs a clamped length above zero, but it "
                                             "is %1 mm")
                           .arg(num(clamped))));
        else if (length > 0.0 && clamped >= length)
            out.push_back(makeError(
                field, ProjectValidation::tr("the clamped length %1 mm leaves nothing to turn on a part %2 mm "
                                             "long")
                           .arg(num(clamped), num(length))));
        break;
    case ClampingMethod::BetweenCentres:
        if (clamped > 0.0)
            out.push_back(makeWarning(
                field, ProjectValidation::tr("a part between centres is not clamped; the clamped length %1 mm "
                                             "is ignored")
                           .arg(num(clamped))));
        break;
    }
}

void checkPasses(const std::vector<CuttingPass> &passes, const QString &prefix, Diagnostics &out)
{
    for (std::size_t i = 0; i < passes.size(); ++i) {
        const CuttingPass &pass = passes[i];
        const QString path = prefix + QStringLiteral("passes[%1].").arg(i);
        const std::pair<const char *, double> values[] = {{"cutting_speed_m_min", pass.cuttingSpeed_m_min},
                                                          {"feed_mm_rev", pass.feed_mm_rev},
                                                          {"depth_of_cut_mm", pass.depthOfCut_mm}};
        // The least the program can state (post_processor.cpp): G96 S in whole m/min, F and the
        // coordinates in thousandths of a mm; less would be written as zero.
        const double leastWritten[] = {1.0, 0.001, 0.001};
        for (std::size_t k = 0; k < std::size(values); ++k) {
            const auto &[name, value] = values[k];
            if (!std::isfinite(value) || value <= 0.0)
                out.push_back(makeError(path + QLatin1String(name),
                                        ProjectValidation::tr("must be above zero, but is %1").arg(num(value))));
            else if (value < leastWritten[k])
                out.push_back(makeError(path + QLatin1String(name),
                                        ProjectValidation::tr("%1 is below %2, the least the program can state; it "
                                                              "would be written as zero")
                                            .arg(num(value), num(leastWritten[k]))));
        }
    }
}

void checkDatums(const Project &p, Diagnostics &out)
{
    static const QRegularExpression label(QStringLiteral("^[A-Z]{1,2}$"));
    QSet<QString> seen;
    for (std::size_t i = 0; i < p.datums.size(); ++i) {
        const Datum &d = p.datums[i];
        const QString path = QStringLiteral("datums[%1].").arg(i);
        if (!label.match(d.label).hasMatch())
            out.push_back(
                makeError(path + QStringLiteral("label"),
                          ProjectValidation::tr("a datum is named by one or two capital letters (ISO 5459), not '%1'")
                              .arg(d.label)));
        else if (seen.contains(d.label))
            out.push_back(makeError(path + QStringLiteral("label"),
                                    ProjectValidation::tr("datum '%1' is defined twice").arg(d.label)));
        seen.insert(d.label);
        if (!findFeature(p.part, d.featureId))
            out.push_back(makeError(path + QStringLiteral("feature"),
                                    ProjectValidation::tr("there is no feature '%1' in the profile").arg(d.featureId)));
    }
}

} // namespace

// Which kinds of feature each tolerance may sit on (Valiño et al. 2008, §V, Fig. 4).
bool toleranceFitsFeature(ToleranceType type, SegmentKind kind)
{
    const bool face = kind == SegmentKind::Face;
    const bool cylinder = kind == SegmentKind::Cylinder;
    switch (type) {
    case ToleranceType::Length:
    case ToleranceType::Flatness:
    case ToleranceType::Parallelism:
    case ToleranceType::CircularAxialRunout:
    case ToleranceType::TotalAxialRunout:
        return face;
    case ToleranceType::Diameter:
    case ToleranceType::Cylindricity:
    case ToleranceType::Coaxiality:
        return cylinder;
    case ToleranceType::Profile:
        return !face && !cylinder;
    case ToleranceType::Perpendicularity: // face to the axis, or an axis to a face
        return face || cylinder;
    case ToleranceType::CircularRadialRunout:
    case ToleranceType::TotalRadialRunout:
        return !face;
    }
    return false;
}

namespace {

// ISO 286-1 does not define every class at every size (j8 above Ø3 mm, for one): a class that has
// no limits at the feature's diameter is named here, not left for the verdicts to find.
void checkClassAtSize(const QString &toleranceClass, double nominal_mm, const QString &path, Diagnostics &out)
{
    const iso286::LimitsResult limits = iso286::limits(nominal_mm, toleranceClass);
    if (limits.limits)
        return;
    QStringList why;
    for (const Diagnostic &d : limits.diagnostics)
        why << d.message;
    out.push_back(makeError(path + QStringLiteral("iso286"),
                            ProjectValidation::tr("ISO 286 gives no limits for %1 at Ø%2 mm: %3")
                                .arg(toleranceClass, num(nominal_mm), why.join(QStringLiteral("; ")))));
}

void checkSizeLimits(const Tolerance &t, const FeatureRef &feature, const QString &path, Diagnostics &out)
{
    // Grammar of an ISO 286-1 class: fundamental deviation letter(s) then the IT grade number.
    static const QRegularExpression isoClass(QStringLiteral("^([A-Za-z]{1,2})(01|0|[1-9]|1[0-8])$"));
    const bool hasClass = !t.iso286Class.isEmpty();
    const bool hasLimits = t.upperDeviation_um.has_value() || t.lowerDeviation_um.has_value();
    if (hasClass == hasLimits) {
        out.push_back(makeError(
            path + QStringLiteral("iso286"),
            ProjectValidation::tr("give either an ISO 286 class or both limit deviations (upper_um, lower_um)")));
        return;
    }
    if (hasClass) {
        const auto match = isoClass.match(t.iso286Class);
        if (!match.hasMatch()) {
            out.push_back(makeError(
                path + QStringLiteral("iso286"),
                ProjectValidation::tr("'%1' is not an ISO 286 tolerance class (a letter and a grade, e.g. h6 or H7)")
                    .arg(t.iso286Class)));
            return;
        }
        if (t.type == ToleranceType::Diameter) {
            const bool holeClass = match.captured(1).at(0).isUpper();
            const bool bore = feature.side == ContourSide::Inner;
            if (holeClass != bore)
                out.push_back(makeError(
                    path + QStringLiteral("iso286"),
                    (bore ? ProjectValidation::tr("'%1' is a shaft class, but feature '%2' is a bore: use capital "
                                                  "letters (e.g. H7)")
                          : ProjectValidation::tr("'%1' is a hole class, but feature '%2' is an outer surface: use "
                                                  "small letters (e.g. h6)"))
                        .arg(t.iso286Class, t.featureId)));
            else
                checkClassAtSize(t.iso286Class, 2.0 * feature.segment->from.r_mm, path, out);
        }
        return;
    }
    if (!t.upperDeviation_um || !t.lowerDeviation_um) {
        out.push_back(makeError(path + (t.upperDeviation_um ? QStringLiteral("lower_um") : QStringLiteral("upper_um")),
                                ProjectValidation::tr("both limit deviations are needed, upper_um and lower_um")));
        return;
    }
    if (*t.upperDeviation_um <= *t.lowerDeviation_um)
        out.push_back(
            makeError(path + QStringLiteral("upper_um"),
                      ProjectValidation::tr("the upper deviation %1 µm must be above the lower deviation %2 µm")
                          .arg(num(*t.upperDeviation_um), num(*t.lowerDeviation_um))));
}

void checkGeometric(const Tolerance &t, const QSet<QString> &datumLabels, const QString &path, Diagnostics &out)
{
    if (!t.zone_um || !std::isfinite(*t.zone_um) || *t.zone_um <= 0.0) {
        out.push_back(makeError(path + QStringLiteral("value_um"),
                                ProjectValidation::tr("a %1 tolerance needs a zone width above zero, but it is %2")
                                    .arg(keyword(t.type), t.zone_um ? num(*t.zone_um) + QStringLiteral(" µm")
                                                                    : ProjectValidation::tr("missing"))));
    }
    if (needsDatum(t.type) && t.datums.isEmpty())
        out.push_back(
            makeError(path + QStringLiteral("datums"),
                      ProjectValidation::tr("a %1 tolerance is defined relative to a datum, but none is given")
                          .arg(keyword(t.type))));
    for (qsizetype j = 0; j < t.datums.size(); ++j) {
        if (!datumLabels.contains(t.datums.at(j)))
            out.push_back(makeError(
                path + QStringLiteral("datums[%1]").arg(j),
                ProjectValidation::tr("datum '%1' is not defined in the project's datums").arg(t.datums.at(j))));
    }
}

void checkTolerance(const Project &p, const Tolerance &t, const QSet<QString> &datumLabels, const QString &path,
                    Diagnostics &out)
{
    const auto feature = findFeature(p.part, t.featureId);
    if (!feature) {
        out.push_back(makeError(path + QStringLiteral("feature"),
                                ProjectValidation::tr("there is no feature '%1' in the profile").arg(t.featureId)));
        return;
    }
    if (!toleranceFitsFeature(t.type, feature->segment->kind))
        out.push_back(makeError(path + QStringLiteral("feature"),
                                ProjectValidation::tr("a %1 tolerance cannot sit on feature '%2', which is a %3")
                                    .arg(keyword(t.type), t.featureId, keyword(feature->segment->kind))));
    if (t.type == ToleranceType::Length) {
        const auto other = findFeature(p.part, t.toFeatureId);
        if (!other)
            out.push_back(makeError(
                path + QStringLiteral("to_feature"),
                ProjectValidation::tr("a length runs between two faces; there is no feature '%1' in the profile")
                    .arg(t.toFeatureId)));
        else if (other->segment->kind != SegmentKind::Face || t.toFeatureId == t.featureId)
            out.push_back(makeError(path + QStringLiteral("to_feature"),
                                    ProjectValidation::tr("a length runs between two different faces; '%1' is not one")
                                        .arg(t.toFeatureId)));
    }
    if (isSizeTolerance(t.type))
        checkSizeLimits(t, *feature, path, out);
    else
        checkGeometric(t, datumLabels, path, out);
}

void checkSizesMeet(const Project &p, Diagnostics &out);

void checkTolerances(const Project &p, Diagnostics &out)
{
    QSet<QString> datumLabels;
    for (const Datum &d : p.datums)
        datumLabels.insert(d.label);
    QSet<QString> ids;
    for (std::size_t i = 0; i < p.tolerances.size(); ++i) {
        const Tolerance &t = p.tolerances[i];
        const QString path = QStringLiteral("tolerances[%1].").arg(i);
        if (t.id.trimmed().isEmpty())
            out.push_back(makeError(path + QStringLiteral("id"),
                                    ProjectValidation::tr("every tolerance needs an id, but this one is empty")));
        else if (ids.contains(t.id))
            out.push_back(
                makeError(path + QStringLiteral("id"), ProjectValidation::tr("the id '%1' is used twice").arg(t.id)));
        ids.insert(t.id);
        checkTolerance(p, t, datumLabels, path, out);
    }
    if (!hasErrors(out))
        checkSizesMeet(p, out);
}

// Two size tolerances on one diameter must allow a common size: the program aims at the middle of
// the zone both allow (targetContour), and no offset or correction can cut a size neither allows.
// A zone narrower than the program's step on the diameter (X to 0.001 mm, post_processor.cpp
// coordinate()) cannot be aimed at either: the rounded target may lie outside it.
void checkSizesMeet(const Project &p, Diagnostics &out)
{
    constexpr double kProgramStep_um = 1.0;
    for (const DiameterTarget &target : diameterTargets(p)) {
        if (target.upper_um - target.lower_um >= kProgramStep_um)
            continue;
        std::size_t last = 0;
        for (std::size_t i = 0; i < p.tolerances.size(); ++i) {
            if (p.tolerances[i].featureId == target.featureId && p.tolerances[i].type == ToleranceType::Diameter)
                last = i;
        }
        if (target.upper_um == target.lower_um) {
            out.push_back(makeError(QStringLiteral("tolerances[%1]").arg(last),
                                    ProjectValidation::tr("the size tolerances of feature %1 leave a zone of no width "
                                                          "(both limits at %2 µm), which no cut can hold")
                                        .arg(target.featureId, num(target.upper_um))));
            continue;
        }
        if (target.upper_um > target.lower_um) {
            out.push_back(makeError(QStringLiteral("tolerances[%1]").arg(last),
                                    ProjectValidation::tr("the size tolerances of feature %1 leave a zone from %2 to "
                                                          "%3 µm, narrower than the 1 µm step of the program's "
                                                          "diameters: no program can aim into it")
                                        .arg(target.featureId, num(target.lower_um), num(target.upper_um))));
            continue;
        }
        out.push_back(makeError(QStringLiteral("tolerances[%1]").arg(last),
                                ProjectValidation::tr("the size tolerances of feature %1 allow no common size: one "
                                                      "needs at most %2 µm, another at least %3 µm")
                                    .arg(target.featureId, num(target.upper_um), num(target.lower_um))));
    }
}

void requirePositive(const std::optional<double> &value, const QString &field, Diagnostics &out)
{
    if (value && (!std::isfinite(*value) || *value <= 0.0))
        out.push_back(makeError(field, ProjectValidation::tr("must be above zero, but is %1").arg(num(*value))));
}

void requireNonNegative(std::optional<double> value, const QString &field, Diagnostics &out)
{
    if (value && (!std::isfinite(*value) || *value < 0.0))
        out.push_back(makeError(field, ProjectValidation::tr("must be zero or more, but is %1").arg(num(*value))));
}

void checkCuttingModel(const Project &p, Diagnostics &out)
{
    const CuttingModel &m = p.cuttingModel;
    requireNonNegative(m.feedToCuttingRatio, QStringLiteral("cutting_model.feed_to_cutting_ratio"), out);
    requireNonNegative(m.passiveToCuttingRatio, QStringLiteral("cutting_model.passive_to_cutting_ratio"), out);
    requirePositive(m.normalPressure_MPa, QStringLiteral("cutting_model.normal_pressure_MPa"), out);
    requireNonNegative(m.frictionRatio, QStringLiteral("cutting_model.friction_ratio"), out);
    if (m.forceModel == ForceModel::LiDu && (!m.normalPressure_MPa || !m.frictionRatio))
        out.push_back(makeError(
            QStringLiteral("cutting_model"),
            ProjectValidation::tr("the li_du force model needs normal_pressure_MPa (K_n) and friction_ratio (K_f); "
                                  "fit them from measured forces with 'tolturn-cli calibrate-forces'")));
}

// The tools of a set-up (prefix "" for the project's own, "further_operations[i]." for the others).
void checkTools(const Tool &tool, const std::optional<Tool> &boringTool, const QString &prefix, Diagnostics &out)
{
    requirePositive(tool.overhang_mm, prefix + QStringLiteral("tool.overhang_mm"), out);
    if (tool.pilotHoleDiameter_mm)
        out.push_back(makeError(prefix + QStringLiteral("tool.pilot_hole_diameter_mm"),
                                ProjectValidation::tr("only a boring bar starts from a pilot hole: give it in "
                                                      "boring_tool")));
    if (!boringTool)
        return;
    requireText(boringTool->insertCode, prefix + QStringLiteral("boring_tool.insert"),
                ProjectValidation::tr("the boring bar's insert code"), out);
    requireText(boringTool->holderCode, prefix + QStringLiteral("boring_tool.holder"),
                ProjectValidation::tr("the boring bar"), out);
    requirePositive(boringTool->overhang_mm, prefix + QStringLiteral("boring_tool.overhang_mm"), out);
    requirePositive(boringTool->edgeOffset_mm, prefix + QStringLiteral("boring_tool.edge_offset_mm"), out);
    requirePositive(boringTool->pilotHoleDiameter_mm, prefix + QStringLiteral("boring_tool.pilot_hole_diameter_mm"),
                    out);
}

void checkSprings(const std::optional<SpindleSprings> &s, const QString &path, Diagnostics &out)
{
    if (!s)
        return;
    requirePositive(s->k1_N_per_mm, path + QStringLiteral(".k1_N_per_mm"), out);
    requirePositive(s->k2_Nmm_per_rad, path + QStringLiteral(".k2_Nmm_per_rad"), out);
    requirePositive(s->k3_Nmm_per_rad, path + QStringLiteral(".k3_Nmm_per_rad"), out);
}

void checkSupport(const std::optional<SupportStiffness> &s, const QString &path, Diagnostics &out)
{
    if (!s)
        return;
    requirePositive(s->radial_N_per_mm, path + QStringLiteral(".radial_N_per_mm"), out);
    requirePositive(s->tangential_N_per_mm, path + QStringLiteral(".tangential_N_per_mm"), out);
}

void checkCharacterisation(const Project &p, Diagnostics &out)
{
    const MachineCharacterisation &c = p.characterisation;
    if (c == MachineCharacterisation{})
        return;
    requireText(c.source, QStringLiteral("characterisation.source"),
                ProjectValidation::tr("where the machine characterisation comes from"), out);
    checkSprings(c.spindleRadial, QStringLiteral("characterisation.spindle_radial"), out);
    checkSprings(c.spindleTangential, QStringLiteral("characterisation.spindle_tangential"), out);
    checkSupport(c.tailstock, QStringLiteral("characterisation.tailstock"), out);
    checkSupport(c.centres, QStringLiteral("characterisation.centres"), out);
    if ((c.spindleRadial || c.spindleTangential) && !c.pivotDistance_mm)
        out.push_back(
            makeError(QStringLiteral("characterisation.pivot_distance_mm"),
                      ProjectValidation::tr(
                          "spindle springs need the pivot distance Lc of the k2 spring behind the chuck face")));
    requireNonNegative(c.pivotDistance_mm, QStringLiteral("characterisation.pivot_distance_mm"), out);
    if (c.thermal)
        requirePositive(c.thermal->timeConstant_min, QStringLiteral("characterisation.thermal.time_constant_min"), out);
}

// Checked with or without a thermal characterisation: the values are the shop's, kept in the file.
void checkEnvironment(const Environment &e, Diagnostics &out)
{
    requireNonNegative(e.timeSinceStart_min, QStringLiteral("environment.time_since_start_min"), out);
    constexpr double kAbsoluteZero_C = -273.15; // ITS-90 / SI: 0 K
    if (e.ambientTemperature_C &&
        (!std::isfinite(*e.ambientTemperature_C) || *e.ambientTemperature_C <= kAbsoluteZero_C))
        out.push_back(makeError(QStringLiteral("environment.ambient_temperature_C"),
                                ProjectValidation::tr("must be above absolute zero (-273.15 °C), but is %1 °C")
                                    .arg(num(*e.ambientTemperature_C))));
}

// A measured thermal drift needs the shop's conditions; what is missing is not taken as the ideal
// (docs/model.md §5, resolveTurningInputs), and `check` says so.
void checkThermalConditions(const Project &p, Diagnostics &out)
{
    if (!p.characterisation.thermal)
        return;
    if (!p.environment.timeSinceStart_min)
        out.push_back(makeWarning(QStringLiteral("environment.time_since_start_min"),
                                  ProjectValidation::tr("not given: the thermal drift is computed for a machine "
                                                        "warmed through, the largest drift; give the time since the "
                                                        "machine started")));
    if (!p.environment.ambientTemperature_C && p.characterisation.thermal->drift_um_per_K != 0.0)
        out.push_back(makeWarning(QStringLiteral("environment.ambient_temperature_C"),
                                  ProjectValidation::tr("not given: taken as the characterisation's reference "
                                                        "temperature, %1 °C, so no drift from it")
                                      .arg(num(p.characterisation.thermal->referenceTemperature_C))));
}

void checkRange(const std::optional<ValueRange> &range, const QString &field, Diagnostics &out)
{
    if (!range)
        return;
    if (!std::isfinite(range->min) || range->min <= 0.0)
        out.push_back(makeError(field + QStringLiteral(".min"),
                                ProjectValidation::tr("must be above zero, but is %1").arg(num(range->min))));
    else if (!std::isfinite(range->max) || range->max < range->min)
        out.push_back(makeError(
            field + QStringLiteral(".max"),
            ProjectValidation::tr("must be at least the minimum %1, but is %2").arg(num(range->min), num(range->max))));
}

void checkPlanning(const Project &p, Diagnostics &out)
{
    const PlanningSettings &s = p.planning;
    const QString path = QStringLiteral("planning.");
    const std::pair<const char *, double> rates[] = {{"machine_rate_per_min", s.machineRate_per_min},
                                                     {"tool_cost_per_edge", s.toolCostPerEdge},
                                                     {"tool_change_time_min", s.toolChangeTime_min},
                                                     {"handling_time_min", s.handlingTime_min}};
    for (const auto &[name, value] : rates)
        requireNonNegative(value, path + QLatin1String(name), out);
    // Without the rate the cost of a part is its inserts alone, and without those nothing: a plan at
    // no cost would be chosen at random, so least cost asks for the rate (docs/planning.md §1).
    // (A warning here: the other commands need no rate; planning refuses to plan without it.)
    if (s.objective == PlanningObjective::Cost && s.machineRate_per_min == 0.0)
        out.push_back(makeWarning(path + QStringLiteral("machine_rate_per_min"),
                                  ProjectValidation::tr("least cost needs the machine and operator rate per minute, "
                                                        "but it is 0 (or not given)")));
    requirePositive(s.taylorC_m_min, path + QStringLiteral("tool_life.C_m_min"), out);
    if (s.taylorN && (!std::isfinite(*s.taylorN) || *s.taylorN <= 0.0 || *s.taylorN >= 1.0))
        out.push_back(makeError(
            path + QStringLiteral("tool_life.n"),
            ProjectValidation::tr("the Taylor exponent n lies between 0 and 1, but is %1").arg(num(*s.taylorN))));
    if (s.taylorC_m_min.has_value() != s.taylorN.has_value())
        out.push_back(
            makeError(path + (s.taylorN ? QStringLiteral("tool_life.C_m_min") : QStringLiteral("tool_life.n")),
                      ProjectValidation::tr("give both Taylor constants C and n, or neither")));
    if (s.taylorC_m_min)
        requireText(s.toolLifeSource, path + QStringLiteral("tool_life.source"),
                    ProjectValidation::tr("the source of the Taylor constants"), out);
    requirePositive(s.minToolLife_min, path + QStringLiteral("tool_life.min_minutes"), out);
    checkRange(s.cuttingSpeed_m_min, path + QStringLiteral("ranges.cutting_speed_m_min"), out);
    checkRange(s.feed_mm_rev, path + QStringLiteral("ranges.feed_mm_rev"), out);
    checkRange(s.depthOfCut_mm, path + QStringLiteral("ranges.depth_of_cut_mm"), out);
    if (s.cuttingSpeed_m_min || s.feed_mm_rev || s.depthOfCut_mm)
        requireText(s.rangesSource, path + QStringLiteral("ranges.source"),
                    ProjectValidation::tr("the source of the cutting ranges"), out);
    const std::pair<const char *, std::optional<double>> limits[] = {
        {"max_ra_um", s.maxRa_um},         {"max_rz_um", s.maxRz_um},
        {"max_force_N", s.maxForce_N},     {"max_power_kW", s.maxPower_kW},
        {"max_torque_Nm", s.maxTorque_Nm}, {"max_spindle_speed_rpm", s.maxSpindleSpeed_rpm}};
    for (const auto &[name, value] : limits)
        requirePositive(value, path + QLatin1String(name), out);
    for (qsizetype i = 0; i < s.disabledConstraints.size(); ++i) {
        const QString &name = s.disabledConstraints.at(i);
        if (!planningConstraintKeywords().contains(name))
            out.push_back(makeError(path + QStringLiteral("disabled_constraints[%1]").arg(i),
                                    ProjectValidation::tr("unknown constraint \"%1\"; the constraints are: %2")
                                        .arg(name, planningConstraintKeywords().join(QStringLiteral(", ")))));
    }
}

} // namespace

Diagnostics validateProject(const Project &project)
{
    Diagnostics out = validateProfile(project.part);
    requireText(project.materialId, QStringLiteral("material"), ProjectValidation::tr("the work material"), out);
    requireText(project.machineId, QStringLiteral("machine"), ProjectValidation::tr("the machine"), out);
    requireText(project.tool.insertCode, QStringLiteral("tool.insert"), ProjectValidation::tr("the insert code"), out);
    checkClamping(project.clamping, project.part.length_mm(), QString(), out);
    checkPasses(project.passes, QString(), out);
    checkTools(project.tool, project.boringTool, QString(), out);
    for (std::size_t i = 0; i < project.furtherOperations.size(); ++i) {
        const Operation &op = project.furtherOperations[i];
        const QString prefix = QStringLiteral("further_operations[%1].").arg(i);
        checkClamping(op.clamping, project.part.length_mm(), prefix, out);
        checkPasses(op.passes, prefix, out);
        requireText(op.tool.insertCode, prefix + QStringLiteral("tool.insert"),
                    ProjectValidation::tr("the insert code"), out);
        checkTools(op.tool, op.boringTool, prefix, out);
    }
    checkDatums(project, out);
    checkTolerances(project, out);
    checkCuttingModel(project, out);
    checkCharacterisation(project, out);
    checkEnvironment(project.environment, out);
    checkThermalConditions(project, out);
    checkPlanning(project, out);
    checkMilledFeatures(project, out);
    const Diagnostics operations = checkOperations(project);
    out.insert(out.end(), operations.begin(), operations.end());
    return out;
}

} // namespace tolturn
