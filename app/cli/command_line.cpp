// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/command_line.h"

#include "core/common/library_info.h"
#include "core/io/project_file.h"
#include "core/project/keywords.h"
#include "widgets/dialogs/about_dialog.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <functional>
#include <vector>

namespace tolturn {

namespace {

struct CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};

QString tr(const char *text)
{
    return CommandLine::tr(text);
}

using Handler = std::function<int(const QStringList &, QTextStream &, QTextStream &)>;

struct Command {
    QString name;
    QString synopsis;
    QString summary;
    Handler run;
};

const std::vector<Command> &commands();

QString programName()
{
    return QStringLiteral("tolturn-cli");
}

QString usage()
{
    QString text = tr("Usage: %1 [--help] [--version] COMMAND [ARGUMENTS]\n\n"
                      "TolTurn's command-line front end: the same computations as the desktop program, "
                      "headless, for batch use and regression tests.\n\nCommands:\n")
                       .arg(programName());
    for (const Command &c : commands())
        text += QStringLiteral("  %1\n      %2\n").arg(c.synopsis, c.summary);
    text += tr("\nRun '%1 COMMAND --help' for the options of a command.\n"
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

// Parses the options of one command; handles --help. Returns nullopt-like -1 to go on, or an
// exit code when the command must stop here.
int parseCommand(QCommandLineParser &parser, const Command &command, const QStringList &args, QTextStream &out,
                 QTextStream &err)
{
    parser.setApplicationDescription(command.summary);
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")}, tr("Show this help."));
    parser.addOption(help);
    if (!parser.parse(args)) {
        err << programName() << ' ' << command.name << ": " << parser.errorText() << '\n';
        return kExitUsage;
    }
    if (parser.isSet(help)) {
        out << tr("Usage: %1 %2").arg(programName(), command.synopsis) << "\n\n"
            << parser.helpText().section(QLatin1Char('\n'), 2);
        return kExitOk;
    }
    return -1;
}

QJsonObject diagnosticJson(const Diagnostic &d)
{
    return {{QStringLiteral("severity"),
             d.severity == Severity::Error ? QStringLiteral("error") : QStringLiteral("warning")},
            {QStringLiteral("field"), d.field},
            {QStringLiteral("message"), d.message}};
}

QString projectSummary(const Project &p)
{
    return tr("part \"%1\", %2 mm long, %3 outer and %4 inner features, %5, %6 passes, %7 tolerances")
        .arg(p.part.name)
        .arg(p.part.length_mm())
        .arg(p.part.outer.segments.size())
        .arg(p.part.inner.segments.size())
        .arg(keyword(p.clamping.method))
        .arg(p.passes.size())
        .arg(p.tolerances.size());
}

int runCheck(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), tr("Print the findings as JSON on standard output."));
    parser.addOption(json);
    parser.addPositionalArgument(QStringLiteral("project"), tr("Project files to check."),
                                 QStringLiteral("PROJECT..."));
    if (const int stop = parseCommand(parser, commands().at(0), args, out, err); stop >= 0)
        return stop;
    const QStringList files = parser.positionalArguments();
    if (files.isEmpty()) {
        err << programName() << " check: " << tr("no project file given") << '\n';
        return kExitUsage;
    }
    bool anyErrors = false;
    QJsonArray reports;
    for (const QString &file : files) {
        const ProjectParseResult result = readProjectFile(file);
        const bool valid = result.project.has_value();
        anyErrors = anyErrors || !valid;
        if (parser.isSet(json)) {
            QJsonArray list;
            for (const Diagnostic &d : result.diagnostics)
                list.append(diagnosticJson(d));
            reports.append(QJsonObject{{QStringLiteral("file"), file},
                                       {QStringLiteral("valid"), valid},
                                       {QStringLiteral("diagnostics"), list}});
            continue;
        }
        for (const Diagnostic &d : result.diagnostics)
            err << file << ": " << d.toString() << '\n';
        if (valid)
            out << file << ": " << tr("ok") << " — " << projectSummary(*result.project) << '\n';
    }
    if (parser.isSet(json))
        out << QJsonDocument(reports).toJson(QJsonDocument::Indented);
    return anyErrors ? kExitProblems : kExitOk;
}

const std::vector<Command> &commands()
{
    static const std::vector<Command> list{
        {QStringLiteral("check"), QStringLiteral("check [--json] PROJECT..."),
         tr("Validate project files: report every problem with the field and value; exit 1 on errors."), runCheck},
    };
    return list;
}

} // namespace

int runCommandLine(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    const QStringList args = arguments.mid(1);
    if (args.isEmpty()) {
        err << usage();
        return kExitUsage;
    }
    const QString &first = args.constFirst();
    if (first == QLatin1String("--help") || first == QLatin1String("-h") || first == QLatin1String("help")) {
        out << usage();
        return kExitOk;
    }
    if (first == QLatin1String("--version") || first == QLatin1String("-v")) {
        out << versionText();
        return kExitOk;
    }
    for (const Command &c : commands()) {
        if (c.name == first)
            return c.run(QStringList{programName() + QLatin1Char(' ') + c.name} + args.mid(1), out, err);
    }
    err << tr("%1: unknown command '%2'. Run '%1 --help' for the list of commands.").arg(programName(), first) << '\n';
    return kExitUsage;
}

} // namespace tolturn
