// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/control_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "core/adaptive/controller_tuning.h"
#include "core/adaptive/project_control.h"
#include "core/common/csv.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <QTextStream>

#include <algorithm>
#include <optional>

namespace tolturn {

namespace {

struct ControlCommand {
    Q_DECLARE_TR_FUNCTIONS(ControlCommand)
};

QString passKindName(PassKind kind)
{
    return kind == PassKind::Roughing ? ControlCommand::tr("roughing") : ControlCommand::tr("finishing");
}

struct RunFigures {
    double feedMin = 0.0;
    double feedMax = 0.0;
    double raMax = 0.0;
};

RunFigures figuresOf(const ControlRun &run)
{
    RunFigures f;
    f.feedMin = 1e300;
    for (const ControlSample &s : run.samples) {
        if (s.depth_mm <= 0.0)
            continue;
        f.feedMin = std::min(f.feedMin, s.feed_mm_rev);
        f.feedMax = std::max(f.feedMax, s.feed_mm_rev);
        f.raMax = std::max(f.raMax, s.ra_um);
    }
    if (f.feedMin > f.feedMax)
        f.feedMin = f.feedMax = 0.0;
    return f;
}

double timeSaved_pct(const PassControlResult &p)
{
    return p.constantFeed.time_s > 0.0 ? 100.0 * (1.0 - p.adaptive.time_s / p.constantFeed.time_s) : 0.0;
}

QJsonObject runJson(const ControlRun &run)
{
    const RunFigures f = figuresOf(run);
    return {{QStringLiteral("time_s"), run.time_s},
            {QStringLiteral("peak_force_N"), run.peakForce_N},
            {QStringLiteral("feed_mm_rev"), QJsonArray{f.feedMin, f.feedMax}},
            {QStringLiteral("deviation_um"), QJsonArray{run.smallestDeviation_um, run.largestDeviation_um}},
            {QStringLiteral("ra_max_um"), f.raMax}};
}

QJsonObject resultJson(const QString &file, const ProjectControlResult &r)
{
    QJsonArray passes;
    for (const PassControlResult &p : r.passes)
        passes.append(QJsonObject{{QStringLiteral("pass"), p.pass.passIndex + 1},
                                  {QStringLiteral("kind"), p.pass.conditions.kind == PassKind::Roughing
                                                               ? QStringLiteral("roughing")
                                                               : QStringLiteral("finishing")},
                                  {QStringLiteral("programmed_feed_mm_rev"), p.pass.conditions.feed_mm_rev},
                                  {QStringLiteral("depth_of_cut_mm"), p.pass.conditions.depthOfCut_mm},
                                  {QStringLiteral("cutting_speed_m_min"), p.pass.conditions.cuttingSpeed_m_min},
                                  {QStringLiteral("set_force_N"), p.setForce_N},
                                  {QStringLiteral("feed_exponent"), p.feedExponent},
                                  {QStringLiteral("constant_feed"), runJson(p.constantFeed)},
                                  {QStringLiteral("adaptive"), runJson(p.adaptive)},
                                  {QStringLiteral("time_saved_pct"), timeSaved_pct(p)}});
    QJsonArray diagnostics;
    for (const Diagnostic &d : r.diagnostics)
        diagnostics.append(diagnosticJson(d));
    return {{QStringLiteral("file"), file},
            {QStringLiteral("passes"), passes},
            {QStringLiteral("notes"), QJsonArray::fromStringList(r.notes)},
            {QStringLiteral("diagnostics"), diagnostics}};
}

void printCsv(const ProjectControlResult &r, QTextStream &out)
{
    out << csvLine({QStringLiteral("run"), QStringLiteral("pass"), QStringLiteral("t_s"), QStringLiteral("z_mm"),
                    QStringLiteral("depth_mm"), QStringLiteral("commanded_feed_mm_rev"), QStringLiteral("feed_mm_rev"),
                    QStringLiteral("spindle_rpm"), QStringLiteral("force_N"), QStringLiteral("measured_force_N"),
                    QStringLiteral("radial_force_N"), QStringLiteral("ra_um"), QStringLiteral("deviation_um")})
        << '\n';
    const auto number = [](double v, int decimals) { return QString::number(v, 'f', decimals); };
    for (const PassControlResult &p : r.passes) {
        for (const auto &[name, run] : {std::pair{QStringLiteral("adaptive"), &p.adaptive},
                                        std::pair{QStringLiteral("constant_feed"), &p.constantFeed}}) {
            for (const ControlSample &s : run->samples)
                out << csvLine({name, QString::number(p.pass.passIndex + 1), number(s.time_s, 3), number(s.z_mm, 4),
                                number(s.depth_mm, 4), number(s.commandedFeed_mm_rev, 5), number(s.feed_mm_rev, 5),
                                number(s.spindle_rpm, 1), number(s.force_N, 2), number(s.measuredForce_N, 2),
                                number(s.radialForce_N, 2), number(s.ra_um, 3), number(s.deviation_um, 3)})
                    << '\n';
        }
    }
}

void printTable(const QString &file, const ProjectControlResult &r, QTextStream &out)
{
    out << ControlCommand::tr("%1: constant-force control, adaptive against the programmed feed").arg(file) << '\n';
    const auto range = [](double a, double b, int decimals) {
        return QStringLiteral("%1–%2").arg(QString::number(a, 'f', decimals), QString::number(b, 'f', decimals));
    };
    for (const PassControlResult &p : r.passes) {
        const CuttingPass &c = p.pass.conditions;
        out << '\n'
            << ControlCommand::tr("Pass %1 (%2): f %3 mm/rev, a_p %4 mm, vc %5 m/min; set force %6 N (F ∝ f^%7)")
                   .arg(p.pass.passIndex + 1)
                   .arg(passKindName(c.kind), QString::number(c.feed_mm_rev, 'f', 3),
                        QString::number(c.depthOfCut_mm, 'f', 2), QString::number(c.cuttingSpeed_m_min, 'f', 0),
                        QString::number(p.setForce_N, 'f', 1), QString::number(p.feedExponent, 'f', 3))
            << '\n';
        const RunFigures k = figuresOf(p.constantFeed);
        const RunFigures a = figuresOf(p.adaptive);
        const auto row = [&](const QString &what, const QString &constant, const QString &adaptive) {
            out << QStringLiteral("  %1 %2 %3").arg(what, -24).arg(constant, 16).arg(adaptive, 16) << '\n';
        };
        row(QString(), ControlCommand::tr("constant feed"), ControlCommand::tr("adaptive"));
        row(ControlCommand::tr("time in cut [s]"), QString::number(p.constantFeed.time_s, 'f', 2),
            ControlCommand::tr("%1 (%2 %)")
                .arg(QString::number(p.adaptive.time_s, 'f', 2), QString::number(-timeSaved_pct(p), 'f', 1)));
        row(ControlCommand::tr("peak force [N]"), QString::number(p.constantFeed.peakForce_N, 'f', 1),
            QString::number(p.adaptive.peakForce_N, 'f', 1));
        row(ControlCommand::tr("feed [mm/rev]"), range(k.feedMin, k.feedMax, 3), range(a.feedMin, a.feedMax, 3));
        row(ControlCommand::tr("deviation [µm]"),
            range(p.constantFeed.smallestDeviation_um, p.constantFeed.largestDeviation_um, 1),
            range(p.adaptive.smallestDeviation_um, p.adaptive.largestDeviation_um, 1));
        row(ControlCommand::tr("largest Ra [µm]"), QString::number(k.raMax, 'f', 2), QString::number(a.raMax, 'f', 2));
    }
    out << '\n';
    for (const QString &note : r.notes)
        out << ControlCommand::tr("note: %1").arg(note) << '\n';
}

// The options both commands take: the pass, the machine noise and its seed, the controller's gains.
struct LoopOptions {
    QCommandLineOption pass{QStringLiteral("pass"), ControlCommand::tr("Only pass N of the plan (1, 2, …)."),
                            QStringLiteral("N")};
    QCommandLineOption noise{
        QStringLiteral("noise"),
        ControlCommand::tr("Machine noise: standard deviation of the measured force in % (default 0)."),
        QStringLiteral("PCT"), QStringLiteral("0")};
    QCommandLineOption seed{QStringLiteral("seed"), ControlCommand::tr("Seed of the noise (default 1)."),
                            QStringLiteral("N"), QStringLiteral("1")};

    [[nodiscard]] QList<QCommandLineOption> all() const { return {pass, noise, seed}; }

    // Into `options`; false (with the message printed) on a bad value.
    [[nodiscard]] bool read(const QCommandLineParser &parser, const QString &command, ProjectControlOptions &options,
                            QTextStream &err) const
    {
        if (parser.isSet(pass)) {
            const std::optional<long long> n = wholeNumberInRange(parser, pass, 1, 1000, command, err);
            if (!n)
                return false;
            options.passIndex = static_cast<int>(*n) - 1;
        }
        const std::optional<double> noisePct = numberInRange(parser, noise, 0.0, 50.0, command, err);
        const std::optional<long long> seedValue = wholeNumberInRange(parser, seed, 0, 4294967295LL, command, err);
        if (!noisePct || !seedValue)
            return false;
        options.control.forceNoise = *noisePct / 100.0;
        options.control.noiseSeed = static_cast<unsigned>(*seedValue);
        return true;
    }
};

} // namespace

QString simulateControlSynopsis()
{
    return QStringLiteral("simulate-control [--pass N] [--set-force N] [--noise PCT] [--seed N] [--estimator-gain G] "
                          "[--command-gain G] [--json|--csv] PROJECT");
}

QString simulateControlSummary()
{
    return ControlCommand::tr(
        "Constant-force adaptive control of the plan's passes (Čuš & Župerl): the feed override commanded every "
        "20 ms through the feed drive's dynamics, against the programmed feed: time, peak force, feed, deviation "
        "and roughness along the pass.");
}

int runSimulateControl(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), ControlCommand::tr("Print a summary per pass as JSON."));
    const QCommandLineOption csv(QStringLiteral("csv"),
                                 ControlCommand::tr("Print every control period of both runs as CSV."));
    const LoopOptions loop;
    const QCommandLineOption setForce(
        QStringLiteral("set-force"),
        ControlCommand::tr("The resultant force to hold in N (default: the programmed feed's at the pass's depth)."),
        QStringLiteral("N"));
    const QCommandLineOption estimatorGain(
        QStringLiteral("estimator-gain"),
        ControlCommand::tr("Weight of each period's estimate of the process gain, %1–%2 (default 1; tune-control "
                           "finds it).")
            .arg(kLowestGains.estimatorGain)
            .arg(kHighestGains.estimatorGain),
        QStringLiteral("G"), QStringLiteral("1"));
    const QCommandLineOption commandGain(
        QStringLiteral("command-gain"),
        ControlCommand::tr("Share of the step to the set force's feed commanded each period, %1–%2 (default 1).")
            .arg(kLowestGains.commandGain)
            .arg(kHighestGains.commandGain),
        QStringLiteral("G"), QStringLiteral("1"));
    parser.addOptions({json, csv, setForce, estimatorGain, commandGain});
    parser.addOptions(loop.all());
    parser.addPositionalArgument(QStringLiteral("project"), ControlCommand::tr("The project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseNamedCommand(parser, QStringLiteral("simulate-control"), args, out, err); stop >= 0)
        return stop;
    const QString file = oneProjectFile(parser, QStringLiteral("simulate-control"), err);
    if (file.isEmpty())
        return kExitUsage;
    if (parser.isSet(json) && parser.isSet(csv)) {
        err << programName() << " simulate-control: " << ControlCommand::tr("give --json or --csv, not both") << '\n';
        return kExitUsage;
    }
    const QString command = QStringLiteral("simulate-control");
    ProjectControlOptions options;
    if (!loop.read(parser, command, options, err))
        return kExitUsage;
    if (parser.isSet(setForce)) {
        const std::optional<double> f = numberInRange(parser, setForce, 1.0, 1e6, command, err);
        if (!f)
            return kExitUsage;
        options.control.setForce_N = *f;
    }
    const std::optional<double> lambda =
        numberInRange(parser, estimatorGain, kLowestGains.estimatorGain, kHighestGains.estimatorGain, command, err);
    const std::optional<double> gain =
        numberInRange(parser, commandGain, kLowestGains.commandGain, kHighestGains.commandGain, command, err);
    if (!lambda || !gain)
        return kExitUsage;
    options.control.estimatorGain = *lambda;
    options.control.commandGain = *gain;

    const std::optional<Project> project = readProject(file, err);
    if (!project)
        return kExitProblems;
    const ProjectControlResult result = simulateProjectControl(*project, DataLibrary::builtIn(), options);
    for (const Diagnostic &d : result.diagnostics)
        err << file << ": " << d.toString() << '\n';
    if (!result.ok())
        return kExitProblems;
    if (parser.isSet(json))
        return printJson(resultJson(file, result), out, err, QStringLiteral("simulate-control"));
    if (parser.isSet(csv))
        printCsv(result, out);
    else
        printTable(file, result, out);
    return kExitOk;
}

namespace {

QJsonObject tuningJson(const QString &file, const PassSetup &pass, double untuned,
                       const std::vector<TuningResult> &results, const QStringList &notes)
{
    QJsonArray methods;
    for (const TuningResult &r : results)
        methods.append(QJsonObject{{QStringLiteral("method"), tuningMethodName(r.method)},
                                   {QStringLiteral("library"), tuningMethodLibrary(r.method)},
                                   {QStringLiteral("estimator_gain"), r.gains.estimatorGain},
                                   {QStringLiteral("command_gain"), r.gains.commandGain},
                                   {QStringLiteral("rms_force_error"), r.objective},
                                   {QStringLiteral("evaluations"), r.evaluations},
                                   {QStringLiteral("time_s"), r.wallTime_s}});
    return {{QStringLiteral("file"), file},
            {QStringLiteral("pass"), pass.pass.passIndex + 1},
            {QStringLiteral("untuned_rms_force_error"), untuned},
            {QStringLiteral("methods"), methods},
            {QStringLiteral("notes"), QJsonArray::fromStringList(notes)}};
}

void printTuning(const QString &file, const PassSetup &pass, double untuned, const std::vector<TuningResult> &results,
                 const QStringList &notes, QTextStream &out)
{
    out << ControlCommand::tr("%1: controller tuning on pass %2, RMS of F / F_set − 1 over the cut")
               .arg(file)
               .arg(pass.pass.passIndex + 1)
        << '\n'
        << ControlCommand::tr("untuned (both gains 1): %1 %").arg(100.0 * untuned, 0, 'f', 3) << "\n\n";
    out << QStringLiteral("%1 %2 %3 %4 %5 %6")
               .arg(ControlCommand::tr("method"), -26)
               .arg(ControlCommand::tr("estimator"), 10)
               .arg(ControlCommand::tr("command"), 10)
               .arg(ControlCommand::tr("RMS [%]"), 10)
               .arg(ControlCommand::tr("evaluations"), 12)
               .arg(ControlCommand::tr("time [s]"), 10)
        << '\n';
    for (const TuningResult &r : results)
        out << QStringLiteral("%1 %2 %3 %4 %5 %6")
                   .arg(tuningMethodLibrary(r.method), -26)
                   .arg(r.gains.estimatorGain, 10, 'f', 3)
                   .arg(r.gains.commandGain, 10, 'f', 3)
                   .arg(100.0 * r.objective, 10, 'f', 3)
                   .arg(r.evaluations, 12)
                   .arg(r.wallTime_s, 10, 'f', 2)
            << '\n';
    out << '\n';
    for (const QString &note : notes)
        out << ControlCommand::tr("note: %1").arg(note) << '\n';
}

// The methods named in a comma-separated list; empty (with the message printed) on an unknown one.
std::vector<TuningMethod> methodsNamed(const QString &list, QTextStream &err)
{
    std::vector<TuningMethod> methods;
    const QStringList names = list.split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (names.isEmpty()) {
        err << programName() << " tune-control: " << ControlCommand::tr("--methods: no method named") << '\n';
        return {};
    }
    for (const QString &name : names) {
        const std::vector<TuningMethod> all = allTuningMethods();
        const auto it =
            std::find_if(all.begin(), all.end(), [&](TuningMethod m) { return tuningMethodName(m) == name.trimmed(); });
        if (it == all.end()) {
            QStringList known;
            for (const TuningMethod m : all)
                known << tuningMethodName(m);
            err << programName() << " tune-control: "
                << ControlCommand::tr("--methods: \"%1\" is not a method (%2)")
                       .arg(name, known.join(QStringLiteral(", ")))
                << '\n';
            return {};
        }
        methods.push_back(*it);
    }
    return methods;
}

} // namespace

QString tuneControlSynopsis()
{
    return QStringLiteral("tune-control [--pass N] [--noise PCT] [--seed N] [--evaluations N] [--methods LIST] "
                          "[--json] PROJECT");
}

QString tuneControlSummary()
{
    return ControlCommand::tr(
        "Tune the constant-force controller on a pass of the plan (the estimator's and the command's gains): "
        "particle swarm (Čuš & Župerl's method, pagmo2) against NLopt's algorithms on the same objective.");
}

int runTuneControl(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), ControlCommand::tr("Print the comparison as JSON."));
    const LoopOptions loop;
    const QCommandLineOption evaluations(
        QStringLiteral("evaluations"),
        ControlCommand::tr("Simulations of the pass each method may ask for, at least %1 (default 400).")
            .arg(kLeastTuningEvaluations),
        QStringLiteral("N"), QStringLiteral("400"));
    QStringList names;
    for (const TuningMethod m : allTuningMethods())
        names << tuningMethodName(m);
    const QCommandLineOption methods(
        QStringLiteral("methods"),
        ControlCommand::tr("Comma-separated methods (default all: %1).").arg(names.join(QStringLiteral(","))),
        QStringLiteral("LIST"), names.join(QLatin1Char(',')));
    parser.addOptions({json, evaluations, methods});
    parser.addOptions(loop.all());
    parser.addPositionalArgument(QStringLiteral("project"), ControlCommand::tr("The project file."),
                                 QStringLiteral("PROJECT"));
    const QString command = QStringLiteral("tune-control");
    if (const int stop = parseNamedCommand(parser, command, args, out, err); stop >= 0)
        return stop;
    const QString file = oneProjectFile(parser, command, err);
    if (file.isEmpty())
        return kExitUsage;
    ProjectControlOptions options;
    options.passIndex = 0;
    if (!loop.read(parser, command, options, err))
        return kExitUsage;
    const std::optional<long long> budget =
        wholeNumberInRange(parser, evaluations, kLeastTuningEvaluations, 100000, command, err);
    const std::vector<TuningMethod> chosen = methodsNamed(parser.value(methods), err);
    if (!budget || chosen.empty())
        return kExitUsage;

    const std::optional<Project> project = readProject(file, err);
    if (!project)
        return kExitProblems;
    const ProjectControlSetup setup = prepareProjectControl(*project, DataLibrary::builtIn(), options);
    for (const Diagnostic &d : setup.diagnostics)
        err << file << ": " << d.toString() << '\n';
    if (!setup.ok())
        return kExitProblems;
    const PassSetup &pass = setup.passes.front();
    const double untuned = forceTrackingError(pass.pass, pass.process, options.control, {1.0, 1.0});
    std::vector<TuningResult> results;
    results.reserve(chosen.size());
    for (const TuningMethod m : chosen)
        results.push_back(tuneController(pass.pass, pass.process, options.control, m, static_cast<int>(*budget)));
    if (parser.isSet(json))
        return printJson(tuningJson(file, pass, untuned, results, setup.notes), out, err, command);
    printTuning(file, pass, untuned, results, setup.notes, out);
    return kExitOk;
}

} // namespace tolturn
