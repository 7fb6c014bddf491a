// SPDX-License-Identifier: GPL-3.0-or-later
// Cutting forces, roughness, kinematics and insert codes against hand calculations.
#include "tests/core/test_support.h"

#include "core/cutting/cutting_forces.h"
#include "core/cutting/cutting_quantities.h"
#include "core/tooling/iso1832.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace tolturn;

namespace {

double deg(double d)
{
    return d * std::numbers::pi / 180.0;
}

} // namespace

class TestCutting : public QObject {
    Q_OBJECT
private Q_SLOTS:

    // kc1.1 = 1500 N/mm², mc = 0.22, f = 0.2 mm, ap = 2 mm, kappa_r = 90°:
    // h = 0.2, b = 2; h^(1-mc) = 0.2^0.78 = exp(0.78 ln 0.2) = exp(-1.25537) = 0.28497;
    // Fc = 1500 * 2 * 0.28497 = 854.9 N. Ratios 0.5 and 0.25: Ff = 427.5 N, Fp = 213.7 N.
    void kienzleHandCalculation()
    {
        KienzleConstants k;
        k.cutting = {1500.0, 0.22};
        k.feedToCuttingRatio = 0.5;
        k.passiveToCuttingRatio = 0.25;
        const ForceResult r = kienzleForces(k, 0.2, 2.0, deg(90.0));
        QVERIFY2(test::nearRelative(r.forces.tangential_N, 854.9, 2e-4),
                 qPrintable(QString::number(r.forces.tangential_N)));
        QVERIFY(test::nearRelative(r.forces.axial_N, 427.5, 2e-4));
        QVERIFY(test::nearRelative(r.forces.radial_N, 213.7, 3e-4));
        QVERIFY(r.warnings.empty());
    }

    // kappa_r = 45°: h = 0.2 sin45 = 0.141421, b = 2/sin45 = 2.828427;
    // h^0.78 = exp(0.78 ln 0.141421) = exp(0.78 * -1.956012) = exp(-1.525689) = 0.217452;
    // Fc = 1500 * 2.828427 * 0.217452 = 922.6 N. Own Kienzle laws for Ff (kf = 350, mf = 0.6):
    // h^0.4 = exp(0.4 * -1.956012) = 0.457299; Ff = 350 * 2.828427 * 0.457299 = 452.7 N.
    void kienzleEnteringAngleAndOwnLaws()
    {
        KienzleConstants k;
        k.cutting = {1500.0, 0.22};
        k.feed = KienzleLaw{350.0, 0.6};
        k.passive = KienzleLaw{250.0, 0.5};
        k.validChipThicknessMin_mm = 0.15;
        k.validChipThicknessMax_mm = 1.0;
        const ForceResult r = kienzleForces(k, 0.2, 2.0, deg(45.0));
        QVERIFY2(test::nearRelative(r.forces.tangential_N, 922.6, 2e-4),
                 qPrintable(QString::number(r.forces.tangential_N)));
        QVERIFY2(test::nearRelative(r.forces.axial_N, 452.7, 2e-4), qPrintable(QString::number(r.forces.axial_N)));
        // h = 0.1414 mm lies below the stated 0.15 mm: a warning naming the range.
        QCOMPARE(int(r.warnings.size()), 1);
        QVERIFY(r.warnings[0].message.contains(QStringLiteral("0.15–1 mm")));
    }

    // A finishing cut on the nose (docs/model.md §3): f = 0.1, ap = 0.5, r_n = 0.8 mm, kappa_r = 95°
    // (lead angle -5°), kc1.1 = 1500, mc = 0.22, ratios 0.5 and 0.25 at kappa_r.
    // Li & Du eq. 20: tan(gamma_Le) = 0.5053 tan(-5°) + 1.0473 (0.1/0.8) + 0.4654 (0.8/0.5)
    //   = -0.044208 + 0.130913 + 0.744640 = 0.831344, gamma_Le = 39.738°, kappa_eq = 50.262°.
    // h = 0.1 sin(50.262°) = 0.076897, b = 0.5 / sin(50.262°) = 0.650218;
    // Fc = 1500 * 0.650218 * 0.076897^0.78 = 131.87 N. Thrust (0.5, 0.25) Fc: 73.720 N at
    // atan(0.5) = 26.565°, turned by 95° - 50.262° = 44.738° to 71.303°:
    // Ff = 73.720 cos(71.303°) = 23.63 N, Fp = 73.720 sin(71.303°) = 69.83 N (Fp at kappa_r: 33.0 N).
    void kienzleWithNoseRadius()
    {
        KienzleConstants k;
        k.cutting = {1500.0, 0.22};
        k.feedToCuttingRatio = 0.5;
        k.passiveToCuttingRatio = 0.25;
        QVERIFY(test::nearRelative(equivalentEnteringAngle_rad(deg(95.0), 0.8, 0.1, 0.5), deg(50.262), 2e-5));
        const ForceResult r = kienzleForces(k, 0.1, 0.5, deg(95.0), 0.8);
        QVERIFY2(test::nearRelative(r.forces.tangential_N, 131.87, 1e-4),
                 qPrintable(QString::number(r.forces.tangential_N)));
        QVERIFY2(test::nearRelative(r.forces.axial_N, 23.63, 3e-4), qPrintable(QString::number(r.forces.axial_N)));
        QVERIFY2(test::nearRelative(r.forces.radial_N, 69.83, 2e-4), qPrintable(QString::number(r.forces.radial_N)));
        QVERIFY(r.warnings.empty()); // inside every range eq. 20 states
        // A deep cut, a_p = 5 mm: eq. 20 still (continuous in the depth): tan(gamma_Le) = -0.044208
        // + 0.130913 + 0.4654 (0.8/5) = 0.161169, kappa_eq = 80.844°; h = 0.098726, b = 5.064522;
        // Fc = 1248.21 N; the thrust 697.87 N turned by 14.156° to 40.721°: Fp = 455.20 N.
        const ForceResult deep = kienzleForces(k, 0.1, 5.0, deg(95.0), 0.8);
        QVERIFY2(test::nearRelative(deep.forces.tangential_N, 1248.21, 1e-5),
                 qPrintable(QString::number(deep.forces.tangential_N)));
        QVERIFY2(test::nearRelative(deep.forces.radial_N, 455.20, 2e-5),
                 qPrintable(QString::number(deep.forces.radial_N)));
        // No jump with the depth: 4.999 and 5.001 mm give forces within 0.1 % of each other.
        const double below = kienzleForces(k, 0.1, 4.999, deg(95.0), 0.8).forces.radial_N;
        const double above = kienzleForces(k, 0.1, 5.001, deg(95.0), 0.8).forces.radial_N;
        QVERIFY(std::abs(above / below - 1.0) < 1e-3);
        // ap = 0.25 mm is below the 0.5 mm eq. 20 was fitted over: computed, with a warning.
        const ForceResult shallow = kienzleForces(k, 0.1, 0.25, deg(95.0), 0.8);
        QVERIFY(!shallow.warnings.empty());
        QVERIFY(shallow.warnings.front().message.contains(QStringLiteral("depth of cut")));
    }

    // Taylor: C = v T^n; 250 m/min at 15 min with n = 0.25: 15^0.25 = exp(0.25 ln 15) = exp(0.677013)
    // = 1.967990, C = 491.998 m/min.
    void taylorConstantFromACatalogueSpeed()
    {
        QVERIFY(test::nearRelative(taylorConstant_m_min(250.0, 15.0, 0.25), 491.998, 2e-6));
        QCOMPARE(taylorConstant_m_min(300.0, 1.0, 0.3), 300.0); // T = 1 min: C is the speed itself
    }

    // The speed for a tool life: C = 491.998 m/min, n = 0.25, 15 min: 491.998 / 1.967990 = 250 m/min;
    // 30 min: 30^0.25 = exp(0.25 ln 30) = exp(0.850302) = 2.340347, 491.998 / 2.340347 = 210.2244 m/min.
    void speedForAToolLife()
    {
        QVERIFY(test::nearRelative(speedForToolLife_m_min(491.998, 15.0, 0.25), 250.0, 2e-6));
        QVERIFY(test::nearRelative(speedForToolLife_m_min(491.998, 30.0, 0.25), 210.2244, 1e-6));
    }

    // Li & Du eq. 16a: f = 0.2, d = 1, r_n = 0.8: sqrt(0.64 - 0.01) = 0.793725;
    // A_c = 0.2 - 0.2 (0.8 - 0.793725)/2 = 0.2 - 0.0006275 = 0.1993725 mm². Eq. 16b when r_n < f/2.
    void liDuChipArea()
    {
        QVERIFY(test::nearRelative(liDuUncutChipArea_mm2(0.2, 1.0, 0.8), 0.1993725, 1e-6));
        QCOMPARE(liDuUncutChipArea_mm2(0.5, 1.0, 0.2), 0.5);
    }

    // Eq. 20 with gamma_L = 0, f = 0.2, r_n = 0.8, d = 1: tan = 1.0473*0.25 + 0.4654*0.8 = 0.26183 + 0.37232
    // = 0.63415, gamma_Le = 32.38°. Eq. 17–19 with alpha = alpha_b = 0, K_n = 2000, K_f = 0.5:
    // Ft = K_n A_c = 398.745 N; Fa = K_n A_c K_f cos(g) = 398.745*0.5*0.84452 = 168.37 N;
    // Fr = K_n A_c K_f sin(g) = 398.745*0.5*0.53556 = 106.78 N.
    void liDuForcesHandCalculation()
    {
        LiDuToolGeometry tool;
        tool.noseRadius_mm = 0.8;
        const double gle = liDuEffectiveLeadAngle_rad(tool, 0.2, 1.0);
        QVERIFY2(test::nearRelative(gle * 180.0 / std::numbers::pi, 32.38, 2e-4), qPrintable(QString::number(gle)));
        const ForceResult r = liDuForces({2000.0, 0.5}, tool, 0.2, 1.0);
        QVERIFY(test::nearRelative(r.forces.tangential_N, 398.745, 1e-5));
        QVERIFY2(test::nearRelative(r.forces.axial_N, 168.37, 3e-4), qPrintable(QString::number(r.forces.axial_N)));
        QVERIFY2(test::nearRelative(r.forces.radial_N, 106.78, 3e-4), qPrintable(QString::number(r.forces.radial_N)));
        QVERIFY(r.warnings.empty());
    }

    void liDuValidityWarnings()
    {
        LiDuToolGeometry tool;
        tool.noseRadius_mm = 0.8;
        const ForceResult r = liDuForces({2000.0, 0.5}, tool, 0.05, 0.3); // f and d below their ranges
        QCOMPARE(int(r.warnings.size()), 2);
        QVERIFY(r.warnings[0].message.contains(QStringLiteral("0.5 < depth of cut [mm] < 5")));
        QVERIFY(r.warnings[1].message.contains(QStringLiteral("0.1 < feed [mm/rev] < 1")));
    }

    // Calibration recovers K_n and K_f from forces made with them (several conditions, negative
    // rake), and from a single measurement solves the two equations exactly.
    void liDuCalibrationRecoversCoefficients()
    {
        LiDuToolGeometry tool{deg(-6.0), deg(-6.0), deg(-5.0), 0.8};
        const LiDuCoefficients truth{2350.0, 0.62};
        std::vector<ForceMeasurement> measurements;
        for (const auto &[f, d] : {std::pair{0.15, 1.0}, std::pair{0.25, 2.0}, std::pair{0.35, 3.0}}) {
            const CuttingForces c = liDuForces(truth, tool, f, d).forces;
            measurements.push_back({f, d, c.tangential_N, c.axial_N});
        }
        const LiDuCalibration cal = calibrateLiDu(tool, measurements);
        QVERIFY(cal.coefficients);
        QVERIFY(test::nearRelative(cal.coefficients->normalPressure_MPa, 2350.0, 1e-9));
        QVERIFY(test::nearRelative(cal.coefficients->frictionRatio, 0.62, 1e-9));
        QVERIFY(cal.rmsResidual_N < 1e-9);
        QVERIFY(!calibrateLiDu(tool, {}).coefficients);
    }

    // Ra = f²/(32 r), Rz = f²/(8 r): f = 0.2, r = 0.8 -> 0.04/25.6 mm = 1.5625 µm; 0.04/6.4 mm = 6.25 µm.
    void roughness()
    {
        QVERIFY(test::nearRelative(theoreticalRa_um(0.2, 0.8), 1.5625, 1e-12));
        QVERIFY(test::nearRelative(theoreticalRz_um(0.2, 0.8), 6.25, 1e-12));
    }

    // The same solved for what a roughness needs. Ra 1.6 µm with r 0.4 mm: f = sqrt(32 * 0.4 * 0.0016)
    // = sqrt(0.02048) = 0.1431084 mm/rev; at f 0.17: r = 0.0289 / (32 * 0.0016) = 0.0289 / 0.0512
    // = 0.564453 mm. Rz 6.3 µm with r 0.4: f = sqrt(8 * 0.4 * 0.0063) = sqrt(0.02016) = 0.141986;
    // at 0.17: r = 0.0289 / (8 * 0.0063) = 0.0289 / 0.0504 = 0.573413 mm.
    void roughnessNeeds()
    {
        QVERIFY(test::nearRelative(feedForRa_mm_rev(1.6, 0.4), 0.1431084, 1e-6));
        QVERIFY(test::nearRelative(noseRadiusForRa_mm(1.6, 0.17), 0.564453, 2e-6));
        QVERIFY(test::nearRelative(feedForRz_mm_rev(6.3, 0.4), 0.141986, 2e-6));
        QVERIFY(test::nearRelative(noseRadiusForRz_mm(6.3, 0.17), 0.573413, 2e-6));
    }

    // n = 1000 v/(pi D): 200 m/min on Ø50 -> 1273.24 rpm; P = Fc v = 1000 N * 200 m/min = 3.333 kW;
    // torque 1000 N * 25 mm = 25 N·m.
    void kinematics()
    {
        QVERIFY(test::nearRelative(spindleSpeed_rpm(200.0, 50.0), 1273.2395, 1e-7));
        QVERIFY(test::nearRelative(cuttingPower_kW(1000.0, 200.0), 3.3333333, 1e-7));
        QVERIFY(test::nearRelative(spindleTorque_Nm(1000.0, 50.0), 25.0, 1e-12));
    }

    void insertCodes_data()
    {
        QTest::addColumn<QString>("code");
        QTest::addColumn<double>("angle");
        QTest::addColumn<double>("clearance");
        QTest::addColumn<double>("ic");
        QTest::addColumn<double>("thickness");
        QTest::addColumn<double>("nose");
        // Values from the ISO 1832 tables: shape angle, clearance, IC of the size code, thickness, radius.
        QTest::newRow("CNMG 120408") << QStringLiteral("CNMG 120408") << 80.0 << 0.0 << 12.7 << 4.76 << 0.8;
        QTest::newRow("DNMG150612-PM") << QStringLiteral("DNMG150612-PM") << 55.0 << 0.0 << 12.7 << 6.35 << 1.2;
        QTest::newRow("VBMT 160404") << QStringLiteral("VBMT 160404") << 35.0 << 5.0 << 9.525 << 4.76 << 0.4;
        QTest::newRow("TNMG 220408") << QStringLiteral("TNMG 220408") << 60.0 << 0.0 << 12.7 << 4.76 << 0.8;
        QTest::newRow("SNMG 120412") << QStringLiteral("SNMG 120412") << 90.0 << 0.0 << 12.7 << 4.76 << 1.2;
        QTest::newRow("CCMT 09T308") << QStringLiteral("CCMT 09T308") << 80.0 << 7.0 << 9.525 << 3.97 << 0.8;
        QTest::newRow("WNMG 080408") << QStringLiteral("WNMG 080408") << 80.0 << 0.0 << 12.7 << 4.76 << 0.8;
        QTest::newRow("RCMT 1204M0") << QStringLiteral("RCMT 1204M0") << 0.0 << 7.0 << 12.0 << 4.76 << 0.0;
    }

    void insertCodes()
    {
        QFETCH(QString, code);
        QFETCH(double, angle);
        QFETCH(double, clearance);
        QFETCH(double, ic);
        QFETCH(double, thickness);
        QFETCH(double, nose);
        const InsertParseResult r = parseInsertCode(code);
        QVERIFY2(r.insert, r.diagnostics.empty() ? "" : qPrintable(r.diagnostics[0].message));
        QCOMPARE(r.insert->includedAngle_deg, angle);
        QCOMPARE(r.insert->clearanceAngle_deg, clearance);
        QCOMPARE(r.insert->inscribedCircle_mm, ic);
        QCOMPARE(r.insert->thickness_mm, thickness);
        QCOMPARE(r.insert->noseRadius_mm, nose);
    }

    void malformedInsertCodes_data()
    {
        QTest::addColumn<QString>("code");
        QTest::addColumn<QString>("fragment");
        QTest::newRow("shape") << QStringLiteral("XNMG 120408") << QStringLiteral("position 1 (shape) 'X'");
        QTest::newRow("clearance") << QStringLiteral("CXMG 120408")
                                   << QStringLiteral("position 2 (clearance angle) 'X'");
        QTest::newRow("tolerance") << QStringLiteral("CNZG 120408")
                                   << QStringLiteral("position 3 (tolerance class) 'Z'");
        QTest::newRow("type") << QStringLiteral("CNMZ 120408") << QStringLiteral("position 4 (type) 'Z'");
        QTest::newRow("size") << QStringLiteral("CNMG 130408") << QStringLiteral("position 5 (size) '13'");
        QTest::newRow("thickness") << QStringLiteral("CNMG 120808") << QStringLiteral("position 6 (thickness) '08'");
        QTest::newRow("garbage") << QStringLiteral("hello") << QStringLiteral("not an ISO 1832 designation");
    }

    void malformedInsertCodes()
    {
        QFETCH(QString, code);
        QFETCH(QString, fragment);
        const InsertParseResult r = parseInsertCode(code);
        QVERIFY(!r.insert);
        QCOMPARE(int(r.diagnostics.size()), 1);
        QCOMPARE(r.diagnostics[0].field, QStringLiteral("tool.insert"));
        QVERIFY2(r.diagnostics[0].message.contains(fragment), qPrintable(r.diagnostics[0].message));
        QVERIFY(r.diagnostics[0].message.contains(code));
    }
};

QTEST_GUILESS_MAIN(TestCutting)
#include "tst_cutting.moc"
