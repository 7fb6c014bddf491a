// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/gcode_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "app/cli/learn_command.h"
#include "core/deviation/deviation_model.h"
#include "core/planning/feed_schedule.h"
#include "core/planning/gcode.h"
#include "core/planning/planning_report.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTextStream>

namespace tolturn {

namespace {

struct GCodeCommand {
    Q_DECLARE_TR_FUNCTIONS(GCodeCommand)
};

// Each feature the compensated program corrects (or says something of), under the file's name as
// every other line; that nothing needed correcting is said too.
void printCompensation(const CompensationPlan &plan, const QString &file, QTextStream &err)
{
    bool said = false;
    for (const FeatureCompensation &f : plan.features) {
        if (f.action == CompensationAction::None && f.note.isEmpty())
            continue;
        const QString line =
            GCodeCommand::tr("compensation: %1 %2, residual %3 → %4 µm")
                .arg(f.featureId, compensationKeyword(f.action), QString::number(f.residualBefore_um, 'f', 3),
                     QString::number(f.residualAfter_um, 'f', 3));
        err << file << ": " << (f.note.isEmpty() ? line : line + QStringLiteral("; ") + f.note) << '\n';
        said = true;
    }
    if (!said)
        err << file << ": "
            << GCodeCommand::tr("compensation: no tolerance needs a correction; the moves are the nominal program's")
            << '\n';
}

void printSchedule(const FeedSchedule &schedule, const std::vector<PassSummary> &constant,
                   const std::vector<PassSummary> &scheduled, const QString &file, QTextStream &err)
{
    for (const ScheduledFeed &f : schedule.features)
        err << file << ": "
            << (f.held ? GCodeCommand::tr("feed schedule: %1 kept at the programmed %2 mm/rev: %3 is not held at any "
                                          "feed of the range (a case for compensation)")
                             .arg(f.featureId, QString::number(f.feed_mm_rev, 'f', 3), f.limitedBy)
                       : GCodeCommand::tr("feed schedule: %1 at %2 mm/rev (programmed %3), limited by %4")
                             .arg(f.featureId, QString::number(f.feed_mm_rev, 'f', 3),
                                  QString::number(schedule.programmedFeed_mm_rev, 'f', 3), f.limitedBy))
            << '\n';
    const double before = 60.0 * outerFinishingTime_min(constant);
    const double after = 60.0 * outerFinishingTime_min(scheduled);
    err << file << ": "
        << GCodeCommand::tr("feed schedule: finishing pass %1 s at the programmed feed, %2 s scheduled (%3 %)")
               .arg(QString::number(before, 'f', 1), QString::number(after, 'f', 1),
                    QString::number(before > 0.0 ? 100.0 * (after - before) / before : 0.0, 'f', 1))
        << '\n';
    const double roughingBefore = 60.0 * outerRoughingTime_min(constant);
    const double roughingAfter = 60.0 * outerRoughingTime_min(scheduled);
    err << file << ": "
        << GCodeCommand::tr("feed schedule: roughing passes %1 s at the programmed feed, %2 s scheduled (%3 %)")
               .arg(QString::number(roughingBefore, 'f', 1), QString::number(roughingAfter, 'f', 1),
                    QString::number(
                        roughingBefore > 0.0 ? 100.0 * (roughingAfter - roughingBefore) / roughingBefore : 0.0, 'f', 1))
        << '\n';
    for (const QString &note : schedule.notes)
        err << file << ": " << GCodeCommand::tr("note: %1").arg(note) << '\n';
}

} // namespace

QString gcodeSynopsis()
{
    return QStringLiteral(
        "gcode [--compensated] [--feed-schedule] [--learned [--store STORE]] [--dialect fanuc|sinumerik|linuxcnc] "
        "[--nose control|tip-path] [--operation NAME] -o FILE|- PROJECT");
}

QString gcodeSummary()
{
    return GCodeCommand::tr("The turning program: the planned roughing passes and the finishing pass of the outer "
                            "contour, nominal or compensated only where a tolerance needs it, for the machine's "
                            "control (Fanuc/Haas, Sinumerik or LinuxCNC).");
}

int runGCode(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption output({QStringLiteral("o"), QStringLiteral("output")},
                                    GCodeCommand::tr("File to write; - for standard output."), QStringLiteral("FILE"));
    const QCommandLineOption compensated(
        QStringLiteral("compensated"),
        GCodeCommand::tr("Correct the path where a tolerance needs it (offset or profile)."));
    const QCommandLineOption dialect(
        QStringLiteral("dialect"),
        GCodeCommand::tr("Control dialect: fanuc (also Haas), sinumerik or linuxcnc. Default: the machine's control."),
        QStringLiteral("DIALECT"));
    const QCommandLineOption nose(
        QStringLiteral("nose"),
        GCodeCommand::tr("Nose radius: 'control' programs the contour with G42, the bore "
                         "with G41 (the control compensates), 'tip-path' the path of the imaginary tool tip "
                         "computed by TolTurn. Default: control."),
        QStringLiteral("HANDLING"), QStringLiteral("control"));
    const QCommandLineOption learned(
        QStringLiteral("learned"),
        GCodeCommand::tr("Compensate with what was learned of the machine from its measured parts (learn --save)."));
    const QCommandLineOption store = measurementStoreOption();
    const QCommandLineOption feedSchedule(
        QStringLiteral("feed-schedule"),
        GCodeCommand::tr("Cut each feature of the finishing pass at its own feed: the largest in the plan's feed "
                         "range that holds its tolerances and the pass's limits. With --compensated, the features "
                         "no feed holds keep the programmed feed and are compensated at it."));
    parser.addOptions({output, compensated, dialect, nose, learned, store, feedSchedule, operationOption()});
    parser.addPositionalArgument(QStringLiteral("project"), GCodeCommand::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseCommand(parser, QStringLiteral("gcode"), gcodeSynopsis(), gcodeSummary(), args, out, err);
        stop >= 0)
        return stop;
    if (parser.positionalArguments().size() != 1 || !parser.isSet(output)) {
        err << programName() << " gcode: " << GCodeCommand::tr("give one project file and -o FILE") << '\n';
        return kExitUsage;
    }
    GCodeOptions options;
    if (parser.isSet(dialect)) {
        options.dialect = controlDialectFromKeyword(parser.value(dialect));
        if (!options.dialect) {
            err << programName() << " gcode: "
                << GCodeCommand::tr("--dialect: '%1' is not fanuc, sinumerik or linuxcnc").arg(parser.value(dialect))
                << '\n';
            return kExitUsage;
        }
    }
    const auto handling = noseHandlingFromKeyword(parser.value(nose));
    if (!handling) {
        err << programName()
            << " gcode: " << GCodeCommand::tr("--nose: '%1' is not control or tip-path").arg(parser.value(nose))
            << '\n';
        return kExitUsage;
    }
    options.nose = *handling;
    const QString file = parser.positionalArguments().constFirst();
    QString problem = overwritesInput(parser.value(output), file);
    if (problem.isEmpty() && parser.isSet(learned))
        problem = overwritesStore(parser.value(output), parser.value(store));
    if (!problem.isEmpty()) {
        err << programName() << " gcode: " << problem << '\n';
        return kExitUsage;
    }
    const std::optional<Project> whole = readProject(file, err);
    if (!whole)
        return kExitProblems;
    // One set-up at a time: the program and the report of the operation --operation names.
    const std::optional<Project> project = selectOperation(*whole, parser, QStringLiteral("gcode"), err);
    if (!project)
        return kExitUsage;
    DeviationResult deviation = computeDeviation(*project, DataLibrary::builtIn(), {});
    std::shared_ptr<const LoadedModel> model;
    if (parser.isSet(learned)) {
        std::optional<LoadedModel> loaded =
            loadLearnedModel(parser.value(store), *project, QStringLiteral("gcode"), err);
        if (!loaded)
            return kExitProblems;
        model = std::make_shared<const LoadedModel>(std::move(*loaded));
        deviation = withLearnedResidual(*project, std::move(deviation), model->model, model->provenance());
    }
    std::optional<FeedSchedule> schedule;
    if (parser.isSet(feedSchedule)) {
        schedule = scheduleProjectFinishingFeeds(*project, DataLibrary::builtIn(), model);
        for (const Diagnostic &d : schedule->diagnostics)
            err << file << ": " << d.toString() << '\n';
        if (!schedule->ok())
            return kExitProblems;
        options.finishingFeeds_mm_rev = schedule->feedByFeature();
        options.roughingFeedSchedule = true;
    }
    // A scheduled program is compensated from the scheduled pass's deviation: each feature's at
    // the feed it is cut at.
    const DeviationResult constantFeedDeviation = deviation;
    const FinishingOutput finishing = finishingOutputFor(
        *project, DataLibrary::builtIn(),
        schedule && parser.isSet(compensated) ? scheduledDeviation(*schedule, deviation) : std::move(deviation),
        options);
    for (const Diagnostic &d : finishing.deviation.diagnostics)
        err << file << ": " << d.toString() << '\n';
    if (!finishing.deviation.inputs)
        return kExitProblems;
    if (parser.isSet(compensated)) {
        const QStringList beyond =
            correctionsBeyondTheCut(finishing.compensation, finishing.deviation.inputs->pass.depthOfCut_mm);
        for (const QString &line : beyond)
            err << file << ": error: " << line << '\n';
        if (!beyond.isEmpty())
            return kExitProblems;
    }
    const TurningProgram &program = parser.isSet(compensated) ? finishing.compensated : finishing.nominal;
    if (const QString unwritten = writeOutput(parser.value(output), program.text.toUtf8(), out); !unwritten.isEmpty()) {
        err << unwritten << '\n';
        return kExitProblems;
    }
    err << file << ": " << GCodeCommand::tr("dialect %1").arg(program.dialectReason) << '\n';
    err << file << ": "
        << GCodeCommand::tr("program %1, checksum %2 (SHA-256, first 16 digits)")
               .arg(programNumberWord(program.programNumber), program.checksum)
        << '\n';
    for (const QString &w : program.warnings())
        err << file << ": " << GCodeCommand::tr("warning: %1").arg(w) << '\n';
    if (parser.isSet(compensated))
        printCompensation(finishing.compensation, file, err);
    if (schedule) {
        GCodeOptions constant = options;
        constant.finishingFeeds_mm_rev.clear();
        constant.roughingFeedSchedule = false;
        const FinishingOutput plain =
            finishingOutputFor(*project, DataLibrary::builtIn(), constantFeedDeviation, constant);
        printSchedule(*schedule, (parser.isSet(compensated) ? plain.compensated : plain.nominal).passes, program.passes,
                      file, err);
    }
    return kExitOk;
}

} // namespace tolturn
