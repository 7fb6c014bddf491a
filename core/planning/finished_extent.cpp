// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/finished_extent.h"

#include "core/common/diagnostic.h"
#include "core/planning/gcode.h"
#include "core/planning/path_geometry.h"
#include "core/tolerance/target_contour.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {

struct FinishedExtent {
    Q_DECLARE_TR_FUNCTIONS(FinishedExtent)
};

constexpr double kOnThePath_mm = 0.002; // the program's coordinates are stated to 0.001 mm
constexpr double kSampleStep_mm = 0.05;

// The finishing moves that finish a feature, as elements from where the move before ended.
std::vector<PathElement> finishingElements(const std::vector<PassPath> &passes)
{
    std::vector<PathElement> out;
    for (const PassPath &pass : passes) {
        for (std::size_t i = 1; i < pass.moves.size(); ++i) {
            const ToolMove &m = pass.moves[i];
            if (m.featureId.isEmpty() || m.kind == MoveKind::Rapid)
                continue;
            PathElement e;
            e.from = pass.moves[i - 1].to;
            e.to = m.to;
            e.featureId = m.featureId;
            if (m.kind == MoveKind::ArcClockwise || m.kind == MoveKind::ArcCounterClockwise) {
                e.arc = true;
                e.centre = m.centre;
                e.radius_mm = m.radius_mm;
                e.counterClockwise = m.kind == MoveKind::ArcCounterClockwise;
            }
            out.push_back(e);
        }
    }
    return out;
}

bool onThePath(const std::vector<PathElement> &path, ProfilePoint p)
{
    return std::any_of(path.begin(), path.end(),
                       [p](const PathElement &e) { return distanceTo(e, p) <= kOnThePath_mm; });
}

// Whether the program is asked to finish a point of a feature of this set-up: outside, right of
// the jaws (the bore inside them is the boring bar's to reach), and not inside the pilot hole on a
// bore's bottom face.
bool askedOf(const Project &project, const Segment &s, ContourSide side, ProfilePoint p)
{
    const bool held = project.clamping.method != ClampingMethod::BetweenCentres;
    if (side == ContourSide::Outer && held && p.z_mm < project.clamping.clampedLength_mm - 1e-9)
        return false;
    const bool face = s.kind == SegmentKind::Face;
    const double pilot = side == ContourSide::Inner && project.boringTool && project.boringTool->pilotHoleDiameter_mm
                             ? 0.5 * *project.boringTool->pilotHoleDiameter_mm
                             : 0.0;
    return !(face && p.r_mm < pilot - 1e-9);
}

// A stretch of one sample (the end of a feature at the jaw face, say) is below what the sampling
// resolves: not said.
void keepIfLong(const UnfinishedStretch &s, std::vector<UnfinishedStretch> &out)
{
    if (std::hypot(s.to.z_mm - s.from.z_mm, s.to.r_mm - s.from.r_mm) > 1e-9)
        out.push_back(s);
}

void collect(const Project &project, const Contour &target, ContourSide side, const std::vector<PathElement> &path,
             std::vector<UnfinishedStretch> &out)
{
    for (const Segment &s : target.segments) {
        if (project.scope && !project.scope->cutFeatures.contains(s.id))
            continue;
        const std::vector<PathElement> elements = reversedElements({s});
        if (elements.empty())
            continue;
        std::optional<UnfinishedStretch> open;
        for (const ProfilePoint &p : sampled(elements.front(), kSampleStep_mm, 20000)) {
            const bool unfinished = askedOf(project, s, side, p) && !onThePath(path, p);
            if (unfinished && !open)
                open = UnfinishedStretch{s.id, p, p};
            else if (unfinished)
                open->to = p;
            if (!unfinished && open) {
                keepIfLong(*open, out);
                open.reset();
            }
        }
        if (open)
            keepIfLong(*open, out);
    }
}

QString mm(double v)
{
    return formatFixed(v, 3);
}

} // namespace

std::vector<UnfinishedStretch> unfinishedStretches(const Project &project, const TurningInputs &inputs)
{
    const std::vector<PassPath> passes = finishingPasses(project, inputs);
    const std::vector<PathElement> path = finishingElements(passes);
    std::vector<UnfinishedStretch> out;
    collect(project, targetContour(project, ContourSide::Outer), ContourSide::Outer, path, out);
    collect(project, targetContour(project, ContourSide::Inner), ContourSide::Inner, path, out);
    return out;
}

QString unfinishedText(const UnfinishedStretch &s)
{
    if (std::abs(s.from.z_mm - s.to.z_mm) < 1e-9)
        return FinishedExtent::tr("%1 at z = %2 mm from r %3 to %4 mm")
            .arg(s.featureId, mm(s.from.z_mm), mm(std::min(s.from.r_mm, s.to.r_mm)),
                 mm(std::max(s.from.r_mm, s.to.r_mm)));
    return FinishedExtent::tr("z %1–%2 mm of %3")
        .arg(mm(std::min(s.from.z_mm, s.to.z_mm)), mm(std::max(s.from.z_mm, s.to.z_mm)), s.featureId);
}

void addWhatTheProgramLeaves(const Project &project, RangeEvaluation &range)
{
    if (!range.compliant.inputs)
        return;
    const std::vector<UnfinishedStretch> stretches = unfinishedStretches(project, *range.compliant.inputs);
    if (stretches.empty())
        return;
    for (ToleranceRangeEvaluation &e : range.tolerances) {
        if (e.compliant.verdict == Verdict::CannotEvaluate)
            continue; // not cut in this set-up, or its limits cannot be formed: said already
        const auto t = std::find_if(project.tolerances.begin(), project.tolerances.end(),
                                    [&e](const Tolerance &x) { return x.id == e.compliant.toleranceId; });
        if (t == project.tolerances.end())
            continue;
        QStringList left;
        for (const UnfinishedStretch &s : stretches)
            if (s.featureId == t->featureId || (!t->toFeatureId.isEmpty() && s.featureId == t->toFeatureId))
                left << unfinishedText(s);
        if (left.isEmpty())
            continue;
        const QString onWhatItTurns = e.range == RangeVerdict::NoRange || e.range == RangeVerdict::NotDecided
                                          ? verdictName(e.compliant.verdict)
                                          : rangeVerdictText(e);
        const QString text = FinishedExtent::tr("not finished by this set-up's program, which leaves %1 as it was "
                                                "(see the program's warnings); on what it turns: %2")
                                 .arg(left.join(QStringLiteral(", ")), onWhatItTurns);
        e.compliant.verdict = Verdict::CannotEvaluate;
        e.compliant.reason = e.compliant.reason.isEmpty() ? text : text + QStringLiteral("; ") + e.compliant.reason;
        e.range = RangeVerdict::NotFinished;
        e.unfinished = left;
        // No figure to act on: the offsets and the stiffness needed hold for a part the program
        // does not make (the reason keeps what they were).
        e.compliant.offset_um.reset();
        e.stiff.reset();
        e.chuck.reset();
        e.tailstock.reset();
        e.offsetOnAnyMachine_um.reset();
    }
}

} // namespace tolturn
