// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of planning (issue 5), results recorded in docs/benchmarks.md:
//  1. optimisation of one part with 10 toleranced features;
//  2. a 256 x 256 cutting window on two cores (feed-speed; feed-depth for comparison).
// Run: build/<preset>/benchmarks/bench_planning [path/to/stepped-shaft-chuck.tolturn]
#include "benchmarks/bench_timing.h"

#include "core/io/project_file.h"
#include "core/planning/cutting_window.h"

#include <QCoreApplication>

#include <cstdio>
#include <vector>

using namespace tolturn;
using tolturn::bench::medianMilliseconds;

namespace {

Tolerance geometric(const char *id, ToleranceType type, const char *feature, double zone,
                    const QStringList &datums = {})
{
    Tolerance t;
    t.id = QString::fromLatin1(id);
    t.type = type;
    t.featureId = QString::fromLatin1(feature);
    t.zone_um = zone;
    t.datums = datums;
    return t;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QString path = argc > 1
                             ? QString::fromLocal8Bit(argv[1])
                             : QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/stepped-shaft-chuck.tolturn");
    ProjectParseResult read = readProjectFile(path);
    if (!read.project) {
        std::printf("cannot read %s\n", qPrintable(path));
        return 1;
    }
    Project project = *read.project;
    // The example's 8 tolerances on 7 features, plus the profiles of the edge round O7 and the
    // chamfer O10 and, with the chuck gripping only 20 mm so that the Ø56 O2 is partly turned, its
    // cylindricity: 11 tolerances on 10 features.
    project.clamping.clampedLength_mm = 20.0;
    project.tolerances.push_back(geometric("T9", ToleranceType::Profile, "O7", 20.0));
    project.tolerances.push_back(geometric("T10", ToleranceType::Profile, "O10", 30.0));
    project.tolerances.push_back(geometric("T11", ToleranceType::Cylindricity, "O2", 10.0));
    QStringList features;
    for (const Tolerance &t : project.tolerances) {
        if (!features.contains(t.featureId))
            features << t.featureId;
        if (!t.toFeatureId.isEmpty() && !features.contains(t.toFeatureId))
            features << t.toFeatureId;
    }
    std::printf("part: %s, %lld tolerances on %lld features\n", qPrintable(project.part.name),
                static_cast<long long>(project.tolerances.size()), static_cast<long long>(features.size()));

    const auto built = PlanningProblem::build(project, DataLibrary::builtIn());
    if (!built.problem)
        return 1;
    PlanResult plan;
    const double optimise = medianMilliseconds(21, [&] { plan = optimisePlan(*built.problem); });
    std::printf("optimisation: median %.1f ms, %d evaluations, feasible %d, time %.3f min per part\n", optimise,
                plan.evaluations, plan.feasible ? 1 : 0, plan.evaluation.time_min);
    const double build = medianMilliseconds(21, [&] { (void)PlanningProblem::build(project, DataLibrary::builtIn()); });
    std::printf("problem set-up (inputs, influence table, finishing passes' tool paths): median %.2f ms\n", build);
    const double depth = plan.candidate.finishing.depthOfCut_mm;
    const double table = medianMilliseconds(21, [&] { (void)built.problem->forFinishingDepth(depth); });
    std::printf("influence table at the optimum's depth (%.3f mm): median %.2f ms\n", depth, table);

    for (const auto &[windowPlane, name] :
         {std::pair{WindowPlane::FeedSpeed, "feed-speed"}, std::pair{WindowPlane::FeedDepth, "feed-depth"}}) {
        const WindowPlane plane = windowPlane; // clang 14 cannot capture a structured binding in a lambda (P1091R3)
        for (const int threads : {1, 2}) {
            WindowOptions o;
            o.threads = threads;
            const double ms =
                medianMilliseconds(7, [&] { (void)cuttingWindow(*built.problem, plane, plan.candidate, o); });
            std::printf("window 256 x 256 %s, %d thread%s: median %.1f ms\n", name, threads, threads > 1 ? "s" : "",
                        ms);
        }
    }
    return 0;
}
