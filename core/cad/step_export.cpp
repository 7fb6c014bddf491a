// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cad/step_export.h"

#include "core/cad/occt_guard.h"
#include "core/common/atomic_file.h"
#include "core/part/profile_geometry.h"
#include "core/part/profile_validation.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryFile>
#include <Standard_Failure.hxx>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Edge.hxx>
#include <algorithm>
#include <array>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <gp_Ax1.hxx>
#include <numbers>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace tolturn {

namespace {

struct StepExport {
    Q_DECLARE_TR_FUNCTIONS(StepExport)
};

// The half-section lies in the XZ plane of the file: z along the Z axis, r along X; the solid
// is that face turned about Z.
gp_Pnt toModel(const ProfilePoint &p)
{
    return {p.r_mm, 0.0, p.z_mm};
}

TopoDS_Edge segmentEdge(const Segment &s)
{
    if (s.kind == SegmentKind::Radius) {
        if (const auto arc = arcGeometry(s)) {
            const ProfilePoint mid = arc->pointAt(arc->startAngle_rad + 0.5 * arc->sweep_rad);
            const GC_MakeArcOfCircle circle(toModel(s.from), toModel(mid), toModel(s.to));
            return BRepBuilderAPI_MakeEdge(circle.Value());
        }
    }
    return BRepBuilderAPI_MakeEdge(toModel(s.from), toModel(s.to));
}

bool samePoint(const ProfilePoint &a, const ProfilePoint &b)
{
    return std::abs(a.z_mm - b.z_mm) <= kProfileEpsilon_mm && std::abs(a.r_mm - b.r_mm) <= kProfileEpsilon_mm;
}

void addLine(BRepBuilderAPI_MakeWire &wire, const ProfilePoint &from, const ProfilePoint &to)
{
    if (!samePoint(from, to))
        wire.Add(BRepBuilderAPI_MakeEdge(toModel(from), toModel(to)));
}

// The closed boundary of the half-section: the outer contour from left to right, then back along
// the axis and the inner contour (reversed) to where the outer contour began; between a bore
// from each end, back along the axis through the solid between them.
TopoDS_Wire sectionWire(const PartProfile &profile)
{
    BRepBuilderAPI_MakeWire wire;
    for (const Segment &s : profile.outer.segments)
        wire.Add(segmentEdge(s));
    if (profile.inner.empty()) {
        addLine(wire, profile.outer.back(), profile.outer.front());
        return wire.Wire();
    }
    addLine(wire, profile.outer.back(), profile.inner.back());
    for (std::size_t i = profile.inner.segments.size(); i-- > 0;) { // clang 14 cannot use views::reverse
        wire.Add(segmentEdge(profile.inner.segments[i]));
        if (profile.inner.breaksBefore(i))
            addLine(wire, profile.inner.segments[i].from, profile.inner.segments[i - 1].to);
    }
    addLine(wire, profile.inner.front(), profile.outer.front());
    return wire.Wire();
}

TopoDS_Shape revolvedSolid(const PartProfile &profile)
{
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(sectionWire(profile), Standard_True);
    BRepPrimAPI_MakeRevol revol(face, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2.0 * std::numbers::pi);
    return revol.Shape();
}

// Writes under the OpenCascade lock; the unit is millimetres whatever a previous user set.
bool writeStep(const TopoDS_Shape &shape, const QString &file)
{
    const std::lock_guard lock(cad::occtMutex());
    const cad::QuietMessages quiet;
    // The shape is in millimetres (the unit OpenCascade converts from, which another user of it in
    // the process may have set otherwise) and the file in millimetres too; the process's own
    // settings come back afterwards. Set before the writer is made: its model takes the file's
    // unit when it is created (a unit set later names the file's unit without scaling to it).
    STEPControl_Controller::Init(); // defines the parameters
    const cad::StaticSetting shapeUnit("xstep.cascade.unit", "MM");
    const cad::StaticSetting fileUnit("write.step.unit", "MM");
    STEPControl_Writer writer;
    if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone)
        return false;
    return writer.Write(QFile::encodeName(file).constData()) == IFSelect_RetDone;
}

StepExportResult exportInto(const PartProfile &profile, const QString &path)
{
    // Only a valid profile bounds a face: a gap or an overlap leaves no closed wire to revolve.
    const Diagnostics findings = validateProfile(profile);
    const auto firstError = std::find_if(findings.begin(), findings.end(),
                                         [](const Diagnostic &d) { return d.severity == Severity::Error; });
    if (firstError != findings.end())
        return {
            false,
            StepExport::tr("cannot write '%1': the profile has errors, first %2").arg(path, firstError->toString())};
    const TopoDS_Shape solid = revolvedSolid(profile);
    // A temporary file beside the target, renamed over it once complete (rename is atomic within
    // a file system, POSIX rename(2)), so a failed export leaves the previous file untouched.
    QTemporaryFile temp(QFileInfo(path).absoluteDir().filePath(QStringLiteral(".tolturn-XXXXXX.step")));
    if (!temp.open())
        return {false, StepExport::tr("cannot write '%1': %2").arg(path, temp.errorString())};
    temp.close();
    const PendingTemporaryFile pending(temp.fileName());
    if (!writeStep(solid, temp.fileName()))
        return {false, StepExport::tr("OpenCascade could not write the solid to '%1'").arg(path)};
    if (!temp.setPermissions(permissionsForWrite(path)))
        return {false, StepExport::tr("cannot set the permissions of '%1': %2").arg(path, temp.errorString())};
    if (std::rename(QFile::encodeName(temp.fileName()).constData(), QFile::encodeName(path).constData()) != 0)
        return {false, StepExport::tr("cannot save '%1': renaming the temporary file failed").arg(path)};
    temp.setAutoRemove(false); // it is the target now
    return {true, QString()};
}

} // namespace

StepExportResult exportProfileToStep(const PartProfile &profile, const QString &path)
{
    try {
        return exportInto(profile, path);
    } catch (const Standard_Failure &e) {
        return {false, StepExport::tr("OpenCascade failed while writing '%1': %2")
                           .arg(path, QString::fromLocal8Bit(e.GetMessageString()))};
    } catch (const std::exception &e) {
        return {false, StepExport::tr("writing '%1' failed: %2").arg(path, QString::fromLocal8Bit(e.what()))};
    }
}

} // namespace tolturn
