// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/mechanics/section.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace tolturn {

using Matrix2 = Eigen::Matrix2d;
using Vector2 = Eigen::Vector2d;

// Stiffness of a two-node Timoshenko beam element in bending, degrees of freedom (w, theta) at
// each node: K = [[A, B], [B^T, D]]. Built from the exact flexibility of the element as a
// cantilever (Castigliano, with bending and shear energy; cf. Valiño et al. 2008 eq. 6):
//   f_ww = int (h-s)^2/EI ds + int 1/(kappa G A) ds,  f_wt = int (h-s)/EI ds,  f_tt = int 1/EI ds
// D = F^-1, A = Gamma^T D Gamma, B = -Gamma^T D with Gamma = [[1, h], [0, 1]] (rigid transfer).
// Under end loads the internal forces of an element are exact (V constant, M linear), so the
// nodal displacements are exact for any variation of the section; only the quadrature of the
// integrals approximates (Gauss–Legendre on each element, which never spans a profile vertex).
struct BeamElementStiffness {
    Matrix2 A;
    Matrix2 B;
    Matrix2 D;
};

[[nodiscard]] Matrix2 elementFlexibility(const SectionAlongZ &section, const ElasticMaterial &material, double z0_mm,
                                         double z1_mm);
[[nodiscard]] BeamElementStiffness elementStiffness(const Matrix2 &flexibility, double length_mm);

// How one end of the beam is held: a 2x2 spring matrix on (w, theta) [N/mm, N, N·mm/rad], and
// which of the two are held rigidly (then their spring entries are ignored).
struct EndSupport {
    Matrix2 stiffness = Matrix2::Zero();
    bool fixedDisplacement = false;
    bool fixedRotation = false;

    static EndSupport free() { return {}; }

    static EndSupport clamped() { return {Matrix2::Zero(), true, true}; }

    static EndSupport pinned() { return {Matrix2::Zero(), true, false}; }

    static EndSupport springs(const Matrix2 &k) { return {k, false, false}; }

    static EndSupport translationSpring(double k_N_per_mm);
};

// A beam along z: nodes, elements between consecutive nodes, supports at the two end nodes.
struct BeamModel {
    std::vector<double> nodes_mm;
    std::vector<BeamElementStiffness> elements; // elements[i] joins nodes i and i+1
    EndSupport left;
    EndSupport right;
};

// Corrections of the Timoshenko beam for what plane sections cannot see: the part is not built in
// at the chuck face but a little inside the jaws, and a shoulder lets the thin section turn more
// than the beam says (beam_corrections.h, docs/solid-fe.md "Corrections").
struct BeamCorrections {
    std::optional<double> builtInAt_mm; // the chuck's or collet's face: the root correction there
    bool shoulders = false;             // a hinge at every step of the outer diameter

    [[nodiscard]] bool any() const { return builtInAt_mm.has_value() || shoulders; }
};

// Builds the elements of a beam over `section` with the given nodes (sorted, unique), with the
// corrections of the root and the shoulders (beam_corrections.h) where asked.
[[nodiscard]] std::vector<BeamElementStiffness> buildElements(const SectionAlongZ &section,
                                                              const ElasticMaterial &material,
                                                              const std::vector<double> &nodes_mm,
                                                              const BeamCorrections &corrections = {});

// Static solution of a beam under nodal loads (force and moment at each node): displacements
// (w, theta) at every node. Dense LDLT: for checks and full deflection lines, not for sweeps.
// Returns an empty vector when the supports leave the beam free to move (singular stiffness).
[[nodiscard]] std::vector<Vector2> solveBeam(const BeamModel &model, const std::vector<Vector2> &nodalLoads);

} // namespace tolturn
