// SPDX-License-Identifier: GPL-3.0-or-later
// The deviation model from a project to per-station contributions, against closed forms, and its
// named errors for bad input.
#include "tests/core/test_support.h"

#include "core/deviation/deviation_model.h"
#include "core/deviation/stiffness_calibration.h"
#include "core/io/project_file.h"
#include "core/mechanics/beam_corrections.h"
#include "core/project/project_validation.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace tolturn;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kE = test::kSteelE_MPa;
constexpr double kNu = test::kSteelNu;
constexpr double kG = test::kSteelG_MPa;
constexpr double kKappaSolid = test::kKappaSolidCircle;

using test::dump;
using test::seg;

// A plain bar Ø2r x L of C45E-N, one finishing pass, a CNMG insert in a PCLNR holder.
Project barProject(double r, double length, ClampingMethod method, double clamped)
{
    Project p;
    p.part.name = QStringLiteral("bar");
    p.part.stockDiameter_mm = 2 * r + 4;
    p.part.outer.segments = {seg("O1", SegmentKind::Face, {0, 0}, {0, r}),
                             seg("O2", SegmentKind::Cylinder, {0, r}, {length, r}),
                             seg("O3", SegmentKind::Face, {length, r}, {length, 0})};
    p.materialId = QStringLiteral("C45E-N");
    p.machineId = QStringLiteral("haas-st-20");
    p.tool.insertCode = QStringLiteral("CNMG 120408");
    p.tool.holderCode = QStringLiteral("PCLNR 2525M12");
    p.clamping = {method, clamped};
    p.passes = {{PassKind::Finishing, 200.0, 0.2, 1.0}};
    return p;
}

const FeatureDeviation &feature(const DeviationResult &r, const char *id)
{
    for (const FeatureDeviation &f : r.features) {
        if (f.featureId == QLatin1String(id))
            return f;
    }
    qFatal("no feature %s", id);
}

} // namespace

class TestDeviation : public QObject {
    Q_OBJECT
private Q_SLOTS:

    // Workpiece only, given forces, no in-process stock: a cantilever from the chuck face.
    //   radial   w = Fr (d^3/(3EI) + d/(kGA)) - Fa r d^2/(2EI)   (moment of Fa at the contact radius)
    //   tangent  w = Ft (d^3/(3EI) + d/(kGA));  radius error = sqrt((r + w_r)^2 + w_t^2) - r
    void cantileverWithGivenLoad()
    {
        const double r = 15.0;
        const Project p = barProject(r, 240.0, ClampingMethod::Chuck, 40.0);
        DeviationOptions o;
        o.beamCorrections = false; // the closed form is plain Timoshenko theory
        o.loadOverride = CuttingForces{500.0, 150.0, 200.0};
        o.workpieceOnly = true;
        o.inProcessSection = false;
        const DeviationResult res = computeDeviation(p, DataLibrary::builtIn(), o);
        QVERIFY2(res.inputs, qPrintable(dump(res.diagnostics)));
        const double I = kPi * std::pow(r, 4) / 4;
        const double A = kPi * r * r;
        for (const Station &st : feature(res, "O2").stations) {
            const double d = st.z_mm - 40.0;
            const double bend = d * d * d / (3 * kE * I) + d / (kKappaSolid * kG * A);
            const double wr = 200.0 * bend - 150.0 * r * d * d / (2 * kE * I);
            const double wt = 500.0 * bend;
            QVERIFY2(test::nearRelative(st.radial.total_mm(), wr, 1e-6, 1e-12), qPrintable(QString::number(st.z_mm)));
            QVERIFY(test::nearRelative(st.tangential.total_mm(), wt, 1e-6, 1e-12));
            QVERIFY(test::nearRelative(st.radiusError_mm, std::sqrt((r + wr) * (r + wr) + wt * wt) - r, 1e-6, 1e-12));
            QCOMPARE(st.radial.spindleChuck_mm, 0.0);
            QCOMPARE(st.radial.toolpost_mm, 0.0);
            QCOMPARE(st.radial.thermal_mm, 0.0);
        }
    }

    // The root correction (docs/solid-fe.md "Corrections"): the bar acts as built in 0.066 d inside
    // the chuck face, so its bending is that of a cantilever 0.066 d longer, F (a + e d)^3 / 3EI;
    // the shear and the feed force's moment M (a + e d)^2 / 2EI alike. Switched off, plain Timoshenko.
    void rootCorrectionOfACantilever()
    {
        const double r = 15.0, root = 0.066 * 30.0;
        const Project p = barProject(r, 240.0, ClampingMethod::Chuck, 40.0);
        DeviationOptions o;
        o.loadOverride = CuttingForces{500.0, 150.0, 200.0};
        o.workpieceOnly = true;
        o.inProcessSection = false;
        const DeviationResult res = computeDeviation(p, DataLibrary::builtIn(), o);
        QVERIFY2(res.inputs, qPrintable(dump(res.diagnostics)));
        QVERIFY(res.inputs->notes.join(QLatin1Char(' ')).contains(QStringLiteral("0.066 of its diameter")));
        const double I = kPi * std::pow(r, 4) / 4;
        const double A = kPi * r * r;
        for (const Station &st : feature(res, "O2").stations) {
            // At the face itself the root's own give (e d)^3 / 3EI, a millionth of the tip's, is not
            // in the beam: the face is the support's node.
            if (st.z_mm <= 40.0)
                continue;
            const double d = st.z_mm - 40.0, db = d + root;
            const double wr =
                200.0 * (db * db * db / (3 * kE * I) + d / (kKappaSolid * kG * A)) - 150.0 * r * db * db / (2 * kE * I);
            QVERIFY2(test::nearRelative(st.radial.total_mm(), wr, 1e-6, 1e-12), qPrintable(QString::number(st.z_mm)));
            QCOMPARE(st.radial.spindleChuck_mm, 0.0); // the root is the part's, not the machine's
        }
    }

    // The shoulder's hinge: the Ø40 → Ø25 cantilever of the solid-FE set (held 40, step 60 mm out,
    // tip 120 mm out), 1 kN at the tip. Timoshenko with two sections, the root 0.066 × 40 mm in,
    // and at the step a hinge of the compliance of e_s d of the thin section, e_s = 0.126 at
    // D/d = 1.6: F a_s^2 e_s d / (E I_d) with a_s = 60 mm from the step.
    void shoulderHingeOfASteppedCantilever()
    {
        const ProjectParseResult read =
            readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/tests/data/solid-fe/stepped-cantilever.tolturn"));
        QVERIFY(read.project);
        DeviationOptions o;
        o.loadOverride = CuttingForces{0.0, 0.0, 1000.0};
        o.workpieceOnly = true;
        o.inProcessSection = false;
        const DeviationResult res = computeDeviation(*read.project, DataLibrary::builtIn(), o);
        QVERIFY2(res.inputs, qPrintable(dump(res.diagnostics)));
        const double I1 = kPi * std::pow(20.0, 4) / 4, A1 = kPi * 400.0;
        const double I2 = kPi * std::pow(12.5, 4) / 4, A2 = kPi * 12.5 * 12.5;
        const double a = 120.0, as = 60.0, root = 0.066 * 40.0;
        const double plain = 1000.0 * ((a * a * a - as * as * as) / (3 * kE * I1) + as * as * as / (3 * kE * I2) +
                                       60.0 / (kKappaSolid * kG * A1) + 60.0 / (kKappaSolid * kG * A2));
        const double rootPart = 1000.0 * (root * root * root / 3 + a * root * root + a * a * root) / (kE * I1);
        const double hinge = 1000.0 * as * as * 0.126 * 25.0 / (kE * I2);
        const Station &tip = feature(res, "O4").stations.back();
        QCOMPARE(tip.z_mm, 160.0);
        QVERIFY2(test::nearRelative(tip.radial.total_mm(), plain + rootPart + hinge, 1e-6, 1e-12),
                 qPrintable(QStringLiteral("%1 vs %2").arg(tip.radial.total_mm()).arg(plain + rootPart + hinge)));
        QVERIFY(test::nearRelative(shoulderHingePerDiameter(1.4), 0.057 + 0.069 * 0.15 / 0.35, 1e-12));
        QCOMPARE(shoulderHingePerDiameter(1.0), 0.0);
        QCOMPARE(shoulderHingePerDiameter(3.0), 0.171); // beyond the runs: the last identified value
    }

    // With the in-process section the whole length between chuck and tool still carries the pass's
    // stock (feeding towards the chuck): the cantilever term uses radius r + ap.
    // Validity (issue 14): a bar that would spring further than the depth of cut is said to lie
    // beyond the linear model; a stiff one is not. A cantilever of Ø40 x L deflects F L³/(3EI)
    // (I = π 20⁴/4 = 125 664 mm⁴, E = 210 000 MPa): under a radial force of the order of 100 N
    // (Fp = 0.25 Fc, Fc some 400 N at f 0.2 mm, ap 1 mm) about 1 m at L = 10 m and 1 µm at 100 mm,
    // against the 1 mm depth of cut.
    void deflectionBeyondTheCutIsFlagged()
    {
        const auto flagged = [](double length) {
            const DeviationResult r =
                computeDeviation(barProject(20.0, length, ClampingMethod::Chuck, 40.0), DataLibrary::builtIn());
            return std::any_of(r.diagnostics.begin(), r.diagnostics.end(), [](const Diagnostic &d) {
                return d.message.contains(QLatin1String("would spring out of the cut"));
            });
        };
        QVERIFY(flagged(10000.0));
        QVERIFY(!flagged(100.0));
    }

    void inProcessSectionOfCantilever()
    {
        const double r = 12.0, ap = 1.0;
        const Project p = barProject(r, 200.0, ClampingMethod::Chuck, 30.0);
        DeviationOptions o;
        o.beamCorrections = false; // the closed form is plain Timoshenko theory
        o.loadOverride = CuttingForces{0.0, 0.0, 300.0};
        o.workpieceOnly = true;
        const DeviationResult res = computeDeviation(p, DataLibrary::builtIn(), o);
        QVERIFY(res.inputs);
        const double rs = r + ap;
        const double I = kPi * std::pow(rs, 4) / 4;
        const double A = kPi * rs * rs;
        for (const Station &st : feature(res, "O2").stations) {
            const double d = st.z_mm - 30.0;
            const double w = 300.0 * (d * d * d / (3 * kE * I) + d / (kKappaSolid * kG * A));
            QVERIFY2(test::nearRelative(st.radial.total_mm(), w, 1e-6, 1e-12), qPrintable(QString::number(st.z_mm)));
        }
    }

    // Measured spindle springs: the spindle–chuck contribution is the rigid-body polynomial of
    // Valiño et al. eq. 3 (z^2 and constant terms as printed, z term as derived), the workpiece
    // contribution the cantilever from the chuck face.
    void spindleChuckContribution()
    {
        const double r = 20.0;
        Project p = barProject(r, 260.0, ClampingMethod::Chuck, 60.0);
        p.characterisation.source = QStringLiteral("test");
        p.characterisation.pivotDistance_mm = 180.0;
        p.characterisation.spindleRadial = SpindleSprings{1.6e5, 1.28e9, 1.52e10};
        p.characterisation.spindleTangential = SpindleSprings{1.0e5, 1.5e9, 1.3e10};
        p.tool.overhang_mm = 40.0;
        DeviationOptions o;
        o.beamCorrections = false; // the closed form is plain Timoshenko theory
        o.loadOverride = CuttingForces{500.0, 150.0, 400.0};
        o.inProcessSection = false;
        const DeviationResult res = computeDeviation(p, DataLibrary::builtIn(), o);
        QVERIFY2(res.inputs, qPrintable(dump(res.diagnostics)));
        const double k1 = 1.6e5, k2 = 1.28e9, k3 = 1.52e10, Lc = 180.0, Fr = 400.0, FaD2 = 150.0 * r;
        const double I = kPi * std::pow(r, 4) / 4;
        const double A = kPi * r * r;
        for (const Station &st : feature(res, "O2").stations) {
            const double z = st.z_mm - 60.0;
            const double spindle = (Fr / k2 + Fr / k3) * z * z + (2 * Fr * Lc / k2 - FaD2 * (1 / k2 + 1 / k3)) * z +
                                   (Fr / k1 - FaD2 * Lc / k2 + Fr * Lc * Lc / k2);
            const double beam =
                Fr * (z * z * z / (3 * kE * I) + z / (kKappaSolid * kG * A)) - FaD2 * z * z / (2 * kE * I);
            QVERIFY2(test::nearRelative(st.radial.spindleChuck_mm, spindle, 1e-7), qPrintable(QString::number(z)));
            QVERIFY2(test::nearRelative(st.radial.workpiece_mm, beam, 1e-6, 1e-12), qPrintable(QString::number(z)));
            // Toolpost, eq. 5: 40 mm of a 25 x 25 mm steel shank, E = 210000 MPa.
            QVERIFY(test::nearRelative(st.radial.toolpost_mm, Fr * 40.0 / (625.0 * 210000.0), 1e-12));
        }
    }

    // Valiño et al. (2008) §III backwards: a test bar's deviation written by hand from known springs
    // (the spindle polynomial of docs/model.md §2, the Timoshenko cantilever over the in-process
    // section Ø2(r + ap) from the chuck face, and the toolpost's eq. 5) gives those springs back.
    void spindleSpringsFromATestBar()
    {
        const double r = 30.0, ap = 1.0, chuckFace = 30.0, Lc = 250.0;
        Project p = barProject(r, 130.0, ClampingMethod::Chuck, chuckFace);
        p.tool.overhang_mm = 40.0;
        const double Ft = 800.0, Fa = 300.0, Fr = 400.0;
        const SpindleSprings radial{2.0e5, 4.0e9, 1.5e9};
        const SpindleSprings tangential{3.0e5, 5.0e9, 2.0e9};
        const double rs = r + ap;
        const double I = kPi * std::pow(rs, 4) / 4;
        const double A = kPi * rs * rs;
        auto spindle = [Lc](const SpindleSprings &k, double F, double M, double x) {
            const double s = 1 / k.k2_Nmm_per_rad + 1 / k.k3_Nmm_per_rad;
            return F * s * x * x + (2 * F * Lc / k.k2_Nmm_per_rad + M * s) * x + F / k.k1_N_per_mm +
                   F * Lc * Lc / k.k2_Nmm_per_rad + M * Lc / k.k2_Nmm_per_rad;
        };
        std::vector<TestBarPoint> points;
        // The bar's bending as the beam has it, built in 0.066 of its diameter inside the chuck face
        // (the root correction, docs/solid-fe.md): the fitted springs are the machine's, net of it.
        const double root = 0.066 * 2.0 * rs;
        for (int i = 0; i < 10; ++i) {
            const double z = 35.0 + 10.0 * i;
            const double x = z - chuckFace;
            const double xb = x + root;
            const double bend = xb * xb * xb / (3 * kE * I) + x / (kKappaSolid * kG * A);
            const double toolpost = Fr * 40.0 / (625.0 * 210000.0);
            const double wr = spindle(radial, Fr, -Fa * r, x) + Fr * bend - Fa * r * xb * xb / (2 * kE * I) + toolpost;
            const double wt = spindle(tangential, Ft, 0.0, x) + Ft * bend;
            points.push_back({z, 1000.0 * wr, 1000.0 * wt});
        }
        const StiffnessCalibration cal =
            calibrateSpindleChuck(p, DataLibrary::builtIn(), points, Lc, CuttingForces{Ft, Fa, Fr});
        QVERIFY2(cal.radial && cal.tangential, qPrintable(dump(cal.diagnostics)));
        QCOMPARE(cal.diameter_mm, 60.0);
        const std::pair<const SpringFit &, const SpindleSprings &> fits[] = {{*cal.radial, radial},
                                                                             {*cal.tangential, tangential}};
        for (const auto &[fit, springs] : fits) {
            QVERIFY2(test::nearRelative(fit.springs.k1_N_per_mm, springs.k1_N_per_mm, 1e-4),
                     qPrintable(QString::number(fit.springs.k1_N_per_mm)));
            QVERIFY2(test::nearRelative(fit.springs.k2_Nmm_per_rad, springs.k2_Nmm_per_rad, 1e-4),
                     qPrintable(QString::number(fit.springs.k2_Nmm_per_rad)));
            QVERIFY2(test::nearRelative(fit.springs.k3_Nmm_per_rad, springs.k3_Nmm_per_rad, 1e-4),
                     qPrintable(QString::number(fit.springs.k3_Nmm_per_rad)));
            QVERIFY(fit.rmsResidual_um < 1e-4);
            QCOMPARE(fit.points, 10);
        }

        // Ten positions are redundant, three are not: the fit passes through them exactly, and
        // says that its zero residual tells nothing of the scatter.
        QVERIFY(!dump(cal.diagnostics).contains(QStringLiteral("three positions z fit")));
        const StiffnessCalibration exact = calibrateSpindleChuck(
            p, DataLibrary::builtIn(), {points[0], points[4], points[9]}, Lc, CuttingForces{Ft, Fa, Fr});
        QVERIFY(exact.radial && exact.radial->rmsResidual_um < 1e-9);
        QVERIFY2(dump(exact.diagnostics).contains(QStringLiteral("three positions z fit a z² + b z + c exactly")),
                 qPrintable(dump(exact.diagnostics)));

        // Tangential deviations at two positions only: the radial springs alone, and a warning
        // that says why the tangential ones are not fitted.
        std::vector<TestBarPoint> twoTangential = points;
        for (std::size_t i = 2; i < twoTangential.size(); ++i)
            twoTangential[i].tangential_um.reset();
        const StiffnessCalibration radialOnly =
            calibrateSpindleChuck(p, DataLibrary::builtIn(), twoTangential, Lc, CuttingForces{Ft, Fa, Fr});
        QVERIFY2(radialOnly.radial && !radialOnly.tangential, qPrintable(dump(radialOnly.diagnostics)));
        QCOMPARE(radialOnly.tangentialPositions, 2);
        QVERIFY2(dump(radialOnly.diagnostics).contains(QStringLiteral("tangential_um is given at 2 positions z")),
                 qPrintable(dump(radialOnly.diagnostics)));

        // A tangential deviation that falls away from the chuck is no spring system: an error, and
        // then not even the radial springs are returned.
        std::vector<TestBarPoint> falling = points;
        for (TestBarPoint &pt : falling)
            pt.tangential_um = 20.0 - 0.1 * (pt.z_mm - chuckFace);
        const StiffnessCalibration failed =
            calibrateSpindleChuck(p, DataLibrary::builtIn(), falling, Lc, CuttingForces{Ft, Fa, Fr});
        QVERIFY2(dump(failed.diagnostics).contains(QStringLiteral("tangential fit gives k")),
                 qPrintable(dump(failed.diagnostics)));
        QVERIFY(!failed.radial && !failed.tangential);

        // Tangential springs fitted for another Lc do not hold at this one: a radial-only fit at
        // Lc 250 removes those of Lc 200, and keeps those of Lc 250.
        MachineCharacterisation before;
        before.pivotDistance_mm = 200.0;
        before.spindleRadial = radial;
        before.spindleTangential = tangential;
        QVERIFY(staleTangentialSprings(before, radialOnly).contains(QStringLiteral("Lc = 200 mm")));
        const MachineCharacterisation after = withFittedSprings(before, radialOnly, QStringLiteral("test"));
        QVERIFY(!after.spindleTangential);
        QCOMPARE(*after.pivotDistance_mm, Lc);
        before.pivotDistance_mm = Lc;
        QVERIFY(staleTangentialSprings(before, radialOnly).isEmpty());
        QVERIFY(withFittedSprings(before, radialOnly, QStringLiteral("test")).spindleTangential == tangential);

        // A project measured radially only says what it takes tangentially.
        p.characterisation = after;
        const DeviationResult measured = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY(measured.inputs);
        QVERIFY2(measured.inputs->notes.join(QLatin1Char('\n')).contains(QStringLiteral("rigid tangentially")),
                 qPrintable(measured.inputs->notes.join(QLatin1Char('\n'))));
        p.characterisation.spindleTangential = tangential;
        QVERIFY(!computeDeviation(p, DataLibrary::builtIn(), {})
                     .inputs->notes.join(QLatin1Char('\n'))
                     .contains(QStringLiteral("rigid tangentially")));
    }

    // Without a tangential column only the radial springs are fitted; a deviation that shrinks
    // away from the chuck is no spring system, and the error names the spring and its value.
    void testBarFitRefusesWhatIsNoSpring()
    {
        Project p = barProject(30.0, 130.0, ClampingMethod::Chuck, 30.0);
        std::vector<TestBarPoint> points;
        for (int i = 0; i < 5; ++i) {
            const double z = 40.0 + 20.0 * i;
            points.push_back({z, 20.0 - 0.1 * (z - 30.0), std::nullopt}); // 20 um at the chuck, falling
        }
        const StiffnessCalibration cal =
            calibrateSpindleChuck(p, DataLibrary::builtIn(), points, 200.0, CuttingForces{800.0, 300.0, 400.0});
        QVERIFY(!cal.radial && !cal.tangential);
        QVERIFY2(dump(cal.diagnostics).contains(QStringLiteral("which is not a spring")),
                 qPrintable(dump(cal.diagnostics)));
        QVERIFY(dump(cal.diagnostics).contains(QStringLiteral("radial fit gives k")));

        p.clamping.method = ClampingMethod::ChuckTailstock;
        const StiffnessCalibration held = calibrateSpindleChuck(p, DataLibrary::builtIn(), points, 200.0);
        QVERIFY(!held.radial);
        QCOMPARE(held.diagnostics.front().field, QStringLiteral("clamping.method"));
        p.clamping.method = ClampingMethod::Chuck;
        const StiffnessCalibration twoPoints =
            calibrateSpindleChuck(p, DataLibrary::builtIn(), {points[0], points[1]}, 200.0);
        QVERIFY(dump(twoPoints.diagnostics).contains(QStringLiteral("three or more positions z, but there are 2")));
        const StiffnessCalibration offBar =
            calibrateSpindleChuck(p, DataLibrary::builtIn(), {points[0], points[1], {150.0, 1.0, {}}}, 200.0);
        QVERIFY(dump(offBar.diagnostics).contains(QStringLiteral("z = 150 mm is not on the turned outer surface")));
    }

    void testBarMeasurementFile()
    {
        const TestBarReadResult reordered = parseTestBarMeasurements(
            QStringLiteral("# bar 1\nradial_um;z_mm\n12.5;40\n13.5;50\n"), QStringLiteral("bar.csv"));
        QVERIFY2(reordered.points, qPrintable(dump(reordered.diagnostics)));
        QCOMPARE(reordered.points->at(1).z_mm, 50.0);
        QCOMPARE(reordered.points->at(1).radial_um, 13.5);
        const TestBarReadResult good = parseTestBarMeasurements(
            QStringLiteral("z_mm,radial_um,tangential_um\n40,12.5,\n50,13.5,4\n"), QStringLiteral("bar.csv"));
        QVERIFY2(good.points, qPrintable(dump(good.diagnostics)));
        QCOMPARE(good.points->size(), std::size_t(2));
        QCOMPARE(good.points->at(0).radial_um, 12.5);
        QVERIFY(!good.points->at(0).tangential_um);
        QCOMPARE(good.points->at(1).tangential_um.value_or(0.0), 4.0);
        const TestBarReadResult bad =
            parseTestBarMeasurements(QStringLiteral("z_mm,radial_um\n40,abc\n"), QStringLiteral("bar.csv"));
        QVERIFY(!bad.points);
        QCOMPARE(bad.diagnostics.front().field, QStringLiteral("bar.csv:2"));
        QVERIFY(bad.diagnostics.front().message.contains(QStringLiteral("radial_um must be a number, not \"abc\"")));
        // A semicolon file with decimal commas: the cells are the header's (z 40, radial 12.5), not
        // "12" and "5" with the "5" dropped.
        const TestBarReadResult decimalCommas =
            parseTestBarMeasurements(QStringLiteral("z_mm;radial_um\n40;12,5\n50;13,5\n"), QStringLiteral("bar.csv"));
        QVERIFY(!decimalCommas.points);
        QCOMPARE(decimalCommas.diagnostics.front().field, QStringLiteral("bar.csv:2"));
        QVERIFY2(decimalCommas.diagnostics.front().message.contains(
                     QStringLiteral("radial_um must be a number with a decimal point, not \"12,5\"")),
                 qPrintable(dump(decimalCommas.diagnostics)));
        // A comma file whose line has a cell more than the header is refused, not cut to the header.
        const TestBarReadResult extraCell =
            parseTestBarMeasurements(QStringLiteral("z_mm,radial_um\n40,12,5\n50,13.5,\n"), QStringLiteral("b.csv"));
        QVERIFY(!extraCell.points);
        QCOMPARE(extraCell.diagnostics.size(), std::size_t(1));
        QVERIFY2(extraCell.diagnostics.front().message.contains(QStringLiteral("the line has 3 cells, the header 2")),
                 qPrintable(dump(extraCell.diagnostics)));
        // A column named twice is refused, not read from the first of them.
        const TestBarReadResult twice = parseTestBarMeasurements(
            QStringLiteral("z_mm,radial_um,radial_um\n40,12.5,13.5\n"), QStringLiteral("b.csv"));
        QVERIFY(!twice.points);
        QVERIFY2(twice.diagnostics.front().message.contains(
                     QStringLiteral("names the column \"radial_um\" twice, as columns 2 and 3")),
                 qPrintable(dump(twice.diagnostics)));
        // Lines ended by CR alone (old Mac spreadsheets) are lines: two points, the second on line 3.
        const TestBarReadResult crOnly =
            parseTestBarMeasurements(QStringLiteral("z_mm,radial_um\r40,12.5\r50,abc\r"), QStringLiteral("b.csv"));
        QVERIFY(!crOnly.points);
        QCOMPARE(crOnly.diagnostics.front().field, QStringLiteral("b.csv:3"));
        const TestBarReadResult crLf =
            parseTestBarMeasurements(QStringLiteral("z_mm,radial_um\r\n40,12.5\r\n50,13\r\n"), QStringLiteral("b.csv"));
        QVERIFY2(crLf.points && crLf.points->size() == 2, qPrintable(dump(crLf.diagnostics)));
        QCOMPARE(crLf.points->at(1).radial_um, 13.0);
        const TestBarReadResult header =
            parseTestBarMeasurements(QStringLiteral("z,radial_um\n"), QStringLiteral("b.csv"));
        QVERIFY(header.diagnostics.front().message.contains(QStringLiteral("lacks the column \"z_mm\"")));
    }

    // Between sprung centres: simply supported beam plus the spring motion of the supports,
    //   w = F [a^2 b^2/(3 E I L) + a b/(L k G A)] + F [(b/L)^2/k_l + (a/L)^2/k_r],  b = L - a.
    void betweenSprungCentres()
    {
        const double r = 16.0, L = 480.0, kl = 3.0e4, kr = 2.0e4;
        Project p = barProject(r, L, ClampingMethod::BetweenCentres, 0.0);
        p.characterisation.source = QStringLiteral("test");
        p.characterisation.centres = SupportStiffness{kl, kl};
        p.characterisation.tailstock = SupportStiffness{kr, kr};
        DeviationOptions o;
        o.loadOverride = CuttingForces{0.0, 0.0, 250.0};
        o.inProcessSection = false;
        const DeviationResult res = computeDeviation(p, DataLibrary::builtIn(), o);
        QVERIFY2(res.inputs, qPrintable(dump(res.diagnostics)));
        const double I = kPi * std::pow(r, 4) / 4;
        const double A = kPi * r * r;
        for (const Station &st : feature(res, "O2").stations) {
            const double a = st.z_mm, b = L - a;
            const double beam = 250.0 * (a * a * b * b / (3 * kE * I * L) + a * b / (L * kKappaSolid * kG * A));
            const double springs = 250.0 * ((b / L) * (b / L) / kl + (a / L) * (a / L) / kr);
            QVERIFY2(test::nearRelative(st.radial.workpiece_mm, beam, 1e-6, 1e-12), qPrintable(QString::number(a)));
            QVERIFY2(test::nearRelative(st.radial.spindleChuck_mm, springs, 1e-6), qPrintable(QString::number(a)));
        }
    }

    // Kienzle forces in the pipeline: C45E-N (kc1.1 = 1500, mc = 0.22; ISCAR 2022 group 2) with a
    // PCLNR holder (kappa_r = 95°) and a CNMG 120408 insert (r_n = 0.8 mm), f = 0.2, ap = 1 (below
    // 5 r_n: on the nose, docs/model.md §3). Li & Du eq. 20: tan(gamma_Le) = 0.5053 tan(-5°)
    // + 1.0473 (0.2/0.8) + 0.4654 (0.8/1) = -0.044208 + 0.261825 + 0.372320 = 0.589937, so
    // kappa_eq = 90° - 30.538° = 59.462°; h = 0.2 sin(kappa_eq) = 0.172259, b = 1/sin(kappa_eq) =
    // 1.161045; Fc = 1500 * 1.161045 * 0.172259^0.78 = 441.73 N. Rule-of-thumb thrust (0.5, 0.25) Fc
    // = 493.88 N turned by 95° - 59.462°: Ff = 115.54 N, Fp = 218.24 N.
    void kienzleForcesFromTheLibrary()
    {
        const DeviationResult res =
            computeDeviation(barProject(15.0, 200.0, ClampingMethod::Chuck, 40.0), DataLibrary::builtIn(), {});
        QVERIFY2(res.inputs, qPrintable(dump(res.diagnostics)));
        QVERIFY2(test::nearRelative(res.inputs->forces.tangential_N, 441.73, 2e-5),
                 qPrintable(QString::number(res.inputs->forces.tangential_N)));
        QVERIFY(test::nearRelative(res.inputs->forces.axial_N, 115.54, 5e-5));
        QVERIFY(test::nearRelative(res.inputs->forces.radial_N, 218.24, 5e-5));
        QVERIFY(res.inputs->notes.join(QLatin1Char(' '))
                    .contains(QStringLiteral("E. Isakov, 'Calculated forces when turning'")));
        // Ra = f^2/(32 r_eps) with r_eps = 0.8 mm from "CNMG 120408".
        QVERIFY(test::nearRelative(res.theoreticalRa_um, 1.5625, 1e-12));
    }

    // The free end face of a Ø30 bar, 160 mm out of a rigid chuck, cut by a facing pass the way the
    // finishing program cuts it, outwards from the centre (Euler–Bernoulli section rotation; shear
    // does not turn the section). The feed force Ff = 100 N loads it radially towards the tool,
    // theta_F = -Ff L²/(2EI) = -100 x 160²/(2 x 210000 x 39760.78) = -1.53297e-4; the passive force
    // Fp = 300 N pushes it towards the chuck at the contact radius rho on the tool's side, which turns
    // it the same way: theta_M = -Fp rho L/(EI) = -5.74867e-6 rho. The face point cut at rho is left
    // u = -rho (1.53297e-4 + 5.74867e-6 rho) out of plane: 0 at the centre, -3.59290 µm at the rim.
    // So e = 3.59290 µm and the mean tilt 3.59290e-3/15 = 2.39527e-4.
    void facingCutLeavesAFaceOutOfPlane()
    {
        const Project p = barProject(15.0, 200.0, ClampingMethod::Chuck, 40.0);
        DeviationOptions o;
        o.beamCorrections = false;                           // the closed form is plain Timoshenko theory
        o.loadOverride = CuttingForces{500.0, 100.0, 300.0}; // Fc, Ff, Fp of the pass
        o.workpieceOnly = true;
        o.inProcessSection = false;
        const DeviationResult res = computeDeviation(p, DataLibrary::builtIn(), o);
        QVERIFY2(res.inputs, qPrintable(dump(res.diagnostics)));
        const auto end = std::find_if(res.faces.begin(), res.faces.end(),
                                      [](const FaceConicity &f) { return f.featureId == QLatin1String("O3"); });
        QVERIFY(end != res.faces.end());
        QVERIFY2(test::nearRelative(end->axialRunout_mm * 1000.0, 3.59290, 2e-5),
                 qPrintable(QString::number(end->axialRunout_mm)));
        QVERIFY2(test::nearRelative(std::abs(end->tanTheta), 2.39527e-4, 2e-5),
                 qPrintable(QString::number(end->tanTheta)));
    }

    // First-order warm-up along the pass (docs/model.md §5): drift = (a_n n/1000 + a_T (T - T_ref))
    // (1 - exp(-t/tau)), t the time since start when the tool passes z. Ø30 at 200 m/min:
    // n = 1000*200/(pi*30) = 2122.07 rpm; a_n = 4 µm/1000 rpm, a_T = 0.5 µm/K, T = 24 °C, T_ref = 20 °C,
    // tau = 30 min. The pass starts at the right end (z = 200) at t = 30 min: (8.48826 + 2)(1 - 1/e)
    // = 6.62985 µm; at f = 0.2 mm/rev the tool moves 0.2 x 2122.07 = 424.41 mm/min, so it reaches the
    // chuck face (z = 40) 160/424.41 = 0.37699 min later: 10.48826 (1 - exp(-30.37699/30)) = 6.67803 µm.
    // One diameter, one speed: the drift in between follows the same exponential.
    void thermalWarmUp()
    {
        Project p = barProject(15.0, 200.0, ClampingMethod::Chuck, 40.0);
        p.characterisation.source = QStringLiteral("test");
        p.characterisation.thermal = ThermalDrift{4.0, 0.5, 20.0, 30.0};
        p.environment.timeSinceStart_min = 30.0;
        p.environment.ambientTemperature_C = 24.0;
        const DeviationResult res = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY2(res.inputs, qPrintable(dump(res.diagnostics)));
        const std::vector<Station> &stations = feature(res, "O2").stations;
        QVERIFY(test::nearRelative(stations.back().radial.thermal_mm * 1000.0, 6.62985, 1e-5));
        QVERIFY2(test::nearRelative(stations.front().radial.thermal_mm * 1000.0, 6.67803, 1e-5),
                 qPrintable(QString::number(stations.front().radial.thermal_mm)));
        const double n = 2122.0659;
        for (const Station &st : stations) {
            QVERIFY(test::nearRelative(st.spindleSpeed_rpm, n, 1e-7));
            const double t = 30.0 + (200.0 - st.z_mm) / (0.2 * n);
            QVERIFY2(test::nearRelative(st.radial.thermal_mm * 1000.0, 10.48826 * (1.0 - std::exp(-t / 30.0)), 1e-5),
                     qPrintable(QString::number(st.z_mm)));
        }
    }

    // The same machine without the shop's conditions: not a cold machine at 20 °C (no drift at the
    // start), but one warmed through, 10 tau = 300 min, at the reference temperature, so every
    // station drifts by the steady a_n n/1000 = 4 x 2.1220659 = 8.48826 µm, less e^-10 of it; and
    // both results and `check` say what was taken.
    void thermalWithoutShopConditionsIsWarm()
    {
        Project p = barProject(15.0, 200.0, ClampingMethod::Chuck, 40.0);
        p.characterisation.source = QStringLiteral("test");
        p.characterisation.thermal = ThermalDrift{4.0, 0.5, 20.0, 30.0};
        const DeviationResult res = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY2(res.inputs, qPrintable(dump(res.diagnostics)));
        const double steady = 4.0 * 2.1220659; // reached to within e^-10 = 4.5e-5 of it
        for (const Station &st : feature(res, "O2").stations)
            QVERIFY2(test::nearRelative(st.radial.thermal_mm * 1000.0, steady, 1e-4),
                     qPrintable(QString::number(st.radial.thermal_mm * 1000.0)));
        QVERIFY(res.inputs->notes.join(QLatin1Char(' ')).contains(QStringLiteral("warmed through, 300 min")));
        QVERIFY(res.inputs->notes.join(QLatin1Char(' ')).contains(QStringLiteral("reference, 20 °C")));
        const Diagnostics checked = validateProject(p);
        for (const char *field : {"environment.time_since_start_min", "environment.ambient_temperature_C"})
            QVERIFY2(std::any_of(checked.begin(), checked.end(),
                                 [field](const Diagnostic &d) {
                                     return d.field == QLatin1String(field) && d.severity == Severity::Warning;
                                 }),
                     field);
    }

    void examplesComputeWithoutErrors_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("shaft") << QStringLiteral("stepped-shaft-chuck.tolturn");
        QTest::newRow("sleeve") << QStringLiteral("hollow-sleeve-tailstock.tolturn");
        QTest::newRow("long shaft") << QStringLiteral("long-shaft-centres.tolturn");
    }

    void examplesComputeWithoutErrors()
    {
        QFETCH(QString, file);
        const ProjectParseResult read =
            readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/") + file);
        QVERIFY(read.project);
        const DeviationResult res = computeDeviation(*read.project, DataLibrary::builtIn(), {});
        QVERIFY2(res.inputs && !hasErrors(res.diagnostics), qPrintable(dump(res.diagnostics)));
        QVERIFY(!res.features.empty());
        for (const FeatureDeviation &f : res.features) {
            for (const Station &st : f.stations)
                QVERIFY(std::isfinite(st.radiusError_mm));
        }
    }

    void badInput_data()
    {
        QTest::addColumn<QString>("what");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("fragment");
        QTest::newRow("material") << QStringLiteral("material") << QStringLiteral("material")
                                  << QStringLiteral("unknown material \"unobtainium\"");
        QTest::newRow("machine") << QStringLiteral("machine") << QStringLiteral("machine")
                                 << QStringLiteral("unknown machine \"lathe-9000\"");
        QTest::newRow("insert") << QStringLiteral("insert") << QStringLiteral("tool.insert")
                                << QStringLiteral("position 1 (shape) 'Q'");
        QTest::newRow("holder") << QStringLiteral("holder") << QStringLiteral("tool.holder")
                                << QStringLiteral("holder \"XYZ\"");
        QTest::newRow("no pass") << QStringLiteral("passes") << QStringLiteral("passes")
                                 << QStringLiteral("there is no cutting pass");
        QTest::newRow("Poisson") << QStringLiteral("poisson") << QStringLiteral("material")
                                 << QStringLiteral("no Poisson's ratio");
    }

    void badInput()
    {
        QFETCH(QString, what);
        QFETCH(QString, field);
        QFETCH(QString, fragment);
        Project p = barProject(15.0, 200.0, ClampingMethod::Chuck, 40.0);
        if (what == QLatin1String("material"))
            p.materialId = QStringLiteral("unobtainium");
        else if (what == QLatin1String("machine"))
            p.machineId = QStringLiteral("lathe-9000");
        else if (what == QLatin1String("insert"))
            p.tool.insertCode = QStringLiteral("QNMG 120408");
        else if (what == QLatin1String("holder"))
            p.tool.holderCode = QStringLiteral("XYZ");
        else if (what == QLatin1String("passes"))
            p.passes.clear();
        else if (what == QLatin1String("poisson"))
            p.materialId = QStringLiteral("CuZn39Pb3"); // the data give no nu for this brass
        const DeviationResult res = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY(!res.inputs);
        QVERIFY(hasErrors(res.diagnostics));
        QCOMPARE(res.diagnostics.front().field, field);
        QVERIFY2(res.diagnostics.front().message.contains(fragment), qPrintable(res.diagnostics.front().message));
    }

    // Li & Du outside its stated range: a warning naming the range, the result still computed.
    void liDuValidityWarning()
    {
        Project p = barProject(15.0, 200.0, ClampingMethod::Chuck, 40.0);
        p.cuttingModel.forceModel = ForceModel::LiDu;
        p.cuttingModel.normalPressure_MPa = 2200.0;
        p.cuttingModel.frictionRatio = 0.5;
        p.passes.front().depthOfCut_mm = 0.3; // eq. 20 holds for 0.5 < d < 5 mm
        const DeviationResult res = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY2(res.inputs, qPrintable(dump(res.diagnostics)));
        QVERIFY(!hasErrors(res.diagnostics));
        QVERIFY(dump(res.diagnostics).contains(QStringLiteral("depth of cut [mm] = 0.3 is outside the range 0.5")));
    }

    void builtInDataIsComplete()
    {
        const DataLibrary &data = DataLibrary::builtIn();
        QVERIFY2(data.diagnostics().empty(), qPrintable(dump(data.diagnostics())));
        QVERIFY(data.materials().size() >= 10);
        for (const MaterialData &m : data.materials()) {
            for (const QString &key :
                 {m.youngsModulus_MPa.source, m.density_kg_m3.source, m.kc11_MPa.source, m.mc.source})
                QVERIFY2(!data.sourceText(key).isEmpty(), qPrintable(m.id + QLatin1Char(' ') + key));
            QVERIFY(m.kc11_MPa.value > 300.0 && m.kc11_MPa.value < 5000.0);
            QVERIFY(m.mc.value > 0.0 && m.mc.value < 1.0);
        }
        QVERIFY(data.holder(QStringLiteral("pclnr2525m12")) != nullptr);
        QCOMPARE(data.styleEnteringAngle(QLatin1Char('L'))->value, 95.0);
    }
};

QTEST_GUILESS_MAIN(TestDeviation)
#include "tst_deviation.moc"
