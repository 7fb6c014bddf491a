// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"

#include <Eigen/Dense>
#include <QJsonObject>
#include <QString>

#include <optional>

namespace tolturn {

// What the spindle and feed drives read during a cut, for Li & Du's estimate of the cutting forces
// from the motor currents (X. Li, R. Du, Int. J. Prod. Res. 40(7) (2002) 1647–1667, §3.3,
// eq. 7–14; core/learning/current_forces.h). A measured part may carry the readings of its
// finishing cut (docs/learning.md).

// Equivalent DC current of a three-phase AC servo motor (eq. 9): I = sqrt((I_U² + I_V² + I_W²) / 3),
// from the three phases' RMS currents [A]. NaN when a phase is negative or not finite (an RMS
// value is neither), so that the reading it goes into is refused.
[[nodiscard]] double equivalentDcCurrent_A(double iU, double iV, double iW);

// The paper's conversion constants from the frequency of the motor current to the speeds, eq. 8
// (ω_s = 2.8 f_s) and eq. 14 (f_as = 0.3586 f_a). They are constants of ITS lathe (a HITEC TURN
// 20SII, Li 2001): pole pairs, belt and gear ratios, ball-screw lead. They are not universal, and
// the paper states the units of neither side (see the .cpp). Measure your own machine's.
inline constexpr double kLiDuSpindleSpeedPerHz = 2.8; // the paper's lathe: ω_s per Hz of f_s
inline constexpr double kLiDuFeedSpeedPerHz = 0.3586; // the paper's lathe: f_as per Hz of f_a

// Eq. 8: ω_s = k·f_s, the spindle speed [rad/s] from the frequency f_s [Hz] of one phase of the
// spindle motor's current; k [rad/s per Hz] is the machine's.
[[nodiscard]] double spindleSpeedFromFrequency_rad_s(double frequency_Hz, double speedPerHz);
// Eq. 14: f_as = k·f_a, the axial feed speed [mm/min] from the feed motor's frequency f_a [Hz];
// k [mm/min per Hz] is the machine's.
[[nodiscard]] double feedSpeedFromFrequency_mm_min(double frequency_Hz, double speedPerHz);

// What the two drives read during a cut (currents as DC-equivalent values, eq. 9 for AC drives).
struct DriveReading {
    // Spindle drive (§3.3.1).
    double spindleCurrent_A = 0.0;           // I_s
    double spindleIdleCurrent_A = 0.0;       // I_s0, measured without cutting (eq. 10)
    double spindleFrictionCurrent_A = 0.0;   // ΔI_sf, measured without cutting (eq. 10)
    double spindleSpeed_rad_s = 0.0;         // ω_s (eq. 8)
    double spindleAcceleration_rad_s2 = 0.0; // ω̇_s
    // Axial feed drive (§3.3.2).
    double feedCurrent_A = 0.0;     // I_a
    double feedIdleCurrent_A = 0.0; // I_a0, measured before cutting
    double feedSpeed_mm_min = 0.0;  // f_as (eq. 14)

    // I_s from the spindle motor's three phase RMS currents (eq. 9).
    void setSpindlePhaseCurrents_A(double iU, double iV, double iW);
    // I_a from the feed motor's three phase RMS currents (eq. 9, for an AC feed servo as well).
    void setFeedPhaseCurrents_A(double iU, double iV, double iW);

    // ΔI_s = I_s − I_s0 − ΔI_sf, the current due to cutting (eq. 10).
    [[nodiscard]] double spindleCuttingCurrent_A() const;
    // ΔI_a = I_a − I_a0, the cutting current of the feed drive (§3.3.2, below eq. 12).
    [[nodiscard]] double feedCuttingCurrent_A() const;
    // The networks' inputs: (ΔI_s, ω_s, ω̇_s) of eq. 11 and (ΔI_a, f_as) of eq. 13.
    static constexpr Eigen::Index kTangentialInputs = 3;
    static constexpr Eigen::Index kAxialInputs = 2;
    [[nodiscard]] Eigen::VectorXd tangentialInputs() const;
    [[nodiscard]] Eigen::VectorXd axialInputs() const;

    friend bool operator==(const DriveReading &, const DriveReading &) = default;
};

// Errors, each naming its field under `prefix` (e.g. "drive.spindle_current_A"): a value not
// finite; a current, idle current, friction current or feed speed below zero; a spindle speed not
// above zero; a current below its idle (plus friction) current, i.e. ΔI_s < 0 or ΔI_a < 0.
[[nodiscard]] Diagnostics validateDriveReading(const DriveReading &drive, const QString &prefix);

// The reading as JSON (the store's drive_json, `measurements add --drive FILE.json`), its keys the
// field names of validateDriveReading ("spindle_current_A", …); back, empty with `error` naming a
// missing or non-numeric key.
[[nodiscard]] QJsonObject driveReadingJson(const DriveReading &drive);
[[nodiscard]] std::optional<DriveReading> driveReadingFromJson(const QJsonObject &json, QString *error);

} // namespace tolturn
