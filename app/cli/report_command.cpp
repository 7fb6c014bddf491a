// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/report_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "app/cli/learn_command.h"
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
#include <vector>

namespace tolturn {

namespace {

struct CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};

} // namespace

int runReport(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption output({QStringLiteral("o"), QStringLiteral("output")},
                                    CommandLine::tr("PDF file to write ('-': standard output)."),
                                    QStringLiteral("FILE"));
    const QCommandLineOption planner(
        QStringLiteral("planner"), CommandLine::tr("The planner's name for the title block."), QStringLiteral("NAME"));
    const QCommandLineOption learned(
        QStringLiteral("learned"),
        CommandLine::tr("Base the report on what was learned of the machine from its measured parts (learn --save)."));
    const QCommandLineOption store = measurementStoreOption();
    parser.addOptions({output, planner, learned, store, operationOption()});
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseNamedCommand(parser, QStringLiteral("report"), args, out, err); stop >= 0)
        return stop;
    if (parser.positionalArguments().size() != 1 || !parser.isSet(output)) {
        err << programName() << " report: " << CommandLine::tr("give one project file and -o FILE.pdf") << '\n';
        return kExitUsage;
    }
    const QString file = parser.positionalArguments().constFirst();
    QString problem = overwritesInput(parser.value(output), file);
    if (problem.isEmpty() && parser.isSet(learned))
        problem = overwritesStore(parser.value(output), parser.value(store));
    if (!problem.isEmpty()) {
        err << programName() << " report: " << problem << '\n';
        return kExitUsage;
    }
    const std::optional<Project> whole = readProject(file, err);
    if (!whole)
        return kExitProblems;
    // One set-up at a time: the program and the report of the operation --operation names.
    const std::optional<Project> project = selectOperation(*whole, parser, QStringLiteral("report"), err);
    if (!project)
        return kExitUsage;
    ReportHeader header{QFileInfo(file).fileName(), parser.value(planner), nullptr};
    if (parser.isSet(learned)) {
        auto model = loadLearnedModel(parser.value(store), *project, QStringLiteral("report"), err);
        if (!model)
            return kExitProblems;
        header.learned = std::make_shared<const LoadedModel>(std::move(*model));
    }
    const RenderedReport report = renderReport(*project, header);
    if (const QString unwritten = writeOutput(parser.value(output), report.pdf, out); !unwritten.isEmpty()) {
        err << programName() << " report: " << unwritten << '\n';
        return kExitProblems;
    }
    (isStandardOutput(parser.value(output)) ? err : out)
        << CommandLine::tr("%1: %2 pages").arg(parser.value(output)).arg(report.pages) << '\n';
    return kExitOk;
}

} // namespace tolturn
