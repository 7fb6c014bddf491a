// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/project.h"
#include "widgets/common/display_units.h"

#include <QString>

class QGraphicsScene;

namespace tolturn {

// Keys of QGraphicsItem::data() on the items of a profile scene, so that views, tools and tests
// can find items by what they represent.
enum ProfileItemData : int {
    kItemKindData = 0,   // QString, one of the kinds below
    kFeatureIdData = 1,  // QString, id of the profile segment (contour items)
    kDefaultPenData = 2, // QPen the item is drawn with when not selected
    kVertexData = 3,     // int, vertex index on its contour (vertex handles)
    kSideData = 4,       // int, ContourSide of a vertex handle
    kSegmentEndData = 5, // bool, a vertex handle at the end (not the start) of its feature
};

namespace profile_item {
inline const QString kAxis = QStringLiteral("axis");
inline const QString kSection = QStringLiteral("section");
inline const QString kOuterContour = QStringLiteral("outer-contour");
inline const QString kInnerContour = QStringLiteral("inner-contour");
inline const QString kViewOutline = QStringLiteral("view-outline");
inline const QString kHiddenLine = QStringLiteral("hidden-line");
inline const QString kDimension = QStringLiteral("dimension");
inline const QString kVertexHandle = QStringLiteral("vertex-handle");
inline const QString kToleranceFrame = QStringLiteral("tolerance-frame");
inline const QString kDatum = QStringLiteral("datum");
inline const QString kClamping = QStringLiteral("clamping");
} // namespace profile_item

// Draws a part as a half-section drawing: above the axis the section (hatched material,
// outer and inner contour, one item per feature), below it the outside view with the bore as
// hidden lines; diameters of every cylinder and the chain of lengths dimensioned. Scene units
// are millimetres with y = -r, so the part reads upright.
// With `tolerances` and `datums`, size tolerances are written after their diameters ("Ø50 h6"),
// geometric tolerances drawn as feature control frames and datums as datum indicators
// (ISO 1101, ISO 5459), each on its feature.
// Dimension texts are in `units` (millimetres unless the settings say inches). `rowPitch_mm` is the
// least distance between rows of length dimensions: their labels keep their size on screen, so a
// view or a report gives the label height at its scale (0: by the part's size alone).
void buildProfileScene(QGraphicsScene &scene, const PartProfile &profile, const std::vector<Tolerance> &tolerances = {},
                       const std::vector<Datum> &datums = {}, const DisplayUnits &units = DisplayUnits(),
                       double rowPitch_mm = 0.0);

// How the part is held, drawn over the section: the chuck jaws over the clamped length (above the
// axis, where they do not meet the dimensions below), the centres at the axis, the tailstock centre.
void addClamping(QGraphicsScene &scene, const PartProfile &profile, const Clamping &clamping);

// The row pitch that fits labels of `labelHeight` device units at `scale` device units per mm.
[[nodiscard]] inline double dimensionRowPitch_mm(double labelHeight, double scale)
{
    return scale > 0.0 ? (labelHeight + 6.0) / scale : 0.0;
}

// Text of a dimension value in mm: at most three decimals, no trailing zeros.
[[nodiscard]] QString dimensionText(double value_mm);

} // namespace tolturn
