// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/iso286_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
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
#include <vector>

namespace tolturn {

namespace {

// A negative nominal size ("-5") would be read as an option. Both commands take only flags, so the
// flags go first and everything else after "--", where the parser takes it as it stands and the
// size check names it ("the nominal size must be above 0 mm, but is -5 mm").
QStringList negativeSizesAsPositional(const QStringList &args)
{
    const auto isNegativeNumber = [](const QString &a) {
        return a.size() > 1 && a.at(0) == QLatin1Char('-') && (a.at(1).isDigit() || a.at(1) == QLatin1Char('.'));
    };
    if (args.contains(QStringLiteral("--")) || std::none_of(args.begin(), args.end(), isNegativeNumber))
        return args;
    QStringList flags{args.value(0)};
    QStringList rest{QStringLiteral("--")};
    for (qsizetype i = 1; i < args.size(); ++i)
        (args.at(i).startsWith(QLatin1Char('-')) && !isNegativeNumber(args.at(i)) ? flags : rest) << args.at(i);
    return flags + rest;
}

struct CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};

QString signedUm(double v)
{
    return (v > 0.0 ? QStringLiteral("+") : QString()) + formatNumber(v);
}

void printDiagnostics(QTextStream &err, const Diagnostics &diagnostics)
{
    for (const Diagnostic &d : diagnostics)
        err << d.toString() << '\n';
}

// A nominal size argument: a number in mm, else a usage error naming it.
std::optional<double> nominalArgument(const QString &text, const QString &command, QTextStream &err)
{
    bool ok = false;
    const double v = QString(text).replace(QLatin1Char(','), QLatin1Char('.')).toDouble(&ok);
    if (!ok || !std::isfinite(v)) {
        err << programName() << ' ' << command << ": "
            << CommandLine::tr("the nominal size must be a number in mm, not \"%1\"").arg(text) << '\n';
        return std::nullopt;
    }
    return v;
}

} // namespace

int runIso286(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the limits as JSON."));
    parser.addOption(json);
    parser.addPositionalArgument(QStringLiteral("nominal"), CommandLine::tr("Nominal size [mm]."),
                                 QStringLiteral("NOMINAL"));
    parser.addPositionalArgument(QStringLiteral("class"), CommandLine::tr("Tolerance class, e.g. H7, g6, js12."),
                                 QStringLiteral("CLASS"));
    if (const int stop = parseNamedCommand(parser, QStringLiteral("iso286"), negativeSizesAsPositional(args), out, err);
        stop >= 0)
        return stop;
    if (parser.positionalArguments().size() != 2) {
        err << programName() << " iso286: " << CommandLine::tr("give a nominal size and a tolerance class, e.g. 50 H7")
            << '\n';
        return kExitUsage;
    }
    const auto nominal = nominalArgument(parser.positionalArguments().at(0), QStringLiteral("iso286"), err);
    if (!nominal)
        return kExitUsage;
    const iso286::LimitsResult r = iso286::limits(*nominal, parser.positionalArguments().at(1));
    printDiagnostics(err, r.diagnostics);
    if (!r.limits)
        return kExitProblems;
    if (parser.isSet(json))
        return printJson(classLimitsJson(*r.limits), out, err, QStringLiteral("iso286"));
    out << CommandLine::tr("%1 %2: upper %3 µm, lower %4 µm (%5 = %6 µm)")
               .arg(formatNumber(*nominal), r.limits->toleranceClass, signedUm(r.limits->upper_um),
                    signedUm(r.limits->lower_um), r.limits->itName, formatNumber(r.limits->it_um))
        << '\n';
    return kExitOk;
}

int runFit(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the fit as JSON."));
    parser.addOption(json);
    parser.addPositionalArgument(QStringLiteral("nominal"), CommandLine::tr("Nominal size [mm]."),
                                 QStringLiteral("NOMINAL"));
    parser.addPositionalArgument(QStringLiteral("fit"), CommandLine::tr("Hole and shaft class, e.g. H7/g6."),
                                 QStringLiteral("HOLE/SHAFT"));
    if (const int stop = parseNamedCommand(parser, QStringLiteral("fit"), negativeSizesAsPositional(args), out, err);
        stop >= 0)
        return stop;
    const QStringList positional = parser.positionalArguments();
    const QStringList classes = positional.value(1).split(QLatin1Char('/'));
    if (positional.size() != 2 || classes.size() != 2) {
        err << programName() << " fit: " << CommandLine::tr("give a nominal size and a fit, e.g. 50 H7/g6") << '\n';
        return kExitUsage;
    }
    const auto nominal = nominalArgument(positional.at(0), QStringLiteral("fit"), err);
    if (!nominal)
        return kExitUsage;
    const iso286::FitResult r = iso286::fit(*nominal, classes.at(0).trimmed(), classes.at(1).trimmed());
    printDiagnostics(err, r.diagnostics);
    if (!r.fit)
        return kExitProblems;
    const iso286::Fit &f = *r.fit;
    if (parser.isSet(json)) {
        if (const int code = printJson(QJsonObject{{QStringLiteral("nominal_mm"), *nominal},
                                                   {QStringLiteral("hole"), classLimitsJson(f.hole)},
                                                   {QStringLiteral("shaft"), classLimitsJson(f.shaft)},
                                                   {QStringLiteral("type"), iso286::fitTypeKeyword(f.type)},
                                                   {QStringLiteral("max_clearance_um"), f.maxClearance_um},
                                                   {QStringLiteral("min_clearance_um"), f.minClearance_um}},
                                       out, err, QStringLiteral("fit"));
            code != kExitOk)
            return code;
    } else {
        out << CommandLine::tr(
                   "%1 %2/%3: %4 fit; hole %5/%6 µm, shaft %7/%8 µm; clearance max %9 µm, min %10 µm (negative: "
                   "interference)")
                   .arg(formatNumber(*nominal), f.hole.toleranceClass, f.shaft.toleranceClass,
                        iso286::fitTypeName(f.type), signedUm(f.hole.upper_um), signedUm(f.hole.lower_um),
                        signedUm(f.shaft.upper_um), signedUm(f.shaft.lower_um))
                   .arg(formatNumber(f.maxClearance_um), formatNumber(f.minClearance_um))
            << '\n';
    }
    return kExitOk;
}

} // namespace tolturn
