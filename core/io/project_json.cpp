// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/project_json.h"

#include "core/io/input_bounds.h"
#include "core/io/json_reader.h"
#include "core/project/keywords.h"
#include "core/project/project_validation.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>

namespace tolturn {

namespace {

struct ProjectJson {
    Q_DECLARE_TR_FUNCTIONS(ProjectJson)
};

template <typename Enum>
std::optional<Enum> readKeyword(JsonObjectReader &reader, const QString &key, Presence presence, const QString &what)
{
    const auto word = reader.keywordText(key, presence, allKeywords<Enum>(), what);
    return word ? fromKeyword<Enum>(*word) : std::nullopt;
}

// ---- reading ---------------------------------------------------------------------------------

ProfilePoint readPoint(const QJsonObject &json, const QString &path, Diagnostics &out)
{
    JsonObjectReader r(json, path, out);
    ProfilePoint p;
    p.z_mm = r.number(QStringLiteral("z_mm"), Presence::Required).value_or(0.0);
    p.r_mm = r.number(QStringLiteral("r_mm"), Presence::Required).value_or(0.0);
    r.finish();
    return p;
}

Segment readSegment(const QJsonObject &json, const QString &path, Diagnostics &out)
{
    JsonObjectReader r(json, path, out);
    Segment s;
    s.id = r.text(QStringLiteral("id"), Presence::Required).value_or(QString());
    s.name = r.text(QStringLiteral("name"), Presence::Optional).value_or(QString());
    s.kind = readKeyword<SegmentKind>(r, QStringLiteral("type"), Presence::Required, ProjectJson::tr("segment type"))
                 .value_or(SegmentKind::Cylinder);
    if (const auto from = r.object(QStringLiteral("from"), Presence::Required))
        s.from = readPoint(*from, r.fieldPath(QStringLiteral("from")), out);
    if (const auto to = r.object(QStringLiteral("to"), Presence::Required))
        s.to = readPoint(*to, r.fieldPath(QStringLiteral("to")), out);
    if (s.kind == SegmentKind::Radius) {
        s.arcRadius_mm = r.number(QStringLiteral("radius_mm"), Presence::Required).value_or(0.0);
        s.arcDirection = readKeyword<ArcDirection>(r, QStringLiteral("direction"), Presence::Required,
                                                   ProjectJson::tr("arc direction"))
                             .value_or(ArcDirection::CounterClockwise);
    }
    r.finish();
    return s;
}

Contour readContour(const QJsonArray &json, const QString &path, Diagnostics &out)
{
    Contour c;
    for (qsizetype i = 0; i < json.size(); ++i) {
        const QString itemPath = elementPath(path, i);
        if (!json.at(i).isObject()) {
            out.push_back(makeError(
                itemPath, ProjectJson::tr("expected a segment object, found %1").arg(describeJsonValue(json.at(i)))));
            continue;
        }
        c.segments.push_back(readSegment(json.at(i).toObject(), itemPath, out));
    }
    return c;
}

PartProfile readPart(const QJsonObject &json, Diagnostics &out)
{
    JsonObjectReader r(json, QStringLiteral("part"), out);
    PartProfile part;
    part.name = r.text(QStringLiteral("name"), Presence::Optional).value_or(QString());
    part.drawingNumber = r.text(QStringLiteral("drawing_number"), Presence::Optional).value_or(QString());
    part.revision = r.text(QStringLiteral("revision"), Presence::Optional).value_or(QString());
    part.stockDiameter_mm = r.number(QStringLiteral("stock_diameter_mm"), Presence::Required).value_or(0.0);
    if (const auto outer = r.array(QStringLiteral("outer"), Presence::Required))
        part.outer = readContour(*outer, QStringLiteral("part.outer"), out);
    if (const auto inner = r.array(QStringLiteral("inner"), Presence::Optional))
        part.inner = readContour(*inner, QStringLiteral("part.inner"), out);
    r.finish();
    return part;
}

Tool readTool(const QJsonObject &json, const QString &path, Diagnostics &out)
{
    JsonObjectReader r(json, path, out);
    Tool tool;
    tool.insertCode = r.text(QStringLiteral("insert"), Presence::Required).value_or(QString());
    tool.holderCode = r.text(QStringLiteral("holder"), Presence::Optional).value_or(QString());
    tool.overhang_mm = r.number(QStringLiteral("overhang_mm"), Presence::Optional);
    tool.rake_deg = r.number(QStringLiteral("rake_deg"), Presence::Optional);
    tool.inclination_deg = r.number(QStringLiteral("inclination_deg"), Presence::Optional);
    tool.edgeOffset_mm = r.number(QStringLiteral("edge_offset_mm"), Presence::Optional);
    tool.pilotHoleDiameter_mm = r.number(QStringLiteral("pilot_hole_diameter_mm"), Presence::Optional);
    r.finish();
    return tool;
}

CuttingModel readCuttingModel(const QJsonObject &json, Diagnostics &out)
{
    JsonObjectReader r(json, QStringLiteral("cutting_model"), out);
    CuttingModel m;
    m.forceModel =
        readKeyword<ForceModel>(r, QStringLiteral("force_model"), Presence::Optional, ProjectJson::tr("force model"))
            .value_or(ForceModel::Kienzle);
    m.feedToCuttingRatio = r.number(QStringLiteral("feed_to_cutting_ratio"), Presence::Optional);
    m.passiveToCuttingRatio = r.number(QStringLiteral("passive_to_cutting_ratio"), Presence::Optional);
    m.normalPressure_MPa = r.number(QStringLiteral("normal_pressure_MPa"), Presence::Optional);
    m.frictionRatio = r.number(QStringLiteral("friction_ratio"), Presence::Optional);
    r.finish();
    return m;
}

std::optional<SpindleSprings> readSprings(JsonObjectReader &parent, const QString &key, Diagnostics &out)
{
    const auto json = parent.object(key, Presence::Optional);
    if (!json)
        return std::nullopt;
    JsonObjectReader r(*json, parent.fieldPath(key), out);
    SpindleSprings s;
    s.k1_N_per_mm = r.number(QStringLiteral("k1_N_per_mm"), Presence::Required).value_or(0.0);
    s.k2_Nmm_per_rad = r.number(QStringLiteral("k2_Nmm_per_rad"), Presence::Required).value_or(0.0);
    s.k3_Nmm_per_rad = r.number(QStringLiteral("k3_Nmm_per_rad"), Presence::Required).value_or(0.0);
    r.finish();
    return s;
}

std::optional<SupportStiffness> readSupport(JsonObjectReader &parent, const QString &key, Diagnostics &out)
{
    const auto json = parent.object(key, Presence::Optional);
    if (!json)
        return std::nullopt;
    JsonObjectReader r(*json, parent.fieldPath(key), out);
    SupportStiffness s;
    s.radial_N_per_mm = r.number(QStringLiteral("radial_N_per_mm"), Presence::Required).value_or(0.0);
    s.tangential_N_per_mm = r.number(QStringLiteral("tangential_N_per_mm"), Presence::Required).value_or(0.0);
    r.finish();
    return s;
}

std::optional<ThermalDrift> readThermal(JsonObjectReader &parent, Diagnostics &out)
{
    const auto json = parent.object(QStringLiteral("thermal"), Presence::Optional);
    if (!json)
        return std::nullopt;
    JsonObjectReader r(*json, parent.fieldPath(QStringLiteral("thermal")), out);
    ThermalDrift t;
    t.drift_um_per_1000rpm = r.number(QStringLiteral("drift_um_per_1000rpm"), Presence::Required).value_or(0.0);
    t.drift_um_per_K = r.number(QStringLiteral("drift_um_per_K"), Presence::Optional).value_or(0.0);
    t.referenceTemperature_C = r.number(QStringLiteral("reference_temperature_C"), Presence::Optional).value_or(20.0);
    t.timeConstant_min = r.number(QStringLiteral("time_constant_min"), Presence::Required).value_or(0.0);
    r.finish();
    return t;
}

MachineCharacterisation readCharacterisation(const QJsonObject &json, Diagnostics &out)
{
    JsonObjectReader r(json, QStringLiteral("characterisation"), out);
    MachineCharacterisation c;
    c.source = r.text(QStringLiteral("source"), Presence::Required).value_or(QString());
    c.pivotDistance_mm = r.number(QStringLiteral("pivot_distance_mm"), Presence::Optional);
    c.spindleRadial = readSprings(r, QStringLiteral("spindle_radial"), out);
    c.spindleTangential = readSprings(r, QStringLiteral("spindle_tangential"), out);
    c.tailstock = readSupport(r, QStringLiteral("tailstock"), out);
    c.centres = readSupport(r, QStringLiteral("centres"), out);
    c.thermal = readThermal(r, out);
    r.finish();
    return c;
}

std::optional<ValueRange> readRange(JsonObjectReader &parent, const QString &key, Diagnostics &out)
{
    const auto json = parent.object(key, Presence::Optional);
    if (!json)
        return std::nullopt;
    JsonObjectReader r(*json, parent.fieldPath(key), out);
    ValueRange range;
    range.min = r.number(QStringLiteral("min"), Presence::Required).value_or(0.0);
    range.max = r.number(QStringLiteral("max"), Presence::Required).value_or(0.0);
    r.finish();
    return range;
}

// A list of texts; `expected` says what each is ("expected a feature id, found the number 1").
QStringList readTextList(JsonObjectReader &r, const QString &key, const QString &expected, Diagnostics &out)
{
    QStringList items;
    const auto json = r.array(key, Presence::Optional);
    if (!json)
        return items;
    for (qsizetype i = 0; i < json->size(); ++i) {
        if (json->at(i).isString())
            items << json->at(i).toString();
        else
            out.push_back(
                makeError(elementPath(r.fieldPath(key), i),
                          ProjectJson::tr("expected %1, found %2").arg(expected, describeJsonValue(json->at(i)))));
    }
    return items;
}

PlanningSettings readPlanning(const QJsonObject &json, Diagnostics &out)
{
    JsonObjectReader r(json, QStringLiteral("planning"), out);
    PlanningSettings p;
    p.objective =
        readKeyword<PlanningObjective>(r, QStringLiteral("objective"), Presence::Optional, ProjectJson::tr("objective"))
            .value_or(PlanningObjective::Time);
    p.machineRate_per_min = r.number(QStringLiteral("machine_rate_per_min"), Presence::Optional).value_or(0.0);
    p.toolCostPerEdge = r.number(QStringLiteral("tool_cost_per_edge"), Presence::Optional).value_or(0.0);
    p.toolChangeTime_min = r.number(QStringLiteral("tool_change_time_min"), Presence::Optional).value_or(0.0);
    p.handlingTime_min = r.number(QStringLiteral("handling_time_min"), Presence::Optional).value_or(0.0);
    if (const auto life = r.object(QStringLiteral("tool_life"), Presence::Optional)) {
        JsonObjectReader t(*life, r.fieldPath(QStringLiteral("tool_life")), out);
        p.taylorC_m_min = t.number(QStringLiteral("C_m_min"), Presence::Required);
        p.taylorN = t.number(QStringLiteral("n"), Presence::Required);
        p.minToolLife_min = t.number(QStringLiteral("min_minutes"), Presence::Optional);
        p.toolLifeSource = t.text(QStringLiteral("source"), Presence::Required).value_or(QString());
        t.finish();
    }
    if (const auto ranges = r.object(QStringLiteral("ranges"), Presence::Optional)) {
        JsonObjectReader g(*ranges, r.fieldPath(QStringLiteral("ranges")), out);
        p.cuttingSpeed_m_min = readRange(g, QStringLiteral("cutting_speed_m_min"), out);
        p.feed_mm_rev = readRange(g, QStringLiteral("feed_mm_rev"), out);
        p.depthOfCut_mm = readRange(g, QStringLiteral("depth_of_cut_mm"), out);
        p.rangesSource = g.text(QStringLiteral("source"), Presence::Required).value_or(QString());
        g.finish();
    }
    p.maxRa_um = r.number(QStringLiteral("max_ra_um"), Presence::Optional);
    p.maxRz_um = r.number(QStringLiteral("max_rz_um"), Presence::Optional);
    p.maxForce_N = r.number(QStringLiteral("max_force_N"), Presence::Optional);
    p.maxPower_kW = r.number(QStringLiteral("max_power_kW"), Presence::Optional);
    p.maxTorque_Nm = r.number(QStringLiteral("max_torque_Nm"), Presence::Optional);
    p.maxSpindleSpeed_rpm = r.number(QStringLiteral("max_spindle_speed_rpm"), Presence::Optional);
    p.disabledConstraints =
        readTextList(r, QStringLiteral("disabled_constraints"), ProjectJson::tr("a constraint name"), out);
    r.finish();
    return p;
}

Environment readEnvironment(const QJsonObject &json, Diagnostics &out)
{
    JsonObjectReader r(json, QStringLiteral("environment"), out);
    Environment e;
    e.ambientTemperature_C = r.number(QStringLiteral("ambient_temperature_C"), Presence::Optional);
    e.timeSinceStart_min = r.number(QStringLiteral("time_since_start_min"), Presence::Optional);
    r.finish();
    return e;
}

Clamping readClamping(const QJsonObject &json, const QString &path, Diagnostics &out)
{
    JsonObjectReader r(json, path, out);
    Clamping c;
    c.method =
        readKeyword<ClampingMethod>(r, QStringLiteral("method"), Presence::Required, ProjectJson::tr("clamping method"))
            .value_or(ClampingMethod::Chuck);
    c.clampedLength_mm = r.number(QStringLiteral("clamped_length_mm"), Presence::Optional).value_or(0.0);
    c.heldEnd = readKeyword<PartEnd>(r, QStringLiteral("held_end"), Presence::Optional, ProjectJson::tr("part end"))
                    .value_or(PartEnd::Left);
    r.finish();
    return c;
}

template <typename T, typename ReadOne>
std::vector<T> readList(JsonObjectReader &parent, const QString &key, Diagnostics &out, ReadOne readOne)
{
    std::vector<T> items;
    const auto json = parent.array(key, Presence::Optional);
    if (!json)
        return items;
    const QString path = parent.fieldPath(key);
    for (qsizetype i = 0; i < json->size(); ++i) {
        const QString itemPath = elementPath(path, i);
        if (!json->at(i).isObject()) {
            out.push_back(makeError(
                itemPath, ProjectJson::tr("expected an object, found %1").arg(describeJsonValue(json->at(i)))));
            continue;
        }
        JsonObjectReader r(json->at(i).toObject(), itemPath, out);
        items.push_back(readOne(r));
        r.finish();
    }
    return items;
}

CuttingPass readPass(JsonObjectReader &r)
{
    CuttingPass p;
    p.kind = readKeyword<PassKind>(r, QStringLiteral("kind"), Presence::Required, ProjectJson::tr("pass kind"))
                 .value_or(PassKind::Finishing);
    p.cuttingSpeed_m_min = r.number(QStringLiteral("cutting_speed_m_min"), Presence::Required).value_or(0.0);
    p.feed_mm_rev = r.number(QStringLiteral("feed_mm_rev"), Presence::Required).value_or(0.0);
    p.depthOfCut_mm = r.number(QStringLiteral("depth_of_cut_mm"), Presence::Required).value_or(0.0);
    return p;
}

// One of "further_operations" (format version 2, docs/project-format.md).
Operation readOperation(JsonObjectReader &r, Diagnostics &out)
{
    Operation op;
    op.name = r.text(QStringLiteral("name"), Presence::Required).value_or(QString());
    if (const auto clamping = r.object(QStringLiteral("clamping"), Presence::Required))
        op.clamping = readClamping(*clamping, r.fieldPath(QStringLiteral("clamping")), out);
    if (const auto tool = r.object(QStringLiteral("tool"), Presence::Required))
        op.tool = readTool(*tool, r.fieldPath(QStringLiteral("tool")), out);
    if (const auto tool = r.object(QStringLiteral("boring_tool"), Presence::Optional))
        op.boringTool = readTool(*tool, r.fieldPath(QStringLiteral("boring_tool")), out);
    op.passes = readList<CuttingPass>(r, QStringLiteral("passes"), out, readPass);
    op.features = readTextList(r, QStringLiteral("features"), ProjectJson::tr("a feature id"), out);
    return op;
}

Datum readDatum(JsonObjectReader &r)
{
    Datum d;
    d.label = r.text(QStringLiteral("label"), Presence::Required).value_or(QString());
    d.featureId = r.text(QStringLiteral("feature"), Presence::Required).value_or(QString());
    return d;
}

Tolerance readTolerance(JsonObjectReader &r, Diagnostics &out)
{
    Tolerance t;
    t.id = r.text(QStringLiteral("id"), Presence::Required).value_or(QString());
    t.type =
        readKeyword<ToleranceType>(r, QStringLiteral("type"), Presence::Required, ProjectJson::tr("tolerance type"))
            .value_or(ToleranceType::Diameter);
    t.featureId = r.text(QStringLiteral("feature"), Presence::Required).value_or(QString());
    if (t.type == ToleranceType::Length)
        t.toFeatureId = r.text(QStringLiteral("to_feature"), Presence::Required).value_or(QString());
    if (isSizeTolerance(t.type)) {
        t.iso286Class = r.text(QStringLiteral("iso286"), Presence::Optional).value_or(QString());
        t.upperDeviation_um = r.number(QStringLiteral("upper_um"), Presence::Optional);
        t.lowerDeviation_um = r.number(QStringLiteral("lower_um"), Presence::Optional);
    } else {
        t.zone_um = r.number(QStringLiteral("value_um"), Presence::Required);
        t.datums = readTextList(r, QStringLiteral("datums"), ProjectJson::tr("a datum letter"), out);
    }
    return t;
}

// ---- milled features (docs/project-format.md "Milled features") ------------------------------

std::optional<double> readOptionalNumber(JsonObjectReader &r, const char *key)
{
    return r.number(QLatin1String(key), Presence::Optional);
}

BallEndTool readBallEndTool(const QJsonObject &json, const QString &path, Diagnostics &out)
{
    JsonObjectReader r(json, path, out);
    BallEndTool t;
    t.diameter_mm = r.number(QStringLiteral("diameter_mm"), Presence::Required).value_or(0.0);
    t.flutes = r.integer(QStringLiteral("flutes"), Presence::Required).value_or(0);
    t.helix_deg = r.number(QStringLiteral("helix_deg"), Presence::Required).value_or(0.0);
    t.overhang_mm = r.number(QStringLiteral("overhang_mm"), Presence::Required).value_or(0.0);
    t.equivalentDiameter_mm = r.number(QStringLiteral("equivalent_diameter_mm"), Presence::Required).value_or(0.0);
    t.youngsModulus_N_mm2 = readOptionalNumber(r, "youngs_modulus_N_mm2");
    t.holderStiffness_N_mm = readOptionalNumber(r, "holder_stiffness_N_mm");
    t.holderRotational_N_mm_rad = readOptionalNumber(r, "holder_rotational_Nmm_rad");
    r.finish();
    return t;
}

MillingConditions readMillingConditions(const QJsonObject &json, const QString &path, Diagnostics &out)
{
    JsonObjectReader r(json, path, out);
    MillingConditions c;
    c.cut = readKeyword<BallEndCutKind>(r, QStringLiteral("cut"), Presence::Required, ProjectJson::tr("cut"))
                .value_or(BallEndCutKind::Slot);
    c.direction = readKeyword<MillingDirection>(r, QStringLiteral("direction"), Presence::Optional,
                                                ProjectJson::tr("milling direction"))
                      .value_or(MillingDirection::Down);
    c.axialDepth_mm = r.number(QStringLiteral("axial_depth_mm"), Presence::Required).value_or(0.0);
    c.radialDepth_mm = r.number(QStringLiteral("radial_depth_mm"),
                                c.cut == BallEndCutKind::Slot ? Presence::Optional : Presence::Required)
                           .value_or(0.0);
    c.feedPerTooth_mm = r.number(QStringLiteral("feed_per_tooth_mm"), Presence::Required).value_or(0.0);
    c.spindle_rpm = r.number(QStringLiteral("spindle_rpm"), Presence::Required).value_or(0.0);
    c.lead_deg = r.number(QStringLiteral("lead_deg"), Presence::Optional).value_or(0.0);
    c.tilt_deg = r.number(QStringLiteral("tilt_deg"), Presence::Optional).value_or(0.0);
    r.finish();
    return c;
}

MillingForceCoefficients readMillingCoefficients(const QJsonObject &json, const QString &path, QString &source,
                                                 Diagnostics &out)
{
    JsonObjectReader r(json, path, out);
    MillingForceCoefficients k;
    k.tangentialCutting_N_mm2 = r.number(QStringLiteral("Ktc_N_mm2"), Presence::Required).value_or(0.0);
    k.radialCutting_N_mm2 = r.number(QStringLiteral("Krc_N_mm2"), Presence::Required).value_or(0.0);
    k.axialCutting_N_mm2 = r.number(QStringLiteral("Kac_N_mm2"), Presence::Required).value_or(0.0);
    k.tangentialEdge_N_mm = r.number(QStringLiteral("Kte_N_mm"), Presence::Required).value_or(0.0);
    k.radialEdge_N_mm = r.number(QStringLiteral("Kre_N_mm"), Presence::Required).value_or(0.0);
    k.axialEdge_N_mm = r.number(QStringLiteral("Kae_N_mm"), Presence::Required).value_or(0.0);
    source = r.text(QStringLiteral("source"), Presence::Optional).value_or(QString());
    r.finish();
    return k;
}

MilledTolerance readMilledTolerance(const QJsonObject &json, const QString &path, Diagnostics &out)
{
    JsonObjectReader r(json, path, out);
    MilledTolerance t;
    t.type = readKeyword<MilledToleranceType>(r, QStringLiteral("type"), Presence::Required,
                                              ProjectJson::tr("milled tolerance type"))
                 .value_or(MilledToleranceType::Flatness);
    t.zone_um = r.number(QStringLiteral("value_um"), Presence::Required).value_or(0.0);
    t.datums = readTextList(r, QStringLiteral("datums"), ProjectJson::tr("a datum letter"), out);
    r.finish();
    return t;
}

// [x, y, z]: three numbers, or an error naming the field.
std::array<double, 3> readTriple(JsonObjectReader &r, const QString &key, Diagnostics &out)
{
    std::array<double, 3> v{};
    const auto json = r.array(key, Presence::Required);
    if (!json)
        return v;
    if (json->size() != 3) {
        out.push_back(
            makeError(r.fieldPath(key), ProjectJson::tr("expected three numbers, found %1").arg(json->size())));
        return v;
    }
    for (qsizetype i = 0; i < 3; ++i) {
        if (!json->at(i).isDouble())
            out.push_back(
                makeError(elementPath(r.fieldPath(key), i),
                          ProjectJson::tr("expected a number, found %1").arg(describeJsonValue(json->at(i)))));
        v[static_cast<std::size_t>(i)] = json->at(i).toDouble();
    }
    return v;
}

ClPoint readClPoint(JsonObjectReader &r, Diagnostics &out)
{
    ClPoint p;
    p.position_mm = readTriple(r, QStringLiteral("tip_mm"), out);
    p.toolAxis = readTriple(r, QStringLiteral("axis"), out);
    p.surfaceNormal = readTriple(r, QStringLiteral("normal"), out);
    return p;
}

MilledFeature readMilledFeature(JsonObjectReader &r, Diagnostics &out)
{
    MilledFeature f;
    f.id = r.text(QStringLiteral("id"), Presence::Required).value_or(QString());
    f.kind = readKeyword<MilledFeatureKind>(r, QStringLiteral("kind"), Presence::Required,
                                            ProjectJson::tr("milled feature kind"))
                 .value_or(MilledFeatureKind::Flat);
    f.description = r.text(QStringLiteral("description"), Presence::Optional).value_or(QString());
    f.zFrom_mm = r.number(QStringLiteral("z_from_mm"), Presence::Required).value_or(0.0);
    f.zTo_mm = r.number(QStringLiteral("z_to_mm"), Presence::Required).value_or(0.0);
    if (const auto tool = r.object(QStringLiteral("tool"), Presence::Optional))
        f.tool = readBallEndTool(*tool, r.fieldPath(QStringLiteral("tool")), out);
    if (const auto conditions = r.object(QStringLiteral("conditions"), Presence::Optional))
        f.conditions = readMillingConditions(*conditions, r.fieldPath(QStringLiteral("conditions")), out);
    if (const auto coefficients = r.object(QStringLiteral("coefficients"), Presence::Optional))
        f.coefficients = readMillingCoefficients(*coefficients, r.fieldPath(QStringLiteral("coefficients")),
                                                 f.coefficientsSource, out);
    if (const auto tolerance = r.object(QStringLiteral("tolerance"), Presence::Optional))
        f.tolerance = readMilledTolerance(*tolerance, r.fieldPath(QStringLiteral("tolerance")), out);
    f.path = readList<ClPoint>(r, QStringLiteral("path"), out,
                               [&out](JsonObjectReader &point) { return readClPoint(point, out); });
    return f;
}

std::optional<Project> readProject(const QJsonObject &root, Diagnostics &out)
{
    JsonObjectReader r(root, QString(), out);
    const auto format = r.text(QStringLiteral("format"), Presence::Required);
    if (format && *format != QLatin1String(kProjectFormatName)) {
        out.push_back(
            makeError(QStringLiteral("format"), ProjectJson::tr("this is not a TolTurn project: format is \"%1\", "
                                                                "expected \"%2\"")
                                                    .arg(*format, QLatin1String(kProjectFormatName))));
        return std::nullopt;
    }
    const auto version = r.integer(QStringLiteral("version"), Presence::Required);
    // Version 1 is read as it is: a project of one operation, held at its left end (the upgrade,
    // docs/project-format.md "Versions"); it is written back as version 2.
    if (version && *version != kProjectFormatVersion && *version != 1) {
        out.push_back(makeError(QStringLiteral("version"),
                                ProjectJson::tr("unknown format version %1; this TolTurn reads versions 1 to %2")
                                    .arg(*version)
                                    .arg(kProjectFormatVersion)));
        return std::nullopt;
    }
    if (hasErrors(out))
        return std::nullopt;

    Project p;
    if (const auto part = r.object(QStringLiteral("part"), Presence::Required))
        p.part = readPart(*part, out);
    p.materialId = r.text(QStringLiteral("material"), Presence::Required).value_or(QString());
    p.machineId = r.text(QStringLiteral("machine"), Presence::Required).value_or(QString());
    if (const auto tool = r.object(QStringLiteral("tool"), Presence::Required))
        p.tool = readTool(*tool, QStringLiteral("tool"), out);
    if (const auto tool = r.object(QStringLiteral("boring_tool"), Presence::Optional))
        p.boringTool = readTool(*tool, QStringLiteral("boring_tool"), out);
    if (const auto clamping = r.object(QStringLiteral("clamping"), Presence::Required))
        p.clamping = readClamping(*clamping, QStringLiteral("clamping"), out);
    p.passes = readList<CuttingPass>(r, QStringLiteral("passes"), out, readPass);
    // Read in a version-1 file too (a hand-edited one): left unknown there, they would be written
    // back as version 2, where they mean something, and the project would change on its reload.
    p.firstOperationName = r.text(QStringLiteral("first_operation_name"), Presence::Optional).value_or(QString());
    p.furtherOperations = readList<Operation>(r, QStringLiteral("further_operations"), out,
                                              [&out](JsonObjectReader &op) { return readOperation(op, out); });
    p.datums = readList<Datum>(r, QStringLiteral("datums"), out, readDatum);
    if (const auto model = r.object(QStringLiteral("cutting_model"), Presence::Optional))
        p.cuttingModel = readCuttingModel(*model, out);
    if (const auto characterisation = r.object(QStringLiteral("characterisation"), Presence::Optional))
        p.characterisation = readCharacterisation(*characterisation, out);
    if (const auto environment = r.object(QStringLiteral("environment"), Presence::Optional))
        p.environment = readEnvironment(*environment, out);
    if (const auto planning = r.object(QStringLiteral("planning"), Presence::Optional))
        p.planning = readPlanning(*planning, out);
    p.tolerances = readList<Tolerance>(r, QStringLiteral("tolerances"), out,
                                       [&out](JsonObjectReader &reader) { return readTolerance(reader, out); });
    p.milledFeatures =
        readList<MilledFeature>(r, QStringLiteral("milled_features"), out,
                                [&out](JsonObjectReader &reader) { return readMilledFeature(reader, out); });
    r.finish();
    return p;
}

// Line and column of a byte offset, for parse error messages.
std::pair<int, int> lineColumn(const QByteArray &text, int offset)
{
    int line = 1;
    int column = 1;
    for (int i = 0; i < offset && i < text.size(); ++i) {
        if (text.at(i) == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return {line, column};
}

// ---- writing ---------------------------------------------------------------------------------

QJsonObject pointJson(const ProfilePoint &p)
{
    return {{QStringLiteral("z_mm"), p.z_mm}, {QStringLiteral("r_mm"), p.r_mm}};
}

QJsonArray contourJson(const Contour &contour)
{
    QJsonArray out;
    for (const Segment &s : contour.segments) {
        QJsonObject o{{QStringLiteral("id"), s.id},
                      {QStringLiteral("type"), keyword(s.kind)},
                      {QStringLiteral("from"), pointJson(s.from)},
                      {QStringLiteral("to"), pointJson(s.to)}};
        if (!s.name.isEmpty())
            o.insert(QStringLiteral("name"), s.name);
        if (s.kind == SegmentKind::Radius) {
            o.insert(QStringLiteral("radius_mm"), s.arcRadius_mm);
            o.insert(QStringLiteral("direction"), keyword(s.arcDirection));
        }
        out.append(o);
    }
    return out;
}

QJsonObject toleranceJson(const Tolerance &t)
{
    QJsonObject o{{QStringLiteral("id"), t.id},
                  {QStringLiteral("type"), keyword(t.type)},
                  {QStringLiteral("feature"), t.featureId}};
    if (t.type == ToleranceType::Length)
        o.insert(QStringLiteral("to_feature"), t.toFeatureId);
    if (!t.iso286Class.isEmpty())
        o.insert(QStringLiteral("iso286"), t.iso286Class);
    if (t.upperDeviation_um)
        o.insert(QStringLiteral("upper_um"), *t.upperDeviation_um);
    if (t.lowerDeviation_um)
        o.insert(QStringLiteral("lower_um"), *t.lowerDeviation_um);
    if (t.zone_um)
        o.insert(QStringLiteral("value_um"), *t.zone_um);
    if (!t.datums.isEmpty())
        o.insert(QStringLiteral("datums"), QJsonArray::fromStringList(t.datums));
    return o;
}

void insertOptional(QJsonObject &o, const char *key, const std::optional<double> &value)
{
    if (value)
        o.insert(QLatin1String(key), *value);
}

QJsonObject toolJson(const Tool &t)
{
    QJsonObject tool{{QStringLiteral("insert"), t.insertCode}};
    if (!t.holderCode.isEmpty())
        tool.insert(QStringLiteral("holder"), t.holderCode);
    insertOptional(tool, "overhang_mm", t.overhang_mm);
    insertOptional(tool, "rake_deg", t.rake_deg);
    insertOptional(tool, "inclination_deg", t.inclination_deg);
    insertOptional(tool, "edge_offset_mm", t.edgeOffset_mm);
    insertOptional(tool, "pilot_hole_diameter_mm", t.pilotHoleDiameter_mm);
    return tool;
}

QJsonObject clampingJson(const Clamping &c)
{
    QJsonObject o{{QStringLiteral("method"), keyword(c.method)},
                  {QStringLiteral("clamped_length_mm"), c.clampedLength_mm}};
    if (c.heldEnd != PartEnd::Left)
        o.insert(QStringLiteral("held_end"), keyword(c.heldEnd));
    return o;
}

QJsonArray passesJson(const std::vector<CuttingPass> &list)
{
    QJsonArray passes;
    for (const CuttingPass &pass : list)
        passes.append(QJsonObject{{QStringLiteral("kind"), keyword(pass.kind)},
                                  {QStringLiteral("cutting_speed_m_min"), pass.cuttingSpeed_m_min},
                                  {QStringLiteral("feed_mm_rev"), pass.feed_mm_rev},
                                  {QStringLiteral("depth_of_cut_mm"), pass.depthOfCut_mm}});
    return passes;
}

QJsonObject operationJson(const Operation &op)
{
    QJsonObject o{{QStringLiteral("name"), op.name},
                  {QStringLiteral("clamping"), clampingJson(op.clamping)},
                  {QStringLiteral("tool"), toolJson(op.tool)},
                  {QStringLiteral("passes"), passesJson(op.passes)},
                  {QStringLiteral("features"), QJsonArray::fromStringList(op.features)}};
    if (op.boringTool)
        o.insert(QStringLiteral("boring_tool"), toolJson(*op.boringTool));
    return o;
}

QJsonArray tripleJson(const std::array<double, 3> &v)
{
    return QJsonArray{v[0], v[1], v[2]};
}

QJsonObject ballEndToolJson(const BallEndTool &t)
{
    QJsonObject o{{QStringLiteral("diameter_mm"), t.diameter_mm},
                  {QStringLiteral("flutes"), t.flutes},
                  {QStringLiteral("helix_deg"), t.helix_deg},
                  {QStringLiteral("overhang_mm"), t.overhang_mm},
                  {QStringLiteral("equivalent_diameter_mm"), t.equivalentDiameter_mm}};
    insertOptional(o, "youngs_modulus_N_mm2", t.youngsModulus_N_mm2);
    insertOptional(o, "holder_stiffness_N_mm", t.holderStiffness_N_mm);
    insertOptional(o, "holder_rotational_Nmm_rad", t.holderRotational_N_mm_rad);
    return o;
}

QJsonObject millingConditionsJson(const MillingConditions &c)
{
    QJsonObject o{{QStringLiteral("cut"), keyword(c.cut)},
                  {QStringLiteral("direction"), keyword(c.direction)},
                  {QStringLiteral("axial_depth_mm"), c.axialDepth_mm},
                  {QStringLiteral("feed_per_tooth_mm"), c.feedPerTooth_mm},
                  {QStringLiteral("spindle_rpm"), c.spindle_rpm},
                  {QStringLiteral("lead_deg"), c.lead_deg},
                  {QStringLiteral("tilt_deg"), c.tilt_deg}};
    if (c.cut != BallEndCutKind::Slot || c.radialDepth_mm != 0.0) // a slot's is read back, so kept
        o.insert(QStringLiteral("radial_depth_mm"), c.radialDepth_mm);
    return o;
}

QJsonObject millingCoefficientsJson(const MillingForceCoefficients &k, const QString &source)
{
    QJsonObject o{
        {QStringLiteral("Ktc_N_mm2"), k.tangentialCutting_N_mm2}, {QStringLiteral("Krc_N_mm2"), k.radialCutting_N_mm2},
        {QStringLiteral("Kac_N_mm2"), k.axialCutting_N_mm2},      {QStringLiteral("Kte_N_mm"), k.tangentialEdge_N_mm},
        {QStringLiteral("Kre_N_mm"), k.radialEdge_N_mm},          {QStringLiteral("Kae_N_mm"), k.axialEdge_N_mm}};
    if (!source.isEmpty())
        o.insert(QStringLiteral("source"), source);
    return o;
}

} // namespace

QJsonObject milledFeatureJson(const MilledFeature &f)
{
    QJsonObject o{{QStringLiteral("id"), f.id},
                  {QStringLiteral("kind"), keyword(f.kind)},
                  {QStringLiteral("z_from_mm"), f.zFrom_mm},
                  {QStringLiteral("z_to_mm"), f.zTo_mm}};
    if (!f.description.isEmpty())
        o.insert(QStringLiteral("description"), f.description);
    if (f.tool)
        o.insert(QStringLiteral("tool"), ballEndToolJson(*f.tool));
    if (f.conditions)
        o.insert(QStringLiteral("conditions"), millingConditionsJson(*f.conditions));
    if (f.coefficients)
        o.insert(QStringLiteral("coefficients"), millingCoefficientsJson(*f.coefficients, f.coefficientsSource));
    if (f.tolerance) {
        QJsonObject t{{QStringLiteral("type"), keyword(f.tolerance->type)},
                      {QStringLiteral("value_um"), f.tolerance->zone_um}};
        if (!f.tolerance->datums.isEmpty())
            t.insert(QStringLiteral("datums"), QJsonArray::fromStringList(f.tolerance->datums));
        o.insert(QStringLiteral("tolerance"), t);
    }
    if (!f.path.empty()) {
        QJsonArray path;
        for (const ClPoint &p : f.path)
            path.append(QJsonObject{{QStringLiteral("tip_mm"), tripleJson(p.position_mm)},
                                    {QStringLiteral("axis"), tripleJson(p.toolAxis)},
                                    {QStringLiteral("normal"), tripleJson(p.surfaceNormal)}});
        o.insert(QStringLiteral("path"), path);
    }
    return o;
}

MilledFeature milledFeatureFromJson(const QJsonObject &json, const QString &path, Diagnostics &out)
{
    JsonObjectReader r(json, path, out);
    MilledFeature f = readMilledFeature(r, out);
    r.finish();
    return f;
}

namespace {

QJsonObject springsJson(const SpindleSprings &s)
{
    return {{QStringLiteral("k1_N_per_mm"), s.k1_N_per_mm},
            {QStringLiteral("k2_Nmm_per_rad"), s.k2_Nmm_per_rad},
            {QStringLiteral("k3_Nmm_per_rad"), s.k3_Nmm_per_rad}};
}

QJsonObject supportJson(const SupportStiffness &s)
{
    return {{QStringLiteral("radial_N_per_mm"), s.radial_N_per_mm},
            {QStringLiteral("tangential_N_per_mm"), s.tangential_N_per_mm}};
}

QJsonObject characterisationJson(const MachineCharacterisation &c)
{
    QJsonObject o{{QStringLiteral("source"), c.source}};
    insertOptional(o, "pivot_distance_mm", c.pivotDistance_mm);
    if (c.spindleRadial)
        o.insert(QStringLiteral("spindle_radial"), springsJson(*c.spindleRadial));
    if (c.spindleTangential)
        o.insert(QStringLiteral("spindle_tangential"), springsJson(*c.spindleTangential));
    if (c.tailstock)
        o.insert(QStringLiteral("tailstock"), supportJson(*c.tailstock));
    if (c.centres)
        o.insert(QStringLiteral("centres"), supportJson(*c.centres));
    if (c.thermal)
        o.insert(QStringLiteral("thermal"),
                 QJsonObject{{QStringLiteral("drift_um_per_1000rpm"), c.thermal->drift_um_per_1000rpm},
                             {QStringLiteral("drift_um_per_K"), c.thermal->drift_um_per_K},
                             {QStringLiteral("reference_temperature_C"), c.thermal->referenceTemperature_C},
                             {QStringLiteral("time_constant_min"), c.thermal->timeConstant_min}});
    return o;
}

QJsonObject rangeJson(const ValueRange &r)
{
    return {{QStringLiteral("min"), r.min}, {QStringLiteral("max"), r.max}};
}

QJsonObject planningJson(const PlanningSettings &p)
{
    QJsonObject o{{QStringLiteral("objective"), keyword(p.objective)},
                  {QStringLiteral("machine_rate_per_min"), p.machineRate_per_min},
                  {QStringLiteral("tool_cost_per_edge"), p.toolCostPerEdge},
                  {QStringLiteral("tool_change_time_min"), p.toolChangeTime_min},
                  {QStringLiteral("handling_time_min"), p.handlingTime_min}};
    // Each part that is set, so that a file's values come back whatever else is missing.
    if (p.taylorC_m_min || p.taylorN || p.minToolLife_min || !p.toolLifeSource.isEmpty()) {
        QJsonObject life;
        insertOptional(life, "C_m_min", p.taylorC_m_min);
        insertOptional(life, "n", p.taylorN);
        insertOptional(life, "min_minutes", p.minToolLife_min);
        if (!p.toolLifeSource.isEmpty())
            life.insert(QStringLiteral("source"), p.toolLifeSource);
        o.insert(QStringLiteral("tool_life"), life);
    }
    if (p.cuttingSpeed_m_min || p.feed_mm_rev || p.depthOfCut_mm || !p.rangesSource.isEmpty()) {
        QJsonObject ranges;
        if (!p.rangesSource.isEmpty())
            ranges.insert(QStringLiteral("source"), p.rangesSource);
        if (p.cuttingSpeed_m_min)
            ranges.insert(QStringLiteral("cutting_speed_m_min"), rangeJson(*p.cuttingSpeed_m_min));
        if (p.feed_mm_rev)
            ranges.insert(QStringLiteral("feed_mm_rev"), rangeJson(*p.feed_mm_rev));
        if (p.depthOfCut_mm)
            ranges.insert(QStringLiteral("depth_of_cut_mm"), rangeJson(*p.depthOfCut_mm));
        o.insert(QStringLiteral("ranges"), ranges);
    }
    insertOptional(o, "max_ra_um", p.maxRa_um);
    insertOptional(o, "max_rz_um", p.maxRz_um);
    insertOptional(o, "max_force_N", p.maxForce_N);
    insertOptional(o, "max_power_kW", p.maxPower_kW);
    insertOptional(o, "max_torque_Nm", p.maxTorque_Nm);
    insertOptional(o, "max_spindle_speed_rpm", p.maxSpindleSpeed_rpm);
    if (!p.disabledConstraints.isEmpty())
        o.insert(QStringLiteral("disabled_constraints"), QJsonArray::fromStringList(p.disabledConstraints));
    return o;
}

QJsonObject cuttingModelJson(const CuttingModel &m)
{
    QJsonObject o{{QStringLiteral("force_model"), keyword(m.forceModel)}};
    insertOptional(o, "feed_to_cutting_ratio", m.feedToCuttingRatio);
    insertOptional(o, "passive_to_cutting_ratio", m.passiveToCuttingRatio);
    insertOptional(o, "normal_pressure_MPa", m.normalPressure_MPa);
    insertOptional(o, "friction_ratio", m.frictionRatio);
    return o;
}

} // namespace

ProjectParseResult parseProjectJson(const QByteArray &json)
{
    ProjectParseResult result;
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        const auto [line, column] = lineColumn(json, parseError.offset);
        result.diagnostics.push_back(makeError(QString(), ProjectJson::tr("invalid JSON at line %1, column %2: %3")
                                                              .arg(line)
                                                              .arg(column)
                                                              .arg(parseError.errorString())));
        return result;
    }
    if (!doc.isObject()) {
        result.diagnostics.push_back(
            makeError(QString(), ProjectJson::tr("a project file holds one JSON object, not a list")));
        return result;
    }
    std::vector<std::pair<QString, QJsonValue>> unknown;
    std::optional<Project> project;
    {
        const JsonObjectReader::CollectUnknown collect(unknown);
        project = readProject(doc.object(), result.diagnostics);
    }
    if (!project)
        return result;
    project->unknownFields = std::move(unknown);
    checkInputBounds(doc.object(), result.diagnostics);
    if (!hasErrors(result.diagnostics)) {
        const Diagnostics semantic = validateProject(*project);
        result.diagnostics.insert(result.diagnostics.end(), semantic.begin(), semantic.end());
    }
    if (hasErrors(result.diagnostics))
        result.repairable = std::move(project);
    else
        result.project = std::move(project);
    return result;
}

namespace {

// The steps of a field path: object keys (plain, or JSON strings in brackets) and list indices.
struct PathStep {
    QString key;    // empty for an index
    int index = -1; // -1 for a key
};

std::vector<PathStep> pathSteps(const QString &path)
{
    static const QRegularExpression step(QStringLiteral(R"(\.?([^.\[\]"]+)|\[(\d+)\]|\[("(?:[^"\\]|\\.)*")\])"));
    std::vector<PathStep> steps;
    qsizetype consumed = 0;
    for (auto it = step.globalMatch(path); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        if (m.capturedStart() != consumed)
            return {}; // not a path this program writes
        consumed = m.capturedEnd();
        if (m.capturedLength(1) > 0)
            steps.push_back({m.captured(1)});
        else if (m.capturedLength(2) > 0)
            steps.push_back({QString(), m.captured(2).toInt()});
        else
            steps.push_back({QJsonDocument::fromJson("[" + m.captured(3).toUtf8() + "]").array().at(0).toString()});
    }
    return consumed == path.size() ? steps : std::vector<PathStep>{};
}

// `node` with `value` at the steps from `at` where the parent still exists and the field is not
// set: an unknown field written back where it was.
QJsonValue withUnknownField(const QJsonValue &node, const std::vector<PathStep> &steps, std::size_t at,
                            const QJsonValue &value)
{
    if (at >= steps.size())
        return node;
    const PathStep &s = steps[at];
    const bool last = at + 1 == steps.size();
    if (s.index >= 0) {
        QJsonArray array = node.toArray();
        if (!node.isArray() || s.index >= array.size() || last)
            return node;
        array[s.index] = withUnknownField(array.at(s.index), steps, at + 1, value);
        return array;
    }
    if (!node.isObject())
        return node;
    QJsonObject object = node.toObject();
    if (last) {
        if (!object.contains(s.key))
            object.insert(s.key, value);
    } else if (object.contains(s.key) || steps[at + 1].index < 0) {
        // An object that held only unknown fields is written again to hold them.
        object.insert(
            s.key, withUnknownField(object.value(s.key).isUndefined() ? QJsonValue(QJsonObject()) : object.value(s.key),
                                    steps, at + 1, value));
    }
    return object;
}

} // namespace

QByteArray serializeProjectJson(const Project &project)
{
    return QJsonDocument(projectJsonObject(project)).toJson(QJsonDocument::Indented);
}

QJsonValue projectValueAt(const Project &project, const QString &field)
{
    QJsonValue value = projectJsonObject(project);
    for (const PathStep &step : pathSteps(field)) {
        value = step.index >= 0 ? value.toArray().at(step.index) : value.toObject().value(step.key);
        if (value.isUndefined())
            break;
    }
    return value;
}

QJsonObject projectJsonObject(const Project &p)
{
    QJsonObject part{{QStringLiteral("stock_diameter_mm"), p.part.stockDiameter_mm},
                     {QStringLiteral("outer"), contourJson(p.part.outer)}};
    if (!p.part.name.isEmpty())
        part.insert(QStringLiteral("name"), p.part.name);
    if (!p.part.drawingNumber.isEmpty())
        part.insert(QStringLiteral("drawing_number"), p.part.drawingNumber);
    if (!p.part.revision.isEmpty())
        part.insert(QStringLiteral("revision"), p.part.revision);
    if (!p.part.inner.empty())
        part.insert(QStringLiteral("inner"), contourJson(p.part.inner));

    const QJsonObject tool = toolJson(p.tool);

    QJsonArray datums;
    for (const Datum &d : p.datums)
        datums.append(QJsonObject{{QStringLiteral("label"), d.label}, {QStringLiteral("feature"), d.featureId}});
    QJsonArray tolerances;
    for (const Tolerance &t : p.tolerances)
        tolerances.append(toleranceJson(t));

    QJsonObject root{
        {QStringLiteral("format"), QLatin1String(kProjectFormatName)},
        {QStringLiteral("version"), kProjectFormatVersion},
        {QStringLiteral("part"), part},
        {QStringLiteral("material"), p.materialId},
        {QStringLiteral("machine"), p.machineId},
        {QStringLiteral("tool"), tool},
        {QStringLiteral("clamping"), clampingJson(p.clamping)},
        {QStringLiteral("passes"), passesJson(p.passes)},
        {QStringLiteral("datums"), datums},
        {QStringLiteral("tolerances"), tolerances},
    };
    if (p.boringTool)
        root.insert(QStringLiteral("boring_tool"), toolJson(*p.boringTool));
    if (!p.firstOperationName.isEmpty())
        root.insert(QStringLiteral("first_operation_name"), p.firstOperationName);
    if (!p.furtherOperations.empty()) {
        QJsonArray operations;
        for (const Operation &op : p.furtherOperations)
            operations.append(operationJson(op));
        root.insert(QStringLiteral("further_operations"), operations);
    }
    if (!p.milledFeatures.empty()) {
        QJsonArray milled;
        for (const MilledFeature &f : p.milledFeatures)
            milled.append(milledFeatureJson(f));
        root.insert(QStringLiteral("milled_features"), milled);
    }
    if (p.cuttingModel != CuttingModel{})
        root.insert(QStringLiteral("cutting_model"), cuttingModelJson(p.cuttingModel));
    if (p.characterisation != MachineCharacterisation{})
        root.insert(QStringLiteral("characterisation"), characterisationJson(p.characterisation));
    if (p.planning != PlanningSettings{})
        root.insert(QStringLiteral("planning"), planningJson(p.planning));
    if (p.environment != Environment{}) {
        QJsonObject environment;
        insertOptional(environment, "ambient_temperature_C", p.environment.ambientTemperature_C);
        insertOptional(environment, "time_since_start_min", p.environment.timeSinceStart_min);
        root.insert(QStringLiteral("environment"), environment);
    }
    for (const auto &[path, value] : p.unknownFields)
        root = withUnknownField(root, pathSteps(path), 0, value).toObject();
    return root;
}

} // namespace tolturn
