// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/control_example_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "core/adaptive/seed_milling_example.h"
#include "core/common/csv.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <QTextStream>

#include <optional>

namespace tolturn {

namespace {

struct ControlExample {
    Q_DECLARE_TR_FUNCTIONS(ControlExample)
};

QJsonObject sampleJson(const SeedControlSample &s)
{
    return {{QStringLiteral("feed_rate_mm_min"), s.feedRate_mm_min},
            {QStringLiteral("spindle_rpm"), s.spindle_rpm},
            {QStringLiteral("force_N"), s.force_N},
            {QStringLiteral("ra_um"), s.ra_um}};
}

QJsonObject exampleJson(const SeedExampleResult &r)
{
    QJsonArray conditions;
    for (const SeedConditions &c : r.conditions)
        conditions.append(QJsonObject{{QStringLiteral("method"), tuningMethodName(c.method)},
                                      {QStringLiteral("library"), tuningMethodLibrary(c.method)},
                                      {QStringLiteral("feed_rate_mm_min"), c.feedRate_mm_min},
                                      {QStringLiteral("spindle_rpm"), c.spindle_rpm},
                                      {QStringLiteral("force_N"), c.force_N},
                                      {QStringLiteral("evaluations"), c.evaluations},
                                      {QStringLiteral("time_s"), c.wallTime_s}});
    QJsonArray table;
    for (const SeedRowResult &row : r.table)
        table.append(QJsonObject{{QStringLiteral("force_N"), row.paper.force_N},
                                 {QStringLiteral("paper_feed_rate_mm_min"), row.paper.feedRate_mm_min},
                                 {QStringLiteral("paper_spindle_rpm"), row.paper.spindle_rpm},
                                 {QStringLiteral("paper_ra_um"), row.paper.producedRa_um},
                                 {QStringLiteral("settled"), sampleJson(row.settled)}});
    return {{QStringLiteral("axial_depth_mm"), r.setup.axialDepth_mm},
            {QStringLiteral("network_unseen_rms_error"), r.unseenError},
            {QStringLiteral("conditions"), conditions},
            {QStringLiteral("set_force_N"), r.settings.setForce_N},
            {QStringLiteral("adaptive_settled"), sampleJson(r.loop.adaptive.back())},
            {QStringLiteral("uncontrolled"), sampleJson(r.loop.uncontrolled.back())},
            {QStringLiteral("table1"), table}};
}

void printCsv(const SeedExampleResult &r, QTextStream &out)
{
    out << csvLine({QStringLiteral("run"), QStringLiteral("t_s"), QStringLiteral("commanded_feed_rate_mm_min"),
                    QStringLiteral("feed_rate_mm_min"), QStringLiteral("commanded_spindle_rpm"),
                    QStringLiteral("spindle_rpm"), QStringLiteral("force_N"), QStringLiteral("measured_force_N"),
                    QStringLiteral("ra_um")})
        << '\n';
    const auto number = [](double v, int decimals) { return QString::number(v, 'f', decimals); };
    for (const auto &[name, run] : {std::pair{QStringLiteral("adaptive"), &r.loop.adaptive},
                                    std::pair{QStringLiteral("uncontrolled"), &r.loop.uncontrolled}})
        for (const SeedControlSample &s : *run)
            out << csvLine({name, number(s.time_s, 3), number(s.commandedFeedRate_mm_min, 2),
                            number(s.feedRate_mm_min, 2), number(s.commandedSpindle_rpm, 1), number(s.spindle_rpm, 1),
                            number(s.force_N, 2), number(s.measuredForce_N, 2), number(s.ra_um, 4)})
                << '\n';
}

void printSetup(const SeedExampleResult &r, QTextStream &out)
{
    const MillingForceCoefficients &k = r.setup.coefficients;
    out << ControlExample::tr("Čuš & Župerl's end-milling system rebuilt (docs/adaptive.md §9)") << "\n\n"
        << ControlExample::tr("Cut data: mean forces of the linear edge-force model (Altintas 2012 §2.4), Al7075-T6, "
                              "carbide, dry: Ktc %1, Krc %2, Kac %3 N/mm², Kte %4, Kre %5, Kae %6 N/mm (CJME 2021, "
                              "doi:10.1186/s10033-021-00536-9, table 5); 004 gives neither its data nor its material.")
               .arg(k.tangentialCutting_N_mm2)
               .arg(k.radialCutting_N_mm2)
               .arg(k.axialCutting_N_mm2)
               .arg(k.tangentialEdge_N_mm)
               .arg(k.radialEdge_N_mm)
               .arg(k.axialEdge_N_mm)
        << '\n'
        << ControlExample::tr("Tool and cut: Ø%1 mm, %2 flutes, down milling, radial depth %3 mm; axial depth %4 mm, "
                              "at which the model gives the paper's 181.1 N at 324.61 mm/min and 2201 1/min.")
               .arg(r.setup.toolDiameter_mm)
               .arg(r.setup.flutes)
               .arg(r.setup.radialDepth_mm)
               .arg(r.setup.axialDepth_mm, 0, 'f', 3)
        << '\n'
        << ControlExample::tr("Network 8–15–3, ArcTangent, max–min normalised, back-propagation (learning rate 0.05, "
                              "momentum 0.008, 2000 epochs) on 441 cut points: %1 % RMS error on the 400 between them.")
               .arg(100.0 * r.unseenError, 0, 'f', 2)
        << "\n\n";
}

void printConditions(const SeedExampleResult &r, QTextStream &out)
{
    out << ControlExample::tr("Off-line PSO-NN: the largest feed rate within %1 N by the network (%2–%3 mm/min, "
                              "%4–%5 1/min)")
               .arg(r.settings.setForce_N)
               .arg(kSeedLowestFeedRate_mm_min)
               .arg(kSeedHighestFeedRate_mm_min)
               .arg(kSeedLowestSpindle_rpm)
               .arg(kSeedHighestSpindle_rpm)
        << '\n';
    for (const SeedConditions &c : r.conditions)
        out << QStringLiteral("  %1 %2 mm/min %3 1/min %4 N %5")
                   .arg(tuningMethodLibrary(c.method), -22)
                   .arg(c.feedRate_mm_min, 8, 'f', 2)
                   .arg(c.spindle_rpm, 6, 'f', 0)
                   .arg(c.force_N, 7, 'f', 2)
                   .arg(ControlExample::tr("%n evaluation(s) of the network", nullptr, c.evaluations))
            << '\n';
    out << '\n';
}

void printLoop(const SeedExampleResult &r, QTextStream &out)
{
    const SeedControlSample &a = r.loop.adaptive.back();
    const SeedControlSample &u = r.loop.uncontrolled.back();
    out << ControlExample::tr("The loop, table 1 simulation 5: from %1 mm/min and %2 1/min, set force %3 N, %4 s")
               .arg(r.settings.feedRate_mm_min)
               .arg(r.settings.spindle_rpm)
               .arg(r.settings.setForce_N)
               .arg(r.settings.duration_s)
        << '\n';
    const auto line = [&](const QString &what, const SeedControlSample &s) {
        out << QStringLiteral("  %1 %2 mm/min %3 1/min %4 N Ra %5 µm")
                   .arg(what, -14)
                   .arg(s.feedRate_mm_min, 8, 'f', 2)
                   .arg(s.spindle_rpm, 6, 'f', 0)
                   .arg(s.force_N, 7, 'f', 1)
                   .arg(s.ra_um, 0, 'f', 3)
            << '\n';
    };
    line(ControlExample::tr("uncontrolled"), u);
    line(ControlExample::tr("adaptive"), a);
    out << QStringLiteral("  %1 %2 mm/min %3 1/min %4 N Ra %5 µm")
               .arg(ControlExample::tr("paper"), -14)
               .arg(324.61, 8, 'f', 2)
               .arg(2201.0, 6, 'f', 0)
               .arg(181.1, 7, 'f', 1)
               .arg(0.79, 0, 'f', 3)
        << "\n\n";
    out << ControlExample::tr("Table 1, every row from its conditions to its force: settled against the paper") << '\n';
    for (const SeedRowResult &row : r.table)
        out << QStringLiteral("  %1 N: %2 (%3) mm/min %4 (%5) 1/min, Ra %6 (%7) µm%8")
                   .arg(row.paper.force_N, 6, 'f', 1)
                   .arg(row.settled.feedRate_mm_min, 7, 'f', 2)
                   .arg(row.paper.feedRate_mm_min, 7, 'f', 2)
                   .arg(row.settled.spindle_rpm, 5, 'f', 0)
                   .arg(row.paper.spindle_rpm, 5, 'f', 0)
                   .arg(row.settled.ra_um, 0, 'f', 3)
                   .arg(row.paper.producedRa_um, 0, 'f', 2)
                   .arg(outsideSeedNetworkRange(row.settled.feedRate_mm_min, row.settled.spindle_rpm)
                            ? QStringLiteral(" *")
                            : QString())
            << '\n';
    out << ControlExample::tr("  * outside the network's training range: it extrapolates there") << '\n'
        << '\n'
        << ControlExample::tr("note: Ra from the printed M5 (eq. 6), which does not reproduce the paper's table "
                              "(docs/adaptive.md §2). The spindle follows eq. 1 too: 004 gives no spindle model.")
        << '\n';
}

} // namespace

QString controlExampleSynopsis()
{
    return QStringLiteral("control-example [--noise PCT] [--seed N] [--speed-share B] [--duration S] [--json|--csv]");
}

QString controlExampleSummary()
{
    return ControlExample::tr(
        "Čuš & Župerl's own end-milling system rebuilt: the force network trained on cut data, the off-line "
        "PSO-NN optimisation, the loop overriding feed and spindle speed, beside the paper's table 1.");
}

int runControlExample(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QString command = QStringLiteral("control-example");
    const QCommandLineOption json(QStringLiteral("json"), ControlExample::tr("Print the results as JSON."));
    const QCommandLineOption csv(QStringLiteral("csv"),
                                 ControlExample::tr("Print every control period of both runs as CSV."));
    const QCommandLineOption noise(
        QStringLiteral("noise"),
        ControlExample::tr("Machine noise: standard deviation of the measured force in % (default 0)."),
        QStringLiteral("PCT"), QStringLiteral("0"));
    const QCommandLineOption seed(QStringLiteral("seed"), ControlExample::tr("Seed of the noise (default 1)."),
                                  QStringLiteral("N"), QStringLiteral("1"));
    const QCommandLineOption share(
        QStringLiteral("speed-share"),
        ControlExample::tr("Share of a change of chip load the spindle speed takes, 0–1 (default 0.5)."),
        QStringLiteral("B"), QStringLiteral("0.5"));
    const QCommandLineOption duration(QStringLiteral("duration"),
                                      ControlExample::tr("Simulated time in s, 0.1–60 (default 3)."),
                                      QStringLiteral("S"), QStringLiteral("3"));
    parser.addOptions({json, csv, noise, seed, share, duration});
    if (const int stop = parseNamedCommand(parser, command, args, out, err); stop >= 0)
        return stop;
    if (!parser.positionalArguments().isEmpty()) {
        err << programName() << ' ' << command << ": "
            << ControlExample::tr("takes no file: \"%1\"").arg(parser.positionalArguments().constFirst()) << '\n';
        return kExitUsage;
    }
    if (parser.isSet(json) && parser.isSet(csv)) {
        err << programName() << ' ' << command << ": " << ControlExample::tr("give --json or --csv, not both") << '\n';
        return kExitUsage;
    }
    const std::optional<double> noisePct = numberInRange(parser, noise, 0.0, 50.0, command, err);
    const std::optional<long long> seedValue = wholeNumberInRange(parser, seed, 0, 4294967295LL, command, err);
    const std::optional<double> shareValue = numberInRange(parser, share, 0.0, 1.0, command, err);
    const std::optional<double> seconds = numberInRange(parser, duration, 0.1, 60.0, command, err);
    if (!noisePct || !seedValue || !shareValue || !seconds)
        return kExitUsage;
    SeedControlSettings settings;
    settings.forceNoise = *noisePct / 100.0;
    settings.noiseSeed = static_cast<unsigned>(*seedValue);
    settings.speedShare = *shareValue;
    settings.duration_s = *seconds;
    const SeedExampleResult result = runSeedExample(settings);
    if (parser.isSet(json))
        return printJson(exampleJson(result), out, err, command);
    if (parser.isSet(csv)) {
        printCsv(result, out);
        return kExitOk;
    }
    printSetup(result, out);
    printConditions(result, out);
    printLoop(result, out);
    return kExitOk;
}

} // namespace tolturn
