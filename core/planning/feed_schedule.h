// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A feed schedule for the finishing pass (docs/adaptive.md §5): one feed per turned feature of the
// outer contour, the largest in the plan's feed range that keeps every tolerance the pass can hold
// inside its limit, with the finishing pass's own limits (roughness, power, torque, force). The
// deflection at a station depends on the force while the tool is there, so the deviation of a
// scheduled pass is that of each feature's own feed, feature by feature.

#include "core/common/diagnostic.h"
#include "core/planning/gcode.h"
#include "core/planning/planning_problem.h"

#include <QMap>
#include <QString>
#include <QStringList>

#include <vector>

namespace tolturn {

struct ScheduledFeed {
    QString featureId;
    double feed_mm_rev = 0.0;
    QString limitedBy; // what stops a larger feed: a tolerance's label, a limit's, or the feed range
    bool held = false; // kept at the programmed feed: `limitedBy` is a tolerance no feed in the range holds
};

struct FeedSchedule {
    double programmedFeed_mm_rev = 0.0;
    std::vector<ScheduledFeed> features;     // outer features and faces, in the order of the contour
    std::vector<ConstraintValue> tolerances; // of the scheduled pass
    // The scheduled pass's deviation, each feature's at its own feed (the kept-back ones at the
    // programmed feed): what a compensation of the scheduled program is planned from.
    DeviationResult deviation;
    QStringList notes;
    Diagnostics diagnostics;

    [[nodiscard]] bool ok() const { return !hasErrors(diagnostics); }

    [[nodiscard]] QMap<QString, double> feedByFeature() const;
};

// `finishing` is the plan's finishing pass (its cutting speed and depth are kept).
[[nodiscard]] FeedSchedule scheduleFinishingFeeds(const PlanningProblem &problem, const CuttingPass &finishing);
// The schedule of the project's own (last) finishing pass, the planning problem built at the
// compliant end of the machine's range and with what was learned of it, when given.
[[nodiscard]] FeedSchedule scheduleProjectFinishingFeeds(const Project &project, const DataLibrary &data,
                                                         std::shared_ptr<const LoadedModel> learned = nullptr);

// The deviation to compensate a scheduled program from: the schedule's, with the inputs and the
// diagnostics of the deviation at the programmed feed (`constantFeed`, computed the verdicts' way)
// that the program is generated from.
[[nodiscard]] DeviationResult scheduledDeviation(const FeedSchedule &schedule, const DeviationResult &constantFeed);

// The roughing passes' feed move by move: where a level cuts less than its depth (over a shoulder
// it meets the allowance, or the stock the level above left), the move runs at the feed at which the
// resultant force is the programmed feed's at the full depth, up to `maxFeed_mm_rev` (the top of the
// plan's feed range), rounded down to 0.001 mm/rev. The plan's limits (power, torque, force) were
// checked at that force, so none is passed. Moves along z only; plunges and climbs keep the pass's
// feed. The depth along each pass is that of pass_depth.h. Returns the moves given a feed.
int scheduleRoughingFeeds(const Project &project, const ForceFunction &forces, double maxFeed_mm_rev,
                          std::vector<PassPath> &roughing);

// The time of the outer finishing passes, and of the outer roughing passes, of a program's summary [min].
[[nodiscard]] double outerFinishingTime_min(const std::vector<PassSummary> &passes);
[[nodiscard]] double outerRoughingTime_min(const std::vector<PassSummary> &passes);

} // namespace tolturn
