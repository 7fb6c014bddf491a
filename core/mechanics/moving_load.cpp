// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/mechanics/moving_load.h"

#include <Eigen/LU>

#include <cmath>

namespace tolturn {

namespace {

// Inverse of a 2x2 stiffness restricted to its free degrees of freedom (zero rows and columns
// for the held ones). Whether the beam is held at all is decided beforehand by
// supportsHoldBeam(), so a singular matrix here cannot arise from the supports.
Matrix2 restrictedInverse(const Matrix2 &k, bool fixed0, bool fixed1)
{
    Matrix2 inv = Matrix2::Zero();
    if (fixed0 && fixed1)
        return inv;
    if (fixed0 || fixed1) {
        const int i = fixed0 ? 1 : 0;
        inv(i, i) = 1.0 / k(i, i);
        return inv;
    }
    return k.inverse();
}

// Rows of the rigid-body motion (w0, theta0) of the beam that a support restrains: a held or
// sprung displacement restrains w at its node, a held or sprung rotation restrains theta.
void addRestraints(const EndSupport &s, double arm_mm, std::vector<Eigen::RowVector2d> &rows)
{
    if (s.fixedDisplacement || s.stiffness(0, 0) > 0.0)
        rows.emplace_back(1.0, arm_mm);
    if (s.fixedRotation || s.stiffness(1, 1) > 0.0)
        rows.emplace_back(0.0, 1.0);
}

} // namespace

bool supportsHoldBeam(const EndSupport &left, const EndSupport &right, double length_mm)
{
    std::vector<Eigen::RowVector2d> rows;
    addRestraints(left, 0.0, rows);
    addRestraints(right, length_mm, rows);
    Eigen::MatrixXd m(static_cast<Eigen::Index>(rows.size()), 2);
    for (std::size_t i = 0; i < rows.size(); ++i)
        m.row(static_cast<Eigen::Index>(i)) = rows[i];
    return rows.size() >= 2 && Eigen::FullPivLU<Eigen::MatrixXd>(m).rank() == 2;
}

std::vector<NodeInfluence> movingLoadInfluence(const MovingLoadBeam &beam)
{
    const std::size_t n = beam.nodes_mm.size();
    std::vector<NodeInfluence> out(n);
    if (n < 2)
        return out;
    const std::size_t last = n - 1;
    if (!supportsHoldBeam(beam.left, beam.right, beam.nodes_mm[last] - beam.nodes_mm[0]))
        return out; // every node unsupported

    // Sweep from the left over the uncut elements: L[i] is the stiffness of everything left of
    // node i condensed onto it; X[i] maps the displacement of node i+1 to that of node i.
    std::vector<Matrix2> left(n);
    std::vector<Matrix2> toLeft(last);
    left[0] = beam.left.stiffness;
    for (std::size_t i = 0; i < last; ++i) {
        const BeamElementStiffness &e = beam.uncut[i];
        const bool first = i == 0;
        const Matrix2 inv =
            restrictedInverse(left[i] + e.A, first && beam.left.fixedDisplacement, first && beam.left.fixedRotation);
        toLeft[i] = -inv * e.B;
        left[i + 1] = e.D + e.B.transpose() * toLeft[i];
    }

    // Sweep from the right over the finished elements: R[i] likewise, Y[i] maps node i to i+1.
    std::vector<Matrix2> right(n);
    std::vector<Matrix2> toRight(last);
    right[last] = beam.right.stiffness;
    for (std::size_t i = last; i-- > 0;) {
        const BeamElementStiffness &e = beam.finished[i];
        const bool end = i + 1 == last;
        const Matrix2 inv =
            restrictedInverse(right[i + 1] + e.D, end && beam.right.fixedDisplacement, end && beam.right.fixedRotation);
        toRight[i] = -inv * e.B.transpose();
        right[i] = e.A + e.B * toRight[i];
    }

    // Flexibility at each node, and the end-node motions through the transfer products.
    Matrix2 transferLeft = Matrix2::Identity(); // u_0 = transferLeft * u_j
    for (std::size_t j = 0; j < n; ++j) {
        if (j > 0)
            transferLeft = transferLeft * toLeft[j - 1];
        const bool atLeft = j == 0;
        const bool atRight = j == last;
        const Matrix2 g = restrictedInverse(
            left[j] + right[j], (atLeft && beam.left.fixedDisplacement) || (atRight && beam.right.fixedDisplacement),
            (atLeft && beam.left.fixedRotation) || (atRight && beam.right.fixedRotation));
        out[j].atLoad = g;
        out[j].leftSupport = transferLeft * g;
        out[j].supported = true;
    }
    Matrix2 transferRight = Matrix2::Identity(); // u_N = transferRight * u_j
    for (std::size_t j = n; j-- > 0;) {
        if (j < last)
            transferRight = transferRight * toRight[j];
        out[j].rightSupport = transferRight * out[j].atLoad;
    }
    return out;
}

} // namespace tolturn
