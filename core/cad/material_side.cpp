// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cad/material_side.h"

#include <Standard_Failure.hxx>

#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <optional>

namespace tolturn::cad {
namespace {

// Faces this close are sewn edge to edge: gaps below it are no feature a part is cut with (the
// 0.01 mm at which the import joins the z ranges of milled features).
constexpr double kSewing_mm = 0.01;

bool allShellsClosed(const TopoDS_Shape &shape)
{
    bool any = false;
    for (TopExp_Explorer shell(shape, TopAbs_SHELL); shell.More(); shell.Next()) {
        if (!BRep_Tool::IsClosed(shell.Current()))
            return false;
        any = true;
    }
    return any;
}

// The solid turned so that its material is inside; none when it is open or OpenCascade cannot
// tell inside from outside.
std::optional<TopoDS_Solid> oriented(TopoDS_Solid solid)
{
    if (!allShellsClosed(solid) || !BRepLib::OrientClosedSolid(solid))
        return std::nullopt;
    return solid;
}

// True when `sewn` (a face of an oriented shell) points the other way from `face` at the point of
// `face` where its normal is taken.
bool turnedBySewing(const TopoDS_Face &face, const TopoDS_Face &sewn)
{
    const auto written = pointAndNormal(face);
    if (!written)
        return false;
    GeomAPI_ProjectPointOnSurf onSewn(written->first, BRep_Tool::Surface(sewn));
    if (onSewn.NbPoints() == 0)
        return false;
    double u = 0.0;
    double v = 0.0;
    onSewn.LowerDistanceParameters(u, v);
    gp_Pnt point;
    gp_Vec normal;
    BRepGProp_Face(sewn).Normal(u, v, point, normal);
    return normal.Dot(written->second) < 0.0;
}

// Loose faces or an open shell, each face turned as the closed shell they sew into turns it.
std::optional<TopoDS_Shape> turnedAsSewn(const TopoDS_Shape &faces)
{
    BRepBuilderAPI_Sewing sewing(kSewing_mm);
    sewing.Add(faces);
    sewing.Perform();
    const TopoDS_Shape sewnShape = sewing.SewedShape();
    TopExp_Explorer shell(sewnShape, TopAbs_SHELL);
    if (!shell.More() || TopExp_Explorer(sewnShape, TopAbs_FACE, TopAbs_SHELL).More())
        return std::nullopt; // no shell, or faces left out of it
    const TopoDS_Shell sewn = TopoDS::Shell(shell.Current());
    shell.Next();
    if (shell.More() || !BRep_Tool::IsClosed(sewn))
        return std::nullopt;
    const auto solid = oriented(BRepBuilderAPI_MakeSolid(sewn).Solid());
    if (!solid)
        return std::nullopt;
    TopTools_IndexedMapOfShape sewnFaces; // as the oriented solid turns them
    TopExp::MapShapes(*solid, TopAbs_FACE, sewnFaces);
    TopTools_IndexedMapOfShape written;
    TopExp::MapShapes(faces, TopAbs_FACE, written);
    BRep_Builder builder;
    TopoDS_Compound turned;
    builder.MakeCompound(turned);
    for (int i = 1; i <= written.Extent(); ++i) {
        TopoDS_Face face = TopoDS::Face(written(i));
        const int k = sewnFaces.FindIndex(sewing.ModifiedSubShape(face));
        if (k == 0)
            return std::nullopt;
        if (turnedBySewing(face, TopoDS::Face(sewnFaces(k))))
            face.Reverse();
        builder.Add(turned, face);
    }
    return TopoDS_Shape(turned);
}

} // namespace

std::optional<std::pair<gp_Pnt, gp_Vec>> pointAndNormal(const TopoDS_Face &face)
{
    double u0 = 0.0;
    double u1 = 0.0;
    double v0 = 0.0;
    double v1 = 0.0;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    gp_Pnt point;
    gp_Vec normal;
    BRepGProp_Face(face).Normal(0.5 * (u0 + u1), 0.5 * (v0 + v1), point, normal);
    if (normal.Magnitude() <= gp::Resolution())
        return std::nullopt;
    return std::pair{point, normal};
}

TopoDS_Shape withMaterialInside(const TopoDS_Shape &body)
{
    try {
        switch (body.ShapeType()) {
        case TopAbs_SOLID:
            return oriented(TopoDS::Solid(body)).value_or(TopoDS::Solid(body));
        case TopAbs_SHELL:
            if (BRep_Tool::IsClosed(body)) {
                const auto solid = oriented(BRepBuilderAPI_MakeSolid(TopoDS::Shell(body)).Solid());
                return solid ? TopExp_Explorer(*solid, TopAbs_SHELL).Current() : body;
            }
            return turnedAsSewn(body).value_or(body);
        default:
            return turnedAsSewn(body).value_or(body);
        }
    } catch (const Standard_Failure &) {
        return body; // the import goes on with the faces as written
    }
}

} // namespace tolturn::cad
