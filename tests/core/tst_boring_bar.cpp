// SPDX-License-Identifier: GPL-3.0-or-later
// The boring bar (docs/model.md §3.1): its tip deflection against the cantilever closed form with
// shear for a steel and a carbide bar, the feed force's moment and the twist, the bar in the
// deviation of a bushing's bore, its own forces, the maker's overhang limit as a warning and a
// planning constraint, and the named errors for a bar that does not reach or is not a bar.
#include "tests/core/test_support.h"

#include "core/deviation/deviation_model.h"
#include "core/io/project_json.h"
#include "core/planning/planning_problem.h"
#include "core/planning/plausibility.h"
#include "core/project/project_validation.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace tolturn;

namespace {

constexpr double kPi = std::numbers::pi;

// The bar materials of resources/data/holders.json "boring_bar_materials", written out here:
// steel E = 190 000 MPa (the low end of 42CrMo4's 190–210 GPa), nu = 0.269; carbide
// E = 530 000 MPa (the low end of 530–700 GPa), nu = 0.24.
constexpr double kSteelBarE = 190000.0;
constexpr double kSteelBarNu = 0.269;
constexpr double kCarbideBarE = 530000.0;
constexpr double kCarbideBarNu = 0.24;

// Tip deflection of a solid round cantilever Ø d, length L under a tip force F, by hand:
// F L^3/(3 E I) + F L/(kappa G A), I = pi d^4/64, A = pi d^2/4, kappa = 6(1+nu)/(7+6nu) (Cowper 1966).
double cantileverTip(double force, double length, double d, double e, double nu)
{
    const double i = kPi * std::pow(d, 4) / 64.0;
    const double a = kPi * d * d / 4.0;
    const double g = e / (2.0 * (1.0 + nu));
    const double kappa = 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
    return force * std::pow(length, 3) / (3.0 * e * i) + force * length / (kappa * g * a);
}

using test::dump;
using test::seg;

// A bushing Ø60 x 100 with a through bore Ø32, 20 mm in the chuck: the bar reaches 80 mm.
Project bushing()
{
    Project p;
    p.part.name = QStringLiteral("bushing");
    p.part.stockDiameter_mm = 64.0;
    p.part.outer.segments = {seg("O1", SegmentKind::Face, {0, 16}, {0, 30}),
                             seg("O2", SegmentKind::Cylinder, {0, 30}, {100, 30}),
                             seg("O3", SegmentKind::Face, {100, 30}, {100, 16})};
    p.part.inner.segments = {seg("I1", SegmentKind::Cylinder, {0, 16}, {100, 16})};
    p.materialId = QStringLiteral("C45E-N");
    p.machineId = QStringLiteral("haas-st-20");
    p.tool.insertCode = QStringLiteral("CNMG 120408");
    p.tool.holderCode = QStringLiteral("PCLNR 2525M12");
    Tool bar;
    bar.insertCode = QStringLiteral("CNMG 120408");
    bar.holderCode = QStringLiteral("S25T-PCLNR12");
    bar.overhang_mm = 90.0;
    p.boringTool = bar;
    p.clamping = {ClampingMethod::Chuck, 20.0};
    p.passes = {{PassKind::Finishing, 200.0, 0.2, 0.5}};
    return p;
}

const Station &firstInnerStation(const DeviationResult &r)
{
    for (const FeatureDeviation &f : r.features) {
        if (f.side == ContourSide::Inner && !f.stations.empty())
            return f.stations.front();
    }
    qFatal("no inner station");
}

bool hasField(const Diagnostics &d, const char *field, Severity severity)
{
    return std::any_of(d.begin(), d.end(),
                       [&](const Diagnostic &x) { return x.field == QLatin1String(field) && x.severity == severity; });
}

} // namespace

class TestBoringBar : public QObject {
    Q_OBJECT

private Q_SLOTS:

    void tipDeflectionIsTheCantileverWithShear_data()
    {
        QTest::addColumn<double>("diameter");
        QTest::addColumn<double>("length");
        QTest::addColumn<double>("modulus");
        QTest::addColumn<double>("poisson");
        QTest::newRow("steel Ø25 x 100") << 25.0 << 100.0 << kSteelBarE << kSteelBarNu;
        QTest::newRow("carbide Ø16 x 120") << 16.0 << 120.0 << kCarbideBarE << kCarbideBarNu;
        QTest::newRow("stubby steel Ø32 x 40") << 32.0 << 40.0 << kSteelBarE << kSteelBarNu;
    }

    void tipDeflectionIsTheCantileverWithShear()
    {
        QFETCH(double, diameter);
        QFETCH(double, length);
        QFETCH(double, modulus);
        QFETCH(double, poisson);
        BoringBar bar;
        bar.diameter_mm = diameter;
        bar.overhang_mm = length;
        bar.material = {modulus, poisson, true};
        const BoringBarCompliance c = boringBarCompliance(bar);
        const BoringBarDeflection d = boringBarDeflection(bar, c, 250.0, 0.0, 0.0);
        QVERIFY2(test::nearRelative(d.radial_mm, cantileverTip(250.0, length, diameter, modulus, poisson), 1e-12),
                 qPrintable(QString::number(d.radial_mm, 'g', 12)));
        // Without shear: the Euler–Bernoulli cantilever F L^3 / 3EI.
        bar.material.shearDeformation = false;
        const double eb = 250.0 * std::pow(length, 3) / (3.0 * modulus * kPi * std::pow(diameter, 4) / 64.0);
        QVERIFY(test::nearRelative(boringBarDeflection(bar, boringBarCompliance(bar), 250.0, 0.0, 0.0).radial_mm, eb,
                                   1e-12));
    }

    // A hand calculation for the steel bar: Ø25, L = 100, F = 200 N. I = 19 174.76 mm^4,
    // EI = 3.643 2e9 N mm^2, F L^3/3EI = 2e8/1.092 97e10 = 0.018 299 mm; A = 490.874 mm^2,
    // G = 74 862.1 MPa, kappa = 7.614/8.614 = 0.883 910, F L/(kappa G A) = 2e4/32 481 300 = 0.000 616 mm.
    void steelBarByHand()
    {
        BoringBar bar;
        bar.diameter_mm = 25.0;
        bar.overhang_mm = 100.0;
        bar.material = {kSteelBarE, kSteelBarNu, true};
        const BoringBarDeflection d = boringBarDeflection(bar, boringBarCompliance(bar), 200.0, 0.0, 0.0);
        QVERIFY2(test::nearRelative(d.radial_mm, 0.018299 + 0.000616, 2e-4),
                 qPrintable(QString::number(d.radial_mm, 'g', 8)));
    }

    // The feed force F_a along the bar at the edge's offset e bends the tip towards the wall by
    // F_a e L^2/2EI (material taken off: negative); the cutting force twists the bar by F_t e L/GJ,
    // which moves the edge F_t e^2 L/GJ along the cutting speed, on top of its bending.
    void feedForceMomentAndTwist()
    {
        BoringBar bar;
        bar.diameter_mm = 20.0;
        bar.overhang_mm = 80.0;
        bar.edgeOffset_mm = 14.0;
        bar.material = {kSteelBarE, kSteelBarNu, true};
        const BoringBarCompliance c = boringBarCompliance(bar);
        const double i = kPi * std::pow(20.0, 4) / 64.0;
        const double g = kSteelBarE / (2.0 * (1.0 + kSteelBarNu));
        const double axial = 150.0;
        QVERIFY(test::nearRelative(boringBarDeflection(bar, c, 0.0, 0.0, axial).radial_mm,
                                   -axial * 14.0 * 80.0 * 80.0 / (2.0 * kSteelBarE * i), 1e-12));
        const double cutting = 400.0;
        const double j = kPi * std::pow(20.0, 4) / 32.0;
        const double twist = cutting * 14.0 * 14.0 * 80.0 / (g * j);
        const BoringBarDeflection d = boringBarDeflection(bar, c, 0.0, cutting, 0.0);
        QVERIFY(test::nearRelative(d.tangential_mm, cantileverTip(cutting, 80.0, 20.0, kSteelBarE, kSteelBarNu) + twist,
                                   1e-12));
        QCOMPARE(d.radial_mm, 0.0);
    }

    // In a bushing's bore the bar's bending is a contribution of its own, from the boring tool's
    // forces and the steel bar's data; the turning tool's toolpost term is not applied there.
    void barBendsInTheBore_data()
    {
        QTest::addColumn<QString>("holder");
        QTest::addColumn<double>("diameter");
        QTest::addColumn<double>("modulus");
        QTest::addColumn<double>("poisson");
        QTest::newRow("steel S25T") << QStringLiteral("S25T-PCLNR12") << 25.0 << kSteelBarE << kSteelBarNu;
        QTest::newRow("carbide E16R") << QStringLiteral("E16R-SCLCR09") << 16.0 << kCarbideBarE << kCarbideBarNu;
    }

    void barBendsInTheBore()
    {
        QFETCH(QString, holder);
        QFETCH(double, diameter);
        QFETCH(double, modulus);
        QFETCH(double, poisson);
        Project p = bushing();
        p.boringTool->holderCode = holder;
        p.boringTool->insertCode =
            holder.startsWith(QLatin1Char('E')) ? QStringLiteral("CCMT 09T304") : QStringLiteral("CNMG 120408");
        p.boringTool->edgeOffset_mm = 12.0;
        const DeviationResult r = computeDeviation(p, DataLibrary::builtIn());
        QVERIFY2(r.inputs && r.inputs->boring, qPrintable(dump(r.diagnostics)));
        const CuttingForces &f = r.inputs->boring->forces;
        QVERIFY(f.radial_N > 0.0 && f.axial_N > 0.0);
        const double i = kPi * std::pow(diameter, 4) / 64.0;
        const double expected = cantileverTip(f.radial_N, 90.0, diameter, modulus, poisson) -
                                f.axial_N * 12.0 * 90.0 * 90.0 / (2 * modulus * i);
        const Station &st = firstInnerStation(r);
        QVERIFY2(test::nearRelative(st.radial.boringBar_mm, expected, 1e-9),
                 qPrintable(QStringLiteral("%1 vs %2").arg(st.radial.boringBar_mm).arg(expected)));
        QCOMPARE(st.radial.toolpost_mm, 0.0);
        QVERIFY(test::nearRelative(st.radial.total_mm(),
                                   st.radial.spindleChuck_mm + st.radial.workpiece_mm + st.radial.thermal_mm + expected,
                                   1e-12));
        // The outer surface keeps the turning tool's toolpost term and has no bar.
        const Station &outer = r.features.front().stations.front();
        QCOMPARE(r.features.front().side, ContourSide::Outer);
        QCOMPARE(outer.radial.boringBar_mm, 0.0);
        QVERIFY(outer.radial.toolpost_mm > 0.0);
    }

    // The boring tool's own insert gives its own forces: a 0.4 mm nose takes less passive force
    // than the turning tool's 0.8 mm at the same depth (Kienzle with the nose radius, §6).
    void boringToolHasItsOwnForces()
    {
        Project p = bushing();
        p.boringTool->insertCode = QStringLiteral("CNMG 120404");
        const DeviationResult r = computeDeviation(p, DataLibrary::builtIn());
        QVERIFY2(r.inputs && r.inputs->boring, qPrintable(dump(r.diagnostics)));
        QCOMPARE(r.inputs->boring->noseRadius_mm, 0.4);
        QCOMPARE(r.inputs->noseRadius_mm, 0.8);
        QVERIFY(r.inputs->boring->forces.radial_N < r.inputs->forces.radial_N);
    }

    // The overhang not given: the bore's depth from the right end face to the chuck face, 80 mm,
    // and the 2 mm the program keeps the turret off the end face; the notes say so.
    void overhangDefaultsToTheReach()
    {
        Project p = bushing();
        p.boringTool->overhang_mm.reset();
        const DeviationResult r = computeDeviation(p, DataLibrary::builtIn());
        QVERIFY2(r.inputs && r.inputs->boring, qPrintable(dump(r.diagnostics)));
        QCOMPARE(r.inputs->boring->bar.overhang_mm, 80.0 + 2.0);
        QCOMPARE(r.inputs->boring->bar.edgeOffset_mm, 12.5);
        QVERIFY(r.inputs->notes.join(QLatin1Char(' ')).contains(QLatin1String("overhang not given")));
    }

    void badBoringBarsAreNamed()
    {
        Project shortBar = bushing();
        shortBar.boringTool->overhang_mm = 60.0;
        const DeviationResult r1 = computeDeviation(shortBar, DataLibrary::builtIn());
        QVERIFY(!r1.inputs);
        QVERIFY2(hasField(r1.diagnostics, "boring_tool.overhang_mm", Severity::Error),
                 qPrintable(dump(r1.diagnostics)));

        Project notABar = bushing();
        notABar.boringTool->holderCode = QStringLiteral("PCLNR 2525M12");
        const DeviationResult r2 = computeDeviation(notABar, DataLibrary::builtIn());
        QVERIFY(!r2.inputs);
        QVERIFY(hasField(r2.diagnostics, "boring_tool.holder", Severity::Error));
        QVERIFY(hasField(checkPlausibility(notABar, DataLibrary::builtIn()), "boring_tool.holder", Severity::Error));

        Project badInsert = bushing();
        badInsert.boringTool->insertCode = QStringLiteral("XXXX");
        QVERIFY(hasField(computeDeviation(badInsert, DataLibrary::builtIn()).diagnostics, "boring_tool.insert",
                         Severity::Error));

        Project negative = bushing();
        negative.boringTool->edgeOffset_mm = -3.0;
        QVERIFY(hasField(validateProject(negative), "boring_tool.edge_offset_mm", Severity::Error));

        // The pilot hole is the boring bar's start: above zero, and no turning tool's.
        Project noHole = bushing();
        noHole.boringTool->pilotHoleDiameter_mm = 0.0;
        QVERIFY(hasField(validateProject(noHole), "boring_tool.pilot_hole_diameter_mm", Severity::Error));
        Project turningToolsHole = bushing();
        turningToolsHole.tool.pilotHoleDiameter_mm = 24.0;
        QVERIFY(hasField(validateProject(turningToolsHole), "tool.pilot_hole_diameter_mm", Severity::Error));
        QVERIFY(!hasField(validateProject(bushing()), "tool.pilot_hole_diameter_mm", Severity::Error));

        // What the computing commands refuse, check refuses: the 60 mm bar above does not reach the
        // bore's 80 mm. And what no bore allows: a pilot hole as wide as the Ø32 bore leaves nothing
        // to bore; an edge 32 mm off the bar's axis cannot cut inside it. Ø31.9 and 31.9 mm are
        // geometrically possible.
        QVERIFY2(
            hasField(checkPlausibility(shortBar, DataLibrary::builtIn()), "boring_tool.overhang_mm", Severity::Error),
            qPrintable(dump(checkPlausibility(shortBar, DataLibrary::builtIn()))));
        QVERIFY(!hasErrors(checkPlausibility(bushing(), DataLibrary::builtIn())));
        Project wideHole = bushing();
        wideHole.boringTool->pilotHoleDiameter_mm = 32.0;
        QVERIFY(hasField(checkPlausibility(wideHole, DataLibrary::builtIn()), "boring_tool.pilot_hole_diameter_mm",
                         Severity::Error));
        wideHole.boringTool->pilotHoleDiameter_mm = 31.9;
        QVERIFY(!hasField(checkPlausibility(wideHole, DataLibrary::builtIn()), "boring_tool.pilot_hole_diameter_mm",
                          Severity::Error));
        Project farEdge = bushing();
        farEdge.boringTool->edgeOffset_mm = 32.0;
        QVERIFY(hasField(checkPlausibility(farEdge, DataLibrary::builtIn()), "boring_tool.edge_offset_mm",
                         Severity::Error));
        farEdge.boringTool->edgeOffset_mm = 31.9;
        QVERIFY(!hasField(checkPlausibility(farEdge, DataLibrary::builtIn()), "boring_tool.edge_offset_mm",
                          Severity::Error));

        // Per set-up: the valve body's first set-up bores only I4, Ø25 (OP 20 the Ø32 I1), so a Ø30
        // pilot hole there leaves nothing to bore, though OP 20's bore is wider.
        Project valve = test::exampleProject("valve-body-two-bores.tolturn");
        QVERIFY(!hasErrors(checkPlausibility(valve, DataLibrary::builtIn())));
        valve.boringTool->pilotHoleDiameter_mm = 30.0;
        const Diagnostics d = checkPlausibility(valve, DataLibrary::builtIn());
        QVERIFY2(hasField(d, "boring_tool.pilot_hole_diameter_mm", Severity::Error), qPrintable(dump(d)));
    }

    // A bar too short for the bore: its edge reaches z = length + 2 mm clearance - overhang. At 90 mm
    // that is z = 12, inside the 20 mm of jaws, where no verdict judges the bore (its stations start
    // at the chuck face); at 81 mm z = 21, 1 mm out of the jaws, which T1's verdict takes as bored.
    // 102 mm reaches the bottom. A bore open only at the held end is another set-up's: the valve
    // body's I1 (z 0-45) is not this bar's, even as one set-up with a bar long enough to pass it.
    void barTooShortForTheBoreIsSaid()
    {
        Project p = bushing();
        Tolerance t;
        t.id = QStringLiteral("T1");
        t.type = ToleranceType::Cylindricity;
        t.featureId = QStringLiteral("I1");
        t.zone_um = 10.0;
        p.tolerances = {t};
        const auto reachWarning = [](const Project &project) {
            for (const Diagnostic &x : checkPlausibility(project, DataLibrary::builtIn())) {
                if (x.field == QLatin1String("boring_tool.overhang_mm") &&
                    x.message.contains(QStringLiteral("not bored")))
                    return x.message;
            }
            return QString();
        };
        QCOMPARE(reachWarning(p), QStringLiteral("90 mm reaches z = 12 mm (the free end at 100 mm, 2 mm clear of it): "
                                                 "bore I1 not bored from z = 0 mm to there, inside the jaws (left of "
                                                 "z = 20 mm), where no verdict judges it. Reaching it needs an "
                                                 "overhang of 102 mm; or bore from both ends"));
        p.boringTool->overhang_mm = 81.0;
        QCOMPARE(reachWarning(p), QStringLiteral("81 mm reaches z = 21 mm (the free end at 100 mm, 2 mm clear of it): "
                                                 "bore I1 not bored from z = 0 mm to there, while the verdicts of T1 "
                                                 "take it as bored. Reaching it needs an overhang of 102 mm; or bore "
                                                 "from both ends"));
        p.boringTool->overhang_mm = 102.0; // 4.1 x D: reaches, and is said to be past the maker's 4 x D
        QVERIFY(reachWarning(p).isEmpty());

        Project valve = test::exampleProject("valve-body-two-bores.tolturn");
        valve.furtherOperations.clear();
        valve.boringTool->overhang_mm = 100.0; // reaches z = 22, far past the port bore's bottom at 75
        QVERIFY2(reachWarning(valve).isEmpty(), qPrintable(reachWarning(valve)));
    }

    // The maker's longest overhang (WIDIA: 4 x D for steel shank bars): 120 mm on Ø25 is 4.8 x D,
    // a warning in check and a planning constraint that no cutting condition can satisfy.
    void overhangBeyondTheMakersLimit()
    {
        Project p = bushing();
        p.boringTool->overhang_mm = 120.0;
        const Diagnostics d = checkPlausibility(p, DataLibrary::builtIn());
        QVERIFY2(hasField(d, "boring_tool.overhang_mm", Severity::Warning), qPrintable(dump(d)));

        p.planning.cuttingSpeed_m_min = ValueRange{150.0, 250.0};
        p.planning.feed_mm_rev = ValueRange{0.1, 0.3};
        p.planning.depthOfCut_mm = ValueRange{0.3, 2.0};
        const PlanningProblem::BuildResult b = PlanningProblem::build(p, DataLibrary::builtIn());
        QVERIFY2(b.problem, qPrintable(dump(b.diagnostics)));
        const CandidateEvaluation e = b.problem->evaluate({{200.0, 0.2, 0.5}, {200.0, 0.25, 1.5}, 1});
        const auto it = std::find_if(e.constraints.begin(), e.constraints.end(),
                                     [](const ConstraintValue &c) { return c.name == QLatin1String("bar_overhang"); });
        QVERIFY(it != e.constraints.end());
        QCOMPARE(it->value, 120.0 / 25.0);
        QCOMPARE(it->limit, 4.0);
        QVERIFY(!e.feasible());

        p.boringTool->overhang_mm = 90.0; // 3.6 x D (too short for the bore, barTooShortForTheBoreIsSaid)
        QVERIFY(!test::dump(checkPlausibility(p, DataLibrary::builtIn())).contains(QStringLiteral("times the bar's")));
    }

    // Bores without a bar are computed with the turning tool, and check says so.
    void boresWithoutABarAreNamed()
    {
        Project p = bushing();
        p.boringTool.reset();
        QVERIFY(hasField(checkPlausibility(p, DataLibrary::builtIn()), "boring_tool", Severity::Warning));
        const DeviationResult r = computeDeviation(p, DataLibrary::builtIn());
        QVERIFY(r.inputs);
        QVERIFY(r.inputs->notes.join(QLatin1Char(' ')).contains(QLatin1String("No boring bar given")));
        QCOMPARE(firstInnerStation(r).radial.boringBar_mm, 0.0);
    }

    void boringToolRoundTripsThroughTheFile()
    {
        Project p = bushing();
        p.boringTool->edgeOffset_mm = 17.0;
        p.boringTool->pilotHoleDiameter_mm = 24.5;
        const QByteArray json = serializeProjectJson(p);
        const ProjectParseResult back = parseProjectJson(json);
        QVERIFY2(back.project, qPrintable(dump(back.diagnostics)));
        QCOMPARE(back.project->boringTool, p.boringTool);
        QVERIFY(json.contains("\"boring_tool\""));
        QVERIFY(json.contains("\"edge_offset_mm\": 17"));
        QVERIFY(json.contains("\"pilot_hole_diameter_mm\": 24.5"));
    }
};

QTEST_GUILESS_MAIN(TestBoringBar)
#include "tst_boring_bar.moc"
