// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/mechanics/beam.h"
#include "core/mechanics/section.h"

namespace tolturn {

// The corrections' numbers were identified from solid finite-element runs (gmsh + CalculiX,
// core/fe) of uniform and stepped solid bars in rigid jaws; the identified ranges are in the
// constants' comments (docs/solid-fe.md "Corrections").

// How far inside the jaws a bar held in a chuck acts as built in, as a share of its diameter.
// Identified (docs/solid-fe.md, first set): uniform Ø20 bars held over 0.5 and 1 diameter, 1 kN
// at eight stations 0.6 to 9.4 d from the face, 3 mm mesh: e = 0.061–0.069, nearly the same for
// every clamped length and station (2 d held, 4 mm mesh: within 0.001 of 1 d); 0.066 is the mean
// of those sixteen values.
inline constexpr double kRootEmbedmentPerDiameter = 0.066;

// The length of the thin section whose bending compliance a shoulder adds as a hinge at the step,
// as a share of the thin diameter d, for an outer-diameter ratio D/d. Identified (docs/solid-fe.md,
// second set): bars Ø(D) then Ø20, 1 kN at eight stations past the step; far-field values 0.057
// (D/d 1.25, 3 mm mesh), 0.126 (1.6, 4 mm) and 0.171 (2, 4 mm); 0 at D/d = 1; linear in between,
// and 0.171 beyond D/d = 2, where no run was made.
[[nodiscard]] double shoulderHingePerDiameter(double diameterRatio);

// Flexibility at the chuck face (displacement and rotation per force and moment there) of the
// length e·D of the section `root` inside the jaws, bent as a cantilever of that length.
[[nodiscard]] Matrix2 rootFlexibility(const RoundSection &root, const ElasticMaterial &material);

// Rotational compliance [rad/(N·mm)] of the shoulder between `thick` and `thin` outer sections.
[[nodiscard]] double shoulderCompliance(const RoundSection &thick, const RoundSection &thin,
                                        const ElasticMaterial &material);

// The flexibility an element (z0 to z0 + h, cantilever from z0) gains from a compliance C at its
// start: Gamma C Gamma^T with Gamma = [[1, h], [0, 1]] (the base's rotation carried to the end).
[[nodiscard]] Matrix2 flexibilityAtStart(const Matrix2 &compliance, double length_mm);

// The extra flexibility of the element from z0 to z1 of a beam over `section`: the root where z0
// is the built-in face, the hinge of a shoulder where the outer diameter steps at z0.
[[nodiscard]] Matrix2 correctionFlexibility(const SectionAlongZ &section, const ElasticMaterial &material,
                                            const BeamCorrections &corrections, double z0_mm, double z1_mm);

} // namespace tolturn
