// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/adaptive/pass_depth.h"

#include "core/mechanics/section.h"

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {

// Linear interpolation in a table sampled at z decreasing; ends held.
double interpolate(const std::vector<double> &z, const std::vector<double> &v, double at)
{
    if (z.empty())
        return 0.0;
    if (at >= z.front())
        return v.front();
    if (at <= z.back())
        return v.back();
    const auto it = std::lower_bound(z.begin(), z.end(), at, std::greater<>());
    const auto i = static_cast<std::size_t>(it - z.begin());
    if (i == 0)
        return v.front();
    const double t = (z[i - 1] - at) / (z[i - 1] - z[i]);
    return v[i - 1] + t * (v[i] - v[i - 1]);
}

} // namespace

double PassDepthProfile::depthAt(double z) const
{
    return interpolate(z_mm, depth_mm, z);
}

double PassDepthProfile::cutDiameterAt(double z) const
{
    return interpolate(z_mm, cutDiameter_mm, z);
}

double PassDepthProfile::nextCut_mm(double z, double air_mm) const
{
    for (std::size_t i = 0; i < z_mm.size(); ++i)
        if (z_mm[i] < z && depth_mm[i] > air_mm)
            return z_mm[i];
    return z_mm.empty() ? z : z_mm.back();
}

std::vector<PassDepthProfile> passDepthProfiles(const Project &project, double leftEnd_mm, double step_mm)
{
    const PartProfile &part = project.part;
    const double length = part.length_mm();
    if (length <= leftEnd_mm || step_mm <= 0.0)
        return {};
    std::vector<double> z;
    const auto n = static_cast<std::size_t>(std::ceil((length - leftEnd_mm) / step_mm));
    for (std::size_t i = 0; i <= n; ++i)
        z.push_back(std::max(leftEnd_mm, length - static_cast<double>(i) * step_mm));
    // The profile just inside each sample, so an end face or a shoulder at a sample counts as the
    // diameter the tool turns there, not as the face.
    const SectionAlongZ section(part);
    std::vector<double> contour;
    contour.reserve(z.size());
    for (const double zi : z)
        contour.push_back(section.at(std::clamp(zi, leftEnd_mm + 1e-6, length - 1e-6)).outerRadius_mm);

    std::vector<const CuttingPass *> roughing;
    const CuttingPass *finishing = nullptr;
    std::vector<int> roughingIndex;
    int finishingIndex = -1;
    for (std::size_t i = 0; i < project.passes.size(); ++i) {
        if (project.passes[i].kind == PassKind::Roughing) {
            roughing.push_back(&project.passes[i]);
            roughingIndex.push_back(static_cast<int>(i));
        } else {
            finishing = &project.passes[i];
            finishingIndex = static_cast<int>(i);
        }
    }
    // A plan without a finishing pass is programmed with its last pass along the contour, the passes
    // before it leaving it its depth (gcode.cpp, turningProgram): so it is taken here.
    if (!finishing && !roughing.empty()) {
        finishing = roughing.back();
        finishingIndex = roughingIndex.back();
        roughing.pop_back();
        roughingIndex.pop_back();
    }
    const double allowance = finishing ? finishing->depthOfCut_mm : 0.0;
    std::vector<double> surface(z.size(), 0.5 * part.stockDiameter_mm); // S_0
    std::vector<PassDepthProfile> out;
    const auto take = [&](const CuttingPass &pass, int index, const std::vector<double> &below) {
        PassDepthProfile p;
        p.passIndex = index;
        p.conditions = pass;
        p.z_mm = z;
        p.contourRadius_mm = contour;
        for (std::size_t i = 0; i < z.size(); ++i) {
            const double next = std::min(surface[i], below[i]);
            p.depth_mm.push_back(surface[i] - next);
            p.cutDiameter_mm.push_back(2.0 * next);
            surface[i] = next;
        }
        out.push_back(std::move(p));
    };
    double level = 0.5 * part.stockDiameter_mm;
    for (std::size_t k = 0; k < roughing.size(); ++k) {
        level -= roughing[k]->depthOfCut_mm; // l_k
        std::vector<double> below(z.size());
        for (std::size_t i = 0; i < z.size(); ++i)
            below[i] = std::max(level, contour[i] + allowance);
        take(*roughing[k], roughingIndex[k], below);
    }
    if (finishing) {
        take(*finishing, finishingIndex, contour);
        out.back().conditions.kind = PassKind::Finishing; // it cuts the finished surface: Ra, Rz hold
    }
    return out;
}

} // namespace tolturn
