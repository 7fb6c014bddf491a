// SPDX-License-Identifier: GPL-3.0-or-later
// The forces and the tool deflection of five-axis ball-end milling (Öztürk & Budak, seed 001;
// docs/milling.md), each against a closed form, a hand calculation or a three-axis summation written
// here from the paper's tables and the classic ball-end force directions.
#include "tests/core/test_support.h"

#include "core/milling/ball_end_deflection.h"
#include "core/milling/ball_end_forces.h"
#include "core/milling/seed_ball_end_cases.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace tolturn;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kR0 = 6.0; // the paper's Ø12 mm tool (001 §5)

BallEndMill paperTool(int flutes, double helix_deg)
{
    return {2.0 * kR0, flutes, helix_deg * kPi / 180.0};
}

MillingForceCoefficients tangentialOnly(double ktc)
{
    MillingForceCoefficients k;
    k.tangentialCutting_N_mm2 = ktc;
    return k;
}

// Test coefficients, all six non-zero and distinct so that a mixed-up direction shows.
MillingForceCoefficients allSix()
{
    return {2000.0, 700.0, 400.0, 25.0, 40.0, 8.0};
}

BallEndCut slot(double axialDepth_mm, double feedPerTooth_mm)
{
    BallEndCut cut;
    cut.axialDepth_mm = axialDepth_mm;
    cut.feedPerTooth_mm = feedPerTooth_mm;
    return cut;
}

// ∫₀ᵃ R(z) dz = ∫ sqrt(R_o² − u²) du over u from R_o − a to R_o: a segment of the circle.
double integralOfLocalRadius(double a)
{
    const auto primitive = [](double u) {
        return 0.5 * u * std::sqrt(kR0 * kR0 - u * u) + 0.5 * kR0 * kR0 * std::asin(u / kR0);
    };
    return primitive(kR0) - primitive(kR0 - a);
}

// The angle φ brought into [0, 2π).
double wrapped(double phi)
{
    const double twoPi = 2.0 * kPi;
    return phi - twoPi * std::floor(phi / twoPi);
}

// Three-axis ball-end forces summed the classic way (Lee & Altintas 1996): slices of dz from the
// tip, each flute's element at φ + j·2π/N − z tan i0 / R_o, in the cut where φ lies within the
// table's limits at z ≤ a, chip f_t sin φ sin κ, and the forces turned by the matrix of the ball's
// normal, the edge's velocity and the meridian.
Eigen::Vector3d threeAxisForce(const BallEndMill &mill, const MillingForceCoefficients &k, const BallEndCut &cut,
                               int slices, double rotation)
{
    const double dz = cut.axialDepth_mm / slices;
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    for (int i = 0; i < slices; ++i) {
        const double z = (i + 0.5) * dz;
        const double r = localRadius_mm(kR0, z);
        const double kappa = std::asin(r / kR0);
        const double db = dz / std::sin(kappa);
        const double tanI = std::tan(mill.helix_rad);
        const double ds = dz * std::sqrt(1.0 + std::pow((kR0 - z) / r, 2) + std::pow(r * tanI / kR0, 2));
        const Engagement e = cut.kind == BallEndCutKind::SideCut
                                 ? uncutEngagement(kR0, cut.radialDepth_mm, cut.axialDepth_mm, z, cut.direction)
                                 : previouslyCutEngagement(kR0, cut.radialDepth_mm, z, cut.direction);
        for (int j = 0; j < mill.flutes; ++j) {
            const double phi = wrapped(rotation + j * 2.0 * kPi / mill.flutes - z * tanI / kR0);
            if (phi < e.entry_rad || phi > e.exit_rad)
                continue;
            const double t = cut.feedPerTooth_mm * std::sin(phi) * std::sin(kappa);
            const double fr = k.radialEdge_N_mm * ds + k.radialCutting_N_mm2 * t * db;
            const double ft = k.tangentialEdge_N_mm * ds + k.tangentialCutting_N_mm2 * t * db;
            const double fa = k.axialEdge_N_mm * ds + k.axialCutting_N_mm2 * t * db;
            const double sk = std::sin(kappa);
            const double ck = std::cos(kappa);
            f += Eigen::Vector3d(-fr * sk * std::sin(phi) - ft * std::cos(phi) - fa * ck * std::sin(phi),
                                 -fr * sk * std::cos(phi) + ft * std::sin(phi) - fa * ck * std::cos(phi),
                                 fr * ck - fa * sk);
        }
    }
    return f;
}

} // namespace

class TestBallEndForces : public QObject {
    Q_OBJECT

private Q_SLOTS:

    // Helix 0, K_tc only, one flute in a slot: every element is at φ, its tangential force is
    // K_tc f_t sin φ sin κ · dz / sin κ = K_tc f_t sin φ dz in the plane, so the in-plane resultant
    // is K_tc f_t a sin φ while the flute is in the front half, and 0 behind.
    void inPlaneResultantZeroHelix()
    {
        const double ktc = 2000.0;
        const double ft = 0.1;
        const double a = 3.0;
        const auto samples = ballEndForces(paperTool(1, 0.0), tangentialOnly(ktc), slot(a, ft), {200, 360});
        for (const BallEndForceSample &s : samples) {
            const double expected = std::max(0.0, ktc * ft * a * std::sin(s.rotation_rad));
            QVERIFY2(test::nearAbsolute(s.workpieceFrame_N.head<2>().norm(), expected, 1e-9 * ktc),
                     qPrintable(QStringLiteral("φ = %1").arg(s.rotation_rad)));
        }
        // At φ = 90° the flute is at the front (+F) moving towards −C: 2000 · 0.1 · 3 = 600 N on the
        // tool along +C, against the edge's motion.
        QVERIFY(test::nearAbsolute(samples[90].workpieceFrame_N.y(), 600.0, 1e-9));
        QVERIFY(test::nearAbsolute(samples[90].workpieceFrame_N.x(), 0.0, 1e-9));
    }

    void slotMeanTorque_data()
    {
        QTest::addColumn<double>("lead");
        QTest::addColumn<double>("tilt");
        QTest::addColumn<double>("axialDepth");
        QTest::newRow("three-axis") << 0.0 << 0.0 << 3.0;
        QTest::newRow("001 case 1: 0°, −15°") << 0.0 << -15.0 << 3.0;
        QTest::newRow("001 case 2: 15°, 15°") << 15.0 << 15.0 << 3.0;
        QTest::newRow("001 case 4: 30°, 30°") << 30.0 << 30.0 << 1.5;
        QTest::newRow("−20°, 10°") << -20.0 << 10.0 << 2.0;
    }

    // The radial force pushes the tool away from the material, whatever the matrix says: with K_rc
    // only, helix 0, one flute in a three-axis slot at φ = 90° (the flute at the front), the tool is
    // pushed back against the feed (−F) and up off the floor (+N), and not sideways.
    void radialForcePushesTheToolAway()
    {
        MillingForceCoefficients k;
        k.radialCutting_N_mm2 = 700.0;
        const auto samples = ballEndForces(paperTool(1, 0.0), k, slot(3.0, 0.1), {200, 360});
        const Eigen::Vector3d f = samples[90].workpieceFrame_N;
        QVERIFY(f.x() < -1.0);
        QVERIFY(f.z() > 1.0);
        QVERIFY(std::abs(f.y()) < 1e-9 * f.norm());
    }

    // A slot, two flutes, 30° helix, K_tc only: an element's torque is R K_tc t db with t = f_t n_F,
    // n the ball's unit normal, and R db dφ = R dz dφ / sin κ is the ball's area element dA. Over a
    // revolution each flute sweeps the cut's cap once, so the mean torque is N K_tc f_t ∫ n_F dA / 2π:
    // the cap's shadow along F, the disc's segment below a, 2 ∫R dz. N K_tc f_t ∫R dz / π then holds
    // at any lead and tilt, which tests the chip thickness in the workpiece frame (eq. 8).
    void slotMeanTorque()
    {
        QFETCH(double, lead);
        QFETCH(double, tilt);
        QFETCH(double, axialDepth);
        const double ktc = 1800.0;
        const double ft = 0.08;
        const double expected = 2.0 * ktc * ft * integralOfLocalRadius(axialDepth) / kPi;
        BallEndCut cut = slot(axialDepth, ft);
        cut.lead_rad = lead * kPi / 180.0;
        cut.tilt_rad = tilt * kPi / 180.0;
        const auto samples = ballEndForces(paperTool(2, 30.0), tangentialOnly(ktc), cut, {400, 360});
        const double mean = summarise(samples).meanTorque_N_mm;
        QVERIFY2(std::abs(mean / expected - 1.0) < 2e-3,
                 qPrintable(QStringLiteral("%1 against %2").arg(mean).arg(expected)));
        // 1 kN·mm at 1000 1/min: 1 N·m · 2π · 1000 / 60 = 104.72 W.
        QVERIFY(test::nearAbsolute(spindlePower_W(1000.0, 1000.0), 104.719755, 1e-6));
    }

    // Helix 0, one flute, slot, the three cutting coefficients: all elements at φ, t·db = f_t sin φ
    // dz, so F_x = −f_t sin φ (K_rc sin φ ∫sin κ dz + K_tc cos φ a + K_ac sin φ ∫cos κ dz), with
    // ∫sin κ dz = ∫R dz / R_o and ∫cos κ dz = a − a² / 2R_o; F_y likewise with cos φ in place of
    // sin φ in the radial and axial terms and −sin φ in the tangential; F_z = f_t sin φ (K_rc ∫cos κ dz
    // − K_ac ∫sin κ dz).
    void threeAxisSlotClosedForm()
    {
        const MillingForceCoefficients k{2000.0, 700.0, 400.0, 0.0, 0.0, 0.0};
        const double ft = 0.1;
        const double a = 3.0;
        const double sinIntegral = integralOfLocalRadius(a) / kR0;
        const double cosIntegral = a - a * a / (2.0 * kR0);
        const auto samples = ballEndForces(paperTool(1, 0.0), k, slot(a, ft), {400, 360});
        for (const int degrees : {30, 60, 90, 135}) {
            const double phi = degrees * kPi / 180.0;
            const double s = std::sin(phi);
            const double c = std::cos(phi);
            const Eigen::Vector3d expected(
                -ft * s * (700.0 * s * sinIntegral + 2000.0 * c * a + 400.0 * s * cosIntegral),
                -ft * s * (700.0 * c * sinIntegral - 2000.0 * s * a + 400.0 * c * cosIntegral),
                ft * s * (700.0 * cosIntegral - 400.0 * sinIntegral));
            const Eigen::Vector3d got = samples[static_cast<std::size_t>(degrees)].toolFrame_N;
            // The midpoint sum of ∫R dz over 400 slices: within 0.01 %.
            QVERIFY2((got - expected).norm() < 1e-4 * expected.norm(),
                     qPrintable(QStringLiteral("%1°: (%2, %3, %4) against (%5, %6, %7)")
                                    .arg(degrees)
                                    .arg(got.x())
                                    .arg(got.y())
                                    .arg(got.z())
                                    .arg(expected.x())
                                    .arg(expected.y())
                                    .arg(expected.z())));
        }
    }

    void leadTiltZeroIsThreeAxis_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<int>("direction");
        QTest::addColumn<double>("radialDepth");
        QTest::newRow("side cut, down, 001 case 3's s")
            << int(BallEndCutKind::SideCut) << int(MillingDirection::Down) << 4.5962;
        QTest::newRow("side cut, up, s = 2") << int(BallEndCutKind::SideCut) << int(MillingDirection::Up) << 2.0;
        QTest::newRow("step-over, down, s = 1") << int(BallEndCutKind::StepOver) << int(MillingDirection::Down) << 1.0;
        QTest::newRow("step-over, up, s = 3") << int(BallEndCutKind::StepOver) << int(MillingDirection::Up) << 3.0;
    }

    // Lead = tilt = 0: the five-axis summation, which tests the cut in the workpiece frame, gives
    // the three-axis forces summed from tables 1 and 2's angles, at every rotation angle, with a
    // 30° helix, two flutes and all six coefficients.
    void leadTiltZeroIsThreeAxis()
    {
        QFETCH(int, kind);
        QFETCH(int, direction);
        QFETCH(double, radialDepth);
        BallEndCut cut = slot(3.0, 0.1);
        cut.kind = static_cast<BallEndCutKind>(kind);
        cut.direction = static_cast<MillingDirection>(direction);
        cut.radialDepth_mm = radialDepth;
        const BallEndMill mill = paperTool(2, 30.0);
        const auto samples = ballEndForces(mill, allSix(), cut, {200, 72});
        double largest = 0.0;
        for (const BallEndForceSample &s : samples) {
            const Eigen::Vector3d expected = threeAxisForce(mill, allSix(), cut, 200, s.rotation_rad);
            largest = std::max(largest, expected.norm());
            QVERIFY2(
                (s.toolFrame_N - expected).norm() < 1e-9 * std::max(1.0, expected.norm()),
                qPrintable(
                    QStringLiteral("φ = %1: |Δ| = %2").arg(s.rotation_rad).arg((s.toolFrame_N - expected).norm())));
            QVERIFY((s.workpieceFrame_N - s.toolFrame_N).norm() < 1e-12 * std::max(1.0, expected.norm()));
        }
        QVERIFY(largest > 100.0); // the cut is not empty
    }

    // Helix 0 and no axial coefficients: in a slot F_z = Σ dF_r cos κ, and dF_r = K_re dS + K_rc f_t
    // sin φ dz is the same at φ and π − φ, both in the cut.
    void slotAxialForceSymmetric()
    {
        const MillingForceCoefficients k{2000.0, 700.0, 0.0, 25.0, 40.0, 0.0};
        const auto samples = ballEndForces(paperTool(1, 0.0), k, slot(3.0, 0.1), {200, 360});
        double largest = 0.0;
        for (int m = 1; m < 180; ++m) {
            const double fz = samples[static_cast<std::size_t>(m)].toolFrame_N.z();
            const double mirrored = samples[static_cast<std::size_t>(180 - m)].toolFrame_N.z();
            QVERIFY(test::nearAbsolute(fz, mirrored, 1e-9 * std::abs(fz)));
            largest = std::max(largest, std::abs(fz));
        }
        QVERIFY(largest > 10.0);
    }

    // Forces converge as the slices get thinner: with the edge coefficients, whose dS is largest at
    // the tip, the peak resultant and the mean torque at 200 slices are within 0.5 % of 3200's.
    void slicesConverge()
    {
        BallEndCut cut = slot(1.5, 0.1);
        cut.lead_rad = 30.0 * kPi / 180.0;
        cut.tilt_rad = 30.0 * kPi / 180.0;
        const BallEndMill mill = paperTool(2, 30.0);
        const auto at = [&](int slices) { return summarise(ballEndForces(mill, allSix(), cut, {slices, 360})); };
        const BallEndForceSummary fine = at(3200);
        double previous = 1.0;
        for (const int slices : {25, 50, 100, 200}) {
            const BallEndForceSummary s = at(slices);
            const double error = std::max(std::abs(s.peakResultant_N / fine.peakResultant_N - 1.0),
                                          std::abs(s.meanTorque_N_mm / fine.meanTorque_N_mm - 1.0));
            QVERIFY2(error < previous, qPrintable(QStringLiteral("%1 slices: %2").arg(slices).arg(error)));
            previous = error;
        }
        QVERIFY2(previous < 5e-3, qPrintable(QString::number(previous)));
    }

    // Five-axis geometry: a 30°/30° lead–tilt keeps the tip out of a 1.5 mm cut (001 case 4): the
    // band starts at R_o (1 − cos(θ − γ)) with cos θ = cos²30° = 0.75, cos γ = 1 − 1.5 / 6 = 0.75.
    // Deeper than R_o (1 − sin θ) = 6 (1 − 0.66144) = 2.0314 mm, the shank would cut: refused.
    void fiveAxisBandByHand()
    {
        BallEndCut cut = slot(1.5, 0.1);
        cut.lead_rad = kPi / 6.0;
        cut.tilt_rad = kPi / 6.0;
        const BallEndMill mill = paperTool(2, 30.0);
        const BallEndBand band = engagedBand(mill, cut);
        QVERIFY(test::nearAbsolute(band.low_mm, 0.0, 1e-12)); // θ = γ: the cap just reaches the tip
        const double theta = std::acos(0.75);
        QVERIFY(test::nearAbsolute(band.high_mm, kR0 * (1.0 - std::cos(2.0 * theta)), 1e-12));
        QVERIFY(test::nearAbsolute(deepestCutOnBall_mm(12.0, kPi / 6.0, kPi / 6.0),
                                   6.0 * (1.0 - std::sqrt(1.0 - 0.5625)), 1e-12));
        cut.axialDepth_mm = 2.1;
        const auto problems = validateBallEndCut(mill, cut, {});
        QCOMPARE(problems.size(), std::size_t(1));
        QVERIFY(QString::fromStdString(problems.front()).contains(QStringLiteral("axial depth: 2.1 mm")));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)ballEndForces(mill, allSix(), cut, {}));
    }

    // 001 table 4 as bundled: the feed is printed per revolution, so case 4's two flutes take
    // 0.05 mm each; case 3 is a side cut 4.5962 mm wide, the others slots; every cut on the ball.
    void paperCasesAsPrinted()
    {
        const auto cases = seedBallEndCases();
        QCOMPARE(cases.size(), std::size_t(4));
        const double leads[] = {0.0, 15.0, -10.0, 30.0};
        const double tilts[] = {-15.0, 15.0, 0.0, 30.0};
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const SeedBallEndCase &c = cases[i];
            QCOMPARE(c.mill.diameter_mm, 12.0);
            QVERIFY(test::nearAbsolute(c.mill.helix_rad, kPi / 6.0, 1e-15));
            QVERIFY(test::nearAbsolute(c.cut.lead_rad, leads[i] * kPi / 180.0, 1e-15));
            QVERIFY(test::nearAbsolute(c.cut.tilt_rad, tilts[i] * kPi / 180.0, 1e-15));
            QVERIFY(test::nearAbsolute(c.cut.feedPerTooth_mm * c.mill.flutes, 0.1, 1e-15));
            QVERIFY(validateBallEndCut(c.mill, c.cut, {}).empty());
        }
        QCOMPARE(cases[3].mill.flutes, 2);
        QCOMPARE(cases[3].spindle_rpm, 500.0);
        QCOMPARE(cases[2].cut.kind, BallEndCutKind::SideCut);
        QCOMPARE(cases[2].cut.radialDepth_mm, 4.5962);
        QCOMPARE(cases[0].cut.kind, BallEndCutKind::Slot);
    }

    // The coefficients as typed: commas, or semicolons where the comma is the decimal separator;
    // six numbers, each at most 100 000 in size.
    void coefficientsAsTyped()
    {
        const auto k = parseMillingCoefficients(QStringLiteral("2000, 700,400 ,25,40,8"));
        QVERIFY(k.has_value());
        QCOMPARE(k->tangentialCutting_N_mm2, 2000.0);
        QCOMPARE(k->axialEdge_N_mm, 8.0);
        const auto semicolons = parseMillingCoefficients(QStringLiteral("2000.5; 700; 400; 25; 40; 8"));
        QVERIFY(semicolons.has_value());
        QCOMPARE(semicolons->tangentialCutting_N_mm2, 2000.5);
        QVERIFY(!parseMillingCoefficients(QStringLiteral("2000, 700, 400, 25, 40")).has_value());
        QVERIFY(!parseMillingCoefficients(QStringLiteral("2000, 700, 400, 25, 40, x")).has_value());
        QVERIFY(!parseMillingCoefficients(QStringLiteral("200000, 700, 400, 25, 40, 8")).has_value());
        QVERIFY(!parseMillingCoefficients(QStringLiteral("nan, 700, 400, 25, 40, 8")).has_value());
    }

    // Table 3 for the paper's tool (k = 6306 N/mm, k_θ = 1.656·10⁷ N·mm/rad), a Ø9.6 mm cylinder of
    // E = 630 000 N/mm², L = 40 mm, 1 N at the tip seen at the tip: 40³ / 3EI + 1/k + 40² / k_θ with
    // I = π 9.6⁴ / 64 = 416.92 mm⁴: 8.1220·10⁻⁵ + 1.5858·10⁻⁴ + 9.6618·10⁻⁵ = 3.36418·10⁻⁴ mm/N.
    // Force 10 mm above the point: v_m = 30, v_k = 40 → 30² (120 − 30) / 6EI + 1/k + 1200 / k_θ.
    void deflectionUnderUnitLoad()
    {
        const BallEndToolStructure tool{40.0, 9.6, 630000.0, 6306.0, 1.656e7};
        const double ei = 630000.0 * kPi * std::pow(9.6, 4) / 64.0;
        QVERIFY(test::nearAbsolute(lateralCompliance_mm_N(tool, 40.0, 40.0),
                                   64000.0 / (3.0 * ei) + 1.0 / 6306.0 + 1600.0 / 1.656e7, 1e-15));
        QVERIFY(test::nearAbsolute(lateralCompliance_mm_N(tool, 40.0, 40.0), 3.36418e-4, 1e-9));
        QVERIFY(test::nearAbsolute(lateralCompliance_mm_N(tool, 30.0, 40.0),
                                   900.0 * 90.0 / (6.0 * ei) + 1.0 / 6306.0 + 1200.0 / 1.656e7, 1e-15));
        // Maxwell's reciprocity: the force at 40 seen at 30 is the force at 30 seen at 40.
        QVERIFY(test::nearAbsolute(lateralCompliance_mm_N(tool, 40.0, 30.0), lateralCompliance_mm_N(tool, 30.0, 40.0),
                                   1e-15));
        QVERIFY(test::nearAbsolute(axialCompliance_mm_N(tool), 40.0 / (630000.0 * kPi * 9.6 * 9.6 / 4.0), 1e-18));
    }

    // The deflection of a cut is each element's force times its own compliance: with one slice the
    // whole force acts at its height z. With a 20° lead the generating point is R_o (1 − cos 20°) up
    // the axis, so v_k = L − that and v_m = L − z; δ_N is the N row of T times δ.
    void deflectionOfACut()
    {
        const BallEndToolStructure tool{40.0, 9.6, 630000.0, 6306.0, 1.656e7};
        const BallEndMill mill = paperTool(1, 0.0);
        BallEndCut cut = slot(1.0, 0.1);
        cut.lead_rad = 20.0 * kPi / 180.0;
        const double generating = kR0 * (1.0 - std::cos(cut.lead_rad));
        QVERIFY(test::nearAbsolute(surfaceGenerationHeight_mm(mill, cut), generating, 1e-12));
        const BallEndDeflection led = ballEndDeflection(mill, tool, allSix(), cut, {1, 36});
        const BallEndBand band = engagedBand(mill, cut);
        const double z = 0.5 * (band.low_mm + band.high_mm); // the single slice's middle
        const double lateral = lateralCompliance_mm_N(tool, 40.0 - z, 40.0 - generating);
        const Eigen::Vector3d nRow(-std::sin(cut.lead_rad), 0.0, std::cos(cut.lead_rad)); // T₃· at tilt 0
        double least = 1.0;
        for (std::size_t m = 0; m < led.forces.size(); ++m) {
            const Eigen::Vector3d f = led.forces[m].toolFrame_N;
            const Eigen::Vector3d expected(lateral * f.x(), lateral * f.y(), axialCompliance_mm_N(tool) * f.z());
            const BallEndDeflectionSample &d = led.deflection[m];
            QVERIFY((d.toolFrame_mm - expected).norm() < 1e-15 + 1e-12 * expected.norm());
            QVERIFY(test::nearAbsolute(d.surfaceNormal_mm(), nRow.dot(d.toolFrame_mm), 1e-15));
            least = std::min(least, d.surfaceNormal_mm());
        }
        QCOMPARE(led.leastSurfaceNormal_mm, least);
        QVERIFY(led.greatestSurfaceNormal_mm > led.leastSurfaceNormal_mm);

        // The deflection is affine in the feed per tooth: at 0.16 mm it is the one at 0.1 mm plus
        // 0.06 mm times the cutting coefficients' part per mm.
        BallEndCut faster = cut;
        faster.feedPerTooth_mm = 0.16;
        const BallEndDeflection at016 = ballEndDeflection(mill, tool, allSix(), faster, {50, 36});
        const BallEndDeflection at010 = ballEndDeflection(mill, tool, allSix(), cut, {50, 36});
        for (std::size_t m = 0; m < at016.forces.size(); ++m) {
            const BallEndForceSample &s = at010.forces[m];
            const Eigen::Vector3d predicted = s.deflection_mm + 0.06 * s.deflectionPerFeed_mm_mm;
            QVERIFY((at016.forces[m].deflection_mm - predicted).norm() < 1e-15 + 1e-12 * predicted.norm());
        }
    }
};

QTEST_GUILESS_MAIN(TestBallEndForces)
#include "tst_ball_end_forces.moc"
