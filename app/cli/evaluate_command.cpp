// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/evaluate_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "app/cli/learn_command.h"
#include "app/cli/milled_feature_output.h"
#include "core/common/diagnostic.h"
#include "core/common/library_info.h"
#include "core/deviation/deviation_model.h"
#include "core/io/force_measurements.h"
#include "core/io/project_file.h"
#include "core/io/result_json.h"
#include "core/planning/clamping_advisor.h"
#include "core/planning/cutting_window.h"
#include "core/planning/finished_extent.h"
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

// The verdicts on physics + what was learned: one prediction, the machine's measured behaviour in
// place of its stiffness range (docs/learning.md).
int evaluateLearned(const QString &file, const Project &project, const QString &store, bool json, QTextStream &out,
                    QTextStream &err)
{
    const std::optional<LoadedModel> model = loadLearnedModel(store, project, QStringLiteral("evaluate"), err);
    if (!model)
        return kExitProblems;
    const QString provenance = model->provenance();
    RangeEvaluation learned = evaluateWithLearned(project, DataLibrary::builtIn(), *model);
    addWhatTheProgramLeaves(project, learned);
    const DeviationResult &deviation = learned.compliant;
    for (const Diagnostic &d : deviation.diagnostics)
        err << file << ": " << d.toString() << '\n';
    if (!deviation.inputs)
        return kExitProblems;
    std::vector<ToleranceEvaluation> verdicts;
    for (const ToleranceRangeEvaluation &e : learned.tolerances)
        verdicts.push_back(e.compliant);
    if (json) {
        QJsonArray list;
        for (const ToleranceEvaluation &e : verdicts)
            list.append(evaluationJson(e));
        QJsonArray diagnostics; // where the plan lies outside what was measured, say
        for (const Diagnostic &d : deviation.diagnostics)
            diagnostics.append(diagnosticJson(d));
        return printJson(
            QJsonObject{{QStringLiteral("file"), file},
                        {QStringLiteral("learned"),
                         QJsonObject{{QStringLiteral("machine"), model->record.machineId},
                                     {QStringLiteral("model"), model->record.id},
                                     {QStringLiteral("parts"), model->record.parts},
                                     {QStringLiteral("physics_rms_um"), 1000.0 * model->record.physicsRms_mm},
                                     {QStringLiteral("learned_rms_um"), 1000.0 * model->record.learnedRms_mm}}},
                        {QStringLiteral("notes"), QJsonArray::fromStringList(deviation.inputs->notes)},
                        {QStringLiteral("diagnostics"), diagnostics},
                        {QStringLiteral("tolerances"), list}},
            out, err, QStringLiteral("evaluate"));
    }
    out << CommandLine::tr("Machine: learned from measured parts (%1); parts left out were predicted to %2 µm RMS, "
                           "the physics alone to %3 µm")
               .arg(provenance, QString::number(1000.0 * model->record.learnedRms_mm, 'f', 1),
                    QString::number(1000.0 * model->record.physicsRms_mm, 'f', 1))
        << '\n';
    for (const ToleranceEvaluation &e : verdicts) {
        const auto number = [](const std::optional<double> &v) {
            return v ? QString::number(*v, 'f', 3) : QStringLiteral("—");
        };
        out << QStringLiteral("%1 %2 %3 %4 %5 %6  %7\n")
                   .arg(e.toleranceId, -10)
                   .arg(displayName(e.type), -23)
                   .arg(e.featureId, -8)
                   .arg(number(e.value_um), 10)
                   .arg(number(e.limit_um), 11)
                   .arg(number(e.utilisation_pct), 8)
                   .arg(verdictName(e.verdict));
    }
    return kExitOk;
}

const Tolerance *toleranceById(const Project &project, const QString &id)
{
    for (const Tolerance &t : project.tolerances) {
        if (t.id == id)
            return &t;
    }
    return nullptr;
}

// The verdicts of one set-up as JSON; a tolerance that spans set-ups carries its re-clamping error.
QJsonObject rangeJson(const Project &project, const RangeEvaluation &range)
{
    QJsonArray list;
    for (const ToleranceRangeEvaluation &e : range.tolerances) {
        QJsonObject o = rangeEvaluationJson(e);
        if (const Tolerance *t = toleranceById(project, e.compliant.toleranceId))
            if (const auto error = reclampingError(project, *t, DataLibrary::builtIn()))
                o.insert(QStringLiteral("reclamping_max_um"), error->max_um);
        list.append(o);
    }
    return {{QStringLiteral("machine_assumption"), machineAssumptionText(range, DataLibrary::builtIn())},
            {QStringLiteral("machine_is_range"), range.machineIsRange},
            {QStringLiteral("rigid_support_assumed"), range.someSupportRigid},
            {QStringLiteral("notes"), QJsonArray::fromStringList(range.compliant.inputs->notes)},
            {QStringLiteral("tolerances"), list}};
}

void printRange(const RangeEvaluation &range, QTextStream &out)
{
    const QString assumption = machineAssumptionText(range, DataLibrary::builtIn());
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
        if (r.range != RangeVerdict::NoRange && r.range != RangeVerdict::NotDecided &&
            r.range != RangeVerdict::NotFinished)
            out << indent << CommandLine::tr("at the compliant end: %1").arg(verdictName(e.verdict)) << '\n';
        if (r.chuck)
            out << indent
                << (r.collet ? CommandLine::tr("collet stiffness needed: %1")
                             : CommandLine::tr("chuck stiffness needed: %1"))
                       .arg(requiredStiffnessText(*r.chuck))
                << '\n';
        if (r.tailstock)
            out << indent << CommandLine::tr("tailstock stiffness needed: %1").arg(requiredStiffnessText(*r.tailstock))
                << '\n';
        if (!e.condition.isEmpty())
            out << indent << e.condition << '\n';
        if (!e.reason.isEmpty())
            out << indent << e.reason << '\n';
    }
}

} // namespace

int runEvaluate(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the verdicts as JSON."));
    const QCommandLineOption learned(
        QStringLiteral("learned"),
        CommandLine::tr("Judge with what was learned of the machine from its measured parts (learn --save)."));
    const QCommandLineOption store = measurementStoreOption();
    parser.addOptions({json, learned, store, operationOption()});
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
    if (parser.isSet(learned)) { // one prediction of one set-up: --operation, or the first
        const std::optional<Project> view = selectOperation(*project, parser, QStringLiteral("evaluate"), err);
        if (!view)
            return kExitUsage;
        return evaluateLearned(file, *view, parser.value(store), parser.isSet(json), out, err);
    }
    // A project of several operations is judged operation by operation, each on its own set-up
    // (docs/operations.md); the tolerances that span set-ups carry the error of clamping again.
    const int count = operationCount(*project);
    int first = 0;
    int last = count - 1;
    if (parser.isSet(QStringLiteral("operation"))) { // one set-up only
        const std::optional<Project> chosen = selectOperation(*project, parser, QStringLiteral("evaluate"), err);
        if (!chosen)
            return kExitUsage;
        first = last = chosen->scope ? chosen->scope->index : 0;
    }
    QJsonArray operations;
    // The milled features belong to the part, not to a set-up of the lathe: judged once.
    const std::vector<MilledFeatureEvaluation> milled = evaluateMilledFeatures(*project);
    for (int k = first; k <= last; ++k) {
        const Project view = operationView(*project, k);
        RangeEvaluation range = evaluateOverStiffnessRange(view, DataLibrary::builtIn());
        addReclampingNotes(view, range, DataLibrary::builtIn());
        addWhatTheProgramLeaves(view, range);
        const DeviationResult &deviation = range.compliant;
        for (const Diagnostic &d : deviation.diagnostics)
            err << file << ": " << (count > 1 ? operationName(*project, k) + QStringLiteral(": ") : QString())
                << d.toString() << '\n';
        if (!deviation.inputs)
            return kExitProblems;
        if (parser.isSet(json)) {
            QJsonObject o = rangeJson(view, range);
            if (count == 1) {
                o.insert(QStringLiteral("file"), file);
                o.insert(QStringLiteral("milled_features"), milledFeaturesJson(*project, milled));
                return printJson(o, out, err, QStringLiteral("evaluate"));
            }
            o.insert(QStringLiteral("name"), operationName(*project, k));
            o.insert(QStringLiteral("held_end"), keyword(view.clamping.heldEnd));
            operations.append(o);
            continue;
        }
        if (count > 1)
            out << (k > 0 ? QStringLiteral("\n") : QString())
                << CommandLine::tr("%1 (operation %2 of %3): %4, the %5 end held")
                       .arg(operationName(*project, k))
                       .arg(k + 1)
                       .arg(count)
                       .arg(displayName(view.clamping.method), displayName(view.clamping.heldEnd))
                << '\n';
        printRange(range, out);
    }
    if (parser.isSet(json))
        return printJson(QJsonObject{{QStringLiteral("file"), file},
                                     {QStringLiteral("operations"), operations},
                                     {QStringLiteral("milled_features"), milledFeaturesJson(*project, milled)}},
                         out, err, QStringLiteral("evaluate"));
    printMilledFeatures(*project, milled, out);
    return kExitOk;
}

} // namespace tolturn
