// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/part/profile.h"

#include <QString>

#include <variant>

namespace tolturn {

// The edits of the profile editor, as functions from a profile to a new one. They keep the
// contour connected and its features what they are in machining terms (a cylinder stays at one
// diameter, a face at one z); whether the result is a valid part is for validateProfile() to say.
// An edit that cannot be made gives the reason instead, naming the feature and the value.
using ProfileEdit = std::variant<PartProfile, QString>;

// Vertex k of a contour is where segment k-1 ends and segment k starts (0 … n). Where the
// inner contour breaks (the solid between a bore from each end) these are two points: `atBreak`
// says which one moves.
enum class AtBreak { StartOfSegment, EndOfSegment };

// Moves vertex k to `to`. A neighbouring cylinder keeps its diameter by moving its other end radially,
// a neighbouring face keeps its z by moving its other end axially (with the vertex beyond);
// cones, chamfers and radii change their slope.
[[nodiscard]] ProfileEdit moveVertex(const PartProfile &profile, ContourSide side, int vertex, ProfilePoint to,
                                     AtBreak atBreak = AtBreak::StartOfSegment);

// Splits cylinder `featureId` at `z_mm` into a cylinder, a face and a cylinder of diameter
// `diameter_mm` up to the cylinder's end: a step. The new features get fresh ids.
[[nodiscard]] ProfileEdit insertStep(const PartProfile &profile, const QString &featureId, double z_mm,
                                     double diameter_mm);

// Breaks the corner at vertex k (between a face and a cylinder) with a 45° chamfer of leg
// `size_mm`, or a radius `size_mm` tangent to both when `round` is true.
[[nodiscard]] ProfileEdit breakCorner(const PartProfile &profile, ContourSide side, int vertex, double size_mm,
                                      bool round);

// Turns a chamfer into an edge round of the same size (its leg as the radius) or a round into
// a 45° chamfer, keeping the feature's id. Both sit between a face and a cylinder.
[[nodiscard]] ProfileEdit swapCornerBreak(const PartProfile &profile, const QString &featureId);

// Removes a feature. A chamfer or radius gives back the sharp corner; a face between two
// cylinders removes the step (the cylinders merge at the first one's diameter); otherwise the
// features after it move to close the gap.
[[nodiscard]] ProfileEdit deleteFeature(const PartProfile &profile, const QString &featureId);

// Turns a cylinder into a cone (taper) ending at `endDiameter_mm`; what follows it moves with its end.
[[nodiscard]] ProfileEdit makeCone(const PartProfile &profile, const QString &featureId, double endDiameter_mm);
// Turns a cone into a cylinder at the diameter of its start; what follows it moves with its end.
[[nodiscard]] ProfileEdit makeCylinder(const PartProfile &profile, const QString &featureId);

// Bores a solid part from its end face `endFaceId` (the first or last outer feature): a
// cylindrical hole of `diameter_mm`, `depth_mm` deep (through when it reaches the other end),
// with a flat bottom. The end faces then close at the bore.
[[nodiscard]] ProfileEdit addBore(const PartProfile &profile, const QString &endFaceId, double depth_mm,
                                  double diameter_mm);

// A feature id not used yet on the contour: "O12", "I4", …
[[nodiscard]] QString nextFeatureId(const PartProfile &profile, ContourSide side);

// The number of an id made by nextFeatureId() ("O12" → 12; 0 for another id).
[[nodiscard]] int featureNumber(const QString &id);

// A straight feature (not a Radius) from `from` to `to`.
[[nodiscard]] Segment makeFeature(const QString &id, const QString &name, SegmentKind kind, ProfilePoint from,
                                  ProfilePoint to);

} // namespace tolturn
