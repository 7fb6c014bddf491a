// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/cutting/cutting_forces.h"
#include "core/data/data_library.h"
#include "core/mechanics/moving_load.h"
#include "core/project/project.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <vector>

namespace tolturn {

// Which end of a published stiffness range a machine that was not measured is computed at
// (docs/model.md §2). Planning and the verdicts take the compliant end unless told otherwise.
enum class StiffnessEnd { Compliant, Stiff };

struct DeviationOptions {
    std::optional<CuttingForces> loadOverride; // forces given by the user instead of a force model
    StiffnessEnd stiffnessEnd = StiffnessEnd::Compliant;
    // A radial stiffness that replaces what the chuck face, or the tailstock (both centres between
    // centres), would otherwise be: the search for the stiffness a tolerance needs [N/mm].
    std::optional<double> chuckStiffness_N_per_mm;
    std::optional<double> tailstockStiffness_N_per_mm;
    bool workpieceOnly = false;   // rigid machine supports, no toolpost or thermal term
    bool inProcessSection = true; // the pass's own stock still on, left of the tool
    int stationsPerFeature = 21;
    int passIndex = -1; // -1: the last finishing pass (or the last pass)
};

// What a support's stiffness rests on, for people and for the range verdicts.
enum class SupportBasis {
    NotUsed,     // the clamping has no such support
    Measured,    // the project's characterisation
    RangeEnd,    // one end of the data library's published range
    Given,       // DeviationOptions: a value tried by the caller
    RigidNoData, // neither measured nor published: rigid, which is optimistic
};

struct SupportStiffnessUsed {
    SupportBasis basis = SupportBasis::NotUsed;
    double stiffness_N_per_mm = 0.0;     // RangeEnd and Given; 0 otherwise
    std::optional<StiffnessRange> range; // the published range, where there is one
};

// Everything the deviation model needs, resolved from a project and the data library.
struct TurningInputs {
    ElasticMaterial material;
    QString materialName;
    CuttingPass pass;
    int passIndex = 0;
    CuttingForces forces;
    QString forceModel; // "kienzle", "li_du" or "given"
    double noseRadius_mm = 0.0;
    double enteringAngle_deg = 0.0;
    double toolpostCompliance_mm_per_N = 0.0;
    double supportStart_mm = 0.0; // chuck face or left centre
    double supportEnd_mm = 0.0;   // right end of the part
    EndSupport radialLeft, radialRight, tangentialLeft, tangentialRight;
    bool spindleCharacterised = false;
    SupportStiffnessUsed chuck;     // chuck face (chuck and chuck + tailstock)
    SupportStiffnessUsed tailstock; // tailstock, or both centres between centres
    std::optional<ThermalDrift> thermal;
    double timeSinceStart_min = 0.0;
    double ambientTemperature_C = 20.0;
    std::optional<double> maxSpindleSpeed_rpm;
    std::optional<double> maxPower_kW;
    QStringList notes; // assumptions the result depends on, for people
};

struct InputsResult {
    std::optional<TurningInputs> inputs;
    Diagnostics diagnostics;
};

[[nodiscard]] InputsResult resolveTurningInputs(const Project &project, const DataLibrary &data,
                                                const DeviationOptions &options);

// The tool geometry of the Li & Du model for a project: rake and inclination from the project,
// the holder data, or the seat of a holder for negative inserts; lead angle from the entering
// angle; nose radius from the insert code. nullopt with an error naming the missing field.
[[nodiscard]] std::optional<LiDuToolGeometry> resolveLiDuToolGeometry(const Project &project, const DataLibrary &data,
                                                                      Diagnostics &out);

// The project's force model (Kienzle or Li & Du, as its cutting_model says) as a function of
// feed and depth of cut, with material and tool resolved once; nullopt with errors when they
// cannot be.
using ForceFunction = std::function<CuttingForces(double feed_mm_rev, double depthOfCut_mm)>;
[[nodiscard]] std::optional<ForceFunction> projectForceModel(const Project &project, const DataLibrary &data,
                                                             Diagnostics &out);

// Deviations at one tool position, in mm. Radial contributions are "material left": positive
// where the surface stays proud of nominal (a shaft too large, a bore too small).
struct Contributions {
    double spindleChuck_mm = 0.0; // rigid motion of the machine's supports (chuck, or centres)
    double toolpost_mm = 0.0;
    double workpiece_mm = 0.0;
    double thermal_mm = 0.0;

    [[nodiscard]] double total_mm() const { return spindleChuck_mm + toolpost_mm + workpiece_mm + thermal_mm; }
};

struct Station {
    double z_mm = 0.0;
    double nominalRadius_mm = 0.0;
    double spindleSpeed_rpm = 0.0;
    Contributions radial;
    Contributions tangential;         // toolpost and thermal terms are radial only
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
