// SPDX-License-Identifier: GPL-3.0-or-later
// The workpiece beam model against closed forms of textbook beams, the papers' eq. 6 for
// stepped hollow bars, mesh convergence on a cone, Maxwell–Betti reciprocity, the moving-load
// sweep against a direct solve, and the spindle–chuck springs against the printed eq. 3 terms.
#include "tests/core/test_support.h"

#include "core/mechanics/moving_load.h"
#include "core/mechanics/spindle_chuck.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace tolturn;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kE = test::kSteelE_MPa;
constexpr double kNu = test::kSteelNu;

using test::seg;

// A bar of length L, outer radius ro, bore ri (0: solid), as a part profile.
PartProfile uniformBar(double length, double ro, double ri)
{
    PartProfile p;
    p.stockDiameter_mm = 2.0 * ro;
    p.outer.segments = {seg("O1", SegmentKind::Face, {0, ri}, {0, ro}),
                        seg("O2", SegmentKind::Cylinder, {0, ro}, {length, ro}),
                        seg("O3", SegmentKind::Face, {length, ro}, {length, ri})};
    if (ri > 0.0)
        p.inner.segments = {seg("I1", SegmentKind::Cylinder, {0, ri}, {length, ri})};
    return p;
}

std::vector<double> evenNodes(double z0, double z1, int elements)
{
    std::vector<double> nodes;
    for (int i = 0; i <= elements; ++i)
        nodes.push_back(z0 + (z1 - z0) * i / elements);
    return nodes;
}

std::vector<NodeInfluence> influence(const PartProfile &p, const ElasticMaterial &m, const std::vector<double> &nodes,
                                     const EndSupport &left, const EndSupport &right)
{
    const SectionAlongZ section(p);
    MovingLoadBeam beam;
    beam.nodes_mm = nodes;
    beam.uncut = buildElements(section, m, nodes);
    beam.finished = beam.uncut;
    beam.left = left;
    beam.right = right;
    return movingLoadInfluence(beam);
}

double relativeError(double value, double reference)
{
    return std::abs(value - reference) / std::abs(reference);
}

struct Bar {
    double ro, ri;

    double I() const { return kPi * (std::pow(ro, 4) - std::pow(ri, 4)) / 4.0; }

    double A() const { return kPi * (ro * ro - ri * ri); }

    // Cowper (1966) Table 1, hollow circle, written out independently of the library.
    double kappa() const
    {
        const double m = ri / ro;
        const double c = (1 + m * m) * (1 + m * m);
        return 6 * (1 + kNu) * c / ((7 + 6 * kNu) * c + (20 + 12 * kNu) * m * m);
    }

    double G() const { return kE / (2 * (1 + kNu)); }
};

} // namespace

class TestBeam : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void cowperSolidCircle()
    {
        // Cowper (1966): solid circle kappa = 6(1+nu)/(7+6nu) = 7.8/8.8 at nu = 0.3.
        QVERIFY(relativeError(cowperShearCoefficient(0.0, 0.3), 7.8 / 8.8) < 1e-14);
    }

    // Cantilever clamped at z = 0, load F at a: w = F a^3/(3EI) + F a/(kappa G A)
    // (Timoshenko & Gere, Mechanics of Materials; shear term from Castigliano with V = F).
    void cantilever_data()
    {
        QTest::addColumn<double>("ro");
        QTest::addColumn<double>("ri");
        QTest::addColumn<bool>("shear");
        QTest::newRow("solid, bending only") << 10.0 << 0.0 << false;
        QTest::newRow("solid, with shear") << 10.0 << 0.0 << true;
        QTest::newRow("hollow, bending only") << 20.0 << 14.0 << false;
        QTest::newRow("hollow, with shear") << 20.0 << 14.0 << true;
    }

    void cantilever()
    {
        QFETCH(double, ro);
        QFETCH(double, ri);
        QFETCH(bool, shear);
        const double L = 250.0;
        const ElasticMaterial m{kE, kNu, shear};
        const auto result =
            influence(uniformBar(L, ro, ri), m, evenNodes(0, L, 50), EndSupport::clamped(), EndSupport::free());
        const Bar bar{ro, ri};
        for (std::size_t j = 1; j < result.size(); ++j) {
            const double a = L * static_cast<double>(j) / 50.0;
            double reference = a * a * a / (3 * kE * bar.I());
            if (shear)
                reference += a / (bar.kappa() * bar.G() * bar.A());
            QVERIFY2(relativeError(result[j].atLoad(0, 0), reference) < 1e-3, qPrintable(QString::number(a)));
            // Rotation under a unit moment at a: a/(EI); rotation under the force: a^2/(2EI).
            QVERIFY(relativeError(result[j].atLoad(1, 1), a / (kE * bar.I())) < 1e-3);
            QVERIFY(relativeError(result[j].atLoad(1, 0), a * a / (2 * kE * bar.I())) < 1e-3);
        }
    }

    // Simply supported on both ends, load at a: w = F a^2 (L-a)^2 / (3 E I L) + F a (L-a) / (L kappa G A).
    void simplySupported_data() { cantilever_data(); }

    void simplySupported()
    {
        QFETCH(double, ro);
        QFETCH(double, ri);
        QFETCH(bool, shear);
        const double L = 400.0;
        const ElasticMaterial m{kE, kNu, shear};
        const auto result =
            influence(uniformBar(L, ro, ri), m, evenNodes(0, L, 40), EndSupport::pinned(), EndSupport::pinned());
        const Bar bar{ro, ri};
        for (std::size_t j = 1; j + 1 < result.size(); ++j) {
            const double a = L * static_cast<double>(j) / 40.0;
            double reference = a * a * (L - a) * (L - a) / (3 * kE * bar.I() * L);
            if (shear)
                reference += a * (L - a) / (L * bar.kappa() * bar.G() * bar.A());
            QVERIFY2(relativeError(result[j].atLoad(0, 0), reference) < 1e-3, qPrintable(QString::number(a)));
        }
    }

    // Propped cantilever (fixed at 0, simply supported at L), load at a, bending only:
    // w = F a^3 (L-a)^2 (3L + (L-a)) / (12 E I L^3)  (Roark's Formulas for Stress and Strain,
    // 7th ed., Table 8.1 case 1c, deflection under the load).
    void proppedCantilever()
    {
        const double L = 300.0;
        const ElasticMaterial m{kE, kNu, false};
        for (const double ri : {0.0, 9.0}) {
            const auto result =
                influence(uniformBar(L, 15.0, ri), m, evenNodes(0, L, 30), EndSupport::clamped(), EndSupport::pinned());
            const Bar bar{15.0, ri};
            for (std::size_t j = 1; j + 1 < result.size(); ++j) {
                const double a = L * static_cast<double>(j) / 30.0;
                const double b = L - a;
                const double reference = a * a * a * b * b * (3 * L + b) / (12 * kE * bar.I() * L * L * L);
                QVERIFY2(relativeError(result[j].atLoad(0, 0), reference) < 1e-3, qPrintable(QString::number(a)));
            }
        }
    }

    // A stepped hollow bar in a rigid chuck against Valiño et al. (2008) eq. 6, its integrals
    // evaluated in closed form for each uniform zone (here, not in the library):
    //   delta(a) = sum_i (4F/(pi E)) int (a-z)^2/(re^4 - ri^4) dz + (chi F/(pi G)) int 1/(re^2 - ri^2) dz
    void steppedHollowAgainstEq6()
    {
        PartProfile p;
        p.stockDiameter_mm = 60.0;
        p.outer.segments = {
            seg("O1", SegmentKind::Face, {0, 8}, {0, 30}),      seg("O2", SegmentKind::Cylinder, {0, 30}, {60, 30}),
            seg("O3", SegmentKind::Face, {60, 30}, {60, 22}),   seg("O4", SegmentKind::Cylinder, {60, 22}, {140, 22}),
            seg("O5", SegmentKind::Face, {140, 22}, {140, 16}), seg("O6", SegmentKind::Cylinder, {140, 16}, {200, 16}),
            seg("O7", SegmentKind::Face, {200, 16}, {200, 10})};
        p.inner.segments = {seg("I1", SegmentKind::Cylinder, {0, 8}, {100, 8}),
                            seg("I2", SegmentKind::Face, {100, 8}, {100, 10}),
                            seg("I3", SegmentKind::Cylinder, {100, 10}, {200, 10})};

        struct Zone {
            double z0, z1, re, ri;
        };

        const Zone zones[] = {{0, 60, 30, 8}, {60, 100, 22, 8}, {100, 140, 22, 10}, {140, 200, 16, 10}};
        const double G = kE / (2 * (1 + kNu));
        const ElasticMaterial m{kE, kNu, true};
        const std::vector<double> nodes = evenNodes(0, 200, 40);
        const auto result = influence(p, m, nodes, EndSupport::clamped(), EndSupport::free());
        for (std::size_t j = 1; j < nodes.size(); ++j) {
            const double a = nodes[j];
            double reference = 0.0;
            for (const Zone &zone : zones) {
                const double hi = std::min(zone.z1, a);
                if (hi <= zone.z0)
                    continue;
                const double chi = 1.0 / Bar{zone.re, zone.ri}.kappa();
                const double r4 = std::pow(zone.re, 4) - std::pow(zone.ri, 4);
                const double r2 = zone.re * zone.re - zone.ri * zone.ri;
                reference += 4.0 / (kPi * kE) * (std::pow(a - zone.z0, 3) - std::pow(a - hi, 3)) / 3.0 / r4;
                reference += chi / (kPi * G) * (hi - zone.z0) / r2;
            }
            QVERIFY2(relativeError(result[j].atLoad(0, 0), reference) < 1e-9, qPrintable(QString::number(a)));
        }
    }

    // A solid cone (r from 25 to 10 over 200 mm) in a rigid chuck: the tip deflection converges as
    // the mesh is refined, to the eq. 6 integral evaluated by composite Simpson with 200000 panels.
    void coneMeshConvergence()
    {
        PartProfile p;
        p.stockDiameter_mm = 50.0;
        p.outer.segments = {seg("O1", SegmentKind::Face, {0, 0}, {0, 25}),
                            seg("O2", SegmentKind::Cone, {0, 25}, {200, 10}),
                            seg("O3", SegmentKind::Face, {200, 10}, {200, 0})};
        const ElasticMaterial m{kE, kNu, false};
        auto integrand = [](double z) {
            const double r = 25.0 - 15.0 * z / 200.0;
            return (200.0 - z) * (200.0 - z) / (kE * kPi * std::pow(r, 4) / 4.0);
        };
        const int panels = 200000;
        const double h = 200.0 / panels;
        double simpson = integrand(0.0) + integrand(200.0);
        for (int i = 1; i < panels; ++i)
            simpson += (i % 2 == 1 ? 4.0 : 2.0) * integrand(i * h);
        const double reference = simpson * h / 3.0;

        double previousError = 1.0;
        for (const int elements : {1, 2, 4, 8, 16}) {
            const auto result = influence(p, m, evenNodes(0, 200, elements), EndSupport::clamped(), EndSupport::free());
            const double error = relativeError(result.back().atLoad(0, 0), reference);
            // Each refinement is closer, until the quadrature reaches the reference's own accuracy.
            QVERIFY2(error < previousError || error < 1e-10, qPrintable(QString::number(error)));
            previousError = error;
        }
        QVERIFY2(previousError < 1e-6, qPrintable(QString::number(previousError)));
    }

    // Maxwell–Betti: the deflection at i under a unit load at j equals that at j under a unit
    // load at i, here on a stepped part held in a sprung chuck with a tailstock spring.
    void reciprocity()
    {
        PartProfile p = uniformBar(300.0, 20.0, 0.0);
        const ElasticMaterial m{kE, kNu, true};
        const std::vector<double> nodes = evenNodes(30, 300, 27);
        BeamModel model;
        model.nodes_mm = nodes;
        model.elements = buildElements(SectionAlongZ(p), m, nodes);
        model.left = EndSupport::springs(chuckFaceStiffness({2.0e5, 4.0e9, 8.0e9, 150.0}));
        model.right = EndSupport::translationSpring(3.0e4);
        for (const auto &[i, j] : {std::pair{3, 20}, std::pair{8, 27}, std::pair{0, 14}}) {
            std::vector<Vector2> loadAtJ(nodes.size(), Vector2::Zero());
            loadAtJ[static_cast<std::size_t>(j)] = Vector2(1.0, 0.0);
            std::vector<Vector2> loadAtI(nodes.size(), Vector2::Zero());
            loadAtI[static_cast<std::size_t>(i)] = Vector2(1.0, 0.0);
            const double wij = solveBeam(model, loadAtJ)[static_cast<std::size_t>(i)](0);
            const double wji = solveBeam(model, loadAtI)[static_cast<std::size_t>(j)](0);
            QVERIFY(relativeError(wij, wji) < 1e-9);
        }
    }

    // The sweep gives the same flexibility at each node as a direct solve, with the section left
    // of the load different from the section right of it (the in-process section).
    void sweepMatchesDirectSolveWithInProcessSection()
    {
        const PartProfile finished = uniformBar(200.0, 12.0, 5.0);
        const ElasticMaterial m{kE, kNu, true};
        const std::vector<double> nodes = evenNodes(20, 200, 18);
        const SectionAlongZ uncutSection(finished, 3.0, 0.0); // 3 mm of stock still on, left of the tool
        MovingLoadBeam beam;
        beam.nodes_mm = nodes;
        beam.uncut = buildElements(uncutSection, m, nodes);
        beam.finished = buildElements(SectionAlongZ(finished), m, nodes);
        beam.left = EndSupport::springs(chuckFaceStiffness({1.5e5, 3.0e9, 6.0e9, 120.0}));
        beam.right = EndSupport::translationSpring(2.0e4);
        const auto sweep = movingLoadInfluence(beam);
        for (const std::size_t j : {std::size_t{0}, std::size_t{5}, std::size_t{11}, std::size_t{18}}) {
            BeamModel model;
            model.nodes_mm = nodes;
            for (std::size_t e = 0; e + 1 < nodes.size(); ++e)
                model.elements.push_back(e < j ? beam.uncut[e] : beam.finished[e]);
            model.left = beam.left;
            model.right = beam.right;
            for (int column = 0; column < 2; ++column) {
                std::vector<Vector2> load(nodes.size(), Vector2::Zero());
                load[j](column) = 1.0;
                const std::vector<Vector2> u = solveBeam(model, load);
                QVERIFY(!u.empty());
                for (int row = 0; row < 2; ++row) {
                    QVERIFY(relativeError(sweep[j].atLoad(row, column), u[j](row)) < 1e-9);
                    QVERIFY(relativeError(sweep[j].leftSupport(row, column), u.front()(row)) < 1e-9);
                    QVERIFY(relativeError(sweep[j].rightSupport(row, column), u.back()(row)) < 1e-9);
                }
            }
        }
    }

    // A bar in the spring chuck deflects as the spindle–chuck polynomial plus the cantilever from
    // the chuck face (F z^3/(3EI) + M z^2/(2EI)). The polynomial's z^2 and constant terms are those
    // printed in Valiño et al. (2008) eq. 3 (written here as printed, with F_a D/2 = -M), its z term
    // the one derived in docs/model.md §2.
    void spindleChuckPolynomial()
    {
        const SpindleChuckSprings s{1.6e5, 1.28e9, 1.52e10, 180.0};
        const double Fr = 400.0;
        const double FaD2 = 150.0 * 25.0; // F_a = 150 N at D = 50 mm
        const double k1 = s.k1_N_per_mm, k2 = s.k2_Nmm_per_rad, k3 = s.k3_Nmm_per_rad, Lc = s.pivotDistance_mm;
        const double printedSquare = Fr / k2 + Fr / k3;                              // eq. 3, z^2
        const double printedConstant = Fr / k1 - FaD2 * Lc / k2 + Fr * Lc * Lc / k2; // eq. 3, constant
        const double derivedLinear = 2 * Fr * Lc / k2 - FaD2 * (1 / k2 + 1 / k3);
        const ElasticMaterial steel{kE, kNu, false};
        const PartProfile bar = uniformBar(260.0, 25.0, 0.0);
        const double EI = kE * Bar{25.0, 0.0}.I();
        const std::vector<double> nodes = evenNodes(60, 260, 20);
        const auto result =
            influence(bar, steel, nodes, EndSupport::springs(chuckFaceStiffness(s)), EndSupport::free());
        for (std::size_t j = 0; j < nodes.size(); ++j) {
            const double z = nodes[j] - 60.0;
            const double spindle = printedSquare * z * z + derivedLinear * z + printedConstant;
            const double expected = spindle + Fr * z * z * z / (3 * EI) - FaD2 * z * z / (2 * EI);
            const double w = result[j].atLoad(0, 0) * Fr + result[j].atLoad(0, 1) * (-FaD2);
            QVERIFY2(relativeError(w, expected) < 1e-9, qPrintable(QString::number(z)));
            QVERIFY(relativeError(spindleChuckDeflection(s, Fr, -FaD2, z), spindle) < 1e-12);
        }
    }

    // Toolpost, eq. 5: a 25 x 25 mm steel shank 40 mm out of a 120 mm holder of 40 x 40 mm.
    void toolpostShortening()
    {
        const ToolpostCompliance tp{40.0, 625.0, 210000.0, 120.0, 1600.0, 210000.0};
        // 40/(625*210000) + 120/(1600*210000) = 3.0476e-7 + 3.5714e-7 = 6.6190e-7 mm/N
        QVERIFY(relativeError(tp.compliance_mm_per_N(), 6.6190476e-7) < 1e-6);
    }

    void unsupportedBeamIsDetected()
    {
        QVERIFY(!supportsHoldBeam(EndSupport::pinned(), EndSupport::free(), 100.0));
        QVERIFY(!supportsHoldBeam(EndSupport::free(), EndSupport::free(), 100.0));
        QVERIFY(supportsHoldBeam(EndSupport::pinned(), EndSupport::translationSpring(1.0), 100.0));
        QVERIFY(supportsHoldBeam(EndSupport::clamped(), EndSupport::free(), 100.0));
        const auto result = influence(uniformBar(100, 10, 0), ElasticMaterial{kE, kNu, true}, evenNodes(0, 100, 4),
                                      EndSupport::pinned(), EndSupport::free());
        for (const NodeInfluence &r : result)
            QVERIFY(!r.supported);
    }
};

QTEST_GUILESS_MAIN(TestBeam)
#include "tst_beam.moc"
