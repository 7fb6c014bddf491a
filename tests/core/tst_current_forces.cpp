// SPDX-License-Identifier: GPL-3.0-or-later
// The first stage of Li & Du (003, §3.3): cutting forces from the motor currents (eq. 7–14), the
// radial force from the oblique model (eq. 15–20). References are worked by hand here or computed
// with the printed formulas in this file; the networks are trained on data generated from a known
// truth with noise.
#include "tests/core/test_support.h"

#include "core/learning/current_forces.h"

#include <Eigen/Dense>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

using namespace tolturn;

namespace {

double deg(double d)
{
    return d * std::numbers::pi / 180.0;
}

QString show(double a, double b)
{
    return QStringLiteral("%1 vs %2").arg(a, 0, 'g', 17).arg(b, 0, 'g', 17);
}

// Eq. 17–19 as printed.
struct Printed {
    double ft, fa, fr;
};

Printed printedForces(double kn, double kf, double area, double ab, double a, double g)
{
    using std::cos;
    using std::sin;
    return {kn * area * (cos(ab) * cos(a) + kf * (cos(g) * sin(a) + sin(g) * sin(ab))), // eq. 17
            kn * area * (-cos(ab) * sin(a) + kf * cos(g) * cos(a)),                     // eq. 18
            kn * area * (-sin(ab) + kf * sin(g) * cos(ab))};                            // eq. 19
}

// The shop's truth: what the dynamometer would read for given drive readings.
constexpr double kIdleSpindle_A = 4.0;
constexpr double kFrictionSpindle_A = 1.5;
constexpr double kIdleFeed_A = 1.2;
constexpr double kNoiseTangential_N = 5.0;
constexpr double kNoiseAxial_N = 3.0;

// F_t = K_t ΔI_s (1 − 0.02 ω̇_s) − 0.1 ω_s: the torque constant over the radius, less the part of
// the current that accelerates the spindle, less a speed-dependent friction under load.
double truthTangential(const DriveReading &d)
{
    return 60.0 * d.spindleCuttingCurrent_A() * (1.0 - 0.02 * d.spindleAcceleration_rad_s2) -
           0.1 * d.spindleSpeed_rad_s;
}

// F_a = c ΔI_a − b f_as: the cutting current less the feed drive's damping.
double truthAxial(const DriveReading &d)
{
    return 150.0 * d.feedCuttingCurrent_A() - 0.1 * d.feedSpeed_mm_min;
}

DriveReading reading(double dIs, double ws, double dws, double dIa, double fas)
{
    DriveReading d;
    d.spindleIdleCurrent_A = kIdleSpindle_A;
    d.spindleFrictionCurrent_A = kFrictionSpindle_A;
    d.spindleCurrent_A = kIdleSpindle_A + kFrictionSpindle_A + dIs; // eq. 10
    d.spindleSpeed_rad_s = ws;
    d.spindleAcceleration_rad_s2 = dws;
    d.feedIdleCurrent_A = kIdleFeed_A;
    d.feedCurrent_A = kIdleFeed_A + dIa;
    d.feedSpeed_mm_min = fas;
    return d;
}

std::vector<ForceCalibrationSample> calibration(int n, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> noiseT(0.0, kNoiseTangential_N);
    std::normal_distribution<double> noiseA(0.0, kNoiseAxial_N);
    std::vector<ForceCalibrationSample> out;
    for (int i = 0; i < n; ++i) {
        ForceCalibrationSample s;
        s.drive = reading(2.0 + 10.0 * u(random), 100.0 + 200.0 * u(random), -5.0 + 10.0 * u(random),
                          0.5 + 2.5 * u(random), 50.0 + 350.0 * u(random));
        s.tangential_N = truthTangential(s.drive) + noiseT(random);
        s.axial_N = truthAxial(s.drive) + noiseA(random);
        out.push_back(s);
    }
    return out;
}

struct HeldOut {
    double tangentialRms_N = 0.0;
    double axialRms_N = 0.0;
};

// RMS of (estimate − measured) over the samples: the noise's RMS for a perfect model.
HeldOut heldOutRms(const CurrentForceModel &model, const std::vector<ForceCalibrationSample> &samples)
{
    double st = 0.0, sa = 0.0;
    for (const ForceCalibrationSample &s : samples) {
        const double et = model.tangential.predict(s.drive.tangentialInputs()) - s.tangential_N;
        const double ea = model.axial.predict(s.drive.axialInputs()) - s.axial_N;
        st += et * et;
        sa += ea * ea;
    }
    const auto n = static_cast<double>(samples.size());
    return {std::sqrt(st / n), std::sqrt(sa / n)};
}

// Generated calibration cuts. With 240 the held-out RMS of F_t stayed within 1.35 × the noise over
// 14 seeds tried (the bound below is 1.6 ×); with 160 one seed in 12 exceeded it.
constexpr int kTrainingCuts = 240;

// The acceptance bound of the held-out predictions: 1.5 × the noise's RMS plus 0.5 N.
constexpr double kBoundFactor = 1.5;
constexpr double kBoundSlack_N = 0.5;

bool hasErrorAt(const Diagnostics &diagnostics, const QString &field)
{
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [&](const Diagnostic &d) { return d.severity == Severity::Error && d.field == field; });
}

} // namespace

class TestCurrentForces : public QObject {
    Q_OBJECT

    std::vector<ForceCalibrationSample> m_training;
    std::vector<ForceCalibrationSample> m_heldOut;
    CurrentForceModel m_model;

private Q_SLOTS:

    void initTestCase()
    {
        m_training = calibration(kTrainingCuts, 11);
        m_heldOut = calibration(80, 12);
        QString error;
        auto model = trainCurrentForceModel(m_training, currentForceTrainingOptions(), &error);
        QVERIFY2(model, qPrintable(error));
        m_model = std::move(*model);
    }

    // Eq. 9: I_U = 10, I_V = 11, I_W = 12 A: (100 + 121 + 144) / 3 = 121.666…, sqrt = 11.0302614 A.
    void equivalentDcCurrent()
    {
        QVERIFY(test::nearRelative(equivalentDcCurrent_A(10.0, 11.0, 12.0), 11.030261405182864, 1e-14));
        QVERIFY(test::nearRelative(equivalentDcCurrent_A(7.0, 7.0, 7.0), 7.0, 1e-15));
        QCOMPARE(equivalentDcCurrent_A(0.0, 0.0, 0.0), 0.0);
        QVERIFY(std::isnan(equivalentDcCurrent_A(-10.0, 11.0, 12.0)));
        QVERIFY(std::isnan(equivalentDcCurrent_A(10.0, std::nan(""), 12.0)));
        DriveReading d;
        d.setSpindlePhaseCurrents_A(10.0, 11.0, 12.0);
        d.setFeedPhaseCurrents_A(3.0, 4.0, 5.0); // (9 + 16 + 25) / 3 = 16.666…, sqrt = 4.0824829 A
        QVERIFY(test::nearRelative(d.spindleCurrent_A, 11.030261405182864, 1e-14));
        QVERIFY(test::nearRelative(d.feedCurrent_A, 4.0824829046386302, 1e-14));
    }

    // Eq. 10: ΔI_s = 20 − 5 − 2 = 13 A; ΔI_a = 3.5 − 1.25 = 2.25 A. Eq. 8 with the paper's constant:
    // 2.8 × 50 Hz = 140; eq. 14: 0.3586 × 100 Hz = 35.86; another machine's k = 2π/2 → 157.08 rad/s.
    void cuttingCurrentsAndSpeeds()
    {
        DriveReading d;
        d.spindleCurrent_A = 20.0;
        d.spindleIdleCurrent_A = 5.0;
        d.spindleFrictionCurrent_A = 2.0;
        d.feedCurrent_A = 3.5;
        d.feedIdleCurrent_A = 1.25;
        QCOMPARE(d.spindleCuttingCurrent_A(), 13.0);
        QCOMPARE(d.feedCuttingCurrent_A(), 2.25);
        d.spindleSpeed_rad_s = 150.0;
        d.spindleAcceleration_rad_s2 = -2.0;
        d.feedSpeed_mm_min = 120.0;
        const Eigen::VectorXd t = d.tangentialInputs();
        const Eigen::VectorXd a = d.axialInputs();
        QCOMPARE(t.size(), Eigen::Index(3));
        QCOMPARE(a.size(), Eigen::Index(2));
        QCOMPARE(t[0], 13.0);
        QCOMPARE(t[1], 150.0);
        QCOMPARE(t[2], -2.0);
        QCOMPARE(a[0], 2.25);
        QCOMPARE(a[1], 120.0);
        QVERIFY(test::nearRelative(spindleSpeedFromFrequency_rad_s(50.0, kLiDuSpindleSpeedPerHz), 140.0, 1e-15));
        QVERIFY(test::nearRelative(feedSpeedFromFrequency_mm_min(100.0, kLiDuFeedSpeedPerHz), 35.86, 1e-15));
        QVERIFY(test::nearRelative(spindleSpeedFromFrequency_rad_s(50.0, std::numbers::pi), 157.07963267948966, 1e-15));
        QVERIFY(validateDriveReading(d, QStringLiteral("drive")).empty());
    }

    // Eq. 17–18 inverted: forces from hand-picked K_n, K_f and angles by the printed eq. 17–19;
    // the solver must give K_n, K_f and F_r back.
    void inversion_data()
    {
        QTest::addColumn<double>("kn");
        QTest::addColumn<double>("kf");
        QTest::addColumn<double>("area");
        QTest::addColumn<double>("backRake");
        QTest::addColumn<double>("normalRake");
        QTest::addColumn<double>("lead");
        // The paper's fig. 10 tool (α_b = −7°, α = −3.5°) at γ_Le = 25°, A_c of f 0.2, d 1, r_n 0.8.
        QTest::newRow("fig10") << 2100.0 << 0.6 << 0.19937253933193771 << deg(-7.0) << deg(-3.5) << deg(25.0);
        QTest::newRow("positive rakes") << 1500.0 << 0.9 << 0.05 << deg(5.0) << deg(10.0) << deg(-3.0);
        QTest::newRow("zero rakes") << 900.0 << 0.3 << 0.2 << 0.0 << 0.0 << deg(40.0);
        QTest::newRow("steep lead") << 3000.0 << 1.2 << 0.4 << deg(-15.0) << deg(6.0) << deg(60.0);
    }

    void inversion()
    {
        QFETCH(double, kn);
        QFETCH(double, kf);
        QFETCH(double, area);
        QFETCH(double, backRake);
        QFETCH(double, normalRake);
        QFETCH(double, lead);
        const Printed f = printedForces(kn, kf, area, backRake, normalRake, lead);
        QString error;
        const auto r = solveLiDuCoefficients(f.ft, f.fa, area, backRake, normalRake, lead, &error);
        QVERIFY2(r, qPrintable(error));
        QVERIFY2(test::nearRelative(r->coefficients.normalPressure_MPa, kn, 1e-9),
                 qPrintable(show(r->coefficients.normalPressure_MPa, kn)));
        QVERIFY2(test::nearRelative(r->coefficients.frictionRatio, kf, 1e-9),
                 qPrintable(show(r->coefficients.frictionRatio, kf)));
        QVERIFY2(test::nearRelative(r->radial_N, f.fr, 1e-9), qPrintable(show(r->radial_N, f.fr)));
    }

    // With zero rakes eq. 17–19 reduce to F_t = K_n A, F_a = K_n K_f A cos γ, F_r = K_n K_f A sin γ:
    // K_n = 900, K_f = 0.3, A = 0.2, γ = 40°: F_t = 180 N, F_a = 54 cos 40° = 41.3664 N,
    // F_r = 54 sin 40° = 34.7105309 N.
    void inversionByHand()
    {
        QString error;
        const auto r = solveLiDuCoefficients(180.0, 54.0 * std::cos(deg(40.0)), 0.2, 0.0, 0.0, deg(40.0), &error);
        QVERIFY2(r, qPrintable(error));
        QVERIFY(test::nearRelative(r->coefficients.normalPressure_MPa, 900.0, 1e-12));
        QVERIFY(test::nearRelative(r->coefficients.frictionRatio, 0.3, 1e-12));
        QVERIFY(test::nearRelative(r->radial_N, 34.7105309, 1e-8));
    }

    // α_b = 90°: cos α_b = 0 makes eq. 17 and 18 dependent. Forces that need K_n ≤ 0 are refused.
    void inversionRefused()
    {
        QString error;
        QVERIFY(!solveLiDuCoefficients(100.0, 50.0, 0.2, deg(90.0), deg(5.0), deg(20.0), &error));
        QVERIFY2(error.contains(QStringLiteral("do not determine")), qPrintable(error));
        error.clear();
        QVERIFY(!solveLiDuCoefficients(-100.0, 50.0, 0.2, deg(-7.0), deg(-3.5), deg(20.0), &error));
        QVERIFY2(error.contains(QStringLiteral("not positive")), qPrintable(error));
        error.clear();
        QVERIFY(!solveLiDuCoefficients(100.0, 50.0, 0.0, deg(-7.0), deg(-3.5), deg(20.0), &error));
        QVERIFY2(error.contains(QStringLiteral("uncut chip area")), qPrintable(error));
        error.clear();
        QVERIFY(!solveLiDuCoefficients(std::nan(""), 50.0, 0.2, deg(-7.0), deg(-3.5), deg(20.0), &error));
        QVERIFY(!error.isEmpty());
    }

    // The whole estimate with the fig. 10 tool (γ_L = −3°: κ_r = 93°), f = 0.2, d = 1, r_n = 0.8:
    // eq. 16a: A_c = 0.2 − 0.2 (0.8 − sqrt(0.64 − 0.01)) / 2 = 0.199372539 mm²;
    // eq. 20: tan γ_Le = 0.5053 tan(−3°) + 1.0473 × 0.25 + 0.4654 × 0.8 = 0.607663, γ_Le = 31.2825°.
    // F_r by solving the printed eq. 17–18 numerically (not by the closed form) and eq. 19.
    void estimateWholeChain()
    {
        const ToolAngles tool{deg(-3.5), deg(-7.0), deg(93.0)};
        const DriveReading d = reading(7.0, 200.0, 0.5, 1.5, 200.0);
        const CuttingForceEstimate e = m_model.estimate(d, tool, 0.2, 1.0, 0.8);
        QVERIFY2(e.diagnostics.empty(), qPrintable(e.diagnostics.empty() ? QString() : e.diagnostics[0].toString()));
        QVERIFY(e.forces && e.coefficients);
        QVERIFY(test::nearRelative(e.uncutChipArea_mm2, 0.19937253933193771, 1e-14));
        const double tanLe = 0.5053 * std::tan(deg(-3.0)) + 1.0473 * 0.2 / 0.8 + 0.4654 * 0.8 / 1.0;
        QVERIFY(test::nearRelative(tanLe, 0.607663, 1e-5));
        QVERIFY2(test::nearRelative(e.effectiveLeadAngle_rad, std::atan(tanLe), 1e-12),
                 qPrintable(show(e.effectiveLeadAngle_rad, std::atan(tanLe))));
        // F_t, F_a: the networks, near the truth.
        QCOMPARE(e.forces->tangential_N, m_model.tangential.predict(d.tangentialInputs()));
        QCOMPARE(e.forces->axial_N, m_model.axial.predict(d.axialInputs()));
        QVERIFY(std::abs(e.forces->tangential_N - truthTangential(d)) < 3.0 * kNoiseTangential_N);
        QVERIFY(std::abs(e.forces->axial_N - truthAxial(d)) < 3.0 * kNoiseAxial_N);
        // (p, q) = (K_n A_c, K_n K_f A_c) from the printed equations as a 2 × 2 system.
        const double ab = deg(-7.0), a = deg(-3.5), g = std::atan(tanLe);
        Eigen::Matrix2d m;
        m << std::cos(ab) * std::cos(a), std::cos(g) * std::sin(a) + std::sin(g) * std::sin(ab),
            -std::cos(ab) * std::sin(a), std::cos(g) * std::cos(a);
        const Eigen::Vector2d pq = m.fullPivLu().solve(Eigen::Vector2d(e.forces->tangential_N, e.forces->axial_N));
        const double kn = pq[0] / e.uncutChipArea_mm2;
        const double kf = pq[1] / pq[0];
        const double fr = kn * e.uncutChipArea_mm2 * (-std::sin(ab) + kf * std::sin(g) * std::cos(ab)); // eq. 19
        QVERIFY2(test::nearRelative(e.coefficients->normalPressure_MPa, kn, 1e-9),
                 qPrintable(show(e.coefficients->normalPressure_MPa, kn)));
        QVERIFY2(test::nearRelative(e.coefficients->frictionRatio, kf, 1e-9),
                 qPrintable(show(e.coefficients->frictionRatio, kf)));
        QVERIFY2(test::nearRelative(e.forces->radial_N, fr, 1e-9), qPrintable(show(e.forces->radial_N, fr)));
        QVERIFY(e.forces->radial_N > 0.0);
    }

    // Eq. 16b (r_n < f/2): A_c = f d = 0.2 × 1 = 0.2 mm²; without a nose radius eq. 20 is not
    // defined and γ_Le = γ_L = 90° − 93° = −3°. Eq. 16a at f = 0.1, d = 0.5, r_n = 0.4:
    // 0.05 − 0.1 (0.4 − sqrt(0.16 − 0.0025)) / 2 = 0.0498431348 mm².
    void estimateChipAreaAndLead()
    {
        const ToolAngles tool{deg(-3.5), deg(-7.0), deg(93.0)};
        const DriveReading d = reading(7.0, 200.0, 0.5, 1.5, 200.0);
        const CuttingForceEstimate sharp = m_model.estimate(d, tool, 0.2, 1.0, 0.0);
        QVERIFY(sharp.forces);
        QCOMPARE(sharp.uncutChipArea_mm2, 0.2);
        QVERIFY(test::nearRelative(sharp.effectiveLeadAngle_rad, deg(-3.0), 1e-12));
        const CuttingForceEstimate small = m_model.estimate(d, tool, 0.2, 1.0, 0.05); // r_n < f/2
        QCOMPARE(small.uncutChipArea_mm2, 0.2);
        const CuttingForceEstimate fine = m_model.estimate(d, tool, 0.1, 0.5, 0.4);
        QVERIFY(test::nearRelative(fine.uncutChipArea_mm2, 0.04984313483298443, 1e-13));
    }

    // F_r depends on F_t, F_a and the angles only (p = K_n A_c and q = K_n K_f A_c are fixed by the
    // forces): a quarter of the chip area gives four times K_n, the same K_f and the same F_r.
    void inversionAreaCancels()
    {
        QString error;
        const auto a = solveLiDuCoefficients(400.0, 150.0, 0.2, deg(-7.0), deg(-3.5), deg(30.0), &error);
        const auto b = solveLiDuCoefficients(400.0, 150.0, 0.05, deg(-7.0), deg(-3.5), deg(30.0), &error);
        QVERIFY(a && b);
        QVERIFY(
            test::nearRelative(b->coefficients.normalPressure_MPa, 4.0 * a->coefficients.normalPressure_MPa, 1e-14));
        QVERIFY(test::nearRelative(b->coefficients.frictionRatio, a->coefficients.frictionRatio, 1e-14));
        QVERIFY(test::nearRelative(b->radial_N, a->radial_N, 1e-14));
    }

    // Held-out cuts of the same truth are predicted within 1.5 × the noise's RMS (+ 0.5 N), and a
    // model trained on shuffled forces is not: the bound can fail.
    void trainingPredictsHeldOut()
    {
        const HeldOut good = heldOutRms(m_model, m_heldOut);
        qInfo("held out: F_t RMS %.3f N (noise %.1f), F_a RMS %.3f N (noise %.1f); nodes %d and %d",
              good.tangentialRms_N, kNoiseTangential_N, good.axialRms_N, kNoiseAxial_N, m_model.tangential.nodes(),
              m_model.axial.nodes());
        QVERIFY(good.tangentialRms_N <= kBoundFactor * kNoiseTangential_N + kBoundSlack_N);
        QVERIFY(good.axialRms_N <= kBoundFactor * kNoiseAxial_N + kBoundSlack_N);
        QCOMPARE(m_model.samples, kTrainingCuts);

        std::vector<ForceCalibrationSample> shuffled = m_training;
        std::mt19937 random(5);
        std::vector<double> ft, fa;
        for (const ForceCalibrationSample &s : shuffled) {
            ft.push_back(s.tangential_N);
            fa.push_back(s.axial_N);
        }
        std::shuffle(ft.begin(), ft.end(), random);
        std::shuffle(fa.begin(), fa.end(), random);
        for (std::size_t i = 0; i < shuffled.size(); ++i) {
            shuffled[i].tangential_N = ft[i];
            shuffled[i].axial_N = fa[i];
        }
        QString error;
        const auto wrong = trainCurrentForceModel(shuffled, currentForceTrainingOptions(), &error);
        QVERIFY2(wrong, qPrintable(error));
        const HeldOut bad = heldOutRms(*wrong, m_heldOut);
        qInfo("shuffled: F_t RMS %.1f N, F_a RMS %.1f N", bad.tangentialRms_N, bad.axialRms_N);
        QVERIFY(bad.tangentialRms_N > kBoundFactor * kNoiseTangential_N + kBoundSlack_N);
        QVERIFY(bad.axialRms_N > kBoundFactor * kNoiseAxial_N + kBoundSlack_N);
    }

    void badInputs()
    {
        const ToolAngles tool{deg(-3.5), deg(-7.0), deg(93.0)};
        // A spindle current below idle + friction: ΔI_s < 0 (eq. 10).
        DriveReading below = reading(7.0, 200.0, 0.0, 1.5, 200.0);
        below.spindleCurrent_A = kIdleSpindle_A + 1.0; // below 4 + 1.5
        CuttingForceEstimate e = m_model.estimate(below, tool, 0.2, 1.0, 0.8);
        QVERIFY(!e.forces);
        QVERIFY(hasErrorAt(e.diagnostics, QStringLiteral("drive.spindle_current_A")));
        // A feed current below idle.
        DriveReading feedBelow = reading(7.0, 200.0, 0.0, 1.5, 200.0);
        feedBelow.feedCurrent_A = 0.5;
        QVERIFY(hasErrorAt(validateDriveReading(feedBelow, QStringLiteral("drive")),
                           QStringLiteral("drive.feed_current_A")));
        // Not a number; a phase current negative; the spindle standing; a negative idle current.
        DriveReading nan = reading(7.0, 200.0, 0.0, 1.5, 200.0);
        nan.feedSpeed_mm_min = std::nan("");
        e = m_model.estimate(nan, tool, 0.2, 1.0, 0.8);
        QVERIFY(!e.forces);
        QVERIFY(hasErrorAt(e.diagnostics, QStringLiteral("drive.feed_speed_mm_min")));
        DriveReading phase = reading(7.0, 200.0, 0.0, 1.5, 200.0);
        phase.setSpindlePhaseCurrents_A(12.0, -12.0, 12.0);
        QVERIFY(hasErrorAt(validateDriveReading(phase, QStringLiteral("drive")),
                           QStringLiteral("drive.spindle_current_A")));
        DriveReading standing = reading(7.0, 0.0, 0.0, 1.5, 200.0);
        QVERIFY(hasErrorAt(validateDriveReading(standing, QStringLiteral("drive")),
                           QStringLiteral("drive.spindle_speed_rad_s")));
        DriveReading negativeIdle = reading(7.0, 200.0, 0.0, 1.5, 200.0);
        negativeIdle.feedIdleCurrent_A = -1.0;
        QVERIFY(hasErrorAt(validateDriveReading(negativeIdle, QStringLiteral("drive")),
                           QStringLiteral("drive.feed_idle_current_A")));
        // Cut and tool.
        const DriveReading good = reading(7.0, 200.0, 0.0, 1.5, 200.0);
        QVERIFY(hasErrorAt(m_model.estimate(good, tool, 0.0, 1.0, 0.8).diagnostics, QStringLiteral("feed_mm_rev")));
        QVERIFY(
            hasErrorAt(m_model.estimate(good, tool, 0.2, -1.0, 0.8).diagnostics, QStringLiteral("depth_of_cut_mm")));
        QVERIFY(hasErrorAt(m_model.estimate(good, tool, 0.2, 1.0, -0.8).diagnostics,
                           QStringLiteral("tool.nose_radius_mm")));
        QVERIFY(
            hasErrorAt(m_model.estimate(good, ToolAngles{deg(-3.5), deg(95.0), deg(93.0)}, 0.2, 1.0, 0.8).diagnostics,
                       QStringLiteral("tool.back_rake")));
        QVERIFY(
            hasErrorAt(CurrentForceModel{}.estimate(good, tool, 0.2, 1.0, 0.8).diagnostics, QStringLiteral("model")));
        // A reading just outside the calibration's range (ΔI_s = 12.5 A, calibrated to 12 A): forces,
        // with a warning naming the input.
        e = m_model.estimate(reading(12.5, 200.0, 0.0, 1.5, 200.0), tool, 0.2, 1.0, 0.8);
        QVERIFY(e.forces);
        QCOMPARE(e.diagnostics.size(), std::size_t(1));
        QCOMPARE(e.diagnostics[0].severity, Severity::Warning);
        QCOMPARE(e.diagnostics[0].field, QStringLiteral("drive.spindle_cutting_current_A"));

        // Training: too few cuts, a cut below idle, a force not a number.
        QString error;
        std::vector<ForceCalibrationSample> few(m_training.begin(), m_training.begin() + 5);
        QVERIFY(!trainCurrentForceModel(few, RbfTrainingOptions{}, &error));
        QVERIFY2(error.startsWith(QStringLiteral("samples:")), qPrintable(error));
        std::vector<ForceCalibrationSample> some(m_training.begin(), m_training.begin() + 20);
        some[2].drive.spindleCurrent_A = 1.0;
        QVERIFY(!trainCurrentForceModel(some, RbfTrainingOptions{}, &error));
        QVERIFY2(error.startsWith(QStringLiteral("samples[2].drive.spindle_current_A:")), qPrintable(error));
        some[2] = m_training[2];
        some[7].axial_N = std::numeric_limits<double>::infinity();
        QVERIFY(!trainCurrentForceModel(some, RbfTrainingOptions{}, &error));
        QVERIFY2(error.startsWith(QStringLiteral("samples[7].axial_N:")), qPrintable(error));
    }

    // Written as JSON text and read back: the same predictions to the last bit; broken fields named.
    void jsonRoundTrip()
    {
        const QByteArray text = QJsonDocument(currentForceModelJson(m_model)).toJson(QJsonDocument::Compact);
        QString error;
        const auto back = currentForceModelFromJson(QJsonDocument::fromJson(text).object(), &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->samples, m_model.samples);
        QCOMPARE(back->tangential.nodes(), m_model.tangential.nodes());
        const ToolAngles tool{deg(-3.5), deg(-7.0), deg(93.0)};
        for (const ForceCalibrationSample &s : m_heldOut) {
            QCOMPARE(back->tangential.predict(s.drive.tangentialInputs()),
                     m_model.tangential.predict(s.drive.tangentialInputs()));
            QCOMPARE(back->axial.predict(s.drive.axialInputs()), m_model.axial.predict(s.drive.axialInputs()));
            const CuttingForceEstimate a = m_model.estimate(s.drive, tool, 0.2, 1.0, 0.8);
            const CuttingForceEstimate b = back->estimate(s.drive, tool, 0.2, 1.0, 0.8);
            QCOMPARE(a.forces.has_value(), b.forces.has_value());
            if (a.forces)
                QCOMPARE(a.forces->radial_N, b.forces->radial_N);
            QCOMPARE(a.diagnostics.size(), b.diagnostics.size());
        }

        QJsonObject broken = currentForceModelJson(m_model);
        QJsonObject axial = broken.value(QStringLiteral("axial")).toObject();
        QJsonObject net = axial.value(QStringLiteral("network")).toObject();
        QJsonArray radii = net.value(QStringLiteral("radii")).toArray();
        QJsonArray row = radii.at(0).toArray();
        row[1] = -1.0;
        radii[0] = row;
        net.insert(QStringLiteral("radii"), radii);
        axial.insert(QStringLiteral("network"), net);
        broken.insert(QStringLiteral("axial"), axial);
        QVERIFY(!currentForceModelFromJson(broken, &error));
        QVERIFY2(error.contains(QStringLiteral("axial.network.radii")), qPrintable(error));
        QJsonObject noMax = currentForceModelJson(m_model);
        QJsonObject tangential = noMax.value(QStringLiteral("tangential")).toObject();
        tangential.remove(QStringLiteral("input_max"));
        noMax.insert(QStringLiteral("tangential"), tangential);
        QVERIFY(!currentForceModelFromJson(noMax, &error));
        QVERIFY2(error.contains(QStringLiteral("tangential.input_max")), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestCurrentForces)
#include "tst_current_forces.moc"
