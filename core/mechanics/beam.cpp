// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/mechanics/beam.h"

#include "core/mechanics/beam_corrections.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <array>
#include <cmath>

namespace tolturn {

namespace {

// Gauss–Legendre nodes and weights on [-1, 1], 6 points (exact for polynomials of degree 11).
// Abramowitz & Stegun, Handbook of Mathematical Functions (1964), Table 25.4.
constexpr std::array<double, 6> kGaussNodes{-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                                            0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
constexpr std::array<double, 6> kGaussWeights{0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                                              0.4679139345726910, 0.3607615730481386, 0.1713244923791704};

} // namespace

Matrix2 elementFlexibility(const SectionAlongZ &section, const ElasticMaterial &material, double z0_mm, double z1_mm)
{
    const double h = z1_mm - z0_mm;
    const double E = material.youngsModulus_MPa;
    const double G = material.shearModulus_MPa();
    double fww = 0.0;
    double fwt = 0.0;
    double ftt = 0.0;
    for (std::size_t i = 0; i < kGaussNodes.size(); ++i) {
        const double s = 0.5 * h * (kGaussNodes[i] + 1.0);
        const double w = 0.5 * h * kGaussWeights[i];
        const RoundSection rs = section.at(z0_mm + s);
        const double invEI = 1.0 / (E * rs.secondMoment_mm4());
        const double ratio = rs.outerRadius_mm > 0.0 ? rs.innerRadius_mm / rs.outerRadius_mm : 0.0;
        const double invKGA = material.shearDeformation
                                  ? 1.0 / (cowperShearCoefficient(ratio, material.poissonRatio) * G * rs.area_mm2())
                                  : 0.0;
        fww += w * ((h - s) * (h - s) * invEI + invKGA);
        fwt += w * (h - s) * invEI;
        ftt += w * invEI;
    }
    Matrix2 f;
    f << fww, fwt, fwt, ftt;
    return f;
}

BeamElementStiffness elementStiffness(const Matrix2 &flexibility, double length_mm)
{
    Matrix2 gamma;
    gamma << 1.0, length_mm, 0.0, 1.0;
    BeamElementStiffness k;
    k.D = flexibility.inverse();
    k.A = gamma.transpose() * k.D * gamma;
    k.B = -gamma.transpose() * k.D;
    return k;
}

EndSupport EndSupport::translationSpring(double k_N_per_mm)
{
    EndSupport s;
    s.stiffness(0, 0) = k_N_per_mm;
    return s;
}

std::vector<BeamElementStiffness> buildElements(const SectionAlongZ &section, const ElasticMaterial &material,
                                                const std::vector<double> &nodes_mm, const BeamCorrections &corrections)
{
    std::vector<BeamElementStiffness> elements;
    elements.reserve(nodes_mm.size());
    for (std::size_t i = 0; i + 1 < nodes_mm.size(); ++i) {
        const double z0 = nodes_mm[i];
        const double z1 = nodes_mm[i + 1];
        Matrix2 f = elementFlexibility(section, material, z0, z1);
        if (corrections.any())
            f += correctionFlexibility(section, material, corrections, z0, z1);
        elements.push_back(elementStiffness(f, z1 - z0));
    }
    return elements;
}

std::vector<Vector2> solveBeam(const BeamModel &model, const std::vector<Vector2> &nodalLoads)
{
    const auto nodeCount = static_cast<Eigen::Index>(model.nodes_mm.size());
    const Eigen::Index n = 2 * nodeCount;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index e = 0; e + 1 < nodeCount; ++e) {
        const BeamElementStiffness &k = model.elements[static_cast<std::size_t>(e)];
        K.block<2, 2>(2 * e, 2 * e) += k.A;
        K.block<2, 2>(2 * e, 2 * e + 2) += k.B;
        K.block<2, 2>(2 * e + 2, 2 * e) += k.B.transpose();
        K.block<2, 2>(2 * e + 2, 2 * e + 2) += k.D;
    }
    K.block<2, 2>(0, 0) += model.left.stiffness;
    K.block<2, 2>(n - 2, n - 2) += model.right.stiffness;
    Eigen::VectorXd f(n);
    for (Eigen::Index i = 0; i < nodeCount; ++i)
        f.segment<2>(2 * i) = nodalLoads[static_cast<std::size_t>(i)];

    // Rigidly held degrees of freedom are removed from the system.
    std::vector<Eigen::Index> freeDofs;
    const std::array<bool, 4> fixedEnds{model.left.fixedDisplacement, model.left.fixedRotation,
                                        model.right.fixedDisplacement, model.right.fixedRotation};
    for (Eigen::Index d = 0; d < n; ++d) {
        const bool fixed = (d < 2 && fixedEnds[static_cast<std::size_t>(d)]) ||
                           (d >= n - 2 && fixedEnds[static_cast<std::size_t>(d - (n - 2) + 2)]);
        if (!fixed)
            freeDofs.push_back(d);
    }
    const auto m = static_cast<Eigen::Index>(freeDofs.size());
    Eigen::MatrixXd Kf(m, m);
    Eigen::VectorXd ff(m);
    for (Eigen::Index i = 0; i < m; ++i) {
        ff(i) = f(freeDofs[static_cast<std::size_t>(i)]);
        for (Eigen::Index j = 0; j < m; ++j)
            Kf(i, j) = K(freeDofs[static_cast<std::size_t>(i)], freeDofs[static_cast<std::size_t>(j)]);
    }
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(Kf);
    if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || ldlt.vectorD().minCoeff() <= 1e-12 * Kf.norm())
        return {};
    const Eigen::VectorXd uf = ldlt.solve(ff);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
    for (Eigen::Index i = 0; i < m; ++i)
        u(freeDofs[static_cast<std::size_t>(i)]) = uf(i);
    std::vector<Vector2> out(static_cast<std::size_t>(nodeCount));
    for (Eigen::Index i = 0; i < nodeCount; ++i)
        out[static_cast<std::size_t>(i)] = u.segment<2>(2 * i);
    return out;
}

} // namespace tolturn
