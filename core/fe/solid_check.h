// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Check with Solid FE (docs/solid-fe.md): the part as a solid from OpenCascade, meshed with gmsh
// in quadratic tetrahedra, held as its clamping holds it, loaded by the cutting force as a
// traction on a small patch of the surface at each of a few tool positions, solved with CalculiX;
// the deflection of the section under the load against the beam's. The machine's supports are
// rigid in both, so the check is of the part's own elasticity, where the beam's assumptions
// (plane sections, a built-in root, a load at a point) are the question.

#include "core/common/diagnostic.h"
#include "core/cutting/cutting_forces.h"
#include "core/data/data_library.h"
#include "core/project/project.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <vector>

namespace tolturn {

struct SolidCheckOptions {
    int stations = 5;                  // tool positions, evenly along the supported length
    std::optional<double> meshSize_mm; // largest element edge; default: defaultMeshSize()
    int operation = 0;                 // which set-up (0: the first)
    std::optional<CuttingForces> load; // instead of the forces of the project's pass
    bool beamCorrections = true;       // the beam compared with its corrections (docs/solid-fe.md)
};

// Why a check gave no result; its diagnostic names the cause.
enum class SolidCheckFailure { None, Project, MissingEngine, Mesh, Solver, Cancelled };

struct SolidCheckStation {
    double z_mm = 0.0;             // tool position, from the held end
    double contactRadius_mm = 0.0; // the outer radius there
    // Deflection of the section under the load: radial away from the tool, tangential along the
    // cutting force [mm].
    double beamRadial_mm = 0.0;
    double solidRadial_mm = 0.0;
    double beamTangential_mm = 0.0;
    double solidTangential_mm = 0.0;
    double timoshenkoRadial_mm = 0.0; // the beam without its corrections, for comparison

    // (beam - solid) / solid, in per cent: positive where the beam is the softer.
    [[nodiscard]] double radialDifference_pct() const;
};

struct SolidCheckResult {
    SolidCheckFailure failure = SolidCheckFailure::None;
    Diagnostics diagnostics;
    std::vector<SolidCheckStation> stations;
    CuttingForces forces;        // at every station, of the pass the beam uses
    QString clamping;            // keyword of the operation's clamping
    bool beamCorrections = true; // beamRadial_mm with the beam's corrections
    double youngsModulus_MPa = 0.0;
    double poissonRatio = 0.0;
    double meshSize_mm = 0.0;
    double loadPatch_mm = 0.0; // side of the square patch the force is spread over
    int nodes = 0;
    int elements = 0;
    int degreesOfFreedom = 0; // free displacement components
    double meshSeconds = 0.0;
    double solveSeconds = 0.0;
    double beamSeconds = 0.0;
    QStringList notes; // what the comparison rests on, for people

    [[nodiscard]] bool ok() const { return failure == SolidCheckFailure::None; }

    // The largest |beam - solid| radial deflection over the stations as a share of the largest
    // solid deflection, in per cent: what a form error sees (near a support both are small, and
    // their ratio says little). 0 without stations.
    [[nodiscard]] double largestRadialDifference_pct() const;
};

// Called with the per cent done and what is being done; returning false cancels the run.
using SolidCheckProgress = std::function<bool(int percent, const QString &stage)>;

// The element size the check meshes with when none is given: a fifth of the smallest outer
// diameter in the supported length, at least 1 mm (docs/solid-fe.md, convergence).
[[nodiscard]] double defaultMeshSize(const PartProfile &part);

// Runs the check. Never changes the project; files go to a temporary folder that is removed.
[[nodiscard]] SolidCheckResult checkWithSolidFe(const Project &project, const DataLibrary &data,
                                                const SolidCheckOptions &options,
                                                const SolidCheckProgress &progress = {});

} // namespace tolturn
