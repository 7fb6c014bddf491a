// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/part/profile.h"
#include "core/project/milled_feature.h"

#include <QJsonValue>
#include <QMap>
#include <QString>
#include <QStringList>

#include <optional>
#include <utility>
#include <vector>

namespace tolturn {

// How the part is held on the lathe (Valiño et al. 2008, §II: the three methods of the model), and
// in a collet: built in at the collet's face like a chuck, its own stiffness (docs/model.md §2).
enum class ClampingMethod { Chuck, BetweenCentres, ChuckTailstock, Collet };

// Held at one end only, in a chuck or a collet: the other end is free.
[[nodiscard]] constexpr bool holdsOneEndOnly(ClampingMethod m)
{
    return m == ClampingMethod::Chuck || m == ClampingMethod::Collet;
}

// An end of the part: left is z = 0 of the drawing, right is z = length.
enum class PartEnd { Left, Right };

struct Clamping {
    ClampingMethod method = ClampingMethod::Chuck;
    // Length of the part held in the jaws, from the held end. The chuck face is at that distance
    // from it. Zero between centres.
    double clampedLength_mm = 0.0;
    // The end the chuck holds (between centres: the end on the headstock centre and driver). An
    // operation that holds the right end sees the part turned end for end (docs/operations.md).
    PartEnd heldEnd = PartEnd::Left;

    friend bool operator==(const Clamping &, const Clamping &) = default;
};

// How far the program keeps a tool, and the turret face, off the part in its approach and retract
// moves (a programming convention, not a datum): the default boring-bar overhang adds it, so the
// bar's edge reaches the bottom of its bore with the turret this far off the end face.
inline constexpr double kToolClearance_mm = 2.0;

struct Tool {
    QString insertCode;                // ISO 1832, e.g. "CNMG 120408"
    QString holderCode;                // ISO 5608, e.g. "PCLNR 2525M12"
    std::optional<double> overhang_mm; // tool length out of the turret (a boring bar: clamping to edge)
    std::optional<double> rake_deg;    // normal rake, when the holder data do not give it
    std::optional<double> inclination_deg;
    // A boring bar's cutting edge from the bar's axis, the maker's functional dimension f [mm].
    std::optional<double> edgeOffset_mm;
    // A boring bar's: the hole drilled (or cored) before the bar starts, which its roughing levels
    // widen to the bore. Unset: the bore is taken as roughed to its finishing allowance before.
    std::optional<double> pilotHoleDiameter_mm;

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

// Which cutting-force model gives the forces, and the constants a project supplies itself
// (docs/model.md §3). Unset ratios and coefficients come from the material data.
enum class ForceModel { Kienzle, LiDu };

struct CuttingModel {
    ForceModel forceModel = ForceModel::Kienzle;
    std::optional<double> feedToCuttingRatio;
    std::optional<double> passiveToCuttingRatio;
    std::optional<double> normalPressure_MPa; // Li & Du K_n
    std::optional<double> frictionRatio;      // Li & Du K_f

    friend bool operator==(const CuttingModel &, const CuttingModel &) = default;
};

// Springs of the spindle–chuck unit in one direction (docs/model.md §2).
struct SpindleSprings {
    double k1_N_per_mm = 0.0;
    double k2_Nmm_per_rad = 0.0;
    double k3_Nmm_per_rad = 0.0;

    friend bool operator==(const SpindleSprings &, const SpindleSprings &) = default;
};

// A support stiffness in the radial and tangential directions [N/mm].
struct SupportStiffness {
    double radial_N_per_mm = 0.0;
    double tangential_N_per_mm = 0.0;

    friend bool operator==(const SupportStiffness &, const SupportStiffness &) = default;
};

// First-order warm-up of the radial thermal drift (docs/model.md §5):
// delta_th = (a_n n/1000 + a_T (T - T_ref)) (1 - exp(-t/tau)).
struct ThermalDrift {
    double drift_um_per_1000rpm = 0.0;
    double drift_um_per_K = 0.0;
    double referenceTemperature_C = 20.0;
    double timeConstant_min = 0.0;

    friend bool operator==(const ThermalDrift &, const ThermalDrift &) = default;
};

// What was measured on the machine this part is planned for. Anything absent is not
// characterised: its supports are then taken as rigid (Valiño et al. 2008 eq. 6–8 make the same
// assumption) and the thermal drift as zero, and every result says so.
struct MachineCharacterisation {
    QString source; // who measured it, when, how
    std::optional<double> pivotDistance_mm;
    std::optional<SpindleSprings> spindleRadial;
    std::optional<SpindleSprings> spindleTangential;
    std::optional<SupportStiffness> tailstock;
    std::optional<SupportStiffness> centres;
    std::optional<ThermalDrift> thermal;

    friend bool operator==(const MachineCharacterisation &, const MachineCharacterisation &) = default;
};

struct Environment {
    std::optional<double> ambientTemperature_C;
    std::optional<double> timeSinceStart_min;

    friend bool operator==(const Environment &, const Environment &) = default;
};

// What the optimiser of cutting conditions works with (docs/planning.md). Rates and requirements
// are the planner's; tool life and cutting ranges come from the insert maker, with their source.
enum class PlanningObjective { Time, Cost };

struct ValueRange {
    double min = 0.0;
    double max = 0.0;

    friend bool operator==(const ValueRange &, const ValueRange &) = default;
};

struct PlanningSettings {
    PlanningObjective objective = PlanningObjective::Time;
    double machineRate_per_min = 0.0; // cost of the machine and operator per minute
    double toolCostPerEdge = 0.0;
    double toolChangeTime_min = 0.0;
    double handlingTime_min = 0.0;       // loading, unloading, idle moves per part
    std::optional<double> taylorC_m_min; // Taylor: vc T^n = C (T in min)
    std::optional<double> taylorN;
    std::optional<double> minToolLife_min;
    QString toolLifeSource;
    std::optional<ValueRange> cuttingSpeed_m_min;
    std::optional<ValueRange> feed_mm_rev;
    std::optional<ValueRange> depthOfCut_mm;
    QString rangesSource;
    std::optional<double> maxRa_um;
    std::optional<double> maxRz_um;
    std::optional<double> maxForce_N;
    std::optional<double> maxPower_kW; // overrides the machine data
    std::optional<double> maxTorque_Nm;
    std::optional<double> maxSpindleSpeed_rpm;
    QStringList disabledConstraints; // constraint keywords switched off by the planner

    friend bool operator==(const PlanningSettings &, const PlanningSettings &) = default;
};

// A set-up of the part on the lathe after the first (docs/operations.md): its clamping, tools and
// passes, and the turned features it cuts. The first operation is the project's own clamping,
// tool, boring tool and passes, and cuts every feature no later operation names.
struct Operation {
    QString name; // as the routing sheet names it: "OP 20"
    Clamping clamping;
    Tool tool;
    std::optional<Tool> boringTool;
    std::vector<CuttingPass> passes;
    QStringList features; // ids of the features this operation cuts

    friend bool operator==(const Operation &, const Operation &) = default;
};

// Set on the project of one operation of a project of several (operationView(),
// docs/operations.md): which operation it is, the features it cuts, and the outer z ranges where
// the part still has its stock because a later operation turns them.
struct OperationScope {
    QString name;
    int index = 0;
    int count = 1;
    QStringList cutFeatures;
    QMap<QString, QString> cutElsewhere;                  // feature id -> the operation that cuts it, for the others
    std::vector<std::pair<double, double>> stockOuter_mm; // [z from, z to] in the operation's frame
    std::vector<std::pair<double, double>> solidInner_mm; // where a later operation bores: not bored yet

    friend bool operator==(const OperationScope &, const OperationScope &) = default;
};

struct Project {
    PartProfile part;
    QString materialId;
    QString machineId;
    Tool tool;
    // The tool that cuts the inner contour: a boring bar (docs/model.md §3.1). Without one the
    // bores are computed as if cut by `tool`, and every result says so.
    std::optional<Tool> boringTool;
    Clamping clamping;
    std::vector<CuttingPass> passes;
    QString firstOperationName;               // empty: "OP 10"
    std::vector<Operation> furtherOperations; // the set-ups after the first, in order
    std::optional<OperationScope> scope;      // set only on a view of one operation, never in a file
    std::vector<Datum> datums;
    std::vector<Tolerance> tolerances;
    std::vector<MilledFeature> milledFeatures; // of a mill-turn part (docs/milling.md)
    CuttingModel cuttingModel;
    MachineCharacterisation characterisation;
    Environment environment;
    PlanningSettings planning;
    // Fields of the file this TolTurn does not know (a newer version's, another tool's), by path
    // ("part.colour"), written back as they were so that no command drops them.
    std::vector<std::pair<QString, QJsonValue>> unknownFields;

    friend bool operator==(const Project &, const Project &) = default;
};

// True for the types whose value is a size with limit deviations (ISO 286 or explicit).
[[nodiscard]] bool isSizeTolerance(ToleranceType type);
// True for the ISO 1101 types that are defined relative to a datum.
[[nodiscard]] bool needsDatum(ToleranceType type);

} // namespace tolturn
