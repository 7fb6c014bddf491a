// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/part/profile.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace tolturn {

// How the part is held on the lathe (Valiño et al. 2008, §II: the three methods of the model).
enum class ClampingMethod { Chuck, BetweenCentres, ChuckTailstock };

struct Clamping {
    ClampingMethod method = ClampingMethod::Chuck;
    // Length of the part held in the jaws, from its left end (z = 0). The chuck face is at
    // z = clampedLength_mm. Zero between centres.
    double clampedLength_mm = 0.0;

    friend bool operator==(const Clamping &, const Clamping &) = default;
};

struct Tool {
    QString insertCode; // ISO 1832, e.g. "CNMG 120408"
    QString holderCode; // ISO 5608, e.g. "PCLNR 2525M12"

    friend bool operator==(const Tool &, const Tool &) = default;
};

enum class PassKind { Roughing, Finishing };

struct CuttingPass {
    PassKind kind = PassKind::Finishing;
    double cuttingSpeed_m_min = 0.0;
    double feed_mm_rev = 0.0;
    double depthOfCut_mm = 0.0;

    friend bool operator==(const CuttingPass &, const CuttingPass &) = default;
};

// ISO 1101 / ISO 286 characteristics a turned part carries (Valiño et al. 2008, §V, Fig. 4).
enum class ToleranceType {
    Length,
    Diameter,
    Flatness,
    Cylindricity,
    Profile,
    Parallelism,
    Perpendicularity,
    Coaxiality,
    CircularRadialRunout,
    CircularAxialRunout,
    TotalRadialRunout,
    TotalAxialRunout,
};

// A datum feature (ISO 5459): a letter attached to a feature of the profile.
struct Datum {
    QString label;
    QString featureId;

    friend bool operator==(const Datum &, const Datum &) = default;
};

// A size tolerance (length, diameter) is either an ISO 286 class or explicit limit deviations;
// a geometric tolerance has a zone width and, where its type needs them, datums.
struct Tolerance {
    QString id;
    ToleranceType type = ToleranceType::Diameter;
    QString featureId;
    QString toFeatureId; // Length: the second face
    QString iso286Class; // e.g. "h6", "H7", "js12"; empty when explicit limits are used
    std::optional<double> upperDeviation_um;
    std::optional<double> lowerDeviation_um;
    std::optional<double> zone_um; // geometric tolerances: width of the tolerance zone
    QStringList datums;

    friend bool operator==(const Tolerance &, const Tolerance &) = default;
};

struct Project {
    PartProfile part;
    QString materialId;
    QString machineId;
    Tool tool;
    Clamping clamping;
    std::vector<CuttingPass> passes;
    std::vector<Datum> datums;
    std::vector<Tolerance> tolerances;

    friend bool operator==(const Project &, const Project &) = default;
};

// True for the types whose value is a size with limit deviations (ISO 286 or explicit).
[[nodiscard]] bool isSizeTolerance(ToleranceType type);
// True for the ISO 1101 types that are defined relative to a datum.
[[nodiscard]] bool needsDatum(ToleranceType type);

} // namespace tolturn
