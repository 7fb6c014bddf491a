// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/boring_toolpath.h"

#include "core/part/profile_geometry.h"
#include "core/planning/toolpath_detail.h"
#include "core/tolerance/target_contour.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tolturn {

namespace {

using namespace toolpath_detail;

struct Toolpaths {
    Q_DECLARE_TR_FUNCTIONS(Toolpath)
};

constexpr double kTiny = 1e-9;
constexpr double kLeftAboveAllowance_mm = 1e-3; // the last roughing level stays this far off the allowance
constexpr std::size_t kMaxBoringLevels = 100;   // as many as the project's roughing passes may be

QString mm(double value)
{
    return QString::number(value, 'f', 3);
}

// The segments of the bore open at the free end (z = length): a through bore, or the bore from
// the right end of a part bored from both ends. Empty when there is none.
std::vector<Segment> boreOpenAtFreeEnd(const Contour &inner, double length_mm)
{
    for (const auto &[first, end] : inner.pieces()) {
        if (std::abs(inner.segments[end - 1].to.z_mm - length_mm) < 1e-6)
            return {inner.segments.begin() + static_cast<std::ptrdiff_t>(first),
                    inner.segments.begin() + static_cast<std::ptrdiff_t>(end)};
    }
    return {};
}

// In one set-up of several: the chain up to the first element of a feature another set-up cuts.
std::vector<PathElement> thisOperationsPart(std::vector<PathElement> chain, const Project &project)
{
    if (!project.scope)
        return chain;
    const auto other = std::find_if(chain.begin(), chain.end(), [&](const PathElement &e) {
        return !project.scope->cutFeatures.contains(e.featureId);
    });
    chain.erase(other, chain.end());
    return chain;
}

bool isFace(const PathElement &e)
{
    return !e.arc && std::abs(e.from.z_mm - e.to.z_mm) < kTiny;
}

// The faces the chain ends with (running towards the axis) end at rStop.
void stopBottomFaceAt(std::vector<PathElement> &chain, double rStop)
{
    while (!chain.empty() && isFace(chain.back()) && chain.back().to.r_mm < rStop - kTiny) {
        if (chain.back().from.r_mm <= rStop + kTiny) {
            chain.pop_back();
            continue;
        }
        chain.back().to.r_mm = rStop;
        break;
    }
}

// Stock above the allowance that the finishing pass takes as it is (as in turning, toolpath.cpp):
// a tenth of the allowance, at least 10 µm.
double finishingSlack(double allowance_mm)
{
    return std::max(0.01, 0.1 * allowance_mm);
}

// The depths of the roughing levels that take the bore from `stockLevel` to `deepest` (mirrored
// nose-centre coordinates): the project's roughing passes in order, the last repeated, the last
// level shortened to end on the allowance; stock within the slack is left to the finishing pass.
std::vector<CuttingPass> boringLevels(const std::vector<CuttingPass> &roughing, double stockLevel, double deepest,
                                      double slack, bool &tooMany)
{
    std::vector<CuttingPass> levels;
    double level = stockLevel;
    const double bottom = deepest + kLeftAboveAllowance_mm;
    tooMany = false;
    while (level - bottom > slack && !roughing.empty()) {
        if (levels.size() == kMaxBoringLevels) {
            tooMany = true;
            break;
        }
        CuttingPass pass = roughing[std::min(levels.size(), roughing.size() - 1)];
        pass.depthOfCut_mm = std::min(pass.depthOfCut_mm, level - bottom);
        level -= pass.depthOfCut_mm;
        levels.push_back(pass);
    }
    return levels;
}

// The lowest point of the envelope on the part: the largest bore radius less the allowance and r_e.
double deepestOnPart(const Envelope &env, double length_mm)
{
    double deepest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < env.r_mm.size(); ++i)
        if (env.z(i) <= length_mm && std::isfinite(env.r_mm[i]))
            deepest = std::min(deepest, env.r_mm[i]);
    return deepest;
}

PassPath mirroredBack(PassPath pass)
{
    for (ToolMove &m : pass.moves)
        m = mirrored(m);
    return pass;
}

// The bar in a hole of radius rHole with its cutting edge at radius rTip: the bar's section, a
// circle of its diameter about a point f below the edge, must stay inside the hole.
bool barFits(const BoringBarGeometry &bar, double rTip, double rHole)
{
    return std::abs(rTip - bar.edgeOffset_mm) + 0.5 * bar.barDiameter_mm <= rHole + 1e-9;
}

struct BoreFrame {
    std::vector<Segment> target;    // the bore's target segments, left to right
    std::vector<PathElement> chain; // what the finishing pass cuts, right to left
    double zStop = 0.0;             // the leftmost z of the nose centre: the bore's bottom or the bar's reach
    double rHole = 0.0;             // radius of the hole the bar enters
    double rSafe = 0.0;             // radius of the cutting edge in moves along z
};

void roughTheBore(Toolpath &path, const BoreFrame &f, const std::vector<CuttingPass> &roughing, double allowance_mm,
                  const BoringBarGeometry &bar, const ToolpathOptions &options, double length_mm)
{
    const double re = bar.noseRadius_mm;
    Envelope env = widenedEnvelope(mirrored(f.target), allowance_mm + re, f.zStop,
                                   length_mm + options.clearance_mm + re, kEnvelopeStep_mm);
    if (bar.trailingEdgeAngle_deg)
        rideOverSteepFalls(env, rideAngle_deg(*bar.trailingEdgeAngle_deg));
    const double stockLevel = -f.rHole + re;
    const double deepest = deepestOnPart(env, length_mm);
    bool tooMany = false;
    const double slack = finishingSlack(allowance_mm);
    const std::vector<CuttingPass> levels = boringLevels(roughing, stockLevel, deepest, slack, tooMany);
    if (levels.empty() && stockLevel - deepest > slack)
        path.warnings << Toolpaths::tr("No roughing pass is planned: the finishing pass would bore up to %1 mm more "
                                       "than its depth of cut from the pilot hole.")
                             .arg(mm(stockLevel - deepest));
    if (tooMany)
        path.warnings << Toolpaths::tr("The bore needs more than %1 roughing levels at the planned depths of cut: "
                                       "the program stops there.")
                             .arg(kMaxBoringLevels);
    std::vector<PassPath> passes;
    const double last = roughLevels(passes, levels, env, stockLevel, -f.rSafe, re, options.clearance_mm);
    for (PassPath &p : passes) {
        p = mirroredBack(std::move(p));
        p.smallestDiameter_mm = -p.smallestDiameter_mm; // the nose's top on the level, mirrored back
    }
    path.roughing = std::move(passes);
    const double left = stockLeftAboveAllowance(env, last, length_mm);
    if (!tooMany && left > slack)
        path.warnings << Toolpaths::tr("The boring levels leave up to %1 mm more than the finishing allowance of "
                                       "%2 mm: the finishing pass would cut it.")
                             .arg(mm(left), mm(allowance_mm));
}

void finishTheBore(Toolpath &path, const BoreFrame &f, const CuttingPass &finishing, const BoringBarGeometry &bar,
                   const ToolpathOptions &options, double length_mm)
{
    std::vector<PathElement> mirror = mirrored(f.chain);
    std::vector<RiddenOver> ridden;
    if (bar.trailingEdgeAngle_deg)
        mirror = riddenOverSteepFalls(mirror, rideAngle_deg(*bar.trailingEdgeAngle_deg), &ridden);
    path.finishing = mirroredBack(
        contourPass(mirror, false, finishing, options, bar.noseRadius_mm, -f.rSafe, length_mm, path.warnings));
    path.finishing.smallestDiameter_mm = 2.0 * smallestAxialRadius(f.chain);
    // The exit (the move before the last rapid) leaves the bottom face or the bore's end by the
    // clearance along z as it goes to the safe radius, instead of running along the face it cut.
    if (path.finishing.moves.size() >= 2)
        path.finishing.moves[path.finishing.moves.size() - 2].to.z_mm += options.clearance_mm;
    if (bar.trailingEdgeAngle_deg)
        warnWhereTheToolRidesOver(ridden, *bar.trailingEdgeAngle_deg, bar.noseRadius_mm, path.warnings);
    else
        path.warnings << Toolpaths::tr("The trailing edge angle of the boring bar is not known (bar entering angle "
                                       "and insert shape): falling contours of the bore are not checked.");
}

} // namespace

std::optional<Toolpath> boringToolpath(const Project &project, const CuttingPass &finishing,
                                       const std::vector<CuttingPass> &roughing, const BoringBarGeometry &bar,
                                       const ToolpathOptions &options)
{
    const double length = project.part.length_mm();
    BoreFrame f;
    f.target = boreOpenAtFreeEnd(targetContour(project, ContourSide::Inner), length);
    f.chain = thisOperationsPart(compensatedChain(Contour{f.target}, options.compensation), project);
    if (f.chain.empty())
        return std::nullopt;
    Toolpath path;
    path.side = ContourSide::Inner;
    path.nose = options.nose;
    path.noseRadius_mm = bar.noseRadius_mm;
    const double allowance = finishing.depthOfCut_mm;
    const double boreBottom = f.chain.back().to.z_mm;
    // The turret face stays the clearance off the end face: the edge reaches the overhang less it.
    // That is the nose's leftmost point; its centre, which the paths are planned for, stays r_e
    // to the right of it, and so does the last point of the wall it cuts.
    const double reach = length + options.clearance_mm - bar.overhang_mm;
    f.zStop = boreBottom;
    if (reach > boreBottom + 1e-6) {
        f.zStop = reach + bar.noseRadius_mm;
        f.chain = clippedAtLeft(f.chain, f.zStop, bar.noseRadius_mm, true);
        path.warnings << Toolpaths::tr("Boring bar %1 reaches z = %2 mm with its overhang of %3 mm: the bore from "
                                       "z = %4 mm to there is not bored. Set a longer overhang.")
                             .arg(bar.holderCode, mm(reach), mm(bar.overhang_mm), mm(boreBottom));
        if (f.chain.empty())
            return path; // the bar does not reach into the part: nothing to bore, said above
    }
    const double smallestBore = smallestAxialRadius(f.chain);
    f.rHole = bar.pilotHoleDiameter_mm ? 0.5 * *bar.pilotHoleDiameter_mm : smallestBore - allowance;
    if (!bar.pilotHoleDiameter_mm)
        path.warnings << Toolpaths::tr("The pilot hole is not given (Set-up dock, Boring bar): the bore is taken as "
                                       "roughed to Ø%1 mm, its finishing allowance, before this program, and only its "
                                       "finishing pass is programmed.")
                             .arg(mm(2.0 * f.rHole));
    else if (f.rHole >= smallestBore - 1e-6)
        path.warnings << Toolpaths::tr("The pilot hole Ø%1 mm is as wide as the bore's narrowest Ø%2 mm or wider: "
                                       "nothing is left to bore there, and it stays the pilot hole's size, not the "
                                       "drawing's.")
                             .arg(mm(2.0 * f.rHole), mm(2.0 * smallestBore));
    else if (f.rHole > smallestBore - allowance + 1e-6)
        path.warnings << Toolpaths::tr("The pilot hole Ø%1 mm is wider than the bore less its finishing allowance "
                                       "(Ø%2 mm): the finishing pass cuts less than its depth of cut.")
                             .arg(mm(2.0 * f.rHole), mm(2.0 * (smallestBore - allowance)));
    // Along z the edge runs where the bar's axis is on the spindle's (f off the axis), or as near
    // as the hole lets it.
    f.rSafe = std::min(bar.edgeOffset_mm, f.rHole - options.clearance_mm);
    path.safeDiameter_mm = 2.0 * f.rSafe;
    if (!barFits(bar, f.rSafe, f.rHole))
        path.warnings << Toolpaths::tr("Boring bar %1 (Ø%2 mm, edge %3 mm from its axis) does not fit in the Ø%4 mm "
                                       "hole it enters: it needs a hole of Ø%5 mm or more.")
                             .arg(bar.holderCode, mm(bar.barDiameter_mm), mm(bar.edgeOffset_mm), mm(2.0 * f.rHole),
                                  mm(std::max(bar.barDiameter_mm,
                                              bar.edgeOffset_mm + 0.5 * bar.barDiameter_mm + options.clearance_mm)));
    if (isFace(f.chain.back())) {
        // A face that ends on the axis is the bottom of a blind bore: inside the pilot hole it is the
        // drill's. One that ends on a bore another set-up cuts is faced to its end. Neither further in
        // than the bar reaches without touching the opposite wall.
        const PathElement &face = f.chain.back();
        const bool bottom = face.to.r_mm < kTiny;
        const double drilled = bottom && bar.pilotHoleDiameter_mm ? f.rHole : face.to.r_mm;
        const double barReach = bar.edgeOffset_mm + 0.5 * bar.barDiameter_mm - face.from.r_mm;
        const double rStop = std::max(drilled, barReach);
        if (barReach > drilled + 1e-6)
            path.warnings << Toolpaths::tr("Boring bar %1 faces %2 only down to Ø%3 mm (further in, it would touch "
                                           "the opposite wall).")
                                 .arg(bar.holderCode, face.featureId, mm(2.0 * rStop));
        if (bottom && bar.pilotHoleDiameter_mm)
            path.notes << Toolpaths::tr("The bottom of the bore inside the pilot hole, Ø%1 mm, is the drill's: it is "
                                        "not bored.")
                              .arg(mm(2.0 * f.rHole));
        stopBottomFaceAt(f.chain, rStop);
    } else if (f.chain.back().to.r_mm < kTiny) {
        path.warnings << Toolpaths::tr("The bottom of the bore, %1, is a cone or a radius down to the axis: the "
                                       "program finishes it to the axis, without the pilot hole's and the bar's "
                                       "limits of a flat bottom. Check that the bar clears the opposite wall there.")
                             .arg(f.chain.back().featureId);
    } else if (boreBottom < kTiny && reach <= kTiny) {
        path.notes << Toolpaths::tr("The bar bores through to the held end: the chuck's or collet's bore must be "
                                    "free behind it.");
    }
    if (bar.pilotHoleDiameter_mm && !f.chain.empty())
        roughTheBore(path, f, roughing, allowance, bar, options, length);
    if (!f.chain.empty())
        finishTheBore(path, f, finishing, bar, options, length);
    path.notes << Toolpaths::tr("The bore is bored from the free end with boring bar %1.").arg(bar.holderCode);
    return path;
}

} // namespace tolturn
