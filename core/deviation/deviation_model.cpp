// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/deviation/deviation_model.h"

#include "core/cutting/cutting_quantities.h"
#include "core/mechanics/spindle_chuck.h"
#include "core/part/profile_geometry.h"
#include "core/project/keywords.h"
#include "core/tooling/iso1832.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

namespace tolturn {

namespace {

struct DeviationModel {
    Q_DECLARE_TR_FUNCTIONS(DeviationModel)
};

QString num(double v)
{
    return formatNumber(v);
}

double radians(double deg)
{
    return deg * std::numbers::pi / 180.0;
}

int choosePass(const Project &p, int requested)
{
    if (requested >= 0)
        return requested;
    for (int i = static_cast<int>(p.passes.size()) - 1; i >= 0; --i) {
        if (p.passes[static_cast<std::size_t>(i)].kind == PassKind::Finishing)
            return i;
    }
    return static_cast<int>(p.passes.size()) - 1;
}

// Entering angle from the holder: the library's holder, else its ISO 5608 style letter.
std::optional<SourcedValue> enteringAngleOf(const QString &holderCode, const DataLibrary &data)
{
    if (const HolderData *h = data.holder(holderCode))
        return h->enteringAngle_deg;
    const QString code = holderCode.trimmed().toUpper();
    if (code.size() >= 3 && code.at(0).isLetter() && code.at(1).isLetter() && code.at(2).isLetter())
        return data.styleEnteringAngle(code.at(2));
    return std::nullopt;
}

KienzleConstants kienzleOf(const MaterialData &m, const CuttingModel &model, const DataLibrary &data,
                           QStringList &notes)
{
    KienzleConstants k;
    k.cutting = {m.kc11_MPa.value, m.mc.value};
    if (m.kf11_MPa && m.mf)
        k.feed = KienzleLaw{m.kf11_MPa->value, m.mf->value};
    if (m.kp11_MPa && m.mp)
        k.passive = KienzleLaw{m.kp11_MPa->value, m.mp->value};
    const bool projectRatios = model.feedToCuttingRatio || model.passiveToCuttingRatio;
    const auto feedRatio = m.feedToCuttingRatio ? m.feedToCuttingRatio : data.defaultFeedToCuttingRatio();
    const auto passiveRatio = m.passiveToCuttingRatio ? m.passiveToCuttingRatio : data.defaultPassiveToCuttingRatio();
    k.feedToCuttingRatio = model.feedToCuttingRatio.value_or(feedRatio ? feedRatio->value : 0.0);
    k.passiveToCuttingRatio = model.passiveToCuttingRatio.value_or(passiveRatio ? passiveRatio->value : 0.0);
    if (projectRatios) {
        k.feed.reset();
        k.passive.reset();
    } else if ((!k.feed && !m.feedToCuttingRatio) || (!k.passive && !m.passiveToCuttingRatio)) {
        notes << DeviationModel::tr(
                     "Feed and passive force from the rule of thumb Ff = %1 Fc, Fp = %2 Fc (%3): the material data "
                     "give no feed or passive force constants. Calibrate the forces for accuracy.")
                     .arg(num(k.feedToCuttingRatio), num(k.passiveToCuttingRatio),
                          feedRatio ? data.sourceText(feedRatio->source).section(QLatin1Char(','), 0, 1)
                                    : DeviationModel::tr("no source: zero"));
    }
    return k;
}

std::optional<double> seatAngle(const std::optional<double> &projectValue, const std::optional<SourcedValue> &holder,
                                const std::optional<SourcedValue> &negativeSeat, bool negativeInsert)
{
    if (projectValue)
        return projectValue;
    if (holder)
        return holder->value;
    if (negativeInsert && negativeSeat)
        return negativeSeat->value;
    return std::nullopt;
}

void resolveForces(const Project &p, const DataLibrary &data, const DeviationOptions &options,
                   const MaterialData &material, TurningInputs &in, Diagnostics &out)
{
    if (options.loadOverride) {
        in.forces = *options.loadOverride;
        in.forceModel = QStringLiteral("given");
        return;
    }
    if (p.cuttingModel.forceModel == ForceModel::Kienzle) {
        const ForceResult r = kienzleForces(kienzleOf(material, p.cuttingModel, data, in.notes), in.pass.feed_mm_rev,
                                            in.pass.depthOfCut_mm, radians(in.enteringAngle_deg), in.noseRadius_mm);
        in.forces = r.forces;
        in.forceModel = QStringLiteral("kienzle");
        out.insert(out.end(), r.warnings.begin(), r.warnings.end());
        return;
    }
    const auto tool = resolveLiDuToolGeometry(p, data, out);
    if (!tool)
        return;
    const LiDuCoefficients c{p.cuttingModel.normalPressure_MPa.value_or(0.0),
                             p.cuttingModel.frictionRatio.value_or(0.0)};
    const ForceResult r = liDuForces(c, *tool, in.pass.feed_mm_rev, in.pass.depthOfCut_mm);
    in.forces = r.forces;
    in.forceModel = QStringLiteral("li_du");
    out.insert(out.end(), r.warnings.begin(), r.warnings.end());
}

double toolpostCompliance(const Project &p, const DataLibrary &data, QStringList &notes)
{
    const HolderData *h = data.holder(p.tool.holderCode);
    const auto modulus = data.shankModulus();
    if (h == nullptr || !modulus) {
        notes << DeviationModel::tr("Toolpost shortening not included: holder \"%1\" is not in the data library.")
                     .arg(p.tool.holderCode);
        return 0.0;
    }
    double area = 0.0;
    if (h->shankHeight_mm && h->shankWidth_mm)
        area = h->shankHeight_mm->value * h->shankWidth_mm->value;
    else if (h->barDiameter_mm)
        area = 0.25 * std::numbers::pi * h->barDiameter_mm->value * h->barDiameter_mm->value;
    double length = p.tool.overhang_mm.value_or(0.0);
    if (!p.tool.overhang_mm && h->length_mm) {
        length = h->length_mm->value;
        notes << DeviationModel::tr(
                     "Toolpost: the whole holder length (%1 mm) is taken in compression, an upper bound; give "
                     "tool.overhang_mm for the length out of the turret.")
                     .arg(num(length));
    }
    ToolpostCompliance tp;
    tp.toolLength_mm = length;
    tp.toolArea_mm2 = area;
    tp.toolModulus_MPa = modulus->value;
    return tp.compliance_mm_per_N();
}

EndSupport chuckSupport(const MachineCharacterisation &c, const std::optional<SpindleSprings> &springs)
{
    if (!springs || !c.pivotDistance_mm)
        return EndSupport::clamped();
    return EndSupport::springs(chuckFaceStiffness(
        {springs->k1_N_per_mm, springs->k2_Nmm_per_rad, springs->k3_Nmm_per_rad, *c.pivotDistance_mm}));
}

// The chuck of the one-parameter family (docs/model.md §2): a translational spring K at the chuck
// face (k1 = K), the face held against tilt.
EndSupport chuckFamilySupport(double k_N_per_mm)
{
    EndSupport s = EndSupport::translationSpring(k_N_per_mm);
    s.fixedRotation = true;
    return s;
}

double rangeEnd(const StiffnessRange &r, StiffnessEnd end)
{
    return end == StiffnessEnd::Compliant ? r.compliant_N_per_mm.value : r.stiff_N_per_mm.value;
}

QString perMicrometre(double k_N_per_mm)
{
    return formatNumber(k_N_per_mm / 1000.0);
}

QString endName(StiffnessEnd end)
{
    return end == StiffnessEnd::Compliant ? DeviationModel::tr("compliant") : DeviationModel::tr("stiff");
}

// The chuck face: a value tried by the caller, the measured springs, the end of the published
// range, or (no data at all) rigid.
void resolveChuck(const Project &p, const DataLibrary &data, const DeviationOptions &options, TurningInputs &in)
{
    const MachineCharacterisation &c = p.characterisation;
    const auto &range = data.uncharacterisedSupports().chuckRadial;
    in.chuck.range = range;
    in.spindleCharacterised = c.spindleRadial.has_value() && c.pivotDistance_mm.has_value();
    if (options.chuckStiffness_N_per_mm) {
        in.chuck.basis = SupportBasis::Given;
        in.chuck.stiffness_N_per_mm = *options.chuckStiffness_N_per_mm;
        in.radialLeft = in.tangentialLeft = chuckFamilySupport(in.chuck.stiffness_N_per_mm);
    } else if (in.spindleCharacterised) {
        in.chuck.basis = SupportBasis::Measured;
        in.radialLeft = chuckSupport(c, c.spindleRadial);
        in.tangentialLeft = chuckSupport(c, c.spindleTangential);
    } else if (range) {
        in.chuck.basis = SupportBasis::RangeEnd;
        in.chuck.stiffness_N_per_mm = rangeEnd(*range, options.stiffnessEnd);
        in.radialLeft = in.tangentialLeft = chuckFamilySupport(in.chuck.stiffness_N_per_mm);
        in.notes << DeviationModel::tr(
                        "Spindle–chuck not measured: a radial spring of %1 N/µm at the chuck face, the %2 end of "
                        "the published range %3–%4 N/µm (%5); no tilt of the chuck. A test-bar fit (Valiño et al. "
                        "2008 §III) replaces it.")
                        .arg(perMicrometre(in.chuck.stiffness_N_per_mm), endName(options.stiffnessEnd),
                             perMicrometre(range->compliant_N_per_mm.value), perMicrometre(range->stiff_N_per_mm.value),
                             data.sourceText(range->compliant_N_per_mm.source).section(QLatin1Char(','), 0, 1));
    } else {
        in.chuck.basis = SupportBasis::RigidNoData;
        in.radialLeft = in.tangentialLeft = EndSupport::clamped();
        in.notes << DeviationModel::tr(
            "Spindle–chuck neither measured nor in the data: taken as rigid, which is optimistic. Measure k1, k2, k3 "
            "(Valiño et al. 2008 §III).");
    }
}

// A centre or the tailstock: a value tried by the caller, the measured stiffness, the end of a
// published range, or (none found, docs/model.md §2) a rigid pin, which the notes say.
EndSupport resolveCentre(const std::optional<SupportStiffness> &measured, const std::optional<StiffnessRange> &range,
                         const DeviationOptions &options, SupportStiffnessUsed &used, bool radial, const QString &name,
                         QStringList &notes)
{
    used.range = range;
    if (options.tailstockStiffness_N_per_mm) {
        used.basis = SupportBasis::Given;
        used.stiffness_N_per_mm = *options.tailstockStiffness_N_per_mm;
        return EndSupport::translationSpring(used.stiffness_N_per_mm);
    }
    if (measured) {
        used.basis = SupportBasis::Measured;
        return EndSupport::translationSpring(radial ? measured->radial_N_per_mm : measured->tangential_N_per_mm);
    }
    if (range) {
        used.basis = SupportBasis::RangeEnd;
        used.stiffness_N_per_mm = rangeEnd(*range, options.stiffnessEnd);
        return EndSupport::translationSpring(used.stiffness_N_per_mm);
    }
    used.basis = SupportBasis::RigidNoData;
    if (radial)
        notes << DeviationModel::tr(
                     "%1 not measured and no published stiffness found: taken as a rigid pin, which is optimistic. "
                     "The verdicts give the stiffness each tolerance needs of it.")
                     .arg(name);
    return EndSupport::pinned();
}

void resolveSupports(const Project &p, const DataLibrary &data, const DeviationOptions &options, TurningInputs &in)
{
    const MachineCharacterisation &c = p.characterisation;
    const ClampingMethod method = p.clamping.method;
    const bool chuck = method != ClampingMethod::BetweenCentres;
    in.supportStart_mm = chuck ? p.clamping.clampedLength_mm : 0.0;
    in.supportEnd_mm = p.part.length_mm();
    if (options.workpieceOnly) {
        in.radialLeft = in.tangentialLeft = chuck ? EndSupport::clamped() : EndSupport::pinned();
        in.radialRight = in.tangentialRight =
            method == ClampingMethod::Chuck ? EndSupport::free() : EndSupport::pinned();
        in.notes << DeviationModel::tr("Workpiece only: machine supports rigid, no toolpost or thermal term.");
        return;
    }
    const UncharacterisedSupports &ranges = data.uncharacterisedSupports();
    if (chuck) {
        resolveChuck(p, data, options, in);
    } else {
        // The headstock centre; what the verdicts report is the tailstock's basis (both centres
        // take a value tried by the caller).
        const QString name = DeviationModel::tr("Headstock centre");
        SupportStiffnessUsed used;
        in.radialLeft = resolveCentre(c.centres, ranges.centreRadial, options, used, true, name, in.notes);
        in.tangentialLeft = resolveCentre(c.centres, ranges.centreRadial, options, used, false, name, in.notes);
    }
    if (method == ClampingMethod::Chuck) {
        in.radialRight = in.tangentialRight = EndSupport::free();
    } else {
        const QString name = DeviationModel::tr("Tailstock");
        SupportStiffnessUsed tangential;
        in.radialRight =
            resolveCentre(c.tailstock, ranges.tailstockRadial, options, in.tailstock, true, name, in.notes);
        in.tangentialRight =
            resolveCentre(c.tailstock, ranges.tailstockRadial, options, tangential, false, name, in.notes);
    }
}

std::optional<double> machineLimit(const MachineData *m, const char *key)
{
    if (m == nullptr)
        return std::nullopt;
    const auto it = m->limits.find(QLatin1String(key));
    if (it == m->limits.end())
        return std::nullopt;
    return it->second.value;
}

// The ids of a data library's entries, for the message naming an unknown one.
template <typename Entries>
QString libraryIds(const Entries &entries)
{
    QStringList ids;
    for (const auto &entry : entries)
        ids << entry.id;
    return ids.join(QStringLiteral(", "));
}

bool resolveMaterial(const Project &p, const DataLibrary &data, TurningInputs &in, Diagnostics &out,
                     const MaterialData *&material)
{
    material = data.material(p.materialId);
    if (material == nullptr) {
        out.push_back(makeError(QStringLiteral("material"),
                                DeviationModel::tr("unknown material \"%1\"; the data library has: %2")
                                    .arg(p.materialId, libraryIds(data.materials()))));
        return false;
    }
    if (!material->poissonRatio) {
        out.push_back(makeError(
            QStringLiteral("material"),
            DeviationModel::tr("material \"%1\" has no Poisson's ratio in the data, which the shear deflection "
                               "needs")
                .arg(material->id)));
        return false;
    }
    in.material = {material->youngsModulus_MPa.value, material->poissonRatio->value, true};
    in.materialName = material->name;
    return true;
}

} // namespace

std::optional<LiDuToolGeometry> resolveLiDuToolGeometry(const Project &p, const DataLibrary &data, Diagnostics &out)
{
    const InsertParseResult insert = parseInsertCode(p.tool.insertCode);
    if (!insert.insert) {
        out.insert(out.end(), insert.diagnostics.begin(), insert.diagnostics.end());
        return std::nullopt;
    }
    const auto angle = enteringAngleOf(p.tool.holderCode, data);
    if (!angle) {
        out.push_back(makeError(
            QStringLiteral("tool.holder"),
            DeviationModel::tr("holder \"%1\" is not in the data library and its ISO 5608 style letter (third "
                               "character) gives no known entering angle")
                .arg(p.tool.holderCode)));
        return std::nullopt;
    }
    const HolderData *holder = data.holder(p.tool.holderCode);
    const bool negative = insert.insert->clearanceAngle_deg == 0.0;
    const auto rake =
        seatAngle(p.tool.rake_deg, holder ? holder->rake_deg : std::nullopt, data.negativeSeatRake(), negative);
    const auto inclination = seatAngle(p.tool.inclination_deg, holder ? holder->inclination_deg : std::nullopt,
                                       data.negativeSeatInclination(), negative);
    if (!rake || !inclination) {
        out.push_back(makeError(
            QStringLiteral("tool.rake_deg"),
            DeviationModel::tr("the Li & Du model needs the rake and inclination angles of the tool; the data "
                               "give none for holder \"%1\" with insert \"%2\": set tool.rake_deg and "
                               "tool.inclination_deg")
                .arg(p.tool.holderCode, p.tool.insertCode)));
        return std::nullopt;
    }
    LiDuToolGeometry tool;
    tool.normalRake_rad = radians(*rake);
    tool.backRake_rad = radians(*inclination); // back rake taken as the ISO inclination angle
    tool.leadAngle_rad = radians(90.0 - angle->value);
    tool.noseRadius_mm = insert.insert->noseRadius_mm;
    return tool;
}

std::optional<ForceFunction> projectForceModel(const Project &p, const DataLibrary &data, Diagnostics &out)
{
    const MaterialData *material = data.material(p.materialId);
    const auto angle = enteringAngleOf(p.tool.holderCode, data);
    if (material == nullptr || !angle) {
        out.push_back(makeError(material == nullptr ? QStringLiteral("material") : QStringLiteral("tool.holder"),
                                DeviationModel::tr("the force model needs a known material and holder")));
        return std::nullopt;
    }
    if (p.cuttingModel.forceModel == ForceModel::Kienzle) {
        QStringList notes;
        const KienzleConstants k = kienzleOf(*material, p.cuttingModel, data, notes);
        const double kappa = radians(angle->value);
        const InsertParseResult insert = parseInsertCode(p.tool.insertCode);
        const double noseRadius = insert.insert ? insert.insert->noseRadius_mm : 0.0;
        return ForceFunction([k, kappa, noseRadius](double feed, double depth) {
            return kienzleForces(k, feed, depth, kappa, noseRadius).forces;
        });
    }
    const auto tool = resolveLiDuToolGeometry(p, data, out);
    if (!tool)
        return std::nullopt;
    const LiDuCoefficients c{p.cuttingModel.normalPressure_MPa.value_or(0.0),
                             p.cuttingModel.frictionRatio.value_or(0.0)};
    const LiDuToolGeometry g = *tool;
    return ForceFunction([c, g](double feed, double depth) { return liDuForces(c, g, feed, depth).forces; });
}

InputsResult resolveTurningInputs(const Project &p, const DataLibrary &data, const DeviationOptions &options)
{
    InputsResult result;
    Diagnostics &out = result.diagnostics;
    TurningInputs in;
    const MaterialData *material = nullptr;
    if (!resolveMaterial(p, data, in, out, material))
        return result;

    in.passIndex = choosePass(p, options.passIndex);
    if (in.passIndex < 0 || in.passIndex >= static_cast<int>(p.passes.size())) {
        out.push_back(makeError(QStringLiteral("passes"),
                                p.passes.empty()
                                    ? DeviationModel::tr("there is no cutting pass; the deviation is that of the pass "
                                                         "that finishes the features")
                                    : DeviationModel::tr("there is no pass %1").arg(in.passIndex)));
        return result;
    }
    in.pass = p.passes[static_cast<std::size_t>(in.passIndex)];

    const InsertParseResult insert = parseInsertCode(p.tool.insertCode);
    if (!insert.insert) {
        out.insert(out.end(), insert.diagnostics.begin(), insert.diagnostics.end());
        return result;
    }
    in.noseRadius_mm = insert.insert->noseRadius_mm;
    const auto angle = enteringAngleOf(p.tool.holderCode, data);
    if (!angle) {
        out.push_back(makeError(
            QStringLiteral("tool.holder"),
            DeviationModel::tr("holder \"%1\" is not in the data library and its ISO 5608 style letter (third "
                               "character) gives no known entering angle")
                .arg(p.tool.holderCode)));
        return result;
    }
    in.enteringAngle_deg = angle->value;

    const MachineData *machine = data.machine(p.machineId);
    if (machine == nullptr) {
        out.push_back(
            makeError(QStringLiteral("machine"), DeviationModel::tr("unknown machine \"%1\"; the data library has: %2")
                                                     .arg(p.machineId, libraryIds(data.machines()))));
        return result;
    }
    in.maxSpindleSpeed_rpm = machineLimit(machine, "max_speed_rpm");
    in.maxPower_kW = machineLimit(machine, "power_kW");

    resolveForces(p, data, options, *material, in, out);
    if (hasErrors(out))
        return result;
    resolveSupports(p, data, options, in);
    if (!supportsHoldBeam(in.radialLeft, in.radialRight, in.supportEnd_mm - in.supportStart_mm) ||
        !supportsHoldBeam(in.tangentialLeft, in.tangentialRight, in.supportEnd_mm - in.supportStart_mm)) {
        out.push_back(makeError(QStringLiteral("clamping"),
                                DeviationModel::tr("the %1 clamping with these supports leaves the part free to move")
                                    .arg(displayName(p.clamping.method))));
        return result;
    }
    if (!options.workpieceOnly) {
        in.toolpostCompliance_mm_per_N = toolpostCompliance(p, data, in.notes);
        in.thermal = p.characterisation.thermal;
        if (!in.thermal)
            in.notes << DeviationModel::tr("Thermal drift not characterised for this machine: taken as zero.");
    }
    in.timeSinceStart_min = p.environment.timeSinceStart_min.value_or(0.0);
    in.ambientTemperature_C = p.environment.ambientTemperature_C.value_or(20.0);
    result.inputs = in;
    return result;
}

namespace {

struct NodeIndex {
    std::vector<double> nodes;

    std::size_t at(double z) const
    {
        const auto it = std::lower_bound(nodes.begin(), nodes.end(), z - 1e-9);
        return static_cast<std::size_t>(std::distance(nodes.begin(), it));
    }
};

// Stations of a feature inside the supported length, evenly spaced, ends included.
std::vector<double> featureStations(const Segment &s, double zMin, double zMax, int count)
{
    const double a = std::max(s.from.z_mm, zMin);
    const double b = std::min(s.to.z_mm, zMax);
    std::vector<double> z;
    if (b - a <= kProfileEpsilon_mm)
        return z;
    const int n = std::max(count, 2);
    for (int i = 0; i < n; ++i)
        z.push_back(a + (b - a) * i / (n - 1));
    return z;
}

struct Sweeps {
    std::vector<NodeInfluence> radial;
    std::vector<NodeInfluence> tangential;
};

Sweeps sweep(const NodeIndex &index, const std::vector<BeamElementStiffness> &uncut,
             const std::vector<BeamElementStiffness> &finished, const TurningInputs &in)
{
    MovingLoadBeam beam;
    beam.nodes_mm = index.nodes;
    beam.uncut = uncut;
    beam.finished = finished;
    beam.left = in.radialLeft;
    beam.right = in.radialRight;
    Sweeps s;
    s.radial = movingLoadInfluence(beam);
    beam.left = in.tangentialLeft;
    beam.right = in.tangentialRight;
    s.tangential = movingLoadInfluence(beam);
    return s;
}

// Rigid-body motion of the supports carried to the load at z, per unit load in `column`: the
// chuck face's displacement and rotation, or the chord between the two centres.
double supportMotion(const NodeInfluence &n, int column, double z, const TurningInputs &in, bool chuck)
{
    const double x0 = in.supportStart_mm;
    if (chuck)
        return n.leftSupport(0, column) + n.leftSupport(1, column) * (z - x0);
    const double span = in.supportEnd_mm - x0;
    return n.leftSupport(0, column) * (in.supportEnd_mm - z) / span + n.rightSupport(0, column) * (z - x0) / span;
}

StationInfluence stationInfluence(const Sweeps &s, std::size_t node, double z, double contactRadius, bool outer,
                                  const TurningInputs &in, bool chuck)
{
    // The feed force (towards the chuck) acts at the contact radius on the tool's side; its moment
    // moves the section towards the tool for an outer surface and away from it for a bore
    // (docs/model.md §4).
    const double momentPerAxial = outer ? -contactRadius : contactRadius;
    const NodeInfluence &r = s.radial[node];
    const NodeInfluence &t = s.tangential[node];
    StationInfluence si;
    si.radialPerRadial_mm_per_N = r.atLoad(0, 0);
    si.radialPerAxial_mm_per_N = r.atLoad(0, 1) * momentPerAxial;
    si.tangentialPerTangential_mm_per_N = t.atLoad(0, 0);
    si.spindlePerRadial_mm_per_N = supportMotion(r, 0, z, in, chuck);
    si.spindlePerAxial_mm_per_N = supportMotion(r, 1, z, in, chuck) * momentPerAxial;
    si.spindleTangential_mm_per_N = supportMotion(t, 0, z, in, chuck);
    si.rotationPerRadial_rad_per_N = r.atLoad(1, 0);
    si.rotationPerAxial_rad_per_N = r.atLoad(1, 1) * momentPerAxial;
    si.rotationPerMoment_rad_per_Nmm = r.atLoad(1, 1);
    return si;
}

} // namespace

InfluenceTable buildInfluenceTable(const PartProfile &part, const TurningInputs &in, int stationsPerFeature,
                                   double allowance_mm)
{
    InfluenceTable table;
    table.toolpostCompliance_mm_per_N = in.toolpostCompliance_mm_per_N;
    const double x0 = in.supportStart_mm;
    const double x1 = in.supportEnd_mm;

    // Nodes: supports, profile vertices and every station.
    std::set<double> nodeSet{x0, x1};
    const SectionAlongZ finished(part);
    for (const double z : finished.breakpoints()) {
        if (z > x0 && z < x1)
            nodeSet.insert(z);
    }
    for (const ContourSide side : {ContourSide::Outer, ContourSide::Inner}) {
        const Contour &contour = side == ContourSide::Outer ? part.outer : part.inner;
        for (const Segment &s : contour.segments) {
            FeatureInfluence f{s.id, side, s.kind, {}, {}, {}};
            if (s.isAxial()) {
                f.z_mm = featureStations(s, x0, x1, stationsPerFeature);
                for (const double z : f.z_mm)
                    f.nominalRadius_mm.push_back(radiusOnSegment(s, z));
                if (!f.z_mm.empty())
                    table.features.push_back(f);
            } else if (s.from.z_mm >= x0 - kProfileEpsilon_mm && s.from.z_mm <= x1 + kProfileEpsilon_mm) {
                f.z_mm = {s.from.z_mm};
                f.nominalRadius_mm = {std::max(s.from.r_mm, s.to.r_mm)};
                table.faces.push_back(f);
            }
            for (const double z : f.z_mm)
                nodeSet.insert(z);
        }
    }
    // Merge nodes closer than a micrometre (a station on a vertex).
    NodeIndex index;
    for (const double z : nodeSet) {
        if (index.nodes.empty() || z - index.nodes.back() > 1e-6)
            index.nodes.push_back(z);
    }

    const std::vector<BeamElementStiffness> finishedElements = buildElements(finished, in.material, index.nodes);
    const bool chuck = in.radialLeft.fixedRotation || in.radialLeft.stiffness(1, 1) > 0.0;
    auto sweepsFor = [&](ContourSide side) {
        if (allowance_mm <= 0.0)
            return sweep(index, finishedElements, finishedElements, in);
        const SectionAlongZ uncut(part, side == ContourSide::Outer ? allowance_mm : 0.0,
                                  side == ContourSide::Inner ? allowance_mm : 0.0);
        return sweep(index, buildElements(uncut, in.material, index.nodes), finishedElements, in);
    };
    const Sweeps outer = sweepsFor(ContourSide::Outer);
    const Sweeps inner = part.inner.empty() ? outer : sweepsFor(ContourSide::Inner);

    for (std::vector<FeatureInfluence> *list : {&table.features, &table.faces}) {
        for (FeatureInfluence &f : *list) {
            const bool isOuter = f.side == ContourSide::Outer;
            const Sweeps &s = isOuter ? outer : inner;
            for (std::size_t i = 0; i < f.z_mm.size(); ++i)
                f.stations.push_back(
                    stationInfluence(s, index.at(f.z_mm[i]), f.z_mm[i], f.nominalRadius_mm[i], isOuter, in, chuck));
        }
    }
    return table;
}

namespace {

// Steady radial drift at a spindle speed (docs/model.md §5): a_n n/1000 + a_T (T - T_ref) [mm].
double steadyDrift_mm(const ThermalDrift &t, const TurningInputs &in, double spindleSpeed_rpm)
{
    return 1e-3 * (t.drift_um_per_1000rpm * spindleSpeed_rpm / 1000.0 +
                   t.drift_um_per_K * (in.ambientTemperature_C - t.referenceTemperature_C));
}

double spindleSpeedAt(const TurningInputs &in, double radius_mm)
{
    double n = spindleSpeed_rpm(in.pass.cuttingSpeed_m_min, 2.0 * radius_mm);
    if (in.maxSpindleSpeed_rpm)
        n = std::min(n, *in.maxSpindleSpeed_rpm);
    return n;
}

// The thermal drift at every station of one contour's features, along the pass (docs/model.md §5):
// the first-order warm-up d(delta)/dt = (delta_ss(n) - delta)/tau integrated as the tool travels
// from the right end towards the chuck, dt = dz / (f n(z)) at constant cutting speed, each step
// with the mean steady drift of its two ends. At the start of the pass the machine has warmed
// for the time since start at the first station's speed: delta_0 = delta_ss (1 - exp(-t0/tau)).
// Returns the drift per feature and station (0 where nothing is characterised).
std::vector<std::vector<double>> thermalAlongPass(const InfluenceTable &table, const TurningInputs &in,
                                                  ContourSide side)
{
    std::vector<std::vector<double>> drift(table.features.size());
    for (std::size_t i = 0; i < table.features.size(); ++i)
        drift[i].assign(table.features[i].z_mm.size(), 0.0);
    if (!in.thermal)
        return drift;
    const ThermalDrift &t = *in.thermal;

    struct Point {
        std::size_t feature, station;
        double z, n;
    };

    std::vector<Point> points;
    for (std::size_t i = 0; i < table.features.size(); ++i) {
        const FeatureInfluence &f = table.features[i];
        if (f.side != side)
            continue;
        for (std::size_t j = 0; j < f.z_mm.size(); ++j)
            points.push_back({i, j, f.z_mm[j], spindleSpeedAt(in, f.nominalRadius_mm[j])});
    }
    std::stable_sort(points.begin(), points.end(), [](const Point &a, const Point &b) { return a.z > b.z; });
    double delta = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const Point &p = points[k];
        if (k == 0) {
            const double warm =
                t.timeConstant_min > 0.0 ? 1.0 - std::exp(-in.timeSinceStart_min / t.timeConstant_min) : 1.0;
            delta = steadyDrift_mm(t, in, p.n) * warm;
        } else {
            const Point &q = points[k - 1];
            const double dt_min = (q.z - p.z) / in.pass.feed_mm_rev * 0.5 * (1.0 / q.n + 1.0 / p.n);
            const double steady = 0.5 * (steadyDrift_mm(t, in, q.n) + steadyDrift_mm(t, in, p.n));
            const double decay = t.timeConstant_min > 0.0 ? std::exp(-dt_min / t.timeConstant_min) : 0.0;
            delta = steady + (delta - steady) * decay;
        }
        drift[p.feature][p.station] = delta;
    }
    return drift;
}

Station evaluateStation(const StationInfluence &si, double z, double r0, bool outer, const TurningInputs &in,
                        double toolpost, double drift)
{
    const CuttingForces &f = in.forces;
    Station st;
    st.z_mm = z;
    st.nominalRadius_mm = r0;
    st.spindleSpeed_rpm = spindleSpeedAt(in, r0);
    st.radial.spindleChuck_mm = f.radial_N * si.spindlePerRadial_mm_per_N + f.axial_N * si.spindlePerAxial_mm_per_N;
    st.radial.workpiece_mm =
        f.radial_N * si.radialPerRadial_mm_per_N + f.axial_N * si.radialPerAxial_mm_per_N - st.radial.spindleChuck_mm;
    st.radial.toolpost_mm = f.radial_N * toolpost;
    // A drift of the tool away from the axis enlarges shafts and bores alike.
    st.radial.thermal_mm = outer ? drift : -drift;
    st.tangential.spindleChuck_mm = f.tangential_N * si.spindleTangential_mm_per_N;
    st.tangential.workpiece_mm = f.tangential_N * si.tangentialPerTangential_mm_per_N - st.tangential.spindleChuck_mm;
    // Exact combination (MODEL §1): the tool tip sits at (r0 + d_r, d_t) from the deflected axis.
    const double dr = st.radial.total_mm();
    const double dt = st.tangential.total_mm();
    const double rr = outer ? r0 + dr : r0 - dr;
    st.radiusError_mm = std::sqrt(rr * rr + dt * dt) - r0;
    st.sectionRotation_rad = f.radial_N * si.rotationPerRadial_rad_per_N + f.axial_N * si.rotationPerAxial_rad_per_N;
    return st;
}

// A face cut by a facing pass (docs/model.md §4): the tool feeds radially, so the feed force Ff
// loads the section radially and the passive force Fp axially, with a moment arm that is the
// contact radius rho as the tool crosses the face. The section at the face turns by
//   theta(rho) = Ff c_theta,F + Fp (-/+ rho) c_theta,M
// and the face point cut at rho is left u(rho) = rho theta(rho) out of its plane; the axial
// run-out e is the range of u over the face (Valiño et al. 2008 eq. 12, e = (D_M - D_m)/2
// tan(theta), when theta does not change across it). tan(theta) reported is the mean tilt.
FaceConicity faceUnderFacingCut(const Segment &s, const FeatureInfluence &f, const TurningInputs &in)
{
    const StationInfluence &si = f.stations.front();
    const double sign = f.side == ContourSide::Outer ? -1.0 : 1.0; // as for the feed force in turning
    const double rIn = std::min(s.from.r_mm, s.to.r_mm);
    const double rOut = std::max(s.from.r_mm, s.to.r_mm);
    const auto u = [&](double rho) {
        return rho * (in.forces.axial_N * si.rotationPerRadial_rad_per_N +
                      in.forces.radial_N * sign * rho * si.rotationPerMoment_rad_per_Nmm);
    };
    constexpr int kSamples = 41;
    double lo = u(rIn);
    double hi = lo;
    for (int i = 1; i < kSamples; ++i) {
        const double v = u(rIn + (rOut - rIn) * i / (kSamples - 1));
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    // The extreme of the parabola u(rho) where it lies inside the face.
    const double a = in.forces.axial_N * si.rotationPerRadial_rad_per_N;
    const double b = in.forces.radial_N * sign * si.rotationPerMoment_rad_per_Nmm;
    if (b != 0.0) {
        const double vertex = -a / (2.0 * b);
        if (vertex > rIn && vertex < rOut) {
            lo = std::min(lo, u(vertex));
            hi = std::max(hi, u(vertex));
        }
    }
    FaceConicity fc;
    fc.featureId = f.featureId;
    fc.side = f.side;
    fc.z_mm = f.z_mm.front();
    fc.tanTheta = rOut > rIn ? (u(rOut) - u(rIn)) / (rOut - rIn) : 0.0;
    fc.axialRunout_mm = hi - lo;
    return fc;
}

} // namespace

DeviationResult evaluateInfluenceTable(const PartProfile &part, const InfluenceTable &table, const TurningInputs &in)
{
    DeviationResult result;
    result.features.reserve(table.features.size());
    const std::vector<std::vector<double>> outerDrift = thermalAlongPass(table, in, ContourSide::Outer);
    const std::vector<std::vector<double>> innerDrift = thermalAlongPass(table, in, ContourSide::Inner);
    for (std::size_t k = 0; k < table.features.size(); ++k) {
        const FeatureInfluence &f = table.features[k];
        FeatureDeviation fd{f.featureId, f.side, f.kind, {}};
        fd.stations.reserve(f.stations.size());
        const bool outer = f.side == ContourSide::Outer;
        const std::vector<double> &drift = (outer ? outerDrift : innerDrift)[k];
        for (std::size_t i = 0; i < f.stations.size(); ++i) {
            const Station st = evaluateStation(f.stations[i], f.z_mm[i], f.nominalRadius_mm[i], outer, in,
                                               table.toolpostCompliance_mm_per_N, drift[i]);
            const double diameter = 2.0 * st.nominalRadius_mm;
            const double speed = std::numbers::pi * diameter * st.spindleSpeed_rpm / 1000.0;
            result.maxPower_kW = std::max(result.maxPower_kW, cuttingPower_kW(in.forces.tangential_N, speed));
            result.maxTorque_Nm = std::max(result.maxTorque_Nm, spindleTorque_Nm(in.forces.tangential_N, diameter));
            fd.stations.push_back(st);
        }
        result.features.push_back(std::move(fd));
    }
    for (const FeatureInfluence &f : table.faces)
        result.faces.push_back(faceUnderFacingCut(*findFeature(part, f.featureId)->segment, f, in));
    result.theoreticalRa_um = theoreticalRa_um(in.pass.feed_mm_rev, in.noseRadius_mm);
    result.theoreticalRz_um = theoreticalRz_um(in.pass.feed_mm_rev, in.noseRadius_mm);
    result.inputs = in;
    return result;
}

DeviationResult computeDeviation(const Project &project, const DataLibrary &data, const DeviationOptions &options)
{
    InputsResult resolved = resolveTurningInputs(project, data, options);
    if (!resolved.inputs) {
        DeviationResult failed;
        failed.diagnostics = resolved.diagnostics;
        return failed;
    }
    const TurningInputs &in = *resolved.inputs;
    const double allowance = options.inProcessSection ? in.pass.depthOfCut_mm : 0.0;
    const InfluenceTable table = buildInfluenceTable(project.part, in, options.stationsPerFeature, allowance);
    DeviationResult result = evaluateInfluenceTable(project.part, table, in);
    result.diagnostics = resolved.diagnostics;
    if (in.maxPower_kW && result.maxPower_kW > *in.maxPower_kW)
        result.diagnostics.push_back(
            makeWarning(QStringLiteral("passes"),
                        DeviationModel::tr("the pass needs %1 kW of cutting power, more than the machine's "
                                           "%2 kW")
                            .arg(num(result.maxPower_kW), num(*in.maxPower_kW))));
    return result;
}

std::vector<double> sweepFormErrors(const InfluenceTable &table, const std::vector<ConditionForces> &conditions)
{
    // Per station the radial deviation is Fr (c_r + c_tp) + Fa c_a; the spread over a feature is
    // evaluated for every condition from the two coefficient columns.
    std::vector<double> out;
    out.reserve(conditions.size() * table.features.size());
    for (const ConditionForces &c : conditions) {
        for (const FeatureInfluence &f : table.features) {
            double lo = 1e300;
            double hi = -1e300;
            for (const StationInfluence &si : f.stations) {
                const double w = c.radial_N * (si.radialPerRadial_mm_per_N + table.toolpostCompliance_mm_per_N) +
                                 c.axial_N * si.radialPerAxial_mm_per_N;
                lo = std::min(lo, w);
                hi = std::max(hi, w);
            }
            out.push_back(hi - lo);
        }
    }
    return out;
}

} // namespace tolturn
