// SPDX-License-Identifier: GPL-3.0-or-later
// Private to core/cad: a body's faces turned to point out of its material, which the import tells
// flats from keyways by (docs/step-import.md, "Milled features"). Uses OpenCascade types; not part
// of the public API.
#pragma once

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <optional>
#include <utility>

namespace tolturn::cad {

// The body with its faces pointing out of the material, in the same faces and the same order
// (TopExp::MapShapes numbers them as before):
// - a solid, or a closed shell, whose shells are all closed is turned round if it is inside out
//   (OpenCascade classifies a point at infinity);
// - loose faces or an open shell (IGES trimmed surfaces) are sewn, and if they close one shell and
//   leave no face out, each face is turned as that shell turns it;
// - anything else (an open solid, faces that close no shell) is returned as written.
// Never throws: a model OpenCascade cannot orient is returned as written.
[[nodiscard]] TopoDS_Shape withMaterialInside(const TopoDS_Shape &body);

// A point of the face (the middle of its parameter range, on its surface) and the face's normal
// there, turned with the face's orientation: out of the material once withMaterialInside has
// turned the body. None for a degenerate face.
[[nodiscard]] std::optional<std::pair<gp_Pnt, gp_Vec>> pointAndNormal(const TopoDS_Face &face);

} // namespace tolturn::cad
