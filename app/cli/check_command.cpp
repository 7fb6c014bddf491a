// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/check_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "core/common/finding_groups.h"
#include "core/common/library_info.h"
#include "core/deviation/deviation_model.h"
#include "core/io/force_measurements.h"
#include "core/io/project_file.h"
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
#include <optional>
#include <vector>

namespace tolturn {

namespace {

struct CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};

QString projectSummary(const Project &p)
{
    QString summary = CommandLine::tr("part \"%1\", %2 mm long, %3 outer and %4 inner features, %5, %6, %7")
                          .arg(p.part.name)
                          .arg(p.part.length_mm())
                          .arg(p.part.outer.segments.size())
                          .arg(p.part.inner.segments.size())
                          .arg(displayName(p.clamping.method),
                               CommandLine::tr("%n pass(es)", nullptr, static_cast<int>(p.passes.size())),
                               CommandLine::tr("%n tolerance(s)", nullptr, static_cast<int>(p.tolerances.size())));
    if (!p.milledFeatures.empty())
        summary += CommandLine::tr(", %n milled feature(s)", nullptr, static_cast<int>(p.milledFeatures.size()));
    const int count = operationCount(p);
    if (count == 1)
        return summary;
    QStringList setUps;
    for (int k = 0; k < count; ++k)
        setUps << CommandLine::tr("%1 (%2, %3 end held)")
                      .arg(operationName(p, k), displayName(operationClamping(p, k).method),
                           displayName(operationClamping(p, k).heldEnd));
    return summary + CommandLine::tr("; %n set-up(s): ", nullptr, count) + setUps.join(QStringLiteral(", "));
}

} // namespace

int runCheck(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"),
                                  CommandLine::tr("Print the findings as JSON on standard output."));
    parser.addOption(json);
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project files to check."),
                                 QStringLiteral("PROJECT..."));
    if (const int stop = parseNamedCommand(parser, QStringLiteral("check"), args, out, err); stop >= 0)
        return stop;
    const QStringList files = parser.positionalArguments();
    if (files.isEmpty()) {
        err << programName() << " check: " << CommandLine::tr("no project file given") << '\n';
        return kExitUsage;
    }
    bool anyErrors = false;
    QJsonArray reports;
    for (const QString &file : files) {
        ProjectParseResult result = readProjectFile(file);
        if (result.project) {
            // What the project asks of the data library and the machine (docs/planning.md).
            const Diagnostics plausibility = checkPlausibility(*result.project, DataLibrary::builtIn());
            result.diagnostics.insert(result.diagnostics.end(), plausibility.begin(), plausibility.end());
        }
        const bool valid = result.project.has_value() && !hasErrors(result.diagnostics);
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
        // A finding repeated on several passes is told once, with the passes it is on.
        for (const FindingGroup &g : groupedByIndex(result.diagnostics))
            err << file << ": " << groupText(g) << '\n';
        if (valid)
            out << file << ": " << CommandLine::tr("ok") << " — " << projectSummary(*result.project) << '\n';
    }
    if (parser.isSet(json)) {
        if (const int code = printJson(reports, out, err, QStringLiteral("check")); code != kExitOk)
            return code;
    }
    return anyErrors ? kExitProblems : kExitOk;
}

} // namespace tolturn
