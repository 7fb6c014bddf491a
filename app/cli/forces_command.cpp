// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/forces_command.h"

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

void printCalibration(QTextStream &out, const LiDuCalibration &cal, const LiDuToolGeometry &tool,
                      const std::vector<ForceMeasurement> &cuts)
{
    out << CommandLine::tr("K_n = %1 N/mm², K_f = %2 (Li & Du eq. 15), RMS residual %3 N over %4 cuts")
               .arg(QString::number(cal.coefficients->normalPressure_MPa, 'f', 1),
                    QString::number(cal.coefficients->frictionRatio, 'f', 4),
                    QString::number(cal.rmsResidual_N, 'f', 2))
               .arg(cuts.size())
        << '\n';
    out << CommandLine::tr("   f [mm/rev]  d [mm]   Ft meas   Ft model   Fa meas   Fa model   Fr model [N]") << '\n';
    for (const ForceMeasurement &m : cuts) {
        const CuttingForces f = liDuForces(*cal.coefficients, tool, m.feed_mm_rev, m.depthOfCut_mm).forces;
        out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7")
                   .arg(m.feed_mm_rev, 12, 'f', 3)
                   .arg(m.depthOfCut_mm, 7, 'f', 2)
                   .arg(m.tangential_N, 9, 'f', 1)
                   .arg(f.tangential_N, 10, 'f', 1)
                   .arg(m.axial_N, 9, 'f', 1)
                   .arg(f.axial_N, 10, 'f', 1)
                   .arg(f.radial_N, 10, 'f', 1)
            << '\n';
    }
}

} // namespace

int runCalibrateForces(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), CommandLine::tr("Print the result as JSON."));
    const QCommandLineOption write(
        QStringLiteral("write"), CommandLine::tr("Store K_n and K_f in the project (force model li_du) and save it."));
    parser.addOptions({json, write});
    parser.addPositionalArgument(QStringLiteral("project"),
                                 CommandLine::tr("Project file (its tool gives the geometry)."),
                                 QStringLiteral("PROJECT"));
    parser.addPositionalArgument(
        QStringLiteral("measurements"),
        CommandLine::tr("CSV of measured cuts: feed_mm_rev,depth_of_cut_mm,tangential_N,axial_N."),
        QStringLiteral("MEASUREMENTS.csv"));
    if (const int stop = parseNamedCommand(parser, QStringLiteral("calibrate-forces"), args, out, err); stop >= 0)
        return stop;
    if (parser.positionalArguments().size() != 2) {
        err << programName() << " calibrate-forces: " << CommandLine::tr("give a project file and a measurements file")
            << '\n';
        return kExitUsage;
    }
    const QString projectPath = parser.positionalArguments().at(0);
    const QString csvPath = parser.positionalArguments().at(1);
    ProjectParseResult read = readProjectFile(projectPath);
    MeasurementsReadResult cuts = readForceMeasurements(csvPath);
    Diagnostics problems = read.diagnostics;
    problems.insert(problems.end(), cuts.diagnostics.begin(), cuts.diagnostics.end());
    std::optional<LiDuToolGeometry> tool;
    if (read.project)
        tool = resolveLiDuToolGeometry(*read.project, DataLibrary::builtIn(), problems);
    LiDuCalibration cal;
    if (tool && cuts.measurements) {
        cal = calibrateLiDu(*tool, *cuts.measurements);
        problems.insert(problems.end(), cal.diagnostics.begin(), cal.diagnostics.end());
        for (const ForceMeasurement &m : *cuts.measurements)
            (void)liDuEffectiveLeadAngle_rad(*tool, m.feed_mm_rev, m.depthOfCut_mm, &problems);
    }
    QStringList printed;
    for (const Diagnostic &d : problems) {
        if (!printed.contains(d.toString()))
            err << d.toString() << '\n';
        printed << d.toString();
    }
    if (!cal.coefficients)
        return kExitProblems;
    if (parser.isSet(json)) {
        const QJsonObject result{{QStringLiteral("normal_pressure_MPa"), cal.coefficients->normalPressure_MPa},
                                 {QStringLiteral("friction_ratio"), cal.coefficients->frictionRatio},
                                 {QStringLiteral("rms_residual_N"), cal.rmsResidual_N},
                                 {QStringLiteral("cuts"), static_cast<int>(cuts.measurements->size())}};
        if (const int code = printJson(result, out, err, QStringLiteral("calibrate-forces")); code != kExitOk)
            return code;
    } else {
        printCalibration(out, cal, *tool, *cuts.measurements);
    }
    if (parser.isSet(write)) {
        read.project->cuttingModel.forceModel = ForceModel::LiDu;
        read.project->cuttingModel.normalPressure_MPa = cal.coefficients->normalPressure_MPa;
        read.project->cuttingModel.frictionRatio = cal.coefficients->frictionRatio;
        const WriteResult w = writeProjectFile(projectPath, *read.project);
        if (!w.ok) {
            err << w.error << '\n';
            return kExitProblems;
        }
        err << CommandLine::tr("wrote %1: force model li_du").arg(projectPath) << '\n';
    }
    return kExitOk;
}

} // namespace tolturn
