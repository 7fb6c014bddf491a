// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/planning_commands.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "app/cli/learn_command.h"
#include "core/common/csv.h"
#include "core/common/library_info.h"
#include "core/deviation/deviation_model.h"
#include "core/io/force_measurements.h"
#include "core/io/project_file.h"
#include "core/io/result_json.h"
#include "core/planning/clamping_advisor.h"
#include "core/planning/cutting_window.h"
#include "core/planning/optimiser.h"
#include "core/planning/plausibility.h"
#include "core/project/keywords.h"
#include "core/project/operations.h"
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
#include <memory>
#include <optional>
#include <vector>

namespace tolturn {

namespace {

struct CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};

QString constraintText(const ConstraintValue &c)
{
    if (!std::isfinite(c.value))
        return QStringLiteral("%1: %2 (limit %3 %4)")
            .arg(c.label(), c.violatedBy(), QString::number(c.limit, 'g', 4), c.unit);
    // Four significant digits: a ratio of 10^270 (degenerate tool-life data) is no row of digits.
    return QStringLiteral("%1: %2 of %3 %4 (%5 %)")
        .arg(c.label(), QString::number(c.value, 'g', 4), QString::number(c.limit, 'g', 4), c.unit,
             QString::number(100.0 * (c.value / c.limit), 'g', 4));
}

void printPlan(QTextStream &out, const PlanResult &r, const PlanningProblem &problem)
{
    const CandidateEvaluation &e = r.evaluation;
    const PassConditions rough = roughingPassOf(r, problem);
    const QString objective = keyword(problem.project().planning.objective);
    if (r.feasible)
        out << (r.timedOut ? CommandLine::tr("Best plan (%1) found within the time limit").arg(objective)
                           : CommandLine::tr("Optimum (%1)").arg(objective));
    else
        out << CommandLine::tr("No plan meets every constraint; the one that violates them least");
    out << '\n';
    // The parts of the time as planning_problem.cpp adds them: handling and tool changes too.
    const PlanningSettings &s = problem.project().planning;
    const bool toolLifeKnown = problem.knowsToolLife();
    out << CommandLine::tr("  time per part %1 min (finishing %2, roughing %3, handling %4, tool changes %5), cost %6 "
                           "at %7 per min, %8")
               .arg(formatFixed(e.time_min, 3), formatFixed(e.finishingTime_min, 3), formatFixed(e.roughingTime_min, 3),
                    formatFixed(s.handlingTime_min, 3),
                    toolLifeKnown ? formatFixed(s.toolChangeTime_min * e.toolEdgesPerPart, 3)
                                  : CommandLine::tr("not known"),
                    formatFixed(e.cost, 2), formatNumber(s.machineRate_per_min),
                    toolLifeKnown ? CommandLine::tr("%1 tool edges per part").arg(formatFixed(e.toolEdgesPerPart, 3))
                                  : CommandLine::tr("tool edges per part not known (no tool life)"))
        << '\n';
    out << CommandLine::tr("  finishing: vc %1 m/min, f %2 mm/rev, ap %3 mm")
               .arg(QString::number(r.candidate.finishing.cuttingSpeed_m_min, 'f', 0),
                    QString::number(r.candidate.finishing.feed_mm_rev, 'f', 3),
                    QString::number(r.candidate.finishing.depthOfCut_mm, 'f', 3))
        << '\n';
    if (r.candidate.roughingPasses > 0)
        out << CommandLine::tr("  roughing: %n pass(es) of ap %1 mm at vc %2 m/min, f %3 mm/rev", nullptr,
                               r.candidate.roughingPasses)
                   .arg(QString::number(rough.depthOfCut_mm, 'f', 3), QString::number(rough.cuttingSpeed_m_min, 'f', 0),
                        QString::number(rough.feed_mm_rev, 'f', 3))
            << '\n';
    for (const ConstraintValue &c : r.binding)
        out << CommandLine::tr("  binding: ") << constraintText(c) << '\n';
    for (const ConstraintValue &c : r.conflicts)
        out << CommandLine::tr("  violated: ") << constraintText(c) << '\n';
    for (const QString &remedy : r.remedies)
        out << CommandLine::tr("  to meet it: ") << remedy << '\n';
    for (const QString &note : r.notes)
        out << CommandLine::tr("note: ") << note << '\n';
}

// A project's planning problem, or the exit code of why there is none (its problems printed).
struct LoadedProblem {
    std::shared_ptr<const PlanningProblem> problem;
    int exitCode = kExitProblems;
};

// Loads a project and builds the planning problem of the operation --operation names: an unknown
// operation is a usage error, as optimize says.
LoadedProblem loadPlanningProblem(const QString &file, const QCommandLineParser &parser, const QString &command,
                                  QTextStream &err)
{
    const std::optional<Project> whole = readProject(file, err, MissingPasses::Planned);
    if (!whole)
        return {};
    const std::optional<Project> read = selectOperation(*whole, parser, command, err);
    if (!read)
        return {nullptr, kExitUsage};
    const PlanningProblem::BuildResult built = PlanningProblem::build(*read, DataLibrary::builtIn());
    for (const Diagnostic &d : built.diagnostics) {
        if (d.severity == Severity::Error)
            err << file << ": " << d.toString() << '\n';
    }
    return {built.problem, built.problem ? kExitOk : kExitProblems};
}

} // namespace

int runOptimize(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the plan as JSON."));
    const QCommandLineOption objective(QStringLiteral("objective"),
                                       CommandLine::tr("time or cost (default: the project's)."),
                                       QStringLiteral("OBJECTIVE"));
    const QCommandLineOption write(
        QStringLiteral("write"),
        CommandLine::tr("Store the optimal passes in the project (replacing its passes) and save it."));
    const QCommandLineOption machineEnd(
        QStringLiteral("machine-end"),
        CommandLine::tr(
            "Plan for the compliant (default) or the stiff end of an unmeasured machine's stiffness range."),
        QStringLiteral("END"));
    const QCommandLineOption timeLimit(
        QStringLiteral("time-limit"),
        CommandLine::tr("Stop the search after SECONDS (0.01 to 3600, default 60) with the best plan found by then."),
        QStringLiteral("SECONDS"), QStringLiteral("60"));
    const QCommandLineOption learned(
        QStringLiteral("learned"),
        CommandLine::tr("Plan with what was learned of the machine from its measured parts (learn --save)."));
    const QCommandLineOption store = measurementStoreOption();
    parser.addOptions({json, objective, write, machineEnd, timeLimit, learned, store, operationOption()});
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseNamedCommand(parser, QStringLiteral("optimize"), args, out, err); stop >= 0)
        return stop;
    const QString file = oneProjectFile(parser, QStringLiteral("optimize"), err);
    if (file.isEmpty())
        return kExitUsage;
    OptimisationOptions options;
    bool ok = false;
    options.timeLimit_s = parser.value(timeLimit).toDouble(&ok);
    if (!ok || !(options.timeLimit_s >= 0.01 && options.timeLimit_s <= 3600.0)) {
        err << programName() << " optimize: "
            << CommandLine::tr("--time-limit is from 0.01 to 3600 seconds, not \"%1\"").arg(parser.value(timeLimit))
            << '\n';
        return kExitUsage;
    }
    std::optional<Project> project = readProject(file, err, MissingPasses::Planned);
    if (!project)
        return kExitProblems;
    if (parser.isSet(objective)) {
        const auto chosen = fromKeyword<PlanningObjective>(parser.value(objective));
        if (!chosen) {
            err << programName() << " optimize: "
                << CommandLine::tr("--objective is time or cost, not \"%1\"").arg(parser.value(objective)) << '\n';
            return kExitUsage;
        }
        project->planning.objective = *chosen;
    }
    StiffnessEnd end = StiffnessEnd::Compliant;
    if (parser.isSet(machineEnd)) {
        const QString value = parser.value(machineEnd);
        if (value != QLatin1String("compliant") && value != QLatin1String("stiff")) {
            err << programName()
                << " optimize: " << CommandLine::tr("--machine-end is compliant or stiff, not \"%1\"").arg(value)
                << '\n';
            return kExitUsage;
        }
        end = value == QLatin1String("stiff") ? StiffnessEnd::Stiff : StiffnessEnd::Compliant;
    }
    std::shared_ptr<const LoadedModel> model;
    if (parser.isSet(learned)) {
        if (parser.isSet(machineEnd)) {
            err << programName() << " optimize: "
                << CommandLine::tr("--learned replaces the stiffness range: give it or --machine-end, not both")
                << '\n';
            return kExitUsage;
        }
        auto loaded = loadLearnedModel(parser.value(store), *project, QStringLiteral("optimize"), err);
        if (!loaded)
            return kExitProblems;
        model = std::make_shared<const LoadedModel>(std::move(*loaded));
    }
    const std::optional<Project> view = selectOperation(*project, parser, QStringLiteral("optimize"), err);
    if (!view)
        return kExitUsage;
    const PlanningProblem::BuildResult built = PlanningProblem::build(*view, DataLibrary::builtIn(), end, model);
    for (const Diagnostic &d : built.diagnostics) {
        if (d.severity == Severity::Error)
            err << file << ": " << d.toString() << '\n';
    }
    if (!built.problem)
        return kExitProblems;
    const PlanResult plan = optimisePlan(*built.problem, options);
    if (parser.isSet(json)) {
        if (const int code = printJson(planJson(plan, *built.problem), out, err, QStringLiteral("optimize"));
            code != kExitOk)
            return code;
    } else {
        printPlan(out, plan, *built.problem);
    }
    if (!plan.feasible)
        return kExitProblems;
    if (parser.isSet(write)) {
        const PassConditions rough = roughingPassOf(plan, *built.problem);
        // The passes of the operation planned, in the project as its file holds it.
        const int index = view->scope ? view->scope->index : 0;
        std::vector<CuttingPass> &passes =
            index == 0 ? project->passes : project->furtherOperations[static_cast<std::size_t>(index - 1)].passes;
        passes.clear();
        // Fields this program does not know that sat on the old passes belong to none of the new
        // ones: they are dropped, each named, rather than left to land on another pass.
        const QString passesPath =
            index == 0 ? QStringLiteral("passes[") : QStringLiteral("further_operations[%1].passes[").arg(index - 1);
        auto &unknown = project->unknownFields;
        for (auto it = unknown.begin(); it != unknown.end();) {
            if (it->first.startsWith(passesPath)) {
                err << CommandLine::tr("warning: %1: dropped with the passes it was on").arg(it->first) << '\n';
                it = unknown.erase(it);
            } else {
                ++it;
            }
        }
        for (int i = 0; i < plan.candidate.roughingPasses; ++i)
            passes.push_back({PassKind::Roughing, rough.cuttingSpeed_m_min, rough.feed_mm_rev, rough.depthOfCut_mm});
        const PassConditions &f = plan.candidate.finishing;
        passes.push_back({PassKind::Finishing, f.cuttingSpeed_m_min, f.feed_mm_rev, f.depthOfCut_mm});
        const WriteResult w = writeProjectFile(file, *project);
        if (!w.ok) {
            err << w.error << '\n';
            return kExitProblems;
        }
        err << CommandLine::tr("wrote %1: %n pass(es)", nullptr, static_cast<int>(passes.size())).arg(file) << '\n';
    }
    return kExitOk;
}

int runWindow(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption plane(QStringLiteral("plane"), CommandLine::tr("feed-speed (default) or feed-depth."),
                                   QStringLiteral("PLANE"), QStringLiteral("feed-speed"));
    const QCommandLineOption csv(QStringLiteral("csv"), CommandLine::tr("Print every grid point as CSV."));
    const QCommandLineOption size(QStringLiteral("size"), CommandLine::tr("Points along each axis (default 256)."),
                                  QStringLiteral("N"), QStringLiteral("256"));
    parser.addOptions({plane, csv, size, operationOption()});
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseNamedCommand(parser, QStringLiteral("window"), args, out, err); stop >= 0)
        return stop;
    bool ok = false;
    const int n = parser.value(size).toInt(&ok);
    const QString planeName = parser.value(plane);
    if (parser.positionalArguments().size() != 1 || !ok || n < 2 || n > 4096 ||
        (planeName != QLatin1String("feed-speed") && planeName != QLatin1String("feed-depth"))) {
        err << programName() << " window: "
            << CommandLine::tr("give one project file, --plane feed-speed or feed-depth, --size from 2 to 4096")
            << '\n';
        return kExitUsage;
    }
    const LoadedProblem loaded =
        loadPlanningProblem(parser.positionalArguments().constFirst(), parser, QStringLiteral("window"), err);
    if (!loaded.problem)
        return loaded.exitCode;
    const auto &problem = loaded.problem;
    const PlanResult plan = optimisePlan(*problem);
    WindowOptions options;
    options.columns = options.rows = n;
    const WindowPlane which =
        planeName == QLatin1String("feed-speed") ? WindowPlane::FeedSpeed : WindowPlane::FeedDepth;
    const CuttingWindow w =
        cuttingWindow(*problem, which, plan.candidate, options); // the optimum, or the least-violating plan
    const QString yName =
        which == WindowPlane::FeedSpeed ? QStringLiteral("cutting_speed_m_min") : QStringLiteral("depth_of_cut_mm");
    if (parser.isSet(csv)) {
        out << "feed_mm_rev," << yName << ",objective,feasible,binding\n";
        for (const WindowCell &c : w.cells)
            out << QString::number(c.x, 'g', 8) << ',' << QString::number(c.y, 'g', 8) << ','
                << QString::number(c.objective, 'g', 8) << ',' << (c.feasible ? 1 : 0) << ','
                << (c.feasible ? QString() : csvField(c.bindingLabel)) << '\n';
        return kExitOk;
    }
    int feasible = 0;
    for (const WindowCell &c : w.cells)
        feasible += c.feasible ? 1 : 0;
    // The window lies around the optimum, or around the plan that violates the constraints least;
    // named with the symbols of the rest of the output (vc, ap), not the CSV's column names.
    const QString other =
        which == WindowPlane::FeedSpeed
            ? CommandLine::tr("vc = %1 m/min").arg(QString::number(w.base.finishing.cuttingSpeed_m_min, 'f', 0))
            : CommandLine::tr("ap = %1 mm").arg(QString::number(w.base.finishing.depthOfCut_mm, 'f', 3));
    const QString centre = (plan.feasible ? CommandLine::tr("optimum at f = %1 mm/rev, %2")
                                          : CommandLine::tr("no plan meets every constraint; the one that violates "
                                                            "them least at f = %1 mm/rev, %2"))
                               .arg(QString::number(w.base.finishing.feed_mm_rev, 'f', 3), other);
    out << CommandLine::tr("%1 × %2 window, %3 % feasible; %4")
               .arg(w.columns)
               .arg(w.rows)
               .arg(QString::number(100.0 * feasible / static_cast<double>(w.cells.size()), 'f', 1), centre)
        << '\n';
    for (const auto &[label, cells] : w.boundaries())
        out << CommandLine::tr("  bounded by %1 (%2 points beyond it)").arg(label).arg(cells) << '\n';
    return kExitOk;
}

int runAdviseClamping(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the ranking as JSON."));
    parser.addOptions({json, operationOption()});
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseNamedCommand(parser, QStringLiteral("advise-clamping"), args, out, err); stop >= 0)
        return stop;
    const QString file = oneProjectFile(parser, QStringLiteral("advise-clamping"), err);
    if (file.isEmpty())
        return kExitUsage;
    const std::optional<Project> whole = readProject(file, err, MissingPasses::Planned); // it plans them
    if (!whole)
        return kExitProblems;
    const std::optional<Project> project = selectOperation(*whole, parser, QStringLiteral("advise-clamping"), err);
    if (!project)
        return kExitUsage;
    const std::vector<ClampingOption> options = adviseClamping(*project, DataLibrary::builtIn());
    const std::optional<SplitProposal> split = proposeSplit(*whole);
    // The ranking is printed with each method's reason; a project no method can plan (no ranges
    // of the insert, say) is a problem with the input, as optimize says.
    const int exitCode = std::any_of(options.begin(), options.end(), [](const ClampingOption &o) { return o.possible; })
                             ? kExitOk
                             : kExitProblems;
    if (parser.isSet(json)) {
        QJsonArray list;
        int rank = 1;
        for (const ClampingOption &o : options) {
            QJsonObject entry{{QStringLiteral("rank"), rank++},
                              {QStringLiteral("method"), keyword(o.method)},
                              {QStringLiteral("clamped_length_mm"), o.clampedLength_mm},
                              {QStringLiteral("possible"), o.possible},
                              {QStringLiteral("feasible"), o.plan.feasible},
                              {QStringLiteral("reason"), o.reason}};
            if (o.possible)
                entry.insert(QStringLiteral("objective_value"), o.plan.evaluation.objective);
            QJsonArray notHeld;
            for (const ToleranceLeftOut &t : o.tolerancesNotHeld)
                notHeld.append(
                    QJsonObject{{QStringLiteral("tolerance"), t.toleranceId}, {QStringLiteral("reason"), t.reason}});
            entry.insert(QStringLiteral("tolerances_not_held"), notHeld);
            list.append(entry);
        }
        QJsonObject result{{QStringLiteral("file"), file},
                           {QStringLiteral("objective"), keyword(project->planning.objective)},
                           {QStringLiteral("ranking"), list}};
        if (split)
            result.insert(
                QStringLiteral("split"),
                QJsonObject{{QStringLiteral("reason"), split->reason},
                            {QStringLiteral("name"), split->second.name},
                            {QStringLiteral("held_end"), keyword(split->second.clamping.heldEnd)},
                            {QStringLiteral("clamped_length_mm"), split->second.clamping.clampedLength_mm},
                            {QStringLiteral("features"), QJsonArray::fromStringList(split->second.features)}});
        const int printed = printJson(result, out, err, QStringLiteral("advise-clamping"));
        return printed != kExitOk ? printed : exitCode;
    }
    int rank = 1;
    for (const ClampingOption &o : options)
        out << QStringLiteral("%1. %2: %3").arg(rank++).arg(displayName(o.method), o.reason) << '\n';
    if (split) // features the jaws cover: the second set-up that turns them (docs/operations.md)
        out << CommandLine::tr("Split into operations: %1 (Edit > Operations…, or further_operations in the file)")
                   .arg(split->reason)
            << '\n';
    return exitCode;
}

} // namespace tolturn
