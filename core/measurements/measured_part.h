// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/measurements/drive_reading.h"

#include <QByteArray>
#include <QDateTime>
#include <QString>

#include <optional>
#include <vector>

namespace tolturn {

// What was measured at a point of a turned surface (docs/learning.md): the diameter there; the
// radial deviation from the programmed size (a dial gauge along the part); or a point of the
// surface as a coordinate measuring machine reports it, x and y across the axis and z along it, in
// the part's frame (the CMM aligned on the part's axis, as its software does on a datum axis),
// whose radius √(x² + y²) is what is compared. All in mm in the store; shown in µm where they are
// deviations.
enum class MeasuredQuantity { Diameter, RadialDeviation, CmmPoint };

struct MeasuredPoint {
    QString featureId; // the profile segment's id ("O3", "I1") in the part's snapshot
    double z_mm = 0.0;
    MeasuredQuantity quantity = MeasuredQuantity::Diameter;
    // The diameter, the radial deviation (positive: material left), or a CMM point's radius.
    double value_mm = 0.0;
    double x_mm = 0.0; // CmmPoint only
    double y_mm = 0.0; // CmmPoint only

    friend bool operator==(const MeasuredPoint &, const MeasuredPoint &) = default;
};

// A CMM point, its radius worked out: value_mm = √(x² + y²).
[[nodiscard]] MeasuredPoint cmmPoint(const QString &featureId, double x_mm, double y_mm, double z_mm);

// One part as it came off a machine and was measured, with what it was cut from: the project
// snapshot (profile, conditions, tool, clamping) and the shop conditions of the cut (Li & Du,
// 003 §3.2: time since start and ambient temperature drive the thermal error).
struct MeasuredPart {
    qint64 id = 0; // given by the store
    QString machineId;
    QDateTime measuredAt; // UTC
    QString measuredBy;
    QString method; // "micrometer", "CMM", "bore gauge", …
    std::optional<double> timeSinceStart_min;
    std::optional<double> ambient_C;
    QByteArray projectJson; // the project file the part was cut from, as written then
    QString note;
    std::vector<MeasuredPoint> points;
    // The drives' readings during the finishing cut, when they were logged: the forces the network
    // learns from are then estimated from the motor currents (Li & Du eq. 7–14) rather than taken
    // from the force model.
    std::optional<DriveReading> drive;

    friend bool operator==(const MeasuredPart &, const MeasuredPart &) = default;
};

// A line of a listing: the part without its snapshot and points.
struct MeasuredPartSummary {
    qint64 id = 0;
    QString machineId;
    QString partName; // from the snapshot
    QDateTime measuredAt;
    QString measuredBy;
    QString method;
    int pointCount = 0;
};

[[nodiscard]] QString keyword(MeasuredQuantity quantity);
[[nodiscard]] std::optional<MeasuredQuantity> measuredQuantityFromKeyword(const QString &text);

// The part's findings before it is stored: a snapshot that is a valid project, points on its
// profile (the feature exists, z within it, values finite and in the bounds of
// docs/learning.md), a machine, a plausible time and temperature. Fields are named as in the CLI
// ("points[3].z_mm").
[[nodiscard]] Diagnostics validateMeasuredPart(const MeasuredPart &part);

} // namespace tolturn
