// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cad/revolved_faces.h"

#include "core/cad/material_side.h"

#include <Eigen/Dense>
#include <QCoreApplication>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_Surface.hxx>
#include <ShapeCustom_Surface.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <gp_Lin.hxx>

namespace tolturn::cad {

namespace {

struct RevolvedFaces {
    Q_DECLARE_TR_FUNCTIONS(RevolvedFaces)
};

// Two axes are the same when their directions differ by less than this and each passes within
// kJoinTolerance_mm of the other's origin. OpenCascade's own angular confusion
// (Precision::Angular) is 1e-12; files written by other systems round directions to ~1e-9.
constexpr double kAngularTolerance_rad = 1e-6;

// Points sampled along a curved edge to bound its extent. The extreme z of a face revolved about
// the axis lies on its circular edges (constant z, any sample is exact); the samples only bound
// the other edges (cuts of keyways and flats), whose z ranges are reported, not used.
constexpr int kEdgeSamples = 16;

// A revolved face that covers less than this fraction of the area its trace sweeps in a full
// turn is not a turned surface but part of one (the end wall of a keyway, the bottom of a slot).
constexpr double kMinRevolvedCoverage = 0.5;

struct Frame {
    gp_Ax1 axis;

    [[nodiscard]] double z(const gp_Pnt &p) const { return gp_Vec(axis.Location(), p).Dot(gp_Vec(axis.Direction())); }

    [[nodiscard]] double r(const gp_Pnt &p) const { return gp_Lin(axis).Distance(p); }
};

bool coaxial(const gp_Ax1 &a, const gp_Ax1 &b)
{
    return a.IsParallel(b, kAngularTolerance_rad) && gp_Lin(a).Distance(b.Location()) <= kJoinTolerance_mm;
}

// One representation per line: the direction with its largest component positive, the origin
// the point of the line nearest the model origin. So a part modelled along +Z gets z = 0 at its
// lowest Z end.
gp_Ax1 canonical(const gp_Ax1 &a)
{
    gp_Dir d = a.Direction();
    const double x = d.X();
    const double y = d.Y();
    const double z = d.Z();
    const double largest = std::abs(x) >= std::abs(y) && std::abs(x) >= std::abs(z) ? x
                           : std::abs(y) >= std::abs(z)                             ? y
                                                                                    : z;
    if (largest < 0.0)
        d.Reverse();
    const gp_Pnt o = a.Location();
    const double t = gp_Vec(gp_Pnt(0, 0, 0), o).Dot(gp_Vec(d));
    return {gp_Pnt(o.XYZ() - t * d.XYZ()), d};
}

// Within this distance a B-spline or Bézier surface is taken as the plane, cylinder, cone,
// sphere or torus it stands for: 1 µm, a hundredth of the tightest IT grade a turned diameter
// gets here (IT5 at 3 mm is 4 µm, ISO 286-1 table 1), and far above the approximation error of
// the CAD systems that write elementary faces as splines.
constexpr double kAnalyticTolerance_mm = 1e-3;

// The face's surface (with its location) as the tracer reads it: an elementary surface as it is,
// a spline one converted to the elementary surface it is within kAnalyticTolerance_mm
// (ShapeCustom_Surface::ConvertToAnalytical), else as it is.
struct FaceGeometry {
    GeomAdaptor_Surface surface;
    bool converted = false;
};

FaceGeometry faceGeometry(const TopoDS_Face &face)
{
    FaceGeometry g;
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    if (surface.IsNull())
        return g;
    g.surface.Load(surface);
    const GeomAbs_SurfaceType type = g.surface.GetType();
    if (type != GeomAbs_BSplineSurface && type != GeomAbs_BezierSurface)
        return g;
    ShapeCustom_Surface convert(surface);
    const Handle(Geom_Surface) analytic = convert.ConvertToAnalytical(kAnalyticTolerance_mm, Standard_False);
    if (!analytic.IsNull()) {
        g.surface.Load(analytic);
        g.converted = true;
    }
    return g;
}

std::optional<gp_Ax1> surfaceAxis(const Adaptor3d_Surface &s)
{
    switch (s.GetType()) {
    case GeomAbs_Cylinder:
        return s.Cylinder().Axis();
    case GeomAbs_Cone:
        return s.Cone().Axis();
    case GeomAbs_Torus:
        return s.Torus().Axis();
    case GeomAbs_SurfaceOfRevolution: // IGES 120, the usual form of turned faces in IGES files
        return s.AxeOfRevolution();
    default:
        return std::nullopt; // a sphere is symmetric about every line through its centre
    }
}

double faceArea(const TopoDS_Face &face)
{
    GProp_GProps props;
    BRepGProp::SurfaceProperties(face, props);
    return props.Mass();
}

struct Extent {
    double zMin = HUGE_VAL;
    double zMax = -HUGE_VAL;
    double rMin = HUGE_VAL;
    double rMax = -HUGE_VAL;

    void add(const Frame &f, const gp_Pnt &p)
    {
        const double z = f.z(p);
        const double r = f.r(p);
        zMin = std::min(zMin, z);
        zMax = std::max(zMax, z);
        rMin = std::min(rMin, r);
        rMax = std::max(rMax, r);
    }
};

Extent faceExtent(const TopoDS_Face &face, const Frame &f)
{
    Extent e;
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
        const TopoDS_Edge &edge = TopoDS::Edge(ex.Current());
        if (BRep_Tool::Degenerated(edge))
            continue; // the apex of a cone, the pole of a sphere: no 3-D curve
        const BRepAdaptor_Curve c(edge);
        const int n = c.GetType() == GeomAbs_Line ? 1 : kEdgeSamples;
        for (int i = 0; i <= n; ++i)
            e.add(f, c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * i / n));
    }
    return e;
}

SectionPiece line(ProfilePoint a, ProfilePoint b)
{
    SectionPiece p;
    p.a = a;
    p.b = b;
    return p;
}

SectionPiece arc(ProfilePoint a, ProfilePoint b, ProfilePoint centre, double radius)
{
    SectionPiece p = line(a, b);
    p.arc = true;
    p.centre = centre;
    p.radius_mm = radius;
    return p;
}

// The point of the face in the middle of its parameter range, to tell which half of a circle
// an arc of a torus lies on.
gp_Pnt midPoint(const TopoDS_Face &face)
{
    const BRepAdaptor_Surface s(face); // the face's own parameters, whatever surface it is read as
    double u0 = 0.0;
    double u1 = 0.0;
    double v0 = 0.0;
    double v1 = 0.0;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    return s.Value(0.5 * (u0 + u1), 0.5 * (v0 + v1));
}

class FaceTracer {
public:
    FaceTracer(const gp_Ax1 &axis, SectionTrace &out) : m_frame{axis}, m_out(out) {}

    void trace(int index, const TopoDS_Face &face)
    {
        const FaceGeometry geometry = faceGeometry(face);
        const GeomAdaptor_Surface &s = geometry.surface;
        const Extent e = faceExtent(face, m_frame);
        std::optional<SectionPiece> piece;
        QString what;
        switch (s.GetType()) {
        case GeomAbs_Plane:
            piece = plane(face, s, e, what);
            break;
        case GeomAbs_Cylinder:
            piece = cylinder(s, e, what);
            break;
        case GeomAbs_Cone:
            piece = cone(s, e, what);
            break;
        case GeomAbs_Torus:
            piece = torus(face, s, e, what);
            break;
        case GeomAbs_Sphere:
            piece = sphere(s, e, what);
            break;
        case GeomAbs_SurfaceOfRevolution:
            piece = revolution(face, s, what);
            break;
        case GeomAbs_BSplineSurface:
        case GeomAbs_BezierSurface:
            // Not an elementary surface as a whole: a fillet (torus) or a cone written as a spline
            // is still one meridian curve turned about the part axis.
            piece = meridian(face, e);
            if (piece)
                m_out.convertedFaces.emplace_back(
                    index, piece->arc ? RevolvedFaces::tr("a torus about the part axis")
                                      : RevolvedFaces::tr("a cylinder, cone or face about the part axis"));
            else
                what = otherSurface(s.GetType());
            break;
        default:
            what = otherSurface(s.GetType());
            break;
        }
        if (piece && geometry.converted)
            m_out.convertedFaces.emplace_back(index, surfaceName(s.GetType()));
        if (piece) {
            piece->faces.push_back(index);
            piece->faceArea_mm2 = faceArea(face);
            m_out.pieces.push_back(*piece);
        } else {
            m_out.leftOut.push_back(leftOutFace(index, what, e, face, s));
        }
    }

private:
    [[nodiscard]] LeftOutFace leftOutFace(int index, const QString &what, const Extent &e, const TopoDS_Face &face,
                                          const GeomAdaptor_Surface &s) const
    {
        LeftOutFace f{index, what, e.zMin, e.zMax, leftOutShape(s), {}, 0.0, {}};
        if (f.shape != LeftOutShape::PlaneAlongAxis)
            return f;
        // The face's own normal, turned with its orientation, points out of the material.
        const auto pointNormal = pointAndNormal(face);
        if (!pointNormal)
            return f; // a degenerate face: no direction to tell a flat by
        const gp_Pnt point = pointNormal->first;
        gp_Vec normal = pointNormal->second;
        normal.Normalize();
        f.outwardNormal = {normal.X(), normal.Y(), normal.Z()};
        f.axisOffset_mm = normal.Dot(gp_Vec(m_frame.axis.Location(), point));
        return f;
    }

    // Called for a face left out: a plane there is not across the axis (plane() takes those).
    [[nodiscard]] LeftOutShape leftOutShape(const GeomAdaptor_Surface &s) const
    {
        if (s.GetType() != GeomAbs_Plane)
            return LeftOutShape::Other;
        return s.Plane().Axis().IsNormal(m_frame.axis, kAngularTolerance_rad) ? LeftOutShape::PlaneAlongAxis
                                                                              : LeftOutShape::PlaneAtSlant;
    }

    // A plane is a turned face when its normal is the axis (the trace is a line at constant z);
    // the face reaches the axis when the axis point of the plane lies inside it.
    std::optional<SectionPiece> plane(const TopoDS_Face &face, const GeomAdaptor_Surface &s, const Extent &e,
                                      QString &what) const
    {
        const gp_Pln pln = s.Plane();
        if (!pln.Axis().IsParallel(m_frame.axis, kAngularTolerance_rad)) {
            what = RevolvedFaces::tr("a plane not perpendicular to the axis (a flat or a side of a keyway)");
            return std::nullopt;
        }
        const double z = m_frame.z(pln.Location());
        const gp_Pnt onAxis(m_frame.axis.Location().XYZ() + z * m_frame.axis.Direction().XYZ());
        const BRepClass_FaceClassifier classifier(face, onAxis, kJoinTolerance_mm);
        const bool throughAxis = classifier.State() == TopAbs_IN || classifier.State() == TopAbs_ON;
        return line({z, throughAxis ? 0.0 : e.rMin}, {z, e.rMax});
    }

    std::optional<SectionPiece> cylinder(const GeomAdaptor_Surface &s, const Extent &e, QString &what) const
    {
        const gp_Cylinder c = s.Cylinder();
        if (!coaxial(c.Axis(), m_frame.axis)) {
            what = c.Axis().IsParallel(m_frame.axis, kAngularTolerance_rad)
                       ? RevolvedFaces::tr("a cylinder parallel to the axis but off it (an eccentric or an "
                                           "off-centre hole)")
                       : RevolvedFaces::tr("a cylinder across the axis (a cross hole)");
            return std::nullopt;
        }
        const double r = c.Radius();
        return line({e.zMin, r}, {e.zMax, r});
    }

    // gp_Cone: P(u, v) = O + (R + v sin a)(cos u X + sin u Y) + v cos a Z, so the radius grows by
    // tan a per unit along the cone's own axis direction Z.
    std::optional<SectionPiece> cone(const GeomAdaptor_Surface &s, const Extent &e, QString &what) const
    {
        const gp_Cone c = s.Cone();
        if (!coaxial(c.Axis(), m_frame.axis)) {
            what = RevolvedFaces::tr("a cone whose axis is not the part axis (a countersink of a cross hole)");
            return std::nullopt;
        }
        const double z0 = m_frame.z(c.Location());
        const double sense = c.Axis().Direction().Dot(m_frame.axis.Direction()) > 0.0 ? 1.0 : -1.0;
        const auto radiusAt = [&](double z) {
            return std::max(0.0, c.RefRadius() + sense * (z - z0) * std::tan(c.SemiAngle()));
        };
        return line({e.zMin, radiusAt(e.zMin)}, {e.zMax, radiusAt(e.zMax)});
    }

    // gp_Torus: the tube circle of minor radius rho is centred at the major radius R; its trace
    // is an arc centred at (z of the torus centre, R). Its ends are at the face's z extremes,
    // on the half of the circle the middle of the face lies on.
    std::optional<SectionPiece> torus(const TopoDS_Face &face, const GeomAdaptor_Surface &s, const Extent &e,
                                      QString &what) const
    {
        const gp_Torus t = s.Torus();
        if (!coaxial(t.Axis(), m_frame.axis)) {
            what = RevolvedFaces::tr("a torus whose axis is not the part axis");
            return std::nullopt;
        }
        const ProfilePoint centre{m_frame.z(t.Location()), t.MajorRadius()};
        const double rho = t.MinorRadius();
        return meridianArc(face, centre, rho, e);
    }

    // A sphere centred on the axis traces an arc centred on the axis (a ball end, a spherical
    // seat); r >= 0 takes the upper half of its circle.
    std::optional<SectionPiece> sphere(const GeomAdaptor_Surface &s, const Extent &e, QString &what) const
    {
        const gp_Sphere sp = s.Sphere();
        if (m_frame.r(sp.Location()) > kJoinTolerance_mm) {
            what = RevolvedFaces::tr("a sphere whose centre is off the axis");
            return std::nullopt;
        }
        const ProfilePoint centre{m_frame.z(sp.Location()), 0.0};
        const double radius = sp.Radius();
        const auto at = [&](double z) {
            const double dz = z - centre.z_mm;
            return ProfilePoint{z, std::sqrt(std::max(0.0, radius * radius - dz * dz))};
        };
        return arc(at(e.zMin), at(e.zMax), centre, radius);
    }

    // A curve swept about an axis (what BRepPrimAPI_MakeRevol makes of a line or an arc): its
    // meridian is the basis curve, traced at the middle angle of the face from the first to the
    // last parameter of the curve. Lines and circles are turned; other curves are free-form.
    std::optional<SectionPiece> revolution(const TopoDS_Face &face, const GeomAdaptor_Surface &s, QString &what) const
    {
        const GeomAbs_CurveType basis = s.BasisCurve()->GetType();
        if (!coaxial(s.AxeOfRevolution(), m_frame.axis) || (basis != GeomAbs_Line && basis != GeomAbs_Circle)) {
            what = otherSurface(GeomAbs_SurfaceOfRevolution);
            return std::nullopt;
        }
        double u0 = 0.0;
        double u1 = 0.0;
        double v0 = 0.0;
        double v1 = 0.0;
        BRepTools::UVBounds(face, u0, u1, v0, v1);
        const double u = 0.5 * (u0 + u1);
        const auto at = [&](double v) {
            const gp_Pnt p = s.Value(u, v);
            return ProfilePoint{m_frame.z(p), m_frame.r(p)};
        };
        if (basis == GeomAbs_Line)
            return line(at(v0), at(v1));
        // A circle in a meridian plane sweeps a torus (IGES writes fillets so): its trace is the
        // arc of that circle between the face's z extremes, on the half the face lies on, as for
        // a torus. Three points of the parameter range would not do: an IGES trimmed surface
        // keeps the whole circle as its parameter range.
        const gp_Circ circle = s.BasisCurve()->Circle();
        const ProfilePoint centre{m_frame.z(circle.Location()), m_frame.r(circle.Location())};
        const double rho = circle.Radius();
        const Extent e = faceExtent(face, m_frame);
        return meridianArc(face, centre, rho, e);
    }

    // A spline face that is a surface of revolution about the part axis: points over its parameter
    // range, each taken to (z, r) about the axis, lie on one line (a cone, cylinder or plane) or one
    // circle (a torus) within kAnalyticTolerance_mm. The circle is the least-squares fit of
    // (z - zc)² + (r - rc)² = rho² written linear in zc, rc and rho² - zc² - rc² (Kasa 1976).
    std::optional<SectionPiece> meridian(const TopoDS_Face &face, const Extent &e) const
    {
        constexpr int kSamples = 9; // per parameter direction
        const BRepAdaptor_Surface s(face);
        std::vector<ProfilePoint> points;
        for (int i = 0; i < kSamples; ++i) {
            for (int j = 0; j < kSamples; ++j) {
                const double u = s.FirstUParameter() + (s.LastUParameter() - s.FirstUParameter()) * i / (kSamples - 1);
                const double v = s.FirstVParameter() + (s.LastVParameter() - s.FirstVParameter()) * j / (kSamples - 1);
                const gp_Pnt p = s.Value(u, v);
                points.push_back({m_frame.z(p), m_frame.r(p)});
            }
        }
        // A line first: all points at the distance of the line through the extreme z.
        const ProfilePoint a = *std::min_element(points.begin(), points.end(),
                                                 [](const auto &p, const auto &q) { return p.z_mm < q.z_mm; });
        const ProfilePoint b = *std::max_element(points.begin(), points.end(),
                                                 [](const auto &p, const auto &q) { return p.z_mm < q.z_mm; });
        const double length = std::hypot(b.z_mm - a.z_mm, b.r_mm - a.r_mm);
        const auto offLine = [&](const ProfilePoint &p) {
            return std::abs((b.z_mm - a.z_mm) * (p.r_mm - a.r_mm) - (b.r_mm - a.r_mm) * (p.z_mm - a.z_mm)) / length;
        };
        if (length > kJoinTolerance_mm && std::all_of(points.begin(), points.end(), [&](const auto &p) {
                return offLine(p) <= kAnalyticTolerance_mm;
            }))
            return line(a, b);
        Eigen::MatrixXd m(static_cast<Eigen::Index>(points.size()), 3);
        Eigen::VectorXd rhs(static_cast<Eigen::Index>(points.size()));
        for (std::size_t k = 0; k < points.size(); ++k) {
            const auto row = static_cast<Eigen::Index>(k);
            m(row, 0) = 2.0 * points[k].z_mm;
            m(row, 1) = 2.0 * points[k].r_mm;
            m(row, 2) = 1.0;
            rhs(row) = points[k].z_mm * points[k].z_mm + points[k].r_mm * points[k].r_mm;
        }
        const Eigen::Vector3d x = m.colPivHouseholderQr().solve(rhs);
        const ProfilePoint centre{x(0), x(1)};
        const double rho2 = x(2) + x(0) * x(0) + x(1) * x(1);
        if (!(rho2 > 0.0))
            return std::nullopt;
        const double rho = std::sqrt(rho2);
        const bool onCircle = std::all_of(points.begin(), points.end(), [&](const ProfilePoint &p) {
            return std::abs(std::hypot(p.z_mm - centre.z_mm, p.r_mm - centre.r_mm) - rho) <= kAnalyticTolerance_mm;
        });
        if (!onCircle)
            return std::nullopt;
        return meridianArc(face, centre, rho, e);
    }

    // The trace of a face whose meridian is a circle (centre, radius rho) in the half-plane: the
    // arc between the face's z extremes, on the half of the circle the middle of the face lies on.
    // The (z, r) of the face's edges that are circles (or arcs of circles) about the axis: every
    // point of such an edge has the same z and r. Seams and meridian edges are left out.
    [[nodiscard]] std::vector<ProfilePoint> boundaryCircles(const TopoDS_Face &face) const
    {
        std::vector<ProfilePoint> found;
        for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
            const TopoDS_Edge &edge = TopoDS::Edge(ex.Current());
            if (BRep_Tool::Degenerated(edge))
                continue;
            const BRepAdaptor_Curve c(edge);
            std::array<ProfilePoint, 3> at{};
            for (std::size_t i = 0; i < at.size(); ++i) {
                const gp_Pnt p = c.Value(c.FirstParameter() +
                                         (c.LastParameter() - c.FirstParameter()) * 0.5 * static_cast<double>(i));
                at[i] = {m_frame.z(p), m_frame.r(p)};
            }
            const auto same = [](const ProfilePoint &a, const ProfilePoint &b) {
                return std::hypot(a.z_mm - b.z_mm, a.r_mm - b.r_mm) <= kJoinTolerance_mm;
            };
            if (!same(at[0], at[1]) || !same(at[0], at[2]))
                continue; // not about the axis
            if (std::none_of(found.begin(), found.end(), [&](const ProfilePoint &q) { return same(q, at[0]); }))
                found.push_back(at[0]);
        }
        return found;
    }

    [[nodiscard]] std::optional<SectionPiece> meridianArc(const TopoDS_Face &face, const ProfilePoint &centre,
                                                          double rho, const Extent &e) const
    {
        // The ends are where the face's boundary circles about the axis cut the meridian: an
        // undercut's radius turns back along z and does not end at its z extremes.
        if (const std::vector<ProfilePoint> ends = boundaryCircles(face); ends.size() == 2)
            return arc(ends[0], ends[1], centre, rho);
        const double side = m_frame.r(midPoint(face)) >= centre.r_mm ? 1.0 : -1.0;
        const auto at = [&](double z) {
            const double dz = z - centre.z_mm;
            return ProfilePoint{z, centre.r_mm + side * std::sqrt(std::max(0.0, rho * rho - dz * dz))};
        };
        return arc(at(e.zMin), at(e.zMax), centre, rho);
    }

    static QString surfaceName(GeomAbs_SurfaceType type)
    {
        switch (type) {
        case GeomAbs_Plane:
            return RevolvedFaces::tr("a plane");
        case GeomAbs_Cylinder:
            return RevolvedFaces::tr("a cylinder");
        case GeomAbs_Cone:
            return RevolvedFaces::tr("a cone");
        case GeomAbs_Sphere:
            return RevolvedFaces::tr("a sphere");
        case GeomAbs_Torus:
            return RevolvedFaces::tr("a torus");
        default:
            return otherSurface(type);
        }
    }

    static QString otherSurface(GeomAbs_SurfaceType type)
    {
        switch (type) {
        case GeomAbs_BezierSurface:
        case GeomAbs_BSplineSurface:
            return RevolvedFaces::tr("a free-form (B-spline) surface, such as a modelled thread or an engraving");
        case GeomAbs_SurfaceOfRevolution:
            return RevolvedFaces::tr("a surface of revolution of a free-form curve");
        case GeomAbs_SurfaceOfExtrusion:
            return RevolvedFaces::tr("an extruded free-form surface");
        default:
            return RevolvedFaces::tr("a surface of a kind TolTurn does not turn (offset or other)");
        }
    }

    Frame m_frame;
    SectionTrace &m_out;
};

bool sameTrace(const SectionPiece &p, const SectionPiece &q)
{
    const auto near = [](const ProfilePoint &a, const ProfilePoint &b) {
        return std::abs(a.z_mm - b.z_mm) <= kJoinTolerance_mm && std::abs(a.r_mm - b.r_mm) <= kJoinTolerance_mm;
    };
    return p.arc == q.arc && ((near(p.a, q.a) && near(p.b, q.b)) || (near(p.a, q.b) && near(p.b, q.a)));
}

// Several faces on one trace (a cylinder written as two half-cylinders) are one piece; a piece
// whose faces cover too little of its revolution is a partial wall, reported instead.
void mergeAndFilter(SectionTrace &trace)
{
    std::vector<SectionPiece> merged;
    for (SectionPiece &p : trace.pieces) {
        const auto same = std::find_if(merged.begin(), merged.end(), [&](const auto &m) { return sameTrace(m, p); });
        if (same == merged.end()) {
            merged.push_back(std::move(p));
            continue;
        }
        same->faces.insert(same->faces.end(), p.faces.begin(), p.faces.end());
        same->faceArea_mm2 += p.faceArea_mm2;
    }
    trace.pieces.clear();
    for (SectionPiece &p : merged) {
        const double length = std::hypot(p.b.z_mm - p.a.z_mm, p.b.r_mm - p.a.r_mm);
        if (length <= kJoinTolerance_mm)
            continue; // a sliver with no extent in the section
        if (p.faceArea_mm2 >= kMinRevolvedCoverage * revolvedArea_mm2(p)) {
            trace.pieces.push_back(std::move(p));
            continue;
        }
        const QString what = RevolvedFaces::tr("a part of a turned surface that does not go round (the end wall of "
                                               "a keyway or a slot)");
        for (const int face : p.faces)
            trace.leftOut.push_back({face,
                                     what,
                                     std::min(p.a.z_mm, p.b.z_mm),
                                     std::max(p.a.z_mm, p.b.z_mm),
                                     LeftOutShape::Other,
                                     {},
                                     0.0,
                                     {}});
    }
}

// The faces that share an edge with each left-out face.
void addNeighbours(const TopoDS_Shape &body, const TopTools_IndexedMapOfShape &faces, SectionTrace &trace)
{
    TopTools_IndexedDataMapOfShapeListOfShape facesOfEdge;
    TopExp::MapShapesAndAncestors(body, TopAbs_EDGE, TopAbs_FACE, facesOfEdge);
    for (LeftOutFace &f : trace.leftOut) {
        for (TopExp_Explorer edge(faces(f.face), TopAbs_EDGE); edge.More(); edge.Next()) {
            const int k = facesOfEdge.FindIndex(edge.Current());
            if (k == 0)
                continue;
            for (const TopoDS_Shape &other : facesOfEdge(k))
                if (const int j = faces.FindIndex(other); j != 0 && j != f.face)
                    f.neighbours.push_back(j);
        }
        std::sort(f.neighbours.begin(), f.neighbours.end());
        f.neighbours.erase(std::unique(f.neighbours.begin(), f.neighbours.end()), f.neighbours.end());
    }
}

} // namespace

std::vector<AxisCandidate> findAxes(const TopoDS_Shape &body)
{
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(body, TopAbs_FACE, faces);
    std::vector<AxisCandidate> axes;
    for (int i = 1; i <= faces.Extent(); ++i) {
        const TopoDS_Face &face = TopoDS::Face(faces(i));
        const auto axis = surfaceAxis(faceGeometry(face).surface);
        if (!axis)
            continue;
        const double area = faceArea(face);
        auto known = std::find_if(axes.begin(), axes.end(), [&](const auto &c) { return coaxial(c.axis, *axis); });
        if (known == axes.end()) {
            axes.push_back({canonical(*axis), 0.0, 0});
            known = axes.end() - 1;
        }
        known->revolvedArea_mm2 += area;
        ++known->faceCount;
    }
    std::stable_sort(axes.begin(), axes.end(),
                     [](const auto &a, const auto &b) { return a.revolvedArea_mm2 > b.revolvedArea_mm2; });
    return axes;
}

SectionTrace traceSection(const TopoDS_Shape &body, const gp_Ax1 &axis, const Progress &progress)
{
    SectionTrace out;
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(body, TopAbs_FACE, faces);
    FaceTracer tracer(axis, out);
    for (int i = 1; i <= faces.Extent(); ++i) {
        if (!progress.report(static_cast<double>(i - 1) / faces.Extent())) {
            out.cancelled = true;
            return out;
        }
        tracer.trace(i, TopoDS::Face(faces(i)));
    }
    mergeAndFilter(out);
    addNeighbours(body, faces, out);
    return out;
}

} // namespace tolturn::cad
