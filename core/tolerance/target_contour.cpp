// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/tolerance/target_contour.h"

#include "core/part/profile_geometry.h"
#include "core/tolerance/iso286.h"

#include <algorithm>
#include <limits>
#include <map>

namespace tolturn {

namespace {

// The limit deviations of one diameter tolerance at its nominal size [µm], as the verdicts form
// them (ISO 286-1 class, or the explicit limits).
std::optional<std::pair<double, double>> diameterLimits_um(const Tolerance &t, double nominal_mm)
{
    if (!t.iso286Class.isEmpty()) {
        const iso286::LimitsResult limits = iso286::limits(nominal_mm, t.iso286Class);
        if (!limits.limits)
            return std::nullopt;
        return std::make_pair(limits.limits->upper_um, limits.limits->lower_um);
    }
    if (!t.upperDeviation_um || !t.lowerDeviation_um)
        return std::nullopt;
    return std::make_pair(*t.upperDeviation_um, *t.lowerDeviation_um);
}

bool joinsWithCylinder(SegmentKind kind)
{
    return kind == SegmentKind::Cone || kind == SegmentKind::Chamfer || kind == SegmentKind::Radius;
}

struct Reach {
    int steps = 0;
    double shift_mm = 0.0;
};

// Walks from segment `start` in direction `step` over chamfers, cones and edge rounds to the
// cylinder whose chain they belong to, never across the solid between two bores.
std::optional<Reach> chainCylinder(const Contour &contour, const std::vector<double> &shift, int start, int step)
{
    const std::vector<Segment> &segments = contour.segments;
    for (int i = start, steps = 0; i >= 0 && i < static_cast<int>(segments.size()); i += step, ++steps) {
        const Segment &s = segments[static_cast<std::size_t>(i)];
        if (s.kind == SegmentKind::Cylinder)
            return Reach{steps, shift[static_cast<std::size_t>(i)]};
        if (!joinsWithCylinder(s.kind))
            return std::nullopt;
        const int next = i + step;
        if (contour.breaksBefore(static_cast<std::size_t>(std::max(i, next))))
            return std::nullopt;
    }
    return std::nullopt;
}

} // namespace

std::vector<DiameterTarget> diameterTargets(const Project &project)
{
    std::map<QString, DiameterTarget> byFeature;
    for (const Tolerance &t : project.tolerances) {
        if (t.type != ToleranceType::Diameter)
            continue;
        const auto feature = findFeature(project.part, t.featureId);
        if (!feature || feature->segment->kind != SegmentKind::Cylinder)
            continue;
        const double nominal = 2.0 * feature->segment->from.r_mm;
        const auto limits = diameterLimits_um(t, nominal);
        if (!limits)
            continue;
        auto [it, inserted] =
            byFeature.try_emplace(t.featureId, DiameterTarget{t.featureId, nominal, limits->first, limits->second});
        if (!inserted) { // two size tolerances on one diameter: the zone both allow
            it->second.upper_um = std::min(it->second.upper_um, limits->first);
            it->second.lower_um = std::max(it->second.lower_um, limits->second);
        }
    }
    std::vector<DiameterTarget> out;
    out.reserve(byFeature.size());
    for (auto &[id, target] : byFeature)
        out.push_back(target);
    return out;
}

Contour targetContour(const Project &project, ContourSide side)
{
    Contour contour = project.part.contour(side);
    std::vector<Segment> &segments = contour.segments;
    if (segments.empty())
        return contour;
    std::map<QString, double> radialShift_mm;
    for (const DiameterTarget &t : diameterTargets(project))
        radialShift_mm[t.featureId] = 0.5 * (t.target_mm() - t.nominal_mm);
    std::vector<double> shift(segments.size(), 0.0);
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const auto it = radialShift_mm.find(segments[i].id);
        if (segments[i].kind == SegmentKind::Cylinder && it != radialShift_mm.end())
            shift[i] = it->second;
    }
    // Vertex v sits between segments v-1 and v; where the inner contour breaks these are two
    // points, each moved with its own bore.
    const int n = static_cast<int>(segments.size());
    std::vector<double> endShift(segments.size() + 1, 0.0);   // of segment v-1's end
    std::vector<double> startShift(segments.size() + 1, 0.0); // of segment v's start
    const Reach none{std::numeric_limits<int>::max(), 0.0};   // no cylinder that way: no shift
    for (int v = 0; v <= n; ++v) {
        const Reach left = v > 0 ? chainCylinder(contour, shift, v - 1, -1).value_or(none) : none;
        const Reach right = v < n ? chainCylinder(contour, shift, v, +1).value_or(none) : none;
        const auto k = static_cast<std::size_t>(v);
        if (contour.breaksBefore(k)) {
            endShift[k] = left.shift_mm;
            startShift[k] = right.shift_mm;
        } else {
            endShift[k] = startShift[k] = left.steps <= right.steps ? left.shift_mm : right.shift_mm;
        }
    }
    for (std::size_t i = 0; i < segments.size(); ++i) {
        segments[i].from.r_mm += startShift[i];
        segments[i].to.r_mm += endShift[i + 1];
    }
    return contour;
}

ProgramTargets programTargets(const Project &project)
{
    return {diameterTargets(project),
            targetContour(project, ContourSide::Outer),
            targetContour(project, ContourSide::Inner),
            {}};
}

std::optional<double> targetRadius_mm(const Contour &target, const QString &featureId, double z_mm)
{
    for (const Segment &s : target.segments) {
        if (s.id == featureId)
            return radiusOnSegment(s, z_mm);
    }
    return std::nullopt;
}

} // namespace tolturn
