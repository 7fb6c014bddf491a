// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A linear static CalculiX job on a tetrahedral mesh (docs/solid-fe.md): the input deck, one
// step per load case, and the displacements read back from the .dat file. Keywords as in the
// CalculiX CrunchiX User's Manual 2.20 (§7: *NODE, *ELEMENT, *NSET, *MATERIAL, *ELASTIC,
// *SOLID SECTION, *BOUNDARY, *STEP, *STATIC, *CLOAD with OP=NEW, *NODE PRINT, *END STEP).

#include "core/fe/tet_mesh.h"

#include <QByteArray>
#include <QString>

#include <optional>
#include <vector>

namespace tolturn {

// Which displacement components of a node are held at zero.
struct NodeSupport {
    int node = 0; // 0-based
    bool x = false;
    bool y = false;
    bool z = false;
};

struct NodalForce {
    int node = 0; // 0-based
    Point3 force_N = Point3::Zero();
};

using LoadCase = std::vector<NodalForce>;

struct CalculixJob {
    const TetMesh *mesh = nullptr;
    double youngsModulus_MPa = 0.0;
    double poissonRatio = 0.0;
    std::vector<NodeSupport> supports;
    // Nodes whose mean axial displacement is held at zero (one *EQUATION): the axial support of
    // a centre, which leaves the section free to rotate.
    std::vector<int> axialMeanHeld;
    std::vector<LoadCase> loadCases;
};

// The input deck (units N, mm, MPa).
[[nodiscard]] QByteArray calculixDeck(const CalculixJob &job);

struct CalculixDisplacements {
    std::vector<std::vector<Point3>> perCase; // [load case][node], mm
    QString error;                            // empty when every case was read
};

// Reads the displacement blocks *NODE PRINT wrote to the .dat file, one per step, in order.
[[nodiscard]] CalculixDisplacements parseCalculixDisplacements(const QByteArray &dat, std::size_t nodeCount,
                                                               std::size_t caseCount);

// The first line of CalculiX's output that reports an error, or its last non-empty line.
[[nodiscard]] QString calculixErrorLine(const QByteArray &output);

} // namespace tolturn
