// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/cli_common.h"

#include "app/cli/command_line.h"
#include "core/common/atomic_file.h"
#include "core/data/data_library.h"
#include "core/io/project_file.h"
#include "core/measurements/measurement_store.h"
#include "core/planning/plausibility.h"
#include "core/project/operations.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileDevice>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {
struct CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};
} // namespace

QString programName()
{
    return QStringLiteral("tolturn-cli");
}

int parseCommand(QCommandLineParser &parser, const QString &name, const QString &synopsis, const QString &summary,
                 const QStringList &args, QTextStream &out, QTextStream &err)
{
    parser.setApplicationDescription(summary);
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")}, CommandLine::tr("Show this help."));
    parser.addOption(help);
    if (!parser.parse(args)) {
        err << programName() << ' ' << name << ": " << parser.errorText() << '\n';
        return kExitUsage;
    }
    if (parser.isSet(help)) {
        out << CommandLine::tr("Usage: %1 %2").arg(programName(), synopsis) << "\n\n"
            << parser.helpText().section(QLatin1Char('\n'), 2);
        return kExitOk;
    }
    // An option given an empty value (--store "") is refused: taken as given it would quietly mean
    // the option's default (the default store, the first operation, ...), which is not what was
    // typed. Free text (a note, who measured, a planner's name) may be empty: it is then none.
    static const QStringList freeText{QStringLiteral("by"), QStringLiteral("method"), QStringLiteral("note"),
                                      QStringLiteral("planner"), QStringLiteral("text")};
    for (const QString &option : parser.optionNames()) {
        const QStringList values = parser.values(option);
        if (!freeText.contains(option) &&
            std::any_of(values.begin(), values.end(), [](const QString &v) { return v.isEmpty(); })) {
            const QString dashes = option.size() == 1 ? QStringLiteral("-") : QStringLiteral("--");
            err << programName() << ' ' << name << ": "
                << CommandLine::tr("%1%2: the value is empty; give one, or leave the option out for its default")
                       .arg(dashes, option)
                << '\n';
            return kExitUsage;
        }
    }
    return -1;
}

std::optional<Project> readProject(const QString &file, QTextStream &err, MissingPasses missingPasses)
{
    const ProjectParseResult read = readProjectFile(file);
    for (const Diagnostic &d : read.diagnostics)
        err << file << ": " << d.toString() << '\n';
    if (!read.project)
        return std::nullopt;
    // What `check` calls an error (an unknown material, no pass, a bar that does not fit the pilot
    // hole) stops every command, as the file's own errors do; its warnings are `check`'s to give.
    bool refused = false;
    const Project &project = *read.project;
    // "passes" or "further_operations[i].passes" of a set-up that has none: the optimiser plans them.
    const auto planned = [&](const QString &field) {
        if (missingPasses != MissingPasses::Planned)
            return false;
        if (field == QLatin1String("passes"))
            return project.passes.empty();
        for (std::size_t i = 0; i < project.furtherOperations.size(); ++i) {
            if (field == QStringLiteral("further_operations[%1].passes").arg(i))
                return project.furtherOperations[i].passes.empty();
        }
        return false;
    };
    for (const Diagnostic &d : checkPlausibility(project, DataLibrary::builtIn())) {
        if (d.severity == Severity::Error && !planned(d.field)) {
            err << file << ": " << d.toString() << '\n';
            refused = true;
        }
    }
    return refused ? std::nullopt : read.project;
}

QCommandLineOption operationOption()
{
    return {QStringLiteral("operation"),
            CommandLine::tr("The operation (set-up) to work on, by its name (default: the first)."),
            QStringLiteral("NAME")};
}

std::optional<Project> selectOperation(const Project &project, const QCommandLineParser &parser, const QString &command,
                                       QTextStream &err)
{
    const int count = operationCount(project);
    QStringList names;
    for (int k = 0; k < count; ++k)
        names << operationName(project, k);
    const QString wanted = parser.value(QStringLiteral("operation"));
    const auto index = wanted.isEmpty() ? qsizetype(0) : names.indexOf(wanted);
    if (index < 0) {
        err << programName() << ' ' << command << ": "
            << CommandLine::tr("--operation: the project has no operation \"%1\"; it has: %2")
                   .arg(wanted, names.join(QStringLiteral(", ")))
            << '\n';
        return std::nullopt;
    }
    if (count > 1 && wanted.isEmpty())
        err << programName() << ' ' << command << ": "
            << CommandLine::tr("the project has %1 operations (%2); this is %3 (--operation NAME for another)")
                   .arg(count)
                   .arg(names.join(QStringLiteral(", ")), names.front())
            << '\n';
    return operationView(project, static_cast<int>(index));
}

namespace {

// Whether writing `output` would replace `input`, by any spelling of its path or a link to it.
bool replaces(const QString &output, const QString &input)
{
    if (isStandardOutput(output))
        return false;
    const QFileInfo target(output);
    const QFileInfo source(input);
    return target.exists() && source.exists() && target.canonicalFilePath() == source.canonicalFilePath();
}

} // namespace

QString overwritesInput(const QString &output, const QString &input)
{
    if (!replaces(output, input))
        return {};
    return CommandLine::tr("the output '%1' is the input file '%2': give another output file, so that the input is "
                           "not overwritten")
        .arg(output, input);
}

QString overwritesStore(const QString &output, const QString &store)
{
    const std::optional<StoreLocation> location =
        store.isEmpty() ? std::optional<StoreLocation>(defaultStoreLocation()) : storeLocationFromText(store, nullptr);
    if (!location || location->kind != StoreLocation::Kind::SQLite)
        return {}; // a store that cannot be named is refused when it is opened; a server is no file
    if (!replaces(output, location->file))
        return {};
    return CommandLine::tr("the output '%1' is the measurement store '%2': give another output file, so that the "
                           "store is not overwritten")
        .arg(output, location->file);
}

QString writeOutput(const QString &path, const QByteArray &data, QTextStream &out)
{
    if (path == QLatin1String("-")) {
        // The bytes as they are (a PDF or STEP file too), after whatever the stream holds.
        out.flush();
        if (auto *device = qobject_cast<QFileDevice *>(out.device())) {
            if (device->write(data) != data.size() || !device->flush())
                return CommandLine::tr("cannot write to standard output: %1").arg(device->errorString());
        } else {
            out << QString::fromUtf8(data);
            out.flush();
        }
        return {};
    }
    return writeFileAtomically(path, data);
}

int parseNamedCommand(QCommandLineParser &parser, const QString &name, const QStringList &args, QTextStream &out,
                      QTextStream &err)
{
    const CommandHelp help = commandHelp(name);
    return parseCommand(parser, name, help.synopsis, help.summary, args, out, err);
}

QString oneProjectFile(const QCommandLineParser &parser, const QString &command, QTextStream &err)
{
    if (parser.positionalArguments().size() == 1)
        return parser.positionalArguments().constFirst();
    err << programName() << ' ' << command << ": " << CommandLine::tr("give exactly one project file") << '\n';
    return {};
}

namespace {

// The path ("tolerances[2].value_um") of the first number in `v` that is not finite; empty if none.
QString firstNonFinite(const QJsonValue &v, const QString &path)
{
    if (v.isDouble())
        return std::isfinite(v.toDouble()) ? QString() : path;
    if (v.isArray()) {
        const QJsonArray array = v.toArray();
        for (qsizetype i = 0; i < array.size(); ++i)
            if (QString found = firstNonFinite(array.at(i), QStringLiteral("%1[%2]").arg(path).arg(i));
                !found.isEmpty())
                return found;
    } else if (v.isObject()) {
        const QJsonObject object = v.toObject();
        for (auto it = object.begin(); it != object.end(); ++it)
            if (QString found =
                    firstNonFinite(it.value(), path.isEmpty() ? it.key() : path + QLatin1Char('.') + it.key());
                !found.isEmpty())
                return found;
    }
    return {};
}

} // namespace

int printJson(const QJsonValue &result, QTextStream &out, QTextStream &err, const QString &command)
{
    if (const QString bad = firstNonFinite(result, QString()); !bad.isEmpty()) {
        err << programName() << ' ' << command << ": "
            << CommandLine::tr("the result is not finite at '%1': the inputs lie beyond what the model computes "
                               "(see the input bounds in docs/project-format.md)")
                   .arg(bad)
            << '\n';
        return kExitProblems;
    }
    out << (result.isArray() ? QJsonDocument(result.toArray()) : QJsonDocument(result.toObject()))
               .toJson(QJsonDocument::Indented);
    return kExitOk;
}

std::optional<CuttingForces> parseLoad(const QString &text)
{
    const QStringList parts = text.split(QLatin1Char(','));
    if (parts.size() != 3)
        return std::nullopt;
    double v[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        bool ok = false;
        v[i] = parts.at(i).trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(v[i]) || std::abs(v[i]) > kMaxLoad_N)
            return std::nullopt;
    }
    return CuttingForces{v[1], v[2], v[0]};
}

QCommandLineOption measurementStoreOption()
{
    return {QStringLiteral("store"),
            QCoreApplication::translate("CommandLine",
                                        "The measurement store: an SQLite file, or "
                                        "postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE (default: %1).")
                .arg(defaultStoreLocation().describe()),
            QStringLiteral("STORE")};
}

std::unique_ptr<MeasurementStore> openMeasurementStore(const QString &store, const QString &prefix, QTextStream &err,
                                                       StoreAccess access)
{
    QString error;
    const std::optional<StoreLocation> location =
        store.isEmpty() ? std::optional<StoreLocation>(defaultStoreLocation()) : storeLocationFromText(store, &error);
    if (location && access == StoreAccess::Read && location->kind == StoreLocation::Kind::SQLite &&
        !QFileInfo::exists(location->file)) {
        err << prefix
            << CommandLine::tr("there is no measurement store %1: 'measurements add' stores the first part in it")
                   .arg(location->file)
            << '\n';
        return nullptr;
    }
    std::unique_ptr<MeasurementStore> opened = location ? MeasurementStore::open(*location, &error) : nullptr;
    if (!opened)
        err << prefix << error << '\n';
    return opened;
}

std::optional<double> numberInRange(const QCommandLineParser &parser, const QCommandLineOption &option, double lo,
                                    double hi, const QString &command, QTextStream &err)
{
    bool ok = false;
    const double v = parser.value(option).toDouble(&ok);
    if (ok && v >= lo && v <= hi)
        return v;
    err << programName() << ' ' << command << ": "
        << CommandLine::tr("--%1: \"%2\" is not a number from %3 to %4")
               .arg(option.names().constFirst(), parser.value(option), QString::number(lo), QString::number(hi))
        << '\n';
    return std::nullopt;
}

std::optional<long long> wholeNumberInRange(const QCommandLineParser &parser, const QCommandLineOption &option,
                                            long long lo, long long hi, const QString &command, QTextStream &err)
{
    bool ok = false;
    const long long v = parser.value(option).toLongLong(&ok);
    if (ok && v >= lo && v <= hi)
        return v;
    err << programName() << ' ' << command << ": "
        << CommandLine::tr("--%1: \"%2\" is not a whole number from %3 to %4")
               .arg(option.names().constFirst(), parser.value(option))
               .arg(lo)
               .arg(hi)
        << '\n';
    return std::nullopt;
}

} // namespace tolturn
