// SPDX-License-Identifier: GPL-3.0-or-later
// The ball-end mill's geometry in the cut (Öztürk & Budak, seed 001; docs/milling.md): the local
// radius, the engagement heights and limits of tables 1 and 2, and the lead–tilt transformation,
// each against a hand calculation or an independent construction.
#include "core/milling/ball_end_geometry.h"

#include <Eigen/Geometry>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace tolturn;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kR0 = 6.0; // the paper's Ø12 mm tool (001 §5)

} // namespace

class TestBallEndGeometry : public QObject {
    Q_OBJECT

private Q_SLOTS:

    // R(z) = sqrt(36 − (6 − z)²): R(3) = sqrt(27) = 5.19615; 0 at the tip; 6 above the ball.
    void localRadiusByHand()
    {
        QVERIFY(std::abs(localRadius_mm(kR0, 3.0) - std::sqrt(27.0)) < 1e-12);
        QCOMPARE(localRadius_mm(kR0, 0.0), 0.0);
        QCOMPARE(localRadius_mm(kR0, 8.0), 6.0);
        // κ at z = 3: cos κ = (R_o − z) / R_o = 0.5, so κ = 60°.
        QVERIFY(std::abs(axialImmersionAngle_rad(kR0, 3.0) - kPi / 3.0) < 1e-12);
    }

    // s = 2, a = 3: R(a) = 5.19615, hc = 6 − sqrt(36 − 3.19615²) = 0.92215. The scallop of passes
    // 2 mm apart: 6 − sqrt(35) = 0.08392.
    void engagementHeightsByHand()
    {
        const double d = std::sqrt(27.0) - 2.0;
        QVERIFY(std::abs(uncutEngagementHeight_mm(kR0, 2.0, 3.0) - (6.0 - std::sqrt(36.0 - d * d))) < 1e-12);
        QVERIFY(std::abs(uncutEngagementHeight_mm(kR0, 2.0, 3.0) - 0.92215) < 1e-5);
        QVERIFY(std::abs(scallopHeight_mm(kR0, 2.0) - (6.0 - std::sqrt(35.0))) < 1e-12);
    }

    // Table 1 at z = 3 (above hc), s = 2, a = 3: down milling enters at π − acos((R(a) − s) / R(z))
    // = π − acos(3.19615 / 5.19615) and leaves at π; up milling is the mirror. Below hc the cut
    // narrower than R(a) does not reach the element; as wide as R(a) or wider, the whole half cuts.
    void uncutEngagementTable1()
    {
        const double edge = std::acos((std::sqrt(27.0) - 2.0) / std::sqrt(27.0));
        const Engagement down = uncutEngagement(kR0, 2.0, 3.0, 3.0, MillingDirection::Down);
        QVERIFY(std::abs(down.entry_rad - (kPi - edge)) < 1e-12);
        QCOMPARE(down.exit_rad, kPi);
        const Engagement up = uncutEngagement(kR0, 2.0, 3.0, 3.0, MillingDirection::Up);
        QCOMPARE(up.entry_rad, 0.0);
        QVERIFY(std::abs(up.exit_rad - edge) < 1e-12);
        QVERIFY(!uncutEngagement(kR0, 2.0, 3.0, 0.5, MillingDirection::Down).cuts());
        QVERIFY(!uncutEngagement(kR0, 2.0, 3.0, 0.5, MillingDirection::Up).cuts());
        // s = 6 ≥ R(3): hc = 6 − sqrt(36 − 0.80385²) = 0.05407; below it the half-disc cuts.
        const Engagement wide = uncutEngagement(kR0, 6.0, 3.0, 0.05, MillingDirection::Down);
        QCOMPARE(wide.entry_rad, 0.0);
        QCOMPARE(wide.exit_rad, kPi);
        // s = R(a): hc = 0 and every element cuts half, entering at π/2.
        QVERIFY(std::abs(uncutEngagement(kR0, std::sqrt(27.0), 3.0, 1.0, MillingDirection::Down).entry_rad - kPi / 2) <
                1e-12);
    }

    // Table 2 beside a pass 2 mm away at z = 3: π − acos(1 − s / R(z)) = π − acos(1 − 2 / 5.19615),
    // the same angle as table 1's above (R(a) = R(z) there); below the scallop, the half-disc.
    void previouslyCutEngagementTable2()
    {
        const double edge = std::acos(1.0 - 2.0 / std::sqrt(27.0));
        const Engagement down = previouslyCutEngagement(kR0, 2.0, 3.0, MillingDirection::Down);
        QVERIFY(std::abs(down.entry_rad - (kPi - edge)) < 1e-12);
        QVERIFY(std::abs(previouslyCutEngagement(kR0, 2.0, 3.0, MillingDirection::Up).exit_rad - edge) < 1e-12);
        const Engagement low = previouslyCutEngagement(kR0, 2.0, 0.05, MillingDirection::Up);
        QCOMPARE(low.entry_rad, 0.0);
        QCOMPARE(low.exit_rad, kPi);
    }

    // Eq. 6 against the rotation by the tilt about X after the lead about Y, built from Eigen's
    // angle–axis rotations; the identity at lead = tilt = 0; a 30° lead turns the tool axis to
    // (sin 30°, 0, cos 30°).
    void leadTiltIsARotation()
    {
        for (const double lead : {-0.5, 0.0, 0.3, 0.52}) {
            for (const double tilt : {-0.26, 0.0, 0.26, 0.52}) {
                const Eigen::Matrix3d expected = (Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()) *
                                                  Eigen::AngleAxisd(lead, Eigen::Vector3d::UnitY()))
                                                     .toRotationMatrix();
                QVERIFY((leadTiltTransform(lead, tilt) - expected).norm() < 1e-12);
            }
        }
        QVERIFY((leadTiltTransform(0.0, 0.0) - Eigen::Matrix3d::Identity()).norm() < 1e-15);
        const Eigen::Vector3d axis = leadTiltTransform(kPi / 6.0, 0.0) * Eigen::Vector3d::UnitZ();
        QVERIFY((axis - Eigen::Vector3d(0.5, 0.0, std::sqrt(3.0) / 2.0)).norm() < 1e-12);
    }
};

QTEST_GUILESS_MAIN(TestBallEndGeometry)
#include "tst_ball_end_geometry.moc"
