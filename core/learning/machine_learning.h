// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/data/data_library.h"
#include "core/learning/measured_residuals.h"
#include "core/measurements/measurement_store.h"
#include "core/tolerance/range_verdicts.h"

#include <QString>

#include <optional>
#include <vector>

namespace tolturn {

// One learning run of a machine (docs/learning.md): its stored parts against the physics, the
// residual learned from all of them, and how well parts left out are predicted. The command
// line's `learn` and the desktop program's Measurements dock both run this.
struct MachineLearning {
    std::optional<LearnedResidual> learned;    // with `validation`, or neither
    std::optional<CrossValidation> validation; // leave one part out
    int parts = 0;                             // stored parts of the machine
    int usablePoints = 0;                      // points compared with the physics
    int partsWithCurrentForces = 0;            // parts whose forces came from their motor currents
    Diagnostics warnings;                      // parts left out, and why
    QString error;                             // why nothing was learned; empty on success
    bool cancelled = false;

    [[nodiscard]] bool ok() const { return learned && validation; }
};

// With `forcesFromCurrents`, parts that carry drive readings learn from the forces estimated from
// their motor currents (residualSamples).
[[nodiscard]] MachineLearning learnMachine(const std::vector<MeasuredPart> &parts, const DataLibrary &data,
                                           const RbfTrainingOptions &options, const LearningControl &control = {},
                                           const CurrentForceModel *forcesFromCurrents = nullptr);

// Every stored part of a machine, with its snapshot and points; empty with `error` when the store
// refused.
[[nodiscard]] std::optional<std::vector<MeasuredPart>> storedPartsOf(const MeasurementStore &store,
                                                                     const QString &machineId, QString *error);

// The record that keeps a successful run in the store (its id given by the store).
[[nodiscard]] LearnedModelRecord learnedModelRecord(const QString &machineId, const MachineLearning &run);

// A learned model as the commands and the window use it: the stored record and the model read
// back from it.
struct LoadedModel {
    LearnedModelRecord record;
    LearnedResidual model;
    // For notes and headings: "haas-st-20, model 3, 30 parts".
    [[nodiscard]] QString provenance() const;

    // The uncertainty of a prediction with it: the RMS error on parts not learned from [mm].
    [[nodiscard]] double uncertainty_mm() const { return record.learnedRms_mm; }
};

// The newest model of `machineId` in the store. Empty with `error` empty when nothing has been
// learned of it yet; with `error` set when the store refused or the stored model is damaged.
[[nodiscard]] std::optional<LoadedModel> latestModelOf(const MeasurementStore &store, const QString &machineId,
                                                       QString *error);

// A measured part against the predictions, along z (the Measurements dock's plot): per turned
// feature of its snapshot the physics' radius error at each station and, with a model, physics +
// learned; and each measured point as a radius error (machined radius − programmed radius, mm).
struct PartComparison {
    struct Feature {
        QString featureId;
        std::vector<double> z_mm;
        std::vector<double> physics_mm;
        std::vector<double> learned_mm; // physics + learned; empty without a model
    };

    std::vector<Feature> features;
    std::vector<ResidualSample> measured; // measured_mm and physics_mm at each usable point
    Diagnostics warnings;
    QString error; // the snapshot cannot be computed
};

[[nodiscard]] PartComparison comparePart(const MeasuredPart &part, const DataLibrary &data,
                                         const LoadedModel *model = nullptr);

// The verdicts of `project` on physics + what was learned: one prediction, the machine's measured
// behaviour in place of its stiffness range (RangeVerdict::NoRange, as for a measured machine).
// `physics`, when given, receives the physics alone (for the curves that draw both).
[[nodiscard]] RangeEvaluation evaluateWithLearned(const Project &project, const DataLibrary &data,
                                                  const LoadedModel &model, DeviationResult *physics = nullptr);

// Why `model` cannot be added to the physics of `project`: it was learned against another
// characterisation of the machine, so its residual is that physics' and would be counted against
// this one (after a test-bar fit, say, the spindle would be counted twice). Empty when it can, or
// when the model predates the record of its physics.
[[nodiscard]] QString learnedPhysicsMismatch(const Project &project, const LoadedModel &model);

// One line on what the prediction rests on, for the banner above the verdicts and the report.
[[nodiscard]] QString learnedAssumptionText(const LoadedModel &model);

// Where what was learned predicted the parts it did not learn from (leave one part out) worse than
// the physics alone: a warning that it adds error, to be said wherever the model is learned, kept
// or used. Empty when it predicts them better or as well.
[[nodiscard]] QString learnedWorseThanPhysics(double physicsRms_mm, double learnedRms_mm);

} // namespace tolturn
