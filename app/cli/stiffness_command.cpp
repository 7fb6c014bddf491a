// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/stiffness_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "core/deviation/stiffness_calibration.h"
#include "core/io/project_file.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDate>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

namespace tolturn {

namespace {

struct StiffnessCommand {
    Q_DECLARE_TR_FUNCTIONS(StiffnessCommand)
};

QJsonValue fitJson(const std::optional<SpringFit> &fit)
{
    if (!fit)
        return QJsonValue::Null;
    return QJsonObject{{QStringLiteral("k1_N_per_mm"), fit->springs.k1_N_per_mm},
                       {QStringLiteral("k2_Nmm_per_rad"), fit->springs.k2_Nmm_per_rad},
                       {QStringLiteral("k3_Nmm_per_rad"), fit->springs.k3_Nmm_per_rad},
                       {QStringLiteral("a_per_mm"), fit->a_per_mm},
                       {QStringLiteral("b"), fit->b},
                       {QStringLiteral("c_mm"), fit->c_mm},
                       {QStringLiteral("rms_residual_um"), fit->rmsResidual_um},
                       {QStringLiteral("points"), fit->points}};
}

// `problems`: everything said about the test bar's project, its measurements and the fit.
QJsonObject calibrationJson(const StiffnessCalibration &cal, const Diagnostics &problems)
{
    QJsonArray diagnostics;
    for (const Diagnostic &d : problems)
        diagnostics.append(diagnosticJson(d));
    return {{QStringLiteral("pivot_distance_mm"), cal.pivotDistance_mm},
            {QStringLiteral("diameter_mm"), cal.diameter_mm},
            {QStringLiteral("forces"), QJsonObject{{QStringLiteral("radial_N"), cal.forces.radial_N},
                                                   {QStringLiteral("tangential_N"), cal.forces.tangential_N},
                                                   {QStringLiteral("axial_N"), cal.forces.axial_N}}},
            {QStringLiteral("bar_share_at_end"), cal.barShareAtEnd},
            {QStringLiteral("radial"), fitJson(cal.radial)},
            {QStringLiteral("tangential"), fitJson(cal.tangential)},
            {QStringLiteral("diagnostics"), diagnostics}};
}

QString fitLine(const QString &direction, const SpringFit &fit)
{
    return StiffnessCommand::tr("  %1: k1 = %2 N/mm, k2 = %3 N·mm/rad, k3 = %4 N·mm/rad; RMS residual %5 µm over %6 "
                                "points")
        .arg(direction, QString::number(fit.springs.k1_N_per_mm, 'e', 4),
             QString::number(fit.springs.k2_Nmm_per_rad, 'e', 4), QString::number(fit.springs.k3_Nmm_per_rad, 'e', 4),
             QString::number(fit.rmsResidual_um, 'f', 2))
        .arg(fit.points);
}

void printCalibration(QTextStream &out, const StiffnessCalibration &cal)
{
    out << StiffnessCommand::tr(
               "Spindle–chuck springs from the test bar (Valiño et al. 2008 §III): Lc = %1 mm, Ø%2 mm, "
               "F_r = %3 N, F_t = %4 N, F_a = %5 N")
               .arg(cal.pivotDistance_mm)
               .arg(cal.diameter_mm)
               .arg(QString::number(cal.forces.radial_N, 'f', 1), QString::number(cal.forces.tangential_N, 'f', 1),
                    QString::number(cal.forces.axial_N, 'f', 1))
        << '\n'
        << fitLine(StiffnessCommand::tr("radial"), *cal.radial) << '\n';
    if (cal.tangential)
        out << fitLine(StiffnessCommand::tr("tangential"), *cal.tangential) << '\n';
    else if (cal.tangentialPositions == 0)
        out << StiffnessCommand::tr("  tangential: not measured (no tangential_um column)") << '\n';
    else
        out << StiffnessCommand::tr("  tangential: not fitted (the warning above says why)") << '\n';
    out << StiffnessCommand::tr("The bar's own bending and the toolpost, subtracted before the fit: %1 % of the "
                                "deviation measured farthest from the chuck.")
               .arg(QString::number(100.0 * cal.barShareAtEnd, 'f', 1))
        << '\n';
}

// Stores the fitted springs in `target`'s characterisation, keeping everything else it has; only
// in a project for the machine the test bar was cut on (`machineId`).
QString writeSprings(const QString &target, const StiffnessCalibration &cal, const QString &measurements,
                     const QString &machineId, QTextStream &err)
{
    ProjectParseResult read = readProjectFile(target);
    if (!read.project)
        return read.diagnostics.empty() ? target : read.diagnostics.front().toString();
    if (read.project->machineId != machineId)
        return StiffnessCommand::tr("%1 is planned for machine \"%2\", but the test bar was cut on \"%3\": its "
                                    "springs are that machine's; nothing written")
            .arg(target, read.project->machineId, machineId);
    const QString source =
        StiffnessCommand::tr("Test bar fit (Valiño et al. 2008 §III), tolturn-cli calibrate-stiffness, %1, %2: "
                             "%3 points, RMS residual %4 µm")
            .arg(QFileInfo(measurements).fileName(), QDate::currentDate().toString(Qt::ISODate))
            .arg(cal.radial->points)
            .arg(QString::number(cal.radial->rmsResidual_um, 'f', 2));
    if (const QString stale = staleTangentialSprings(read.project->characterisation, cal); !stale.isEmpty())
        err << target << ": " << stale << '\n';
    read.project->characterisation = withFittedSprings(read.project->characterisation, cal, source);
    const WriteResult w = writeProjectFile(target, *read.project);
    return w.ok ? QString() : w.error;
}

} // namespace

QString calibrateStiffnessSynopsis()
{
    return QStringLiteral("calibrate-stiffness [--json] [--pivot MM] [--load Fr,Ft,Fa] [--write | --into PROJECT] "
                          "TESTBAR MEASUREMENTS.csv");
}

QString calibrateStiffnessSummary()
{
    return StiffnessCommand::tr(
        "Fit the spindle–chuck springs k1, k2, k3 (radial, and tangential where measured) to the measured deviation "
        "of a test bar turned in the chuck (Valiño et al. 2008 §III); --write stores them in the test bar's "
        "project, --into in another project on the same machine.");
}

int runCalibrateStiffness(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), StiffnessCommand::tr("Print the result as JSON."));
    const QCommandLineOption pivot(
        QStringLiteral("pivot"),
        StiffnessCommand::tr("Lc: distance of the front spindle bearing behind the chuck face, in mm (default: the "
                             "project's characterisation)."),
        QStringLiteral("MM"));
    const QCommandLineOption load(QStringLiteral("load"),
                                  StiffnessCommand::tr("Measured forces of the test cut in newtons, radial,tangential,"
                                                       "axial (default: the project's force model)."),
                                  QStringLiteral("Fr,Ft,Fa"));
    const QCommandLineOption write(QStringLiteral("write"),
                                   StiffnessCommand::tr("Store the springs in the test bar's project and save it."));
    const QCommandLineOption into(QStringLiteral("into"),
                                  StiffnessCommand::tr("Store the springs in this project instead and save it."),
                                  QStringLiteral("PROJECT"));
    parser.addOptions({json, pivot, load, write, into});
    parser.addPositionalArgument(
        QStringLiteral("testbar"),
        StiffnessCommand::tr("Project of the test bar as cut: chuck only, its part, tool, material and pass."),
        QStringLiteral("TESTBAR"));
    parser.addPositionalArgument(QStringLiteral("measurements"),
                                 StiffnessCommand::tr("CSV of the measured bar: z_mm,radial_um[,tangential_um]."),
                                 QStringLiteral("MEASUREMENTS.csv"));
    const QString name = QStringLiteral("calibrate-stiffness");
    if (const int stop =
            parseCommand(parser, name, calibrateStiffnessSynopsis(), calibrateStiffnessSummary(), args, out, err);
        stop >= 0)
        return stop;
    if (parser.positionalArguments().size() != 2 || (parser.isSet(write) && parser.isSet(into))) {
        err << programName() << ' ' << name << ": "
            << StiffnessCommand::tr("give a test bar project and a measurements file, and --write or --into, not both")
            << '\n';
        return kExitUsage;
    }
    std::optional<CuttingForces> forces;
    if (parser.isSet(load) && !(forces = parseLoad(parser.value(load)))) {
        err << programName() << ' ' << name << ": "
            << StiffnessCommand::tr(
                   "--load takes three numbers in newtons, radial,tangential,axial, each at most 1e6, not "
                   "\"%1\"")
                   .arg(parser.value(load))
            << '\n';
        return kExitUsage;
    }
    const QString projectPath = parser.positionalArguments().at(0);
    const QString csvPath = parser.positionalArguments().at(1);
    const ProjectParseResult read = readProjectFile(projectPath);
    const TestBarReadResult bar = readTestBarMeasurements(csvPath);
    Diagnostics problems = read.diagnostics;
    problems.insert(problems.end(), bar.diagnostics.begin(), bar.diagnostics.end());
    StiffnessCalibration cal;
    const bool pivotGiven = parser.isSet(pivot) || (read.project && read.project->characterisation.pivotDistance_mm);
    if (read.project && bar.points && !pivotGiven) { // where to give it, not only that it is zero
        problems.push_back(makeError(QStringLiteral("characterisation.pivot_distance_mm"),
                                     StiffnessCommand::tr("Lc, the distance of the spindle bearing behind the chuck "
                                                          "face, is not given: give it with --pivot MM, or in the "
                                                          "project's characterisation")));
    } else if (read.project && bar.points) {
        bool ok = true;
        const double lc = parser.isSet(pivot) ? parser.value(pivot).toDouble(&ok)
                                              : read.project->characterisation.pivotDistance_mm.value_or(0.0);
        if (!ok) {
            err << programName() << ' ' << name << ": "
                << StiffnessCommand::tr("--pivot takes a length in mm, not \"%1\"").arg(parser.value(pivot)) << '\n';
            return kExitUsage;
        }
        cal = calibrateSpindleChuck(*read.project, DataLibrary::builtIn(), *bar.points, lc, forces);
        problems.insert(problems.end(), cal.diagnostics.begin(), cal.diagnostics.end());
    }
    if (parser.isSet(json)) {
        if (const int code = printJson(calibrationJson(cal, problems), out, err, QStringLiteral("calibrate-stiffness"));
            code != kExitOk)
            return code;
    } else {
        for (const Diagnostic &d : problems)
            err << d.toString() << '\n';
        if (cal.radial)
            printCalibration(out, cal);
    }
    if (!cal.radial)
        return kExitProblems;
    if (parser.isSet(write) || parser.isSet(into)) {
        const QString target = parser.isSet(into) ? parser.value(into) : projectPath;
        const QString error = writeSprings(target, cal, csvPath, read.project->machineId, err);
        if (!error.isEmpty()) {
            err << error << '\n';
            return kExitProblems;
        }
        err << StiffnessCommand::tr("wrote %1: spindle–chuck springs").arg(target) << '\n';
    }
    return kExitOk;
}

} // namespace tolturn
