// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/learn_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "core/data/data_library.h"
#include "core/learning/learned_model_json.h"
#include "core/learning/measured_residuals.h"
#include "core/measurements/measurement_store.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDateTime>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

namespace tolturn {

namespace {

struct LearnCommand {
    Q_DECLARE_TR_FUNCTIONS(LearnCommand)
};

QString um(double mm)
{
    return QString::number(1000.0 * mm, 'f', 2);
}

} // namespace

int runLearn(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption machine(QStringLiteral("machine"), LearnCommand::tr("The machine to learn."),
                                     QStringLiteral("ID"));
    const QCommandLineOption store(
        QStringLiteral("store"),
        LearnCommand::tr(
            "The store: an SQLite file, or postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE (default: %1).")
            .arg(defaultStoreLocation().describe()),
        QStringLiteral("STORE"));
    const QCommandLineOption criterion(QStringLiteral("criterion"),
                                       LearnCommand::tr("gcv (default) or bic: when the network stops growing."),
                                       QStringLiteral("NAME"), QStringLiteral("gcv"));
    const QCommandLineOption json(QStringLiteral("json"), LearnCommand::tr("Print the result as JSON."));
    const QCommandLineOption save(
        QStringLiteral("save"),
        LearnCommand::tr("Keep what was learned in the store as the machine's model, for the commands' --learned."));
    parser.addOptions({machine, store, criterion, json, save});
    if (const int stop = parseNamedCommand(parser, QStringLiteral("learn"), args, out, err); stop >= 0)
        return stop;
    const QString prefix = programName() + QStringLiteral(" learn: ");
    const QString name = parser.value(criterion);
    if (!parser.isSet(machine) || (name != QLatin1String("gcv") && name != QLatin1String("bic"))) {
        err << prefix << LearnCommand::tr("give --machine ID, and --criterion gcv or bic") << '\n';
        return kExitUsage;
    }
    const auto history = openMeasurementStore(parser.value(store), prefix, err);
    if (!history)
        return kExitProblems;
    QString error;
    PartFilter filter;
    filter.machineId = parser.value(machine);
    const auto list = history->list(filter, &error);
    if (!list) {
        err << prefix << error << '\n';
        return kExitProblems;
    }
    std::vector<qint64> ids;
    for (const MeasuredPartSummary &s : *list)
        ids.push_back(s.id);
    const auto stored = history->parts(ids, &error);
    if (!stored) {
        err << prefix << error << '\n';
        return kExitProblems;
    }
    const std::vector<MeasuredPart> &parts = *stored;
    Diagnostics warnings;
    const std::vector<ResidualSample> samples = residualSamples(parts, DataLibrary::builtIn(), warnings);
    for (const Diagnostic &d : warnings)
        err << d.toString() << '\n';
    RbfTrainingOptions options;
    options.criterion = name == QLatin1String("bic") ? RbfCriterion::Bic : RbfCriterion::Gcv;
    const auto learned = learnResidual(samples, options, &error);
    const auto cv = learned ? leaveOnePartOut(samples, options, &error) : std::nullopt;
    if (!learned || !cv) {
        err << prefix
            << LearnCommand::tr("%1 has %2 stored part(s) with %3 usable point(s): %4")
                   .arg(filter.machineId)
                   .arg(parts.size())
                   .arg(samples.size())
                   .arg(error)
            << '\n';
        return kExitProblems;
    }
    if (parser.isSet(save)) {
        const LearnedModelRecord record{0,
                                        filter.machineId,
                                        QDateTime::currentDateTimeUtc(),
                                        cv->parts,
                                        cv->points,
                                        cv->physicsRms_mm,
                                        cv->learnedRms_mm,
                                        QJsonDocument(learnedResidualJson(*learned)).toJson(QJsonDocument::Compact)};
        const auto id = history->addLearnedModel(record, &error);
        if (!id) {
            err << prefix << error << '\n';
            return kExitProblems;
        }
        err << LearnCommand::tr("kept as the model of %1 (number %2) in %3")
                   .arg(filter.machineId)
                   .arg(*id)
                   .arg(history->location().describe())
            << '\n';
    }
    const GeometricError &g = learned->geometric;
    if (parser.isSet(json))
        return printJson(QJsonObject{{QStringLiteral("machine"), filter.machineId},
                                     {QStringLiteral("parts"), cv->parts},
                                     {QStringLiteral("points"), cv->points},
                                     {QStringLiteral("geometric"),
                                      QJsonObject{{QStringLiteral("per_diameter_um_per_mm"), 1000.0 * g.perDiameter},
                                                  {QStringLiteral("per_z_um_per_mm"), 1000.0 * g.perZ},
                                                  {QStringLiteral("offset_um"), 1000.0 * g.offset_mm}}},
                                     {QStringLiteral("network"),
                                      QJsonObject{{QStringLiteral("nodes"), learned->network->nodes()},
                                                  {QStringLiteral("tree_nodes"), learned->network->treeNodes},
                                                  {QStringLiteral("radius_scale"), learned->network->radiusScale},
                                                  {QStringLiteral("leave_one_out_rms_um"),
                                                   1000.0 * learned->network->leaveOneOutRms}}},
                                     {QStringLiteral("cross_validation"),
                                      QJsonObject{{QStringLiteral("physics_rms_um"), 1000.0 * cv->physicsRms_mm},
                                                  {QStringLiteral("learned_rms_um"), 1000.0 * cv->learnedRms_mm}}}},
                         out, err, QStringLiteral("learn"));
    out << LearnCommand::tr("%1: %2 parts, %3 measured points").arg(filter.machineId).arg(cv->parts).arg(cv->points)
        << '\n'
        << LearnCommand::tr("  geometric error: %1 µm per mm of diameter, %2 µm per mm along z (taper), %3 µm offset")
               .arg(QString::number(1000.0 * g.perDiameter, 'g', 3), QString::number(1000.0 * g.perZ, 'g', 3),
                    QString::number(1000.0 * g.offset_mm, 'f', 2))
        << '\n'
        << LearnCommand::tr("  network: %1 of %2 nodes kept (radius scale %3), leave-one-out RMS %4 µm")
               .arg(learned->network->nodes())
               .arg(learned->network->treeNodes)
               .arg(learned->network->radiusScale)
               .arg(um(learned->network->leaveOneOutRms))
        << '\n'
        << LearnCommand::tr("  parts predicted without having been learned from (leave one part out): physics alone "
                            "%1 µm RMS, physics + learned %2 µm RMS")
               .arg(um(cv->physicsRms_mm), um(cv->learnedRms_mm))
        << '\n';
    return kExitOk;
}

QString LoadedModel::provenance() const
{
    return LearnCommand::tr("%1, model %2, %3 parts").arg(record.machineId).arg(record.id).arg(record.parts);
}

std::optional<LoadedModel> loadLearnedModel(const QString &store, const QString &machineId, const QString &command,
                                            QTextStream &err)
{
    const QString prefix = programName() + QLatin1Char(' ') + command + QStringLiteral(": ");
    const auto history = openMeasurementStore(store, prefix, err);
    if (!history)
        return std::nullopt;
    QString error;
    const auto record = history->latestLearnedModel(machineId, &error);
    if (!record) {
        err << prefix
            << (error.isEmpty()
                    ? LearnCommand::tr("nothing has been learned of %1 yet: run 'learn --machine %1 --save'")
                          .arg(machineId)
                    : error)
            << '\n';
        return std::nullopt;
    }
    const auto model = learnedResidualFromJson(QJsonDocument::fromJson(record->modelJson).object(), &error);
    if (!model) {
        err << prefix << LearnCommand::tr("the model %1 of %2 is damaged: %3").arg(record->id).arg(machineId).arg(error)
            << '\n';
        return std::nullopt;
    }
    return LoadedModel{*record, *model};
}

} // namespace tolturn
