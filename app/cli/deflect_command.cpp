// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/deflect_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "app/cli/learn_command.h"
#include "core/common/library_info.h"
#include "core/cutting/cutting_quantities.h"
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
#include <limits>
#include <optional>
#include <vector>

namespace tolturn {

namespace {

// The most tool positions `deflect` computes in one run, over all features: a few seconds and a
// JSON result of some megabytes (docs/cli.md).
constexpr qsizetype kMaxStations = 25000; // the default 21 per feature on the largest profile, 1000 segments

} // namespace

namespace {

struct CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};

// The learned correction at every station and the predicted radius error with it; the model's
// provenance and figures (docs/learning.md).
void addLearned(QJsonObject &json, const Project &project, const DeviationResult &r, const LoadedModel &model)
{
    const std::vector<std::vector<double>> learned = learnedAtStations(project, r, model.model);
    QJsonArray features = json.value(QStringLiteral("features")).toArray();
    for (qsizetype f = 0; f < features.size() && f < static_cast<qsizetype>(learned.size()); ++f) {
        QJsonObject feature = features.at(f).toObject();
        QJsonArray stations = feature.value(QStringLiteral("stations")).toArray();
        const std::vector<double> &values = learned[static_cast<std::size_t>(f)];
        const std::vector<Station> &physics = r.features[static_cast<std::size_t>(f)].stations;
        for (qsizetype i = 0; i < stations.size() && i < static_cast<qsizetype>(values.size()); ++i) {
            QJsonObject st = stations.at(i).toObject();
            const double v = values[static_cast<std::size_t>(i)];
            st.insert(QStringLiteral("learned_um"), v * kUmPerMm);
            st.insert(QStringLiteral("radius_error_with_learned_um"),
                      (physics[static_cast<std::size_t>(i)].radiusError_mm + v) * kUmPerMm);
            stations[i] = st;
        }
        feature[QStringLiteral("stations")] = stations;
        features[f] = feature;
    }
    json[QStringLiteral("features")] = features;
    json[QStringLiteral("learned")] =
        QJsonObject{{QStringLiteral("machine"), model.record.machineId},
                    {QStringLiteral("model"), model.record.id},
                    {QStringLiteral("trained_at"), model.record.trainedAt.toUTC().toString(Qt::ISODateWithMs)},
                    {QStringLiteral("parts"), model.record.parts},
                    {QStringLiteral("points"), model.record.points},
                    {QStringLiteral("physics_rms_um"), model.record.physicsRms_mm * kUmPerMm},
                    {QStringLiteral("learned_rms_um"), model.record.learnedRms_mm * kUmPerMm}};
}

void printLearned(QTextStream &out, const Project &project, const DeviationResult &r, const LoadedModel &model)
{
    out << CommandLine::tr("With what was learned of %1 (model %2, %3 parts; parts left out predicted to %4 µm RMS, "
                           "the physics alone %5 µm):")
               .arg(model.record.machineId)
               .arg(model.record.id)
               .arg(model.record.parts)
               .arg(QString::number(model.record.learnedRms_mm * kUmPerMm, 'f', 1),
                    QString::number(model.record.physicsRms_mm * kUmPerMm, 'f', 1))
        << '\n';
    const std::vector<std::vector<double>> learned = learnedAtStations(project, r, model.model);
    for (std::size_t f = 0; f < r.features.size() && f < learned.size(); ++f) {
        const std::vector<Station> &st = r.features[f].stations;
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (std::size_t i = 0; i < st.size() && i < learned[f].size(); ++i) {
            lo = std::min(lo, st[i].radiusError_mm + learned[f][i]);
            hi = std::max(hi, st[i].radiusError_mm + learned[f][i]);
        }
        if (st.empty())
            continue;
        out << QStringLiteral("  %1  ").arg(r.features[f].featureId, -6)
            << CommandLine::tr("radius error %1 … %2 µm")
                   .arg(QString::number(lo * kUmPerMm, 'f', 1), QString::number(hi * kUmPerMm, 'f', 1))
            << '\n';
    }
}

void printDeviationText(QTextStream &out, const DeviationResult &r)
{
    const TurningInputs &in = *r.inputs;
    out << CommandLine::tr("Forces (%1): Fc = %2 N tangential, Ff = %3 N axial, Fp = %4 N radial")
               .arg(forceModelName(in.forceModel), QString::number(in.forces.tangential_N, 'f', 1),
                    QString::number(in.forces.axial_N, 'f', 1), QString::number(in.forces.radial_N, 'f', 1))
        << '\n';
    out << CommandLine::tr("Pass %1 (%2): vc %3 m/min, f %4 mm/rev, ap %5 mm; Ra %6 µm, Rz %7 µm; max %8 kW, %9 N·m")
               .arg(in.passIndex + 1)
               .arg(keyword(in.pass.kind), formatNumber(in.pass.cuttingSpeed_m_min), formatNumber(in.pass.feed_mm_rev),
                    formatNumber(in.pass.depthOfCut_mm),
                    QString::number(theoreticalRa_um(in.pass.feed_mm_rev, in.noseRadius_mm), 'f', 2),
                    QString::number(theoreticalRz_um(in.pass.feed_mm_rev, in.noseRadius_mm), 'f', 2),
                    QString::number(r.maxPower_kW, 'f', 2), QString::number(r.maxTorque_Nm, 'f', 1))
        << '\n';
    if (in.boring)
        out << CommandLine::tr("Boring bar %1 (%2): Fc = %3 N, Ff = %4 N, Fp = %5 N; tip compliance %6 µm/N; Ra %7 µm, "
                               "Rz %8 µm")
                   .arg(in.boring->holderCode, in.boring->barMaterial,
                        QString::number(in.boring->forces.tangential_N, 'f', 1),
                        QString::number(in.boring->forces.axial_N, 'f', 1),
                        QString::number(in.boring->forces.radial_N, 'f', 1),
                        QString::number(in.boring->compliance.transverse_mm_per_N() * kUmPerMm, 'g', 3),
                        QString::number(theoreticalRa_um(in.pass.feed_mm_rev, in.boring->noseRadius_mm), 'f', 2),
                        QString::number(theoreticalRz_um(in.pass.feed_mm_rev, in.boring->noseRadius_mm), 'f', 2))
            << '\n';
    for (const QString &note : in.notes)
        out << CommandLine::tr("note: ") << note << '\n';
    out << CommandLine::tr(
               "feature  side   z from–to [mm]    radial deviation [µm] min … max   diameter error [µm] min … max")
        << '\n';
    for (const FeatureDeviation &f : r.features) {
        double rMin = 1e300, rMax = -1e300, dMin = 1e300, dMax = -1e300;
        for (const Station &st : f.stations) {
            rMin = std::min(rMin, st.radial.total_mm());
            rMax = std::max(rMax, st.radial.total_mm());
            dMin = std::min(dMin, 2.0 * st.radiusError_mm);
            dMax = std::max(dMax, 2.0 * st.radiusError_mm);
        }
        out << QStringLiteral("%1 %2 %3–%4   %5 … %6   %7 … %8")
                   .arg(f.featureId, -8)
                   .arg(contourName(f.side), -6)
                   .arg(f.stations.front().z_mm, 7, 'f', 1)
                   .arg(f.stations.back().z_mm, -7, 'f', 1)
                   .arg(rMin * kUmPerMm, 10, 'f', 2)
                   .arg(rMax * kUmPerMm, -10, 'f', 2)
                   .arg(dMin * kUmPerMm, 10, 'f', 2)
                   .arg(dMax * kUmPerMm, -10, 'f', 2)
            << '\n';
    }
    for (const FaceConicity &f : r.faces)
        out << CommandLine::tr("face %1 at z = %2 mm: tan(theta) = %3, axial run-out e = %4 µm")
                   .arg(f.featureId, formatNumber(f.z_mm), QString::number(f.tanTheta, 'g', 4),
                        QString::number(f.axialRunout_mm * kUmPerMm, 'f', 3))
            << '\n';
}

} // namespace

int runDeflect(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the result as JSON."));
    const QCommandLineOption load(
        QStringLiteral("load"),
        CommandLine::tr("Use these forces [N] instead of the force model: radial, tangential, axial."),
        QStringLiteral("Fr,Ft,Fa"));
    const QCommandLineOption workpieceOnly(
        QStringLiteral("workpiece-only"),
        CommandLine::tr("Rigid machine supports, no toolpost or thermal term: the beam alone."));
    const QCommandLineOption stations(QStringLiteral("stations"),
                                      CommandLine::tr("Tool positions per turned feature (default 21)."),
                                      QStringLiteral("N"), QStringLiteral("21"));
    const QCommandLineOption pass(
        QStringLiteral("pass"),
        CommandLine::tr("Number of the pass, 1 for the first (default: the last finishing pass)."),
        QStringLiteral("N"));
    const QCommandLineOption noInProcess(QStringLiteral("no-in-process"),
                                         CommandLine::tr("Ignore the stock still on the uncut side of the tool."));
    const QCommandLineOption uncorrected(
        QStringLiteral("uncorrected-beam"),
        CommandLine::tr("Plain Timoshenko beam: without the corrections for the root in the jaws and the shoulders "
                        "identified from solid FE."));
    const QCommandLineOption learned(
        QStringLiteral("learned"),
        CommandLine::tr("Add what was learned of the machine from its measured parts (learn --save)."));
    const QCommandLineOption store = measurementStoreOption();
    parser.addOptions(
        {json, load, workpieceOnly, stations, pass, noInProcess, uncorrected, learned, store, operationOption()});
    parser.addPositionalArgument(QStringLiteral("project"), CommandLine::tr("Project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseNamedCommand(parser, QStringLiteral("deflect"), args, out, err); stop >= 0)
        return stop;
    const QString file = oneProjectFile(parser, QStringLiteral("deflect"), err);
    if (file.isEmpty())
        return kExitUsage;
    DeviationOptions options;
    options.workpieceOnly = parser.isSet(workpieceOnly);
    options.inProcessSection = !parser.isSet(noInProcess);
    options.beamCorrections = !parser.isSet(uncorrected);
    bool ok = true;
    options.stationsPerFeature = parser.value(stations).toInt(&ok);
    if (!ok || options.stationsPerFeature < 2 || options.stationsPerFeature > 100000) {
        err << programName() << " deflect: "
            << CommandLine::tr("--stations must be a whole number from 2 to 100000, not \"%1\"")
                   .arg(parser.value(stations))
            << '\n';
        return kExitUsage;
    }
    if (parser.isSet(pass)) { // counted from 1, as the output and the other commands count passes
        const int number = parser.value(pass).toInt(&ok);
        if (!ok || number < 1) {
            err << programName() << " deflect: "
                << CommandLine::tr("--pass must be a pass number (1, 2, …), not \"%1\"").arg(parser.value(pass))
                << '\n';
            return kExitUsage;
        }
        options.passIndex = number - 1;
    }
    if (parser.isSet(load)) {
        options.loadOverride = parseLoad(parser.value(load));
        if (!options.loadOverride) {
            err << programName() << " deflect: "
                << CommandLine::tr("--load takes three numbers in newtons, radial,tangential,axial (e.g. 200,500,150), "
                                   "each at most "
                                   "1e6, not \"%1\"")
                       .arg(parser.value(load))
                << '\n';
            return kExitUsage;
        }
    }
    const std::optional<Project> whole = readProject(file, err);
    if (!whole)
        return kExitProblems;
    const std::optional<Project> project = selectOperation(*whole, parser, QStringLiteral("deflect"), err);
    if (!project)
        return kExitUsage;
    // The stations are per feature: their total bounds the time and the size of the output.
    const auto features = static_cast<qsizetype>(project->part.outer.segments.size()) +
                          static_cast<qsizetype>(project->part.inner.segments.size());
    if (const qsizetype total = features * options.stationsPerFeature; total > kMaxStations) {
        err << programName() << " deflect: "
            << CommandLine::tr("--stations %1 on %2 features makes %3 tool positions, more than the %4 computed at "
                               "once; give at most %5")
                   .arg(options.stationsPerFeature)
                   .arg(features)
                   .arg(total)
                   .arg(kMaxStations)
                   .arg(std::max<qsizetype>(2, kMaxStations / std::max<qsizetype>(1, features)))
            << '\n';
        return kExitUsage;
    }
    const DeviationResult result = computeDeviation(*project, DataLibrary::builtIn(), options);
    for (const Diagnostic &d : result.diagnostics)
        err << file << ": " << d.toString() << '\n';
    if (!result.inputs)
        return kExitProblems;
    std::optional<LoadedModel> model;
    if (parser.isSet(learned)) {
        model = loadLearnedModel(parser.value(store), *project, QStringLiteral("deflect"), err);
        if (!model)
            return kExitProblems;
    }
    if (parser.isSet(json)) {
        QJsonObject result_json = deviationJson(file, *project, result);
        if (model)
            addLearned(result_json, *project, result, *model);
        return printJson(result_json, out, err, QStringLiteral("deflect"));
    }
    printDeviationText(out, result);
    if (model)
        printLearned(out, *project, result, *model);
    return kExitOk;
}

} // namespace tolturn
