// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of learning (issue 15), results recorded in docs/benchmarks.md: the hybrid RBF network
// trained on 10 000 measured points with the eight inputs of Li & Du (speed, feed, time since
// start, ambient; torque, axial and radial force, z), and one prediction.
// Run: build/<preset>/benchmarks/bench_learning
#include "benchmarks/bench_timing.h"

#include "core/learning/hybrid_rbf.h"

#include <cmath>
#include <cstdio>
#include <random>

using namespace tolturn;
using tolturn::bench::medianMilliseconds;

int main()
{
    constexpr int kPoints = 10000;
    constexpr int kInputs = 8;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::normal_distribution<double> noise(0.0, 0.5);
    Eigen::MatrixXd x(kPoints, kInputs);
    Eigen::VectorXd y(kPoints);
    for (int i = 0; i < kPoints; ++i) {
        for (int k = 0; k < kInputs; ++k)
            x(i, k) = uniform(random);
        // A warm-up drift in the time since start and a force term growing with z, in µm.
        y[i] = 8.0 * (1.0 - std::exp(-3.0 * x(i, 2))) + 5.0 * x(i, 5) * x(i, 6) + noise(random);
    }
    std::optional<RbfNetwork> net;
    const double train = medianMilliseconds(5, [&] { net = trainHybridRbf(x, y, {}, nullptr); });
    if (!net)
        return 1;
    const Eigen::VectorXd probe = x.row(17).transpose();
    double sink = 0.0;
    const double predict = medianMilliseconds(1001, [&] { sink += net->predict(probe); });
    std::printf("training on %d points x %d inputs: %.0f ms (median of 5), %d of %d tree nodes kept, "
                "leave-one-out RMS %.3f um (noise 0.5 um)\n",
                kPoints, kInputs, train, net->nodes(), net->treeNodes, net->leaveOneOutRms);
    std::printf("one prediction: %.4f ms (median of 1001)%s\n", predict, sink == 12345.0 ? " " : "");
    return 0;
}
