// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/part/profile_editing.h"

#include <optional>

namespace tolturn {

// DIN 509 undercuts (relief grooves) in the inside corner where a cylinder meets a shoulder face.
// Form E relieves the cylinder only; form F also recesses the shoulder face, so that both can be
// ground (or turned) to the corner: its recess goes back along z under the shoulder.
enum class UndercutForm { E, F };

// One row of the DIN 509 dimensions by the finished diameter d of the cylinder: radius r, depth
// t1 into the cylinder, width f along the cylinder, recess t2 into the face (form F), and the
// angles of the run-out onto the cylinder and of the recess's flank against the face.
struct UndercutSize {
    double diameterAbove_mm = 0.0; // d > this
    double diameterUpTo_mm = 0.0;  // d <= this (infinity for the last row)
    double radius_mm = 0.0;
    double depth_mm = 0.0;     // t1
    double width_mm = 0.0;     // f
    double faceDepth_mm = 0.0; // t2, form F
    double runOut_deg = 15.0;
    double flank_deg = 8.0;

    // "E0.6×0.3": the designation DIN 509 writes on drawings (form, r × t1).
    [[nodiscard]] QString designation(UndercutForm form) const;
};

// The row for a cylinder of diameter d (mm); nullopt for d <= 0 or not finite.
[[nodiscard]] std::optional<UndercutSize> undercutSizeFor(double diameter_mm);

// Cuts a DIN 509 undercut of `form`, sized for the cylinder's diameter, into the inside corner at
// vertex k of a contour (between a cylinder and a shoulder face that rises from it, on the outer
// contour, or falls from it, in a bore). The cylinder gets shorter by f, the face starts where the
// undercut meets it; the run-out, bottom, radius (and form F's flank) are new features.
[[nodiscard]] ProfileEdit insertUndercut(const PartProfile &profile, ContourSide side, int vertex, UndercutForm form);

// Cuts a square groove `width_mm` wide and `depth_mm` deep (radially) into cylinder `featureId`,
// starting at z = `zStart_mm`: the cylinder, a face into the groove, its bottom, a face out and
// the rest of the cylinder.
[[nodiscard]] ProfileEdit insertGroove(const PartProfile &profile, const QString &featureId, double zStart_mm,
                                       double width_mm, double depth_mm);

// A groove of a contour: the two faces that bound it and the width between them, measured where
// the narrower of the two meets the other's side (docs/model.md, "Grooves").
struct Groove {
    QString leftFaceId;
    QString rightFaceId;
    double width_mm = 0.0;
    double depth_mm = 0.0; // from the lower rim to the bottom
};

// The grooves of a contour: a face into the material, then (after anything that stays deeper
// than both rims) a face out of it.
[[nodiscard]] std::vector<Groove> groovesOf(const Contour &contour, ContourSide side);

} // namespace tolturn
