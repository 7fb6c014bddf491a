// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/data/data_library.h"
#include "core/deviation/deviation_model.h"
#include "core/learning/current_forces.h"
#include "core/learning/hybrid_rbf.h"
#include "core/measurements/measured_part.h"
#include "core/tolerance/target_contour.h"

#include <Eigen/Dense>
#include <QJsonObject>

#include <functional>
#include <optional>
#include <vector>

namespace tolturn {

// One measured point against TolTurn's physics (docs/learning.md): what the part came out as and
// what the model predicted for it, both as the machined radius less the programmed one (mm, as
// radiusError_mm: on a bore, material left is negative), and
// the inputs Li & Du give their networks (003 §3.2–3.3).
struct ResidualSample {
    qint64 partId = 0;
    QString featureId;
    bool inner = false;
    double z_mm = 0.0;
    double diameter_mm = 0.0; // the programmed diameter there
    double measured_mm = 0.0; // measured radius − programmed radius
    double physics_mm = 0.0;  // predicted radius error (computeDeviation)
    // Li & Du's inputs: spindle speed [rpm], feed [mm/rev], time since start [min], ambient [°C]
    // (thermal, §3.2); spindle torque T = F_t·D/2 [N·m], axial and radial force [N], z [mm]
    // (force-induced, §3.3; the paper writes T = F_t D, a factor the input scaling removes).
    Eigen::Matrix<double, 8, 1> inputs = Eigen::Matrix<double, 8, 1>::Zero();
    // The same with the force model's forces: what a prediction has (a part being planned has no
    // motor currents), so parts left out are predicted as every prediction is. Equal to `inputs`
    // unless the forces came from the motor currents.
    Eigen::Matrix<double, 8, 1> predictionInputs = Eigen::Matrix<double, 8, 1>::Zero();

    [[nodiscard]] double residual_mm() const { return measured_mm - physics_mm; }
};

// The samples of the stored parts: each part's snapshot through the physics model at its
// finishing pass, each point against the program's target at its z. A part whose snapshot cannot
// be computed is left out with a warning naming it. With `forcesFromCurrents`, a part that carries
// its drives' readings has its forces (the network's torque, axial and radial force) estimated
// from its motor currents (Li & Du eq. 7–19) instead of the force model's; where the estimate
// fails, the force model's, with a warning.
[[nodiscard]] std::vector<ResidualSample> residualSamples(const std::vector<MeasuredPart> &parts,
                                                          const DataLibrary &data, Diagnostics &warnings,
                                                          const CurrentForceModel *forcesFromCurrents = nullptr,
                                                          int *partsWithCurrentForces = nullptr);

// The geometric error as a plane in the diameter and z: δ_G = a·φ + b·z + c. Li & Du's eq. 4 is
// the line in φ (the X axis's linear error); the term in z is the taper that a Z axis not parallel
// to the spindle leaves (ISO 230-1, parallelism of the Z motion to the spindle axis).
struct GeometricError {
    double perDiameter = 0.0; // a [mm/mm]
    double perZ = 0.0;        // b [mm/mm]: the taper
    double offset_mm = 0.0;   // c

    [[nodiscard]] double at(double diameter_mm, double z_mm) const
    {
        return perDiameter * diameter_mm + perZ * z_mm + offset_mm;
    }
};

// The conditions the parts a model was learned from were cut and measured at, each as the smallest
// and largest value among its points. Outside them what was learned is extrapolated: the network's
// Gaussians fade away from them, and a condition the parts did not vary is taken to have no effect.
struct LearnedDomain {
    struct Span {
        double min = 0.0;
        double max = 0.0;
        friend bool operator==(const Span &, const Span &) = default;
    };

    Span spindleSpeed_rpm;
    Span feed_mm_rev;
    Span passiveForce_N; // the network's radial force input: the depth of cut shows in it
    Span timeSinceStart_min;
    Span ambient_C;
    Span diameter_mm;
    Span z_mm;
    friend bool operator==(const LearnedDomain &, const LearnedDomain &) = default;
};

// The spans in words, for the command line and the Measurements dock: "spindle speed 955–3183
// rpm, feed 0.100–0.300 mm/rev, passive force 40–95 N, 0–240 min since start, ambient 18.0–26.0
// °C, diameter 30.0–50.0 mm, z 40.0–146.0 mm".
[[nodiscard]] QString learnedDomainText(const LearnedDomain &domain);

// What was learned of a machine: the residual of the physics model = geometric error + an RBF
// network of the rest over Li & Du's inputs.
struct LearnedResidual {
    GeometricError geometric;
    std::optional<RbfNetwork> network; // absent when too few samples remain for one
    // The physics it is a residual of: the machine's characterisation (physicsBasis) of the parts
    // it was learned from. Absent in a model stored before TolTurn kept it.
    std::optional<QJsonObject> learnedAgainst;
    // Where it was learned. Absent in a model stored before TolTurn kept it.
    std::optional<LearnedDomain> learnedFrom;
    [[nodiscard]] double predict_mm(const ResidualSample &s) const;
};

// What the physics of a project rests on besides the part and the cut: its machine's
// characterisation (springs, supports, thermal drift) as in the project file, without its source
// text. Two projects with the same basis have the same machine in the physics model.
[[nodiscard]] QJsonObject physicsBasis(const Project &project);

[[nodiscard]] std::optional<LearnedResidual> learnResidual(const std::vector<ResidualSample> &samples,
                                                           const RbfTrainingOptions &options, QString *error);

// How well the physics alone and the physics with the learned residual predict parts not used to
// learn (leave one part out, as the issue asks): RMS over every point of every part, in mm.
struct CrossValidation {
    int parts = 0;
    int points = 0;
    double physicsRms_mm = 0.0;
    double learnedRms_mm = 0.0;
};

// Progress and cancel of a long learning run (one step per part left out); both may be empty.
struct LearningControl {
    std::function<bool()> cancelled;
    std::function<void(int done, int total)> progress;
};

// Empty with `error` when a fold cannot be learned, and when `control` cancelled (between folds).
[[nodiscard]] std::optional<CrossValidation> leaveOnePartOut(const std::vector<ResidualSample> &samples,
                                                             const RbfTrainingOptions &options, QString *error,
                                                             const LearningControl &control = {});

// What was learned at every station of a deviation result of `project` (its features in order,
// their stations in order), in mm of radius: the learned correction to each predicted radius error.
[[nodiscard]] std::vector<std::vector<double>>
learnedAtStations(const Project &project, const DeviationResult &deviation, const LearnedResidual &learned);
[[nodiscard]] std::vector<std::vector<double>> learnedAtStations(const Project &project,
                                                                 const DeviationResult &deviation,
                                                                 const LearnedResidual &learned,
                                                                 const ProgramTargets &targets);

// Adds what was learned to every station's radius error, without a note (the optimiser, for each
// candidate, with the program's targets computed once).
void addLearnedResidual(const Project &project, DeviationResult &deviation, const LearnedResidual &learned,
                        const ProgramTargets &targets);

// Where the stations of the toleranced features of a deviation result of `project` are cut at other
// conditions than `learned` was learned at (spindle speed, feed, passive force, time since start
// and ambient temperature; beyond each span by more than a tenth of it, or 1 % of its value where
// it is narrower): one line naming each with the plan's and the measured parts' span, without a
// closing full stop; empty when none is or the model does not record them.
[[nodiscard]] QString outsideLearnedDomain(const Project &project, const DeviationResult &deviation,
                                           const LearnedResidual &learned);

// The deviation result with what was learned added to every station's radius error (the
// predicted machined radius then being physics + learned), and a note saying so, naming
// `provenance` ("haas-st-20, model 3, 30 parts"); a warning with the field "learned" where the plan
// lies outside what was learned (outsideLearnedDomain). Faces keep the physics' conicity.
[[nodiscard]] DeviationResult withLearnedResidual(const Project &project, DeviationResult deviation,
                                                  const LearnedResidual &learned, const QString &provenance);

} // namespace tolturn
