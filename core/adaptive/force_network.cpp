// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/adaptive/force_network.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <utility>

namespace tolturn {

namespace {

using Hidden = Eigen::Matrix<double, kNetworkHidden, 1>;

// The ArcTangent activation of a layer, and its derivative d atan(z) / dz = 1 / (1 + z²).
template <int N>
Eigen::Matrix<double, N, 1> atanOf(const Eigen::Matrix<double, N, 1> &z)
{
    return z.array().atan().matrix();
}

template <int N>
Eigen::Matrix<double, N, 1> atanSlope(const Eigen::Matrix<double, N, 1> &z)
{
    return (1.0 + z.array().square()).inverse().matrix();
}

// Max–min normalisation (004 §2.3): every term mapped to [0, 1] by its range in the training data.
template <typename V>
std::pair<V, V> rangeOf(const std::vector<NetworkSample> &samples, V NetworkSample::*member)
{
    V lo = samples.front().*member;
    V hi = lo;
    for (const NetworkSample &s : samples) {
        lo = lo.cwiseMin(s.*member);
        hi = hi.cwiseMax(s.*member);
    }
    return {lo, hi - lo};
}

} // namespace

ForceNetwork::ForceNetwork(HiddenWeights w1, Eigen::Matrix<double, kNetworkHidden, 1> b1, OutputWeights w2,
                           NetworkOutput b2, NetworkInput inputMin, NetworkInput inputSpan, NetworkOutput outputMin,
                           NetworkOutput outputSpan)
    : m_w1(std::move(w1))
    , m_b1(std::move(b1))
    , m_w2(std::move(w2))
    , m_b2(std::move(b2))
    , m_inputMin(std::move(inputMin))
    , m_inputSpan(std::move(inputSpan))
    , m_outputMin(std::move(outputMin))
    , m_outputSpan(std::move(outputSpan))
{
}

NetworkInput ForceNetwork::normalisedInput(const NetworkInput &input) const
{
    NetworkInput x;
    for (int i = 0; i < kNetworkInputs; ++i)
        x(i) = m_inputSpan(i) > 0.0 ? (input(i) - m_inputMin(i)) / m_inputSpan(i) : 0.0;
    return x;
}

NetworkOutput ForceNetwork::normalisedOutput(const NetworkOutput &output) const
{
    NetworkOutput y;
    for (int i = 0; i < kNetworkOutputs; ++i)
        y(i) = m_outputSpan(i) > 0.0 ? (output(i) - m_outputMin(i)) / m_outputSpan(i) : 0.0;
    return y;
}

NetworkOutput ForceNetwork::operator()(const NetworkInput &input) const
{
    const Hidden z1 = m_w1 * normalisedInput(input) + m_b1;
    const NetworkOutput z2 = m_w2 * atanOf(z1) + m_b2;
    return m_outputMin + m_outputSpan.cwiseProduct(atanOf(z2));
}

double ForceNetwork::halfSquaredError(const NetworkSample &sample) const
{
    const Hidden z1 = m_w1 * normalisedInput(sample.input) + m_b1;
    const NetworkOutput z2 = m_w2 * atanOf(z1) + m_b2;
    return 0.5 * (atanOf(z2) - normalisedOutput(sample.output)).squaredNorm();
}

// Back-propagation: δ₂ = (ŷ − t̂) ∘ atan′(z₂), δ₁ = (W₂ᵀ δ₂) ∘ atan′(z₁); ∂E/∂W₂ = δ₂ hᵀ,
// ∂E/∂W₁ = δ₁ x̂ᵀ, ∂E/∂b = δ.
std::vector<double> ForceNetwork::gradient(const NetworkSample &sample) const
{
    const NetworkInput x = normalisedInput(sample.input);
    const Hidden z1 = m_w1 * x + m_b1;
    const Hidden h = atanOf(z1);
    const NetworkOutput z2 = m_w2 * h + m_b2;
    const NetworkOutput d2 = (atanOf(z2) - normalisedOutput(sample.output)).cwiseProduct(atanSlope(z2));
    const Hidden d1 = (m_w2.transpose() * d2).cwiseProduct(atanSlope(z1));
    const HiddenWeights gw1 = d1 * x.transpose();
    const OutputWeights gw2 = d2 * h.transpose();
    std::vector<double> g;
    g.reserve(static_cast<std::size_t>(gw1.size() + d1.size() + gw2.size() + d2.size()));
    g.insert(g.end(), gw1.data(), gw1.data() + gw1.size());
    g.insert(g.end(), d1.data(), d1.data() + d1.size());
    g.insert(g.end(), gw2.data(), gw2.data() + gw2.size());
    g.insert(g.end(), d2.data(), d2.data() + d2.size());
    return g;
}

std::vector<double> ForceNetwork::weights() const
{
    std::vector<double> w;
    w.insert(w.end(), m_w1.data(), m_w1.data() + m_w1.size());
    w.insert(w.end(), m_b1.data(), m_b1.data() + m_b1.size());
    w.insert(w.end(), m_w2.data(), m_w2.data() + m_w2.size());
    w.insert(w.end(), m_b2.data(), m_b2.data() + m_b2.size());
    return w;
}

void ForceNetwork::setWeights(const std::vector<double> &w)
{
    auto at = w.begin();
    const auto fill = [&](double *out, Eigen::Index n) {
        std::copy(at, at + n, out);
        at += n;
    };
    fill(m_w1.data(), m_w1.size());
    fill(m_b1.data(), m_b1.size());
    fill(m_w2.data(), m_w2.size());
    fill(m_b2.data(), m_b2.size());
}

ForceNetwork ForceNetwork::trained(const std::vector<NetworkSample> &samples, const NetworkTraining &how)
{
    ForceNetwork net;
    if (samples.empty())
        return net;
    std::tie(net.m_inputMin, net.m_inputSpan) = rangeOf(samples, &NetworkSample::input);
    std::tie(net.m_outputMin, net.m_outputSpan) = rangeOf(samples, &NetworkSample::output);
    std::mt19937 random(how.seed);
    std::uniform_real_distribution<double> initial(-0.5, 0.5);
    std::vector<double> w = net.weights();
    for (double &v : w)
        v = initial(random);
    net.setWeights(w);
    std::vector<double> velocity(w.size(), 0.0);
    std::vector<std::size_t> order(samples.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    for (int epoch = 0; epoch < how.epochs; ++epoch) {
        std::shuffle(order.begin(), order.end(), random);
        for (const std::size_t i : order) {
            const std::vector<double> g = net.gradient(samples[i]);
            for (std::size_t j = 0; j < w.size(); ++j) {
                velocity[j] = -how.learningRate * g[j] + how.momentum * velocity[j];
                w[j] += velocity[j];
            }
            net.setWeights(w);
        }
    }
    return net;
}

double ForceNetwork::rmsRelativeError(const std::vector<NetworkSample> &samples) const
{
    double sum = 0.0;
    for (const NetworkSample &s : samples) {
        const double norm = s.output.norm();
        if (norm > 0.0)
            sum += ((*this)(s.input) - s.output).squaredNorm() / (norm * norm);
    }
    return samples.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(samples.size()));
}

} // namespace tolturn
