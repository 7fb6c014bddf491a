// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/measurements_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "core/io/project_json.h"
#include "core/measurements/measurement_csv.h"
#include "core/measurements/measurement_store.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <memory>

namespace tolturn {

namespace {

struct MeasurementsCommand {
    Q_DECLARE_TR_FUNCTIONS(MeasurementsCommand)
};

QString prefix(const QString &action)
{
    return programName() + QStringLiteral(" measurements ") + action + QStringLiteral(": ");
}

std::unique_ptr<MeasurementStore> openStore(const QCommandLineParser &parser, const QString &action, QTextStream &err)
{
    return openMeasurementStore(parser.value(QStringLiteral("store")), prefix(action), err,
                                action == QLatin1String("add") ? StoreAccess::Store : StoreAccess::Read);
}

std::optional<double> numberOption(const QCommandLineParser &parser, const QString &name, const QString &action,
                                   QTextStream &err, bool &bad)
{
    if (!parser.isSet(name))
        return std::nullopt;
    bool ok = false;
    const double v = parser.value(name).toDouble(&ok);
    if (!ok || !std::isfinite(v)) {
        err << prefix(action)
            << MeasurementsCommand::tr("--%1 takes a number, not \"%2\"").arg(name, parser.value(name)) << '\n';
        bad = true;
    }
    return v;
}

std::optional<qint64> partId(const QString &text, const QString &action, QTextStream &err)
{
    bool ok = false;
    const qint64 id = text.toLongLong(&ok);
    if (ok && id > 0)
        return id;
    err << prefix(action) << MeasurementsCommand::tr("a part is named by its number from 1, not \"%1\"").arg(text)
        << '\n';
    return std::nullopt;
}

QJsonObject summaryJson(const MeasuredPartSummary &s)
{
    return {{QStringLiteral("id"), s.id},
            {QStringLiteral("machine"), s.machineId},
            {QStringLiteral("part"), s.partName},
            {QStringLiteral("measured_at"), s.measuredAt.toUTC().toString(Qt::ISODateWithMs)},
            {QStringLiteral("measured_by"), s.measuredBy},
            {QStringLiteral("method"), s.method},
            {QStringLiteral("points"), s.pointCount}};
}

// The drives' readings of the cut from --drive FILE.json (docs/learning.md); `bad` set, with the
// file and the problem named, when it cannot be read.
std::optional<DriveReading> driveOption(const QCommandLineParser &parser, const QString &action, QTextStream &err,
                                        bool &bad)
{
    if (!parser.isSet(QStringLiteral("drive")))
        return std::nullopt;
    const QString path = parser.value(QStringLiteral("drive"));
    QFile file(path);
    QJsonParseError parse{};
    const QJsonDocument doc =
        file.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(file.readAll(), &parse) : QJsonDocument();
    QString error = !file.isOpen()    ? file.errorString()
                    : !doc.isObject() ? MeasurementsCommand::tr("not a JSON object (%1)").arg(parse.errorString())
                                      : QString();
    std::optional<DriveReading> drive = error.isEmpty() ? driveReadingFromJson(doc.object(), &error) : std::nullopt;
    if (!drive) {
        err << prefix(action) << path << ": " << error << '\n';
        bad = true;
    }
    return drive;
}

int runAdd(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QString action = QStringLiteral("add");
    parser.addOptions(
        {measurementStoreOption(),
         {QStringLiteral("csv"),
          MeasurementsCommand::tr("The measured points (feature, z_mm, diameter_mm or "
                                  "radial_deviation_um)."),
          QStringLiteral("FILE.csv")},
         {QStringLiteral("machine"),
          MeasurementsCommand::tr("The machine the part was cut on (default: the project's)."), QStringLiteral("ID")},
         {QStringLiteral("at"), MeasurementsCommand::tr("When it was measured, ISO 8601 (default: now)."),
          QStringLiteral("TIME")},
         {QStringLiteral("by"), MeasurementsCommand::tr("Who measured it."), QStringLiteral("NAME")},
         {QStringLiteral("method"), MeasurementsCommand::tr("How: micrometer, CMM, bore gauge, …"),
          QStringLiteral("METHOD")},
         {QStringLiteral("time-since-start"), MeasurementsCommand::tr("Minutes the machine had run when it was cut."),
          QStringLiteral("MIN")},
         {QStringLiteral("ambient"), MeasurementsCommand::tr("Ambient temperature when it was cut, °C."),
          QStringLiteral("C")},
         {QStringLiteral("note"), MeasurementsCommand::tr("A note."), QStringLiteral("TEXT")},
         {QStringLiteral("drive"),
          MeasurementsCommand::tr("The spindle and feed drives' readings during the finishing cut (JSON: "
                                  "spindle_current_A, spindle_idle_current_A, …; docs/learning.md)."),
          QStringLiteral("FILE.json")}});
    parser.addPositionalArgument(QStringLiteral("project"),
                                 MeasurementsCommand::tr("The project the part was cut from."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseCommand(parser, QStringLiteral("measurements add"),
                                      QStringLiteral("measurements add --csv FILE.csv [OPTIONS] PROJECT"),
                                      MeasurementsCommand::tr("Store a measured part."), args, out, err);
        stop >= 0)
        return stop;
    if (parser.positionalArguments().size() != 1 || !parser.isSet(QStringLiteral("csv"))) {
        err << prefix(action) << MeasurementsCommand::tr("give one project file and --csv FILE.csv") << '\n';
        return kExitUsage;
    }
    bool bad = false;
    MeasuredPart part;
    part.timeSinceStart_min = numberOption(parser, QStringLiteral("time-since-start"), action, err, bad);
    part.ambient_C = numberOption(parser, QStringLiteral("ambient"), action, err, bad);
    part.drive = driveOption(parser, action, err, bad);
    part.measuredAt = parser.isSet(QStringLiteral("at"))
                          ? QDateTime::fromString(parser.value(QStringLiteral("at")), Qt::ISODateWithMs)
                          : QDateTime::currentDateTimeUtc();
    if (!part.measuredAt.isValid()) {
        err << prefix(action)
            << MeasurementsCommand::tr("--at takes a time as 2026-11-24T08:30:00Z, not \"%1\"")
                   .arg(parser.value(QStringLiteral("at")))
            << '\n';
        bad = true;
    }
    if (bad)
        return kExitUsage;
    const QString file = parser.positionalArguments().constFirst();
    const std::optional<Project> project = readProject(file, err);
    if (!project)
        return kExitProblems;
    Diagnostics problems;
    const auto points = readMeasuredPoints(parser.value(QStringLiteral("csv")), problems);
    if (!points) {
        for (const Diagnostic &d : problems)
            err << d.toString() << '\n';
        return kExitProblems;
    }
    part.machineId =
        parser.isSet(QStringLiteral("machine")) ? parser.value(QStringLiteral("machine")) : project->machineId;
    part.measuredBy = parser.value(QStringLiteral("by"));
    part.method = parser.value(QStringLiteral("method"));
    part.note = parser.value(QStringLiteral("note"));
    part.projectJson = serializeProjectJson(*project);
    part.points = *points;
    const auto store = openStore(parser, action, err);
    if (!store)
        return kExitProblems;
    const auto id = store->add(part, problems);
    if (!id) {
        for (const Diagnostic &d : problems)
            err << parser.value(QStringLiteral("csv")) << ": " << d.toString() << '\n';
        return kExitProblems;
    }
    out << MeasurementsCommand::tr("stored part %1: %2, %n point(s), in %3", nullptr, static_cast<int>(points->size()))
               .arg(*id)
               .arg(project->part.name, store->location().describe())
        << '\n';
    return kExitOk;
}

int runList(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QString action = QStringLiteral("list");
    parser.addOptions(
        {measurementStoreOption(),
         {QStringLiteral("machine"), MeasurementsCommand::tr("Only the parts of this machine."), QStringLiteral("ID")},
         {QStringLiteral("text"), MeasurementsCommand::tr("Only parts with this in their name, measurer or method."),
          QStringLiteral("TEXT")},
         {QStringLiteral("limit"), MeasurementsCommand::tr("At most N parts, newest first."), QStringLiteral("N")},
         {QStringLiteral("json"), MeasurementsCommand::tr("Print the list as JSON.")}});
    if (const int stop = parseCommand(parser, QStringLiteral("measurements list"),
                                      QStringLiteral("measurements list [--machine ID] [--text TEXT] [--limit N] "
                                                     "[--json] [--store STORE]"),
                                      MeasurementsCommand::tr("List the stored parts, newest first."), args, out, err);
        stop >= 0)
        return stop;
    PartFilter filter;
    filter.machineId = parser.value(QStringLiteral("machine"));
    filter.text = parser.value(QStringLiteral("text"));
    if (parser.isSet(QStringLiteral("limit"))) {
        bool ok = false;
        filter.limit = parser.value(QStringLiteral("limit")).toInt(&ok);
        if (!ok || filter.limit < 1) {
            err << prefix(action)
                << MeasurementsCommand::tr("--limit takes a number from 1, not \"%1\"")
                       .arg(parser.value(QStringLiteral("limit")))
                << '\n';
            return kExitUsage;
        }
    }
    const auto store = openStore(parser, action, err);
    if (!store)
        return kExitProblems;
    QString error;
    const auto parts = store->list(filter, &error);
    if (!parts) {
        err << prefix(action) << error << '\n';
        return kExitProblems;
    }
    if (parser.isSet(QStringLiteral("json"))) {
        QJsonArray list;
        for (const MeasuredPartSummary &s : *parts)
            list.append(summaryJson(s));
        return printJson(list, out, err, QStringLiteral("measurements list"));
    }
    for (const MeasuredPartSummary &s : *parts)
        out << QStringLiteral("%1  %2  %3  %4  %5  %6\n")
                   .arg(s.id, 6)
                   .arg(s.measuredAt.toUTC().toString(Qt::ISODate), s.machineId, s.partName,
                        MeasurementsCommand::tr("%n point(s)", nullptr, s.pointCount),
                        QStringList{s.measuredBy, s.method}
                            .filter(QRegularExpression(QStringLiteral("\\S")))
                            .join(QStringLiteral(", ")));
    return kExitOk;
}

int runRemove(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QString action = QStringLiteral("remove");
    parser.addOption(measurementStoreOption());
    parser.addPositionalArgument(QStringLiteral("id"), MeasurementsCommand::tr("The part's number."),
                                 QStringLiteral("ID"));
    if (const int stop = parseCommand(parser, QStringLiteral("measurements remove"),
                                      QStringLiteral("measurements remove ID [--store STORE]"),
                                      MeasurementsCommand::tr("Remove a stored part with its points."), args, out, err);
        stop >= 0)
        return stop;
    if (parser.positionalArguments().size() != 1) {
        err << prefix(action) << MeasurementsCommand::tr("give the number of one part") << '\n';
        return kExitUsage;
    }
    const auto id = partId(parser.positionalArguments().constFirst(), action, err);
    if (!id)
        return kExitUsage;
    const auto store = openStore(parser, action, err);
    if (!store)
        return kExitProblems;
    QString error;
    if (!store->remove(*id, &error)) {
        err << prefix(action) << error << '\n';
        return kExitProblems;
    }
    out << MeasurementsCommand::tr("removed part %1").arg(*id) << '\n';
    return kExitOk;
}

int runExport(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QString action = QStringLiteral("export");
    parser.addOptions(
        {measurementStoreOption(),
         {QStringLiteral("machine"), MeasurementsCommand::tr("Every part of this machine."), QStringLiteral("ID")},
         {{QStringLiteral("o"), QStringLiteral("output")},
          MeasurementsCommand::tr("The CSV file to write ('-', the default: standard output)."),
          QStringLiteral("FILE"),
          QStringLiteral("-")}});
    parser.addPositionalArgument(QStringLiteral("id"), MeasurementsCommand::tr("Parts by number."),
                                 QStringLiteral("[ID...]"));
    if (const int stop = parseCommand(parser, QStringLiteral("measurements export"),
                                      QStringLiteral("measurements export [ID...] [--machine ID] [-o FILE.csv] "
                                                     "[--store STORE]"),
                                      MeasurementsCommand::tr("Write stored parts' points as CSV."), args, out, err);
        stop >= 0)
        return stop;
    if (parser.positionalArguments().isEmpty() == !parser.isSet(QStringLiteral("machine"))) {
        err << prefix(action) << MeasurementsCommand::tr("give part numbers or --machine ID") << '\n';
        return kExitUsage;
    }
    if (const QString problem =
            overwritesStore(parser.value(QStringLiteral("output")), parser.value(QStringLiteral("store")));
        !problem.isEmpty()) {
        err << prefix(action) << problem << '\n';
        return kExitUsage;
    }
    std::vector<qint64> ids;
    for (const QString &text : parser.positionalArguments()) {
        const auto id = partId(text, action, err);
        if (!id)
            return kExitUsage;
        ids.push_back(*id);
    }
    const auto store = openStore(parser, action, err);
    if (!store)
        return kExitProblems;
    QString error;
    if (parser.isSet(QStringLiteral("machine"))) {
        PartFilter filter;
        filter.machineId = parser.value(QStringLiteral("machine"));
        const auto parts = store->list(filter, &error);
        if (!parts) {
            err << prefix(action) << error << '\n';
            return kExitProblems;
        }
        for (const MeasuredPartSummary &s : *parts)
            ids.push_back(s.id);
        std::reverse(ids.begin(), ids.end()); // oldest first
    }
    const auto parts = store->parts(ids, &error);
    if (!parts) {
        err << prefix(action) << error << '\n';
        return kExitProblems;
    }
    if (const QString problem =
            writeOutput(parser.value(QStringLiteral("output")), measuredPointsCsv(*parts).toUtf8(), out);
        !problem.isEmpty()) {
        err << prefix(action) << problem << '\n';
        return kExitProblems;
    }
    return kExitOk;
}

} // namespace

QString measurementsSynopsis()
{
    return QStringLiteral("measurements add|list|remove|export [OPTIONS]");
}

QString measurementsSummary()
{
    return MeasurementsCommand::tr(
        "The measurement history of the machines (an SQLite file or a shared PostgreSQL database): store a measured "
        "part with the project it was cut from, list, remove, export as CSV.");
}

int runMeasurements(const QStringList &args, QTextStream &out, QTextStream &err)
{
    const QString action = args.value(1);
    const QStringList rest = QStringList{args.value(0) + QLatin1Char(' ') + action} + args.mid(2);
    if (action == QLatin1String("add"))
        return runAdd(rest, out, err);
    if (action == QLatin1String("list"))
        return runList(rest, out, err);
    if (action == QLatin1String("remove"))
        return runRemove(rest, out, err);
    if (action == QLatin1String("export"))
        return runExport(rest, out, err);
    if (action == QLatin1String("--help") || action == QLatin1String("-h")) {
        out << QStringLiteral("Usage: %1 %2\n\n%3\n").arg(programName(), measurementsSynopsis(), measurementsSummary());
        return kExitOk;
    }
    err << programName()
        << " measurements: " << MeasurementsCommand::tr("say add, list, remove or export, not \"%1\"").arg(action)
        << '\n';
    return kExitUsage;
}

} // namespace tolturn
