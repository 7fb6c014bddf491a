// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/profile/profile_scene.h"

#include "core/part/profile_geometry.h"
#include "core/project/keywords.h"
#include "widgets/profile/dimension_item.h"
#include "widgets/profile/tolerance_frame_item.h"

#include <QBrush>
#include <QGraphicsPathItem>
#include <QGraphicsScene>
#include <QPainterPath>
#include <QPen>

#include <algorithm>
#include <cmath>
#include <set>

namespace tolturn {

namespace {

// Drawing conventions: ISO 128 line types (continuous wide for visible edges, continuous narrow
// for dimensions and hatching, dashed for hidden edges, long-dash dot for centre lines).
QPen cosmeticPen(const QColor &color, double width, Qt::PenStyle style = Qt::SolidLine)
{
    QPen pen(color, width, style);
    pen.setCosmetic(true);
    pen.setCapStyle(Qt::FlatCap);
    pen.setJoinStyle(Qt::RoundJoin);
    return pen;
}

const QColor kEdgeColor(0x20, 0x20, 0x20);
const QColor kHatchColor(0x6a, 0x7f, 0x99);
const QColor kAxisColor(0xb0, 0x30, 0x30);
const QColor kAnnotationColor(0x1f, 0x4e, 0x9a);

QPointF scenePoint(const ProfilePoint &p, double sign = 1.0)
{
    return {p.z_mm, -sign * p.r_mm};
}

QPainterPath segmentPath(const Segment &segment, double sign)
{
    const std::vector<ProfilePoint> points = samplePoints(segment);
    QPainterPath path(scenePoint(points.front(), sign));
    for (std::size_t i = 1; i < points.size(); ++i)
        path.lineTo(scenePoint(points[i], sign));
    return path;
}

void appendContour(QPolygonF &polygon, const Contour &contour, bool reversed)
{
    std::vector<ProfilePoint> points;
    for (const Segment &s : contour.segments) {
        const std::vector<ProfilePoint> seg = samplePoints(s);
        points.insert(points.end(), seg.begin(), seg.end());
    }
    if (reversed)
        std::reverse(points.begin(), points.end());
    for (const ProfilePoint &p : points)
        polygon << scenePoint(p);
}

// Outline of the material in the upper half: the outer contour left to right, then back along
// the bore (or the axis where there is no bore) to the start.
QPolygonF sectionOutline(const PartProfile &profile)
{
    QPolygonF polygon;
    appendContour(polygon, profile.outer, false);
    if (!profile.inner.empty()) {
        if (profile.inner.back().r_mm <= kProfileEpsilon_mm) // blind bore ending inside the part
            polygon << scenePoint({profile.inner.back().z_mm, 0.0});
        appendContour(polygon, profile.inner, true);
        if (profile.inner.front().z_mm > kProfileEpsilon_mm) // blind bore from the right
            polygon << scenePoint({0.0, 0.0});
    }
    return polygon;
}

void tagItem(QGraphicsItem *item, const QString &kind, const QString &featureId = QString())
{
    item->setData(kItemKindData, kind);
    if (!featureId.isEmpty())
        item->setData(kFeatureIdData, featureId);
    if (auto *shape = dynamic_cast<QAbstractGraphicsShapeItem *>(item))
        item->setData(kDefaultPenData, QVariant::fromValue(shape->pen()));
}

QString featureToolTip(const Segment &s, const DisplayUnits &units)
{
    QString text = QStringLiteral("<b>%1</b> %2").arg(s.id.toHtmlEscaped(), displayName(s.kind));
    if (!s.name.isEmpty())
        text += QStringLiteral(" — ") + s.name.toHtmlEscaped();
    const QString unit = units.lengthSymbol();
    text += QStringLiteral("<br>z %1 → %2 %5, r %3 → %4 %5")
                .arg(units.lengthText(s.from.z_mm), units.lengthText(s.to.z_mm), units.lengthText(s.from.r_mm),
                     units.lengthText(s.to.r_mm), unit);
    if (s.kind == SegmentKind::Radius)
        text += QStringLiteral("<br>R %1 %2, %3").arg(units.lengthText(s.arcRadius_mm), unit, keyword(s.arcDirection));
    return text;
}

void addContourItems(QGraphicsScene &scene, const Contour &contour, const QString &kind, const DisplayUnits &units)
{
    for (const Segment &s : contour.segments) {
        auto *item = scene.addPath(segmentPath(s, 1.0), cosmeticPen(kEdgeColor, 2.2));
        tagItem(item, kind, s.id);
        item->setToolTip(featureToolTip(s, units));
        item->setZValue(2.0);
    }
}

// Lower half: the outside view. The mirrored outer contour, and a line from the axis across the
// view at every circular edge: every face (an annulus seen edge-on reaches the axis line even on a
// hollow part) and every other vertex. The bore is drawn with hidden (dashed) lines.
void addOutsideView(QGraphicsScene &scene, const PartProfile &profile)
{
    const QPen outline = cosmeticPen(kEdgeColor, 1.4);
    auto edgeLine = [&](double z, double r, const QString &featureId) {
        QPainterPath edge(scenePoint({z, 0.0}));
        edge.lineTo(scenePoint({z, r}, -1.0));
        tagItem(scene.addPath(edge, outline), profile_item::kViewOutline, featureId);
    };
    for (const Segment &s : profile.outer.segments) {
        if (s.kind == SegmentKind::Face) {
            edgeLine(s.from.z_mm, std::max(s.from.r_mm, s.to.r_mm), s.id);
            continue;
        }
        tagItem(scene.addPath(segmentPath(s, -1.0), outline), profile_item::kViewOutline, s.id);
        if (s.to.r_mm > kProfileEpsilon_mm)
            edgeLine(s.to.z_mm, s.to.r_mm, QString());
    }
    const QPen hidden = cosmeticPen(kEdgeColor, 1.0, Qt::DashLine);
    for (const Segment &s : profile.inner.segments)
        tagItem(scene.addPath(segmentPath(s, -1.0), hidden), profile_item::kHiddenLine, s.id);
}

void addAxis(QGraphicsScene &scene, double length)
{
    QPen pen = cosmeticPen(kAxisColor, 1.0, Qt::CustomDashLine);
    pen.setDashPattern({18.0, 4.0, 2.0, 4.0});
    const double overhang = 0.05 * length + 3.0;
    auto *axis = scene.addLine(-overhang, 0.0, length + overhang, 0.0, pen);
    tagItem(axis, profile_item::kAxis);
    axis->setZValue(3.0);
}

void addDimension(QGraphicsScene &scene, QPointF from, QPointF to, double offset, const QString &text, double arrow,
                  double labelAt = 0.5)
{
    auto *dim = new DimensionItem(from, to, offset, text, arrow, labelAt);
    tagItem(dim, profile_item::kDimension);
    dim->setZValue(4.0);
    scene.addItem(dim);
}

// Ø of every cylinder, drawn across the full diameter at the middle of the feature and lettered
// in the outside view, off the centre line and the hatching; bores are dimensioned a third of the
// way along so they do not sit on an outer dimension.
QString limitsText(const Tolerance &t, const DisplayUnits &units);

// The size tolerance written after a diameter.
QString sizeSuffix(const std::vector<Tolerance> &tolerances, const QString &featureId, const DisplayUnits &units)
{
    for (const Tolerance &t : tolerances) {
        if (t.type == ToleranceType::Diameter && t.featureId == featureId)
            return QLatin1Char(' ') + limitsText(t, units);
    }
    return {};
}

// Where along a cylinder its Ø is lettered: of the fractions `where`, the one furthest from the
// z of any dimension already drawn (a bore's Ø clear of the outside's).
double dimensionZ(const Segment &s, const std::vector<double> &where, const std::vector<double> &taken)
{
    double best = s.from.z_mm + where.front() * (s.to.z_mm - s.from.z_mm);
    double bestGap = -1.0;
    for (const double f : where) {
        const double z = s.from.z_mm + f * (s.to.z_mm - s.from.z_mm);
        double gap = HUGE_VAL;
        for (const double t : taken)
            gap = std::min(gap, std::abs(z - t));
        if (gap > bestGap + 1e-9) {
            best = z;
            bestGap = gap;
        }
    }
    return best;
}

// Returns the z of the dimensions it drew.
std::vector<double> addDiameterDimensions(QGraphicsScene &scene, const Contour &contour,
                                          const std::vector<double> &where, const std::vector<double> &taken,
                                          double arrow, const std::vector<Tolerance> &tolerances,
                                          const DisplayUnits &units)
{
    std::vector<double> drawn;
    for (const Segment &s : contour.segments) {
        if (s.kind != SegmentKind::Cylinder)
            continue;
        const double z = dimensionZ(s, where, taken);
        drawn.push_back(z);
        addDimension(scene, scenePoint({z, s.from.r_mm}, -1.0), scenePoint({z, s.from.r_mm}), 0.0,
                     QStringLiteral("Ø") + units.lengthText(2.0 * s.from.r_mm) + sizeSuffix(tolerances, s.id, units),
                     arrow, 0.3);
    }
    return drawn;
}

// Positions along z that the length chain dimensions: the faces and the ends of cones of the outer
// contour (the functional positions; chamfers, edge radii and an undercut's flank under its
// shoulder are not chained), and both ends, less any closer than `minSpan` to the one kept before.
std::vector<double> chainStations(const PartProfile &profile, double minSpan)
{
    const double length = profile.length_mm();
    std::set<double> all{0.0, length};
    for (const Segment &s : profile.outer.segments) {
        if ((s.kind == SegmentKind::Face || s.kind == SegmentKind::Cone) && !s.turnsBack()) {
            all.insert(s.from.z_mm);
            all.insert(s.to.z_mm);
        }
    }
    std::vector<double> kept;
    for (const double z : all) {
        if (kept.empty() || (z - kept.back() >= minSpan && length - z >= minSpan))
            kept.push_back(z);
    }
    kept.push_back(length);
    return kept;
}

// A chain of lengths between the stations of the outer contour, below the outside view, and
// the overall length below that.
void addLengthDimensions(QGraphicsScene &scene, const PartProfile &profile, double arrow, const DisplayUnits &units,
                         double rowPitch)
{
    const double rMax = profile.maxOuterRadius_mm();
    const double gap = std::max({0.12 * rMax, 4.0 * arrow, rowPitch});
    // Dimension lines run right to left so that the positive offset (left normal) points down.
    const std::vector<double> z = chainStations(profile, 0.04 * profile.length_mm());
    for (std::size_t i = 1; i < z.size() && z.size() > 2; ++i) {
        addDimension(scene, scenePoint({z[i], rMax}, -1.0), scenePoint({z[i - 1], rMax}, -1.0), gap,
                     units.lengthText(z[i] - z[i - 1]), arrow);
    }
    const double overall = z.size() > 2 ? 2.0 * gap : gap;
    addDimension(scene, scenePoint({profile.length_mm(), rMax}, -1.0), scenePoint({0.0, rMax}, -1.0), overall,
                 units.lengthText(profile.length_mm()), arrow);
}

// The limits of a size tolerance as written after its dimension: the ISO 286 class, "±0.05" when
// symmetric, else "+0.05/-0.02" (in the length unit, mm or in).
QString limitsText(const Tolerance &t, const DisplayUnits &units)
{
    if (!t.iso286Class.isEmpty())
        return t.iso286Class;
    if (!t.upperDeviation_um || !t.lowerDeviation_um)
        return {};
    if (std::abs(*t.upperDeviation_um + *t.lowerDeviation_um) < 1e-9)
        return QStringLiteral("±") + units.lengthText(*t.upperDeviation_um / 1000.0);
    const int decimals = units.lengthUnit() == LengthUnit::Inch ? 4 : 3;
    const auto signedLimit = [&](double deviation_um) {
        const double shown = units.lengthFromMm(deviation_um / 1000.0);
        return QString::number(shown, 'f', decimals).prepend(shown >= 0.0 ? QStringLiteral("+") : QString());
    };
    return QStringLiteral("%1/%2").arg(signedLimit(*t.upperDeviation_um), signedLimit(*t.lowerDeviation_um));
}

// Each toleranced length between two faces as its own dimension below the overall length.
void addToleratedLengths(QGraphicsScene &scene, const PartProfile &profile, const std::vector<Tolerance> &tolerances,
                         double arrow, const DisplayUnits &units, double rowPitch)
{
    const double rMax = profile.maxOuterRadius_mm();
    const double gap = std::max({0.12 * rMax, 4.0 * arrow, rowPitch});
    double offset = 3.0 * gap;
    for (const Tolerance &t : tolerances) {
        const std::optional<FeatureRef> a = findFeature(profile, t.featureId);
        const std::optional<FeatureRef> b = findFeature(profile, t.toFeatureId);
        if (t.type != ToleranceType::Length || !a || !b)
            continue;
        const double z0 = std::min(a->segment->from.z_mm, b->segment->from.z_mm);
        const double z1 = std::max(a->segment->from.z_mm, b->segment->from.z_mm);
        addDimension(scene, scenePoint({z1, rMax}, -1.0), scenePoint({z0, rMax}, -1.0), offset,
                     units.lengthText(z1 - z0) + QLatin1Char(' ') + limitsText(t, units), arrow);
        offset += gap;
    }
}

// The point of a feature annotations point at: the middle of the segment, in the section above
// the axis (an outer feature from outside, a bore from its surface).
QPointF annotationPoint(const Segment &s)
{
    return scenePoint({0.5 * (s.from.z_mm + s.to.z_mm), 0.5 * (s.from.r_mm + s.to.r_mm)});
}

// One frame per geometric tolerance. Taken in order along z, the leaders rise in a staircase of
// three heights, so that the frames of neighbouring features (drawn in pixels, whatever the zoom)
// do not sit on each other.
void addToleranceFrames(QGraphicsScene &scene, const PartProfile &profile, const std::vector<Tolerance> &tolerances,
                        const DisplayUnits &units)
{
    std::vector<std::pair<const Tolerance *, const Segment *>> frames;
    for (const Tolerance &t : tolerances) {
        const std::optional<FeatureRef> ref = findFeature(profile, t.featureId);
        if (!isSizeTolerance(t.type) && t.zone_um && ref)
            frames.emplace_back(&t, ref->segment);
    }
    std::stable_sort(frames.begin(), frames.end(), [](const auto &a, const auto &b) {
        return annotationPoint(*a.second).x() < annotationPoint(*b.second).x();
    });
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const Tolerance &t = *frames[i].first;
        auto *frame = new ToleranceFrameItem(t.type, units.lengthText(*t.zone_um / 1000.0), t.datums,
                                             30.0 + 24.0 * static_cast<double>(i % 3));
        // The leader runs in the drawing from the feature up to the part's top line, then on in
        // pixels to the frame; its arrow ends on the feature.
        const QPointF onFeature = annotationPoint(*frames[i].second);
        const QPointF top(onFeature.x(), std::min(onFeature.y(), -profile.maxOuterRadius_mm()));
        auto *leader = scene.addLine(QLineF(onFeature, top), cosmeticPen(kAnnotationColor, 1.0));
        auto *arrowhead = new LeaderArrowItem;
        arrowhead->setPos(onFeature);
        scene.addItem(arrowhead);
        for (QGraphicsItem *part : {static_cast<QGraphicsItem *>(leader), static_cast<QGraphicsItem *>(arrowhead)}) {
            part->setZValue(6.0);
            tagItem(part, profile_item::kToleranceFrame, t.featureId);
        }
        frame->setPos(top);
        frame->setZValue(6.0);
        tagItem(frame, profile_item::kToleranceFrame, t.featureId);
        scene.addItem(frame);
    }
}

void addDatums(QGraphicsScene &scene, const PartProfile &profile, const std::vector<Datum> &datums)
{
    for (const Datum &d : datums) {
        const std::optional<FeatureRef> ref = findFeature(profile, d.featureId);
        if (!ref)
            continue;
        auto *item = new DatumItem(d.label);
        // A fifth of the way along the feature, left of the frames' leaders at its middle.
        const Segment &s = *ref->segment;
        item->setPos(
            scenePoint({s.from.z_mm + 0.2 * (s.to.z_mm - s.from.z_mm), s.from.r_mm + 0.2 * (s.to.r_mm - s.from.r_mm)}));
        item->setZValue(6.0);
        tagItem(item, profile_item::kDatum, d.featureId);
        scene.addItem(item);
    }
}

} // namespace

QString dimensionText(double value_mm)
{
    return DisplayUnits().lengthText(value_mm);
}

void addClamping(QGraphicsScene &scene, const PartProfile &profile, const Clamping &clamping)
{
    if (profile.outer.empty())
        return;
    const double length = profile.length_mm();
    const double rMax = profile.maxOuterRadius_mm();
    const QPen pen = cosmeticPen(QColor(0x55, 0x55, 0x55), 1.0);
    const QBrush brush(QColor(0x80, 0x80, 0x80, 110));
    auto tag = [](QGraphicsItem *item) {
        tagItem(item, profile_item::kClamping);
        item->setZValue(0.5);
    };
    if (clamping.method != ClampingMethod::BetweenCentres && clamping.clampedLength_mm > 0.0) {
        const double grip = profile.gripRadius_mm(clamping.clampedLength_mm);
        const QRectF jaw(scenePoint({0.0, grip + 0.3 * rMax}), scenePoint({clamping.clampedLength_mm, grip}));
        tag(scene.addRect(jaw.normalized(), pen, brush));
    }
    auto centre = [&](double z, double direction) { // a 60° centre with its tip at the axis
        const double size = 0.35 * rMax;
        QPolygonF cone;
        cone << scenePoint({z, 0.0}) << scenePoint({z - direction * size, 0.5 * size})
             << scenePoint({z - direction * size, -0.5 * size});
        tag(scene.addPolygon(cone, pen, brush));
    };
    if (clamping.method == ClampingMethod::BetweenCentres)
        centre(0.0, 1.0); // its body left of the part
    if (!holdsOneEndOnly(clamping.method))
        centre(length, -1.0); // right of it
}

void buildProfileScene(QGraphicsScene &scene, const PartProfile &profile, const std::vector<Tolerance> &tolerances,
                       const std::vector<Datum> &datums, const DisplayUnits &units, double rowPitch_mm)
{
    scene.clear();
    if (profile.outer.empty())
        return;
    const double length = profile.length_mm();
    const double arrow = std::clamp(0.012 * std::max(length, 2.0 * profile.maxOuterRadius_mm()), 0.3, 6.0);

    auto *section = scene.addPolygon(sectionOutline(profile), Qt::NoPen, QBrush(kHatchColor, Qt::BDiagPattern));
    tagItem(section, profile_item::kSection);
    section->setZValue(1.0);

    addContourItems(scene, profile.outer, profile_item::kOuterContour, units);
    addContourItems(scene, profile.inner, profile_item::kInnerContour, units);
    addOutsideView(scene, profile);
    addAxis(scene, length);
    const std::vector<double> outside =
        addDiameterDimensions(scene, profile.outer, {0.5}, {}, arrow, tolerances, units);
    addDiameterDimensions(scene, profile.inner, {0.3, 0.7}, outside, arrow, tolerances, units);
    addLengthDimensions(scene, profile, arrow, units, rowPitch_mm);
    addToleratedLengths(scene, profile, tolerances, arrow, units, rowPitch_mm);
    addToleranceFrames(scene, profile, tolerances, units);
    addDatums(scene, profile, datums);
}

} // namespace tolturn
