// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the constant-force loop and the feed schedule (issue 18), results recorded in
// docs/benchmarks.md:
//  1. the loop on a 500 mm pass at 20 ms periods (the adaptive run alone, and both runs);
//  2. the feed schedule of the finishing pass of a part with 30 turned features.
// The part: the long-shaft example's set-up (between centres, C45E, Haas ST-20, its insert and
// ranges) with an outer contour of 15 diameters Ø56 → Ø28, 34 mm each, and the 14 shoulders
// between them: 514 mm, 31 features with the end face; a diameter tolerance (h6) on every other
// diameter and a cylindricity of 3 µm on the others.
// Run: build/<preset>/benchmarks/bench_adaptive
#include "benchmarks/bench_timing.h"

#include "core/adaptive/project_control.h"
#include "core/io/project_file.h"
#include "core/planning/feed_schedule.h"

#include <QCoreApplication>

#include <cstdio>

using namespace tolturn;
using tolturn::bench::medianMilliseconds;

namespace {

Segment segment(const QString &id, SegmentKind kind, ProfilePoint from, ProfilePoint to)
{
    Segment s;
    s.id = id;
    s.kind = kind;
    s.from = from;
    s.to = to;
    return s;
}

Project thirtyFeatureShaft(Project p)
{
    constexpr int kDiameters = 15;
    constexpr double kStep_mm = 34.0;
    p.part.stockDiameter_mm = 60.0;
    p.part.outer.segments.clear();
    p.tolerances.clear();
    p.datums.clear();
    int n = 0;
    const auto id = [&] { return QStringLiteral("O%1").arg(++n); };
    const auto radius = [](int i) { return 28.0 - i; }; // Ø56 at the left end down to Ø28
    p.part.outer.segments.push_back(segment(id(), SegmentKind::Face, {0, 0}, {0, radius(0)}));
    for (int i = 0; i < kDiameters; ++i) {
        const double z0 = i * kStep_mm;
        const double z1 = z0 + kStep_mm;
        const QString cylinder = id();
        p.part.outer.segments.push_back(segment(cylinder, SegmentKind::Cylinder, {z0, radius(i)}, {z1, radius(i)}));
        Tolerance t;
        t.id = QStringLiteral("T%1").arg(i + 1);
        t.featureId = cylinder;
        if (i % 2 == 0) {
            t.type = ToleranceType::Diameter;
            t.iso286Class = QStringLiteral("h6");
        } else {
            t.type = ToleranceType::Cylindricity;
            t.zone_um = 3.0;
        }
        p.tolerances.push_back(t);
        const double next = i + 1 < kDiameters ? radius(i + 1) : 0.0;
        p.part.outer.segments.push_back(segment(id(), SegmentKind::Face, {z1, radius(i)}, {z1, next}));
    }
    return p;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const ProjectParseResult read =
        readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/long-shaft-centres.tolturn"));
    if (!read.project) {
        std::printf("cannot read the long-shaft example\n");
        return 1;
    }
    const Project project = thirtyFeatureShaft(*read.project);
    std::printf("part: %.0f mm, %lld outer features, %lld tolerances\n", project.part.length_mm(),
                static_cast<long long>(project.part.outer.segments.size()),
                static_cast<long long>(project.tolerances.size()));

    // 1. The first roughing pass: 0.8125 mm over the whole length (2 mm clear of the left centre).
    ProjectControlOptions options;
    options.passIndex = 0;
    const ProjectControlResult once = simulateProjectControl(project, DataLibrary::builtIn(), options);
    if (!once.ok()) {
        std::printf("the loop did not run\n");
        return 1;
    }
    const PassControlResult &pass = once.passes.front();
    std::printf("pass 1: %.0f mm, %zu periods of 20 ms adaptive, %zu at the programmed feed\n",
                pass.pass.z_mm.front() - pass.pass.z_mm.back(), pass.adaptive.samples.size(),
                pass.constantFeed.samples.size());
    PassProcess process;
    Diagnostics ignored;
    process.forces = *projectForceModel(project, DataLibrary::builtIn(), ignored);
    process.cuttingSpeed_m_min = pass.pass.conditions.cuttingSpeed_m_min;
    process.noseRadius_mm = 0.8;
    const double loopMs =
        medianMilliseconds(21, [&] { (void)simulatePassControl(pass.pass, process, ForceControlSettings{}); });
    std::printf("loop, both runs, the force model alone: median %.2f ms\n", loopMs);
    const double projectMs =
        medianMilliseconds(11, [&] { (void)simulateProjectControl(project, DataLibrary::builtIn(), options); });
    std::printf("simulate-control --pass 1 (inputs, depth profile, influence along z, both runs): median %.2f ms\n",
                projectMs);

    // 2. The feed schedule of the finishing pass: as the example asks (Ra 1.6 µm bounds every
    // feature), and without the roughness requirement, so that the tolerances bind.
    for (const bool roughness : {true, false}) {
        Project p = project;
        if (!roughness)
            p.planning.maxRa_um.reset();
        const PlanningProblem::BuildResult built = PlanningProblem::build(p, DataLibrary::builtIn());
        if (!built.problem) {
            std::printf("no planning problem\n");
            return 1;
        }
        const CuttingPass finishing = p.passes.back();
        FeedSchedule schedule;
        const double scheduleMs =
            medianMilliseconds(11, [&] { schedule = scheduleFinishingFeeds(*built.problem, finishing); });
        int bound = 0;
        for (const ScheduledFeed &f : schedule.features)
            bound += f.limitedBy.startsWith(QLatin1String("tolerance")) ? 1 : 0;
        std::printf("feed schedule%s: %zu features (%d bound by a tolerance), median %.1f ms\n",
                    roughness ? ", Ra 1.6" : ", no Ra", schedule.features.size(), bound, scheduleMs);
    }
    return 0;
}
