// SPDX-License-Identifier: GPL-3.0-or-later
// Private to core/cad: turns the pieces of the half-section found on revolved faces into the
// outer and inner contours of a TolTurn profile. Pure 2-D geometry, no OpenCascade.
#pragma once

#include "core/common/diagnostic.h"
#include "core/part/profile.h"

#include <vector>

namespace tolturn::cad {

// Two section points closer than this are one vertex. Well above the 1e-7 model-unit confusion
// tolerance OpenCascade writes into STEP (Precision::Confusion) and the rounding of an inch to mm
// conversion, well below the 1 µm a drawing specifies.
inline constexpr double kJoinTolerance_mm = 1e-4;

// The trace of one revolved face (or of several faces with the same trace) in the half-plane
// through the axis: z along the axis, r from it.
struct SectionPiece {
    bool arc = false;
    ProfilePoint a;
    ProfilePoint b;
    ProfilePoint centre; // arcs
    double radius_mm = 0.0;
    std::vector<int> faces; // face numbers in the body, 1-based as in TopExp::MapShapes
    double faceArea_mm2 = 0.0;
};

// The area the piece sweeps in a full revolution (Pappus: 2 pi times the integral of r ds).
[[nodiscard]] double revolvedArea_mm2(const SectionPiece &piece);

// Where the part goes along z: its left end (the lowest z, or the highest when flipped end for
// end) at z = offset.
struct Placement {
    double low = 0.0;
    double high = 0.0;
    bool flip = false;
    double offset_mm = 0.0;

    [[nodiscard]] double operator()(double z_mm) const { return (flip ? high - z_mm : z_mm - low) + offset_mm; }
};

[[nodiscard]] Placement placementOf(const std::vector<SectionPiece> &pieces, bool flip, double offset_mm);
void placePieces(std::vector<SectionPiece> &pieces, const Placement &placement);

struct ContourBuild {
    Contour outer;
    Contour inner;
    Diagnostics diagnostics; // pieces left over, breaks in the chain
};

// Orders the pieces into the outer contour (left end face, around the outside, right end face)
// and the inner contour (the bore), classifies them as TolTurn segments and names them.
[[nodiscard]] ContourBuild buildContours(const std::vector<SectionPiece> &pieces, double chamferMaxLength_mm);

} // namespace tolturn::cad
