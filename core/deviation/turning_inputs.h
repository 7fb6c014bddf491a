// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A project resolved against the data library (docs/model.md): material constants, forces, tool
// geometry, the supports and what their stiffness rests on, each with its source. The deviation
// model works on what this resolves; the planning problem and the calibrations resolve once and
// evaluate many times.

#include "core/common/diagnostic.h"
#include "core/cutting/cutting_forces.h"
#include "core/data/data_library.h"
#include "core/mechanics/beam.h"
#include "core/mechanics/boring_bar.h"
#include "core/project/project.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <optional>

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
    bool beamCorrections = true;  // the root in the jaws and the shoulders (docs/solid-fe.md)
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

// The boring bar that cuts the inner contour, with its own insert and so its own forces at the
// pass's conditions (docs/model.md §3.1).
struct BoringInputs {
    QString holderCode;
    QString barMaterial; // "steel", "carbide"
    BoringBar bar;
    BoringBarCompliance compliance;
    CuttingForces forces;
    double noseRadius_mm = 0.0;
    double enteringAngle_deg = 0.0;
    std::optional<SourcedValue> maxOverhangRatio; // the maker's largest L/D
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
    SupportStiffnessUsed chuck;           // chuck face (chuck and chuck + tailstock), or the collet's
    bool collet = false;                  // `chuck` is a collet's
    bool beamCorrections = false;         // the root in the jaws and the shoulders (docs/solid-fe.md)
    SupportStiffnessUsed tailstock;       // tailstock, or both centres between centres
    SupportStiffnessUsed headstockCentre; // between centres: the left centre on its own
    std::optional<ThermalDrift> thermal;
    double timeSinceStart_min = 0.0;
    double ambientTemperature_C = 20.0;
    std::optional<double> maxSpindleSpeed_rpm;
    std::optional<double> maxPower_kW;
    std::optional<BoringInputs> boring; // the inner contour's tool, when the project names one
    // One operation of a set-up view (Project::scope): the features it cuts and where the part
    // still has its stock. Without a scope every feature is cut.
    bool scoped = false;
    QStringList cutFeatures;
    std::vector<std::pair<double, double>> stockOuter_mm;
    std::vector<std::pair<double, double>> solidInner_mm;
    QStringList notes; // assumptions the result depends on, for people

    // The forces on the tool that cuts a contour: the boring bar's in a bore, when there is one.
    [[nodiscard]] const CuttingForces &forcesOn(ContourSide side) const
    {
        return side == ContourSide::Inner && boring ? boring->forces : forces;
    }
};

// A force model's keyword ("kienzle", "li_du", "given") as people read it: "Kienzle", "Li & Du",
// "given forces".
[[nodiscard]] QString forceModelName(const QString &keyword);

struct InputsResult {
    std::optional<TurningInputs> inputs;
    Diagnostics diagnostics;
};

// The same inputs with the chuck face held by the family's radial spring K (docs/model.md §2), or
// the tailstock (between centres: both centres) by a radial spring K: the search for the stiffness
// a tolerance needs, without resolving the project again.
[[nodiscard]] TurningInputs withChuckStiffness(TurningInputs inputs, double k_N_per_mm);
[[nodiscard]] TurningInputs withTailstockStiffness(TurningInputs inputs, double k_N_per_mm, ClampingMethod method);

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

} // namespace tolturn
