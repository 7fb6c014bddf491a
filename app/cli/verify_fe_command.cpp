// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/verify_fe_command.h"

#include "app/cli/cli_common.h"
#include "app/cli/command_line.h"
#include "core/data/data_library.h"
#include "core/fe/solid_check.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <QTextStream>

namespace tolturn {

namespace {

struct VerifyFeCommand {
    Q_DECLARE_TR_FUNCTIONS(VerifyFeCommand)
};

constexpr double kUmPerMm = 1000.0;
constexpr int kMaxStations = 50; // one CalculiX load case each

QJsonObject resultJson(const QString &file, const SolidCheckResult &r)
{
    QJsonArray stations;
    for (const SolidCheckStation &s : r.stations)
        stations.append(QJsonObject{{QStringLiteral("z_mm"), s.z_mm},
                                    {QStringLiteral("diameter_mm"), 2.0 * s.contactRadius_mm},
                                    {QStringLiteral("beam_radial_um"), s.beamRadial_mm * kUmPerMm},
                                    {QStringLiteral("solid_radial_um"), s.solidRadial_mm * kUmPerMm},
                                    {QStringLiteral("radial_difference_pct"), s.radialDifference_pct()},
                                    {QStringLiteral("beam_tangential_um"), s.beamTangential_mm * kUmPerMm},
                                    {QStringLiteral("solid_tangential_um"), s.solidTangential_mm * kUmPerMm},
                                    {QStringLiteral("timoshenko_radial_um"), s.timoshenkoRadial_mm * kUmPerMm}});
    return {{QStringLiteral("file"), file},
            {QStringLiteral("clamping"), r.clamping},
            {QStringLiteral("beam_corrections"), r.beamCorrections},
            {QStringLiteral("youngs_modulus_MPa"), r.youngsModulus_MPa},
            {QStringLiteral("poisson_ratio"), r.poissonRatio},
            {QStringLiteral("forces_N"), QJsonObject{{QStringLiteral("tangential"), r.forces.tangential_N},
                                                     {QStringLiteral("axial"), r.forces.axial_N},
                                                     {QStringLiteral("radial"), r.forces.radial_N}}},
            {QStringLiteral("mesh"), QJsonObject{{QStringLiteral("element"), QStringLiteral("C3D10")},
                                                 {QStringLiteral("size_mm"), r.meshSize_mm},
                                                 {QStringLiteral("nodes"), r.nodes},
                                                 {QStringLiteral("elements"), r.elements},
                                                 {QStringLiteral("degrees_of_freedom"), r.degreesOfFreedom},
                                                 {QStringLiteral("load_patch_mm"), r.loadPatch_mm}}},
            {QStringLiteral("seconds"), QJsonObject{{QStringLiteral("mesh"), r.meshSeconds},
                                                    {QStringLiteral("solve"), r.solveSeconds},
                                                    {QStringLiteral("beam"), r.beamSeconds}}},
            {QStringLiteral("largest_radial_difference_pct"), r.largestRadialDifference_pct()},
            {QStringLiteral("notes"), QJsonArray::fromStringList(r.notes)},
            {QStringLiteral("stations"), stations}};
}

void printTable(const QString &file, const SolidCheckResult &r, QTextStream &out)
{
    out << VerifyFeCommand::tr("Solid check of %1 (%2): E = %3 MPa, nu = %4")
               .arg(file, r.clamping)
               .arg(r.youngsModulus_MPa)
               .arg(r.poissonRatio)
        << '\n';
    out << VerifyFeCommand::tr("Force at each station: Fr = %1 N, Ft = %2 N, Fa = %3 N")
               .arg(r.forces.radial_N, 0, 'f', 1)
               .arg(r.forces.tangential_N, 0, 'f', 1)
               .arg(r.forces.axial_N, 0, 'f', 1)
        << '\n';
    out << VerifyFeCommand::tr("Mesh: C3D10 of at most %1 mm, %2 nodes, %3 elements, %4 degrees of freedom; "
                               "gmsh %5 s, CalculiX %6 s, beam %7 ms")
               .arg(r.meshSize_mm)
               .arg(r.nodes)
               .arg(r.elements)
               .arg(r.degreesOfFreedom)
               .arg(r.meshSeconds, 0, 'f', 1)
               .arg(r.solveSeconds, 0, 'f', 1)
               .arg(r.beamSeconds * 1000.0, 0, 'f', 2)
        << '\n';
    out << (r.beamCorrections ? VerifyFeCommand::tr("Beam: corrected for the root in the jaws and the shoulders "
                                                    "(docs/solid-fe.md); Timoshenko: without the corrections")
                              : VerifyFeCommand::tr("Beam: Timoshenko, without the corrections (--uncorrected-beam)"))
        << '\n';
    out << VerifyFeCommand::tr("  z [mm]   D [mm]   radial deflection [um]: beam    solid   beam-solid [%]   "
                               "tangential [um]: beam    solid   Timoshenko radial [um]")
        << '\n';
    for (const SolidCheckStation &s : r.stations)
        out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8\n")
                   .arg(s.z_mm, 8, 'f', 2)
                   .arg(2.0 * s.contactRadius_mm, 8, 'f', 2)
                   .arg(s.beamRadial_mm * kUmPerMm, 31, 'f', 3)
                   .arg(s.solidRadial_mm * kUmPerMm, 8, 'f', 3)
                   .arg(s.radialDifference_pct(), 16, 'f', 2)
                   .arg(s.beamTangential_mm * kUmPerMm, 24, 'f', 3)
                   .arg(s.solidTangential_mm * kUmPerMm, 8, 'f', 3)
                   .arg(s.timoshenkoRadial_mm * kUmPerMm, 24, 'f', 3);
    out << VerifyFeCommand::tr("Largest radial difference: %1 % of the largest deflection")
               .arg(r.largestRadialDifference_pct(), 0, 'f', 2)
        << '\n';
    for (const QString &note : r.notes)
        out << VerifyFeCommand::tr("note: %1").arg(note) << '\n';
}

} // namespace

QString verifyFeSynopsis()
{
    return QStringLiteral("verify-fe [--json] [--stations N] [--mesh-size MM] [--load Fr,Ft,Fa] [--uncorrected-beam] "
                          "[--operation NAME] [--progress] PROJECT");
}

QString verifyFeSummary()
{
    return VerifyFeCommand::tr(
        "Check the beam against a solid model: the part meshed in quadratic tetrahedra with gmsh, held as its "
        "clamping holds it, loaded at N tool positions and solved with CalculiX; beam and solid deflection per "
        "station with the difference, the mesh size and degrees of freedom.");
}

int runVerifyFe(const QStringList &args, QTextStream &out, QTextStream &err)
{
    QCommandLineParser parser;
    const QCommandLineOption json(QStringLiteral("json"), VerifyFeCommand::tr("Print the result as JSON."));
    const QCommandLineOption stations(
        QStringLiteral("stations"),
        VerifyFeCommand::tr("Tool positions along the part, 1 to %1 (default 5).").arg(kMaxStations),
        QStringLiteral("N"), QStringLiteral("5"));
    const QCommandLineOption meshSize(QStringLiteral("mesh-size"),
                                      VerifyFeCommand::tr("Largest element edge in mm (default: a fifth of the "
                                                          "smallest turned diameter, at least 1 mm)."),
                                      QStringLiteral("MM"));
    const QCommandLineOption load(QStringLiteral("load"),
                                  VerifyFeCommand::tr("Forces radial, tangential, axial in N instead of the pass's."),
                                  QStringLiteral("Fr,Ft,Fa"));
    const QCommandLineOption progress(
        QStringLiteral("progress"),
        VerifyFeCommand::tr("Report the progress on standard error, as lines \"progress F\" with F from 0 to 1."));
    const QCommandLineOption uncorrected(
        QStringLiteral("uncorrected-beam"),
        VerifyFeCommand::tr("Compare the beam without its corrections for the root in the jaws and the shoulders."));
    parser.addOptions({json, stations, meshSize, load, uncorrected, operationOption(), progress});
    parser.addPositionalArgument(QStringLiteral("project"), VerifyFeCommand::tr("The project file."),
                                 QStringLiteral("PROJECT"));
    if (const int stop = parseNamedCommand(parser, QStringLiteral("verify-fe"), args, out, err); stop >= 0)
        return stop;
    const QString file = oneProjectFile(parser, QStringLiteral("verify-fe"), err);
    if (file.isEmpty())
        return kExitUsage;

    SolidCheckOptions options;
    options.beamCorrections = !parser.isSet(uncorrected);
    bool ok = false;
    options.stations = parser.value(stations).toInt(&ok);
    if (!ok || options.stations < 1 || options.stations > kMaxStations) {
        err << programName() << " verify-fe: "
            << VerifyFeCommand::tr("--stations: \"%1\" is not a whole number from 1 to %2")
                   .arg(parser.value(stations))
                   .arg(kMaxStations)
            << '\n';
        return kExitUsage;
    }
    if (parser.isSet(meshSize)) {
        const double size = parser.value(meshSize).toDouble(&ok);
        if (!ok || !(size >= 0.2 && size <= 100.0)) {
            err << programName() << " verify-fe: "
                << VerifyFeCommand::tr("--mesh-size: \"%1\" is not a length from 0.2 to 100 mm")
                       .arg(parser.value(meshSize))
                << '\n';
            return kExitUsage;
        }
        options.meshSize_mm = size;
    }
    if (parser.isSet(load)) {
        options.load = parseLoad(parser.value(load));
        if (!options.load) {
            err << programName() << " verify-fe: "
                << VerifyFeCommand::tr("--load: \"%1\" is not three forces Fr,Ft,Fa in N").arg(parser.value(load))
                << '\n';
            return kExitUsage;
        }
    }
    const std::optional<Project> project = readProject(file, err);
    if (!project)
        return kExitProblems;
    const std::optional<Project> view = selectOperation(*project, parser, QStringLiteral("verify-fe"), err);
    if (!view)
        return kExitUsage;
    const bool showProgress = parser.isSet(progress);
    const SolidCheckResult result =
        checkWithSolidFe(*view, DataLibrary::builtIn(), options, [&](int percent, const QString &) {
            if (showProgress)
                err << "progress " << QString::number(percent / 100.0, 'f', 2) << Qt::endl;
            return true;
        });
    for (const Diagnostic &d : result.diagnostics)
        err << file << ": " << d.toString() << '\n';
    if (!result.ok())
        return kExitProblems;
    if (parser.isSet(json))
        return printJson(resultJson(file, result), out, err, QStringLiteral("verify-fe"));
    printTable(file, result, out);
    return kExitOk;
}

} // namespace tolturn
