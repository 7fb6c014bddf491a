// SPDX-License-Identifier: GPL-3.0-or-later
// Private to core/cad: which faces of a body are revolved about an axis, and their traces in the
// half-plane through it. Uses OpenCascade types; not part of the public API.
#pragma once

#include "core/cad/profile_chains.h"
#include "core/common/progress.h"

#include <QString>

#include <TopoDS_Shape.hxx>
#include <array>
#include <functional>
#include <gp_Ax1.hxx>
#include <vector>

namespace tolturn::cad {

// An axis shared by revolved faces (cylinders, cones, tori) of a body.
struct AxisCandidate {
    gp_Ax1 axis;
    double revolvedArea_mm2 = 0.0;
    int faceCount = 0;
};

// The candidate axes of a body, most revolved face area first.
[[nodiscard]] std::vector<AxisCandidate> findAxes(const TopoDS_Shape &body);

// What the import needs to know of a left-out face to tell a flat from a keyway
// (docs/step-import.md, "Milled features").
enum class LeftOutShape {
    PlaneAlongAxis, // a plane whose normal is perpendicular to the axis: a flat, a keyway's side or bottom
    PlaneAtSlant,   // a plane neither along nor across the axis
    Other,          // any other surface, and the parts of turned faces that do not go round
};

// A face that is not revolved about the axis, kept out of the profile and reported.
struct LeftOutFace {
    int face = 0;         // 1-based, as in TopExp::MapShapes
    QString what;         // "a plane not perpendicular to the axis (a flat or a keyway side)", …
    double zMin_mm = 0.0; // along the axis, in the same frame as the section pieces
    double zMax_mm = 0.0;
    LeftOutShape shape = LeftOutShape::Other;
    // A plane along the axis: its unit normal out of the material (model frame; the faces' own
    // orientation, which the import makes point out of the material) and its offset n·(P − A)
    // from the axis along it. A flat, or a keyway's bottom, faces away from the axis (offset > 0
    // unless it is cut past the centre); the two sides of a keyway or slot face each other.
    std::array<double, 3> outwardNormal{};
    double axisOffset_mm = 0.0;
    // The faces that share an edge with it (1-based, sorted): a flat's end walls with the flat.
    std::vector<int> neighbours;
};

struct SectionTrace {
    std::vector<SectionPiece> pieces;
    std::vector<LeftOutFace> leftOut;
    // Faces written as splines and read as the elementary surface they are (face index, its name).
    std::vector<std::pair<int, QString>> convertedFaces;
    bool cancelled = false;
};

// The traces of the body's faces revolved about `axis` (z = distance along it from its origin),
// the same trace of several faces merged, and the faces that are not revolved about it.
// `progress` is told the fraction of faces done; a stop ends the trace, marked cancelled.
[[nodiscard]] SectionTrace traceSection(const TopoDS_Shape &body, const gp_Ax1 &axis, const Progress &progress);

} // namespace tolturn::cad
