// SPDX-License-Identifier: GPL-3.0-or-later
// The beam against the solid model (issue 17): the time of each on the same part, load and tool
// positions, in one run, and their ratio; recorded in docs/benchmarks.md. The solid is the
// whole check (STEP, gmsh, CalculiX, reading back) at its default mesh; the beam is the influence
// of the load at the same stations (elements, both sweeps), the median of 200 runs.
// Run: build/<preset>/benchmarks/bench_solid_fe [PROJECT]
#include "benchmarks/bench_timing.h"

#include "core/data/data_library.h"
#include "core/deviation/deviation_model.h"
#include "core/deviation/turning_inputs.h"
#include "core/fe/solid_check.h"
#include "core/io/project_file.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <cstdio>

using namespace tolturn;
using tolturn::bench::medianMilliseconds;

int main(int argc, char *argv[])
{
    const QCoreApplication app(argc, argv);
    const QString file = argc > 1
                             ? QString::fromLocal8Bit(argv[1])
                             : QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/stepped-shaft-chuck.tolturn");
    const ProjectParseResult read = readProjectFile(file);
    if (!read.project) {
        std::fprintf(stderr, "%s: not a valid project\n", qPrintable(file));
        return 1;
    }
    const DataLibrary &data = DataLibrary::builtIn();
    SolidCheckOptions options;
    options.stations = 5;
    QElapsedTimer clock;
    clock.start();
    const SolidCheckResult solid = checkWithSolidFe(*read.project, data, options);
    const double solidMs = static_cast<double>(clock.nsecsElapsed()) * 1e-6;
    if (!solid.ok()) {
        std::fprintf(stderr, "solid check failed: %s\n", qPrintable(solid.diagnostics.front().toString()));
        return 1;
    }

    DeviationOptions workpiece;
    workpiece.workpieceOnly = true;
    const InputsResult resolved = resolveTurningInputs(*read.project, data, workpiece);
    std::vector<double> z;
    std::vector<double> radius;
    for (const SolidCheckStation &s : solid.stations) {
        z.push_back(s.z_mm);
        radius.push_back(s.contactRadius_mm);
    }
    const double beamMs = medianMilliseconds(200, [&] {
        const std::vector<StationInfluence> beam = influenceAt(read.project->part, *resolved.inputs, z, radius);
        if (beam.size() != z.size())
            std::abort();
    });
    std::printf("%s: %zu stations\n", qPrintable(file), solid.stations.size());
    std::printf("  solid: %.0f ms (gmsh %.2f s, CalculiX %.2f s), %d nodes, %d degrees of freedom, mesh %.2f mm\n",
                solidMs, solid.meshSeconds, solid.solveSeconds, solid.nodes, solid.degreesOfFreedom, solid.meshSize_mm);
    std::printf("  beam:  %.4f ms\n", beamMs);
    std::printf("  ratio solid / beam: %.3g\n", solidMs / beamMs);
    return 0;
}
