// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/plausibility.h"

#include "core/cutting/cutting_quantities.h"
#include "core/deviation/deviation_model.h"
#include "core/part/undercuts.h"
#include "core/project/keywords.h"
#include "core/project/operations.h"
#include "core/tooling/iso1832.h"

#include <QCoreApplication>

#include <algorithm>

namespace tolturn {

namespace {

struct Plausibility {
    Q_DECLARE_TR_FUNCTIONS(Plausibility)
};

QString num(double v)
{
    return formatNumber(v);
}

void checkLibraryEntries(const Project &p, const DataLibrary &data, Diagnostics &out)
{
    if (data.material(p.materialId) == nullptr)
        out.push_back(
            makeError(QStringLiteral("material"), Plausibility::tr("unknown material \"%1\"; the data library has: %2")
                                                      .arg(p.materialId, libraryIds(data.materials()))));
    if (data.machine(p.machineId) == nullptr)
        out.push_back(
            makeError(QStringLiteral("machine"), Plausibility::tr("unknown machine \"%1\"; the data library has: %2")
                                                     .arg(p.machineId, libraryIds(data.machines()))));
    // The insert's code is read as ISO 1832: one that does not decode names what is wrong with it.
    const InsertParseResult insert = parseInsertCode(p.tool.insertCode);
    if (!insert.insert) {
        for (const Diagnostic &d : insert.diagnostics)
            out.push_back(makeError(QStringLiteral("tool.insert"), d.message));
    }
    if (data.holder(p.tool.holderCode) != nullptr)
        return;
    const QString code = p.tool.holderCode.trimmed().toUpper();
    const bool styleKnown = code.size() >= 3 && data.styleEnteringAngle(code.at(2)).has_value();
    if (!styleKnown)
        out.push_back(makeError(QStringLiteral("tool.holder"),
                                Plausibility::tr("holder \"%1\" is not in the data library and its ISO 5608 style "
                                                 "letter (third character) gives no known entering angle")
                                    .arg(p.tool.holderCode)));
    else
        out.push_back(makeWarning(QStringLiteral("tool.holder"),
                                  Plausibility::tr("holder \"%1\" is not in the data library: its entering angle comes "
                                                   "from its ISO 5608 style letter, and its shank is not in the "
                                                   "toolpost term")
                                      .arg(p.tool.holderCode)));
}

// What no bore this set-up cuts allows: a pilot hole at least as wide as the narrowest of them leaves
// nothing to bore there, and an edge as far off the bar's axis as the widest is across cannot cut
// inside it (the bar's axis lies inside the bore, so the edge is less than a diameter from the wall
// opposite).
void checkBoringGeometry(const Project &p, const Tool &t, Diagnostics &out)
{
    double narrowest = 1e300;
    double widest = 0.0;
    QString narrowestId;
    for (const Segment &s : p.part.inner.segments) {
        if (s.kind != SegmentKind::Cylinder || (p.scope && !p.scope->cutFeatures.contains(s.id)))
            continue;
        widest = std::max(widest, 2.0 * s.from.r_mm);
        if (2.0 * s.from.r_mm < narrowest) {
            narrowest = 2.0 * s.from.r_mm;
            narrowestId = s.id;
        }
    }
    if (widest <= 0.0)
        return;
    if (t.pilotHoleDiameter_mm && *t.pilotHoleDiameter_mm >= narrowest)
        out.push_back(makeError(QStringLiteral("boring_tool.pilot_hole_diameter_mm"),
                                Plausibility::tr("a pilot hole of Ø%1 mm leaves nothing to bore in %2, Ø%3 mm")
                                    .arg(num(*t.pilotHoleDiameter_mm), narrowestId, num(narrowest))));
    if (t.edgeOffset_mm && *t.edgeOffset_mm >= widest)
        out.push_back(makeError(QStringLiteral("boring_tool.edge_offset_mm"),
                                Plausibility::tr("an edge %1 mm off the bar's axis cannot cut inside a bore: the "
                                                 "widest is Ø%2 mm")
                                    .arg(num(*t.edgeOffset_mm), num(widest))));
}

// A bar too short for its bores: its edge reaches z = length + clearance - overhang from the free
// end (boring_toolpath.cpp), so the program leaves the bore beyond unbored. The bores are those the
// resolver lets the bar reach (turning_inputs.cpp boringReach_mm): open at the free end, of this
// set-up. One too short for their depth out of the jaws the resolver refuses, which says so. What
// lies unbored out of the jaws the verdicts judge as if bored; inside them no verdict judges it.
void checkBoringReach(const Project &p, const Tool &t, Diagnostics &out)
{
    const double length = p.part.length_mm();
    const double jaws = p.clamping.method == ClampingMethod::BetweenCentres ? 0.0 : p.clamping.clampedLength_mm;
    if (!t.overhang_mm)
        return;
    const double reach = length + kToolClearance_mm - *t.overhang_mm;
    QStringList bores;
    double deepest = reach;
    double deepestOutOfTheJaws = length; // as the resolver takes it
    for (const auto &[first, end] : p.part.inner.pieces()) {
        if (p.part.inner.segments[end - 1].to.z_mm < length - kProfileEpsilon_mm)
            continue; // open at the held end: another set-up's
        for (std::size_t i = first; i < end; ++i) {
            const Segment &s = p.part.inner.segments[i];
            const bool ours = p.scope ? p.scope->cutFeatures.contains(s.id) : operationOf(p, s.id) == 0;
            const double left = std::min(s.from.z_mm, s.to.z_mm);
            if (!ours)
                continue;
            deepestOutOfTheJaws = std::min(deepestOutOfTheJaws, std::max(left, jaws));
            if (left >= reach - 1e-6)
                continue;
            bores << s.id;
            deepest = std::min(deepest, left);
        }
    }
    if (bores.isEmpty() || *t.overhang_mm < length - deepestOutOfTheJaws - kProfileEpsilon_mm)
        return; // nothing left unbored, or a bar the resolver refuses as too short (and says so)
    QStringList judged;
    for (const Tolerance &x : p.tolerances) {
        if (bores.contains(x.featureId))
            judged << x.id;
    }
    QString where = Plausibility::tr("left at the pilot hole");
    if (reach <= jaws + 1e-6)
        where = Plausibility::tr("inside the jaws (left of z = %1 mm), where no verdict judges it").arg(num(jaws));
    else if (!judged.isEmpty())
        where = Plausibility::tr("while the verdicts of %1 take it as bored").arg(judged.join(QStringLiteral(", ")));
    out.push_back(makeWarning(QStringLiteral("boring_tool.overhang_mm"),
                              Plausibility::tr("%1 mm reaches z = %2 mm (the free end at %3 mm, %4 mm clear of it): "
                                               "%5 not bored from z = %6 mm to there, %7. Reaching it needs an "
                                               "overhang of %8 mm; or bore from both ends")
                                  .arg(num(*t.overhang_mm), num(reach), num(length), num(kToolClearance_mm),
                                       (bores.size() == 1 ? Plausibility::tr("bore %1") : Plausibility::tr("bores %1"))
                                           .arg(bores.join(QStringLiteral(", "))),
                                       num(deepest), where, num(length + kToolClearance_mm - deepest))));
}

// The boring bar (docs/model.md §3.1): a bar the data know, its overhang within the maker's
// largest L/D; bores without a bar are computed without its bending, which the planner is told.
void checkBoringTool(const Project &p, const DataLibrary &data, Diagnostics &out)
{
    if (!p.boringTool) {
        if (cutsBores(p))
            out.push_back(makeWarning(QStringLiteral("boring_tool"),
                                      Plausibility::tr("the part has bores but no boring bar is given: they are "
                                                       "computed as if cut by %1, without the bending of a bar")
                                          .arg(p.tool.holderCode)));
        return;
    }
    const Tool &t = *p.boringTool;
    checkBoringGeometry(p, t, out);
    checkBoringReach(p, t, out);
    const InsertParseResult insert = parseInsertCode(t.insertCode);
    if (!insert.insert) {
        for (const Diagnostic &d : insert.diagnostics)
            out.push_back(makeError(QStringLiteral("boring_tool.insert"), d.message));
    }
    const HolderData *bar = data.holder(t.holderCode);
    if (bar == nullptr || !bar->isBoringBar() || !bar->barDiameter_mm) {
        QStringList bars;
        for (const HolderData &h : data.holders()) {
            if (h.isBoringBar())
                bars << h.code;
        }
        out.push_back(makeError(QStringLiteral("boring_tool.holder"),
                                Plausibility::tr("\"%1\" is not a boring bar in the data library; it has: %2")
                                    .arg(t.holderCode, bars.join(QStringLiteral(", ")))));
        return;
    }
    const BoringBarMaterialData *material = data.boringBarMaterial(*bar);
    if (material == nullptr) {
        out.push_back(makeError(QStringLiteral("boring_tool.holder"),
                                Plausibility::tr("the bar material of \"%1\" (type letter %2) is not in the data "
                                                 "library")
                                    .arg(t.holderCode, t.holderCode.left(1))));
        return;
    }
    if (!cutsBores(p))
        out.push_back(
            makeWarning(QStringLiteral("boring_tool"), Plausibility::tr("a boring bar is given but no bore is cut")));
    if (t.overhang_mm) {
        const double ratio = *t.overhang_mm / bar->barDiameter_mm->value;
        if (ratio > material->maxOverhangRatio.value + 1e-9)
            out.push_back(makeWarning(
                QStringLiteral("boring_tool.overhang_mm"),
                Plausibility::tr("%1 mm is %2 times the bar's diameter, more than the %3 times the maker allows a "
                                 "%4 bar (%5): expect chatter; use a carbide or a larger bar, or bore from both ends")
                    .arg(num(*t.overhang_mm), QString::number(ratio, 'f', 1), num(material->maxOverhangRatio.value),
                         material->id,
                         data.sourceText(material->maxOverhangRatio.source).section(QLatin1Char(','), 0, 1))));
    }
}

void checkRange(double value, const std::optional<ValueRange> &range, const QString &field, const QString &unit,
                const QString &source, Diagnostics &out)
{
    if (!range || (value >= range->min && value <= range->max))
        return;
    out.push_back(makeWarning(field, Plausibility::tr("%1 %2 is outside the insert's published range %3–%4 %2 (%5)")
                                         .arg(num(value), unit, num(range->min), num(range->max),
                                              source.isEmpty() ? Plausibility::tr("no source given")
                                                               : source.section(QLatin1Char(','), 0, 1))));
}

// The smallest and largest diameter a pass cuts: the outer contour's turned features outside the jaws.
std::pair<double, double> cutDiameters(const Project &p)
{
    const double chuckFace = p.clamping.method == ClampingMethod::BetweenCentres ? 0.0 : p.clamping.clampedLength_mm;
    double smallest = 1e300;
    double largest = 0.0;
    for (const Segment &s : p.part.outer.segments) {
        if (!s.isAxial() || s.to.z_mm <= chuckFace || (p.scope && !p.scope->cutFeatures.contains(s.id)))
            continue; // in the jaws, or another set-up's
        for (const double r : {s.from.r_mm, s.to.r_mm}) {
            if (r > 0.0) {
                smallest = std::min(smallest, 2.0 * r);
                largest = std::max(largest, 2.0 * r);
            }
        }
    }
    return {smallest, largest};
}

std::optional<double> machineLimit(const MachineData *m, const char *key)
{
    if (m == nullptr)
        return std::nullopt;
    const auto it = m->limits.find(QLatin1String(key));
    return it == m->limits.end() ? std::nullopt : std::optional<double>(it->second.value);
}

void checkStockTaken(const Project &p, double smallestDiameter_mm, Diagnostics &out);

void checkPasses(const Project &p, const DataLibrary &data, Diagnostics &out)
{
    const PlanningSettings &s = p.planning;
    const MachineData *machine = data.machine(p.machineId);
    const auto maxSpeed = s.maxSpindleSpeed_rpm ? s.maxSpindleSpeed_rpm : machineLimit(machine, "max_speed_rpm");
    const auto maxPower = s.maxPower_kW ? s.maxPower_kW : machineLimit(machine, "power_kW");
    const auto [smallest, largest] = cutDiameters(p);
    Diagnostics ignored;
    const auto forces = projectForceModel(p, data, ignored);
    for (std::size_t i = 0; i < p.passes.size(); ++i) {
        const CuttingPass &pass = p.passes[i];
        const QString at = QStringLiteral("passes[%1].").arg(i);
        checkRange(pass.cuttingSpeed_m_min, s.cuttingSpeed_m_min, at + QStringLiteral("cutting_speed_m_min"),
                   QStringLiteral("m/min"), s.rangesSource, out);
        checkRange(pass.feed_mm_rev, s.feed_mm_rev, at + QStringLiteral("feed_mm_rev"), QStringLiteral("mm/rev"),
                   s.rangesSource, out);
        checkRange(pass.depthOfCut_mm, s.depthOfCut_mm, at + QStringLiteral("depth_of_cut_mm"), QStringLiteral("mm"),
                   s.rangesSource, out);
        if (maxSpeed && smallest < 1e299) {
            const double n = spindleSpeed_rpm(pass.cuttingSpeed_m_min, smallest);
            if (n > *maxSpeed)
                out.push_back(makeWarning(
                    at + QStringLiteral("cutting_speed_m_min"),
                    Plausibility::tr("%1 m/min on Ø%2 mm needs %3 rpm, more than the machine's %4 rpm: the spindle "
                                     "speed limit lowers the cutting speed there")
                        .arg(num(pass.cuttingSpeed_m_min), num(smallest), num(std::round(n)), num(*maxSpeed))));
        }
        if (maxPower && forces && largest > 0.0) {
            const double power =
                cuttingPower_kW((*forces)(pass.feed_mm_rev, pass.depthOfCut_mm).tangential_N, pass.cuttingSpeed_m_min);
            if (power > *maxPower)
                out.push_back(makeWarning(at + QStringLiteral("depth_of_cut_mm"),
                                          Plausibility::tr("the pass needs %1 kW of cutting power, more than the "
                                                           "machine's %2 kW")
                                              .arg(num(power), num(*maxPower))));
        }
    }
    checkStockTaken(p, smallest, out);
    if (!p.passes.empty() && std::none_of(p.passes.begin(), p.passes.end(),
                                          [](const CuttingPass &pass) { return pass.kind == PassKind::Finishing; }))
        out.push_back(makeWarning(QStringLiteral("passes"),
                                  Plausibility::tr("no finishing pass: the last pass is taken as the one that cuts "
                                                   "the contour to size (the verdicts and the program rest on it)")));
}

// The passes together cut no deeper than the stock is thick where it is thickest (the bar's
// radius less the smallest turned radius): deeper, the last passes cut air, and their forces,
// deflection and time are not those of the part.
void checkStockTaken(const Project &p, double smallestDiameter_mm, Diagnostics &out)
{
    if (p.passes.empty() || smallestDiameter_mm > 1e299)
        return;
    const double stock_mm = 0.5 * (p.part.stockDiameter_mm - smallestDiameter_mm);
    double depth_mm = 0.0;
    for (const CuttingPass &pass : p.passes)
        depth_mm += pass.depthOfCut_mm;
    constexpr double kTolerance_mm = 1e-6; // equal depths given to a few decimals
    if (depth_mm > stock_mm + kTolerance_mm)
        out.push_back(makeWarning(
            QStringLiteral("passes[%1].depth_of_cut_mm").arg(p.passes.size() - 1),
            Plausibility::tr("the passes cut %1 mm deep in all, but the stock is at most %2 mm thick on the radius "
                             "(Ø%3 mm bar, smallest turned Ø%4 mm): the tool cuts air for %5 mm, and the forces "
                             "and deflection are not those of the passes as given")
                .arg(num(depth_mm), num(stock_mm), num(p.part.stockDiameter_mm), num(smallestDiameter_mm),
                     num(depth_mm - stock_mm))));
}

// The findings about one operation's tools and passes, their fields where the file keeps that
// operation's ("further_operations[0].passes[1].feed_mm_rev"); the project's own (material,
// machine) only once, with the first.
void checkOperation(const Project &project, int index, const DataLibrary &data, Diagnostics &out)
{
    const Project view = operationView(project, index);
    Diagnostics found;
    checkLibraryEntries(view, data, found);
    checkBoringTool(view, data, found);
    checkPasses(view, data, found);
    // What the computing commands would refuse (a bar's overhang short of the bore or longer than the
    // bar, say) is refused here too, each field once.
    if (!hasErrors(found)) {
        for (const Diagnostic &d : resolveTurningInputs(view, data, {}).diagnostics) {
            const bool said = std::any_of(found.begin(), found.end(), [&d](const Diagnostic &x) {
                return x.field == d.field && x.severity == d.severity;
            });
            if (d.severity == Severity::Error && !said)
                found.push_back(d);
        }
    }
    const QString prefix = QStringLiteral("further_operations[%1].").arg(index - 1);
    for (Diagnostic &d : found) {
        // The set-up's own fields; the rest (part, material, machine) are the first set-up's too.
        const bool ofOperation =
            d.field.startsWith(QLatin1String("tool")) || d.field.startsWith(QLatin1String("boring_tool")) ||
            d.field.startsWith(QLatin1String("passes")) || d.field.startsWith(QLatin1String("clamping"));
        if (index == 0 || ofOperation) {
            if (index > 0)
                d.field.prepend(prefix);
            out.push_back(d);
        }
    }
}

// The insert that cuts a feature: the boring insert in a bore (when a boring bar is given), else
// the turning insert, of the operation that cuts it.
const Tool &toolFor(const Project &project, const QString &featureId, ContourSide side)
{
    const int op = operationOf(project, featureId);
    const Tool &tool = op == 0 ? project.tool : project.furtherOperations[static_cast<std::size_t>(op - 1)].tool;
    const std::optional<Tool> &bar =
        op == 0 ? project.boringTool : project.furtherOperations[static_cast<std::size_t>(op - 1)].boringTool;
    return side == ContourSide::Inner && bar ? *bar : tool;
}

// A groove narrower than the insert's nose (2 r_e across) is out of its reach: the nose cannot
// get to the bottom, and the flanks and bottom are left uncut. Grooving inserts are not in the
// data, so the width such an insert may have is said instead.
void checkGrooves(const Project &project, Diagnostics &out)
{
    for (const ContourSide side : {ContourSide::Outer, ContourSide::Inner}) {
        const Contour &contour = project.part.contour(side);
        for (const Groove &g : groovesOf(contour, side)) {
            const Tool &tool = toolFor(project, g.leftFaceId, side);
            const InsertParseResult insert = parseInsertCode(tool.insertCode);
            const auto face = findFeature(project.part, g.leftFaceId);
            if (!insert.insert || !face)
                continue; // a bad insert code is an error of its own
            const double nose = 2.0 * insert.insert->noseRadius_mm;
            if (g.width_mm >= nose - 1e-9)
                continue;
            out.push_back(makeWarning(
                QStringLiteral("part.%1[%2]").arg(contourName(side)).arg(face->index),
                Plausibility::tr("the groove between %1 and %2 is %3 mm wide, narrower than the nose of %4 (r_e %5 "
                                 "mm, %6 mm across): it cannot reach the groove's bottom; cut the groove with a "
                                 "grooving insert at most %3 mm wide")
                    .arg(g.leftFaceId, g.rightFaceId, num(g.width_mm), tool.insertCode,
                         num(insert.insert->noseRadius_mm), num(nose))));
        }
    }
}

} // namespace

Diagnostics checkPlausibility(const Project &project, const DataLibrary &data)
{
    Diagnostics out;
    for (int k = 0; k < operationCount(project); ++k)
        checkOperation(project, k, data, out);
    checkGrooves(project, out);
    return out;
}

} // namespace tolturn
