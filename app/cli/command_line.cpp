// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/command_line.h"

#include "app/cli/check_command.h"
#include "app/cli/cli_common.h"
#include "app/cli/control_command.h"
#include "app/cli/control_example_command.h"
#include "app/cli/deflect_command.h"
#include "app/cli/evaluate_command.h"
#include "app/cli/forces_command.h"
#include "app/cli/gcode_command.h"
#include "app/cli/import_command.h"
#include "app/cli/iso286_command.h"
#include "app/cli/learn_command.h"
#include "app/cli/measurements_command.h"
#include "app/cli/milling_commands.h"
#include "app/cli/planning_commands.h"
#include "app/cli/report_command.h"
#include "app/cli/stiffness_command.h"
#include "app/cli/verify_fe_command.h"
#include "core/common/library_info.h"
#include "core/deviation/deviation_model.h"
#include "core/io/force_measurements.h"
#include "core/io/project_file.h"
#include "core/planning/clamping_advisor.h"
#include "core/planning/cutting_window.h"
#include "core/planning/optimiser.h"
#include "core/planning/plausibility.h"
#include "core/project/keywords.h"
#include "core/tolerance/evaluation.h"
#include "core/tolerance/iso286.h"
#include "core/tolerance/range_verdicts.h"
#include "widgets/dialogs/about_dialog.h"
#include "widgets/report/report_writer.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <vector>

namespace tolturn {

namespace {

struct CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};

using Handler = std::function<int(const QStringList &, QTextStream &, QTextStream &)>;

struct Command {
    QString name;
    QString synopsis;
    QString summary;
    Handler run;
};

const std::vector<Command> &commands();

// The command called `name` (for its synopsis and summary in --help).
const Command &commandNamed(const QString &name)
{
    const std::vector<Command> &list = commands();
    return *std::find_if(list.begin(), list.end(), [&name](const Command &c) { return c.name == name; });
}

QString usage()
{
    QString text = CommandLine::tr("Usage: %1 [--help] [--version] COMMAND [ARGUMENTS]\n\n"
                                   "TolTurn's command-line front end: the same computations as the desktop program, "
                                   "headless, for batch use and regression tests.\n\nCommands:\n")
                       .arg(programName());
    for (const Command &c : commands())
        text += QStringLiteral("  %1\n      %2\n").arg(c.synopsis, c.summary);
    text += CommandLine::tr("\nRun '%1 COMMAND --help' for the options of a command.\n"
                            "Exit codes: 0 success, 1 the input has errors, 2 wrong command line.\n")
                .arg(programName());
    return text;
}

QString versionText()
{
    QString text = QStringLiteral("tolturn-cli %1\n").arg(tolturnVersion());
    for (const LibraryInfo &lib : applicationLibraries())
        text += QStringLiteral("  %1 %2 (%3)\n").arg(lib.name, lib.version, lib.licence);
    return text;
}

const std::vector<Command> &commands()
{
    static const std::vector<Command> list{
        {QStringLiteral("check"), QStringLiteral("check [--json] PROJECT..."),
         CommandLine::tr("Validate project files: report every problem with the field and value; exit 1 on errors."),
         runCheck},
        {QStringLiteral("deflect"),
         QStringLiteral("deflect [--json] [--load Fr,Ft,Fa] [--workpiece-only] [--no-in-process] [--uncorrected-beam] "
                        "[--stations N] [--pass N] [--learned [--store STORE]] [--operation NAME] PROJECT"),
         CommandLine::tr(
             "Predict the deviation at each tool position along every turned feature: radial and tangential, total "
             "and per contribution (spindle–chuck, toolpost, workpiece, thermal), with the forces used."),
         runDeflect},
        {QStringLiteral("calibrate-forces"),
         QStringLiteral("calibrate-forces [--json] [--write] PROJECT MEASUREMENTS.csv"),
         CommandLine::tr(
             "Fit the Li & Du coefficients K_n and K_f to measured tangential and axial forces (eq. 17–18) for the "
             "project's tool; --write stores them in the project."),
         runCalibrateForces},
        {QStringLiteral("calibrate-stiffness"), calibrateStiffnessSynopsis(), calibrateStiffnessSummary(),
         runCalibrateStiffness},
        {QStringLiteral("iso286"), QStringLiteral("iso286 [--json] NOMINAL CLASS"),
         CommandLine::tr("ISO 286 limits of a tolerance class at a nominal size, e.g. 'iso286 50 H7'."), runIso286},
        {QStringLiteral("fit"), QStringLiteral("fit [--json] NOMINAL HOLE/SHAFT"),
         CommandLine::tr("ISO 286 fit of a hole and a shaft class, e.g. 'fit 50 H7/g6': type and clearances."), runFit},
        {QStringLiteral("evaluate"),
         QStringLiteral("evaluate [--json] [--learned [--store STORE]] [--operation NAME] PROJECT"),
         CommandLine::tr(
             "Every tolerance of the project against the predicted deviation: value, limit, utilisation, the "
             "deciding condition of Valiño et al. Fig. 4, and the verdict."),
         runEvaluate},
        {QStringLiteral("optimize"),
         QStringLiteral("optimize [--json] [--objective time|cost] [--machine-end compliant|stiff | --learned "
                        "[--store STORE]] [--time-limit S] [--write] [--operation NAME] PROJECT"),
         CommandLine::tr(
             "Cutting conditions of the finishing and roughing passes at least time or cost per part under every "
             "constraint (tolerances, roughness, power, torque, force, spindle speed, tool life)."),
         runOptimize},
        {QStringLiteral("window"),
         QStringLiteral("window [--plane feed-speed|feed-depth] [--csv] [--size N] [--operation NAME] PROJECT"),
         CommandLine::tr(
             "The cutting window of the finishing pass around the optimum: per grid point the objective, whether "
             "it is feasible and the constraint that bounds it."),
         runWindow},
        {QStringLiteral("advise-clamping"), QStringLiteral("advise-clamping [--json] [--operation NAME] PROJECT"),
         CommandLine::tr("The optimal plan for chuck, between centres and chuck + tailstock, ranked, with the reason."),
         runAdviseClamping},
        {QStringLiteral("gcode"), gcodeSynopsis(), gcodeSummary(), runGCode},
        {QStringLiteral("report"),
         QStringLiteral("report [--planner NAME] [--learned [--store STORE]] [--operation NAME] -o FILE.pdf|- PROJECT"),
         CommandLine::tr(
             "The PDF report: part, inputs, predicted deviation, tolerance verdicts, plan with the cutting window, "
             "clamping ranking, compensation, assumptions and sources."),
         runReport},
        {QStringLiteral("import"), importSynopsis(), importSummary(), runImport},
        {QStringLiteral("export-step"), exportStepSynopsis(), exportStepSummary(), runExportStep},
        {QStringLiteral("verify-fe"), verifyFeSynopsis(), verifyFeSummary(), runVerifyFe},
        {QStringLiteral("simulate-control"), simulateControlSynopsis(), simulateControlSummary(), runSimulateControl},
        {QStringLiteral("tune-control"), tuneControlSynopsis(), tuneControlSummary(), runTuneControl},
        {QStringLiteral("control-example"), controlExampleSynopsis(), controlExampleSummary(), runControlExample},
        {QStringLiteral("mill-forces"), millForcesSynopsis(), millForcesSummary(), runMillForces},
        {QStringLiteral("mill-deflect"), millDeflectSynopsis(), millDeflectSummary(), runMillDeflect},
        {QStringLiteral("mill-optimize"), millOptimizeSynopsis(), millOptimizeSummary(), runMillOptimize},
        {QStringLiteral("measurements"), measurementsSynopsis(), measurementsSummary(), runMeasurements},
        {QStringLiteral("learn"),
         QStringLiteral("learn --machine ID [--criterion gcv|bic] [--force-calibration CAL.csv] [--save] [--json] "
                        "[--store STORE]"),
         CommandLine::tr(
             "Learn what a machine's measured parts show beyond the physics (Li & Du): geometric error, hybrid RBF "
             "network, and how well parts not learned from are predicted with and without it."),
         runLearn},
    };
    return list;
}

// Levenshtein distance, for suggesting a command to a mistyped one.
int editDistance(const QString &a, const QString &b)
{
    std::vector<int> row(static_cast<std::size_t>(b.size()) + 1);
    for (std::size_t j = 0; j < row.size(); ++j)
        row[j] = static_cast<int>(j);
    for (qsizetype i = 1; i <= a.size(); ++i) {
        int diagonal = row[0];
        row[0] = static_cast<int>(i);
        for (qsizetype j = 1; j <= b.size(); ++j) {
            const int above = row[static_cast<std::size_t>(j)];
            const int substitution = diagonal + (a.at(i - 1) == b.at(j - 1) ? 0 : 1);
            row[static_cast<std::size_t>(j)] =
                std::min({above + 1, row[static_cast<std::size_t>(j - 1)] + 1, substitution});
            diagonal = above;
        }
    }
    return row.back();
}

// The command a mistyped name most likely meant: within two edits, or the one it starts.
QString nearestCommand(const QString &typed)
{
    QString best;
    int bestDistance = 3;
    for (const Command &c : commands()) {
        const int d =
            c.name.startsWith(typed.toLower()) && typed.size() >= 3 ? 0 : editDistance(typed.toLower(), c.name);
        if (d < bestDistance) {
            bestDistance = d;
            best = c.name;
        }
    }
    return best;
}

} // namespace

CommandHelp commandHelp(const QString &name)
{
    const Command &c = commandNamed(name);
    return {c.synopsis, c.summary};
}

int runCommandLine(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    const QStringList args = arguments.mid(1);
    if (args.isEmpty()) {
        err << usage();
        return kExitUsage;
    }
    const QString &first = args.constFirst();
    // "help COMMAND" is "COMMAND --help"; "help" alone, the list of commands.
    if (first == QLatin1String("help") && args.size() > 1)
        return runCommandLine({arguments.constFirst(), args.at(1), QStringLiteral("--help")}, out, err);
    if (first == QLatin1String("--help") || first == QLatin1String("-h") || first == QLatin1String("help")) {
        out << usage();
        return kExitOk;
    }
    if (first == QLatin1String("--version") || first == QLatin1String("-v")) {
        out << versionText();
        return kExitOk;
    }
    // British spelling as well: the desktop program says "Optimise".
    const QString name = first == QLatin1String("optimise") ? QStringLiteral("optimize") : first;
    for (const Command &c : commands()) {
        if (c.name != name)
            continue;
        // A command checks its input and names what is wrong; should an input still reach a
        // model that refuses it, the refusal is printed with the command's name, never a crash.
        try {
            return c.run(QStringList{programName() + QLatin1Char(' ') + c.name} + args.mid(1), out, err);
        } catch (const std::invalid_argument &e) {
            err << programName() << ' ' << c.name << ": " << QString::fromStdString(e.what()) << '\n';
            return kExitProblems;
        }
    }
    err << CommandLine::tr("%1: unknown command '%2'.").arg(programName(), first);
    if (const QString close = nearestCommand(first); !close.isEmpty())
        err << ' ' << CommandLine::tr("Did you mean '%1'?").arg(close);
    err << ' ' << CommandLine::tr("Run '%1 --help' for the list of commands.").arg(programName()) << '\n';
    return kExitUsage;
}

} // namespace tolturn
