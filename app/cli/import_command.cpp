// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/import_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "core/cad/step_export.h"
#include "core/cad/step_import.h"
#include "core/data/data_library.h"
#include "core/io/cad_import_json.h"
#include "core/io/project_file.h"
#include "core/project/project_defaults.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTextStream>

#include <algorithm>
#include <optional>
#include <utility>

namespace tolturn {

namespace {

struct ImportCommand {
    Q_DECLARE_TR_FUNCTIONS(ImportCommand)
};

std::optional<int> indexOption(const QCommandLineParser &parser, const QCommandLineOption &option, QTextStream &err)
{
    if (!parser.isSet(option))
        return -1;
    bool ok = false;
    const int value = parser.value(option).toInt(&ok);
    if (ok && value >= 0)
        return value;
    err << programName() << " import: "
        << ImportCommand::tr("--%1 takes a number from 0, not '%2'")
               .arg(option.names().constFirst(), parser.value(option))
        << '\n';
    return std::nullopt;
}

// The ids of the data library's entries (materials, machines), comma-separated.
template <typename Entries>
QString idsOf(const Entries &entries)
{
    QStringList ids;
    for (const auto &entry : entries)
        ids << entry.id;
    return ids.join(QStringLiteral(", "));
}

Project projectFor(const CadImportResult &r, const QString &material, const QString &machine)
{
    Project p = projectForPart(*r.profile);
    p.milledFeatures = r.milledFeatures;
    p.materialId = material;
    p.machineId = machine;
    return p;
}

QJsonObject importJson(const QString &file, const QString &output, const CadImportResult &r, bool written)
{
    QJsonObject json = cadImportJson(r);
    json.insert(QStringLiteral("file"), file);
    json.insert(QStringLiteral("output"), output);
    json.insert(QStringLiteral("written"), written);
    return json;
}

// Writes the project when the import gave a valid profile; the reason otherwise, empty on success.
QString writeImported(const CadImportResult &r, const QString &output, const QString &material, const QString &machine,
                      QTextStream &out)
{
    if (!r.profile || hasErrors(r.diagnostics))
        return ImportCommand::tr("no project written: the import has errors");
    const Project project = projectFor(r, material, machine);
    if (isStandardOutput(output))
        return writeOutput(output, serializeProjectJson(project), out);
    const WriteResult written = writeProjectFile(output, project);
    return written.ok ? QString() : written.error;
}

// The STEP file of `part` at `output`, or on standard output for "-" (OpenCascade writes only
// files: a temporary one is copied).
QString writeStep(const PartProfile &part, const QString &output, QTextStream &out)
{
    if (!isStandardOutput(output)) {
        const StepExportResult written = exportProfileToStep(part, output);
        return written.ok ? QString() : written.error;
    }
    const QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("part.step"));
    if (const StepExportResult written = exportProfileToStep(part, path); !written.ok)
        return written.error;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return ImportCommand::tr("cannot read back '%1': %2").arg(path, file.errorString());
    return writeOutput(output, file.readAll(), out);
}

// The progress on standard error as lines "progress F", a line for each whole percent, flushed for
// the program that reads them.
Progress progressLines(QTextStream &err)
{
    return Progress([&err, last = -1](double fraction) mutable {
        if (const int percent = static_cast<int>(100.0 * fraction); percent != last) {
            last = percent;
            err << "progress " << QString::number(percent / 100.0, 'f', 2) << Qt::endl;
        }
        return true;
    });
}

// One choice of --choose: "SOLID AXIS FLIP", three whole numbers (SOLID and AXIS from 0, or -1 for
// the default; FLIP 0 or 1).
std::optional<CadImportOptions> parseChoice(const QString &line)
{
    const QStringList parts = line.simplified().split(QLatin1Char(' '));
    if (parts.size() != 3)
        return std::nullopt;
    bool ok[3] = {false, false, false};
    CadImportOptions options;
    options.solidIndex = parts.at(0).toInt(&ok[0]);
    options.axisIndex = parts.at(1).toInt(&ok[1]);
    const int flip = parts.at(2).toInt(&ok[2]);
    if (!ok[0] || !ok[1] || !ok[2] || options.solidIndex < -1 || options.axisIndex < -1 || (flip != 0 && flip != 1))
        return std::nullopt;
    options.flip = flip == 1;
    return options;
}

struct ImportTarget {
    QString file;
    QString output;
    QString material;
    QString machine;
};

// Writes the project of one extraction and prints its result as one line of JSON.
void printChoiceResult(const ImportTarget &t, const CadImportResult &r, QTextStream &out, QTextStream &err)
{
    const QString problem = writeImported(r, t.output, t.material, t.machine, out);
    // The reason a sound import was not written goes with its result: the reader of these lines
    // takes each as it comes, before what standard error says after it.
    CadImportResult shown = r;
    if (!problem.isEmpty() && !hasErrors(r.diagnostics))
        shown.diagnostics.push_back(makeError(QStringLiteral("output"), problem));
    out << QJsonDocument(importJson(t.file, t.output, shown, problem.isEmpty())).toJson(QJsonDocument::Compact) << '\n';
    out.flush();
    if (!problem.isEmpty())
        err << programName() << " import: " << problem << Qt::endl;
}

// --choose: the file is read once; the first result is extracted with `options`, then each line
// "SOLID AXIS FLIP" on standard input is extracted from what was read, until the input ends. The
// desktop program reads files this way, so that another body, axis or end is not parsed anew.
int runChoices(const ImportTarget &t, CadImportOptions options, bool progress, QTextStream &out, QTextStream &err)
{
    const Progress whole = progress ? progressLines(err) : Progress();
    CadReadResult read = readCadFile(t.file, Progress(whole, 0.0, 0.8));
    if (!read.model) {
        CadImportResult failed;
        failed.diagnostics = std::move(read.diagnostics);
        failed.cancelled = read.cancelled;
        printChoiceResult(t, failed, out, err);
        return kExitProblems;
    }
    options.progress = Progress(whole, 0.8, 1.0);
    printChoiceResult(t, extractProfile(*read.model, options), out, err);
    QTextStream in(stdin);
    QString line;
    while (in.readLineInto(&line)) {
        std::optional<CadImportOptions> choice = parseChoice(line);
        if (!choice) {
            err << programName() << " import: "
                << ImportCommand::tr(
                       "a choice is three whole numbers \"SOLID AXIS FLIP\" (SOLID and AXIS from 0, -1 for the "
                       "default; FLIP 0 or 1), not '%1'")
                       .arg(line)
                << Qt::endl;
            return kExitUsage;
        }
        if (progress)
            choice->progress = progressLines(err);
        printChoiceResult(t, extractProfile(*read.model, *choice), out, err);
    }
    return kExitOk;
}

} // namespace

QString importSynopsis()
{
    return QStringLiteral(
        "import [--json] [--flip] [--solid N] [--axis N] [--material ID] [--machine ID] [--progress] [--choose] -o "
        "PROJECT FILE");
}

QString importSummary()
{
    return ImportCommand::tr(
        "Turn a STEP (.step, .stp) or IGES (.iges, .igs) part into a new project: the outer and inner contour in "
        "mm, z = 0 at the left end; flats and keyways become milled features, other features that are not turned "
        "(cross holes) are listed as warnings.");
}

int runImport(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), ImportCommand::tr("Print the result as JSON."));
    const QCommandLineOption output({QStringLiteral("o"), QStringLiteral("output")},
                                    ImportCommand::tr("The project file to write ('-': standard output)."),
                                    QStringLiteral("PROJECT"));
    const QCommandLineOption flip(QStringLiteral("flip"),
                                  ImportCommand::tr("Turn the part end for end (z = 0 at the other end)."));
    const QCommandLineOption solid(QStringLiteral("solid"),
                                   ImportCommand::tr("The body to import, from 0 (default: the largest)."),
                                   QStringLiteral("N"));
    const QCommandLineOption axis(QStringLiteral("axis"),
                                  ImportCommand::tr("The axis to turn about, from 0 (default: most revolved area)."),
                                  QStringLiteral("N"));
    const QCommandLineOption material(
        QStringLiteral("material"),
        ImportCommand::tr("The work material's id (default: %1).").arg(QLatin1String(kDefaultMaterialId)),
        QStringLiteral("ID"), QLatin1String(kDefaultMaterialId));
    const QCommandLineOption machine(
        QStringLiteral("machine"),
        ImportCommand::tr("The machine's id (default: %1).").arg(QLatin1String(kDefaultMachineId)),
        QStringLiteral("ID"), QLatin1String(kDefaultMachineId));
    const QCommandLineOption progress(
        QStringLiteral("progress"),
        ImportCommand::tr("Report the progress on standard error, as lines \"progress F\" with F from 0 to 1."));
    const QCommandLineOption choose(
        QStringLiteral("choose"),
        ImportCommand::tr("With --json: read the file once, print each result as one line, then extract again for "
                          "each line \"SOLID AXIS FLIP\" on standard input, until it ends."));
    parser.addOptions({json, output, flip, solid, axis, material, machine, progress, choose});
    parser.addPositionalArgument(QStringLiteral("file"), ImportCommand::tr("The STEP or IGES file."),
                                 QStringLiteral("FILE"));
    if (const int stop =
            parseCommand(parser, QStringLiteral("import"), importSynopsis(), importSummary(), args, out, err);
        stop >= 0)
        return stop;
    if (parser.positionalArguments().size() != 1 || !parser.isSet(output)) {
        err << programName() << " import: " << ImportCommand::tr("give one STEP or IGES file and -o PROJECT") << '\n';
        return kExitUsage;
    }
    const auto solidIndex = indexOption(parser, solid, err);
    const auto axisIndex = indexOption(parser, axis, err);
    if (!solidIndex || !axisIndex)
        return kExitUsage;
    // An id the data library does not know would give a project that does not open: refused before
    // anything is read or written.
    const DataLibrary &data = DataLibrary::builtIn();
    QString unknown;
    if (!data.material(parser.value(material)))
        unknown = ImportCommand::tr("--material: unknown material \"%1\"; the materials are: %2")
                      .arg(parser.value(material), idsOf(data.materials()));
    else if (!data.machine(parser.value(machine)))
        unknown = ImportCommand::tr("--machine: unknown machine \"%1\"; the machines are: %2")
                      .arg(parser.value(machine), idsOf(data.machines()));
    if (!unknown.isEmpty()) {
        err << programName() << " import: " << unknown << '\n';
        return kExitUsage;
    }
    const QString file = parser.positionalArguments().constFirst();
    if (const QString problem = overwritesInput(parser.value(output), file); !problem.isEmpty()) {
        err << programName() << " import: " << problem << '\n';
        return kExitUsage;
    }
    CadImportOptions options;
    options.flip = parser.isSet(flip);
    options.solidIndex = *solidIndex;
    options.axisIndex = *axisIndex;
    const bool toStandardOutput = isStandardOutput(parser.value(output));
    if (toStandardOutput && parser.isSet(json)) {
        err << programName() << " import: " << ImportCommand::tr("--json and -o - would both write to standard output")
            << '\n';
        return kExitUsage;
    }
    if (parser.isSet(choose)) {
        if (!parser.isSet(json) || toStandardOutput) {
            err << programName()
                << " import: " << ImportCommand::tr("--choose needs --json and a project file (-o PROJECT)") << '\n';
            return kExitUsage;
        }
        return runChoices({file, parser.value(output), parser.value(material), parser.value(machine)}, options,
                          parser.isSet(progress), out, err);
    }
    if (parser.isSet(progress))
        options.progress = progressLines(err);
    const CadImportResult r = importCadFile(file, options);
    const QString problem = writeImported(r, parser.value(output), parser.value(material), parser.value(machine), out);
    if (parser.isSet(json)) {
        if (const int code = printJson(importJson(file, parser.value(output), r, problem.isEmpty()), out, err,
                                       QStringLiteral("import"));
            code != kExitOk)
            return code;
    } else {
        for (const Diagnostic &d : r.diagnostics)
            err << file << ": " << d.toString() << '\n';
        if (problem.isEmpty())
            (toStandardOutput ? err : out)
                << ImportCommand::tr("%1: written, part \"%2\", %3 mm long, %4 outer and %5 inner features, %6")
                       .arg(parser.value(output), r.profile->name)
                       .arg(r.profile->length_mm())
                       .arg(r.profile->outer.segments.size())
                       .arg(r.profile->inner.segments.size())
                       .arg(ImportCommand::tr("%n warning(s)", nullptr, static_cast<int>(r.diagnostics.size())))
                << '\n';
    }
    if (!problem.isEmpty()) {
        err << programName() << " import: " << problem << '\n';
        return kExitProblems;
    }
    return kExitOk;
}

QString exportStepSynopsis()
{
    return QStringLiteral("export-step -o FILE.step PROJECT");
}

QString exportStepSummary()
{
    return ImportCommand::tr(
        "Write the project's part as a solid of revolution to a STEP file in mm (AP214), for CAD and CAM.");
}

int runExportStep(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption output({QStringLiteral("o"), QStringLiteral("output")},
                                    ImportCommand::tr("The STEP file to write ('-': standard output)."),
                                    QStringLiteral("FILE.step"));
    parser.addOption(output);
    parser.addPositionalArgument(QStringLiteral("project"), ImportCommand::tr("The project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseCommand(parser, QStringLiteral("export-step"), exportStepSynopsis(), exportStepSummary(),
                                      args, out, err);
        stop >= 0)
        return stop;
    if (parser.positionalArguments().size() != 1 || !parser.isSet(output)) {
        err << programName() << " export-step: " << ImportCommand::tr("give one project file and -o FILE.step") << '\n';
        return kExitUsage;
    }
    const QString file = parser.positionalArguments().constFirst();
    if (const QString problem = overwritesInput(parser.value(output), file); !problem.isEmpty()) {
        err << programName() << " export-step: " << problem << '\n';
        return kExitUsage;
    }
    const ProjectParseResult read = readProjectFile(file);
    for (const Diagnostic &d : read.diagnostics)
        err << file << ": " << d.toString() << '\n';
    if (!read.project)
        return kExitProblems;
    if (const QString problem = writeStep(read.project->part, parser.value(output), out); !problem.isEmpty()) {
        err << programName() << " export-step: " << problem << '\n';
        return kExitProblems;
    }
    (isStandardOutput(parser.value(output)) ? err : out)
        << ImportCommand::tr("%1: written").arg(parser.value(output)) << '\n';
    return kExitOk;
}

} // namespace tolturn
