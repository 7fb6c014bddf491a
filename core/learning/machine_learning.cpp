// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/learning/machine_learning.h"

#include "core/io/project_json.h"
#include "core/learning/learned_model_json.h"
#include "core/project/operations.h"
#include "core/tolerance/evaluation.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace tolturn {

namespace {

struct MachineLearningText {
    Q_DECLARE_TR_FUNCTIONS(MachineLearning)
};

} // namespace

namespace {

// The parts computed against the physics the newest of them was (physicsBasis): a residual is
// what the physics missed, so parts against another characterisation of the machine (before a
// test-bar fit, say) would mix two physics in one model. The others are left out, each said.
std::vector<MeasuredPart> partsOfOnePhysics(const std::vector<MeasuredPart> &parts, QJsonObject &basis,
                                            Diagnostics &warnings)
{
    std::vector<std::pair<const MeasuredPart *, QJsonObject>> read;
    for (const MeasuredPart &part : parts) {
        const ProjectParseResult r = parseProjectJson(part.projectJson);
        read.emplace_back(&part, r.project ? physicsBasis(*r.project) : QJsonObject());
    }
    const auto newest = std::max_element(read.begin(), read.end(), [](const auto &a, const auto &b) {
        return std::tie(a.first->measuredAt, a.first->id) < std::tie(b.first->measuredAt, b.first->id);
    });
    std::vector<MeasuredPart> kept;
    if (newest == read.end())
        return kept;
    basis = newest->second;
    for (const auto &[part, partBasis] : read) {
        // The same part stored twice (the same snapshot, time and points) is one part: as two, its
        // twin would count as a part not learned from in the leave-one-part-out figures.
        const auto twin = std::find_if(kept.begin(), kept.end(), [part = part](const MeasuredPart &k) {
            return k.projectJson == part->projectJson && k.measuredAt == part->measuredAt && k.points == part->points;
        });
        if (twin != kept.end()) {
            warnings.push_back(makeWarning(QStringLiteral("parts[%1]").arg(part->id),
                                           MachineLearningText::tr("part %1 is left out: it is part %2 stored again "
                                                                   "(the same project, time and points)")
                                               .arg(part->id)
                                               .arg(twin->id)));
            continue;
        }
        if (partBasis == basis) {
            kept.push_back(*part);
            continue;
        }
        warnings.push_back(makeWarning(QStringLiteral("parts[%1]").arg(part->id),
                                       MachineLearningText::tr("part %1 is left out: its project was computed against "
                                                               "another characterisation of the machine than the "
                                                               "newest part %2, and a model learns what one physics "
                                                               "misses")
                                           .arg(part->id)
                                           .arg(newest->first->id)));
    }
    return kept;
}

// The geometric plane a·φ + b·z + c is determined only where the points spread in both the
// diameter and z independently: points on one diameter, at one z, or along a line where the two
// move together (a cone) leave the split between the terms to the solver, and the plane then
// extrapolates along the undetermined direction off the measured line.
void warnWhereThePlaneIsUndetermined(const std::vector<ResidualSample> &samples, Diagnostics &warnings)
{
    if (samples.size() < 3)
        return;
    double meanD = 0.0, meanZ = 0.0;
    for (const ResidualSample &s : samples) {
        meanD += s.diameter_mm;
        meanZ += s.z_mm;
    }
    meanD /= static_cast<double>(samples.size());
    meanZ /= static_cast<double>(samples.size());
    double dd = 0.0, zz = 0.0, dz = 0.0;
    for (const ResidualSample &s : samples) {
        dd += (s.diameter_mm - meanD) * (s.diameter_mm - meanD);
        zz += (s.z_mm - meanZ) * (s.z_mm - meanZ);
        dz += (s.diameter_mm - meanD) * (s.z_mm - meanZ);
    }
    constexpr double kNoSpread_mm2 = 1e-12;
    constexpr double kCollinear = 0.99; // |correlation| of diameter and z
    QString why;
    if (dd < kNoSpread_mm2 || zz < kNoSpread_mm2)
        why =
            MachineLearningText::tr("the measured points lie on one %1")
                .arg(dd < kNoSpread_mm2 ? MachineLearningText::tr("diameter") : MachineLearningText::tr("position z"));
    else if (std::abs(dz) / std::sqrt(dd * zz) > kCollinear)
        why = MachineLearningText::tr("the measured points' diameters and positions z move together (correlation %1)")
                  .arg(dz / std::sqrt(dd * zz), 0, 'f', 3);
    if (!why.isEmpty())
        warnings.push_back(makeWarning(
            QStringLiteral("points"),
            MachineLearningText::tr("%1: the geometric error's split between diameter and z is not determined, and "
                                    "what was learned holds along the measured points only; measure features of other "
                                    "diameters at other z")
                .arg(why)));
}

} // namespace

MachineLearning learnMachine(const std::vector<MeasuredPart> &allParts, const DataLibrary &data,
                             const RbfTrainingOptions &options, const LearningControl &control,
                             const CurrentForceModel *forcesFromCurrents)
{
    MachineLearning run;
    run.parts = static_cast<int>(allParts.size());
    QJsonObject basis;
    const std::vector<MeasuredPart> parts = partsOfOnePhysics(allParts, basis, run.warnings);
    const std::vector<ResidualSample> samples =
        residualSamples(parts, data, run.warnings, forcesFromCurrents, &run.partsWithCurrentForces);
    run.usablePoints = static_cast<int>(samples.size());
    warnWhereThePlaneIsUndetermined(samples, run.warnings);
    QString error;
    run.learned = learnResidual(samples, options, &error);
    if (run.learned) {
        run.learned->learnedAgainst = basis;
        run.validation = leaveOnePartOut(samples, options, &error, control);
    }
    if (!run.ok()) {
        run.cancelled = control.cancelled && control.cancelled();
        run.learned.reset();
        run.error = run.cancelled
                        ? MachineLearningText::tr("cancelled")
                        : MachineLearningText::tr("%1 with %2: %3")
                              .arg(MachineLearningText::tr("%n stored part(s)", nullptr, run.parts),
                                   MachineLearningText::tr("%n usable point(s)", nullptr, run.usablePoints), error);
    }
    return run;
}

std::optional<std::vector<MeasuredPart>> storedPartsOf(const MeasurementStore &store, const QString &machineId,
                                                       QString *error)
{
    PartFilter filter;
    filter.machineId = machineId;
    const auto list = store.list(filter, error);
    if (!list)
        return std::nullopt;
    std::vector<qint64> ids;
    ids.reserve(list->size());
    for (const MeasuredPartSummary &s : *list)
        ids.push_back(s.id);
    return store.parts(ids, error);
}

LearnedModelRecord learnedModelRecord(const QString &machineId, const MachineLearning &run)
{
    LearnedModelRecord record;
    record.machineId = machineId;
    record.trainedAt = QDateTime::currentDateTimeUtc();
    if (run.ok()) {
        record.parts = run.validation->parts;
        record.points = run.validation->points;
        record.physicsRms_mm = run.validation->physicsRms_mm;
        record.learnedRms_mm = run.validation->learnedRms_mm;
        record.modelJson = QJsonDocument(learnedResidualJson(*run.learned)).toJson(QJsonDocument::Compact);
    }
    return record;
}

QString LoadedModel::provenance() const
{
    return MachineLearningText::tr("%1, model %2, %3 parts").arg(record.machineId).arg(record.id).arg(record.parts);
}

std::optional<LoadedModel> latestModelOf(const MeasurementStore &store, const QString &machineId, QString *error)
{
    if (error)
        error->clear();
    const auto record = store.latestLearnedModel(machineId, error);
    if (!record)
        return std::nullopt;
    QString why;
    const auto model = learnedResidualFromJson(QJsonDocument::fromJson(record->modelJson).object(), &why);
    if (!model) {
        if (error)
            *error =
                MachineLearningText::tr("the model %1 of %2 is damaged: %3").arg(record->id).arg(machineId).arg(why);
        return std::nullopt;
    }
    return LoadedModel{*record, *model};
}

PartComparison comparePart(const MeasuredPart &part, const DataLibrary &data, const LoadedModel *model)
{
    PartComparison out;
    out.measured = residualSamples({part}, data, out.warnings);
    const ProjectParseResult read = parseProjectJson(part.projectJson);
    if (!read.project) {
        out.error = MachineLearningText::tr("the project snapshot of part %1 does not read").arg(part.id);
        return out;
    }
    // Each set-up as its predictions have it, drawn in the drawing's frame (z from its left end).
    const Project &drawn = *read.project;
    // A model of another physics than this part's is not added to it (learnedPhysicsMismatch).
    if (model) {
        if (const QString mismatch = learnedPhysicsMismatch(drawn, *model); !mismatch.isEmpty()) {
            out.warnings.push_back(makeWarning(QStringLiteral("model"), mismatch));
            model = nullptr;
        }
    }
    const double length = drawn.part.length_mm();
    for (int op = 0; op < operationCount(drawn); ++op) {
        const Project view = operationView(drawn, op);
        const bool mirrored = view.clamping.heldEnd == PartEnd::Right;
        const DeviationResult physics = computeDeviation(view, data, {});
        if (!physics.inputs) {
            out.error =
                MachineLearningText::tr("the physics model cannot compute the snapshot of part %1").arg(part.id);
            return out;
        }
        const std::vector<std::vector<double>> learned =
            model ? learnedAtStations(view, physics, model->model) : std::vector<std::vector<double>>{};
        for (std::size_t f = 0; f < physics.features.size(); ++f) {
            PartComparison::Feature feature{physics.features[f].featureId, {}, {}, {}};
            const std::vector<Station> &stations = physics.features[f].stations;
            for (std::size_t i = 0; i < stations.size(); ++i) {
                feature.z_mm.push_back(mirrored ? length - stations[i].z_mm : stations[i].z_mm);
                feature.physics_mm.push_back(stations[i].radiusError_mm);
                if (f < learned.size() && i < learned[f].size())
                    feature.learned_mm.push_back(stations[i].radiusError_mm + learned[f][i]);
            }
            out.features.push_back(std::move(feature));
        }
        if (mirrored) {
            for (ResidualSample &s : out.measured) {
                if (operationOf(drawn, s.featureId) == op)
                    s.z_mm = length - s.z_mm;
            }
        }
    }
    return out;
}

RangeEvaluation evaluateWithLearned(const Project &project, const DataLibrary &data, const LoadedModel &model,
                                    DeviationResult *physics)
{
    RangeEvaluation r;
    DeviationResult alone = computeDeviation(project, data, {});
    if (physics)
        *physics = alone;
    r.compliant = withLearnedResidual(project, std::move(alone), model.model, model.provenance());
    if (!r.compliant.inputs)
        return r;
    for (ToleranceEvaluation &e : evaluateTolerances(project, r.compliant)) {
        ToleranceRangeEvaluation t;
        t.compliant = std::move(e);
        r.tolerances.push_back(std::move(t));
    }
    // The thermal drift is in what was learned (Li & Du's thermal inputs), measured, not taken as zero.
    r.thermalTakenAsZero = false;
    return r;
}

QString learnedPhysicsMismatch(const Project &project, const LoadedModel &model)
{
    if (!model.model.learnedAgainst || *model.model.learnedAgainst == physicsBasis(project))
        return {};
    return MachineLearningText::tr("%1 was learned against another characterisation of %2 than this project's (its "
                                   "springs, supports or thermal drift differ): what it learned is what that physics "
                                   "missed, not this one. Learn again from parts cut with this characterisation, or "
                                   "predict without it")
        .arg(model.provenance(), model.record.machineId);
}

QString learnedAssumptionText(const LoadedModel &model)
{
    const QString worse = learnedWorseThanPhysics(model.record.physicsRms_mm, model.record.learnedRms_mm);
    return MachineLearningText::tr("as learned from its measured parts (%1, learned %2 UTC): parts not learned "
                                   "from were predicted to %3 µm RMS, the physics alone to %4 µm; its stiffness "
                                   "range is not used")
               .arg(model.provenance(), model.record.trainedAt.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm")),
                    QString::number(1000.0 * model.record.learnedRms_mm, 'f', 1),
                    QString::number(1000.0 * model.record.physicsRms_mm, 'f', 1)) +
           (worse.isEmpty() ? QString() : QStringLiteral(". ") + worse);
}

QString learnedWorseThanPhysics(double physicsRms_mm, double learnedRms_mm)
{
    // Compared as printed, to 0.1 µm: a difference below that is no difference to a planner.
    if (std::round(1e4 * learnedRms_mm) <= std::round(1e4 * physicsRms_mm))
        return {};
    return MachineLearningText::tr("What was learned predicts parts it did not learn from worse than the physics "
                                   "alone (%1 against %2 µm RMS): it adds error here. Learn from more parts, or "
                                   "predict without it")
        .arg(QString::number(1000.0 * learnedRms_mm, 'f', 1), QString::number(1000.0 * physicsRms_mm, 'f', 1));
}

} // namespace tolturn
