// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the deflection model (issue 3), results recorded in docs/benchmarks.md:
//  1. deflection curves of a 30-segment part at 500 tool positions, all contributions;
//  2. a sweep of 65 536 cutting conditions on one part, by the linearity in force.
// Run: build/<preset>/benchmarks/bench_deflection   (one core: taskset -c 0 ...)
#include "core/cutting/cutting_forces.h"
#include "core/deviation/deviation_model.h"
#include "core/project/project_validation.h"

#include <QCoreApplication>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

using namespace tolturn;
using Clock = std::chrono::steady_clock;

namespace {

Segment seg(const QString &id, SegmentKind kind, ProfilePoint a, ProfilePoint b)
{
    Segment s;
    s.id = id;
    s.kind = kind;
    s.from = a;
    s.to = b;
    return s;
}

// A stepped hollow shaft with cones, 400 mm long: 26 outer segments and 4 inner ones, 30 in all.
Project thirtySegmentPart()
{
    Project p;
    p.part.name = QStringLiteral("benchmark part");
    p.part.stockDiameter_mm = 80.0;
    std::vector<Segment> &o = p.part.outer.segments;
    double z = 0.0;
    double r = 36.0;
    o.push_back(seg(QStringLiteral("O0"), SegmentKind::Face, {0, 8}, {0, r}));
    for (int i = 0; i < 8; ++i) {
        o.push_back(seg(QStringLiteral("C%1").arg(i), SegmentKind::Cylinder, {z, r}, {z + 40, r}));
        z += 40;
        const double next = r - 2.5;
        if (i % 2 == 0) {
            o.push_back(seg(QStringLiteral("F%1").arg(i), SegmentKind::Face, {z, r}, {z, next}));
        } else {
            o.push_back(seg(QStringLiteral("K%1").arg(i), SegmentKind::Cone, {z, r}, {z + 6, next}));
            z += 6;
        }
        o.push_back(seg(QStringLiteral("X%1").arg(i), SegmentKind::Cylinder, {z, next}, {z + 4, next}));
        z += 4;
        r = next;
    }
    o.push_back(seg(QStringLiteral("E"), SegmentKind::Face, {z, r}, {z, 5}));
    p.part.inner.segments = {seg(QStringLiteral("I1"), SegmentKind::Cylinder, {0, 8}, {150, 8}),
                             seg(QStringLiteral("I2"), SegmentKind::Cone, {150, 8}, {160, 6}),
                             seg(QStringLiteral("I3"), SegmentKind::Cylinder, {160, 6}, {300, 6}),
                             seg(QStringLiteral("I4"), SegmentKind::Cone, {300, 6}, {z, 5})};
    p.materialId = QStringLiteral("42CrMo4-QT");
    p.machineId = QStringLiteral("haas-st-20");
    p.tool.insertCode = QStringLiteral("CNMG 120408");
    p.tool.holderCode = QStringLiteral("PCLNR 2525M12");
    p.clamping = {ClampingMethod::ChuckTailstock, 40.0};
    p.passes = {{PassKind::Finishing, 220.0, 0.12, 0.5}};
    p.characterisation.source = QStringLiteral("benchmark");
    p.characterisation.pivotDistance_mm = 180.0;
    p.characterisation.spindleRadial = SpindleSprings{1.6e5, 1.3e9, 1.5e10};
    p.characterisation.spindleTangential = SpindleSprings{1.0e5, 1.5e9, 1.3e10};
    p.characterisation.tailstock = SupportStiffness{4e4, 4e4};
    p.characterisation.thermal = ThermalDrift{3.0, 0.5, 20.0, 40.0};
    p.environment.timeSinceStart_min = 60.0;
    return p;
}

template <typename F>
double medianMicroseconds(int repetitions, F &&run)
{
    std::vector<double> times;
    for (int i = 0; i < repetitions; ++i) {
        const auto t0 = Clock::now();
        run();
        times.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const Project project = thirtySegmentPart();
    for (const Diagnostic &d : validateProject(project))
        std::printf("invalid benchmark part: %s\n", qPrintable(d.toString()));
    std::printf("part: %zu outer + %zu inner = %zu segments\n", project.part.outer.segments.size(),
                project.part.inner.segments.size(),
                project.part.outer.segments.size() + project.part.inner.segments.size());

    // 1. Deflection curves: stations per feature so that the part has about 500 tool positions.
    int features = 0;
    for (const Contour *c : {&project.part.outer, &project.part.inner})
        for (const Segment &s : c->segments)
            features += s.isAxial() ? 1 : 0;
    DeviationOptions options;
    options.stationsPerFeature = (500 + features - 1) / features + 1;
    DeviationResult result;
    const double curves =
        medianMicroseconds(200, [&] { result = computeDeviation(project, DataLibrary::builtIn(), options); });
    std::size_t stations = 0;
    for (const FeatureDeviation &f : result.features)
        stations += f.stations.size();
    std::printf("deflection curves: %zu tool positions on %zu features, all contributions: median %.0f us\n", stations,
                result.features.size(), curves);

    // 2. Sweep: 256 feeds x 256 depths of cut, Kienzle forces, form error of every feature.
    const InputsResult inputs = resolveTurningInputs(project, DataLibrary::builtIn(), options);
    const InfluenceTable table = buildInfluenceTable(project.part, *inputs.inputs, options.stationsPerFeature, 0.5);
    KienzleConstants k;
    k.cutting = {1725.0, 0.24}; // 42CrMo4-QT
    k.feedToCuttingRatio = 0.5;
    k.passiveToCuttingRatio = 0.25;
    std::vector<ConditionForces> conditions;
    for (int i = 0; i < 256; ++i) {
        for (int j = 0; j < 256; ++j) {
            const CuttingForces f = kienzleForces(k, 0.05 + 0.45 * i / 255.0, 0.1 + 2.9 * j / 255.0, 1.658).forces;
            conditions.push_back({f.radial_N, f.axial_N});
        }
    }
    std::vector<double> formErrors;
    const double sweep = medianMicroseconds(20, [&] { formErrors = sweepFormErrors(table, conditions); });
    std::printf("sweep: %zu conditions x %zu features: median %.1f ms (influence table built once: %.0f us)\n",
                conditions.size(), table.features.size(), sweep / 1000.0, medianMicroseconds(50, [&] {
                    (void)buildInfluenceTable(project.part, *inputs.inputs, options.stationsPerFeature, 0.5);
                }));
    return formErrors.empty() ? 1 : 0;
}
