// SPDX-License-Identifier: GPL-3.0-or-later
// Verdicts on a machine whose chuck stiffness is a published range, and the stiffness a tolerance
// needs, against the closed form of a bar in a chuck held by one root spring.
#include "tests/core/test_support.h"

#include "core/io/project_file.h"
#include "core/tolerance/range_verdicts.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace tolturn;

namespace {

using test::seg;

constexpr double kPi = std::numbers::pi;
constexpr double kE = test::kSteelE_MPa;
constexpr double kG = test::kSteelG_MPa;
constexpr double kKappaSolid = test::kKappaSolidCircle;
// machines.json "uncharacterised_supports": Ito (2008), 66 and 216 N/µm.
constexpr double kCompliant = 66000.0;
constexpr double kStiff = 216000.0;

// A Ø30 bar of C45E-N, 140 mm long, 40 mm of it in the chuck jaws: 100 mm from the chuck face to
// its free end. Its diameter O2 carries explicit limits ±t/2.
Project chuckedBar(double zone_um)
{
    Project p;
    p.part.name = QStringLiteral("bar");
    p.part.stockDiameter_mm = 34.0;
    p.part.outer.segments = {seg("O1", SegmentKind::Face, {0, 0}, {0, 15}),
                             seg("O2", SegmentKind::Cylinder, {0, 15}, {140, 15}),
                             seg("O3", SegmentKind::Face, {140, 15}, {140, 0})};
    p.materialId = QStringLiteral("C45E-N");
    p.machineId = QStringLiteral("haas-st-20");
    p.tool.insertCode = QStringLiteral("CNMG 120408");
    p.tool.holderCode = QStringLiteral("PCLNR 2525M12");
    p.tool.overhang_mm = 40.0;
    p.clamping = {ClampingMethod::Chuck, 40.0};
    p.passes = {{PassKind::Finishing, 200.0, 0.1, 0.5}};
    Tolerance t;
    t.id = QStringLiteral("T1");
    t.type = ToleranceType::Diameter;
    t.featureId = QStringLiteral("O2");
    t.upperDeviation_um = 0.5 * zone_um;
    t.lowerDeviation_um = -0.5 * zone_um;
    p.tolerances = {t};
    return p;
}

DeviationOptions radialLoad(double force_N)
{
    DeviationOptions o;
    o.beamCorrections = false;                         // the closed form is plain Timoshenko theory
    o.loadOverride = CuttingForces{0.0, 0.0, force_N}; // tangential, axial, radial
    o.inProcessSection = false;
    return o;
}

// The closed form. With the tool at distance d from the chuck face the radius grows by
//   F/K + F l/(A E) + F (d^3/(3 E I) + d/(kappa G A))
// (root spring K, the holder's 40 mm of 25 x 25 mm² shank in compression, Valiño eq. 5, and the
// Timoshenko cantilever). Programmed at the middle of the zone ±t/2, the diameter passes while
// twice the largest of these, at d = 100 mm, is at most t/2; so the smallest K is
//   K = F / (t/4 - F (l/(A E) + w(100))).
constexpr double kToolpost_mm_per_N = 40.0 / (625.0 * 210000.0); // l/(AE)

double barAt100_mm_per_N() // w(100)
{
    const double r = 15.0;
    const double I = kPi * std::pow(r, 4) / 4;
    const double A = kPi * r * r;
    const double d = 100.0;
    return d * d * d / (3 * kE * I) + d / (kKappaSolid * kG * A);
}

// The one offset for both ends of the range (passesOnAnyAndFailsOnStiffest works it out): the sizes
// run from 2F (1/K_stiff + l/(AE)) to 2F (1/K_compliant + l/(AE) + w(100)), centred about zero by
// -F (1/K_stiff + 1/K_compliant + 2 l/(AE) + w(100)) [µm].
double offsetForBothEnds_um(double force_N)
{
    return -1000.0 * force_N * (1.0 / kStiff + 1.0 / kCompliant + 2.0 * kToolpost_mm_per_N + barAt100_mm_per_N());
}

double requiredK(double force_N, double zone_mm)
{
    return force_N / (zone_mm / 4 - force_N * (kToolpost_mm_per_N + barAt100_mm_per_N()));
}

} // namespace

class TestRangeVerdicts : public QObject {
    Q_OBJECT
private Q_SLOTS:

    // t = 40 µm under 200 N: K = 200 / (0.010 - 0.008440) = 128.2 N/µm, inside 66–216 N/µm: the
    // diameter passes only on a machine stiffer than that.
    void requiredChuckStiffnessOfABar()
    {
        const double k = requiredK(200.0, 0.040);
        QVERIFY2(k > kCompliant && k < kStiff, qPrintable(QString::number(k)));
        const RangeEvaluation r = evaluateOverStiffnessRange(chuckedBar(40.0), DataLibrary::builtIn(), radialLoad(200));
        QVERIFY(r.machineIsRange);
        QCOMPARE(int(r.tolerances.size()), 1);
        const ToleranceRangeEvaluation &e = r.tolerances.front();
        QCOMPARE(e.range, RangeVerdict::PassesIfStiffer);
        QVERIFY(e.chuck && e.chuck->kind == RequiredStiffness::Kind::Found);
        QVERIFY2(std::abs(e.chuck->value_N_per_mm / k - 1.0) < 0.005,
                 qPrintable(QStringLiteral("%1 vs %2").arg(e.chuck->value_N_per_mm).arg(k)));
        QVERIFY(!e.tailstock); // no tailstock in a chuck
        QCOMPARE(e.compliant.verdict, Verdict::PassesAfterOffset);
        QCOMPARE(e.stiff->verdict, Verdict::PassesAsProgrammed);
        // The sizes of both ends span 21.0 µm, within 40: one offset holds it on any machine too.
        QVERIFY(e.offsetOnAnyMachine_um);
        QVERIFY2(std::abs(*e.offsetOnAnyMachine_um / offsetForBothEnds_um(200.0) - 1.0) < 0.01,
                 qPrintable(QString::number(*e.offsetOnAnyMachine_um)));
        QVERIFY2(rangeVerdictText(e).endsWith(
                     QStringLiteral("; an offset of %1 µm on the diameter holds it on any machine in the range")
                         .arg(*e.offsetOnAnyMachine_um, 0, 'f', 1)),
                 qPrintable(rangeVerdictText(e)));
        // The offset is a change of the programmed size, whatever the zone's place: the same with
        // limits 0/-40 µm (programmed at -20) as with ±20.
        Project h = chuckedBar(40.0);
        h.tolerances.front().upperDeviation_um = 0.0;
        h.tolerances.front().lowerDeviation_um = -40.0;
        const RangeEvaluation shifted = evaluateOverStiffnessRange(h, DataLibrary::builtIn(), radialLoad(200));
        QVERIFY(shifted.tolerances.front().offsetOnAnyMachine_um);
        QVERIFY2(std::abs(*shifted.tolerances.front().offsetOnAnyMachine_um / offsetForBothEnds_um(200.0) - 1.0) < 0.01,
                 qPrintable(QString::number(*shifted.tolerances.front().offsetOnAnyMachine_um)));
    }

    // The other verdicts: with t = 60 µm the bar needs only 200 / (0.015 - 0.008440) = 30.5 N/µm,
    // below the range; with t = 36 µm, 200 / (0.009 - 0.008440) = 357 N/µm, above it.
    // Above the range, one constant offset may still hold it on every machine of the range. The
    // diameter grows by 2F (1/K + l/(AE)) at the chuck face and by 2F w(100) more at the free end, so
    // over both ends from 2F (1/K_stiff + l/(AE)) to 2F (1/K_compliant + l/(AE) + w(100)): a spread
    // of 2F (1/K_compliant - 1/K_stiff + w(100)) = 21.0 µm, which fits 36 µm, centred about zero by
    // an offset of -F (1/K_stiff + 1/K_compliant + 2 l/(AE) + w(100)) = -12.5 µm; it does not fit 20.
    void passesOnAnyAndFailsOnStiffest()
    {
        const RangeEvaluation loose =
            evaluateOverStiffnessRange(chuckedBar(60.0), DataLibrary::builtIn(), radialLoad(200));
        QCOMPARE(loose.tolerances.front().range, RangeVerdict::PassesOnAnyMachine);
        QVERIFY(std::abs(loose.tolerances.front().chuck->value_N_per_mm / requiredK(200, 0.060) - 1.0) < 0.005);
        const RangeEvaluation tight =
            evaluateOverStiffnessRange(chuckedBar(36.0), DataLibrary::builtIn(), radialLoad(200));
        const ToleranceRangeEvaluation &offset = tight.tolerances.front();
        QCOMPARE(offset.range, RangeVerdict::PassesAfterOffsetOnAnyMachine);
        QVERIFY(std::abs(offset.chuck->value_N_per_mm / requiredK(200, 0.036) - 1.0) < 0.005);
        QCOMPARE(rangeVerdictKeyword(offset.range), QStringLiteral("passes_after_offset_on_any_machine"));
        const double f = 200.0;
        const double w100 = barAt100_mm_per_N();
        const double spread_um = 2000.0 * f * (1.0 / kCompliant - 1.0 / kStiff + w100);
        QVERIFY2(std::abs(spread_um - 21.0) < 0.1, qPrintable(QString::number(spread_um)));
        const double expected_um = offsetForBothEnds_um(f);
        QVERIFY2(std::abs(*offset.offsetOnAnyMachine_um - expected_um) < 0.01 * std::abs(expected_um),
                 qPrintable(QStringLiteral("%1 vs %2").arg(*offset.offsetOnAnyMachine_um).arg(expected_um)));
        QCOMPARE(rangeVerdictText(offset),
                 QStringLiteral("fails as programmed; an offset of %1 µm on the diameter holds it on any machine in "
                                "the range")
                     .arg(*offset.offsetOnAnyMachine_um, 0, 'f', 1));
        // Each end alone fits 20 µm after its own offset (its spread 2F w(100) = 16.8 µm); both do not.
        const RangeEvaluation tighter =
            evaluateOverStiffnessRange(chuckedBar(20.0), DataLibrary::builtIn(), radialLoad(200));
        const ToleranceRangeEvaluation &fails = tighter.tolerances.front();
        QCOMPARE(fails.compliant.verdict, Verdict::PassesAfterOffset);
        QCOMPARE(fails.stiff->verdict, Verdict::PassesAfterOffset);
        QCOMPARE(fails.range, RangeVerdict::FailsEvenOnStiffest);
        QVERIFY(!fails.offsetOnAnyMachine_um);
        QCOMPARE(rangeVerdictKeyword(fails.range), QStringLiteral("fails_even_on_stiffest"));
    }

    // A stiffer chuck does not always help: with a tailstock pin at the far end, the chuck's give lets
    // the sleeve pivot, and the cylindricity of a heavy finishing cut (a_p 2 mm, f 0.3 mm) is least at
    // a middling stiffness. The search reports the window in which 2 µm holds, and each of its
    // edges is where the verdict changes when the chuck stiffness is set directly.
    void stifferIsNotAlwaysBetter()
    {
        const ProjectParseResult read =
            readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/hollow-sleeve-tailstock.tolturn"));
        QVERIFY(read.project);
        Project p = *read.project;
        p.passes.back().depthOfCut_mm = 2.0;
        p.passes.back().feed_mm_rev = 0.3;
        for (Tolerance &t : p.tolerances) {
            if (t.id == QLatin1String("T2"))
                t.zone_um = 2.0;
        }
        // The search itself is under test, on the plain beam whose window this zone was chosen for.
        DeviationOptions plain;
        plain.beamCorrections = false;
        const RangeEvaluation r = evaluateOverStiffnessRange(p, DataLibrary::builtIn(), plain);
        const auto t2 = std::find_if(r.tolerances.begin(), r.tolerances.end(), [](const ToleranceRangeEvaluation &e) {
            return e.compliant.toleranceId == QLatin1String("T2");
        });
        QVERIFY(t2 != r.tolerances.end() && t2->chuck);
        QCOMPARE(t2->chuck->kind, RequiredStiffness::Kind::Window);
        QVERIFY(t2->chuck->value_N_per_mm < t2->chuck->upper_N_per_mm);
        const auto verdictAt = [&](double k) {
            DeviationOptions o = plain;
            o.chuckStiffness_N_per_mm = k;
            const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), o);
            return evaluateTolerances(p, d).at(static_cast<std::size_t>(t2 - r.tolerances.begin())).verdict;
        };
        QVERIFY(verdictAt(0.99 * t2->chuck->value_N_per_mm) != Verdict::PassesAsProgrammed);
        QCOMPARE(verdictAt(1.01 * t2->chuck->value_N_per_mm), Verdict::PassesAsProgrammed);
        QVERIFY(verdictAt(t2->chuck->upper_N_per_mm) != Verdict::PassesAsProgrammed);
    }

    // A bore is cut by the boring bar's insert at its own forces, and the chuck's spring moves the
    // part by those forces: the stiffness a bore's tolerance needs is where its verdict changes when
    // the chuck stiffness is set directly and the whole model is run again (the valve body's two
    // bores are cut at conditions whose forces differ from the turning tool's by some 5 %).
    void requiredChuckStiffnessOfABoreIsTheFullModels()
    {
        const ProjectParseResult read =
            readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/valve-body-two-bores.tolturn"));
        QVERIFY(read.project);
        const Project &p = *read.project;
        const RangeEvaluation r = evaluateOverStiffnessRange(p, DataLibrary::builtIn(), {});
        QVERIFY(r.compliant.inputs && r.compliant.inputs->boring);
        int bores = 0;
        for (std::size_t i = 0; i < r.tolerances.size(); ++i) {
            const ToleranceRangeEvaluation &e = r.tolerances[i];
            const auto feature = findFeature(p.part, e.compliant.featureId);
            if (!feature || feature->side != ContourSide::Inner || !e.chuck ||
                e.chuck->kind != RequiredStiffness::Kind::Found)
                continue;
            ++bores;
            const auto verdictAt = [&](double k) {
                DeviationOptions o;
                o.chuckStiffness_N_per_mm = k;
                return evaluateTolerances(p, computeDeviation(p, DataLibrary::builtIn(), o)).at(i).verdict;
            };
            QVERIFY2(verdictAt(0.99 * e.chuck->value_N_per_mm) != Verdict::PassesAsProgrammed,
                     qPrintable(e.compliant.toleranceId));
            QCOMPARE(verdictAt(1.01 * e.chuck->value_N_per_mm), Verdict::PassesAsProgrammed);
        }
        QVERIFY(bores > 0);
    }

    // A measured spindle replaces the range: no stiff end, the ordinary verdict.
    void measuredMachineHasNoRange()
    {
        Project p = chuckedBar(40.0);
        p.characterisation.pivotDistance_mm = 200.0;
        p.characterisation.spindleRadial = SpindleSprings{5.0e5, 5.0e11, 5.0e11};
        p.characterisation.spindleTangential = p.characterisation.spindleRadial;
        const RangeEvaluation r = evaluateOverStiffnessRange(p, DataLibrary::builtIn(), radialLoad(200));
        QVERIFY(!r.machineIsRange);
        QVERIFY(!r.stiff);
        QCOMPARE(r.tolerances.front().range, RangeVerdict::NoRange);
    }

    // Between centres with only the tailstock measured: the headstock centre is still a rigid pin
    // for want of data, and the result says so rather than "as measured".
    void unmeasuredHeadstockCentreIsNamed()
    {
        Project p = chuckedBar(40.0);
        p.clamping = {ClampingMethod::BetweenCentres, 0.0};
        p.part.outer.segments.front().from.r_mm = 0.0;
        p.characterisation.tailstock = SupportStiffness{2.0e5, 2.0e5};
        p.characterisation.source = QStringLiteral("test");
        const RangeEvaluation r = evaluateOverStiffnessRange(p, DataLibrary::builtIn(), radialLoad(200));
        QVERIFY(r.compliant.inputs);
        QVERIFY(r.someSupportRigid);
        QVERIFY(machineAssumptionText(r, DataLibrary::builtIn()).contains(QStringLiteral("headstock centre")));
    }
};

QTEST_GUILESS_MAIN(TestRangeVerdicts)
#include "tst_range_verdicts.moc"
