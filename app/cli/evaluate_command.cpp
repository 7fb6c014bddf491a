// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/evaluate_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
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

QJsonObject evaluationJson(const ToleranceEvaluation &e)
{
    QJsonObject o{{QStringLiteral("id"), e.toleranceId},      {QStringLiteral("type"), keyword(e.type)},
                  {QStringLiteral("feature"), e.featureId},   {QStringLiteral("verdict"), verdictKeyword(e.verdict)},
                  {QStringLiteral("condition"), e.condition}, {QStringLiteral("reason"), e.reason}};
    const std::pair<const char *, std::optional<double>> numbers[] = {{"value_um", e.value_um},
                                                                      {"limit_um", e.limit_um},
                                                                      {"utilisation_pct", e.utilisation_pct},
                                                                      {"nominal_mm", e.nominal_mm},
                                                                      {"upper_um", e.upper_um},
                                                                      {"lower_um", e.lower_um},
                                                                      {"predicted_max_um", e.predictedMax_um},
                                                                      {"predicted_min_um", e.predictedMin_um},
                                                                      {"offset_um", e.offset_um}};
    for (const auto &[key, value] : numbers) {
        if (value)
            o.insert(QLatin1String(key), *value);
    }
    return o;
}

QString requiredKindKeyword(RequiredStiffness::Kind kind)
{
    switch (kind) {
    case RequiredStiffness::Kind::Found:
        return QStringLiteral("found");
    case RequiredStiffness::Kind::Window:
        return QStringLiteral("window");
    case RequiredStiffness::Kind::AnyStiffness:
        return QStringLiteral("any");
    case RequiredStiffness::Kind::NotReachable:
        return QStringLiteral("not_reachable");
    }
    return {};
}

QJsonValue requiredJson(const std::optional<RequiredStiffness> &r)
{
    if (!r)
        return QJsonValue::Null;
    QJsonObject o{{QStringLiteral("kind"), requiredKindKeyword(r->kind)}};
    if (r->kind != RequiredStiffness::Kind::NotReachable)
        o.insert(QStringLiteral("N_per_um"), r->value_N_per_mm / 1000.0);
    if (r->kind == RequiredStiffness::Kind::Window)
        o.insert(QStringLiteral("fails_again_at_N_per_um"), r->upper_N_per_mm / 1000.0);
    return o;
}

QJsonObject rangeEvaluationJson(const ToleranceRangeEvaluation &e)
{
    QJsonObject o = evaluationJson(e.compliant);
    o.insert(QStringLiteral("range_verdict"), rangeVerdictKeyword(e.range));
    o.insert(QStringLiteral("range_verdict_text"), rangeVerdictText(e));
    if (e.stiff)
        o.insert(QStringLiteral("at_stiff_end"), evaluationJson(*e.stiff));
    o.insert(QStringLiteral("required_chuck_stiffness"), requiredJson(e.chuck));
    o.insert(QStringLiteral("required_tailstock_stiffness"), requiredJson(e.tailstock));
    return o;
}

} // namespace

int runEvaluate(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the verdicts as JSON."));
    parser.addOption(json);
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseNamedCommand(parser, QStringLiteral("evaluate"), args, out, err); stop >= 0)
        return stop;
    const QString file = oneProjectFile(parser, QStringLiteral("evaluate"), err);
    if (file.isEmpty())
        return kExitUsage;
    const std::optional<Project> project = readProject(file, err);
    if (!project)
        return kExitProblems;
    const RangeEvaluation range = evaluateOverStiffnessRange(*project, DataLibrary::builtIn());
    const DeviationResult &deviation = range.compliant;
    for (const Diagnostic &d : deviation.diagnostics)
        err << file << ": " << d.toString() << '\n';
    if (!deviation.inputs)
        return kExitProblems;
    const QString assumption = machineAssumptionText(range, DataLibrary::builtIn());
    if (parser.isSet(json)) {
        QJsonArray list;
        for (const ToleranceRangeEvaluation &e : range.tolerances)
            list.append(rangeEvaluationJson(e));
        return printJson(QJsonObject{{QStringLiteral("file"), file},
                                     {QStringLiteral("machine_assumption"), assumption},
                                     {QStringLiteral("machine_is_range"), range.machineIsRange},
                                     {QStringLiteral("rigid_support_assumed"), range.someSupportRigid},
                                     {QStringLiteral("notes"), QJsonArray::fromStringList(deviation.inputs->notes)},
                                     {QStringLiteral("tolerances"), list}},
                         out, err, QStringLiteral("evaluate"));
    }
    if (!assumption.isEmpty())
        out << CommandLine::tr("Machine: %1").arg(assumption) << '\n';
    out << CommandLine::tr("tolerance  type                    feature  value [µm]  limit [µm]  use [%]  verdict")
        << '\n';
    for (const ToleranceRangeEvaluation &r : range.tolerances) {
        const ToleranceEvaluation &e = r.compliant;
        const auto number = [](const std::optional<double> &v, int width, int decimals) {
            return v ? QStringLiteral("%1").arg(*v, width, 'f', decimals)
                     : QStringLiteral("%1").arg(QStringLiteral("—"), width);
        };
        out << QStringLiteral("%1 %2 %3 %4 %5 %6  %7")
                   .arg(e.toleranceId, -10)
                   .arg(displayName(e.type), -23)
                   .arg(e.featureId, -8)
                   .arg(number(e.value_um, 10, 3), number(e.limit_um, 11, 3), number(e.utilisation_pct, 8, 1),
                        rangeVerdictText(r))
            << '\n';
        const QString indent = QStringLiteral("           ");
        if (r.range != RangeVerdict::NoRange && r.range != RangeVerdict::NotDecided)
            out << indent << CommandLine::tr("at the compliant end: %1").arg(verdictName(e.verdict)) << '\n';
        if (r.chuck)
            out << indent << CommandLine::tr("chuck stiffness needed: %1").arg(requiredStiffnessText(*r.chuck)) << '\n';
        if (r.tailstock)
            out << indent << CommandLine::tr("tailstock stiffness needed: %1").arg(requiredStiffnessText(*r.tailstock))
                << '\n';
        if (!e.condition.isEmpty())
            out << indent << e.condition << '\n';
        if (!e.reason.isEmpty())
            out << indent << e.reason << '\n';
    }
    return kExitOk;
}

} // namespace tolturn
