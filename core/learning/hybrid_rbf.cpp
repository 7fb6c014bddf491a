// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/learning/hybrid_rbf.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace tolturn {

namespace {

struct HybridRbf {
    Q_DECLARE_TR_FUNCTIONS(HybridRbf)
};

// The half-width given along an input that did not vary in training (scaled units): Gaussians
// flat along it.
constexpr double kFlatRadius = 1e6;

// A node of the regression tree: its hyper-rectangle (in scaled inputs) and how many samples it
// holds.
struct TreeNode {
    Eigen::VectorXd lower, upper;
    int samples = 0;
};

double sumOfSquares(const std::vector<int> &rows, const Eigen::VectorXd &y)
{
    double mean = 0.0;
    for (const int i : rows)
        mean += y[i];
    mean /= static_cast<double>(rows.size());
    double s = 0.0;
    for (const int i : rows)
        s += (y[i] - mean) * (y[i] - mean);
    return s;
}

struct Split {
    int dimension = -1;
    double at = 0.0;
    double cost = std::numeric_limits<double>::infinity();
};

// The least-squares split of `rows` (CART, Breiman et al. 1984): for every input, every threshold
// between two successive values; both sides keep at least `minLeaf` samples.
Split bestSplit(const std::vector<int> &rows, const Eigen::MatrixXd &x, const Eigen::VectorXd &y, int minLeaf)
{
    Split best;
    const auto n = static_cast<int>(rows.size());
    std::vector<int> order(rows);
    for (Eigen::Index d = 0; d < x.cols(); ++d) {
        std::sort(order.begin(), order.end(), [&](int a, int b) { return x(a, d) < x(b, d); });
        // Running sums: the cost of a side is Σy² − (Σy)²/k.
        double leftSum = 0.0, leftSquares = 0.0;
        double totalSum = 0.0, totalSquares = 0.0;
        for (const int i : order) {
            totalSum += y[i];
            totalSquares += y[i] * y[i];
        }
        for (int k = 1; k < n; ++k) {
            const int i = order[static_cast<std::size_t>(k - 1)];
            leftSum += y[i];
            leftSquares += y[i] * y[i];
            const double here = x(i, d);
            const double next = x(order[static_cast<std::size_t>(k)], d);
            if (k < minLeaf || n - k < minLeaf || next <= here)
                continue;
            const double rightSum = totalSum - leftSum;
            const double cost =
                (leftSquares - leftSum * leftSum / k) + (totalSquares - leftSquares - rightSum * rightSum / (n - k));
            if (cost < best.cost) {
                // Halfway, unless the two values are neighbouring doubles and the middle rounds
                // to the lower one: then the upper one, so that `here` still goes left.
                const double middle = 0.5 * (here + next);
                best = {static_cast<int>(d), middle > here ? middle : next, cost};
            }
        }
    }
    return best;
}

// Every node of the tree over the scaled samples, root first.
std::vector<TreeNode> regressionTree(const Eigen::MatrixXd &x, const Eigen::VectorXd &y, int minLeaf)
{
    struct Pending {
        std::vector<int> rows;
        Eigen::VectorXd lower, upper;
    };

    std::vector<int> all(static_cast<std::size_t>(x.rows()));
    std::iota(all.begin(), all.end(), 0);
    std::vector<TreeNode> nodes;
    std::vector<Pending> stack{{all, Eigen::VectorXd::Zero(x.cols()), Eigen::VectorXd::Ones(x.cols())}};
    while (!stack.empty()) {
        Pending node = std::move(stack.back());
        stack.pop_back();
        nodes.push_back({node.lower, node.upper, static_cast<int>(node.rows.size())});
        if (static_cast<int>(node.rows.size()) < 2 * minLeaf || sumOfSquares(node.rows, y) <= 0.0)
            continue;
        const Split split = bestSplit(node.rows, x, y, minLeaf);
        if (split.dimension < 0)
            continue;
        Pending left{{}, node.lower, node.upper};
        Pending right{{}, node.lower, node.upper};
        left.upper[split.dimension] = split.at;
        right.lower[split.dimension] = split.at;
        for (const int i : node.rows)
            (x(i, split.dimension) < split.at ? left.rows : right.rows).push_back(i);
        if (left.rows.empty() || right.rows.empty())
            continue; // cannot happen with the threshold above; a leaf rather than the same node again
        stack.push_back(std::move(right));
        stack.push_back(std::move(left));
    }
    return nodes;
}

// The design matrix H (p × m), h_ij = exp(−Σ_k (x_ik − c_jk)² / r_jk²) (eq. A.1).
Eigen::MatrixXd design(const Eigen::MatrixXd &x, const Eigen::MatrixXd &centres, const Eigen::MatrixXd &radii)
{
    Eigen::MatrixXd h(x.rows(), centres.rows());
    for (Eigen::Index j = 0; j < centres.rows(); ++j) {
        for (Eigen::Index i = 0; i < x.rows(); ++i)
            h(i, j) = std::exp(-((x.row(i) - centres.row(j)).array() / radii.row(j).array()).square().sum());
    }
    return h;
}

// Orr 1996, §5.2, with γ = m weights of ordinary least squares.
double criterionOf(RbfCriterion c, double sse, int p, int m)
{
    const double pd = p, md = m;
    if (c == RbfCriterion::Gcv)
        return pd * sse / ((pd - md) * (pd - md));
    return (pd + (std::log(pd) - 1.0) * md) / (pd - md) * sse / pd;
}

// The weights of the columns `kept` of H from the normal equations, and their residual sum of
// squares (yᵀy − wᵀHᵀy at the least-squares solution). A relative ridge of 1e-10 on the diagonal
// keeps nearly equal Gaussians (a node and its only child) solvable.
struct Solved {
    Eigen::VectorXd weights;
    double sse = 0.0;
};

// The weights from the normal equations; the residual sum of squares ‖y − Hw‖² from H itself (the
// shortcut yᵀy − wᵀHᵀy cancels to nothing on a near-exact fit, which would then always win).
Solved solve(const Eigen::MatrixXd &h, const Eigen::VectorXd &y, const Eigen::MatrixXd &hth, const Eigen::VectorXd &hty,
             const std::vector<int> &kept)
{
    const auto m = static_cast<Eigen::Index>(kept.size());
    Eigen::MatrixXd a(m, m);
    Eigen::VectorXd b(m);
    for (Eigen::Index r = 0; r < m; ++r) {
        b[r] = hty[kept[static_cast<std::size_t>(r)]];
        for (Eigen::Index c = 0; c < m; ++c)
            a(r, c) = hth(kept[static_cast<std::size_t>(r)], kept[static_cast<std::size_t>(c)]);
    }
    a.diagonal().array() += 1e-10 * std::max(a.diagonal().maxCoeff(), 1e-300);
    Solved s;
    s.weights = a.ldlt().solve(b);
    Eigen::VectorXd residual = y;
    for (Eigen::Index c = 0; c < m; ++c)
        residual -= s.weights[c] * h.col(kept[static_cast<std::size_t>(c)]);
    s.sse = residual.squaredNorm();
    return s;
}

struct Candidate {
    std::vector<int> kept;
    Eigen::VectorXd weights;
    double criterion = std::numeric_limits<double>::infinity();
};

// Backward elimination (appendix A): the node with the fewest samples goes first (of two equal
// ones, the later in the tree's depth-first order), down to one node; the subset with the lowest
// criterion is kept.
Candidate eliminate(const Eigen::MatrixXd &h, const Eigen::VectorXd &y, const std::vector<TreeNode> &nodes,
                    RbfCriterion criterion)
{
    const Eigen::MatrixXd hth = h.transpose() * h;
    const Eigen::VectorXd hty = h.transpose() * y;
    const auto p = static_cast<int>(y.size());
    std::vector<int> order(nodes.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&nodes](int a, int b) {
        return nodes[static_cast<std::size_t>(a)].samples > nodes[static_cast<std::size_t>(b)].samples;
    });
    Candidate best;
    // order: most samples first; the subsets kept are its prefixes, from all nodes down to one.
    for (std::size_t m = std::min(order.size(), static_cast<std::size_t>(p - 1)); m >= 1; --m) {
        std::vector<int> kept(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(m));
        const Solved s = solve(h, y, hth, hty, kept);
        const double value = criterionOf(criterion, s.sse, p, static_cast<int>(m));
        if (value < best.criterion)
            best = {std::move(kept), s.weights, value};
    }
    return best;
}

bool allFinite(const Eigen::MatrixXd &m)
{
    return m.allFinite();
}

} // namespace

double RbfNetwork::predict(const Eigen::VectorXd &x) const
{
    const Eigen::VectorXd scaled = ((x - inputMin).array() / inputSpan.array()).matrix();
    double f = 0.0;
    for (Eigen::Index j = 0; j < centres.rows(); ++j)
        f += weights[j] *
             std::exp(-((scaled.transpose() - centres.row(j)).array() / radii.row(j).array()).square().sum());
    return f;
}

std::optional<RbfNetwork> trainHybridRbf(const Eigen::MatrixXd &inputs, const Eigen::VectorXd &targets,
                                         const RbfTrainingOptions &options, QString *error)
{
    const auto refuse = [error](const QString &why) -> std::optional<RbfNetwork> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    const auto p = static_cast<int>(inputs.rows());
    if (p != targets.size())
        return refuse(HybridRbf::tr("%1 input rows but %2 targets").arg(p).arg(targets.size()));
    if (p < 3)
        return refuse(HybridRbf::tr("%1 samples; the network needs at least 3").arg(p));
    if (!allFinite(inputs) || !targets.allFinite())
        return refuse(HybridRbf::tr("an input or a target is not a finite number"));
    RbfNetwork net;
    net.inputMin = inputs.colwise().minCoeff().transpose();
    // An input that did not vary in training says nothing: span 1 and, below, a radius that makes
    // the Gaussians flat along it, so that another value there later changes nothing.
    const Eigen::VectorXd range = inputs.colwise().maxCoeff().transpose() - net.inputMin;
    const Eigen::Array<bool, Eigen::Dynamic, 1> constant = (range.array() <= 0.0);
    net.inputSpan = constant.select(Eigen::VectorXd::Ones(range.size()), range);
    const Eigen::MatrixXd x =
        (inputs.rowwise() - net.inputMin.transpose()).array().rowwise() / net.inputSpan.transpose().array();
    const int minLeaf = options.minSamplesPerLeaf > 0 ? options.minSamplesPerLeaf : std::max(3, p / 64);
    const std::vector<TreeNode> nodes = regressionTree(x, targets, minLeaf);
    net.treeNodes = static_cast<int>(nodes.size());
    Eigen::MatrixXd centres(static_cast<Eigen::Index>(nodes.size()), x.cols());
    Eigen::MatrixXd halfWidths(static_cast<Eigen::Index>(nodes.size()), x.cols());
    for (std::size_t j = 0; j < nodes.size(); ++j) {
        centres.row(static_cast<Eigen::Index>(j)) = 0.5 * (nodes[j].lower + nodes[j].upper).transpose();
        // A side of zero width gets a small radius, not zero; an input that never varied, one
        // so large (in the scaled inputs' units) that the Gaussians do not depend on it.
        const Eigen::VectorXd half = (0.5 * (nodes[j].upper - nodes[j].lower)).cwiseMax(1e-3);
        halfWidths.row(static_cast<Eigen::Index>(j)) =
            constant.select(Eigen::VectorXd::Constant(half.size(), kFlatRadius), half).transpose();
    }
    Candidate best;
    for (const double alpha : options.radiusScales) {
        const Eigen::MatrixXd radii = alpha * halfWidths;
        Candidate c = eliminate(design(x, centres, radii), targets, nodes, options.criterion);
        if (c.criterion < best.criterion) {
            best = std::move(c);
            net.radiusScale = alpha;
        }
    }
    if (best.kept.empty())
        return refuse(HybridRbf::tr("no network could be fitted to the samples"));
    const auto m = static_cast<Eigen::Index>(best.kept.size());
    net.centres.resize(m, x.cols());
    net.radii.resize(m, x.cols());
    for (Eigen::Index j = 0; j < m; ++j) {
        net.centres.row(j) = centres.row(best.kept[static_cast<std::size_t>(j)]);
        net.radii.row(j) = net.radiusScale * halfWidths.row(best.kept[static_cast<std::size_t>(j)]);
    }
    net.weights = best.weights;
    net.criterion = best.criterion;
    // Residuals, and the leave-one-out ones from the hat matrix's diagonal (Orr 1996, §5.2).
    const Eigen::MatrixXd h = design(x, net.centres, net.radii);
    const Eigen::VectorXd residual = targets - h * net.weights;
    const Eigen::MatrixXd gram =
        h.transpose() * h + 1e-10 * std::max(h.squaredNorm() / double(m), 1e-300) * Eigen::MatrixXd::Identity(m, m);
    const Eigen::MatrixXd hg = h * gram.ldlt().solve(Eigen::MatrixXd::Identity(m, m));
    double loo = 0.0;
    for (Eigen::Index i = 0; i < h.rows(); ++i) {
        const double leverage = std::min(hg.row(i).dot(h.row(i)), 1.0 - 1e-9);
        const double e = residual[i] / (1.0 - leverage);
        loo += e * e;
    }
    net.trainingRms = std::sqrt(residual.squaredNorm() / p);
    net.leaveOneOutRms = std::sqrt(loo / p);
    return net;
}

std::optional<LineFit> fitLine(const std::vector<double> &x, const std::vector<double> &y)
{
    const std::size_t n = std::min(x.size(), y.size());
    if (n < 2)
        return std::nullopt;
    const double mx = std::accumulate(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n), 0.0) / double(n);
    const double my = std::accumulate(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(n), 0.0) / double(n);
    double sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        sxx += (x[i] - mx) * (x[i] - mx);
        sxy += (x[i] - mx) * (y[i] - my);
    }
    if (sxx <= 0.0)
        return std::nullopt;
    LineFit fit;
    fit.slope = sxy / sxx;
    fit.intercept = my - fit.slope * mx;
    double ss = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double r = y[i] - (fit.slope * x[i] + fit.intercept);
        ss += r * r;
    }
    fit.residualRms = std::sqrt(ss / double(n));
    return fit;
}

} // namespace tolturn
