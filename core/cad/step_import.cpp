// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cad/step_import.h"

#include "core/cad/material_side.h"
#include "core/cad/model_references.h"
#include "core/cad/occt_guard.h"
#include "core/cad/profile_chains.h"
#include "core/cad/revolved_faces.h"
#include "core/part/profile_validation.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QStringList>
#include <Standard_Failure.hxx>

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_InterfaceModel.hxx>
#include <OSD_Signal.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Reader.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <cmath>
#include <deque>
#include <exception>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace tolturn {

struct CadModel::Bodies {
    std::vector<TopoDS_Shape> shapes; // solids, else shells, else the one shape of faces
};

namespace {

struct StepImport {
    Q_DECLARE_TR_FUNCTIONS(StepImport)
};

// Shares of importCadFile's progress: parsing the file, transferring its entities to shapes
// (readCadFile), tracing the faces (extractProfile; the rest is quick).
constexpr double kReadDone = 0.4;
constexpr double kTransferDone = 0.8;
constexpr double kTraceDone = 0.95;
// The same within each phase's own range.
constexpr double kParsedShare = kReadDone / kTransferDone;
constexpr double kTracedShare = (kTraceDone - kTransferDone) / (1.0 - kTransferDone);

// Bytes read from each end of the file to recognise its format.
constexpr qint64 kSniffBytes = 4096;
// Lines are read this long at most when the file is scanned (a STEP or IGES line is far shorter).
constexpr qint64 kMaxLineBytes = 1 << 20;

QString num(double v)
{
    return formatNumber(v);
}

void fail(Diagnostics &diagnostics, const QString &message)
{
    diagnostics.push_back(makeError(QStringLiteral("file"), message));
}

void fail(CadImportResult &result, const QString &message)
{
    fail(result.diagnostics, message);
}

// Tells `progress`; false (and `cancelled` set) once it is stopped.
bool report(const Progress &progress, bool &cancelled, double fraction)
{
    if (!progress.report(fraction))
        cancelled = true;
    return !cancelled;
}

// The format's name, as the milled features' descriptions give the file their faces are from.
QString nameOf(CadFormat format)
{
    return format == CadFormat::Step ? QStringLiteral("STEP") : QStringLiteral("IGES");
}

std::optional<CadFormat> formatOf(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("step") || suffix == QLatin1String("stp"))
        return CadFormat::Step;
    if (suffix == QLatin1String("iges") || suffix == QLatin1String("igs"))
        return CadFormat::Iges;
    return std::nullopt;
}

// ISO 10303-21 §5: an exchange structure begins with the keyword "ISO-10303-21;" and ends with
// "END-ISO-10303-21;". A file cut short (an interrupted download or copy) lacks the end.
QString checkStepText(const QString &path, const QByteArray &head, const QByteArray &tail)
{
    // Some editors save the file with a UTF-8 byte order mark, which the standard does not have.
    const QByteArray start = head.startsWith("\xEF\xBB\xBF") ? head.mid(3) : head;
    if (!start.trimmed().startsWith("ISO-10303-21;"))
        return StepImport::tr("'%1' is not a STEP file: it does not begin with 'ISO-10303-21;' (ISO 10303-21)")
            .arg(path);
    if (!tail.trimmed().endsWith("END-ISO-10303-21;"))
        return StepImport::tr("'%1' is truncated: a STEP file ends with 'END-ISO-10303-21;', which is missing")
            .arg(path);
    return {};
}

// IGES 5.3 §2.1: 80-column records whose column 73 names the section; the first is the Start
// section (S) or the flag of the compressed form (F), the last the Terminate section (T).
QString checkIgesText(const QString &path, const QByteArray &head, const QByteArray &tail)
{
    const QByteArray first = head.left(head.indexOf('\n'));
    const QList<QByteArray> lines = tail.trimmed().split('\n');
    const QByteArray last = lines.isEmpty() ? QByteArray() : lines.constLast();
    constexpr int kSectionColumn = 72;
    if (first.size() <= kSectionColumn || (first.at(kSectionColumn) != 'S' && first.at(kSectionColumn) != 'F'))
        return StepImport::tr("'%1' is not an IGES file: its first line is not a Start section record (IGES 5.3)")
            .arg(path);
    if (last.size() <= kSectionColumn || last.at(kSectionColumn) != 'T')
        return StepImport::tr("'%1' is truncated: an IGES file ends with a Terminate section record, which is missing")
            .arg(path);
    return {};
}

// The number (digits, sign, point, exponent) that the character at `at` belongs to.
QString numberAround(const QString &text, qsizetype at)
{
    const auto inNumber = [](QChar c) {
        return c.isDigit() || c == QLatin1Char('.') || c == QLatin1Char('+') || c == QLatin1Char('-') ||
               c.toUpper() == QLatin1Char('E') || c.toUpper() == QLatin1Char('D');
    };
    qsizetype from = at;
    while (from > 0 && inNumber(text.at(from - 1)))
        --from;
    qsizetype to = at;
    while (to < text.size() && inNumber(text.at(to)))
        ++to;
    return text.mid(from, to - from);
}

// A real that overflows a double (STEP 1.E400, IGES 1.0D400) becomes infinite in OpenCascade,
// whose geometry then fails in ways it does not report (a crash in curve projection): such a
// file is refused with the line and the number.
QString checkRealsFinite(const QString &path, QFile &file, CadFormat format)
{
    static const QRegularExpression withExponent(QStringLiteral("[0-9.]([EeDd])([+]?)([0-9]{3,})"));
    constexpr int kLargestExponent = 308; // DBL_MAX is about 1.8e308 (IEC 60559 binary64)
    file.seek(0);
    for (qint64 line = 1; !file.atEnd(); ++line) {
        QString text = QString::fromLatin1(file.readLine(kMaxLineBytes));
        if (format == CadFormat::Iges) {
            // IGES 5.3 §2.1: reals only in the Global (G) and Parameter Data (P) sections, in
            // columns 1–72 and 1–64; the rest of a record is its section letter and sequence.
            constexpr int kSectionColumn = 72;
            const QChar section = text.size() > kSectionColumn ? text.at(kSectionColumn) : QChar();
            if (section != QLatin1Char('G') && section != QLatin1Char('P'))
                continue;
            text.truncate(section == QLatin1Char('P') ? 64 : kSectionColumn);
        }
        for (auto it = withExponent.globalMatch(text); it.hasNext();) {
            const QRegularExpressionMatch m = it.next();
            if (m.captured(3).toInt() > kLargestExponent)
                return StepImport::tr("'%1', line %2: the number '%3' is beyond the largest real (about 1.8e308)")
                    .arg(path)
                    .arg(line)
                    .arg(numberAround(text, m.capturedStart(1)));
        }
    }
    return {};
}

// The problem with the file before OpenCascade sees it, empty when it looks readable.
QString checkFile(const QString &path, CadFormat format)
{
    const QFileInfo info(path);
    if (!info.exists())
        return StepImport::tr("'%1' does not exist").arg(path);
    if (!info.isFile())
        return StepImport::tr("'%1' is not a file").arg(path);
    if (info.size() == 0)
        return StepImport::tr("'%1' is empty").arg(path);
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return StepImport::tr("cannot open '%1': %2").arg(path, file.errorString());
    const QByteArray head = file.read(kSniffBytes);
    file.seek(std::max<qint64>(0, info.size() - kSniffBytes));
    const QByteArray tail = file.readAll();
    QString problem = format == CadFormat::Step ? checkStepText(path, head, tail) : checkIgesText(path, head, tail);
    return problem.isEmpty() ? checkRealsFinite(path, file, format) : problem;
}

// The first failure OpenCascade found while loading the file (an unresolved reference, an entity
// of the wrong type), with the entity's label; empty when there is none. A model with one is not
// transferred: its translators assume a consistent model.
QString firstLoadFailure(XSControl_Reader &reader)
{
    const Interface_CheckIterator checks = reader.WS()->ModelCheckList(Standard_False);
    const Handle(Interface_InterfaceModel) model = reader.Model();
    for (checks.Start(); checks.More(); checks.Next()) {
        const Handle(Interface_Check) &check = checks.Value();
        if (check.IsNull() || !check->HasFailed() || check->NbFails() < 1)
            continue;
        const int entity = checks.Number();
        const QString label = entity > 0 && !model.IsNull() && entity <= model->NbEntities()
                                  ? QString::fromLatin1(model->StringLabel(model->Value(entity))->ToCString())
                                  : QString();
        const QString message = QString::fromLatin1(check->CFail(1, Standard_True));
        return label.isEmpty() ? message : QStringLiteral("%1: %2").arg(label, message);
    }
    return {};
}

// A cycle of references or a chain too deep: the translators would recurse on it without end.
QString referenceProblemText(const QString &path, const cad::ReferenceProblem &problem)
{
    if (problem.kind == cad::ReferenceProblem::Kind::Cycle)
        return problem.entity == problem.through
                   ? StepImport::tr("'%1' is not a consistent model: %2 refers to itself").arg(path, problem.entity)
                   : StepImport::tr("'%1' is not a consistent model: %2 refers to %3, which leads back to %2 (a cycle "
                                    "of references)")
                         .arg(path, problem.entity, problem.through);
    return StepImport::tr("'%1' nests its entities %2 deep at %3, more than the %4 any CAD model needs")
        .arg(path)
        .arg(problem.depth)
        .arg(problem.entity)
        .arg(cad::kMaxReferenceDepth);
}

// Reads and transfers the file (the caller holds the OpenCascade lock); a null shape after an error.
TopoDS_Shape readShape(const QString &path, CadFormat format, const Progress &progress, CadReadResult &result)
{
    const cad::QuietMessages quiet;
    // The shapes are transferred in millimetres (readCadFile sets xstep.cascade.unit).
    STEPControl_Reader step;
    IGESControl_Reader iges;
    XSControl_Reader &reader = format == CadFormat::Step ? static_cast<XSControl_Reader &>(step) : iges;
    if (!report(progress, result.cancelled, 0.0))
        return {};
    const IFSelect_ReturnStatus status = reader.ReadFile(QFile::encodeName(path).constData());
    if (status != IFSelect_RetDone) {
        fail(result.diagnostics,
             format == CadFormat::Step
                 ? StepImport::tr("OpenCascade cannot parse '%1' as a STEP file (ISO 10303-21)").arg(path)
                 : StepImport::tr("OpenCascade cannot parse '%1' as an IGES file").arg(path));
        return {};
    }
    if (const QString failure = firstLoadFailure(reader); !failure.isEmpty()) {
        fail(result.diagnostics, StepImport::tr("'%1' is not a consistent model: %2").arg(path, failure));
        return {};
    }
    if (const auto problem = cad::firstReferenceProblem(reader.WS()->Graph())) {
        fail(result.diagnostics, referenceProblemText(path, *problem));
        return {};
    }
    if (!report(progress, result.cancelled, kParsedShare))
        return {};
    const Handle(cad::ProgressBridge) bridge = new cad::ProgressBridge(Progress(progress, kParsedShare, 1.0));
    reader.TransferRoots(bridge->Start());
    if (bridge->cancelled()) {
        result.cancelled = true;
        return {};
    }
    if (reader.NbShapes() == 0) {
        fail(result.diagnostics,
             StepImport::tr("'%1' holds no shape that OpenCascade can transfer (no solid, shell or face)").arg(path));
        return {};
    }
    return reader.OneShape();
}

std::vector<TopoDS_Shape> bodiesOf(const TopoDS_Shape &shape)
{
    std::vector<TopoDS_Shape> bodies;
    for (const TopAbs_ShapeEnum kind : {TopAbs_SOLID, TopAbs_SHELL}) {
        for (TopExp_Explorer ex(shape, kind); ex.More(); ex.Next())
            bodies.push_back(ex.Current());
        if (!bodies.empty())
            return bodies; // shells only when there is no solid (IGES surfaces, open models)
    }
    if (TopExp_Explorer(shape, TopAbs_FACE).More())
        bodies.push_back(shape);
    return bodies;
}

CadSolidInfo solidInfo(const TopoDS_Shape &body)
{
    GProp_GProps props;
    BRepGProp::VolumeProperties(body, props);
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(body, TopAbs_FACE, faces);
    return {std::abs(props.Mass()), faces.Extent()};
}

CadAxisInfo axisInfo(const cad::AxisCandidate &c)
{
    CadAxisInfo info;
    const gp_Pnt o = c.axis.Location();
    const gp_Dir d = c.axis.Direction();
    info.origin_mm[0] = o.X();
    info.origin_mm[1] = o.Y();
    info.origin_mm[2] = o.Z();
    info.direction[0] = d.X();
    info.direction[1] = d.Y();
    info.direction[2] = d.Z();
    info.revolvedArea_mm2 = c.revolvedArea_mm2;
    info.faceCount = c.faceCount;
    return info;
}

// The index the caller asked for, or the default; -1 (after an error) when out of range.
int choose(int requested, int fallback, int count, const QString &field, const QString &what, CadImportResult &result)
{
    if (requested < 0)
        return fallback;
    if (requested < count)
        return requested;
    result.diagnostics.push_back(makeError(
        field,
        StepImport::tr("there is no %1 %2: the file has %3 (numbered from 0)").arg(what).arg(requested).arg(count)));
    return -1;
}

int chooseSolid(const CadModel &model, const CadImportOptions &options, CadImportResult &result)
{
    result.solids = model.solids();
    const auto largest = std::max_element(result.solids.begin(), result.solids.end(),
                                          [](const auto &a, const auto &b) { return a.volume_mm3 < b.volume_mm3; });
    const int chosen =
        choose(options.solidIndex, static_cast<int>(largest - result.solids.begin()),
               static_cast<int>(result.solids.size()), QStringLiteral("step.solid"), StepImport::tr("body"), result);
    if (chosen >= 0 && result.solids.size() > 1)
        result.diagnostics.push_back(makeWarning(
            QStringLiteral("step.solid"),
            StepImport::tr("the file holds %1 bodies; body %2 (%3 mm³) is imported, choose another with the solid "
                           "option")
                .arg(result.solids.size())
                .arg(chosen)
                .arg(num(result.solids[static_cast<std::size_t>(chosen)].volume_mm3))));
    return chosen;
}

int chooseAxis(const std::vector<cad::AxisCandidate> &axes, const CadImportOptions &options, const QString &path,
               CadImportResult &result)
{
    for (const auto &a : axes)
        result.axes.push_back(axisInfo(a));
    if (axes.empty()) {
        fail(result, StepImport::tr("the body in '%1' has no cylindrical, conical or toroidal face: it is not a "
                                    "turned part")
                         .arg(path));
        return -1;
    }
    const int chosen = choose(options.axisIndex, 0, static_cast<int>(axes.size()), QStringLiteral("step.axis"),
                              StepImport::tr("axis"), result);
    if (chosen >= 0 && axes.size() > 1)
        result.diagnostics.push_back(makeWarning(
            QStringLiteral("step.axis"),
            StepImport::tr("the body has revolved faces about %1 different axes; axis %2 (%3 mm² of revolved faces) "
                           "is the part axis, choose another with the axis option")
                .arg(axes.size())
                .arg(chosen)
                .arg(num(axes[static_cast<std::size_t>(chosen)].revolvedArea_mm2))));
    return chosen;
}

// A left-out face with its z range in the placed part.
struct PlacedFace {
    const cad::LeftOutFace *face = nullptr;
    double zFrom_mm = 0.0;
    double zTo_mm = 0.0;
};

// Left-out faces whose z ranges overlap or come within kFeatureJoin_mm of each other, by face number.
struct FaceGroup {
    std::vector<PlacedFace> faces;
    double zFrom_mm = 0.0;
    double zTo_mm = 0.0;
};

// Ranges this close are one feature: well above the 0.1 µm at which the section's vertices join,
// well below the width of any milled feature.
constexpr double kFeatureJoin_mm = 0.01;

PlacedFace placed(const cad::LeftOutFace &f, const cad::Placement &place)
{
    const double z0 = place(f.zMin_mm);
    const double z1 = place(f.zMax_mm);
    return {&f, std::min(z0, z1), std::max(z0, z1)};
}

// A group's faces are listed by face number, as the file numbers them.
void sortByFaceNumber(FaceGroup &g)
{
    std::sort(g.faces.begin(), g.faces.end(), [](const auto &a, const auto &b) { return a.face->face < b.face->face; });
}

// The faces in groups of overlapping or touching z ranges, in z order.
std::vector<FaceGroup> groupByZ(const std::vector<cad::LeftOutFace> &faces, const cad::Placement &place)
{
    std::vector<PlacedFace> sorted;
    sorted.reserve(faces.size());
    for (const cad::LeftOutFace &f : faces)
        sorted.push_back(placed(f, place));
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto &a, const auto &b) { return a.zFrom_mm < b.zFrom_mm; });
    std::vector<FaceGroup> groups;
    for (const PlacedFace &p : sorted) {
        if (groups.empty() || p.zFrom_mm > groups.back().zTo_mm + kFeatureJoin_mm)
            groups.push_back({{}, p.zFrom_mm, p.zTo_mm});
        groups.back().faces.push_back(p);
        groups.back().zTo_mm = std::max(groups.back().zTo_mm, p.zTo_mm);
    }
    for (FaceGroup &g : groups)
        sortByFaceNumber(g);
    return groups;
}

bool isPlaneAlongAxis(const PlacedFace &p)
{
    return p.face->shape == cad::LeftOutShape::PlaneAlongAxis;
}

// Planes this far apart along their normal are one plane: the 1 µm to which spline faces are read
// as planes (revolved_faces.cpp, kAnalyticTolerance_mm).
constexpr double kSamePlane_mm = 1e-3;
// Normals this close to parallel (sin of the angle between them) are parallel: the angular
// tolerance the faces are told along or across the axis by (revolved_faces.cpp).
constexpr double kParallel_rad = 1e-6;

// +1 when the outward normals of two faces point the same way, −1 when opposite, 0 otherwise.
int sense(const PlacedFace &a, const PlacedFace &b)
{
    const auto &n = a.face->outwardNormal;
    const auto &m = b.face->outwardNormal;
    const auto unit = [](const std::array<double, 3> &v) { return std::abs(std::hypot(v[0], v[1], v[2]) - 1.0) < 0.5; };
    if (!unit(n) || !unit(m))
        return 0; // a degenerate face has no normal (revolved_faces.cpp)
    const double cross = std::hypot(n[1] * m[2] - n[2] * m[1], n[2] * m[0] - n[0] * m[2], n[0] * m[1] - n[1] * m[0]);
    if (cross >= kParallel_rad)
        return 0;
    return n[0] * m[0] + n[1] * m[1] + n[2] * m[2] > 0.0 ? 1 : -1;
}

bool samePlane(const PlacedFace &a, const PlacedFace &b)
{
    return sense(a, b) == 1 && std::abs(a.face->axisOffset_mm - b.face->axisOffset_mm) <= kSamePlane_mm;
}

// The two sides of a keyway or slot: planes along the axis whose outward normals face each other
// across an empty gap. Sides at y = a and y = b > a have normals +y and −y and offsets a and −b, so
// the offsets add up to a − b < 0; spanner flats (x = ±s, normals ±x) add up to 2s > 0, and a flat
// cut past the centre has no side facing it.
bool slotSides(const PlacedFace &a, const PlacedFace &b)
{
    return isPlaneAlongAxis(a) && isPlaneAlongAxis(b) && sense(a, b) == -1 &&
           a.face->axisOffset_mm + b.face->axisOffset_mm < -kSamePlane_mm;
}

bool hasSlotSides(const FaceGroup &g)
{
    for (auto a = g.faces.begin(); a != g.faces.end(); ++a)
        if (std::any_of(std::next(a), g.faces.end(), [&a](const PlacedFace &b) { return slotSides(*a, b); }))
            return true;
    return false;
}

// `p` in `group`, whose z range grows to take it.
void join(FaceGroup &group, const PlacedFace &p)
{
    group.faces.push_back(p);
    group.zFrom_mm = std::min(group.zFrom_mm, p.zFrom_mm);
    group.zTo_mm = std::max(group.zTo_mm, p.zTo_mm);
}

// `p` and `q` share an edge.
bool neighbours(const PlacedFace &p, const PlacedFace &q)
{
    return std::binary_search(p.face->neighbours.begin(), p.face->neighbours.end(), q.face->face);
}

// The faces of `others` that share an edge with a flat, or with a face already joined to it, join
// that flat (a flat's end walls); they are taken out of `others`. A breadth-first walk from the
// flats' own faces, in flat order: a face joins the flat fewest edges away, the first on a tie.
void joinByEdges(std::vector<FaceGroup> &flats, std::vector<PlacedFace> &others)
{
    std::deque<std::pair<PlacedFace, std::size_t>> reached; // a face and the flat it is part of
    for (std::size_t i = 0; i < flats.size(); ++i)
        for (const PlacedFace &f : flats[i].faces)
            reached.emplace_back(f, i);
    while (!reached.empty()) {
        const PlacedFace face = reached.front().first; // not a structured binding: the lambda takes it
        const std::size_t flat = reached.front().second;
        reached.pop_front();
        const auto joining = std::stable_partition(others.begin(), others.end(),
                                                   [&face](const PlacedFace &p) { return !neighbours(p, face); });
        for (auto p = joining; p != others.end(); ++p) {
            join(flats[flat], *p);
            reached.emplace_back(*p, flat);
        }
        others.erase(joining, others.end());
    }
}

// The flats of a group with several planes along the axis, no two the sides of a slot: the faces of
// one plane are one flat; the group's other faces join the flat they share an edge with (its end
// walls, a hole through it), else the first flat whose z range they meet, else the first flat.
std::vector<FaceGroup> flatsSideBySide(const FaceGroup &g)
{
    std::vector<FaceGroup> flats;
    std::vector<PlacedFace> others;
    for (const PlacedFace &p : g.faces) {
        if (!isPlaneAlongAxis(p)) {
            others.push_back(p);
            continue;
        }
        const auto plane = std::find_if(flats.begin(), flats.end(),
                                        [&p](const FaceGroup &f) { return samePlane(f.faces.front(), p); });
        if (plane == flats.end())
            flats.push_back({{p}, p.zFrom_mm, p.zTo_mm});
        else
            join(*plane, p);
    }
    std::stable_sort(flats.begin(), flats.end(), [](const auto &a, const auto &b) { return a.zFrom_mm < b.zFrom_mm; });
    joinByEdges(flats, others);
    for (const PlacedFace &p : others) {
        const auto meets = std::find_if(flats.begin(), flats.end(), [&p](const FaceGroup &f) {
            return p.zFrom_mm <= f.zTo_mm + kFeatureJoin_mm && p.zTo_mm >= f.zFrom_mm - kFeatureJoin_mm;
        });
        join(meets == flats.end() ? flats.front() : *meets, p);
    }
    for (FaceGroup &f : flats)
        sortByFaceNumber(f);
    return flats;
}

// The milled features a group of faces makes: with two planes along the axis facing each other
// (the sides of a keyway or slot, whatever its bottom), one keyway with all its faces; with planes
// along the axis, no two facing each other, and none at a slant, a flat for each plane (one flat;
// spanner flats, a square, a hexagon); anything else (cross holes, eccentrics, ramps) no milled feature.
std::vector<std::pair<FaceGroup, MilledFeatureKind>> milledFeaturesOf(const FaceGroup &g)
{
    if (hasSlotSides(g))
        return {{g, MilledFeatureKind::Keyway}};
    const bool slanted = std::any_of(g.faces.begin(), g.faces.end(), [](const PlacedFace &p) {
        return p.face->shape == cad::LeftOutShape::PlaneAtSlant;
    });
    if (slanted || std::none_of(g.faces.begin(), g.faces.end(), isPlaneAlongAxis))
        return {};
    std::vector<FaceGroup> flats = flatsSideBySide(g);
    if (flats.size() == 1)
        return {{g, MilledFeatureKind::Flat}};
    std::vector<std::pair<FaceGroup, MilledFeatureKind>> features;
    features.reserve(flats.size());
    for (FaceGroup &f : flats)
        features.emplace_back(std::move(f), MilledFeatureKind::Flat);
    return features;
}

// The next "M<n>" that is no feature of the profile.
QString freeMilledId(const PartProfile &profile, int &next)
{
    QString id;
    do {
        id = QStringLiteral("M%1").arg(next++);
    } while (findFeature(profile, id));
    return id;
}

QString faceList(const FaceGroup &g)
{
    QStringList numbers;
    for (const PlacedFace &p : g.faces)
        numbers << QString::number(p.face->face);
    const QString list = numbers.join(QStringLiteral(", "));
    return g.faces.size() == 1 ? StepImport::tr("face %1").arg(list) : StepImport::tr("faces %1").arg(list);
}

void addMilledFeature(const FaceGroup &g, MilledFeatureKind kind, const PartProfile &profile, CadFormat format,
                      int &nextId, CadImportResult &result)
{
    const double length = profile.length_mm();
    MilledFeature f;
    f.id = freeMilledId(profile, nextId);
    f.kind = kind;
    f.description = QStringLiteral("%1 %2").arg(nameOf(format), faceList(g)); // "STEP faces 4, 5"
    f.zFrom_mm = std::clamp(g.zFrom_mm, 0.0, length);
    f.zTo_mm = std::clamp(g.zTo_mm, 0.0, length);
    const QString message =
        kind == MilledFeatureKind::Flat
            ? StepImport::tr("the flat of %1, from z = %2 mm to z = %3 mm, became milled feature %4; give it a "
                             "tool, conditions, cutting coefficients and a tolerance to evaluate it")
            : StepImport::tr("the keyway of %1, from z = %2 mm to z = %3 mm, became milled feature %4; give it a "
                             "tool, conditions, cutting coefficients and a tolerance to evaluate it");
    result.diagnostics.push_back(makeWarning(QStringLiteral("milled_features[%1]").arg(result.milledFeatures.size()),
                                             message.arg(faceList(g), num(f.zFrom_mm), num(f.zTo_mm), f.id)));
    result.milledFeatures.push_back(std::move(f));
}

void warnLeftOut(const PlacedFace &p, Diagnostics &out)
{
    const cad::LeftOutFace &f = *p.face;
    out.push_back(makeWarning(QStringLiteral("step.face[%1]").arg(f.face),
                              StepImport::tr("face %1 is %2, from z = %3 mm to z = %4 mm; it is not "
                                             "rotationally symmetric about the part axis and is left out of the "
                                             "profile")
                                  .arg(f.face)
                                  .arg(f.what, num(p.zFrom_mm), num(p.zTo_mm))));
}

// The flats and keyways among `faces` (by face number) become milled features of the profile, each
// with a note; every other face is a warning. Without a profile, every face is a warning.
void reportLeftOut(const std::vector<cad::LeftOutFace> &faces, const cad::Placement &place, const PartProfile *profile,
                   CadFormat format, CadImportResult &result)
{
    std::vector<const cad::LeftOutFace *> featured;
    int nextId = 1;
    for (const FaceGroup &g : groupByZ(faces, place)) {
        if (!profile)
            continue;
        for (const auto &[feature, kind] : milledFeaturesOf(g)) {
            addMilledFeature(feature, kind, *profile, format, nextId, result);
            for (const PlacedFace &p : feature.faces)
                featured.push_back(p.face);
        }
    }
    for (const cad::LeftOutFace &f : faces) {
        if (std::find(featured.begin(), featured.end(), &f) == featured.end())
            warnLeftOut(placed(f, place), result.diagnostics);
    }
}

void reportConverted(const cad::SectionTrace &trace, Diagnostics &out)
{
    // Said, not hidden: the profile rests on these faces being what they were taken for.
    for (const auto &[face, surface] : trace.convertedFaces)
        out.push_back(makeWarning(
            QStringLiteral("step.face[%1]").arg(face),
            StepImport::tr("face %1 is written as a B-spline surface and was read as %2, which it is within 0.001 mm")
                .arg(face)
                .arg(surface)));
}

PartProfile makeProfile(const QString &path, cad::ContourBuild &contours)
{
    PartProfile profile;
    profile.name = QFileInfo(path).completeBaseName();
    profile.outer = std::move(contours.outer);
    profile.inner = std::move(contours.inner);
    // The smallest bar the part can be turned from; the planner raises it to a stock size.
    profile.stockDiameter_mm = 2.0 * profile.maxOuterRadius_mm();
    return profile;
}

void traceProfile(const QString &path, CadFormat format, const TopoDS_Shape &body, const gp_Ax1 &axis,
                  const CadImportOptions &options, CadImportResult &result)
{
    cad::SectionTrace trace = cad::traceSection(body, axis, Progress(options.progress, 0.0, kTracedShare));
    if (trace.cancelled) {
        result.cancelled = true;
        return;
    }
    const cad::Placement place = cad::placementOf(trace.pieces, options.flip, options.zOffset_mm);
    cad::placePieces(trace.pieces, place);
    std::sort(trace.leftOut.begin(), trace.leftOut.end(), [](const auto &a, const auto &b) { return a.face < b.face; });
    cad::ContourBuild contours = cad::buildContours(trace.pieces, options.chamferMaxLength_mm);
    // Milled features need the profile (its length, its ids): built first, reported in the order
    // of the steps (left-out faces, converted faces, contours, the profile's findings).
    std::optional<PartProfile> profile;
    if (!hasErrors(contours.diagnostics))
        profile = makeProfile(path, contours);
    reportLeftOut(trace.leftOut, place, profile ? &*profile : nullptr, format, result);
    reportConverted(trace, result.diagnostics);
    result.diagnostics.insert(result.diagnostics.end(), contours.diagnostics.begin(), contours.diagnostics.end());
    if (!profile)
        return;
    const Diagnostics findings = validateProfile(*profile);
    result.diagnostics.insert(result.diagnostics.end(), findings.begin(), findings.end());
    result.profile = std::move(profile);
}

void readInto(const QString &path, const Progress &progress, CadReadResult &result)
{
    const auto format = formatOf(path);
    if (!format) {
        fail(result.diagnostics, StepImport::tr("'%1' is not a STEP or IGES file: TolTurn reads files ending in "
                                                ".step, .stp, .iges or .igs")
                                     .arg(path));
        return;
    }
    if (const QString problem = checkFile(path, *format); !problem.isEmpty()) {
        fail(result.diagnostics, problem);
        return;
    }
    const TopoDS_Shape shape = readShape(path, *format, progress, result);
    if (shape.IsNull())
        return;
    auto bodies = std::make_shared<CadModel::Bodies>();
    bodies->shapes = bodiesOf(shape);
    if (bodies->shapes.empty()) {
        fail(result.diagnostics, StepImport::tr("'%1' holds no solid, shell or face").arg(path));
        return;
    }
    std::vector<CadSolidInfo> solids;
    for (const TopoDS_Shape &b : bodies->shapes)
        solids.push_back(solidInfo(b));
    result.model.emplace(path, *format, std::move(bodies), std::move(solids));
}

void extractInto(const CadModel &model, const CadImportOptions &options, CadImportResult &result)
{
    result.chosenSolid = chooseSolid(model, options, result);
    if (result.chosenSolid < 0)
        return;
    const TopoDS_Shape body =
        cad::withMaterialInside(model.bodies().shapes[static_cast<std::size_t>(result.chosenSolid)]);
    const std::vector<cad::AxisCandidate> axes = cad::findAxes(body);
    result.chosenAxis = chooseAxis(axes, options, model.path(), result);
    if (result.chosenAxis < 0)
        return;
    traceProfile(model.path(), model.format(), body, axes[static_cast<std::size_t>(result.chosenAxis)].axis, options,
                 result);
    if (result.profile)
        report(options.progress, result.cancelled, 1.0);
}

// Runs `work` under the OpenCascade lock and the signal guard: OpenCascade's global state is
// shared, and a malformed model can make its algorithms fault anywhere, not only in the reader.
// A fault becomes an error on `diagnostics` that names the file.
template <class Work>
void guarded(const QString &path, Diagnostics &diagnostics, Work work)
{
    try {
        cad::runGuarded(work);
    } catch (const OSD_Signal &e) {
        fail(diagnostics, StepImport::tr("'%1' could not be read: OpenCascade stopped on an invalid model (%2); check "
                                         "the file in the CAD system that wrote it")
                              .arg(path, QString::fromLocal8Bit(e.GetMessageString()).trimmed()));
    } catch (const Standard_Failure &e) {
        // A stack overflow in a translator arrives here as a bare "System Signal received"
        // (occt_guard.cpp): the same advice as for the other faults.
        fail(diagnostics, StepImport::tr("'%1' could not be read: OpenCascade failed on it (%2); check the file in "
                                         "the CAD system that wrote it")
                              .arg(path, QString::fromLocal8Bit(e.GetMessageString()).trimmed()));
    } catch (const std::exception &e) {
        fail(diagnostics, StepImport::tr("reading '%1' failed: %2").arg(path, QString::fromLocal8Bit(e.what())));
    }
}

} // namespace

CadModel::CadModel(QString path, CadFormat format, std::shared_ptr<const Bodies> bodies,
                   std::vector<CadSolidInfo> solids)
    : m_path(std::move(path))
    , m_format(format)
    , m_bodies(std::move(bodies))
    , m_solids(std::move(solids))
{
}

CadReadResult readCadFile(const QString &path, const Progress &progress)
{
    CadReadResult result;
    const std::lock_guard lock(cad::occtMutex());
    // The unit of the transferred shapes, whatever the file's own unit (STEP: the
    // SI_UNIT/CONVERSION_BASED_UNIT of its context; IGES: the global section's unit flag); set
    // before the readers are made, like the writer's (step_export.cpp), and outside the guard,
    // whose jump out of a fault would skip putting the process's own setting back.
    STEPControl_Controller::Init(); // defines the parameter
    IGESControl_Controller::Init();
    const cad::StaticSetting unit("xstep.cascade.unit", "MM");
    if (!unit.applied()) {
        fail(result.diagnostics, StepImport::tr("'%1' was not read: OpenCascade would not transfer shapes in "
                                                "millimetres (xstep.cascade.unit)")
                                     .arg(path));
        return result;
    }
    guarded(path, result.diagnostics, [&] { readInto(path, progress, result); });
    if (result.cancelled || hasErrors(result.diagnostics))
        result.model.reset();
    return result;
}

CadImportResult extractProfile(const CadModel &model, const CadImportOptions &options)
{
    CadImportResult result;
    const std::lock_guard lock(cad::occtMutex());
    guarded(model.path(), result.diagnostics, [&] { extractInto(model, options, result); });
    if (result.cancelled) {
        result.profile.reset();
        result.milledFeatures.clear();
    }
    return result;
}

CadImportResult importCadFile(const QString &path, const CadImportOptions &options)
{
    CadReadResult read = readCadFile(path, Progress(options.progress, 0.0, kTransferDone));
    if (!read.model) {
        CadImportResult result;
        result.diagnostics = std::move(read.diagnostics);
        result.cancelled = read.cancelled;
        return result;
    }
    CadImportOptions extraction = options;
    extraction.progress = Progress(options.progress, kTransferDone, 1.0);
    return extractProfile(*read.model, extraction);
}

} // namespace tolturn
