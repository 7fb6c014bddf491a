// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/mechanics/beam.h"

#include <vector>

namespace tolturn {

// A beam whose section depends on where the tool is: left of the tool (towards the chuck, the
// feed direction) the material of the pass is still there, right of it the surface is finished.
struct MovingLoadBeam {
    std::vector<double> nodes_mm;
    std::vector<BeamElementStiffness> uncut;    // elements[i] between nodes i, i+1, before the pass
    std::vector<BeamElementStiffness> finished; // the same elements after the pass
    EndSupport left;
    EndSupport right;
};

// True when the two end supports restrain both rigid-body motions of a beam of that length
// (translation and rotation): otherwise the part is not held.
[[nodiscard]] bool supportsHoldBeam(const EndSupport &left, const EndSupport &right, double length_mm);

// Influence of a load at one node on the beam, per unit force (column 0) and unit moment
// (column 1) at that node: rows are displacement w and rotation theta.
struct NodeInfluence {
    Matrix2 atLoad = Matrix2::Zero();       // of the loaded node itself
    Matrix2 leftSupport = Matrix2::Zero();  // of the left end node (chuck face or left centre)
    Matrix2 rightSupport = Matrix2::Zero(); // of the right end node (tailstock or right centre)
    bool supported = false;                 // false: the supports leave the beam free to move
};

// The influence of a load at every node, with the section on each side of the load as it is
// while the tool is there. O(N): the stiffness of everything left of node j is condensed onto
// node j by one sweep from the left over the uncut elements (L_j), everything right of it by one
// sweep from the right over the finished elements (R_j); the flexibility at j is (L_j + R_j)^-1.
// The end-node displacements follow from the same sweeps' transfer matrices. With uncut equal to
// finished this is the diagonal of the ordinary flexibility matrix.
[[nodiscard]] std::vector<NodeInfluence> movingLoadInfluence(const MovingLoadBeam &beam);

} // namespace tolturn
