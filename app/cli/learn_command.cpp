// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/learn_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "core/data/data_library.h"
#include "core/learning/learned_model_json.h"
#include "core/learning/machine_learning.h"
#include "core/measurements/measurement_store.h"

#include <QCommandLineParser>
#include <QCoreApplication>
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

// The first stage of Li & Du's network from calibration cuts, with its figures on `err`; empty
// after naming the problem.
std::optional<CurrentForceModel> currentForceEstimator(const QString &path, const QString &prefix, QTextStream &err)
{
    Diagnostics problems;
    const auto cuts = readForceCalibration(path, problems);
    for (const Diagnostic &d : problems)
        err << d.toString() << '\n';
    if (!cuts)
        return std::nullopt;
    QString error;
    auto model = trainCurrentForceModel(*cuts, currentForceTrainingOptions(), &error);
    if (!model) {
        err << prefix << path << ": " << error << '\n';
        return std::nullopt;
    }
    err << LearnCommand::tr("forces from motor currents: %1 calibration cuts; leaving one out, F_t to %2 N RMS, F_a "
                            "to %3 N RMS")
               .arg(cuts->size())
               .arg(QString::number(model->tangential.leaveOneOutRms, 'f', 1),
                    QString::number(model->axial.leaveOneOutRms, 'f', 1))
        << '\n';
    return model;
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
    const QCommandLineOption calibration(
        QStringLiteral("force-calibration"),
        LearnCommand::tr("Cuts with motor currents and dynamometer forces (CSV): parts that carry their drives' "
                         "readings then learn from forces estimated from their motor currents (Li & Du eq. 7–19)."),
        QStringLiteral("FILE.csv"));
    parser.addOptions({machine, store, criterion, json, save, calibration});
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
    const QString machineId = parser.value(machine);
    const auto parts = storedPartsOf(*history, machineId, &error);
    if (!parts) {
        err << prefix << error << '\n';
        return kExitProblems;
    }
    RbfTrainingOptions options;
    options.criterion = name == QLatin1String("bic") ? RbfCriterion::Bic : RbfCriterion::Gcv;
    std::optional<CurrentForceModel> currents;
    if (parser.isSet(calibration)) {
        currents = currentForceEstimator(parser.value(calibration), prefix, err);
        if (!currents)
            return kExitProblems;
    }
    const MachineLearning run =
        learnMachine(*parts, DataLibrary::builtIn(), options, {}, currents ? &*currents : nullptr);
    for (const Diagnostic &d : run.warnings)
        err << d.toString() << '\n';
    if (!run.ok()) {
        err << prefix << LearnCommand::tr("%1 has %2").arg(machineId, run.error) << '\n';
        return kExitProblems;
    }
    // Said whether it is kept or not, and before it is: a model that adds error is kept only knowingly.
    if (const QString worse = learnedWorseThanPhysics(run.validation->physicsRms_mm, run.validation->learnedRms_mm);
        !worse.isEmpty())
        err << prefix << LearnCommand::tr("warning: %1").arg(worse) << '\n';
    if (parser.isSet(save)) {
        const auto id = history->addLearnedModel(learnedModelRecord(machineId, run), &error);
        if (!id) {
            err << prefix << error << '\n';
            return kExitProblems;
        }
        err << LearnCommand::tr("kept as the model of %1 (number %2) in %3")
                   .arg(machineId)
                   .arg(*id)
                   .arg(history->location().describe())
            << '\n';
    }
    if (currents)
        err << LearnCommand::tr("%1 of %2 parts learned from forces estimated from their motor currents")
                   .arg(run.partsWithCurrentForces)
                   .arg(run.parts)
            << '\n';
    const std::optional<LearnedResidual> &learned = run.learned;
    const std::optional<CrossValidation> &cv = run.validation;
    const GeometricError &g = learned->geometric;
    if (parser.isSet(json))
        return printJson(QJsonObject{{QStringLiteral("machine"), machineId},
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
                                     {QStringLiteral("learned_from"), learnedDomainJson(*learned->learnedFrom)},
                                     {QStringLiteral("cross_validation"),
                                      QJsonObject{{QStringLiteral("physics_rms_um"), 1000.0 * cv->physicsRms_mm},
                                                  {QStringLiteral("learned_rms_um"), 1000.0 * cv->learnedRms_mm}}}},
                         out, err, QStringLiteral("learn"));
    out << LearnCommand::tr("%1: %2 parts, %3 measured points").arg(machineId).arg(cv->parts).arg(cv->points) << '\n'
        << LearnCommand::tr("  learned at: %1").arg(learnedDomainText(*learned->learnedFrom)) << '\n'
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

std::optional<LoadedModel> loadLearnedModel(const QString &store, const Project &project, const QString &command,
                                            QTextStream &err)
{
    const QString &machineId = project.machineId;
    const QString prefix = programName() + QLatin1Char(' ') + command + QStringLiteral(": ");
    const auto history = openMeasurementStore(store, prefix, err);
    if (!history)
        return std::nullopt;
    QString error;
    auto model = latestModelOf(*history, machineId, &error);
    if (!model)
        err << prefix
            << (error.isEmpty()
                    ? LearnCommand::tr("nothing has been learned of %1 yet: run 'learn --machine %1 --save'")
                          .arg(machineId)
                    : error)
            << '\n';
    if (model) {
        if (const QString mismatch = learnedPhysicsMismatch(project, *model); !mismatch.isEmpty()) {
            err << prefix << mismatch << '\n';
            return std::nullopt;
        }
    }
    return model;
}

} // namespace tolturn
