// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/control_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
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

// A number option in [lo, hi]; nullopt (with the message printed) when it is not one.
std::optional<double> numberOption(const QCommandLineParser &parser, const QCommandLineOption &option, double lo,
                                   double hi, QTextStream &err)
{
    bool ok = false;
    const double v = parser.value(option).toDouble(&ok);
    if (ok && v >= lo && v <= hi)
        return v;
    err << programName() << " simulate-control: "
        << ControlCommand::tr("--%1: \"%2\" is not a number from %3 to %4")
               .arg(option.names().constFirst(), parser.value(option), QString::number(lo), QString::number(hi))
        << '\n';
    return std::nullopt;
}

} // namespace

QString simulateControlSynopsis()
{
    return QStringLiteral(
        "simulate-control [--pass N] [--set-force N] [--noise PCT] [--seed N] [--json|--csv] PROJECT");
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
    const QCommandLineOption pass(QStringLiteral("pass"), ControlCommand::tr("Only pass N of the plan (1, 2, …)."),
                                  QStringLiteral("N"));
    const QCommandLineOption setForce(
        QStringLiteral("set-force"),
        ControlCommand::tr("The resultant force to hold in N (default: the programmed feed's at the pass's depth)."),
        QStringLiteral("N"));
    const QCommandLineOption noise(
        QStringLiteral("noise"),
        ControlCommand::tr("Machine noise: standard deviation of the measured force in % (default 0)."),
        QStringLiteral("PCT"), QStringLiteral("0"));
    const QCommandLineOption seed(QStringLiteral("seed"), ControlCommand::tr("Seed of the noise (default 1)."),
                                  QStringLiteral("N"), QStringLiteral("1"));
    parser.addOptions({json, csv, pass, setForce, noise, seed});
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
    ProjectControlOptions options;
    if (parser.isSet(pass)) {
        const std::optional<double> n = numberOption(parser, pass, 1, 1000, err);
        if (!n || *n != std::floor(*n))
            return kExitUsage;
        options.passIndex = static_cast<int>(*n) - 1;
    }
    if (parser.isSet(setForce)) {
        const std::optional<double> f = numberOption(parser, setForce, 1.0, 1e6, err);
        if (!f)
            return kExitUsage;
        options.control.setForce_N = *f;
    }
    const std::optional<double> noisePct = numberOption(parser, noise, 0.0, 50.0, err);
    const std::optional<double> seedValue = numberOption(parser, seed, 0, 4294967295.0, err);
    if (!noisePct || !seedValue)
        return kExitUsage;
    options.control.forceNoise = *noisePct / 100.0;
    options.control.noiseSeed = static_cast<unsigned>(*seedValue);

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

} // namespace tolturn
