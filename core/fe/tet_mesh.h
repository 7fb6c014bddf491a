// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A mesh of quadratic tetrahedra as gmsh writes it for Abaqus and CalculiX (docs/solid-fe.md):
// nodes in mm, ten-node elements (C3D10) with the corner nodes first, then the mid-side nodes
// of the edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4 (CalculiX User's Manual 2.20 §6.2.5).

#include <Eigen/Core>
#include <QByteArray>
#include <QString>

#include <array>
#include <optional>
#include <vector>

namespace tolturn {

using Point3 = Eigen::Vector3d;

struct TetMesh {
    std::vector<Point3> nodes;                 // index = node number - 1, numbered from 1 in files
    std::vector<std::array<int, 10>> elements; // node indices (0-based)

    [[nodiscard]] double volume_mm3(std::size_t element) const;
    [[nodiscard]] Point3 centroid(std::size_t element) const;
};

// A face of a tetrahedron on the mesh boundary: its six nodes, corners first (0-based indices),
// then the mid-side nodes of its edges 0-1, 1-2, 2-0.
struct BoundaryFace {
    std::array<int, 6> nodes{};

    [[nodiscard]] double area_mm2(const TetMesh &mesh) const;
    [[nodiscard]] Point3 centroid(const TetMesh &mesh) const;
};

struct TetMeshParse {
    std::optional<TetMesh> mesh;
    QString error; // what is wrong with the file, with its line; empty when mesh is set
};

// Reads the nodes and the C3D10 elements of an Abaqus input file written by gmsh (its other
// elements, the lines and triangles of the surface, are skipped); nodes no element uses are
// dropped and the rest renumbered.
[[nodiscard]] TetMeshParse parseAbaqusTetMesh(const QByteArray &text);

// The faces that belong to one element only: the surface of the solid.
[[nodiscard]] std::vector<BoundaryFace> boundaryFaces(const TetMesh &mesh);

// The mean displacement of the plane section z = const between the radii rInner and rOuter: the
// Timoshenko beam's w, the area mean of the section's displacement. Sampled on a polar grid of
// `rings` x `sectors` points at the centres of equal-step cells, each weighted by its
// area, the displacement at each from the quadratic shape functions of the element that holds it
// (points in no element, at a curved boundary, are left out). nullopt when no point is found.
[[nodiscard]] std::optional<Point3> sectionMeanDisplacement(const TetMesh &mesh,
                                                            const std::vector<Point3> &displacement, double z_mm,
                                                            double rInner_mm, double rOuter_mm, int rings = 12,
                                                            int sectors = 48);

// The displacement at an element's centroid from its nodes' (C3D10 shape functions at
// L1 = L2 = L3 = L4 = 1/4: -1/8 at each corner, 1/4 at each mid-side node).
[[nodiscard]] Point3 centroidDisplacement(const std::array<int, 10> &element, const std::vector<Point3> &displacement);

} // namespace tolturn
