// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/fe/solid_check.h"

#include "core/cad/step_export.h"
#include "core/deviation/deviation_model.h"
#include "core/deviation/turning_inputs.h"
#include "core/fe/calculix_job.h"
#include "core/fe/external_tools.h"
#include "core/fe/tet_mesh.h"
#include "core/mechanics/section.h"
#include "core/part/profile_geometry.h"
#include "core/project/keywords.h"
#include "core/project/operations.h"

#include <Eigen/Dense>
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QThread>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tolturn {

namespace {

struct SolidCheck {
    Q_DECLARE_TR_FUNCTIONS(SolidCheck)
};

// gmsh puts the nodes of a boundary on the CAD surface; this is far below any element size.
constexpr double kSurfaceTolerance_mm = 2e-3;
// The centre hole a centre sits in: DIN 332-1:1986 form A for a centre drill d1 = 3.15 mm (parts
// of 25–40 mm diameter), countersink diameter d2 = 6.7 mm. The 60° centre bears on the cone from
// d1 to d2; the solid has no hole, so the nodes of the end face within d2/2 of the axis are held
// (within d2/2 - d1/2 of the bore's edge on a hollow part).
constexpr double kCentreHoleRadius_mm = 3.35;
constexpr double kCentreDrillRadius_mm = 1.575;

// ---- geometry of the part as meshed --------------------------------------------------------

double radiusOf(const Point3 &p)
{
    return std::hypot(p.x(), p.y());
}

bool onTurnedSurface(const Contour &outer, const Point3 &p)
{
    const double r = radiusOf(p);
    for (const Segment &s : outer.segments) {
        if (s.kind == SegmentKind::Face)
            continue;
        for (const double rc : crossingRadii(s, p.z())) {
            if (std::abs(rc - r) < kSurfaceTolerance_mm)
                return true;
        }
    }
    return false;
}

// The nodes of the end face at z within a centre hole's reach of the axis (or of the bore).
std::vector<int> centreHoleNodes(const TetMesh &mesh, double zEnd)
{
    std::vector<int> face;
    double innermost = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
        if (std::abs(mesh.nodes[i].z() - zEnd) < kSurfaceTolerance_mm) {
            face.push_back(static_cast<int>(i));
            innermost = std::min(innermost, radiusOf(mesh.nodes[i]));
        }
    }
    const bool hollow = innermost > kSurfaceTolerance_mm;
    double reach = hollow ? innermost + kCentreHoleRadius_mm - kCentreDrillRadius_mm : kCentreHoleRadius_mm;
    // A mesh coarser than the centre hole has too few nodes in it to hold the section: the ring
    // then widens to the nearest nodes of the face (a coarse mesh is a coarse model anyway).
    std::sort(face.begin(), face.end(), [&mesh](int a, int b) {
        return radiusOf(mesh.nodes[static_cast<std::size_t>(a)]) < radiusOf(mesh.nodes[static_cast<std::size_t>(b)]);
    });
    constexpr std::size_t kFewestHeld = 6;
    if (face.size() >= kFewestHeld)
        reach = std::max(reach, radiusOf(mesh.nodes[static_cast<std::size_t>(face[kFewestHeld - 1])]));
    std::vector<int> held;
    for (const int n : face) {
        if (radiusOf(mesh.nodes[static_cast<std::size_t>(n)]) <= reach + kSurfaceTolerance_mm)
            held.push_back(n);
    }
    return held;
}

// Boundary conditions of the clamping (docs/solid-fe.md): a chuck or collet holds the turned
// surface of its clamped length rigidly; a centre holds its centre hole radially, the headstock's
// also along the axis in the mean (a pin: the section stays free to rotate).
void holdAsClamped(CalculixJob &job, const PartProfile &part, const Clamping &clamping)
{
    const TetMesh &mesh = *job.mesh;
    const bool centres = clamping.method == ClampingMethod::BetweenCentres;
    if (!centres) {
        for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
            const Point3 &p = mesh.nodes[i];
            if (p.z() <= clamping.clampedLength_mm + kSurfaceTolerance_mm && onTurnedSurface(part.outer, p))
                job.supports.push_back({static_cast<int>(i), true, true, true});
        }
    } else {
        job.axialMeanHeld = centreHoleNodes(mesh, 0.0);
        for (const int n : job.axialMeanHeld)
            job.supports.push_back({n, true, true, false});
    }
    if (centres || clamping.method == ClampingMethod::ChuckTailstock) {
        for (const int n : centreHoleNodes(mesh, part.length_mm()))
            job.supports.push_back({n, true, true, false});
    }
}

// The part with its turned surface split at z (the chuck face), so that the mesh has nodes on
// that circle and the held length ends exactly there: without it the hold ends at the last row
// of nodes before the face, up to an element short, and the root moves with the mesh.
PartProfile withEdgeAt(PartProfile part, double z)
{
    std::vector<Segment> &segments = part.outer.segments;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Segment &s = segments[i];
        if (!s.isAxial() || z <= s.from.z_mm + kProfileEpsilon_mm || z >= s.to.z_mm - kProfileEpsilon_mm)
            continue;
        Segment first = s;
        Segment second = s;
        first.to = {z, radiusOnSegment(s, z)};
        second.from = first.to;
        second.id += QStringLiteral("-held-end");
        segments[i] = first;
        segments.insert(segments.begin() + static_cast<std::ptrdiff_t>(i) + 1, second);
        break;
    }
    return part;
}

// ---- tool positions and loads --------------------------------------------------------------

struct ToolPosition {
    double z_mm = 0.0;
    double radius_mm = 0.0;
};

// N positions evenly along the supported length (at the middle of N equal parts), each moved onto a turned cylinder or
// cone far enough from its ends that the load patch (half side `halfPatch`) lies on it.
std::vector<ToolPosition> toolPositions(const PartProfile &part, double x0, double x1, int count, double halfPatch)
{
    std::vector<ToolPosition> out;
    for (int i = 1; i <= count; ++i) {
        const double target = x0 + (x1 - x0) * (i - 0.5) / count;
        const Segment *best = nullptr;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (const Segment &s : part.outer.segments) {
            const double a = std::max(s.from.z_mm, x0) + halfPatch;
            const double b = std::min(s.to.z_mm, x1) - halfPatch;
            if (!s.isAxial() || s.kind == SegmentKind::Radius || b < a)
                continue;
            const double d = target < a ? a - target : (target > b ? target - b : 0.0);
            if (d < bestDistance) {
                bestDistance = d;
                best = &s;
            }
        }
        if (best == nullptr)
            break;
        const double z =
            std::clamp(target, std::max(best->from.z_mm, x0) + halfPatch, std::min(best->to.z_mm, x1) - halfPatch);
        if (!out.empty() && z - out.back().z_mm < halfPatch)
            continue;
        out.push_back({z, radiusOnSegment(*best, z)});
    }
    return out;
}

// The boundary faces on the turned surface whose centroid lies in the square patch of half side
// `half` centred on the tool at (r, 0, z).
std::vector<const BoundaryFace *> patchFaces(const TetMesh &mesh, const std::vector<BoundaryFace> &surface,
                                             const ToolPosition &at, double half)
{
    std::vector<const BoundaryFace *> out;
    for (const BoundaryFace &f : surface) {
        const Point3 c = f.centroid(mesh);
        if (c.x() <= 0.0 || std::abs(c.z() - at.z_mm) > half)
            continue;
        if (std::abs(at.radius_mm * std::atan2(c.y(), c.x())) <= half)
            out.push_back(&f);
    }
    return out;
}

// The cutting force as a traction on the patch, as consistent nodal forces of the six-node faces:
// none at the corners, a third of the face's share at each mid-side node (exact for a flat face;
// O. C. Zienkiewicz, R. L. Taylor, The Finite Element Method, vol. 1, 5th ed., §8.8). The shares
// are tilted linearly in z so that the force acts exactly at the tool's z: faces cut the patch's
// edge unevenly, and a load a millimetre off moves a cantilever's tip by 3 mm/L. On the part the
// tool pushes the section away (-x), drags it against the cut (-y) and pushes it towards the held
// end (-z).
LoadCase patchLoad(const TetMesh &mesh, const std::vector<const BoundaryFace *> &faces, const CuttingForces &f,
                   double z0)
{
    LoadCase loads;
    for (const BoundaryFace *face : faces) {
        const double area = face->area_mm2(mesh);
        for (std::size_t i = 3; i < 6; ++i)
            loads.push_back({face->nodes[i], Point3(area, 0.0, 0.0)});
    }
    double first = 0.0;
    double second = 0.0;
    for (const NodalForce &n : loads) {
        const double dz = mesh.nodes[static_cast<std::size_t>(n.node)].z() - z0;
        first += n.force_N.x() * dz;
        second += n.force_N.x() * dz * dz;
    }
    const double tilt = second > 0.0 ? -first / second : 0.0;
    double total = 0.0;
    for (NodalForce &n : loads) {
        const double dz = mesh.nodes[static_cast<std::size_t>(n.node)].z() - z0;
        n.force_N.x() *= std::max(0.0, 1.0 + tilt * dz);
        total += n.force_N.x();
    }
    const Point3 force(-f.radial_N, -f.tangential_N, -f.axial_N);
    for (NodalForce &n : loads)
        n.force_N = n.force_N.x() / total * force;
    return loads;
}

// ---- the run -------------------------------------------------------------------------------

SolidCheckResult failed(SolidCheckResult result, SolidCheckFailure failure, const QString &field, const QString &text)
{
    result.failure = failure;
    result.stations.clear();
    result.diagnostics.push_back(makeError(field, text));
    return result;
}

struct Run {
    const SolidCheckProgress &progress;
    bool cancelled = false;

    bool report(int percent, const QString &stage)
    {
        if (progress && !progress(percent, stage))
            cancelled = true;
        return !cancelled;
    }
};

QString cancelledText()
{
    return SolidCheck::tr("the solid check was cancelled; the project is unchanged");
}

// Meshes part.step in `dir` with gmsh: quadratic tetrahedra no larger than `size`.
// Where the mesh is refined: the circle on the turned surface at the chuck face, where the held
// surface ends in an edge whose stresses are singular and the root's compliance converges slowly.
struct HeldEdge {
    double z_mm = 0.0;
    double radius_mm = 0.0;
};

// The gmsh script: quadratic tetrahedra of at most `size`; near the held edge a quarter of that,
// growing by half the distance from it (a MathEval background field, gmsh reference manual, "Mesh
// size fields").
QByteArray meshScript(double size, std::optional<HeldEdge> edge)
{
    const auto n = [](double v) { return QByteArray::number(v, 'g', 8); };
    QByteArray script = "Merge \"part.step\";\nMesh.ElementOrder = 2;\nMesh.Optimize = 1;\n"
                        "Mesh.CharacteristicLengthMax = " +
                        n(size) + ";\n";
    if (edge)
        script += "Field[1] = MathEval;\nField[1].F = \"" + n(size / 4) + " + 0.5*sqrt((sqrt(x*x+y*y)-" +
                  n(edge->radius_mm) + ")^2 + (z-" + n(edge->z_mm) + ")^2)\";\nBackground Field = 1;\n";
    return script + "Mesh 3;\nSave \"part.inp\";\n";
}

std::optional<TetMesh> meshPart(const QDir &dir, const QString &gmsh, const QByteArray &script, Run &run,
                                SolidCheckResult &result)
{
    const double size = result.meshSize_mm;
    QFile geo(dir.filePath(QStringLiteral("mesh.geo")));
    if (!geo.open(QIODevice::WriteOnly) || geo.write(script) != script.size()) {
        result = failed(result, SolidCheckFailure::Mesh, QStringLiteral("mesh"),
                        SolidCheck::tr("could not write the mesh script in %1").arg(dir.path()));
        return std::nullopt;
    }
    geo.close();
    const ProcessRun meshing =
        runExternal(gmsh, {QStringLiteral("-v"), QStringLiteral("3"), QStringLiteral("mesh.geo"), QStringLiteral("-0")},
                    dir.path(), {}, [&run](const QByteArray &piece) {
                        const int percent = piece.contains("Meshing 3D") ? 25 : 15;
                        return run.report(percent, SolidCheck::tr("meshing with gmsh"));
                    });
    if (meshing.cancelled) {
        result = failed(result, SolidCheckFailure::Cancelled, QStringLiteral("cancelled"), cancelledText());
        return std::nullopt;
    }
    QFile inp(dir.filePath(QStringLiteral("part.inp")));
    const TetMeshParse parsed = inp.open(QIODevice::ReadOnly) ? parseAbaqusTetMesh(inp.readAll()) : TetMeshParse{};
    if (meshing.crashed || meshing.exitCode != 0 || !parsed.mesh) {
        const QString why = !parsed.error.isEmpty() ? parsed.error : calculixErrorLine(meshing.output);
        result = failed(result, SolidCheckFailure::Mesh, QStringLiteral("mesh"),
                        SolidCheck::tr("gmsh could not mesh the part with elements of %1 mm (exit code %2): %3")
                            .arg(size)
                            .arg(meshing.exitCode)
                            .arg(why));
        return std::nullopt;
    }
    return parsed.mesh;
}

double partLength(const TetMesh &mesh)
{
    const auto [lo, hi] = std::minmax_element(mesh.nodes.begin(), mesh.nodes.end(),
                                              [](const Point3 &a, const Point3 &b) { return a.z() < b.z(); });
    return hi->z() - lo->z();
}

// Solves the job with CalculiX in `dir`; the displacements of every load case.
std::optional<std::vector<std::vector<Point3>>> solve(const QDir &dir, const QString &ccx, const CalculixJob &job,
                                                      Run &run, SolidCheckResult &result)
{
    QFile deck(dir.filePath(QStringLiteral("part_fe.inp")));
    const QByteArray text = calculixDeck(job);
    if (!deck.open(QIODevice::WriteOnly) || deck.write(text) != text.size()) {
        result = failed(result, SolidCheckFailure::Solver, QStringLiteral("solver"),
                        SolidCheck::tr("could not write the CalculiX input in %1").arg(dir.path()));
        return std::nullopt;
    }
    deck.close();
    const auto cases = static_cast<int>(job.loadCases.size());
    int stepsSeen = 0;
    // CalculiX solves with as many threads as the machine has cores (its manual, §2).
    const ProcessRun solving = runExternal(
        ccx, {QStringLiteral("-i"), QStringLiteral("part_fe")}, dir.path(),
        {QStringLiteral("OMP_NUM_THREADS=%1").arg(QThread::idealThreadCount())}, [&](const QByteArray &piece) {
            stepsSeen += static_cast<int>(piece.count("STEP"));
            return run.report(40 + 55 * std::min(stepsSeen, cases) / std::max(cases, 1),
                              SolidCheck::tr("solving with CalculiX: load case %1 of %2")
                                  .arg(std::clamp(stepsSeen, 1, cases))
                                  .arg(cases));
        });
    if (solving.cancelled) {
        result = failed(result, SolidCheckFailure::Cancelled, QStringLiteral("cancelled"), cancelledText());
        return std::nullopt;
    }
    QFile dat(dir.filePath(QStringLiteral("part_fe.dat")));
    const CalculixDisplacements u =
        dat.open(QIODevice::ReadOnly)
            ? parseCalculixDisplacements(dat.readAll(), job.mesh->nodes.size(), job.loadCases.size())
            : CalculixDisplacements{{}, SolidCheck::tr("it wrote no results")};
    if (solving.crashed || solving.exitCode != 0 || !u.error.isEmpty()) {
        const QString said = calculixErrorLine(solving.output);
        const bool error = said.contains(QLatin1String("*ERROR"), Qt::CaseInsensitive);
        result = failed(result, SolidCheckFailure::Solver, QStringLiteral("solver"),
                        SolidCheck::tr("CalculiX failed (exit code %1): %2")
                            .arg(solving.exitCode)
                            .arg(error || u.error.isEmpty() ? said : u.error));
        return std::nullopt;
    }
    // A solid the supports leave free to move gives CalculiX a singular system, which it may solve
    // to numbers without saying so.
    const double length = job.mesh->nodes.empty() ? 0.0 : partLength(*job.mesh);
    for (const std::vector<Point3> &loadCase : u.perCase) {
        for (const Point3 &d : loadCase) {
            if (!d.allFinite() || d.norm() > length) {
                result = failed(result, SolidCheckFailure::Solver, QStringLiteral("solver"),
                                SolidCheck::tr("CalculiX moved the part by %1 mm, more than its length: the "
                                               "clamping does not hold the solid")
                                    .arg(d.norm(), 0, 'g', 3));
                return std::nullopt;
            }
        }
    }
    return u.perCase;
}

int freeDegreesOfFreedom(const CalculixJob &job)
{
    int held = job.axialMeanHeld.empty() ? 0 : 1;
    for (const NodeSupport &s : job.supports)
        held += int(s.x) + int(s.y) + int(s.z);
    return 3 * static_cast<int>(job.mesh->nodes.size()) - held;
}

QStringList checkNotes(const Project &project, const SolidCheckResult &r)
{
    QStringList notes{
        SolidCheck::tr("The machine's supports are rigid in both models: the check is of the part's own deflection."),
        SolidCheck::tr("Solid: quadratic tetrahedra (C3D10) of at most %1 mm; %2 nodes, %3 free degrees of freedom.")
            .arg(r.meshSize_mm)
            .arg(r.nodes)
            .arg(r.degreesOfFreedom),
        SolidCheck::tr("The force is a uniform traction on a %1 mm square patch of the turned surface; the solid's "
                       "deflection is the area mean of the displacement of its section under the load.")
            .arg(r.loadPatch_mm, 0, 'g', 3)};
    notes << (r.beamCorrections ? SolidCheck::tr("The beam carries its corrections from solid FE (the root in the "
                                                 "jaws, a hinge at each shoulder); Timoshenko is the beam without "
                                                 "them (docs/solid-fe.md).")
                                : SolidCheck::tr("The beam is plain Timoshenko, without its corrections."));
    if (project.clamping.method == ClampingMethod::BetweenCentres ||
        project.clamping.method == ClampingMethod::ChuckTailstock)
        notes << SolidCheck::tr("A centre holds the end face within 3.35 mm of the axis (DIN 332-1 form A, d2 = "
                                "6.7 mm), or 1.78 mm of a bore's edge.");
    if (!holdsOneEndOnly(project.clamping.method) || project.clamping.clampedLength_mm > 0.0)
        notes << SolidCheck::tr("A chuck or collet holds the turned surface of its clamped length rigidly.");
    if (operationCount(project) > 1)
        notes << SolidCheck::tr(
            "The part is checked as finished: stock a later set-up removes is not in either model.");
    return notes;
}

} // namespace

double SolidCheckStation::radialDifference_pct() const
{
    return solidRadial_mm != 0.0 ? 100.0 * (beamRadial_mm - solidRadial_mm) / solidRadial_mm : 0.0;
}

double SolidCheckResult::largestRadialDifference_pct() const
{
    double largest = 0.0;
    double difference = 0.0;
    for (const SolidCheckStation &s : stations) {
        largest = std::max(largest, std::abs(s.solidRadial_mm));
        difference = std::max(difference, std::abs(s.beamRadial_mm - s.solidRadial_mm));
    }
    return largest > 0.0 ? 100.0 * difference / largest : 0.0;
}

double defaultMeshSize(const PartProfile &part)
{
    double smallest = std::numeric_limits<double>::infinity();
    for (const Segment &s : part.outer.segments) {
        if (s.kind != SegmentKind::Face)
            smallest = std::min({smallest, 2.0 * s.from.r_mm, 2.0 * s.to.r_mm});
    }
    return std::isfinite(smallest) ? std::max(1.0, smallest / 5.0) : 1.0;
}

SolidCheckResult checkWithSolidFe(const Project &project, const DataLibrary &data, const SolidCheckOptions &options,
                                  const SolidCheckProgress &progress)
{
    SolidCheckResult result;
    Run run{progress};
    if (options.operation < 0 || options.operation >= operationCount(project))
        return failed(result, SolidCheckFailure::Project, QStringLiteral("operation"),
                      SolidCheck::tr("operation %1 does not exist; the project has %2")
                          .arg(options.operation + 1)
                          .arg(operationCount(project)));
    const Project view = operationView(project, options.operation);
    DeviationOptions deviationOptions;
    deviationOptions.workpieceOnly = true;
    deviationOptions.inProcessSection = false;
    deviationOptions.loadOverride = options.load;
    deviationOptions.beamCorrections = options.beamCorrections;
    InputsResult resolved = resolveTurningInputs(view, data, deviationOptions);
    if (!resolved.inputs) {
        result.failure = SolidCheckFailure::Project;
        result.diagnostics = resolved.diagnostics;
        return result;
    }
    TurningInputs &in = *resolved.inputs;
    in.stockOuter_mm.clear(); // the part as finished, as the solid is
    in.solidInner_mm.clear();
    result.forces = in.forces;
    result.clamping = keyword(view.clamping.method);
    result.beamCorrections = options.beamCorrections;
    result.youngsModulus_MPa = in.material.youngsModulus_MPa;
    result.poissonRatio = in.material.poissonRatio;
    result.meshSize_mm = options.meshSize_mm.value_or(defaultMeshSize(view.part));
    if (!(result.meshSize_mm > 0.0))
        return failed(result, SolidCheckFailure::Project, QStringLiteral("mesh_size_mm"),
                      SolidCheck::tr("the mesh size must be a positive length in mm, not %1").arg(result.meshSize_mm));

    const ExternalTool gmsh = findGmsh();
    const ExternalTool ccx = findCalculix();
    for (const ExternalTool *tool : {&gmsh, &ccx}) {
        if (!tool->found())
            return failed(result, SolidCheckFailure::MissingEngine, tool->executable, tool->missingMessage());
    }

    QTemporaryDir temporary;
    if (!temporary.isValid())
        return failed(result, SolidCheckFailure::Mesh, QStringLiteral("mesh"),
                      SolidCheck::tr("could not make a temporary folder: %1").arg(temporary.errorString()));
    const QDir dir(temporary.path());
    // For looking at the mesh, the CalculiX input and its output: kept where a note says.
    if (qEnvironmentVariableIsSet("TOLTURN_FE_KEEP")) {
        temporary.setAutoRemove(false);
        result.notes << SolidCheck::tr("Files kept in %1 (TOLTURN_FE_KEEP).").arg(dir.path());
    }
    if (!run.report(5, SolidCheck::tr("writing the solid")))
        return failed(result, SolidCheckFailure::Cancelled, QStringLiteral("cancelled"), cancelledText());
    const bool chuck = view.clamping.method != ClampingMethod::BetweenCentres;
    const PartProfile solid = chuck ? withEdgeAt(view.part, view.clamping.clampedLength_mm) : view.part;
    const StepExportResult step = exportProfileToStep(solid, dir.filePath(QStringLiteral("part.step")));
    if (!step.ok)
        return failed(result, SolidCheckFailure::Mesh, QStringLiteral("mesh"), step.error);

    QElapsedTimer clock;
    clock.start();
    std::optional<HeldEdge> edge;
    if (chuck)
        edge = HeldEdge{view.clamping.clampedLength_mm,
                        radiusAt(view.part.outer, view.clamping.clampedLength_mm, Approach::FromLeft).value_or(0.0)};
    const std::optional<TetMesh> mesh = meshPart(dir, gmsh.path, meshScript(result.meshSize_mm, edge), run, result);
    if (!mesh)
        return result;
    result.meshSeconds = static_cast<double>(clock.restart()) / 1000.0;
    result.nodes = static_cast<int>(mesh->nodes.size());
    result.elements = static_cast<int>(mesh->elements.size());
    if (!run.report(35, SolidCheck::tr("setting up the load cases")))
        return failed(result, SolidCheckFailure::Cancelled, QStringLiteral("cancelled"), cancelledText());

    CalculixJob job{&*mesh, in.material.youngsModulus_MPa, in.material.poissonRatio, {}, {}, {}};
    holdAsClamped(job, view.part, view.clamping);
    result.degreesOfFreedom = freeDegreesOfFreedom(job);
    const std::vector<BoundaryFace> surface = boundaryFaces(*mesh);
    // The patch is of the part's size, not the mesh's, so that a finer mesh converges to the same
    // load; a coarse mesh widens it to a few faces.
    double half = 0.5 * defaultMeshSize(view.part);
    const std::vector<ToolPosition> positions =
        toolPositions(view.part, in.supportStart_mm, in.supportEnd_mm, std::max(options.stations, 1), half);
    if (positions.empty())
        return failed(result, SolidCheckFailure::Project, QStringLiteral("part.outer"),
                      SolidCheck::tr("no turned cylinder or cone between the supports is long enough to load"));
    for (const ToolPosition &at : positions) {
        std::vector<const BoundaryFace *> faces = patchFaces(*mesh, surface, at, half);
        for (int grow = 0; faces.size() < 3 && grow < 6; ++grow)
            faces = patchFaces(*mesh, surface, at, half *= 1.5);
        job.loadCases.push_back(patchLoad(*mesh, faces, in.forces, at.z_mm));
    }
    result.loadPatch_mm = 2.0 * half;

    clock.restart();
    const auto displacements = solve(dir, ccx.path, job, run, result);
    if (!displacements)
        return result;
    result.solveSeconds = static_cast<double>(clock.restart()) / 1000.0;

    std::vector<double> z;
    std::vector<double> radius;
    for (const ToolPosition &at : positions) {
        z.push_back(at.z_mm);
        radius.push_back(at.radius_mm);
    }
    const std::vector<StationInfluence> beam = influenceAt(view.part, in, z, radius);
    result.beamSeconds = static_cast<double>(clock.nsecsElapsed()) * 1e-9;
    TurningInputs plain = in;
    plain.beamCorrections = false;
    const std::vector<StationInfluence> timoshenko = influenceAt(view.part, plain, z, radius);
    const SectionAlongZ finished(view.part);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const RoundSection section = finished.at(z[i]);
        const Point3 u =
            sectionMeanDisplacement(*mesh, (*displacements)[i], z[i], section.innerRadius_mm, section.outerRadius_mm)
                .value_or(Point3::Zero());
        const StationInfluence &b = beam[i];
        result.stations.push_back(
            {z[i], radius[i],
             in.forces.radial_N * b.radialPerRadial_mm_per_N + in.forces.axial_N * b.radialPerAxial_mm_per_N, -u.x(),
             in.forces.tangential_N * b.tangentialPerTangential_mm_per_N, -u.y(),
             in.forces.radial_N * timoshenko[i].radialPerRadial_mm_per_N +
                 in.forces.axial_N * timoshenko[i].radialPerAxial_mm_per_N});
    }
    run.report(100, SolidCheck::tr("done"));
    result.notes = checkNotes(view, result) + result.notes;
    return result;
}

} // namespace tolturn
