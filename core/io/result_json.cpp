// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/result_json.h"

#include "core/common/diagnostic.h"
#include "core/project/keywords.h"
#include "core/tolerance/range_verdicts.h"

#include <QJsonValue>

#include <cmath>
#include <optional>
#include <utility>

namespace tolturn {

namespace {

QJsonObject contributionsJson(const Contributions &c, bool radial)
{
    QJsonObject o{{QStringLiteral("total"), c.total_mm() * kUmPerMm},
                  {QStringLiteral("spindle_chuck"), c.spindleChuck_mm * kUmPerMm},
                  {QStringLiteral("workpiece"), c.workpiece_mm * kUmPerMm},
                  {QStringLiteral("boring_bar"), c.boringBar_mm * kUmPerMm}};
    if (radial) {
        o.insert(QStringLiteral("toolpost"), c.toolpost_mm * kUmPerMm);
        o.insert(QStringLiteral("thermal"), c.thermal_mm * kUmPerMm);
    }
    return o;
}

QJsonObject stationJson(const Station &st)
{
    return {{QStringLiteral("z_mm"), st.z_mm},
            {QStringLiteral("nominal_diameter_mm"), 2.0 * st.nominalRadius_mm},
            {QStringLiteral("spindle_speed_rpm"), st.spindleSpeed_rpm},
            {QStringLiteral("radial_um"), contributionsJson(st.radial, true)},
            {QStringLiteral("tangential_um"), contributionsJson(st.tangential, false)},
            {QStringLiteral("radius_error_um"), st.radiusError_mm * kUmPerMm},
            {QStringLiteral("diameter_error_um"), 2.0 * st.radiusError_mm * kUmPerMm},
            {QStringLiteral("section_rotation_urad"), st.sectionRotation_rad * 1e6}};
}

// The boring bar and its forces (docs/model.md §3.1).
QJsonObject boringBarJson(const BoringInputs &b)
{
    return {{QStringLiteral("holder"), b.holderCode},
            {QStringLiteral("material"), b.barMaterial},
            {QStringLiteral("diameter_mm"), b.bar.diameter_mm},
            {QStringLiteral("overhang_mm"), b.bar.overhang_mm},
            {QStringLiteral("overhang_ratio"), b.bar.overhangRatio()},
            {QStringLiteral("max_overhang_ratio"),
             b.maxOverhangRatio ? QJsonValue(b.maxOverhangRatio->value) : QJsonValue(QJsonValue::Null)},
            {QStringLiteral("edge_offset_mm"), b.bar.edgeOffset_mm},
            {QStringLiteral("youngs_modulus_MPa"), b.bar.material.youngsModulus_MPa},
            {QStringLiteral("tip_compliance_um_per_N"), b.compliance.transverse_mm_per_N() * kUmPerMm},
            {QStringLiteral("forces_N"), QJsonObject{{QStringLiteral("tangential"), b.forces.tangential_N},
                                                     {QStringLiteral("axial"), b.forces.axial_N},
                                                     {QStringLiteral("radial"), b.forces.radial_N}}}};
}

QString requiredKindKeyword(RequiredStiffness::Kind kind)
{
    switch (kind) {
    case RequiredStiffness::Kind::Found:
        return QStringLiteral("found");
    case RequiredStiffness::Kind::Window:
        return QStringLiteral("window");
    case RequiredStiffness::Kind::AnyStiffness:
        return QStringLiteral("any");
    case RequiredStiffness::Kind::NotReachable:
        return QStringLiteral("not_reachable");
    }
    return {};
}

QJsonValue requiredJson(const std::optional<RequiredStiffness> &r)
{
    if (!r)
        return QJsonValue::Null;
    QJsonObject o{{QStringLiteral("kind"), requiredKindKeyword(r->kind)}};
    if (r->kind != RequiredStiffness::Kind::NotReachable)
        o.insert(QStringLiteral("N_per_um"), r->value_N_per_mm / 1000.0);
    if (r->kind == RequiredStiffness::Kind::Window)
        o.insert(QStringLiteral("fails_again_at_N_per_um"), r->upper_N_per_mm / 1000.0);
    return o;
}

} // namespace

QJsonObject deviationJson(const QString &file, const Project &project, const DeviationResult &r)
{
    const TurningInputs &in = *r.inputs;
    QJsonArray features;
    for (const FeatureDeviation &f : r.features) {
        QJsonArray stations;
        for (const Station &st : f.stations)
            stations.append(stationJson(st));
        features.append(QJsonObject{{QStringLiteral("id"), f.featureId},
                                    {QStringLiteral("side"), contourName(f.side)},
                                    {QStringLiteral("type"), keyword(f.kind)},
                                    {QStringLiteral("stations"), stations}});
    }
    QJsonArray faces;
    for (const FaceConicity &f : r.faces)
        faces.append(QJsonObject{{QStringLiteral("id"), f.featureId},
                                 {QStringLiteral("side"), contourName(f.side)},
                                 {QStringLiteral("z_mm"), f.z_mm},
                                 {QStringLiteral("tan_theta"), f.tanTheta},
                                 {QStringLiteral("axial_runout_um"), f.axialRunout_mm * kUmPerMm}});
    QJsonArray warnings;
    for (const Diagnostic &d : r.diagnostics)
        warnings.append(diagnosticJson(d));
    QJsonObject json{
        {QStringLiteral("file"), file},
        {QStringLiteral("material"), project.materialId},
        {QStringLiteral("clamping"), keyword(project.clamping.method)},
        {QStringLiteral("force_model"), in.forceModel},
        {QStringLiteral("pass"), QJsonObject{{QStringLiteral("index"), in.passIndex}, // from 0, as in the file's list
                                             {QStringLiteral("number"), in.passIndex + 1}, // from 1, as --pass
                                             {QStringLiteral("kind"), keyword(in.pass.kind)},
                                             {QStringLiteral("cutting_speed_m_min"), in.pass.cuttingSpeed_m_min},
                                             {QStringLiteral("feed_mm_rev"), in.pass.feed_mm_rev},
                                             {QStringLiteral("depth_of_cut_mm"), in.pass.depthOfCut_mm}}},
        {QStringLiteral("forces_N"), QJsonObject{{QStringLiteral("tangential"), in.forces.tangential_N},
                                                 {QStringLiteral("axial"), in.forces.axial_N},
                                                 {QStringLiteral("radial"), in.forces.radial_N}}},
        {QStringLiteral("max_power_kW"), r.maxPower_kW},
        {QStringLiteral("max_torque_Nm"), r.maxTorque_Nm},
        {QStringLiteral("theoretical_Ra_um"), r.theoreticalRa_um},
        {QStringLiteral("theoretical_Rz_um"), r.theoreticalRz_um},
        {QStringLiteral("notes"), QJsonArray::fromStringList(in.notes)},
        {QStringLiteral("warnings"), warnings},
        {QStringLiteral("features"), features},
        {QStringLiteral("faces"), faces}};
    if (in.boring)
        json.insert(QStringLiteral("boring_bar"), boringBarJson(*in.boring));
    return json;
}

QJsonObject evaluationJson(const ToleranceEvaluation &e)
{
    QJsonObject o{{QStringLiteral("id"), e.toleranceId},      {QStringLiteral("type"), keyword(e.type)},
                  {QStringLiteral("feature"), e.featureId},   {QStringLiteral("verdict"), verdictKeyword(e.verdict)},
                  {QStringLiteral("condition"), e.condition}, {QStringLiteral("reason"), e.reason}};
    const std::pair<const char *, std::optional<double>> numbers[] = {{"value_um", e.value_um},
                                                                      {"limit_um", e.limit_um},
                                                                      {"utilisation_pct", e.utilisation_pct},
                                                                      {"nominal_mm", e.nominal_mm},
                                                                      {"upper_um", e.upper_um},
                                                                      {"lower_um", e.lower_um},
                                                                      {"predicted_max_um", e.predictedMax_um},
                                                                      {"predicted_min_um", e.predictedMin_um},
                                                                      {"offset_um", e.offset_um}};
    for (const auto &[key, value] : numbers) {
        if (value)
            o.insert(QLatin1String(key), *value);
    }
    return o;
}

QJsonObject rangeEvaluationJson(const ToleranceRangeEvaluation &e)
{
    QJsonObject o = evaluationJson(e.compliant);
    o.insert(QStringLiteral("range_verdict"), rangeVerdictKeyword(e.range));
    o.insert(QStringLiteral("range_verdict_text"), rangeVerdictText(e));
    if (e.offsetOnAnyMachine_um)
        o.insert(QStringLiteral("offset_on_any_machine_um"), *e.offsetOnAnyMachine_um);
    if (!e.unfinished.isEmpty())
        o.insert(QStringLiteral("unfinished"), QJsonArray::fromStringList(e.unfinished));
    if (e.stiff)
        o.insert(QStringLiteral("at_stiff_end"), evaluationJson(*e.stiff));
    o.insert(QStringLiteral("required_chuck_stiffness"), requiredJson(e.chuck));
    o.insert(QStringLiteral("required_tailstock_stiffness"), requiredJson(e.tailstock));
    return o;
}

QJsonObject passJson(const PassConditions &p)
{
    return {{QStringLiteral("cutting_speed_m_min"), p.cuttingSpeed_m_min},
            {QStringLiteral("feed_mm_rev"), p.feed_mm_rev},
            {QStringLiteral("depth_of_cut_mm"), p.depthOfCut_mm}};
}

QJsonArray constraintsJson(const std::vector<ConstraintValue> &list)
{
    QJsonArray out;
    for (const ConstraintValue &c : list) {
        QJsonObject o{{QStringLiteral("name"), c.name},
                      {QStringLiteral("subject"), c.subject},
                      {QStringLiteral("limit"), c.limit},
                      {QStringLiteral("unit"), c.unit}};
        // A value that is not finite has no number in JSON: it is said, and has no value.
        if (std::isfinite(c.value)) {
            o.insert(QStringLiteral("value"), c.value);
            o.insert(QStringLiteral("violation_pct"), 100.0 * c.violation());
        } else {
            o.insert(QStringLiteral("not_finite"), true);
        }
        out.append(o);
    }
    return out;
}

PassConditions roughingPassOf(const PlanResult &r, const PlanningProblem &problem)
{
    PassConditions p = r.candidate.roughing;
    if (r.candidate.roughingPasses > 0)
        p.depthOfCut_mm = (problem.radialStock_mm() - r.candidate.finishing.depthOfCut_mm) / r.candidate.roughingPasses;
    return p;
}

QJsonObject planJson(const PlanResult &r, const PlanningProblem &problem)
{
    const CandidateEvaluation &e = r.evaluation;
    const PlanningSettings &s = problem.project().planning;
    // Edges per part follow from the tool life: without Taylor constants they are not known (null),
    // not zero.
    const bool toolLifeKnown = problem.knowsToolLife();
    const QJsonValue edges = toolLifeKnown ? QJsonValue(e.toolEdgesPerPart) : QJsonValue();
    const QJsonValue changes = toolLifeKnown ? QJsonValue(s.toolChangeTime_min * e.toolEdgesPerPart) : QJsonValue();
    return {{QStringLiteral("feasible"), r.feasible},
            {QStringLiteral("objective"), keyword(problem.project().planning.objective)},
            {QStringLiteral("objective_value"), e.objective},
            {QStringLiteral("time_min"), e.time_min},
            {QStringLiteral("cost"), e.cost},
            {QStringLiteral("finishing_time_min"), e.finishingTime_min},
            {QStringLiteral("roughing_time_min"), e.roughingTime_min},
            {QStringLiteral("handling_time_min"), s.handlingTime_min},
            {QStringLiteral("tool_change_time_min"), changes},
            {QStringLiteral("tool_edges_per_part"), edges},
            {QStringLiteral("finishing"), passJson(r.candidate.finishing)},
            {QStringLiteral("roughing"), QJsonObject{{QStringLiteral("passes"), r.candidate.roughingPasses},
                                                     {QStringLiteral("pass"), passJson(roughingPassOf(r, problem))}}},
            {QStringLiteral("constraints"), constraintsJson(e.constraints)},
            {QStringLiteral("binding"), constraintsJson(r.binding)},
            {QStringLiteral("conflicts"), constraintsJson(r.conflicts)},
            {QStringLiteral("what_it_would_take"), QJsonArray::fromStringList(r.remedies)},
            {QStringLiteral("evaluations"), r.evaluations},
            {QStringLiteral("timed_out"), r.timedOut},
            {QStringLiteral("notes"), QJsonArray::fromStringList(r.notes)}};
}

QJsonObject classLimitsJson(const iso286::ClassLimits &l)
{
    return {{QStringLiteral("nominal_mm"), l.nominal_mm},
            {QStringLiteral("class"), l.toleranceClass},
            {QStringLiteral("upper_um"), l.upper_um},
            {QStringLiteral("lower_um"), l.lower_um},
            {QStringLiteral("it_grade"), l.itName},
            {QStringLiteral("it_um"), l.it_um},
            {QStringLiteral("fundamental_um"), l.fundamental_um}};
}

} // namespace tolturn
