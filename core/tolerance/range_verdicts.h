// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/data/data_library.h"
#include "core/deviation/deviation_model.h"
#include "core/tolerance/evaluation.h"

#include <optional>
#include <vector>

namespace tolturn {

// What a tolerance's verdict is worth on a machine whose stiffness is a published range rather
// than a measurement (docs/tolerances.md, "Machines that were not measured"). "Passes" is the
// verdict TolTurn's own program earns: passes as programmed.
enum class RangeVerdict {
    PassesOnAnyMachine,            // passes at the compliant end of the range, so on any machine in it
    PassesIfStiffer,               // passes only on a machine stiffer than the required stiffness
    PassesOnPartOfRange,           // passes at the compliant end but not at the stiff end (a form error that a
                                   // stiffer support makes worse, e.g. a part between a chuck and a tailstock)
    PassesAfterOffsetOnAnyMachine, // fails as programmed at both ends, but one constant offset of the
                                   // programmed size holds it at both (a size only)
    FailsEvenOnStiffest,           // fails at the stiff end of the range too
    NotFinished,                   // the set-up's program leaves part of its feature unfinished (`unfinished`):
                                   // not judged as programmed (finished_extent.h)
    NoRange,                       // the machine was measured (or the clamping uses no ranged support)
    NotDecided,                    // the characteristic is not predicted or cannot be evaluated
};

// The smallest radial stiffness of a support with which a tolerance passes as programmed, the
// other supports as assumed (docs/model.md §2). Searched over 1 N/µm to 10⁶ N/µm. A stiffer support
// does not always make a form error smaller (with a tailstock a stiffer chuck can tilt the part
// more): where a stiffer grid point fails again the result is a window.
struct RequiredStiffness {
    enum class Kind {
        Found,        // value_N_per_mm is the threshold (to 0.5 %); every stiffer grid point passes
        Window,       // passes from value_N_per_mm, but fails again at upper_N_per_mm (grid point)
        AnyStiffness, // passes even at 1 N/µm: the support does not decide it
        NotReachable, // fails at every stiffness searched: stiffness alone will not bring it in
    };
    Kind kind = Kind::AnyStiffness;
    double value_N_per_mm = 0.0;
    double upper_N_per_mm = 0.0; // Window
};

struct ToleranceRangeEvaluation {
    ToleranceEvaluation compliant;            // at the compliant end (or as measured)
    std::optional<ToleranceEvaluation> stiff; // at the stiff end, where a range applies
    RangeVerdict range = RangeVerdict::NoRange;
    std::optional<RequiredStiffness> chuck;     // chuck and chuck + tailstock, or the collet
    std::optional<RequiredStiffness> tailstock; // tailstock, or both centres between centres
    bool collet = false;                        // `chuck` is what a collet needs
    // Where a size does not hold as programmed on the whole range but the sizes of both ends fit its
    // zone together: the change of the programmed diameter that centres them [µm]. Always with
    // PassesAfterOffsetOnAnyMachine; with PassesIfStiffer and PassesOnPartOfRange where it exists.
    std::optional<double> offsetOnAnyMachine_um;
    // NotFinished: what of its feature the program leaves, e.g. "z 35.000–37.750 mm of O4".
    QStringList unfinished;
};

struct RangeEvaluation {
    DeviationResult compliant;
    std::optional<DeviationResult> stiff; // where a range applies
    std::vector<ToleranceRangeEvaluation> tolerances;
    bool machineIsRange = false;     // some support is a published range
    bool someSupportRigid = false;   // some support is neither measured nor published: rigid
    bool thermalTakenAsZero = false; // no thermal characterisation: no drift
};

// The verdicts of `project` at both ends of the stiffness range of its machine's unmeasured
// supports, and the stiffness each tolerance needs of the chuck and the tailstock. The options'
// stiffness end and support overrides are set here; the rest (forces, pass) are the caller's.
[[nodiscard]] RangeEvaluation evaluateOverStiffnessRange(const Project &project, const DataLibrary &data,
                                                         const DeviationOptions &options = {});

// For the view of one operation of several (docs/operations.md): every tolerance that relates a
// feature to one cut in another set-up gets, in its reason, the error of clamping the part again
// and the largest re-clamping error it holds with. Where the deflection predicts nothing of it
// (coaxiality), the re-clamping error is all there is, against the tolerance's zone.
void addReclampingNotes(const Project &project, RangeEvaluation &range, const DataLibrary &data);

[[nodiscard]] QString rangeVerdictKeyword(RangeVerdict verdict); // "passes_on_any_machine", ...
// For people: "passes on any machine in the range", "passes if stiffer than 120 N/µm", ...
[[nodiscard]] QString rangeVerdictText(const ToleranceRangeEvaluation &e);
// "≥ 120 N/µm", "any", "not reachable".
[[nodiscard]] QString requiredStiffnessText(const RequiredStiffness &r);
// One line on what the supports rest on, for the banner above the verdicts and the report.
[[nodiscard]] QString machineAssumptionText(const RangeEvaluation &r, const DataLibrary &data);

} // namespace tolturn
