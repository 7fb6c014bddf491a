// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The cutting forces of five-axis ball-end milling, after Öztürk & Budak (seed 001, in Turkish;
// MODEL §6): the edge is cut into disc elements along the tool axis; for each rotation angle every
// element of every flute is located in the workpiece frame through T(lead, tilt) (eq. 6), tested
// against the engagement limits (tables 1–2), given its chip thickness (eq. 8–10) and its edge and
// cutting forces (eq. 11), which are summed on the tool. docs/milling.md says how.

#include "core/adaptive/end_milling.h"
#include "core/milling/ball_end_geometry.h"

#include <Eigen/Core>
#include <QString>

#include <optional>
#include <string>
#include <vector>

namespace tolturn {

// The largest cutting or edge coefficient taken: K_tc of the hardest materials is a few thousand
// N/mm².
inline constexpr double kMaxMillingCoefficient = 100000.0;

// "Ktc, Krc, Kac, Kte, Kre, Kae" (N/mm², N/mm) as the planner types them: separated by commas, or by
// semicolons where the comma is the decimal separator, each number in the C or the user's locale;
// nullopt unless six finite numbers of at most kMaxMillingCoefficient.
[[nodiscard]] std::optional<MillingForceCoefficients> parseMillingCoefficients(const QString &text);

// A solid ball-end mill (001 fig. 1).
struct BallEndMill {
    double diameter_mm = 0.0;
    int flutes = 0;
    double helix_rad = 0.0; // i0, the helix angle where the edge reaches the full diameter
};

// One five-axis ball-end cut. The workpiece frame (001 §2.3) is F (feed), C (cross-feed), N
// (surface normal); the tool axis is tilted from N by the lead about C and the tilt about F.
struct BallEndCut {
    BallEndCutKind kind = BallEndCutKind::Slot;
    MillingDirection direction = MillingDirection::Down;
    double axialDepth_mm = 0.0;  // a, along the surface normal
    double radialDepth_mm = 0.0; // s: the width of a side cut or the step-over; not used in a slot
    double feedPerTooth_mm = 0.0;
    double lead_rad = 0.0;
    double tilt_rad = 0.0;
};

struct BallEndResolution {
    int axialSlices = 200;         // disc elements over the engaged height of the ball
    int anglesPerRevolution = 360; // rotation angles at which the forces are summed
};

// The band of the tool axis, measured from the tip, that can be in the cut: the cap of the ball
// within the axial depth of its lowest point along N.
struct BallEndBand {
    double low_mm = 0.0;
    double high_mm = 0.0;
};

// The angle between the tool axis and the surface normal, acos(cos lead · cos tilt) (T₃₃ of eq. 6).
[[nodiscard]] double toolAxisInclination_rad(double lead_rad, double tilt_rad);

// The deepest cut the ball alone makes at this lead and tilt: R_o (1 − sin θ), θ the inclination.
// Deeper, the cylinder above the ball cuts too, which 001 does not model.
[[nodiscard]] double deepestCutOnBall_mm(double diameter_mm, double lead_rad, double tilt_rad);

// The band for a cut; the cut must lie on the ball (axial depth within deepestCutOnBall_mm).
[[nodiscard]] BallEndBand engagedBand(const BallEndMill &mill, const BallEndCut &cut);

// The heights of the elements' middles, from the tip, for a cut at a resolution.
[[nodiscard]] std::vector<double> sliceHeights_mm(const BallEndMill &mill, const BallEndCut &cut,
                                                  const BallEndResolution &resolution);

// Compliances that turn the elements' forces into a displacement of the tool (ball_end_deflection):
// the lateral one of each element, in the order of sliceHeights_mm, and the axial one.
struct BallEndSliceCompliance {
    std::vector<double> lateral_mm_N;
    double axial_mm_N = 0.0;
};

struct BallEndForceSample {
    double rotation_rad = 0.0;
    Eigen::Vector3d toolFrame_N = Eigen::Vector3d::Zero();      // on the tool, in its x, y, z
    Eigen::Vector3d workpieceFrame_N = Eigen::Vector3d::Zero(); // on the tool, in F, C, N
    double torque_N_mm = 0.0;                                   // about the tool axis
    Eigen::Vector3d deflection_mm = Eigen::Vector3d::Zero();    // in x, y, z; with compliances only
    // The part of deflection_mm the cutting coefficients make, per mm of feed per tooth: the chip
    // is proportional to the feed and the engagement does not depend on it, so at another feed f
    // the deflection is deflection_mm + (f − f_t) · this.
    Eigen::Vector3d deflectionPerFeed_mm_mm = Eigen::Vector3d::Zero();
};

// The forces on the tool at anglesPerRevolution rotation angles of one revolution, starting at 0
// (the first flute's tip on +y). Throws std::invalid_argument, naming the value, for a tool or cut
// the model does not take (see validateBallEndCut).
[[nodiscard]] std::vector<BallEndForceSample> ballEndForces(const BallEndMill &mill,
                                                            const MillingForceCoefficients &coefficients,
                                                            const BallEndCut &cut, const BallEndResolution &resolution,
                                                            const BallEndSliceCompliance *compliance = nullptr);

// What is wrong with a tool, cut or resolution for the model, one message per field naming it and
// its value; empty when the model takes them.
[[nodiscard]] std::vector<std::string> validateBallEndCut(const BallEndMill &mill, const BallEndCut &cut,
                                                          const BallEndResolution &resolution);

struct BallEndForceSummary {
    Eigen::Vector3d peak_N = Eigen::Vector3d::Zero(); // largest magnitude of each component (F, C, N)
    double peakResultant_N = 0.0;
    double meanTorque_N_mm = 0.0;
    double peakTorque_N_mm = 0.0;
};

[[nodiscard]] BallEndForceSummary summarise(const std::vector<BallEndForceSample> &samples);

// Spindle power of a mean torque at a speed: P = T ω.
[[nodiscard]] double spindlePower_W(double meanTorque_N_mm, double spindle_rpm);

} // namespace tolturn
