// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The deflection of a ball-end mill under its cutting forces and the surface error it leaves, after
// Öztürk & Budak (seed 001 §4, table 3): the tool a cylindrical cantilever held in a rigid holder
// through a translational spring k and a rotational spring k_θ; the deflection along the surface
// normal through T (eq. 6). Only the tool deflects (001 §4); the part's and the machine's
// compliance are not in this model, and docs/milling.md says so.

#include "core/milling/ball_end_forces.h"

#include <QStringList>

#include <string>
#include <vector>

namespace tolturn {

// Carbide's Young's modulus: 630 000 N/mm² (MakeItFrom, "Tungsten Carbide (WC)"); cemented carbides
// span 530 000–700 000 N/mm² (Wikipedia, "Tungsten carbide", 2024-01). resources/data/holders.json
// keeps both sources (MAKEITFROM_WC, WIKIPEDIA_WC). The command line's and the dock's default.
inline constexpr double kCarbideModulus_N_mm2 = 630000.0;

struct BallEndToolStructure {
    double overhang_mm = 0.0;               // L: from where the holder grips the tool to its tip
    double equivalentDiameter_mm = 0.0;     // of the cylinder that stands for the fluted tool
    double youngsModulus_N_mm2 = 0.0;       // of the tool's material
    double holderStiffness_N_mm = 0.0;      // k
    double holderRotational_N_mm_rad = 0.0; // k_θ
};

// The lateral displacement at v_k from the holder per newton at v_m from it (001 table 3):
// v_k² (3 v_m − v_k) / 6EI for v_m ≥ v_k, v_m² (3 v_k − v_m) / 6EI otherwise, plus 1 / k and
// v_m v_k / k_θ.
[[nodiscard]] double lateralCompliance_mm_N(const BallEndToolStructure &tool, double forceFromHolder_mm,
                                            double pointFromHolder_mm);

// The axial displacement per newton, L / EA (001 table 3).
[[nodiscard]] double axialCompliance_mm_N(const BallEndToolStructure &tool);

// The height from the tip, along the tool axis, of the point that generates the surface: the
// ball's lowest point along N, R_o (1 − cos θ) with θ the inclination of the axis.
[[nodiscard]] double surfaceGenerationHeight_mm(const BallEndMill &mill, const BallEndCut &cut);

struct BallEndDeflectionSample {
    double rotation_rad = 0.0;
    Eigen::Vector3d toolFrame_mm = Eigen::Vector3d::Zero();      // δx, δy, δz at the generating point
    Eigen::Vector3d workpieceFrame_mm = Eigen::Vector3d::Zero(); // in F, C, N

    [[nodiscard]] double surfaceNormal_mm() const { return workpieceFrame_mm.z(); } // δ_N
};

struct BallEndDeflection {
    std::vector<BallEndForceSample> forces;
    std::vector<BallEndDeflectionSample> deflection;
    // The range of δ_N over a revolution: the surface lies between them (positive: the tool is
    // pushed away from the surface and leaves material).
    double leastSurfaceNormal_mm = 0.0;
    double greatestSurfaceNormal_mm = 0.0;
};

// What is wrong with a tool structure for a mill, one message per field naming its value.
[[nodiscard]] std::vector<std::string> validateToolStructure(const BallEndToolStructure &tool, const BallEndMill &mill);

// The forces and, at every rotation angle, the deflection of the generating point by table 3,
// every element's force applied where it acts (a linear beam: the sum of each force's own
// deflection). Throws std::invalid_argument, naming the value, for what the model does not take.
[[nodiscard]] BallEndDeflection ballEndDeflection(const BallEndMill &mill, const BallEndToolStructure &tool,
                                                  const MillingForceCoefficients &coefficients, const BallEndCut &cut,
                                                  const BallEndResolution &resolution);

// What a result at this cut rests on beyond 001's validity, one sentence each, for the planner to
// see beside it: the tip, where the cutting speed is zero, in the cut (the engaged band reaches it);
// a negative lead, where 001 §5 finds the feed along the axis makes the milling drill and its force
// model fall short of the measured forces; and 001's holder springs (k 6306 N/mm, k_θ 1.656·10⁷
// N·mm/rad, "calibrated for forces under 1000 N", 001 §4) under a larger lateral force.
[[nodiscard]] QStringList ballEndValidityWarnings(const BallEndMill &mill, const BallEndToolStructure &tool,
                                                  const BallEndCut &cut, const BallEndDeflection &deflection);

} // namespace tolturn
