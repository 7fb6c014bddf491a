// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/data/data_library.h"
#include "core/deviation/turning_inputs.h"
#include "core/planning/compensation.h"
#include "core/planning/post_processor.h"
#include "core/planning/toolpath.h"
#include "core/project/project.h"

#include <QMap>
#include <QString>
#include <QStringList>

#include <optional>

namespace tolturn {

struct GCodeOptions {
    std::optional<ControlDialect> dialect; // unset: the machine's control, else Fanuc/Haas (said in the header)
    NoseHandling nose = NoseHandling::ControlCompensation;
    const CompensationPlan *compensation = nullptr; // nullptr: the target contour as it is
    int tool = 1;
    int boringTool = 2; // the boring bar's, when the set-up bores
    int programNumber = 1000;
    double clearance_mm = kToolClearance_mm;
    // The finishing pass's feed feature by feature (feed_schedule.h): each feature's moves are cut
    // at its feed, the moves between them at the pass's. Empty: the pass's feed throughout.
    QMap<QString, double> finishingFeeds_mm_rev;
    // The roughing moves that cut less than their pass's depth at the feed that keeps the planned
    // force (feed_schedule.h), up to the top of the plan's feed range.
    bool roughingFeedSchedule = false;
};

// What a machinist's set-up sheet gives for a pass of the program: the spindle speed range it
// runs at under G96 and the spindle limit, the cutting power at its conditions, and its time.
struct PassSummary {
    int number = 0;
    PassKind kind = PassKind::Finishing;
    ContourSide side = ContourSide::Outer; // inner: a pass of the boring bar
    CuttingPass conditions;
    double lowestSpeed_rpm = 0.0;
    double highestSpeed_rpm = 0.0;
    std::optional<double> power_kW; // F_c v_c / 60 000; unset when the forces cannot be formed
    double time_min = 0.0;          // every feed move: length / (f n(r)), n = min(1000 v_c / (2 pi r), limit)
};

// A pass as the set-up sheet names it: "roughing", "finishing", "boring, roughing", "boring, finishing".
[[nodiscard]] QString passKindText(const PassSummary &pass);

[[nodiscard]] std::vector<PassSummary> passSummaries(const Toolpath &path, const SpindleLimit &limit,
                                                     const std::optional<ForceFunction> &forces);

struct TurningProgram {
    QString text;
    int programNumber = 1000;
    QString checksum; // the first 16 hex digits of the SHA-256 of the program's UTF-8 text
    ControlDialect dialect = ControlDialect::FanucHaas;
    QString dialectReason; // the machine's control, the caller's choice, or the default
    Toolpath path;
    std::optional<Toolpath> boring; // the boring bar's passes, when the set-up bores (boring_toolpath.h)
    SpindleLimit spindle;
    QString conditions; // the passes the program cuts, in words (for the G-code tab and the report)
    std::vector<PassSummary> passes;

    // What a planner must resolve before running it: the turning path's warnings, then the boring path's.
    [[nodiscard]] QStringList warnings() const;
};

// The program that turns a project's part on its machine: the roughing passes the project plans
// (project.passes, kind roughing) and the finishing pass, then the same passes of the boring bar in
// the bore open at the free end (when the project has a boring bar), along the contour the verdicts assume
// (targetContour(): every toleranced diameter at the middle of its zone, MODEL §3), corrected
// where the compensation plan says, in the dialect of the machine's control. `inputs` are the
// project resolved against the data (nose radius, entering angle, finishing pass, spindle limit).
[[nodiscard]] TurningProgram turningProgram(const Project &project, const DataLibrary &data,
                                            const TurningInputs &inputs, const GCodeOptions &options);

// The finishing passes turningProgram cuts, without the program around them: the outer contour's,
// then the bores' where the set-up bores them. The planner times these (planning_problem.h).
[[nodiscard]] std::vector<PassPath> finishingPasses(const Project &project, const TurningInputs &inputs);

// The control dialect of a machine in the data library, if it has a CNC control.
[[nodiscard]] std::optional<ControlDialect> machineDialect(const DataLibrary &data, const QString &machineId);

[[nodiscard]] QString keyword(NoseHandling nose); // "control", "tip-path"
[[nodiscard]] std::optional<NoseHandling> noseHandlingFromKeyword(const QString &text);

} // namespace tolturn
