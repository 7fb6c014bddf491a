// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/mechanics/beam_corrections.h"

#include "core/part/profile_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace tolturn {

namespace {

// (D/d, e_s): the identified hinge lengths (docs/solid-fe.md, second set), far from the step.
constexpr std::array<std::pair<double, double>, 4> kShoulderHinge{
    {{1.0, 0.0}, {1.25, 0.057}, {1.6, 0.126}, {2.0, 0.171}}};

// A jump of the outer radius smaller than this is none: over kSide_mm on each side of a vertex a
// cone would have to be steeper than 50:1 to count.
constexpr double kStepTolerance_mm = 1e-3;

// Looked at this far on each side of a vertex for the section's jump: ten times the profile's own
// tolerance (kProfileEpsilon_mm), within which both sides are the vertex itself.
constexpr double kSide_mm = 1e-5;

// A shoulder is a jump of the section at a vertex of the profile; a node that is no vertex (a tool
// position a micrometre from the step, say) has none, so no step is counted twice.
bool atVertex(const SectionAlongZ &section, double z_mm)
{
    const std::vector<double> &v = section.breakpoints();
    const auto it = std::lower_bound(v.begin(), v.end(), z_mm - kProfileEpsilon_mm);
    return it != v.end() && *it <= z_mm + kProfileEpsilon_mm;
}

} // namespace

double shoulderHingePerDiameter(double diameterRatio)
{
    if (diameterRatio <= kShoulderHinge.front().first)
        return 0.0;
    for (std::size_t i = 1; i < kShoulderHinge.size(); ++i) {
        const auto [x0, y0] = kShoulderHinge[i - 1];
        const auto [x1, y1] = kShoulderHinge[i];
        if (diameterRatio <= x1)
            return y0 + (y1 - y0) * (diameterRatio - x0) / (x1 - x0);
    }
    return kShoulderHinge.back().second;
}

Matrix2 rootFlexibility(const RoundSection &root, const ElasticMaterial &material)
{
    // The bending of a uniform cantilever of length L built in at its far end, loaded at the face:
    // w = P L^3/3EI + M L^2/2EI, theta = P L^2/2EI + M L/EI (Timoshenko & Gere, Mechanics of
    // Materials, cantilever cases). Bending only, as it was identified: the beam built in L further
    // in, Δ = F [(a + L)^3 - a^3] / 3EI at a from the face (docs/solid-fe.md).
    const double L = kRootEmbedmentPerDiameter * 2.0 * root.outerRadius_mm;
    const double EI = material.youngsModulus_MPa * root.secondMoment_mm4();
    Matrix2 f;
    f << L * L * L / (3.0 * EI), L * L / (2.0 * EI), L * L / (2.0 * EI), L / EI;
    return f;
}

double shoulderCompliance(const RoundSection &thick, const RoundSection &thin, const ElasticMaterial &material)
{
    const double d = 2.0 * thin.outerRadius_mm;
    const double e = shoulderHingePerDiameter(thick.outerRadius_mm / thin.outerRadius_mm);
    return e * d / (material.youngsModulus_MPa * thin.secondMoment_mm4());
}

Matrix2 flexibilityAtStart(const Matrix2 &compliance, double length_mm)
{
    Matrix2 gamma;
    gamma << 1.0, length_mm, 0.0, 1.0;
    return gamma * compliance * gamma.transpose();
}

Matrix2 correctionFlexibility(const SectionAlongZ &section, const ElasticMaterial &material,
                              const BeamCorrections &corrections, double z0_mm, double z1_mm)
{
    Matrix2 c = Matrix2::Zero();
    const RoundSection right = section.at(z0_mm + kSide_mm);
    const bool builtIn = corrections.builtInAt_mm && std::abs(z0_mm - *corrections.builtInAt_mm) < kProfileEpsilon_mm;
    if (builtIn)
        c += rootFlexibility(right, material);
    // A shoulder at the chuck face is in the jaws' hold: the root is its correction, not a hinge.
    if (corrections.shoulders && !builtIn && atVertex(section, z0_mm)) {
        const RoundSection left = section.at(z0_mm - kSide_mm);
        if (std::abs(left.outerRadius_mm - right.outerRadius_mm) > kStepTolerance_mm &&
            std::min(left.outerRadius_mm, right.outerRadius_mm) > 0.0) {
            const bool thinRight = right.outerRadius_mm < left.outerRadius_mm;
            c(1, 1) += shoulderCompliance(thinRight ? left : right, thinRight ? right : left, material);
        }
    }
    return flexibilityAtStart(c, z1_mm - z0_mm);
}

} // namespace tolturn
