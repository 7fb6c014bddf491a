// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/deviation/turning_inputs.h"

#include "core/mechanics/beam_corrections.h"
#include "core/mechanics/moving_load.h"
#include "core/mechanics/spindle_chuck.h"
#include "core/part/profile_geometry.h"
#include "core/project/keywords.h"
#include "core/project/operations.h"
#include "core/tooling/iso1832.h"

#include <QCoreApplication>

#include <cmath>
#include <numbers>

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

// The holder's entering angle, or an error naming the holder.
std::optional<SourcedValue> holderEnteringAngle(const Project &p, const DataLibrary &data, Diagnostics &out)
{
    auto angle = enteringAngleOf(p.tool.holderCode, data);
    if (!angle)
        out.push_back(makeError(
            QStringLiteral("tool.holder"),
            DeviationModel::tr("holder \"%1\" is not in the data library and its ISO 5608 style letter (third "
                               "character) gives no known entering angle")
                .arg(p.tool.holderCode)));
    return angle;
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

// A force model's warnings on the cut's feed or depth, named by the pass they are about
// ("passes[4].depth_of_cut_mm"), as check names every field.
void addPassWarnings(const Diagnostics &warnings, int passIndex, Diagnostics &out)
{
    for (Diagnostic d : warnings) {
        if (d.field == QLatin1String("feed_mm_rev") || d.field == QLatin1String("depth_of_cut_mm"))
            d.field = QStringLiteral("passes[%1].%2").arg(passIndex).arg(d.field);
        out.push_back(d);
    }
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
        addPassWarnings(r.warnings, in.passIndex, out);
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
    addPassWarnings(r.warnings, in.passIndex, out);
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
                     "Toolpost: the whole holder length (%1 mm) is taken in compression, an upper bound; enter "
                     "the tool's overhang (the length out of the turret) to replace it.")
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
        // r = sqrt((r0 ± δ_r)² + δ_t²) (docs/model.md §1): δ_t changes the radius by about δ_t²/2r.
        if (!c.spindleTangential)
            in.notes << DeviationModel::tr(
                "Spindle–chuck tangential springs not measured: the chuck is taken as rigid tangentially (the "
                "radial springs are measured). A tangential deflection δ_t changes the machined radius by about "
                "δ_t²/2r only; give tangential_um in the test-bar fit to measure them.");
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

// A collet: no published stiffness of a collet (or of the spindle with one) was found, and the
// spindle–chuck measurement is of the chuck. A value tried by the caller (the stiffness each
// tolerance needs is searched so), else rigid, which the notes and the banner say.
void resolveCollet(const DeviationOptions &options, TurningInputs &in)
{
    in.collet = true;
    if (options.chuckStiffness_N_per_mm) {
        in.chuck.basis = SupportBasis::Given;
        in.chuck.stiffness_N_per_mm = *options.chuckStiffness_N_per_mm;
        in.radialLeft = in.tangentialLeft = chuckFamilySupport(in.chuck.stiffness_N_per_mm);
        return;
    }
    in.chuck.basis = SupportBasis::RigidNoData;
    in.radialLeft = in.tangentialLeft = EndSupport::clamped();
    in.notes << DeviationModel::tr("Collet: no published stiffness of a collet or of the spindle holding one was "
                                   "found, so it is taken as rigid at the collet's face, which is optimistic. The "
                                   "verdicts give the stiffness each tolerance needs of it.");
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

// The corrections of the beam identified from solid FE (docs/solid-fe.md "Corrections"), said
// in the notes either way: they change every deflection by a few per cent.
void resolveBeamCorrections(const DeviationOptions &options, bool chuck, TurningInputs &in)
{
    if (!options.beamCorrections) {
        in.notes << DeviationModel::tr("Workpiece beam without the corrections for the root in the jaws and the "
                                       "shoulders: plain Timoshenko theory, up to about 10 % stiffer than a solid "
                                       "model where a chuck holds the part (docs/solid-fe.md).");
        return;
    }
    in.beamCorrections = true;
    in.notes << (chuck ? DeviationModel::tr("Workpiece beam corrected from solid FE: built in %1 of its diameter "
                                            "inside the jaws, a hinge at each shoulder (docs/solid-fe.md).")
                             .arg(formatNumber(kRootEmbedmentPerDiameter))
                       : DeviationModel::tr("Workpiece beam corrected from solid FE: a hinge at each shoulder "
                                            "(docs/solid-fe.md)."));
}

void resolveSupports(const Project &p, const DataLibrary &data, const DeviationOptions &options, TurningInputs &in)
{
    const MachineCharacterisation &c = p.characterisation;
    const ClampingMethod method = p.clamping.method;
    const bool chuck = method != ClampingMethod::BetweenCentres;
    in.supportStart_mm = chuck ? p.clamping.clampedLength_mm : 0.0;
    in.supportEnd_mm = p.part.length_mm();
    resolveBeamCorrections(options, chuck, in);
    if (options.workpieceOnly) {
        in.radialLeft = in.tangentialLeft = chuck ? EndSupport::clamped() : EndSupport::pinned();
        in.radialRight = in.tangentialRight = holdsOneEndOnly(method) ? EndSupport::free() : EndSupport::pinned();
        in.notes << DeviationModel::tr("Workpiece only: machine supports rigid, no toolpost or thermal term.");
        return;
    }
    const UncharacterisedSupports &ranges = data.uncharacterisedSupports();
    if (method == ClampingMethod::Collet) {
        resolveCollet(options, in);
    } else if (chuck) {
        resolveChuck(p, data, options, in);
    } else {
        // The headstock centre; what the verdicts report is the tailstock's basis (both centres
        // take a value tried by the caller).
        const QString name = DeviationModel::tr("Headstock centre");
        SupportStiffnessUsed tangential;
        in.radialLeft =
            resolveCentre(c.centres, ranges.centreRadial, options, in.headstockCentre, true, name, in.notes);
        in.tangentialLeft = resolveCentre(c.centres, ranges.centreRadial, options, tangential, false, name, in.notes);
    }
    if (holdsOneEndOnly(method)) {
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

// How deep the boring bar must reach: from the right end face, where it enters, to the deepest
// inner surface it cuts (not left of the chuck face).
double boringReach_mm(const Project &p, double supportStart_mm)
{
    const PartProfile &part = p.part;
    const double length = part.length_mm();
    double deepest = length;
    for (const auto &[first, end] : part.inner.pieces()) {
        // Only a bore open at the free end is reached from there (one from the held end is not
        // this set-up's, checkOperations says so).
        if (part.inner.segments[end - 1].to.z_mm < length - kProfileEpsilon_mm)
            continue;
        for (std::size_t i = first; i < end; ++i) {
            const Segment &s = part.inner.segments[i];
            // Another operation's bore is not this bar's.
            if (p.scope ? p.scope->cutFeatures.contains(s.id) : operationOf(p, s.id) == 0)
                deepest = std::min(deepest, std::max(std::min(s.from.z_mm, s.to.z_mm), supportStart_mm));
        }
    }
    return length - deepest;
}

// Diagnostics of the boring tool's view of the project name the project's "boring_tool" fields.
void renameToolFields(Diagnostics &list, qsizetype from)
{
    for (auto i = static_cast<std::size_t>(from); i < list.size(); ++i) {
        if (list[i].field.startsWith(QLatin1String("tool")))
            list[i].field.replace(0, 4, QStringLiteral("boring_tool"));
    }
}

// The bar: its diameter from the holder data, its material from the designation's first letter,
// the overhang as given (else the reach, the least that cuts the deepest bore), the edge's offset
// as given (else the bar's radius, the least the edge can stand off its axis).
std::optional<BoringBar> resolveBar(const Project &p, const DataLibrary &data, const TurningInputs &in,
                                    BoringInputs &bi, Diagnostics &out)
{
    const Tool &t = *p.boringTool;
    const HolderData *h = data.holder(t.holderCode);
    if (h == nullptr || !h->isBoringBar() || !h->barDiameter_mm) {
        out.push_back(
            makeError(QStringLiteral("boring_tool.holder"),
                      DeviationModel::tr("\"%1\" is not a boring bar in the data library").arg(t.holderCode)));
        return std::nullopt;
    }
    const BoringBarMaterialData *m = data.boringBarMaterial(*h);
    if (m == nullptr) {
        out.push_back(
            makeError(QStringLiteral("boring_tool.holder"),
                      DeviationModel::tr("the bar material of \"%1\" (type letter %2) is not in the data library: its "
                                         "stiffness is unknown")
                          .arg(t.holderCode, t.holderCode.left(1))));
        return std::nullopt;
    }
    BoringBar bar;
    bar.diameter_mm = h->barDiameter_mm->value;
    bar.material = {m->youngsModulus_MPa.value, m->poissonRatio.value, true};
    const double reach = boringReach_mm(p, in.supportStart_mm);
    bar.overhang_mm = t.overhang_mm.value_or(reach + kToolClearance_mm);
    if (bar.overhang_mm + kProfileEpsilon_mm < reach) {
        out.push_back(makeError(QStringLiteral("boring_tool.overhang_mm"),
                                DeviationModel::tr("an overhang of %1 mm does not reach the bottom of the bore, %2 mm "
                                                   "in from the right end face")
                                    .arg(num(bar.overhang_mm), num(reach))));
        return std::nullopt;
    }
    if (h->length_mm && bar.overhang_mm > h->length_mm->value) {
        out.push_back(makeError(QStringLiteral("boring_tool.overhang_mm"),
                                DeviationModel::tr("an overhang of %1 mm is longer than the bar \"%2\" itself (%3 mm)")
                                    .arg(num(bar.overhang_mm), t.holderCode, num(h->length_mm->value))));
        return std::nullopt;
    }
    bar.edgeOffset_mm = t.edgeOffset_mm.value_or(0.5 * bar.diameter_mm);
    bi.holderCode = t.holderCode;
    bi.barMaterial = m->id;
    bi.maxOverhangRatio = m->maxOverhangRatio;
    return bar;
}

void noteBar(const Project &p, const DataLibrary &data, const BoringInputs &bi, QStringList &notes)
{
    const BoringBarMaterialData *m = data.boringBarMaterial(*data.holder(bi.holderCode));
    notes << DeviationModel::tr("Boring bar %1: %2, Ø%3 mm, %4 mm overhang (L/D %5), E = %6 GPa (%7).")
                 .arg(bi.holderCode, bi.barMaterial, num(bi.bar.diameter_mm), num(bi.bar.overhang_mm),
                      QString::number(bi.bar.overhangRatio(), 'f', 1), num(bi.bar.material.youngsModulus_MPa / 1000.0),
                      data.sourceText(m->youngsModulus_MPa.source).section(QLatin1Char(','), 0, 0));
    notes << DeviationModel::tr("The boring bar is taken as held rigidly in the turret: no stiffness of a bar clamp "
                                "is known, so the bar's deflection is a lower bound.");
    if (!p.boringTool->overhang_mm)
        notes << DeviationModel::tr("Boring bar overhang not given: taken as the bore's depth and the program's "
                                    "clearance off the end face, %1 mm, the least that reaches; a longer overhang "
                                    "bends more.")
                     .arg(num(bi.bar.overhang_mm));
    if (!p.boringTool->edgeOffset_mm)
        notes << DeviationModel::tr("The cutting edge's offset from the bar axis (the maker's f) not given: taken as "
                                    "the bar's radius, %1 mm, the least it can be; the twist of the bar and the moment "
                                    "of the feed force grow with it.")
                     .arg(num(bi.bar.edgeOffset_mm));
    // ISO designation type letter A: a steel bar with internal coolant supply (holders.json).
    if (bi.holderCode.startsWith(QLatin1Char('A'), Qt::CaseInsensitive))
        notes << DeviationModel::tr("Boring bar %1 has a coolant bore the designation does not size: computed as a "
                                    "solid bar, which underestimates its deflection.")
                     .arg(bi.holderCode);
}

} // namespace

std::optional<LiDuToolGeometry> resolveLiDuToolGeometry(const Project &p, const DataLibrary &data, Diagnostics &out)
{
    const InsertParseResult insert = parseInsertCode(p.tool.insertCode);
    if (!insert.insert) {
        out.insert(out.end(), insert.diagnostics.begin(), insert.diagnostics.end());
        return std::nullopt;
    }
    const auto angle = holderEnteringAngle(p, data, out);
    if (!angle)
        return std::nullopt;
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

TurningInputs withChuckStiffness(TurningInputs in, double k_N_per_mm)
{
    in.chuck.basis = SupportBasis::Given;
    in.chuck.stiffness_N_per_mm = k_N_per_mm;
    in.radialLeft = in.tangentialLeft = chuckFamilySupport(k_N_per_mm);
    return in;
}

TurningInputs withTailstockStiffness(TurningInputs in, double k_N_per_mm, ClampingMethod method)
{
    in.tailstock.basis = SupportBasis::Given;
    in.tailstock.stiffness_N_per_mm = k_N_per_mm;
    in.radialRight = in.tangentialRight = EndSupport::translationSpring(k_N_per_mm);
    if (method == ClampingMethod::BetweenCentres)
        in.radialLeft = in.tangentialLeft = EndSupport::translationSpring(k_N_per_mm);
    return in;
}

QString forceModelName(const QString &keyword)
{
    if (keyword == QLatin1String("kienzle"))
        return QStringLiteral("Kienzle");
    if (keyword == QLatin1String("li_du"))
        return QStringLiteral("Li & Du");
    if (keyword == QLatin1String("given"))
        return DeviationModel::tr("given forces");
    return keyword;
}

namespace {

// The inner contour's tool: its insert, entering angle and forces as the turning tool's are
// resolved, on a view of the project whose tool is the boring tool; then the bar.
std::optional<BoringInputs> resolveBoring(const Project &p, const DataLibrary &data, const DeviationOptions &options,
                                          const MaterialData &material, const TurningInputs &in, Diagnostics &out)
{
    Project view = p;
    view.tool = *p.boringTool;
    const auto first = static_cast<qsizetype>(out.size());
    TurningInputs bin;
    bin.pass = in.pass;
    bin.passIndex = in.passIndex;
    const InsertParseResult insert = parseInsertCode(view.tool.insertCode);
    std::optional<SourcedValue> angle;
    if (!insert.insert)
        out.insert(out.end(), insert.diagnostics.begin(), insert.diagnostics.end());
    else
        angle = holderEnteringAngle(view, data, out);
    if (insert.insert && angle) {
        bin.noseRadius_mm = insert.insert->noseRadius_mm;
        bin.enteringAngle_deg = angle->value;
        resolveForces(view, data, options, material, bin, out);
    }
    renameToolFields(out, first);
    if (hasErrors(out))
        return std::nullopt;
    BoringInputs bi;
    bi.forces = bin.forces;
    bi.noseRadius_mm = bin.noseRadius_mm;
    bi.enteringAngle_deg = bin.enteringAngle_deg;
    const auto bar = resolveBar(p, data, in, bi, out);
    if (!bar)
        return std::nullopt;
    bi.bar = *bar;
    if (!options.workpieceOnly)
        bi.compliance = boringBarCompliance(bi.bar);
    return bi;
}

// The shop's conditions the thermal drift depends on (docs/model.md §5). What the project does not
// give is not taken as the ideal: a machine whose warm-up is not known is taken as warmed through
// (ten time constants: within 5·10⁻⁵ of its steady drift, the largest; a cold start drifts less),
// and an ambient temperature not given as the characterisation's reference (no ambient term).
// Both are said in the notes.
void environmentOfThermalDrift(const Project &p, TurningInputs &in)
{
    constexpr double kWarmTimeConstants = 10.0;
    in.timeSinceStart_min = p.environment.timeSinceStart_min.value_or(0.0);
    in.ambientTemperature_C = p.environment.ambientTemperature_C.value_or(20.0);
    if (!in.thermal)
        return;
    const ThermalDrift &t = *in.thermal;
    if (!p.environment.timeSinceStart_min) {
        in.timeSinceStart_min = kWarmTimeConstants * t.timeConstant_min;
        in.notes << DeviationModel::tr(
                        "Time since the machine started not given (environment): taken as warmed "
                        "through, %1 min (ten time constants), the largest drift of the size (not always of the form).")
                        .arg(num(in.timeSinceStart_min));
    }
    if (!p.environment.ambientTemperature_C) {
        in.ambientTemperature_C = t.referenceTemperature_C;
        if (t.drift_um_per_K != 0.0)
            in.notes << DeviationModel::tr("Ambient temperature not given (environment): taken as the "
                                           "characterisation's reference, %1 °C, so no drift from it.")
                            .arg(num(t.referenceTemperature_C));
    }
}

} // namespace

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
                                    : DeviationModel::tr("there is no pass %1 (the project has %2)")
                                          .arg(in.passIndex + 1)
                                          .arg(p.passes.size())));
        return result;
    }
    in.pass = p.passes[static_cast<std::size_t>(in.passIndex)];

    const InsertParseResult insert = parseInsertCode(p.tool.insertCode);
    if (!insert.insert) {
        out.insert(out.end(), insert.diagnostics.begin(), insert.diagnostics.end());
        return result;
    }
    in.noseRadius_mm = insert.insert->noseRadius_mm;
    const auto angle = holderEnteringAngle(p, data, out);
    if (!angle)
        return result;
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
    if (p.boringTool) {
        in.boring = resolveBoring(p, data, options, *material, in, out);
        if (!in.boring)
            return result;
        noteBar(p, data, *in.boring, in.notes);
    } else if (cutsBores(p)) {
        in.notes << DeviationModel::tr("No boring bar given: the bores are computed as if cut by the turning tool "
                                       "%1, without the bending of a bar, which in a bore is often the largest term.")
                        .arg(p.tool.holderCode);
    }
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
    if (p.scope) {
        in.scoped = true;
        in.cutFeatures = p.scope->cutFeatures;
        in.stockOuter_mm = p.scope->stockOuter_mm;
        in.solidInner_mm = p.scope->solidInner_mm;
        in.notes << DeviationModel::tr("%1, operation %2 of %3: the part held at its %4 end, z from that end.")
                        .arg(p.scope->name)
                        .arg(p.scope->index + 1)
                        .arg(p.scope->count)
                        .arg(displayName(p.clamping.heldEnd));
        if (!in.stockOuter_mm.empty())
            in.notes << DeviationModel::tr("The outer features later operations turn are still the stock, Ø%1 mm.")
                            .arg(num(p.part.stockDiameter_mm));
        if (!in.solidInner_mm.empty())
            in.notes << DeviationModel::tr("The bores later operations cut are still solid material (no pre-drilled "
                                           "hole is assumed).");
    }
    environmentOfThermalDrift(p, in);
    result.inputs = in;
    return result;
}

} // namespace tolturn
