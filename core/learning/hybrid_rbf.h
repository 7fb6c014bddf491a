// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <Eigen/Dense>
#include <QString>

#include <optional>
#include <vector>

namespace tolturn {

// Model selection criterion of the elimination (Orr, "Introduction to Radial Basis Function
// Networks", 1996, §5.2; Li & Du 003, appendix A): generalised cross-validation or the Bayesian
// information criterion, both from the sum of squared residuals and the number of weights.
enum class RbfCriterion { Gcv, Bic };

struct RbfTrainingOptions {
    // The regression tree's depth control (Orr 2000, p_min): a node with fewer samples than twice
    // this is not split. 0: chosen from the data, p / 64 and at least 3, so that the tree has at
    // most about 128 nodes whatever the number of samples.
    int minSamplesPerLeaf = 0;
    // Orr's α: a node's Gaussian radius is α times its hyper-rectangle's half-width; each is
    // tried and the best network by the criterion kept.
    std::vector<double> radiusScales{1.0, 2.0, 4.0};
    RbfCriterion criterion = RbfCriterion::Gcv;
};

// A trained hybrid RBF network (Li & Du 003, appendix A): f(x) = Σ w_j h_j(x) (eq. A.2) with
// h_j(x) = exp(−Σ_k (x_k − c_jk)² / r_jk²) (eq. A.1), inputs scaled to [0, 1] by the training
// range of each (so that one radius scale fits inputs of different units).
struct RbfNetwork {
    Eigen::VectorXd inputMin, inputSpan; // the scaling: (x − min) / span
    Eigen::MatrixXd centres;             // m × n, in scaled inputs
    Eigen::MatrixXd radii;               // m × n, in scaled inputs
    Eigen::VectorXd weights;             // m
    double radiusScale = 0.0;            // the α chosen
    int treeNodes = 0;                   // candidates before the elimination
    double criterion = 0.0;              // GCV or BIC of the network kept
    double trainingRms = 0.0;            // RMS of the residuals on the training samples
    double leaveOneOutRms = 0.0;         // RMS of the leave-one-out residuals e_i / (1 − h_ii)

    [[nodiscard]] int nodes() const { return static_cast<int>(weights.size()); }

    [[nodiscard]] double predict(const Eigen::VectorXd &x) const;
};

// Trains the network on p samples (rows of `inputs`, p × n) with targets `targets` (Orr 2000,
// after Kubat 1998): a least-squares regression tree over the samples; each node's hyper-rectangle
// becomes a Gaussian (centre: its middle; radius: α times its half-width); backward elimination of
// the nodes that hold the fewest samples, one at a time, the weights by least squares
// (w = (HᵀH)⁻¹ Hᵀ y) at each step, keeping the subset with the lowest criterion. Empty, with
// `error` set, when there are fewer than 3 samples, a non-finite value, or inputs and targets of
// different lengths.
[[nodiscard]] std::optional<RbfNetwork> trainHybridRbf(const Eigen::MatrixXd &inputs, const Eigen::VectorXd &targets,
                                                       const RbfTrainingOptions &options, QString *error);

// A straight line y = slope·x + intercept by least squares (Li & Du 003, eq. 4: the geometric
// error against the diameter), with the RMS of its residuals.
struct LineFit {
    double slope = 0.0;
    double intercept = 0.0;
    double residualRms = 0.0;
};

// Empty when there are fewer than 2 points or all x are equal.
[[nodiscard]] std::optional<LineFit> fitLine(const std::vector<double> &x, const std::vector<double> &y);

} // namespace tolturn
