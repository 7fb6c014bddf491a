// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/deviation/turning_inputs.h"
#include "core/mechanics/moving_load.h"
#include "core/project/project.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <vector>

namespace tolturn {

// Deviations at one tool position, in mm. Radial contributions are "material left": positive
// where the surface stays proud of nominal (a shaft too large, a bore too small).
struct Contributions {
    double spindleChuck_mm = 0.0; // rigid motion of the machine's supports (chuck, or centres)
    double toolpost_mm = 0.0;
    double workpiece_mm = 0.0;
    double thermal_mm = 0.0;
    double boringBar_mm = 0.0; // bending and twist of the boring bar (inner features, docs/model.md §3.1)

    [[nodiscard]] double total_mm() const
    {
        return spindleChuck_mm + toolpost_mm + workpiece_mm + thermal_mm + boringBar_mm;
    }
};

// The machined radius less nominal from the radial and tangential deviation at a station (MODEL §1):
// the tool tip sits at (r0 ± d_r, d_t) from the deflected axis, + on an outer surface.
[[nodiscard]] double radiusError_mm(double r0, double radial_mm, double tangential_mm, bool outer);

struct Station {
    double z_mm = 0.0;
    double nominalRadius_mm = 0.0;
    double spindleSpeed_rpm = 0.0;
    Contributions radial;
    Contributions tangential;         // toolpost and thermal terms are radial only; the boring bar's both
    double radiusError_mm = 0.0;      // machined radius - nominal, radial and tangential combined exactly
    double sectionRotation_rad = 0.0; // rotation of the section under the tool
};

struct FeatureDeviation {
    QString featureId;
    ContourSide side = ContourSide::Outer;
    SegmentKind kind = SegmentKind::Cylinder;
    std::vector<Station> stations;
};

// Conicity of a faced surface (Valiño et al. 2008 eq. 1 and 12) under the forces of a facing cut
// at the finishing conditions (docs/model.md §4): e is the axial run-out left across the face,
// tan(theta) its mean tilt; with a tilt that does not change across the face, e = (D_M - D_m)/2
// tan(theta).
struct FaceConicity {
    QString featureId;
    ContourSide side = ContourSide::Outer;
    double z_mm = 0.0;
    double tanTheta = 0.0;
    double axialRunout_mm = 0.0; // e
};

struct DeviationResult {
    std::optional<TurningInputs> inputs;
    std::vector<FeatureDeviation> features;
    std::vector<FaceConicity> faces;
    double maxPower_kW = 0.0;
    double maxTorque_Nm = 0.0;
    double theoreticalRa_um = 0.0;
    double theoreticalRz_um = 0.0;
    Diagnostics diagnostics; // errors: no result; warnings: validity and limits
};

[[nodiscard]] DeviationResult computeDeviation(const Project &project, const DataLibrary &data,
                                               const DeviationOptions &options = {});
// What computeDeviation() does once the project is resolved: for callers that vary the inputs.
[[nodiscard]] DeviationResult deviationFor(const PartProfile &part, const TurningInputs &inputs,
                                           const DeviationOptions &options = {});

// The influence of unit loads along the turned features, for sweeping many cutting conditions:
// deviation = F_r c_r + F_a c_a + F_r c_tp (radial), F_t c_t (tangential); linear in the forces.
struct StationInfluence {
    double radialPerRadial_mm_per_N = 0.0; // w under a unit radial force, spindle + workpiece
    double radialPerAxial_mm_per_N = 0.0;  // w under the moment of a unit axial force at the contact radius
    double tangentialPerTangential_mm_per_N = 0.0;
    double spindlePerRadial_mm_per_N = 0.0;
    double spindlePerAxial_mm_per_N = 0.0;
    double spindleTangential_mm_per_N = 0.0;
    double rotationPerRadial_rad_per_N = 0.0;
    double rotationPerAxial_rad_per_N = 0.0;
    double rotationPerMoment_rad_per_Nmm = 0.0; // under a unit moment at the load (facing)
};

struct FeatureInfluence {
    QString featureId;
    ContourSide side = ContourSide::Outer;
    SegmentKind kind = SegmentKind::Cylinder;
    std::vector<double> z_mm;
    std::vector<double> nominalRadius_mm;
    std::vector<StationInfluence> stations;
};

struct InfluenceTable {
    std::vector<FeatureInfluence> features;
    std::vector<FeatureInfluence> faces; // one station per face, at the face
    double toolpostCompliance_mm_per_N = 0.0;
};

// Builds the influence table for a project and its resolved inputs. `allowance_mm` is the depth
// of the pass still on the uncut side of the tool (0: the in-process section is ignored).
[[nodiscard]] InfluenceTable buildInfluenceTable(const PartProfile &part, const TurningInputs &inputs,
                                                 int stationsPerFeature, double allowance_mm);

// The influence of unit loads on the outer surface at the given tool positions, on the finished
// section: what buildInfluenceTable() gives at a feature's stations, at any z (the solid check,
// docs/solid-fe.md).
[[nodiscard]] std::vector<StationInfluence> influenceAt(const PartProfile &part, const TurningInputs &inputs,
                                                        const std::vector<double> &z_mm,
                                                        const std::vector<double> &contactRadius_mm);

// The deviation for the forces and pass in `inputs`, from an influence table built for the same
// part and supports: what computeDeviation() does after building the table, for callers that
// evaluate many cutting conditions on one table.
[[nodiscard]] DeviationResult evaluateInfluenceTable(const PartProfile &part, const InfluenceTable &table,
                                                     const TurningInputs &inputs);

// Form error of every turned feature under many cutting conditions at once, by the linearity of
// the deflection in the forces (docs/model.md §6): for each condition, the spread
// max(delta_r) - min(delta_r) of the radial deviation over each feature's stations [mm]. The
// section is that of the table (its in-process allowance), the forces those given.
struct ConditionForces {
    double radial_N = 0.0;
    double axial_N = 0.0;
};

[[nodiscard]] std::vector<double> sweepFormErrors(const InfluenceTable &table,
                                                  const std::vector<ConditionForces> &conditions);

} // namespace tolturn
