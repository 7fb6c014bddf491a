// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/cutting/cutting_forces.h"
#include "core/learning/hybrid_rbf.h"
#include "core/measurements/drive_reading.h"

#include <Eigen/Dense>
#include <QJsonObject>
#include <QString>

#include <numbers>
#include <optional>
#include <vector>

namespace tolturn {

// The first stage of Li & Du's two-stage network: the cutting forces estimated from the spindle
// and feed motor currents instead of a dynamometer (X. Li, R. Du, "Analysis and compensation of
// workpiece errors in turning", Int. J. Prod. Res. 40(7) (2002) 1647–1667, §3.3, eq. 7–20).
// F_t from the spindle drive by one hybrid RBF network (eq. 11), F_a from the axial feed drive by
// another (eq. 13), F_r from the oblique model (eq. 15–19): K_n and K_f solved from F_t and F_a
// (eq. 17, 18), then eq. 19.

// One calibration cut: both the motor currents and the dynamometer's forces (§3.4: "during the
// training, both the motor currents and the cutting forces are needed").
struct ForceCalibrationSample {
    DriveReading drive;
    double tangential_N = 0.0; // F_t measured
    double axial_N = 0.0;      // F_a measured
};

// The fewest calibration cuts accepted. A floor, not enough: below it the spindle network's three
// inputs cannot each vary around a centre (the paper trained on 21 cuts).
inline constexpr int kMinForceCalibrationSamples = 6;

// Tool angles of the oblique model (eq. 17–20).
struct ToolAngles {
    double normalRake_rad = 0.0; // α
    double backRake_rad = 0.0;   // α_b
    // κ_r, the holder's entering angle. The paper's lead angle is γ_L = 90° − κ_r (its fig. 10:
    // γ_L = −3° is a 93° holder), as LiDuToolGeometry::leadAngle_rad.
    double enteringAngle_rad = 0.5 * std::numbers::pi;
};

// K_n, K_f from one pair (F_t, F_a) by eq. 17 and 18 in closed form, and F_r by eq. 19.
struct LiDuInversion {
    LiDuCoefficients coefficients; // K_n [N/mm²], K_f [-]
    double radial_N = 0.0;         // F_r (eq. 19)
};

// Empty, with `error` set, when an input is not finite, the uncut chip area is not positive, the
// 2 × 2 system of eq. 17–18 is singular (|det| < 1e-9, e.g. α_b = ±90°), or K_n ≤ 0.
[[nodiscard]] std::optional<LiDuInversion> solveLiDuCoefficients(double tangential_N, double axial_N,
                                                                 double uncutChipArea_mm2, double backRake_rad,
                                                                 double normalRake_rad, double effectiveLeadAngle_rad,
                                                                 QString *error);

struct CuttingForceEstimate {
    std::optional<CuttingForces> forces; // absent when `diagnostics` holds an error
    std::optional<LiDuCoefficients> coefficients;
    double uncutChipArea_mm2 = 0.0;      // A_c (eq. 16a/16b)
    double effectiveLeadAngle_rad = 0.0; // γ_Le (eq. 20)
    // Errors (bad inputs, eq. 17–18 not solvable) and warnings (a reading outside the calibration's
    // range, where the networks extrapolate; eq. 20 outside its stated ranges).
    Diagnostics diagnostics;
};

// The two networks of the first stage.
struct CurrentForceModel {
    RbfNetwork tangential; // F_t = F(ΔI_s, ω_s, ω̇_s), eq. 11
    RbfNetwork axial;      // F_a = F(ΔI_a, f_as), eq. 13
    // The largest value of each input in the calibration (the smallest is the network's
    // inputMin): a reading outside the range gets a warning.
    Eigen::VectorXd tangentialInputMax; // 3
    Eigen::VectorXd axialInputMax;      // 2
    int samples = 0;                    // calibration cuts

    // F_t, F_a from the networks; A_c (eq. 16), γ_Le (eq. 20, γ_Le = γ_L for r_n = 0), K_n and K_f
    // (eq. 17–18) and F_r (eq. 19).
    [[nodiscard]] CuttingForceEstimate estimate(const DriveReading &drive, const ToolAngles &tool, double feed_mm_rev,
                                                double depth_mm, double noseRadius_mm) const;
};

// The training options for the current–force networks: the defaults with the radius scales
// extended to 8, 16 and 32 (of the tree nodes' half-widths). The forces are nearly linear in the
// currents (eq. 7 and 12 are linear in I_s and I_a), a trend that wide Gaussians follow with few
// nodes and narrow ones only poorly (held-out error about twice the noise in tst_current_forces
// with the default scales 1, 2, 4).
[[nodiscard]] RbfTrainingOptions currentForceTrainingOptions();

// Trains both networks on the calibration cuts. Empty, with `error` naming the sample and field,
// when there are fewer than kMinForceCalibrationSamples, a drive reading is refused by
// validateDriveReading, a force is not finite, or a network cannot be trained.
[[nodiscard]] std::optional<CurrentForceModel>
trainCurrentForceModel(const std::vector<ForceCalibrationSample> &samples, const RbfTrainingOptions &options,
                       QString *error);

// As JSON: {"samples", "tangential": {"inputs", "input_max", "network"}, "axial": {…}}, each
// network with the fields of learnedResidualJson's (its RMS values in newtons: "training_rms_N",
// "leave_one_out_rms_N"); and back, empty with `error` naming the field when a value is missing,
// not finite or of the wrong size, or the inputs are not the ones named here.
// Calibration cuts from a CSV file (docs/learning.md): the columns spindle_current_A,
// spindle_idle_current_A, spindle_friction_current_A, spindle_speed_rad_s,
// spindle_acceleration_rad_s2, feed_current_A, feed_idle_current_A, feed_speed_mm_min (the
// DriveReading) and tangential_N, axial_N (the dynamometer's); every bad cell named by line and
// column, nullopt on any error.
[[nodiscard]] std::optional<std::vector<ForceCalibrationSample>> readForceCalibration(const QString &path,
                                                                                      Diagnostics &out);

[[nodiscard]] QJsonObject currentForceModelJson(const CurrentForceModel &model);
[[nodiscard]] std::optional<CurrentForceModel> currentForceModelFromJson(const QJsonObject &json, QString *error);

} // namespace tolturn
