// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/measurements/drive_reading.h"

#include <QCoreApplication>

#include <cmath>
#include <limits>

namespace tolturn {

// Units of eq. 8 and 14. The paper prints ω_s = 2.8 × f_s and f_as = 0.3586 × f_a and states the
// units of neither side. rad/s per Hz is the likely reading of eq. 8: its cuts (table 1: 2.5 and
// 4 m/s on Ø30–50 mm) turn at 100–270 rad/s, i.e. f_s = 36–95 Hz, a usual inverter frequency;
// in rpm per Hz, f_s would be 340–910 Hz. (ω_s = 2π f_s / (pole pairs × belt ratio): 2.8 is
// 2 pole pairs with a 1.12 belt, say.) Eq. 14 fits no usual drive in either mm/min per Hz
// (f_as = 95–510 mm/min at 0.1–0.2 mm/rev would be 265–1420 Hz) or mm/s per Hz (a screw lead per
// pole pair of 0.36 mm); f_a may be an encoder's pulse frequency rather than the current's. The
// networks scale their inputs to the calibration's range, so what matters is only that
// calibration and use convert with the same constant: TolTurn keeps ω_s in rad/s and f_as in
// mm/min and leaves k to the machine.

namespace {

struct DriveReadings {
    Q_DECLARE_TR_FUNCTIONS(DriveReadings)
};

// The fields of a reading, as JSON keys and in messages.
struct Field {
    const char *name;
    double DriveReading::*member;
};

constexpr Field kFields[] = {{"spindle_current_A", &DriveReading::spindleCurrent_A},
                             {"spindle_idle_current_A", &DriveReading::spindleIdleCurrent_A},
                             {"spindle_friction_current_A", &DriveReading::spindleFrictionCurrent_A},
                             {"spindle_speed_rad_s", &DriveReading::spindleSpeed_rad_s},
                             {"spindle_acceleration_rad_s2", &DriveReading::spindleAcceleration_rad_s2},
                             {"feed_current_A", &DriveReading::feedCurrent_A},
                             {"feed_idle_current_A", &DriveReading::feedIdleCurrent_A},
                             {"feed_speed_mm_min", &DriveReading::feedSpeed_mm_min}};

} // namespace

double equivalentDcCurrent_A(double iU, double iV, double iW)
{
    for (const double i : {iU, iV, iW}) {
        if (!std::isfinite(i) || i < 0.0)
            return std::numeric_limits<double>::quiet_NaN();
    }
    return std::sqrt((iU * iU + iV * iV + iW * iW) / 3.0); // eq. 9
}

double spindleSpeedFromFrequency_rad_s(double frequency_Hz, double speedPerHz)
{
    return speedPerHz * frequency_Hz; // eq. 8: ω_s = k f_s
}

double feedSpeedFromFrequency_mm_min(double frequency_Hz, double speedPerHz)
{
    return speedPerHz * frequency_Hz; // eq. 14: f_as = k f_a
}

void DriveReading::setSpindlePhaseCurrents_A(double iU, double iV, double iW)
{
    spindleCurrent_A = equivalentDcCurrent_A(iU, iV, iW); // eq. 9
}

void DriveReading::setFeedPhaseCurrents_A(double iU, double iV, double iW)
{
    feedCurrent_A = equivalentDcCurrent_A(iU, iV, iW); // eq. 9
}

double DriveReading::spindleCuttingCurrent_A() const
{
    return spindleCurrent_A - spindleIdleCurrent_A - spindleFrictionCurrent_A; // eq. 10
}

double DriveReading::feedCuttingCurrent_A() const
{
    return feedCurrent_A - feedIdleCurrent_A; // I_a = I_a0 + ΔI_a (§3.3.2)
}

Eigen::VectorXd DriveReading::tangentialInputs() const
{
    Eigen::VectorXd x(kTangentialInputs);
    x << spindleCuttingCurrent_A(), spindleSpeed_rad_s, spindleAcceleration_rad_s2; // eq. 11
    return x;
}

Eigen::VectorXd DriveReading::axialInputs() const
{
    Eigen::VectorXd x(kAxialInputs);
    x << feedCuttingCurrent_A(), feedSpeed_mm_min; // eq. 13
    return x;
}

Diagnostics validateDriveReading(const DriveReading &d, const QString &prefix)
{
    Diagnostics out;
    const auto field = [&prefix](const char *name) -> QString {
        return prefix + QLatin1Char('.') + QLatin1String(name);
    };

    struct Value {
        const char *name;
        double value;
        bool nonNegative; // a current (RMS) or a feed speed (from a frequency, eq. 14)
    };

    const Value values[] = {{"spindle_current_A", d.spindleCurrent_A, true},
                            {"spindle_idle_current_A", d.spindleIdleCurrent_A, true},
                            {"spindle_friction_current_A", d.spindleFrictionCurrent_A, true},
                            {"spindle_speed_rad_s", d.spindleSpeed_rad_s, false},
                            {"spindle_acceleration_rad_s2", d.spindleAcceleration_rad_s2, false},
                            {"feed_current_A", d.feedCurrent_A, true},
                            {"feed_idle_current_A", d.feedIdleCurrent_A, true},
                            {"feed_speed_mm_min", d.feedSpeed_mm_min, true}};
    bool finite = true;
    for (const Value &v : values) {
        if (!std::isfinite(v.value)) {
            finite = false;
            out.push_back(
                makeError(field(v.name), DriveReadings::tr("%1 is not a finite number (a current from three phases is "
                                                           "not, when a phase is negative or not finite)")
                                             .arg(QLatin1String(v.name))));
        } else if (v.nonNegative && v.value < 0.0) {
            out.push_back(
                makeError(field(v.name),
                          DriveReadings::tr("%1 = %2 is negative").arg(QLatin1String(v.name), formatNumber(v.value))));
        }
    }
    if (!finite)
        return out;
    if (!(d.spindleSpeed_rad_s > 0.0))
        out.push_back(makeError(field("spindle_speed_rad_s"),
                                DriveReadings::tr("the spindle speed ω_s = %1 rad/s is not above zero: no cut")
                                    .arg(formatNumber(d.spindleSpeed_rad_s))));
    // ΔI_s = I_s − I_s0 − ΔI_sf (eq. 10) and ΔI_a = I_a − I_a0 are the currents due to cutting.
    if (d.spindleCuttingCurrent_A() < 0.0)
        out.push_back(makeError(
            field("spindle_current_A"),
            DriveReadings::tr("the spindle current I_s = %1 A is below its idle current I_s0 = %2 A plus friction "
                              "current ΔI_sf = %3 A, so the cutting current ΔI_s (eq. 10) would be negative: "
                              "measure the idle and friction currents again at this speed")
                .arg(formatNumber(d.spindleCurrent_A), formatNumber(d.spindleIdleCurrent_A),
                     formatNumber(d.spindleFrictionCurrent_A))));
    if (d.feedCuttingCurrent_A() < 0.0)
        out.push_back(makeError(
            field("feed_current_A"),
            DriveReadings::tr("the feed current I_a = %1 A is below its idle current I_a0 = %2 A, so the cutting "
                              "current ΔI_a would be negative: measure the idle current again at this feed speed")
                .arg(formatNumber(d.feedCurrent_A), formatNumber(d.feedIdleCurrent_A))));
    return out;
}

QJsonObject driveReadingJson(const DriveReading &drive)
{
    QJsonObject o;
    for (const Field &f : kFields)
        o.insert(QLatin1String(f.name), drive.*f.member);
    return o;
}

std::optional<DriveReading> driveReadingFromJson(const QJsonObject &json, QString *error)
{
    DriveReading d;
    for (const Field &f : kFields) {
        const QJsonValue v = json.value(QLatin1String(f.name));
        if (!v.isDouble()) {
            if (error)
                *error = DriveReadings::tr("the drive reading lacks the number \"%1\"").arg(QLatin1String(f.name));
            return std::nullopt;
        }
        d.*f.member = v.toDouble();
    }
    return d;
}

} // namespace tolturn
