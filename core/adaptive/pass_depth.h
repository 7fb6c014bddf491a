// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The radial depth of cut each pass of a plan meets along z, from the stock to the profile
// (docs/adaptive.md §3). The roughing levels are those the program cuts (toolpath.h): level k at
// l_k = R_stock − (a_1 + … + a_k), never below the finishing allowance a_f above the profile p(z).
// The surface a pass leaves is
//   S_0(z) = R_stock,  S_k(z) = min(S_{k−1}(z), max(l_k, p(z) + a_f)),
// so pass k takes a_k(z) = S_{k−1}(z) − S_k(z) and the finishing pass S_n(z) − p(z): where a
// shoulder rises into a level, the level cuts less; where a level stops short of the allowance,
// the finishing pass takes what is left. Only the outer contour; the cut up a flank counts as the
// radial depth at its z.

#include "core/project/project.h"

#include <vector>

namespace tolturn {

struct PassDepthProfile {
    int passIndex = 0; // in Project::passes
    CuttingPass conditions;
    std::vector<double> z_mm;             // from the right end towards the chuck, the direction of cut
    std::vector<double> depth_mm;         // radial depth of cut at z
    std::vector<double> cutDiameter_mm;   // the diameter the tool leaves at z (spindle speed at G96)
    std::vector<double> contourRadius_mm; // the finished profile at z

    [[nodiscard]] double depthAt(double z) const;
    [[nodiscard]] double cutDiameterAt(double z) const;
    // The first sample left of z with more than `air_mm` to cut; the left end when there is none.
    [[nodiscard]] double nextCut_mm(double z, double air_mm) const;
};

// One profile per pass of the project's plan (roughing passes in order, then the finishing pass; a
// plan without one has its last pass cut along the contour, as the program cuts it),
// sampled every `step_mm` from the right end face to `leftEnd_mm` (where the tool stops short of
// the jaws or the driver).
[[nodiscard]] std::vector<PassDepthProfile> passDepthProfiles(const Project &project, double leftEnd_mm,
                                                              double step_mm);

} // namespace tolturn
