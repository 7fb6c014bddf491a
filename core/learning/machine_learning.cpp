// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/learning/machine_learning.h"

#include "core/learning/learned_model_json.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonDocument>
#include <QJsonObject>

namespace tolturn {

namespace {

struct MachineLearningText {
    Q_DECLARE_TR_FUNCTIONS(MachineLearning)
};

} // namespace

MachineLearning learnMachine(const std::vector<MeasuredPart> &parts, const DataLibrary &data,
                             const RbfTrainingOptions &options, const LearningControl &control)
{
    MachineLearning run;
    run.parts = static_cast<int>(parts.size());
    const std::vector<ResidualSample> samples = residualSamples(parts, data, run.warnings);
    run.usablePoints = static_cast<int>(samples.size());
    QString error;
    run.learned = learnResidual(samples, options, &error);
    if (run.learned)
        run.validation = leaveOnePartOut(samples, options, &error, control);
    if (!run.ok()) {
        run.cancelled = control.cancelled && control.cancelled();
        run.learned.reset();
        run.error = run.cancelled
                        ? MachineLearningText::tr("cancelled")
                        : MachineLearningText::tr("%n stored part(s) with %1 usable point(s): %2", nullptr, run.parts)
                              .arg(run.usablePoints)
                              .arg(error);
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

} // namespace tolturn
