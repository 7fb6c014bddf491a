// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/fe/tet_mesh.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <QCoreApplication>
#include <QList>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <unordered_map>

namespace tolturn {

namespace {

struct TetMeshText {
    Q_DECLARE_TR_FUNCTIONS(TetMeshText)
};

// Mid-side node of the edge between corners a and b of a C3D10 element (header comment).
int midSideSlot(int a, int b)
{
    static constexpr std::array<std::array<int, 4>, 4> slot{
        {{-1, 4, 6, 7}, {4, -1, 5, 8}, {6, 5, -1, 9}, {7, 8, 9, -1}}};
    return slot[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)];
}

enum class Block { Other, Nodes, Tetrahedra };

Block blockOf(const QByteArray &keywordLine)
{
    const QByteArray upper = keywordLine.toUpper();
    if (upper.startsWith("*NODE") && !upper.startsWith("*NODE PRINT") && !upper.startsWith("*NODE FILE"))
        return Block::Nodes;
    if (upper.startsWith("*ELEMENT") && upper.contains("C3D10"))
        return Block::Tetrahedra;
    return Block::Other;
}

// The comma-separated numbers of a data line; false when one is not a number.
bool numbers(const QByteArray &line, QList<double> &out)
{
    for (const QByteArray &field : line.split(',')) {
        const QByteArray t = field.trimmed();
        if (t.isEmpty())
            continue;
        bool ok = false;
        out.append(t.toDouble(&ok));
        if (!ok)
            return false;
    }
    return true;
}

} // namespace

double TetMesh::volume_mm3(std::size_t element) const
{
    const std::array<int, 10> &e = elements[element];
    const Point3 &a = nodes[static_cast<std::size_t>(e[0])];
    return std::abs((nodes[static_cast<std::size_t>(e[1])] - a)
                        .cross(nodes[static_cast<std::size_t>(e[2])] - a)
                        .dot(nodes[static_cast<std::size_t>(e[3])] - a)) /
           6.0;
}

Point3 TetMesh::centroid(std::size_t element) const
{
    Point3 c = Point3::Zero();
    for (int i = 0; i < 4; ++i)
        c += nodes[static_cast<std::size_t>(elements[element][static_cast<std::size_t>(i)])];
    return c / 4.0;
}

double BoundaryFace::area_mm2(const TetMesh &mesh) const
{
    const Point3 &a = mesh.nodes[static_cast<std::size_t>(nodes[0])];
    return 0.5 * (mesh.nodes[static_cast<std::size_t>(nodes[1])] - a)
                     .cross(mesh.nodes[static_cast<std::size_t>(nodes[2])] - a)
                     .norm();
}

Point3 BoundaryFace::centroid(const TetMesh &mesh) const
{
    return (mesh.nodes[static_cast<std::size_t>(nodes[0])] + mesh.nodes[static_cast<std::size_t>(nodes[1])] +
            mesh.nodes[static_cast<std::size_t>(nodes[2])]) /
           3.0;
}

TetMeshParse parseAbaqusTetMesh(const QByteArray &text)
{
    std::map<long long, Point3> nodes;
    std::vector<std::array<long long, 10>> tets;
    Block block = Block::Other;
    QList<double> pending; // an element's numbers may run over several lines
    int lineNumber = 0;
    for (const QByteArray &raw : text.split('\n')) {
        ++lineNumber;
        const QByteArray line = raw.trimmed();
        if (line.isEmpty() || line.startsWith("**"))
            continue;
        if (line.startsWith('*')) {
            block = blockOf(line);
            pending.clear();
            continue;
        }
        if (block == Block::Other)
            continue;
        if (!numbers(line, pending))
            return {std::nullopt, TetMeshText::tr("line %1 of the mesh is not a list of numbers: \"%2\"")
                                      .arg(lineNumber)
                                      .arg(QString::fromUtf8(line.left(80)))};
        if (block == Block::Nodes && pending.size() >= 4) {
            nodes[static_cast<long long>(pending[0])] = Point3(pending[1], pending[2], pending[3]);
            pending.clear();
        } else if (block == Block::Tetrahedra && pending.size() >= 11) {
            std::array<long long, 10> e{};
            for (std::size_t i = 0; i < 10; ++i)
                e[i] = static_cast<long long>(pending[static_cast<qsizetype>(i) + 1]);
            tets.push_back(e);
            pending.clear();
        }
    }
    if (tets.empty())
        return {std::nullopt, TetMeshText::tr("the mesh has no quadratic tetrahedra (C3D10)")};

    // Renumber the nodes the tetrahedra use, in the order of their numbers.
    std::set<long long> used;
    for (const auto &t : tets) {
        for (const long long n : t)
            used.insert(n);
    }
    std::unordered_map<long long, int> index;
    TetMesh mesh;
    for (const long long number : used) {
        const auto it = nodes.find(number);
        if (it == nodes.end())
            return {std::nullopt,
                    TetMeshText::tr("an element of the mesh uses node %1, which it does not define").arg(number)};
        index.emplace(number, static_cast<int>(mesh.nodes.size()));
        mesh.nodes.push_back(it->second);
    }
    mesh.elements.reserve(tets.size());
    for (const auto &t : tets) {
        std::array<int, 10> e{};
        for (std::size_t i = 0; i < 10; ++i) {
            e[i] = index.at(t[i]);
        }
        mesh.elements.push_back(e);
    }
    return {std::move(mesh), QString()};
}

std::vector<BoundaryFace> boundaryFaces(const TetMesh &mesh)
{
    static constexpr std::array<std::array<int, 3>, 4> corners{{{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}};

    struct Seen {
        BoundaryFace face;
        int count = 0;
    };

    std::map<std::array<int, 3>, Seen> faces;
    for (const std::array<int, 10> &e : mesh.elements) {
        for (const std::array<int, 3> &c : corners) {
            BoundaryFace f;
            for (std::size_t i = 0; i < 3; ++i) {
                f.nodes[i] = e[static_cast<std::size_t>(c[i])];
                f.nodes[i + 3] = e[static_cast<std::size_t>(midSideSlot(c[i], c[(i + 1) % 3]))];
            }
            std::array<int, 3> key{f.nodes[0], f.nodes[1], f.nodes[2]};
            std::sort(key.begin(), key.end());
            Seen &seen = faces[key];
            seen.face = f;
            ++seen.count;
        }
    }
    std::vector<BoundaryFace> out;
    for (const auto &[key, seen] : faces) {
        if (seen.count == 1)
            out.push_back(seen.face);
    }
    return out;
}

namespace {

// Barycentric coordinates of p in the element's straight (corner) tetrahedron.
Eigen::Vector4d barycentric(const TetMesh &mesh, const std::array<int, 10> &e, const Point3 &p)
{
    const Point3 &a = mesh.nodes[static_cast<std::size_t>(e[0])];
    Eigen::Matrix3d m;
    for (int i = 0; i < 3; ++i)
        m.col(i) = mesh.nodes[static_cast<std::size_t>(e[static_cast<std::size_t>(i) + 1])] - a;
    const Point3 l = m.partialPivLu().solve(p - a);
    return {1.0 - l.sum(), l.x(), l.y(), l.z()};
}

// C3D10 shape functions: L_i (2 L_i - 1) at the corners, 4 L_i L_j at the mid-side nodes.
Point3 interpolate(const std::array<int, 10> &e, const Eigen::Vector4d &l, const std::vector<Point3> &u)
{
    static constexpr std::array<std::array<int, 2>, 6> edges{{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
    Point3 out = Point3::Zero();
    for (int i = 0; i < 4; ++i)
        out += l[i] * (2.0 * l[i] - 1.0) * u[static_cast<std::size_t>(e[static_cast<std::size_t>(i)])];
    for (std::size_t k = 0; k < 6; ++k)
        out += 4.0 * l[edges[k][0]] * l[edges[k][1]] * u[static_cast<std::size_t>(e[k + 4])];
    return out;
}

} // namespace

std::optional<Point3> sectionMeanDisplacement(const TetMesh &mesh, const std::vector<Point3> &displacement, double z_mm,
                                              double rInner_mm, double rOuter_mm, int rings, int sectors)
{
    std::vector<std::size_t> cut; // elements the plane passes through
    for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
        double lo = std::numeric_limits<double>::infinity();
        double hi = -lo;
        for (std::size_t i = 0; i < 4; ++i) {
            const double z = mesh.nodes[static_cast<std::size_t>(mesh.elements[e][i])].z();
            lo = std::min(lo, z);
            hi = std::max(hi, z);
        }
        if (lo <= z_mm && z_mm <= hi)
            cut.push_back(e);
    }
    constexpr double kInside = -1e-9;
    Point3 sum = Point3::Zero();
    double area = 0.0;
    const double dr = (rOuter_mm - rInner_mm) / rings;
    const double dt = 2.0 * std::numbers::pi / sectors;
    for (int i = 0; i < rings; ++i) {
        const double r = rInner_mm + (i + 0.5) * dr;
        for (int j = 0; j < sectors; ++j) {
            const Point3 p(r * std::cos(j * dt), r * std::sin(j * dt), z_mm);
            for (const std::size_t e : cut) {
                const Eigen::Vector4d l = barycentric(mesh, mesh.elements[e], p);
                if (l.minCoeff() >= kInside) {
                    sum += r * interpolate(mesh.elements[e], l, displacement);
                    area += r;
                    break;
                }
            }
        }
    }
    if (area <= 0.0)
        return std::nullopt;
    return Point3(sum / area);
}

Point3 centroidDisplacement(const std::array<int, 10> &element, const std::vector<Point3> &displacement)
{
    Point3 u = Point3::Zero();
    for (std::size_t i = 0; i < 10; ++i)
        u += (i < 4 ? -0.125 : 0.25) * displacement[static_cast<std::size_t>(element[i])];
    return u;
}

} // namespace tolturn
