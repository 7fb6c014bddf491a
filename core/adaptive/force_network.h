// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The cutting-force network of Čuš & Župerl (seed 004 §2.3, Fig. 3; [20]): a feed-forward network
// of eight inputs (feed rate, spindle speed, radial and axial depth of cut, material type,
// hardness, tool diameter, tool geometry), one hidden layer of fifteen neurons and three outputs
// (the force components), ArcTangent activation in the hidden and output layers, every input and
// output mapped to [0, 1] by its minimum and maximum in the training data, trained by
// back-propagation with a learning rate and a momentum. docs/adaptive.md §9.

#include <Eigen/Core>

#include <vector>

namespace tolturn {

constexpr int kNetworkInputs = 8;
constexpr int kNetworkHidden = 15;
constexpr int kNetworkOutputs = 3;

using NetworkInput = Eigen::Matrix<double, kNetworkInputs, 1>;
using NetworkOutput = Eigen::Matrix<double, kNetworkOutputs, 1>;

struct NetworkSample {
    NetworkInput input;
    NetworkOutput output;
};

struct NetworkTraining {
    // 004 §2.3: learning rates of 0.03–0.1 train fastest to low errors; momentum rates of
    // 0.008–0.01 give the least error.
    double learningRate = 0.05;
    double momentum = 0.008;
    int epochs = 2000;
    unsigned seed = 1; // the initial weights and the order of the samples in each epoch
};

class ForceNetwork {
public:
    using HiddenWeights = Eigen::Matrix<double, kNetworkHidden, kNetworkInputs>;
    using OutputWeights = Eigen::Matrix<double, kNetworkOutputs, kNetworkHidden>;

    // Trains a network on the samples (online back-propagation of the squared error of the
    // normalised outputs, the samples in a new random order each epoch).
    [[nodiscard]] static ForceNetwork trained(const std::vector<NetworkSample> &samples, const NetworkTraining &how);

    // The force components at an input, in the training data's units.
    [[nodiscard]] NetworkOutput operator()(const NetworkInput &input) const;

    // The root mean square of the error over the samples relative to each sample's output norm.
    [[nodiscard]] double rmsRelativeError(const std::vector<NetworkSample> &samples) const;

    // For tests: a network with given weights and normalisation.
    ForceNetwork(HiddenWeights w1, Eigen::Matrix<double, kNetworkHidden, 1> b1, OutputWeights w2, NetworkOutput b2,
                 NetworkInput inputMin, NetworkInput inputSpan, NetworkOutput outputMin, NetworkOutput outputSpan);

    // The gradient of half the squared error of the normalised output at one sample, for every
    // weight in the order w1, b1, w2, b2 (column-major), and the same set by a flat vector.
    [[nodiscard]] std::vector<double> gradient(const NetworkSample &sample) const;
    [[nodiscard]] double halfSquaredError(const NetworkSample &sample) const;
    [[nodiscard]] std::vector<double> weights() const;
    void setWeights(const std::vector<double> &w);

private:
    ForceNetwork() = default;

    [[nodiscard]] NetworkInput normalisedInput(const NetworkInput &input) const;
    [[nodiscard]] NetworkOutput normalisedOutput(const NetworkOutput &output) const;

    HiddenWeights m_w1 = HiddenWeights::Zero();
    Eigen::Matrix<double, kNetworkHidden, 1> m_b1 = Eigen::Matrix<double, kNetworkHidden, 1>::Zero();
    OutputWeights m_w2 = OutputWeights::Zero();
    NetworkOutput m_b2 = NetworkOutput::Zero();
    NetworkInput m_inputMin = NetworkInput::Zero();
    NetworkInput m_inputSpan = NetworkInput::Ones(); // 0 for an input that does not change: it reads 0
    NetworkOutput m_outputMin = NetworkOutput::Zero();
    NetworkOutput m_outputSpan = NetworkOutput::Ones();
};

} // namespace tolturn
