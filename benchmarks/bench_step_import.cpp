// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of STEP import (issue 7 asks for under 0.5 s for a turned part of 100 faces), results
// recorded in docs/benchmarks.md. The parts are profiles with many grooves, chamfers and radii,
// written as revolved solids with exportProfileToStep, then imported (read, transfer, trace,
// contours, validation).
// Run: build/<preset>/benchmarks/bench_step_import
#include "benchmarks/bench_timing.h"

#include "core/cad/step_export.h"
#include "core/cad/step_import.h"

#include <QCoreApplication>
#include <QTemporaryDir>

#include <cstdio>

using namespace tolturn;
using tolturn::bench::medianMilliseconds;

namespace {

void add(PartProfile &p, SegmentKind kind, ProfilePoint to, double radius = 0.0,
         ArcDirection direction = ArcDirection::CounterClockwise)
{
    Contour &c = p.outer;
    Segment s;
    s.id = QStringLiteral("O%1").arg(c.segments.size() + 1);
    s.kind = kind;
    s.from = c.segments.empty() ? ProfilePoint{0.0, 0.0} : c.back();
    s.to = to;
    s.arcRadius_mm = radius;
    s.arcDirection = direction;
    c.segments.push_back(s);
}

// A shaft Ø40 with `grooves` grooves 3 mm deep and 2 mm wide, each with a radius R0.5 at its
// bottom left and a 0.5 mm chamfer at its right edge: six faces per groove.
PartProfile groovedShaft(int grooves)
{
    using K = SegmentKind;
    PartProfile p;
    p.name = QStringLiteral("grooved shaft");
    add(p, K::Face, {0, 19.5});
    add(p, K::Chamfer, {0.5, 20});
    double z = 0.5;
    for (int i = 0; i < grooves; ++i) {
        add(p, K::Cylinder, {z + 3.0, 20});
        add(p, K::Face, {z + 3.0, 17.5});
        add(p, K::Radius, {z + 3.5, 17}, 0.5, ArcDirection::CounterClockwise);
        add(p, K::Cylinder, {z + 5.0, 17});
        add(p, K::Face, {z + 5.0, 19.5});
        add(p, K::Chamfer, {z + 5.5, 20});
        z += 5.5;
    }
    add(p, K::Cylinder, {z + 3.0, 20});
    add(p, K::Face, {z + 3.0, 0});
    p.stockDiameter_mm = 40.0;
    return p;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QTemporaryDir dir;
    std::printf("%8s %8s %10s %12s\n", "grooves", "faces", "segments", "median [ms]");
    for (const int grooves : {17, 34, 68}) {
        const QString path = dir.filePath(QStringLiteral("grooved-%1.step").arg(grooves));
        const StepExportResult written = exportProfileToStep(groovedShaft(grooves), path);
        if (!written.ok) {
            std::printf("cannot write %s\n", qPrintable(written.error));
            return 1;
        }
        CadImportResult r;
        const double ms = medianMilliseconds(7, [&] { r = importCadFile(path); });
        if (!r.profile || hasErrors(r.diagnostics)) {
            std::printf("import of %d grooves failed\n", grooves);
            return 1;
        }
        std::printf("%8d %8d %10zu %12.1f\n", grooves, r.solids.front().faceCount, r.profile->outer.segments.size(),
                    ms);
    }
    return 0;
}
