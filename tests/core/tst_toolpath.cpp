// SPDX-License-Identifier: GPL-3.0-or-later
// Tool paths and programs: the nose-radius offset against hand calculations, the roughing levels
// against the allowance, and every example's LinuxCNC program read back by LinuxCNC's own
// interpreter (rs274, package linuxcnc-uspace), whose canonical moves must reproduce the profile
// with the nose radius to 1 µm. The Fanuc/Haas and Sinumerik programs must carry the same path.

#include "tests/core/test_support.h"

#include "core/data/data_library.h"
#include "core/deviation/deviation_model.h"
#include "core/io/project_file.h"
#include "core/part/profile_geometry.h"
#include "core/part/undercuts.h"
#include "core/planning/boring_toolpath.h"
#include "core/planning/compensation.h"
#include "core/planning/finished_extent.h"
#include "core/planning/gcode.h"
#include "core/planning/path_geometry.h"
#include "core/planning/planning_report.h"
#include "core/planning/plausibility.h"
#include "core/planning/toolpath_detail.h"
#include "core/project/operations.h"
#include "core/tolerance/target_contour.h"

#include <QDir>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>
#include <numbers>

using namespace tolturn;
using tolturn::test::dump;

namespace {

// A concave fillet of an outer contour, O12, from `from` down to `to` going right (counter-clockwise
// with z to the right and r up).
Segment concaveFillet(ProfilePoint from, ProfilePoint to, double radius_mm)
{
    Segment fillet;
    fillet.id = QStringLiteral("O12");
    fillet.kind = SegmentKind::Radius;
    fillet.from = from;
    fillet.to = to;
    fillet.arcRadius_mm = radius_mm;
    fillet.arcDirection = ArcDirection::CounterClockwise;
    return fillet;
}

Project example(const QString &name)
{
    const ProjectParseResult r = readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/") + name);
    if (!r.project)
        qFatal("cannot read example %s", qPrintable(name));
    return *r.project;
}

PathElement lineElement(double z0, double r0, double z1, double r1)
{
    PathElement e;
    e.from = {z0, r0};
    e.to = {z1, r1};
    return e;
}

double distance(ProfilePoint a, ProfilePoint b)
{
    return std::hypot(a.z_mm - b.z_mm, a.r_mm - b.r_mm);
}

// An arc from `from` to `to` about `centre` (its radius their distance), counter-clockwise or not.
PathElement arcElement(ProfilePoint from, ProfilePoint to, ProfilePoint centre, bool counterClockwise)
{
    PathElement e;
    e.arc = true;
    e.from = from;
    e.to = to;
    e.centre = centre;
    e.radius_mm = distance(to, centre);
    e.counterClockwise = counterClockwise;
    return e;
}

// Distance from a point to a line segment or to an arc (centre, radius, from, to, sense).
double distanceToPath(const PathElement &e, ProfilePoint p)
{
    if (!e.arc) {
        const double dz = e.to.z_mm - e.from.z_mm;
        const double dr = e.to.r_mm - e.from.r_mm;
        const double l2 = dz * dz + dr * dr;
        const double t =
            l2 > 0 ? std::clamp(((p.z_mm - e.from.z_mm) * dz + (p.r_mm - e.from.r_mm) * dr) / l2, 0.0, 1.0) : 0.0;
        return distance(p, {e.from.z_mm + t * dz, e.from.r_mm + t * dr});
    }
    const auto angle = [&](ProfilePoint q) { return std::atan2(q.r_mm - e.centre.r_mm, q.z_mm - e.centre.z_mm); };
    const double turn = 2.0 * std::numbers::pi;
    auto sweepTo = [&](double a) {
        double w = a - angle(e.from);
        if (e.counterClockwise)
            while (w < 0)
                w += turn;
        else
            while (w > 0)
                w -= turn;
        return w;
    };
    const double sweep = sweepTo(angle(e.to));
    const double at = sweepTo(angle(p));
    const bool within = e.counterClockwise ? at <= sweep : at >= sweep;
    if (within)
        return std::abs(distance(p, e.centre) - e.radius_mm);
    return std::min(distance(p, e.from), distance(p, e.to));
}

double distanceToPath(const std::vector<PathElement> &chain, ProfilePoint p)
{
    double best = std::numeric_limits<double>::infinity();
    for (const PathElement &e : chain)
        best = std::min(best, distanceToPath(e, p));
    return best;
}

// The canonical feed moves LinuxCNC's interpreter prints, as path elements of the tool tip in the
// half-section (z from the part's left end, r), with the pass each belongs to (the comments).
struct CanonicalPass {
    bool finishing = false;
    bool bore = false; // a pass of the boring bar (its comment says "BORE PASS")
    std::vector<PathElement> moves;
};

std::vector<CanonicalPass> readCanonical(const QString &text, double length_mm)
{
    static const QRegularExpression number(QStringLiteral("-?\\d+\\.\\d+|-?\\d+"));
    std::vector<CanonicalPass> passes(1);
    ProfilePoint at;
    for (const QString &line : text.split(QLatin1Char('\n'))) {
        auto values = [&](const QString &call) {
            std::vector<double> v;
            const QString args = line.section(call + QLatin1Char('('), 1).section(QLatin1Char(')'), 0, 0);
            for (const QString &a : args.split(QLatin1Char(',')))
                v.push_back(a.trimmed().toDouble());
            return v;
        };
        if (line.contains(QStringLiteral("COMMENT(\"PASS ")) || line.contains(QStringLiteral("COMMENT(\"BORE PASS "))) {
            passes.push_back(
                {line.contains(QStringLiteral("FINISHING")), line.contains(QStringLiteral("BORE PASS")), {}});
        } else if (line.contains(QStringLiteral("STRAIGHT_TRAVERSE("))) {
            const auto v = values(QStringLiteral("STRAIGHT_TRAVERSE"));
            at = {v[2] + length_mm, v[0]};
        } else if (line.contains(QStringLiteral("STRAIGHT_FEED("))) {
            const auto v = values(QStringLiteral("STRAIGHT_FEED"));
            const ProfilePoint to{v[2] + length_mm, v[0]};
            passes.back().moves.push_back(lineElement(at.z_mm, at.r_mm, to.z_mm, to.r_mm));
            at = to;
        } else if (line.contains(QStringLiteral("ARC_FEED("))) {
            const auto v = values(QStringLiteral("ARC_FEED")); // Z end, X end, Z centre, X centre, turn
            const PathElement e = arcElement(at, {v[0] + length_mm, v[1]}, {v[2] + length_mm, v[3]}, v[4] > 0);
            passes.back().moves.push_back(e);
            at = e.to;
        }
    }
    return passes;
}

struct Lathe {
    QTemporaryDir dir;
    QString ini, tools;
};

// A LinuxCNC lathe for the standalone interpreter: X and Z, millimetres, tool 1 with the nose
// radius and orientation 2 (the tip r_e below and r_e left of the nose centre with Z to the right
// and X up), tool 2, the boring bar, with its nose radius and orientation 3 (the tip r_e above and
// r_e left of the nose centre). The standalone interpreter reads the tool table in inches.
void setUpLathe(Lathe &lathe, double noseRadius_mm, double boringNoseRadius_mm = 0.4)
{
    lathe.ini = lathe.dir.filePath(QStringLiteral("lathe.ini"));
    lathe.tools = lathe.dir.filePath(QStringLiteral("tools.tbl"));
    QFile ini(lathe.ini);
    QVERIFY(ini.open(QIODevice::WriteOnly));
    ini.write("[RS274NGC]\nPARAMETER_FILE = rs274.var\n[TRAJ]\nCOORDINATES = X Z\nLINEAR_UNITS = mm\n"
              "ANGULAR_UNITS = degree\n[EMCIO]\nTOOL_TABLE = tools.tbl\n");
    QFile tools(lathe.tools);
    QVERIFY(tools.open(QIODevice::WriteOnly));
    tools.write(QStringLiteral("T1 P1 D%1 Q2 ;nose\nT2 P2 D%2 Q3 ;boring bar\n")
                    .arg(2.0 * noseRadius_mm / 25.4, 0, 'f', 10)
                    .arg(2.0 * boringNoseRadius_mm / 25.4, 0, 'f', 10)
                    .toUtf8());
    QFile var(lathe.dir.filePath(QStringLiteral("rs274.var")));
    QVERIFY(var.open(QIODevice::WriteOnly));
}

QString runInterpreter(const Lathe &lathe, const QString &program)
{
    const QString rs274 = QStandardPaths::findExecutable(QStringLiteral("rs274"));
    if (rs274.isEmpty())
        return QStringLiteral("ERROR: rs274 not found (package linuxcnc-uspace; tools/bootstrap.sh installs it)");
    const QString in = lathe.dir.filePath(QStringLiteral("in.ngc"));
    const QString out = lathe.dir.filePath(QStringLiteral("out.txt"));
    QFile f(in);
    if (!f.open(QIODevice::WriteOnly))
        return QStringLiteral("ERROR: cannot write the program");
    f.write(program.toUtf8());
    f.close();
    QProcess p;
    p.setWorkingDirectory(lathe.dir.path());
    p.start(rs274, {QStringLiteral("-t"), lathe.tools, QStringLiteral("-i"), lathe.ini, QStringLiteral("-g"), in, out});
    p.closeWriteChannel();
    if (!p.waitForFinished(60000) || p.exitCode() != 0)
        return QStringLiteral("ERROR: rs274 failed: ") + QString::fromUtf8(p.readAllStandardError()) +
               QString::fromUtf8(p.readAllStandardOutput());
    QFile result(out);
    if (!result.open(QIODevice::ReadOnly))
        return QStringLiteral("ERROR: no output");
    return QString::fromUtf8(result.readAll());
}

// (kind, X, Z, R) of the motion blocks of a program in any of the three dialects.
QStringList programmedMoves(const QString &program)
{
    static const QRegularExpression comment(QStringLiteral("\\([^)]*\\)|;.*$"));
    static const QRegularExpression motion(QStringLiteral("\\bG0?([0-3])\\b"));
    static const QRegularExpression word(QStringLiteral("\\b(X|Z|R|CR=)(-?\\d+\\.\\d+)"));
    QStringList moves;
    int g = 0;
    for (QString line : program.split(QLatin1Char('\n'))) {
        line.remove(comment);
        if (const auto m = motion.match(line); m.hasMatch())
            g = m.captured(1).toInt();
        QStringList words{QString::number(g)};
        auto it = word.globalMatch(line);
        while (it.hasNext()) {
            const auto w = it.next();
            words << (w.captured(1) == QLatin1String("CR=") ? QStringLiteral("R") : w.captured(1)) + w.captured(2);
        }
        if (words.size() > 1)
            moves << words.join(QLatin1Char(' '));
    }
    return moves;
}

// The bushing with its H7 bore (Ø32, through, 110 mm) bored from a Ø24 pilot hole with the carbide
// bar E16R-SCLCR09 (Ø16, edge offset taken as the bar's radius, 8 mm) and a CCMT 09T304 insert
// (r_e 0.4 mm), at 115 mm overhang, so that it reaches through.
// The least distance of the nose-centre path `centre` from `contour`, sampled every 0.01 mm.
double closestApproach(const std::vector<PathElement> &centre, const std::vector<PathElement> &contour)
{
    double closest = 1e9;
    for (const PathElement &e : centre)
        for (const ProfilePoint &c : sampled(e, 0.01))
            closest = std::min(closest, distanceToPath(contour, c));
    return closest;
}

Project bushingFromPilotHole()
{
    Project p = example(QStringLiteral("bushing-bore-h7.tolturn"));
    p.boringTool->holderCode = QStringLiteral("E16R-SCLCR09");
    p.boringTool->insertCode = QStringLiteral("CCMT 09T304");
    p.boringTool->overhang_mm = 115.0;
    p.boringTool->pilotHoleDiameter_mm = 24.0;
    return p;
}

// The segments of the bore open at the free end of a contour (z = length), left to right.
std::vector<Segment> boreAtFreeEnd(const Contour &inner, double length)
{
    for (const auto &[first, end] : inner.pieces())
        if (std::abs(inner.segments[end - 1].to.z_mm - length) < 1e-6)
            return {inner.segments.begin() + static_cast<std::ptrdiff_t>(first),
                    inner.segments.begin() + static_cast<std::ptrdiff_t>(end)};
    return {};
}

} // namespace

class TestToolpath : public QObject {
    Q_OBJECT
private Q_SLOTS:

    // Points every 0.05 mm: a 10 mm line has 200 steps, both ends exact. A path kilometres long (a
    // compensation from a deviation that is not physical) is bounded by the steps asked for, and one
    // whose length overflows an int is too: it took gigabytes before (an int overflow, then 1e9 points).
    void samplingIsBoundedOnAbsurdPaths()
    {
        const std::vector<ProfilePoint> short10 = sampled(lineElement(0, 10, 10, 10), 0.05);
        QCOMPARE(short10.size(), std::size_t{201});
        QCOMPARE(short10.back().z_mm, 10.0);
        QVERIFY(std::abs(short10[1].z_mm - 0.05) < 1e-12);
        const std::vector<ProfilePoint> long1km = sampled(lineElement(0, 10, 1e6, 10), 0.05, 2000);
        QCOMPARE(long1km.size(), std::size_t{2001});
        QCOMPARE(long1km.back().z_mm, 1e6);
        QCOMPARE(sampled(lineElement(0, 10, 1e300, 10), 0.05).size(), std::size_t{100001});
        const std::vector<ProfilePoint> quarter =
            sampled(arcElement({1e9, 0.0}, {0.0, 1e9}, {0.0, 0.0}, true), 0.05, 2000);
        QCOMPARE(quarter.size(), std::size_t{2001});
        QCOMPARE(quarter.back().r_mm, 1e9);
    }

    // The upper envelope of a disc of radius 1 swept along a contour: on the Ø40 cylinder (z 0..10)
    // r = 20 + 1; on the cone from (10, 20) to (20, 15), slope -1/2, the line moved by 1 along its
    // normal, r = 20 - (z - 10)/2 + sqrt(1 + 1/4) (at z = 15: 17.5 + 1.118034 = 18.618034); past the
    // face at z 20 (r 15 down to 10) the disc about its top corner, r = 15 + sqrt(1 - (z - 20)^2)
    // (at z 20.5: 15 + 0.866025). And everywhere within 1e-6 mm of the brute force: the top of discs
    // about points 1 µm apart along the contour (an edge round included).
    void envelopeIsTheSweptDisc()
    {
        using test::seg;
        std::vector<Segment> contour{
            seg("O1", SegmentKind::Cylinder, {0, 20}, {10, 20}), seg("O2", SegmentKind::Cone, {10, 20}, {20, 15}),
            seg("O3", SegmentKind::Face, {20, 15}, {20, 10}), seg("O4", SegmentKind::Cylinder, {20, 10}, {28, 10})};
        Segment round = seg("O5", SegmentKind::Radius, {28, 10}, {30, 8});
        round.arcRadius_mm = 2.0;
        round.arcDirection = ArcDirection::Clockwise;
        contour.push_back(round);
        const Envelope env = widenedEnvelope(contour, 1.0, -2.0, 32.0, toolpath_detail::kEnvelopeStep_mm);
        const auto at = [&](double z) { // NaN when z is not on the grid
            const auto i = static_cast<std::size_t>(std::lround((z - env.z0_mm) / env.step_mm));
            return std::abs(env.z(i) - z) < 1e-9 ? env.r_mm[i] : std::numeric_limits<double>::quiet_NaN();
        };
        QVERIFY(std::abs(at(5.0) - 21.0) < 1e-12);
        QVERIFY(std::abs(at(15.0) - 18.618034) < 1e-6);
        QVERIFY(std::abs(at(20.5) - 15.866025) < 1e-6);
        std::vector<ProfilePoint> dense;
        for (const PathElement &e : reversedElements(contour))
            for (const ProfilePoint &p : sampled(e, 0.001))
                dense.push_back(p);
        double worst = 0.0;    // along the lines, exact
        double worstArc = 0.0; // where the round is in reach (z > 27), by discs half a grid step apart
        for (std::size_t i = 0; i < env.r_mm.size(); i += 7) {
            double r = -std::numeric_limits<double>::infinity();
            for (const ProfilePoint &p : dense) {
                const double dz = env.z(i) - p.z_mm;
                if (std::abs(dz) <= 1.0)
                    r = std::max(r, p.r_mm + std::sqrt(1.0 - dz * dz));
            }
            if (std::isfinite(r) || std::isfinite(env.r_mm[i]))
                (env.z(i) > 27.0 ? worstArc : worst) =
                    std::max(env.z(i) > 27.0 ? worstArc : worst, std::abs(env.r_mm[i] - r));
        }
        QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));
        // Discs 0.01 mm apart on the R2 round are 0.01 (2 + 1)/2 = 0.015 mm apart on its offset: the top
        // dips between them by at most 1 - sqrt(1 - 0.0075^2) = 2.8e-5 mm.
        QVERIFY2(worstArc < 2.9e-5, qPrintable(QString::number(worstArc)));
    }

    // Offset by r = 0.8 to the right of the travel. Up the end face (z 100, r 0 -> 20), then left along
    // the Ø40 cylinder: a convex corner, closed by an arc of 0.8 about (100, 20) from (100.8, 20) to
    // (100, 20.8). Then left along the cylinder to z 60 and up a shoulder to r 25 (its face looks to
    // +z, where the tool is): a concave corner, where the offsets r = 20.8 and z = 60.8 meet.
    void offsetClosesConvexCornersWithArcsAndTrimsConcaveOnes()
    {
        const std::vector<PathElement> chain{lineElement(100, 0, 100, 20), lineElement(100, 20, 60, 20),
                                             lineElement(60, 20, 60, 25)};
        const std::vector<PathElement> o = offsetToTheRight(chain, 0.8);
        QCOMPARE(o.size(), std::size_t{4});
        QCOMPARE(o[0].from.z_mm, 100.8);
        QCOMPARE(o[0].to.r_mm, 20.0);
        QVERIFY(o[1].arc && o[1].counterClockwise);
        QCOMPARE(o[1].centre.z_mm, 100.0);
        QCOMPARE(o[1].centre.r_mm, 20.0);
        QCOMPARE(o[1].to.z_mm, 100.0);
        QCOMPARE(o[1].to.r_mm, 20.8);
        QVERIFY(std::abs(o[2].to.z_mm - 60.8) < 1e-12 && std::abs(o[2].to.r_mm - 20.8) < 1e-12);
        QVERIFY(std::abs(o[3].from.z_mm - 60.8) < 1e-12 && std::abs(o[3].to.r_mm - 25.0) < 1e-12);
    }

    // A step down towards the headstock, ridden over at 3° (tan 3° = 0.0524078): from z 10 along r 5
    // to z 6, down to r 4 and on to z -30. The line from (6, 5) meets r 4 at 6 - 1/tan 3° =
    // -13.0811 and leaves the whole step, 1 mm, below it. Rounded instead by a convex quarter arc
    // of radius 1 about (6, 4), from (6, 5) to (5, 4): the arc is followed to where its tangent
    // falls at 3°, 93° round its centre, (6 + cos 93°, 4 + sin 93°) = (5.947664, 4.998630), and the
    // line from there meets r 4 at 5.947664 - 0.998630/tan 3° = 5.947664 - 19.054987 = -13.107323.
    void stepDownIsRiddenOverAtTheGivenAngle()
    {
        const double slope = std::tan(3.0 * std::numbers::pi / 180.0);
        std::vector<RiddenOver> ridden;
        const std::vector<PathElement> step{lineElement(10, 5, 6, 5), lineElement(6, 5, 6, 4),
                                            lineElement(6, 4, -30, 4)};
        const std::vector<PathElement> a = riddenOverSteepFalls(step, 3.0, &ridden);
        QCOMPARE(a.size(), std::size_t{3});
        QVERIFY(std::abs(a[1].from.z_mm - 6.0) < 1e-12 && std::abs(a[1].from.r_mm - 5.0) < 1e-12);
        QVERIFY2(std::abs(a[1].to.z_mm - (6.0 - 1.0 / slope)) < 1e-9 && std::abs(a[1].to.z_mm + 13.0811) < 1e-4,
                 qPrintable(QString::number(a[1].to.z_mm, 'f', 6)));
        QVERIFY(std::abs(a[2].from.z_mm - a[1].to.z_mm) < 1e-12 && std::abs(a[2].to.z_mm + 30.0) < 1e-12);
        QCOMPARE(ridden.size(), std::size_t{1});
        QVERIFY(std::abs(ridden[0].deepest_mm - 1.0) < 1e-9);
        QCOMPARE(ridden[0].steepest_deg, 90.0);

        PathElement round;
        round.from = {6.0, 5.0};
        round.to = {5.0, 4.0};
        round.arc = true;
        round.centre = {6.0, 4.0};
        round.radius_mm = 1.0;
        round.counterClockwise = true;
        const std::vector<PathElement> rounded{lineElement(10, 5, 6, 5), round, lineElement(5, 4, -30, 4)};
        const std::vector<PathElement> b = riddenOverSteepFalls(rounded, 3.0);
        QCOMPARE(b.size(), std::size_t{4});
        QVERIFY(b[1].arc && std::abs(b[1].to.z_mm - 5.947664) < 1e-6 && std::abs(b[1].to.r_mm - 4.998630) < 1e-6);
        QVERIFY2(!b[2].arc && std::abs(b[2].to.z_mm + 13.107323) < 1e-6 && std::abs(b[2].to.r_mm - 4.0) < 1e-9,
                 qPrintable(QString::number(b[2].to.z_mm, 'f', 6)));
        // Without a point of the contour on the line's way the line runs to the contour's last z:
        // from (6, 5) to z 0 it falls 6 tan 3° = 0.314447 mm.
        const std::vector<PathElement> shortStep{lineElement(10, 5, 6, 5), lineElement(6, 5, 6, 4),
                                                 lineElement(6, 4, 0, 4)};
        const std::vector<PathElement> c = riddenOverSteepFalls(shortStep, 3.0);
        QCOMPARE(c.size(), std::size_t{2});
        QVERIFY(std::abs(c[1].to.z_mm) < 1e-12 && std::abs(c[1].to.r_mm - (5.0 - 6.0 * slope)) < 1e-12);
        // A rise and a fall shallower than the angle are followed as they are.
        const std::vector<PathElement> gentle{lineElement(10, 4, 6, 5), lineElement(6, 5, 0, 4.8)};
        QCOMPARE(riddenOverSteepFalls(gentle, 3.0).size(), std::size_t{2});
    }

    // The tip path of a 45° chamfer: the nose centre runs r_e off the chamfer, the imaginary tip r_e
    // below and left of the centre. By hand: offset (+r_e/sqrt 2, +r_e/sqrt 2), tip shift (-r_e, -r_e),
    // together -r_e (1 - 1/sqrt 2) in z and in r, so the line z + r = c moves by
    // -r_e (2 - sqrt 2) = -0.58579 r_e; for r_e = 0.8 mm, -0.46863 mm.
    void tipPathOfAChamferIsShiftedByTheClassicCompensation()
    {
        const std::vector<PathElement> chamfer{lineElement(100, 18, 98, 20)};
        const std::vector<PathElement> tip = translated(offsetToTheRight(chamfer, 0.8), -0.8, -0.8);
        QCOMPARE(tip.size(), std::size_t{1});
        const double shift = (tip[0].from.z_mm + tip[0].from.r_mm) - (100.0 + 18.0);
        QVERIFY2(std::abs(shift - (-0.46863)) < 1e-5, qPrintable(QString::number(shift, 'f', 6)));
    }

    // A concave edge round smaller than the nose cannot be followed: it is named and left as a corner.
    void concaveRoundTighterThanTheNoseIsNamed()
    {
        PathElement round = arcElement({60.5, 20.0}, {60.0, 20.5}, {60.5, 20.5}, false);
        round.featureId = QStringLiteral("R1");
        QStringList dropped;
        const std::vector<PathElement> o =
            offsetToTheRight({lineElement(100, 20, 60.5, 20), round, lineElement(60, 20.5, 60, 25)}, 0.8, &dropped);
        QCOMPARE(dropped, QStringList{QStringLiteral("R1")});
        for (const PathElement &e : o)
            QVERIFY(!e.arc);
    }

    // Roughing of the stepped shaft: eight levels of 1.9375 mm from the Ø60 stock (the plan takes
    // 15.5 mm = 30 - 14 - 0.5 down to the Ø28 end less the finishing allowance). No nose centre comes
    // closer to the contour than the allowance plus the nose radius (0.5 + 0.8 mm, less the 2 µm of
    // the path's simplification), and no tool point goes left of the chuck face + 2 mm (z 37).
    void roughingKeepsTheAllowanceAndStaysClearOfTheJaws()
    {
        const Project p = example(QStringLiteral("stepped-shaft-chuck.tolturn"));
        const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY(d.inputs);
        const TurningProgram program = turningProgram(p, DataLibrary::builtIn(), *d.inputs, {});
        QCOMPARE(program.path.roughing.size(), std::size_t{8});
        // O4 runs to the chuck face: the nose keeps 2 mm off the jaws, so 2 + 0.8 mm of O4 is not turned.
        QCOMPARE(program.path.warnings.size(), 1);
        QVERIFY(program.path.warnings.constFirst().startsWith(QStringLiteral("O4 reaches within 2.800 mm")));
        const std::vector<PathElement> contour = reversedElements(targetContour(p, ContourSide::Outer).segments);
        double closest = 1e9;
        for (const PassPath &pass : program.path.roughing) {
            const ToolMove *previous = nullptr;
            for (const ToolMove &m : pass.moves) {
                QVERIFY(m.to.z_mm >= 37.0 - 1e-9);
                if (m.kind == MoveKind::Feed && previous) {
                    const PathElement e =
                        lineElement(previous->to.z_mm + 0.8, previous->to.r_mm + 0.8, m.to.z_mm + 0.8, m.to.r_mm + 0.8);
                    for (const ProfilePoint &c : sampled(e, 0.01))
                        closest = std::min(closest, distanceToPath(contour, c));
                }
                previous = &m;
            }
        }
        QVERIFY2(closest >= 1.3 - 0.002 && closest <= 1.3 + 0.01, qPrintable(QString::number(closest, 'f', 5)));
        const double lowest = 30.0 - 8 * 1.9375;
        QCOMPARE(program.path.roughing.back().smallestDiameter_mm, 2.0 * lowest);
    }

    // The set-up sheet's time of the stepped shaft's first roughing pass, by hand: feed from X64 to X60
    // and on to X56.125 at Z2, 115 mm along X56.125, up to X60 at Z-113; under G96 (200 m/min, below
    // the spindle limit) n = 1000 v/(2 pi r), so a radial move from r1 to r2 takes
    // pi (r2^2 - r1^2)/(1000 v f) and an axial one L 2 pi r/(1000 v f), with 1000 v f = 60 000 mm^2/min:
    // pi (32^2 - 28.0625^2)/60000 + 115 x 2 pi 28.0625/60000 + pi (30^2 - 28.0625^2)/60000
    // = 0.0123828 + 0.3379504 + 0.0058902 = 0.3562234 min. Speeds 994.72 (r 32) to 1134.29 rpm (r 28.0625).
    void setUpSheetTimesAndSpeedsFollowThePath()
    {
        const Project p = example(QStringLiteral("stepped-shaft-chuck.tolturn"));
        const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
        const TurningProgram program = turningProgram(p, DataLibrary::builtIn(), *d.inputs, {});
        QCOMPARE(program.passes.size(), std::size_t{9});
        const PassSummary &first = program.passes.front();
        QCOMPARE(first.number, 1);
        QVERIFY2(std::abs(first.time_min - 0.3562234) < 2e-6, qPrintable(QString::number(first.time_min, 'f', 7)));
        QVERIFY(std::abs(first.lowestSpeed_rpm - 994.72) < 0.01);
        QVERIFY(std::abs(first.highestSpeed_rpm - 1134.29) < 0.01);
        QVERIFY(first.power_kW && *first.power_kW > 0.0);
        QCOMPARE(program.passes.back().kind, PassKind::Finishing);
        QCOMPARE(program.checksum.size(), 16);
    }

    // The step of the long shaft at z 380 falls in the feed direction (vertical); a PCLNR holder
    // (kappa_r 95°) with a CNMG insert (epsilon_r 80°) trails at 180 - 95 - 80 = 5°.
    void fallingStepBeyondTheTrailingEdgeIsAWarning()
    {
        const Project p = example(QStringLiteral("long-shaft-centres.tolturn"));
        const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
        const TurningProgram program = turningProgram(p, DataLibrary::builtIn(), *d.inputs, {});
        QCOMPARE(program.path.warnings.size(), 2); // and the chamfer O2 and O3 near the left centre
        QVERIFY(program.path.warnings.constFirst().startsWith(QStringLiteral("O4 falls at 90.0°")));
        QVERIFY(program.path.warnings.constFirst().contains(QStringLiteral("(5.0°)")));
        QVERIFY(program.path.warnings.constLast().startsWith(QStringLiteral("O2, O3 reach within 2.800 mm")));
        QVERIFY(!program.path.endFaceFaced); // between centres: the end face is not faced
    }

    // Any fall steeper than the trailing edge less 2° of free cutting angle (5° - 2° = 3°) is
    // ridden over, however low: with the nose at a 0.4 mm step down towards the headstock the
    // trailing edge would already dip 0.8 (1 - cos(60° - 5°)) / cos 5° = 0.34 mm into the body
    // behind it (the nose centre 60° round the corner: cos 60° = (0.8 - 0.4)/0.8). The left
    // shoulder lowered to a 0.4 mm step: the body's target (Ø42 h7, 0/-25 µm, at mid-zone r
    // 20.99375) falls to the journal's r 20.6 (O3's tolerance removed: at nominal). The pass rides
    // down from z 120 to 120 - (20.99375 - 20.6)/tan 3° = 112.487 mm and leaves 0.394 mm.
    void fallIsRiddenOverAtTheTrailingEdge()
    {
        Project p = example(QStringLiteral("long-shaft-centres.tolturn"));
        std::vector<Segment> &outer = p.part.outer.segments;
        const double journal = 20.6; // O3, the left journal, under the Ø42 body
        outer[1].to.r_mm = journal;  // O2, the chamfer up to it
        outer[2].from.r_mm = outer[2].to.r_mm = journal;
        outer[3].from.r_mm = journal; // O4, the shoulder up to the body
        p.tolerances.erase(std::remove_if(p.tolerances.begin(), p.tolerances.end(),
                                          [](const Tolerance &t) { return t.featureId == QLatin1String("O3"); }),
                           p.tolerances.end());
        const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY(d.inputs.has_value());
        const TurningProgram program = turningProgram(p, DataLibrary::builtIn(), *d.inputs, {});
        const auto fall = std::find_if(program.path.warnings.begin(), program.path.warnings.end(),
                                       [](const QString &w) { return w.startsWith(QStringLiteral("O4 falls")); });
        QVERIFY(fall != program.path.warnings.end());
        QVERIFY2(fall->contains(QStringLiteral("rides over it at 3.0° from z = 120.000 to 112.487 mm and leaves up to "
                                               "0.394 mm of O4, O3 uncut")),
                 qPrintable(*fall));
    }

    // No line of any example's program, in any dialect, is longer than 72 characters: a comment is
    // wrapped with its parentheses (LinuxCNC refuses blocks over 256, a control's screen is narrow),
    // the spindle limit's reason stands on its own lines above the limit, and the clamping is named
    // as people read it ("CHUCK + TAILSTOCK", not the file's keyword). The O-word and the number the
    // program is known by are the same.
    void everyProgramLineFitsAControlScreen()
    {
        for (const QString &f : QDir(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples"))
                                    .entryList({QStringLiteral("*.tolturn")}, QDir::Files)) {
            const Project p = operationView(example(f), 0);
            const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
            QVERIFY(d.inputs);
            for (const ControlDialect dialect :
                 {ControlDialect::FanucHaas, ControlDialect::Sinumerik, ControlDialect::LinuxCnc}) {
                GCodeOptions o;
                o.dialect = dialect;
                const TurningProgram program = turningProgram(p, DataLibrary::builtIn(), *d.inputs, o);
                for (const QString &line : program.text.split(QLatin1Char('\n')))
                    QVERIFY2(line.size() <= 72, qPrintable(f + QStringLiteral(": ") + line));
                QVERIFY(!program.text.contains(QStringLiteral("CHUCK_TAILSTOCK")));
                if (dialect == ControlDialect::FanucHaas)
                    QVERIFY(program.text.contains(QStringLiteral("\nO01000\n")));
            }
        }
        QCOMPARE(programNumberWord(1000), QStringLiteral("O01000"));
        QCOMPARE(programNumberWord(42), QStringLiteral("O00042"));
    }

    // What the program leaves unfinished, by hand. The long shaft between centres: the tool keeps
    // 2 mm + r_e 0.8 mm from the left centre (z 0), so the journal O3 (from z 1) is turned from
    // z 2.8 (sampled every 0.05 mm: 1.000–2.750 left); at the shoulder O4 (z 120) it rides down at
    // 3° from the body's target (Ø42 h7 at mid-zone, r 20.99375) to the journal's (Ø40 k6, +2/+18
    // µm, at mid-zone r 20.005): the line meets it at 120 - 0.98875/tan 3° = 101.134, and a sample
    // more than 2 µm below it lies at z > 101.134 + 0.002/tan 3° = 101.172: 101.200–120.000 left.
    // The chamfer O2 and the face O4 are left too, and both end faces, O1 and O9, which sit on the
    // centres (faced and centred before); the body O5 and everything right of it up to O9 is turned.
    void unfinishedStretchesOfTheLongShaft()
    {
        const Project p = example(QStringLiteral("long-shaft-centres.tolturn"));
        const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY(d.inputs);
        const std::vector<UnfinishedStretch> left = unfinishedStretches(p, *d.inputs);
        QStringList texts;
        for (const UnfinishedStretch &s : left)
            texts << unfinishedText(s);
        QVERIFY2(texts.contains(QStringLiteral("z 1.000–2.750 mm of O3")), qPrintable(texts.join(QLatin1Char('|'))));
        QVERIFY2(texts.contains(QStringLiteral("z 101.200–120.000 mm of O3")),
                 qPrintable(texts.join(QLatin1Char('|'))));
        QSet<QString> features;
        for (const UnfinishedStretch &s : left)
            features.insert(s.featureId);
        QCOMPARE(features, (QSet<QString>{QStringLiteral("O1"), QStringLiteral("O2"), QStringLiteral("O3"),
                                          QStringLiteral("O4"), QStringLiteral("O9")}));

        // The stepped shaft in its chuck (jaws to z 35): the seat O4 from the jaw face, turned from
        // z 35 + 2 + 0.8 = 37.8, and the shoulder O3 at the jaw face, not faced at all: from the seat's
        // target (Ø50 h6 at mid-zone, r 24.996) to the grip's r 28. The grip O2 is in the jaws.
        const Project shaft = example(QStringLiteral("stepped-shaft-chuck.tolturn"));
        const DeviationResult ds = computeDeviation(shaft, DataLibrary::builtIn(), {});
        QVERIFY(ds.inputs);
        QStringList shaftTexts;
        for (const UnfinishedStretch &s : unfinishedStretches(shaft, *ds.inputs))
            shaftTexts << unfinishedText(s);
        QCOMPARE(shaftTexts, (QStringList{QStringLiteral("O3 at z = 35.000 mm from r 24.996 to 28.000 mm"),
                                          QStringLiteral("z 35.000–37.750 mm of O4")}));
    }

    // A DIN 509 E0.6×0.3 undercut in the stepped shaft's corner O8|O9: its R0.6 is tighter than the
    // nose (r_e 0.8 mm), which LinuxCNC's G42 refuses ("Tool radius not less than arc radius with
    // comp"): the program has the corner instead, the interpreter runs it, and a warning names the
    // radius.
    void tightUndercutRadiusIsProgrammedAsItsCorner()
    {
        Project p = example(QStringLiteral("stepped-shaft-chuck.tolturn"));
        const std::optional<FeatureRef> o9 = findFeature(p.part, QStringLiteral("O9"));
        QVERIFY(o9);
        p.part = std::get<PartProfile>(insertUndercut(p.part, ContourSide::Outer, o9->index, UndercutForm::E));
        const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY(d.inputs);
        GCodeOptions o;
        o.dialect = ControlDialect::LinuxCnc;
        const TurningProgram program = turningProgram(p, DataLibrary::builtIn(), *d.inputs, o);
        QVERIFY2(
            std::any_of(program.path.warnings.begin(), program.path.warnings.end(),
                        [](const QString &w) { return w.startsWith(QStringLiteral("O14 is tighter than the nose")); }),
            qPrintable(program.path.warnings.join(QLatin1Char('\n'))));
        Lathe lathe;
        setUpLathe(lathe, d.inputs->noseRadius_mm);
        const QString canonical = runInterpreter(lathe, program.text);
        QVERIFY2(!canonical.startsWith(QStringLiteral("ERROR")), qPrintable(canonical));
    }

    // A concave R0.5 fillet (tighter than the nose, r_e 0.8) between a convex R2.5 round (on the
    // Ø36 hub seat, untoleranced here, so programmed at nominal) and the Ø30 journal: the round ends vertical at (z
    // 120.5, r 15.5), the journal runs at r 15 from z 121. The corner of their tangents is (120.5, 15): the journal is
    // programmed to it, then a line up the round's tangent to the round, which is programmed as drawn. LinuxCNC runs it
    // (the fillet as drawn it refuses: "Tool radius not less than arc radius with comp"), and says why.
    void tightFilletBesideARoundIsProgrammedAsTheTangentsCorner()
    {
        Project p = example(QStringLiteral("stepped-shaft-chuck.tolturn"));
        std::vector<Segment> &outer = p.part.outer.segments;
        QCOMPARE(outer[6].id, QStringLiteral("O7"));
        outer[5].to.r_mm = outer[4].to.r_mm = outer[5].from.r_mm = 18.0; // the Ø36 hub seat O6
        outer[4].to.r_mm = 18.0;
        outer[6].from = {118.0, 18.0};
        outer[6].to = {120.5, 15.5};
        outer[6].arcRadius_mm = 2.5;
        outer[7] = concaveFillet({120.5, 15.5}, {121.0, 15.0}, 0.5); // in place of the face O8
        outer[8].from = {121.0, 15.0};
        p.tolerances.erase(std::remove_if(p.tolerances.begin(), p.tolerances.end(),
                                          [](const Tolerance &t) {
                                              return t.featureId == QLatin1String("O6") ||
                                                     t.featureId == QLatin1String("O8") ||
                                                     t.toFeatureId == QLatin1String("O8");
                                          }),
                           p.tolerances.end());
        const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY2(d.inputs, qPrintable(dump(d.diagnostics)));
        GCodeOptions o;
        o.dialect = ControlDialect::LinuxCnc;
        const TurningProgram program = turningProgram(p, DataLibrary::builtIn(), *d.inputs, o);
        QVERIFY2(program.warnings().join(QLatin1Char(' ')).contains(QStringLiteral("O12 is tighter than the nose")),
                 qPrintable(program.warnings().join(QLatin1Char('\n'))));
        // Z0 at the right end face (z 150), X on diameter, the tool going left: the journal to the
        // corner, then up the round's tangent to where the round begins.
        const qsizetype corner = program.text.indexOf(QStringLiteral("X30.000 Z-29.500"));
        QVERIFY2(corner > 0, qPrintable(program.text));
        QVERIFY2(program.text.mid(corner).section(QLatin1Char('\n'), 1, 1).contains(QStringLiteral("X31.000 Z-29.500")),
                 qPrintable(program.text.mid(corner, 200)));
        QVERIFY(!program.text.contains(QStringLiteral("R0.500")));
        Lathe lathe;
        setUpLathe(lathe, d.inputs->noseRadius_mm);
        const QString canonical = runInterpreter(lathe, program.text);
        QVERIFY2(!canonical.startsWith(QStringLiteral("ERROR")), qPrintable(canonical));
    }

    // The H7 bushing from a Ø24 pilot hole, by hand. The target is the middle of H7 (0 / +25 µm on
    // Ø32): r = 16.00625 mm; roughed to it less the finishing allowance of 0.5 mm, 15.50625 mm, less
    // the 1 µm the last level stays off it. From r 12 the roughing pass's 1.5 mm give levels (the
    // top of the nose, which cuts the bore) at r 13.5 and 15.0, and the rest, 0.50525 mm, a third at
    // 15.50525. The finishing pass runs along the bore at 16.00625 to the left end (the bar reaches
    // 110 + 2 - 115 = -3 mm). The smallest diameter bored, 27 mm at 220 m/min, sets the spindle limit:
    // 1000 x 220 / (pi x 27) = 2593.6, so 2594 rpm. In the program: tool 2 and G41.
    void boringLevelsByHand()
    {
        const Project p = bushingFromPilotHole();
        const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY2(d.inputs && d.inputs->boring, qPrintable(dump(d.diagnostics)));
        GCodeOptions o;
        o.dialect = ControlDialect::FanucHaas;
        const TurningProgram program = turningProgram(p, DataLibrary::builtIn(), *d.inputs, o);
        QVERIFY(program.boring);
        const Toolpath &bore = *program.boring;
        QVERIFY2(bore.warnings.isEmpty(), qPrintable(bore.warnings.join(QLatin1Char('\n'))));
        const std::vector<double> levels{13.5, 15.0, 16.00625 - 0.5 - 0.001};
        QCOMPARE(bore.roughing.size(), levels.size());
        for (std::size_t k = 0; k < levels.size(); ++k) {
            double highest = -1.0;
            for (const ToolMove &m : bore.roughing[k].moves)
                if (m.kind == MoveKind::Feed)
                    highest = std::max(highest, m.to.r_mm);
            QVERIFY2(std::abs(highest - levels[k]) < 1e-9, qPrintable(QString::number(highest, 'f', 6)));
        }
        QCOMPARE(bore.roughing.front().smallestDiameter_mm, 27.0);
        const auto along = std::find_if(bore.finishing.moves.begin(), bore.finishing.moves.end(),
                                        [](const ToolMove &m) { return m.featureId == QLatin1String("I1"); });
        QVERIFY(along != bore.finishing.moves.end());
        QVERIFY(std::abs(along->to.r_mm - 16.00625) < 1e-9 && std::abs(along->to.z_mm) < 1e-9);
        QCOMPARE(program.spindle.speed_rpm, 2594.0);
        QCOMPARE(program.passes.size(), program.path.roughing.size() + 1 + levels.size() + 1);
        QCOMPARE(program.passes.back().side, ContourSide::Inner);
        QCOMPARE(passKindText(program.passes.back()), QStringLiteral("boring, finishing"));
        QVERIFY(program.text.contains(QStringLiteral("T0202")));
        QVERIFY(program.text.contains(QStringLiteral("G41 G01")));
        QCOMPARE(program.text.count(QStringLiteral("(BORE PASS ")), 4);
        // Before the turret indexes the bar it goes clear of the part: up to the turning path's
        // safe diameter, then out along z by the bar's overhang and the clearance, 115 + 2 mm.
        QStringList blocks;
        for (const QString &line : program.text.split(QLatin1Char('\n')))
            if (!line.startsWith(QLatin1Char('(')))
                blocks << line;
        const auto call = std::find_if(blocks.begin(), blocks.end(),
                                       [](const QString &b) { return b.contains(QStringLiteral("T0202")); });
        QVERIFY(call != blocks.end() && call - blocks.begin() >= 2);
        QVERIFY2(call[-1].endsWith(QStringLiteral("G00 Z117.000")), qPrintable(call[-1]));
        QVERIFY2(call[-2].endsWith(QStringLiteral("G00 X") + QString::number(program.path.safeDiameter_mm, 'f', 3)),
                 qPrintable(call[-2]));
    }

    // What the bar cannot do is said: a bar too thick for the pilot hole, an overhang that does not
    // reach the bottom, a bore without a pilot hole, a bottom face the bar cannot reach to the axis.
    void boringLimitsAreWarnings()
    {
        Project tooThick = bushingFromPilotHole();
        tooThick.boringTool->pilotHoleDiameter_mm = 15.0; // a Ø16 bar in a Ø15 hole
        const DeviationResult d1 = computeDeviation(tooThick, DataLibrary::builtIn(), {});
        QVERIFY(d1.inputs);
        const TurningProgram p1 = turningProgram(tooThick, DataLibrary::builtIn(), *d1.inputs, {});
        QVERIFY2(p1.boring && p1.boring->warnings.join(QLatin1Char(' ')).contains(QStringLiteral("does not fit")),
                 qPrintable(p1.warnings().join(QLatin1Char('\n'))));

        Project shortBar = bushingFromPilotHole();
        shortBar.boringTool->overhang_mm = 100.0; // reaches z = 110 + 2 - 100 = 12
        const DeviationResult d2 = computeDeviation(shortBar, DataLibrary::builtIn(), {});
        QVERIFY(d2.inputs);
        const TurningProgram p2 = turningProgram(shortBar, DataLibrary::builtIn(), *d2.inputs, {});
        QVERIFY(p2.boring && p2.boring->warnings.join(QLatin1Char(' ')).contains(QStringLiteral("reaches z = 12.000")));
        double leftmost = 1e9;
        for (const PassPath *pass : {&p2.boring->roughing.front(), &p2.boring->finishing})
            for (const ToolMove &m : pass->moves)
                leftmost = std::min(leftmost, m.to.z_mm);
        QVERIFY2(leftmost >= 12.0 - 0.4 - 1e-9, qPrintable(QString::number(leftmost))); // tip r_e left of the nose

        Project noPilot = bushingFromPilotHole();
        noPilot.boringTool->pilotHoleDiameter_mm.reset();
        const DeviationResult d3 = computeDeviation(noPilot, DataLibrary::builtIn(), {});
        const TurningProgram p3 = turningProgram(noPilot, DataLibrary::builtIn(), *d3.inputs, {});
        QVERIFY(p3.boring && p3.boring->roughing.empty());
        QVERIFY(p3.boring->warnings.join(QLatin1Char(' ')).contains(QStringLiteral("pilot hole is not given")));

        // The valve body's bore from the right end, blind, with its bottom on the axis at z 75: the
        // Ø16 bar, edge 8 mm from its axis, in the Ø25 bore touches the opposite wall when its edge
        // is nearer the axis than 8 + 8 - 12.508 25 = 3.491 75 mm (the bore at the middle of its H8
        // zone, Ø25.0165: IT8 is 33 µm from 18 to 30 mm, ISO 286-1 table 1). With the Ø19 pilot hole
        // the bottom inside it is the drill's; without one the bar faces down to Ø6.9835 and says so.
        Project valve = operationView(example(QStringLiteral("valve-body-two-bores.tolturn")), 0);
        const DeviationResult d4 = computeDeviation(valve, DataLibrary::builtIn(), {});
        QVERIFY(d4.inputs);
        const TurningProgram p4 = turningProgram(valve, DataLibrary::builtIn(), *d4.inputs, {});
        QVERIFY(p4.boring);
        QVERIFY(!p4.boring->warnings.join(QLatin1Char(' ')).contains(QStringLiteral("only down to")));
        QVERIFY(p4.boring->notes.join(QLatin1Char(' ')).contains(QStringLiteral("pilot hole, Ø19.000 mm")));
        valve.boringTool->pilotHoleDiameter_mm.reset();
        const TurningProgram p4b = turningProgram(valve, DataLibrary::builtIn(), *d4.inputs, {});
        QVERIFY2(p4b.boring->warnings.join(QLatin1Char(' ')).contains(QStringLiteral("I3 only down to Ø6.98")),
                 qPrintable(p4b.boring->warnings.join(QLatin1Char('\n'))));
        double innermost = 1e9; // the G41 contour: the bar's edge stops where it reaches
        for (const ToolMove &m : p4b.boring->finishing.moves)
            innermost = std::min(innermost, m.to.r_mm);
        QVERIFY2(std::abs(innermost - 3.49175) < 1e-6, qPrintable(QString::number(innermost, 'f', 6)));

        // A centre in the free end: no bar can enter it.
        Project centre = bushingFromPilotHole();
        centre.clamping.method = ClampingMethod::ChuckTailstock;
        const DeviationResult d6 = computeDeviation(centre, DataLibrary::builtIn(), {});
        QVERIFY2(d6.inputs, qPrintable(dump(d6.diagnostics)));
        const TurningProgram p6 = turningProgram(centre, DataLibrary::builtIn(), *d6.inputs, {});
        QVERIFY(!p6.boring && !p6.text.contains(QStringLiteral("T0202")));
        QVERIFY(p6.warnings().join(QLatin1Char(' ')).contains(QStringLiteral("a centre holds the set-up's free end")));

        // A bar that does not reach into the part (overhang 1 mm, less than the clearance) bores
        // nothing and says why.
        BoringBarGeometry stub{QStringLiteral("E16R-SCLCR09"), 16.0, 8.0, 1.0, 0.4, std::nullopt, 24.0};
        const Project bushing = bushingFromPilotHole();
        const std::optional<Toolpath> none =
            boringToolpath(bushing, bushing.passes.back(), {}, stub, ToolpathOptions{});
        QVERIFY(none && none->roughing.empty() && none->finishing.moves.empty());
        QVERIFY(none->warnings.join(QLatin1Char(' ')).contains(QStringLiteral("reaches z = 111.000")));

        // A pilot hole wider than the bore (Ø36 in the Ø32 H7 bore): the program cannot make the
        // bore, and says so rather than that the finishing pass cuts less than its depth.
        Project wide = bushingFromPilotHole();
        wide.boringTool->pilotHoleDiameter_mm = 36.0;
        BoringBarGeometry reaching = stub;
        reaching.overhang_mm = 115.0;
        reaching.pilotHoleDiameter_mm = 36.0;
        const std::optional<Toolpath> scrap = boringToolpath(wide, wide.passes.back(), {}, reaching, ToolpathOptions{});
        QVERIFY(scrap);
        QVERIFY2(scrap->warnings.join(QLatin1Char(' ')).contains(QStringLiteral("nothing is left to bore")),
                 qPrintable(scrap->warnings.join(QLatin1Char('\n'))));

        // A through bore corrected station by station: the stations end at the chuck face (z 25), the
        // bore runs on to z 0 inside the jaws, from the last corrected radius to the drawn one.
        FeatureCompensation corrected;
        corrected.featureId = QStringLiteral("I1");
        corrected.side = ContourSide::Inner;
        corrected.action = CompensationAction::ProfileCorrection;
        corrected.correctedPath = {{25.0, 16.012}, {67.5, 16.015}, {110.0, 16.012}};
        CompensationPlan plan;
        plan.features.push_back(corrected);
        const std::vector<PathElement> chain =
            toolpath_detail::compensatedChain(targetContour(bushing, ContourSide::Inner), &plan);
        double deepest = 1e9;
        for (const PathElement &e : chain)
            if (e.featureId == QLatin1String("I1"))
                deepest = std::min({deepest, e.from.z_mm, e.to.z_mm});
        QCOMPARE(deepest, 0.0);

        Project noBar = example(QStringLiteral("bushing-bore-h7.tolturn"));
        noBar.boringTool.reset();
        const DeviationResult d5 = computeDeviation(noBar, DataLibrary::builtIn(), {});
        const TurningProgram p5 = turningProgram(noBar, DataLibrary::builtIn(), *d5.inputs, {});
        QVERIFY(!p5.boring);
        QVERIFY(p5.path.notes.join(QLatin1Char(' ')).contains(QStringLiteral("no boring bar")));
    }

    void linuxCncBoresTheBore_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("operation");
        QTest::addColumn<int>("nose");
        QTest::addColumn<double>("pilot"); // 0: as in the file, -1: none
        QTest::addColumn<bool>("recess");  // the H7 bushing's bore with a recess r 17, z 40-70
        for (const QString &f : QDir(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples"))
                                    .entryList({QStringLiteral("*.tolturn")}, QDir::Files)) {
            for (int k = 0; k < operationCount(example(f)); ++k) {
                const Project view = operationView(example(f), k);
                if (!view.boringTool || boreAtFreeEnd(view.part.inner, view.part.length_mm()).empty())
                    continue;
                QTest::addRow("%s op %d G41", qPrintable(f), k + 1)
                    << f << k << static_cast<int>(NoseHandling::ControlCompensation) << 0.0 << false;
                QTest::addRow("%s op %d tip path", qPrintable(f), k + 1)
                    << f << k << static_cast<int>(NoseHandling::TipPath) << 0.0 << false;
            }
        }
        // Without a pilot hole: the finishing pass only.
        const QString valve = QStringLiteral("valve-body-two-bores.tolturn");
        QTest::addRow("valve body op 1 without a pilot hole")
            << valve << 0 << static_cast<int>(NoseHandling::ControlCompensation) << -1.0 << false;
        QTest::addRow("valve body op 2 without a pilot hole")
            << valve << 1 << static_cast<int>(NoseHandling::TipPath) << -1.0 << false;
        // A recess the bar meets going in (I4 falls away from the axis): ridden over, not gouged.
        const QString bushing = QStringLiteral("bushing-bore-h7.tolturn");
        QTest::addRow("bushing with a recess G41")
            << bushing << 0 << static_cast<int>(NoseHandling::ControlCompensation) << 0.0 << true;
        QTest::addRow("bushing with a recess tip path")
            << bushing << 0 << static_cast<int>(NoseHandling::TipPath) << 0.0 << true;
    }

    // The boring bar's program through LinuxCNC's interpreter. The nose centre of the bar (canonical
    // tip + (r_e, -r_e): its imaginary tip is r_e above and r_e left of the centre) in the finishing
    // pass keeps at least r_e - 1 µm from the bore (no gouge), and every point of the bore this
    // set-up cuts is within r_e + 1 µm of it (the bore is reproduced), except what the bar cannot
    // reach: left of its overhang's reach, the bottom inside the pilot hole or nearer the axis than
    // the bar's edge offset plus its radius less the bore's (where its far side would touch the
    // wall), and the nose's own radius in an inner corner. Every roughing nose centre keeps the
    // finishing allowance plus r_e (less the 2 µm of the path's simplification).
    void linuxCncBoresTheBore()
    {
        QFETCH(QString, file);
        QFETCH(int, operation);
        QFETCH(int, nose);
        QFETCH(double, pilot);
        QFETCH(bool, recess);
        Project whole = example(file);
        if (recess) { // I1 (r 16, z 0-110) in five: r 16 to z 40, up to r 17, on to z 70, down to r 16
            using test::seg;
            whole.part.inner.segments = {
                seg("I1", SegmentKind::Cylinder, {0, 16}, {40, 16}), seg("I2", SegmentKind::Face, {40, 16}, {40, 17}),
                seg("I3", SegmentKind::Cylinder, {40, 17}, {70, 17}), seg("I4", SegmentKind::Face, {70, 17}, {70, 16}),
                seg("I5", SegmentKind::Cylinder, {70, 16}, {110, 16})};
        }
        Project p = operationView(whole, operation);
        if (pilot < 0.0)
            p.boringTool->pilotHoleDiameter_mm.reset();
        const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY2(d.inputs && d.inputs->boring, qPrintable(dump(d.diagnostics)));
        const BoringInputs &bar = *d.inputs->boring;
        const double re = bar.noseRadius_mm;
        GCodeOptions o;
        o.nose = static_cast<NoseHandling>(nose);
        o.dialect = ControlDialect::LinuxCnc;
        const TurningProgram program = turningProgram(p, DataLibrary::builtIn(), *d.inputs, o);
        QVERIFY(program.boring);
        Lathe lathe;
        setUpLathe(lathe, d.inputs->noseRadius_mm, re);
        const QString canonical = runInterpreter(lathe, program.text);
        QVERIFY2(!canonical.startsWith(QStringLiteral("ERROR")), qPrintable(canonical));
        const double length = p.part.length_mm();
        std::vector<PathElement> centre;
        std::vector<PathElement> roughingCentre;
        for (const CanonicalPass &pass : readCanonical(canonical, length)) {
            if (!pass.bore)
                continue;
            for (const PathElement &m : pass.moves)
                (pass.finishing ? centre : roughingCentre).push_back(translated({m}, re, -re).front());
        }
        QVERIFY(!centre.empty());
        QCOMPARE(!roughingCentre.empty(), p.boringTool->pilotHoleDiameter_mm.has_value());
        const std::vector<Segment> boreSegments = boreAtFreeEnd(targetContour(p, ContourSide::Inner), length);
        const std::vector<PathElement> bore = reversedElements(boreSegments);
        const double closest = closestApproach(centre, bore);
        QVERIFY2(closest >= re - 0.001, qPrintable(QStringLiteral("gouge: %1").arg(closest, 0, 'f', 5)));
        // The bar's trailing edge, mirrored about the axis where the bore is an outer contour
        // (E16R-SCLCR09 and S25T-PCLNR12, 95°, with a C insert, 80°: 5°).
        std::vector<ProfilePoint> mirroredBore;
        for (const PathElement &e : toolpath_detail::mirrored(bore))
            for (const ProfilePoint &q : sampled(e, 0.05))
                mirroredBore.push_back(q);
        trailingEdgeStaysOff(toolpath_detail::mirrored(centre), mirroredBore, re);
        trailingEdgeStaysOff(toolpath_detail::mirrored(roughingCentre), mirroredBore, re);
        double roughClosest = 1e9;
        for (const PathElement &e : roughingCentre)
            for (const ProfilePoint &c : sampled(e, 0.01))
                roughClosest = std::min(roughClosest, distanceToPath(bore, c));
        const double allowance = d.inputs->pass.depthOfCut_mm;
        QVERIFY2(roughingCentre.empty() || roughClosest >= allowance + re - 0.002,
                 qPrintable(QStringLiteral("into the allowance: %1").arg(roughClosest, 0, 'f', 5)));

        // The bar's edge (the nose's leftmost point, the imaginary tip in z) reaches the overhang
        // less the 2 mm the turret keeps off the end face, in roughing and finishing alike; the
        // wall is cut up to r_e right of that.
        const double reach = length + 2.0 - bar.bar.overhang_mm;
        for (const CanonicalPass &pass : readCanonical(canonical, length)) {
            for (const PathElement &m : pass.moves) {
                if (!pass.bore)
                    continue;
                for (const ProfilePoint &tip : sampled(m, 0.05))
                    QVERIFY2(tip.z_mm >= reach - 1e-6,
                             qPrintable(QStringLiteral("tip at z %1, the bar reaches %2").arg(tip.z_mm).arg(reach)));
            }
        }
        const double halfBar = 0.5 * bar.bar.diameter_mm;
        // Inner corners of the bore as the bar sees them: mirrored about the axis, where the bore is
        // an outer contour, a corner turning right.
        const std::vector<PathElement> seen = toolpath_detail::mirrored(bore);
        std::vector<ProfilePoint> innerCorners;
        for (std::size_t i = 1; i < seen.size(); ++i) {
            const ProfilePoint a = endTangent(seen[i - 1]);
            const ProfilePoint b = startTangent(seen[i]);
            if (a.z_mm * b.r_mm - a.r_mm * b.z_mm < -1e-9)
                innerCorners.push_back({bore[i].from.z_mm, bore[i].from.r_mm});
        }
        double farthest = 0.0;
        // Where the bore widens going in faster than the bar's trailing edge less 2° (3°), the bar
        // rides over it: a point below (mirrored) the line at 3° from the bore on its right is not
        // reached.
        const double rideSlope = std::tan(3.0 * std::numbers::pi / 180.0);
        double top = -std::numeric_limits<double>::infinity();
        bool otherSetUp = false; // from the first feature another set-up cuts on, nothing is this one's
        for (const PathElement &e : bore) {
            otherSetUp = otherSetUp || (p.scope && !p.scope->cutFeatures.contains(e.featureId));
            if (otherSetUp)
                break;
            const bool face = std::abs(e.from.z_mm - e.to.z_mm) < 1e-9;
            const bool bottom = face && e.to.r_mm < 1e-9;
            const double drilled =
                bottom && p.boringTool->pilotHoleDiameter_mm ? 0.5 * *p.boringTool->pilotHoleDiameter_mm : 0.0;
            const double barReach = face ? bar.bar.edgeOffset_mm + halfBar - e.from.r_mm : 0.0;
            for (const ProfilePoint &q : sampled(e, 0.05)) {
                const bool nearCorner = std::any_of(innerCorners.begin(), innerCorners.end(),
                                                    [&](ProfilePoint c) { return distance(c, q) < re + 1e-6; });
                const bool riddenOver = -q.r_mm + rideSlope * q.z_mm < top - 1e-4;
                top = std::max(top, -q.r_mm + rideSlope * q.z_mm);
                if (q.z_mm < reach + re - 1e-9 || (face && q.r_mm < std::max(drilled, barReach) - 1e-9) || nearCorner ||
                    riddenOver)
                    continue;
                farthest = std::max(farthest, distanceToPath(centre, q));
            }
        }
        QVERIFY2(farthest <= re + 0.001, qPrintable(QStringLiteral("not reached: %1").arg(farthest, 0, 'f', 5)));

        o.dialect = ControlDialect::FanucHaas;
        const QString fanuc = turningProgram(p, DataLibrary::builtIn(), *d.inputs, o).text;
        QCOMPARE(programmedMoves(fanuc), programmedMoves(program.text));
        QVERIFY(fanuc.contains(QStringLiteral("T0202")));
        QCOMPARE(fanuc.contains(QStringLiteral("G41 ")), o.nose == NoseHandling::ControlCompensation);
        QCOMPARE(fanuc.contains(QStringLiteral("BORING BAR: PATH OF THE IMAGINARY TOOL TIP")),
                 o.nose == NoseHandling::TipPath);
    }

    void linuxCncRunsTheCompensatedProgram_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("nose");
        QTest::addColumn<int>("operation");
        for (const QString &f : QDir(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples"))
                                    .entryList({QStringLiteral("*.tolturn")}, QDir::Files)) {
            for (int k = 0; k < operationCount(example(f)); ++k) {
                QTest::addRow("%s op %d G42", qPrintable(f), k + 1)
                    << f << static_cast<int>(NoseHandling::ControlCompensation) << k;
                QTest::addRow("%s op %d tip path", qPrintable(f), k + 1)
                    << f << static_cast<int>(NoseHandling::TipPath) << k;
            }
        }
    }

    // The compensated program (`gcode --compensated`) runs through LinuxCNC's interpreter as the
    // nominal one does. A feature moved by micrometres meets its neighbour without a step of its
    // own: such a step beside a corner is a move the control cannot follow with the nose radius
    // compensated ("Straight feed in concave corner cannot be reached by the tool without gouging"),
    // and the tip path would drop it. The moved feature's radius is where the interpreter cuts.
    void linuxCncRunsTheCompensatedProgram()
    {
        QFETCH(QString, file);
        QFETCH(int, nose);
        QFETCH(int, operation);
        const Project p = operationView(example(file), operation);
        GCodeOptions o;
        o.nose = static_cast<NoseHandling>(nose);
        o.dialect = ControlDialect::LinuxCnc;
        const FinishingOutput out = finishingOutput(p, DataLibrary::builtIn(), o);
        QVERIFY(out.deviation.inputs);
        // No feature the nominal program follows is too tight for the nose in the compensated one.
        const auto tight = [](const TurningProgram &program) {
            QStringList said = program.warnings().filter(QStringLiteral("narrower or tighter than the nose"));
            said.removeDuplicates();
            return said;
        };
        QCOMPARE(tight(out.compensated), tight(out.nominal));
        Lathe lathe;
        setUpLathe(lathe, out.deviation.inputs->noseRadius_mm,
                   out.deviation.inputs->boring ? out.deviation.inputs->boring->noseRadius_mm : 0.4);
        const QString canonical = runInterpreter(lathe, out.compensated.text);
        QVERIFY2(!canonical.startsWith(QStringLiteral("ERROR")), qPrintable(canonical));
        // The thin pin's Ø20 is corrected station by station, and its smallest programmed diameter
        // is in the program (the test is not passed by a program that left the correction out).
        if (file == QLatin1String("thin-pin-compensation.tolturn")) {
            const FeatureCompensation *pin = out.compensation.find(QStringLiteral("O4"));
            QVERIFY(pin && pin->action == CompensationAction::ProfileCorrection);
            double smallest = 1e9;
            for (const ProfilePoint &q : pin->correctedPath)
                smallest = std::min(smallest, q.r_mm);
            QVERIFY(out.compensated.text.contains(QStringLiteral("X%1").arg(2.0 * smallest, 0, 'f', 3)));
        }
    }

    // A profile correction of the stepped shaft's R2 edge round O7 (centre z 118, r 18; material
    // inside the circle): a 10 µm profile tolerance needs it. Lines between its 21 stations,
    // evenly spaced in z, would span up to 18° of the round where it turns steep, and their
    // sagitta R(1 − cos 9°) = 25 µm cuts into the part. The corrected round stays within the
    // largest station correction plus 0.5 µm of the arc everywhere.
    void profileCorrectionOfARoundFollowsTheRound()
    {
        Project p = example(QStringLiteral("stepped-shaft-chuck.tolturn"));
        Tolerance round;
        round.id = QStringLiteral("T9");
        round.featureId = QStringLiteral("O7");
        round.type = ToleranceType::Profile;
        round.zone_um = 10.0;
        p.tolerances.push_back(round);
        const FinishingOutput out = finishingOutput(p, DataLibrary::builtIn(), {});
        const FeatureCompensation *c = out.compensation.find(QStringLiteral("O7"));
        QVERIFY(c && c->action == CompensationAction::ProfileCorrection);
        const ProfilePoint centre{118.0, 18.0};
        const double radius = 2.0;
        double largest = 0.0; // the stations' correction, normal to the round
        for (const ProfilePoint &st : c->correctedPath) {
            const double dz = st.z_mm - centre.z_mm;
            const double onArc = centre.r_mm + std::sqrt(std::max(radius * radius - dz * dz, 0.0));
            largest = std::max(largest, std::abs(st.r_mm - onArc));
        }
        QVERIFY(largest > 0.0 && largest < 0.02);
        const std::vector<PathElement> chain =
            toolpath_detail::compensatedChain(targetContour(p, ContourSide::Outer), &out.compensation);
        double worst = 0.0;
        int pieces = 0;
        for (const PathElement &e : chain) {
            if (e.featureId != QLatin1String("O7"))
                continue;
            ++pieces;
            for (const ProfilePoint &q : sampled(e, 0.001))
                worst = std::max(worst, std::abs(distance(q, centre) - radius));
        }
        QVERIFY(pieces > 0);
        QVERIFY2(worst <= largest + 0.5e-3,
                 qPrintable(QStringLiteral("%1 mm off the round, stations %2 mm").arg(worst).arg(largest)));
    }

    // Where a moved feature meets its neighbour: the stepped shaft's cone O5 (Ø50 at z 80 to Ø40 at
    // z 90) corrected by +3 µm of radius between the toleranced O4 (h6) and O6 (g6), and O6 itself
    // moved by an offset of -10 µm on the diameter next to the R2 round O7. A toleranced cylinder
    // is not tilted to take up a gap (a short line joins), and a moved feature is not moved back
    // beside a round: O4 and O6 stay at their programmed radius all along.
    void movedFeaturesLeaveTolerancedNeighboursAsProgrammed()
    {
        const Project p = example(QStringLiteral("stepped-shaft-chuck.tolturn"));
        const Contour target = targetContour(p, ContourSide::Outer);
        const auto radiusOf = [&target](const char *id) {
            for (const Segment &seg : target.segments)
                if (seg.id == QLatin1String(id))
                    return seg.from.r_mm;
            return -1.0;
        };
        CompensationPlan plan;
        FeatureCompensation cone;
        cone.featureId = QStringLiteral("O5");
        cone.tolerances << QStringLiteral("T3");
        cone.action = CompensationAction::ProfileCorrection;
        cone.correctedPath = {{80.0, radiusOf("O4") + 0.003}, {85.0, 22.5 + 0.003}, {90.0, radiusOf("O6") + 0.003}};
        FeatureCompensation seat;
        seat.featureId = QStringLiteral("O4");
        seat.tolerances << QStringLiteral("T1");
        FeatureCompensation hub;
        hub.featureId = QStringLiteral("O6");
        hub.tolerances << QStringLiteral("T4");
        hub.action = CompensationAction::ConstantOffset;
        hub.offset_um = -10.0;
        plan.features = {cone, seat, hub};
        const std::vector<PathElement> chain = toolpath_detail::compensatedChain(target, &plan);
        int seen = 0;
        for (const PathElement &e : chain) {
            const double expected = e.featureId == QLatin1String("O4")   ? radiusOf("O4")
                                    : e.featureId == QLatin1String("O6") ? radiusOf("O6") - 0.005
                                                                         : -1.0;
            if (expected < 0.0 || std::abs(e.from.z_mm - e.to.z_mm) < 1e-9)
                continue; // not O4 or O6, or a joining step
            ++seen;
            QVERIFY2(std::abs(e.from.r_mm - expected) < 1e-12 && std::abs(e.to.r_mm - expected) < 1e-12,
                     qPrintable(QStringLiteral("%1: r %2 to %3, not %4")
                                    .arg(e.featureId)
                                    .arg(e.from.r_mm, 0, 'f', 6)
                                    .arg(e.to.r_mm, 0, 'f', 6)
                                    .arg(expected, 0, 'f', 6)));
        }
        QCOMPARE(seen, 2);
    }

    // The stepped shaft without its finishing pass: eight roughing passes. The last is the contour
    // pass (the verdicts rest on it); it is not also cut as a ninth level first, and the program and
    // `check` say that the finishing pass is missing.
    void withoutAFinishingPassTheLastPassCutsTheContour()
    {
        Project p = example(QStringLiteral("stepped-shaft-chuck.tolturn"));
        QCOMPARE(p.passes.back().kind, PassKind::Finishing);
        p.passes.pop_back();
        QCOMPARE(p.passes.size(), std::size_t(8));
        const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY(d.inputs);
        const TurningProgram program = turningProgram(p, DataLibrary::builtIn(), *d.inputs, {});
        QCOMPARE(program.path.roughing.size(), std::size_t(7));
        QCOMPARE(program.passes.size(), std::size_t(8));
        QVERIFY2(program.warnings().join(QLatin1Char(' ')).contains(QStringLiteral("has no finishing pass")),
                 qPrintable(program.warnings().join(QLatin1Char('\n'))));
        const Diagnostics found = checkPlausibility(p, DataLibrary::builtIn());
        QVERIFY(std::any_of(found.begin(), found.end(), [](const Diagnostic &x) {
            return x.field == QLatin1String("passes") && x.message.startsWith(QStringLiteral("no finishing pass"));
        }));
    }

    // The tool stops 2 mm off the jaws with its edge: its nose centre 2 + r_e = 2.8 mm. The stepped
    // shaft gripped 32.5 mm: its shoulder O3 at z 35 faces the free end and is faced with the centre
    // r_e right of it, at 35.8 mm, beyond the stop at 35.3: it is in the program (it was dropped, as
    // if it were a diameter there), and the interpreter's tip keeps 2 mm off the jaws. Gripped
    // 34.5 mm the stop is at 37.3: O3 is out of reach. The end face at 150 is faced with the centre
    // at 150.8: gripped 148 mm (stop 150.8) it is cut, gripped 148.5 mm (stop 151.3) nothing is: the
    // finishing pass cuts nothing, which is said; with no roughing either, no spindle limit of
    // 0 rpm is written.
    void facesNearTheJawsAreCutWhereTheNoseReachesThem()
    {
        const auto programFor = [](double gripped, ControlDialect dialect = ControlDialect::LinuxCnc,
                                   bool finishingOnly = false) {
            Project p = example(QStringLiteral("stepped-shaft-chuck.tolturn"));
            p.clamping.clampedLength_mm = gripped;
            if (finishingOnly)
                p.passes.erase(p.passes.begin(), p.passes.end() - 1);
            const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
            GCodeOptions o;
            o.dialect = dialect;
            return turningProgram(p, DataLibrary::builtIn(), *d.inputs, o);
        };
        const auto cuts = [](const TurningProgram &program, const QString &feature) {
            return std::any_of(program.path.finishing.moves.begin(), program.path.finishing.moves.end(),
                               [&feature](const ToolMove &m) { return m.featureId == feature; });
        };
        const TurningProgram near = programFor(32.5);
        QVERIFY(cuts(near, QStringLiteral("O3")));
        // The jaws warning names the clamping diameter, not the shoulder it now faces.
        QVERIFY2(near.warnings().join(QLatin1Char(' ')).contains(QStringLiteral("O2 reaches within 2.800 mm")),
                 qPrintable(near.warnings().join(QLatin1Char('\n'))));
        Lathe lathe;
        setUpLathe(lathe, 0.8);
        const QString canonical = runInterpreter(lathe, near.text);
        QVERIFY2(!canonical.startsWith(QStringLiteral("ERROR")), qPrintable(canonical));
        for (const CanonicalPass &pass : readCanonical(canonical, 150.0))
            for (const PathElement &m : pass.moves)
                for (const ProfilePoint &tip : sampled(m, 0.05))
                    QVERIFY2(tip.z_mm >= 34.5 - 1e-6, qPrintable(QString::number(tip.z_mm)));
        QVERIFY(!cuts(programFor(34.5), QStringLiteral("O3")));
        QVERIFY(cuts(programFor(148.0), QStringLiteral("O11")));
        const TurningProgram none = programFor(148.5);
        QVERIFY(none.path.finishing.moves.empty());
        QVERIFY2(none.warnings().join(QLatin1Char(' ')).contains(QStringLiteral("The finishing pass cuts nothing")),
                 qPrintable(none.warnings().join(QLatin1Char('\n'))));
        // The end face alone (gripped 148 mm, no roughing): no turned diameter, but the spindle is
        // still limited, at the speed of the face's largest diameter, Ø28 at 250 m/min:
        // 1000 · 250 / (π · 28) = 2842.1, so 2843 rpm (without it G96 runs up to the axis).
        const TurningProgram facing = programFor(148.0, ControlDialect::FanucHaas, true);
        QVERIFY(facing.path.roughing.empty() && !facing.path.finishing.moves.empty());
        QVERIFY2(facing.text.contains(QStringLiteral("G50 S2843")), qPrintable(facing.text));
        QVERIFY(!facing.warnings().join(QLatin1Char(' ')).contains(QStringLiteral("No roughing pass is planned")));
        // A set-up that only bores (the valve body's OP 20 given its bores alone) turns nothing
        // outside by design: no "cuts nothing" warning for its outer pass.
        Project valve = example(QStringLiteral("valve-body-two-bores.tolturn"));
        valve.furtherOperations.front().features = {QStringLiteral("I1"), QStringLiteral("I2")};
        const Project boresOnly = operationView(valve, 1);
        const DeviationResult vd = computeDeviation(boresOnly, DataLibrary::builtIn(), {});
        QVERIFY2(vd.inputs, qPrintable(dump(vd.diagnostics)));
        const TurningProgram bores = turningProgram(boresOnly, DataLibrary::builtIn(), *vd.inputs, {});
        QVERIFY(bores.path.finishing.moves.empty());
        QVERIFY(!bores.warnings().join(QLatin1Char(' ')).contains(QStringLiteral("The finishing pass cuts nothing")));
        // Without roughing passes nothing at all is cut: no speed to limit.
        const TurningProgram nothing = programFor(148.5, ControlDialect::FanucHaas, true);
        QVERIFY(nothing.path.roughing.empty() && nothing.path.finishing.moves.empty());
        QVERIFY2(!nothing.text.contains(QStringLiteral("G50 S0")), qPrintable(nothing.text));
        QVERIFY(!none.warnings().join(QLatin1Char(' ')).contains(QStringLiteral("No roughing pass is planned")));
    }

    // A concave R0.4 fillet (tighter than the nose, r_e 0.8) between the shoulder O3 (face at z 35)
    // and the bearing seat O4 (r 25, now from z 35.4). Gripped 32.9 mm, the nose centre stops at
    // 32.9 + 2 + 0.8 = 35.7 mm; touching the shoulder it is at 35 + 0.8 = 35.8 mm, so the shoulder is
    // faced, although the seat ends at 35.4 mm, left of the stop. The fillet is programmed as the
    // corner (35, 25); below the shoulder's top the tool's leftmost point is the face, 35 mm (within
    // 1 µm), and nowhere does it pass the stop 34.9 mm.
    // The jaws warning names the clamping diameter O2 only: O3 and the fillet are cut to their
    // left ends.
    void shoulderBehindATightFilletIsFacedWhereTheNoseReachesIt()
    {
        Project p = example(QStringLiteral("stepped-shaft-chuck.tolturn"));
        p.clamping.clampedLength_mm = 32.9;
        std::vector<Segment> &outer = p.part.outer.segments;
        QCOMPARE(outer[2].id, QStringLiteral("O3"));
        outer[2].to.r_mm = 25.4;
        outer[3].from.z_mm = 35.4;
        outer.insert(outer.begin() + 3, concaveFillet({35.0, 25.4}, {35.4, 25.0}, 0.4));
        const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY2(d.inputs, qPrintable(dump(d.diagnostics)));
        QCOMPARE(d.inputs->noseRadius_mm, 0.8);
        GCodeOptions o;
        o.dialect = ControlDialect::LinuxCnc;
        const TurningProgram program = turningProgram(p, DataLibrary::builtIn(), *d.inputs, o);
        const auto cuts = [&program](const QString &feature) {
            return std::any_of(program.path.finishing.moves.begin(), program.path.finishing.moves.end(),
                               [&feature](const ToolMove &m) { return m.featureId == feature; });
        };
        QVERIFY(cuts(QStringLiteral("O3")));
        // Z0 at the right end face (z 150), X on diameter: the seat, Ø50 h6 at the middle of its zone
        // (IT6 over 30–50 mm is 16 µm: 50 − 0.008 = 49.992), runs to the corner at z 35, and the
        // shoulder is faced from there.
        const qsizetype corner = program.text.indexOf(QStringLiteral("X49.992 Z-115.000"));
        QVERIFY2(corner > 0, qPrintable(program.text.right(600)));
        QVERIFY2(
            program.text.mid(corner).section(QLatin1Char('\n'), 1, 1).contains(QStringLiteral("X56.000 Z-115.000")),
            qPrintable(program.text.mid(corner, 200)));
        const QStringList warnings = program.warnings();
        const auto jaws = std::find_if(warnings.begin(), warnings.end(), [](const QString &w) {
            return w.contains(QStringLiteral("of the chuck face, where the tool does not go"));
        });
        QVERIFY2(jaws != warnings.end() && jaws->startsWith(QStringLiteral("O2 reaches within 2.800 mm")),
                 qPrintable(warnings.join(QLatin1Char('\n'))));
        Lathe lathe;
        setUpLathe(lathe, d.inputs->noseRadius_mm);
        const QString canonical = runInterpreter(lathe, program.text);
        QVERIFY2(!canonical.startsWith(QStringLiteral("ERROR")), qPrintable(canonical));
        for (const CanonicalPass &pass : readCanonical(canonical, 150.0))
            for (const PathElement &m : pass.moves)
                for (const ProfilePoint &tip : sampled(m, 0.05))
                    // Clear of the jaws everywhere; below the shoulder's top (r 28) not into it. Above it
                    // the roughing takes the stock over the clamping diameter to the stop, 34.9 mm.
                    QVERIFY2(tip.z_mm >= (tip.r_mm < 28.0 ? 35.0 - 1e-3 : 34.9 - 1e-6),
                             qPrintable(QStringLiteral("%1 %2").arg(tip.z_mm).arg(tip.r_mm)));
    }

    void linuxCncReproducesTheProfile_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("nose");
        QTest::addColumn<int>("operation");
        QTest::addColumn<QString>("insert"); // instead of the project's, when given
        for (const QString &f : QDir(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples"))
                                    .entryList({QStringLiteral("*.tolturn")}, QDir::Files)) {
            // Each set-up of a project of several has its own program.
            for (int k = 0; k < operationCount(example(f)); ++k) {
                QTest::addRow("%s op %d G42", qPrintable(f), k + 1)
                    << f << static_cast<int>(NoseHandling::ControlCompensation) << k << QString();
                QTest::addRow("%s op %d tip path", qPrintable(f), k + 1)
                    << f << static_cast<int>(NoseHandling::TipPath) << k << QString();
            }
        }
        // A nose (r_e 0.2 mm) smaller than the DIN 509 F undercut's R0.6: bridging the recess at the
        // corner of its face and floor would cut 0.15 mm into that radius (a gouge).
        const QString undercut = QStringLiteral("shaft-din509-undercut.tolturn");
        QTest::addRow("undercut r_e 0.2 G42")
            << undercut << static_cast<int>(NoseHandling::ControlCompensation) << 0 << QStringLiteral("CNMG 120402");
        QTest::addRow("undercut r_e 0.2 tip path")
            << undercut << static_cast<int>(NoseHandling::TipPath) << 0 << QStringLiteral("CNMG 120402");
    }

    // The trailing edge of the insert (5° from the z axis, tangent to the nose of radius r_e at the
    // point 5° right of its bottom) never dips below the contour on its right within 5 mm of the
    // nose, at any point of the finishing pass's nose-centre path, to 1 µm.
    static void trailingEdgeStaysOff(const std::vector<PathElement> &centre, const std::vector<ProfilePoint> &contour,
                                     double re)
    {
        const double k = 5.0 * std::numbers::pi / 180.0;
        std::vector<ProfilePoint> byZ = contour;
        std::sort(byZ.begin(), byZ.end(), [](ProfilePoint a, ProfilePoint b) { return a.z_mm < b.z_mm; });
        double worst = 0.0;
        for (const PathElement &m : centre) {
            for (const ProfilePoint &c : sampled(m, 0.05)) {
                const ProfilePoint t{c.z_mm + re * std::sin(k), c.r_mm - re * std::cos(k)};
                auto q = std::lower_bound(byZ.begin(), byZ.end(), t.z_mm,
                                          [](ProfilePoint a, double z) { return a.z_mm < z; });
                for (; q != byZ.end() && q->z_mm <= t.z_mm + 5.0; ++q)
                    worst = std::max(worst, q->r_mm - (t.r_mm + (q->z_mm - t.z_mm) * std::tan(k)));
            }
        }
        QVERIFY2(worst <= 0.001, qPrintable(QStringLiteral("trailing edge %1 mm into the part").arg(worst, 0, 'f', 4)));
    }

    // The program run through LinuxCNC's interpreter: the nose centre (canonical tip + r_e, r_e) of
    // every finishing move keeps at least r_e - 1 µm from the whole contour (no gouge), and every
    // point of the contour the pass turns is within r_e + 1 µm of the nose-centre path (the profile
    // is reproduced). No roughing or finishing point goes into the jaws; the other dialects carry
    // the same moves.
    void linuxCncReproducesTheProfile()
    {
        QFETCH(QString, file);
        QFETCH(int, nose);
        QFETCH(int, operation);
        QFETCH(QString, insert);
        Project p = operationView(example(file), operation);
        if (!insert.isEmpty())
            p.tool.insertCode = insert;
        const DeviationResult d = computeDeviation(p, DataLibrary::builtIn(), {});
        QVERIFY(d.inputs);
        const double re = d.inputs->noseRadius_mm;
        GCodeOptions o;
        o.nose = static_cast<NoseHandling>(nose);
        o.dialect = ControlDialect::LinuxCnc;
        const TurningProgram linuxcnc = turningProgram(p, DataLibrary::builtIn(), *d.inputs, o);
        QVERIFY(linuxcnc.text.contains(QStringLiteral("G96 D")) && linuxcnc.text.contains(QStringLiteral("G95")) &&
                linuxcnc.text.contains(QStringLiteral("G7")));
        Lathe lathe;
        setUpLathe(lathe, re, d.inputs->boring ? d.inputs->boring->noseRadius_mm : 0.4);
        const QString canonical = runInterpreter(lathe, linuxcnc.text);
        QVERIFY2(!canonical.startsWith(QStringLiteral("ERROR")), qPrintable(canonical));
        const double length = p.part.length_mm();
        const std::vector<CanonicalPass> passes = readCanonical(canonical, length);
        const double support = p.clamping.method == ClampingMethod::BetweenCentres ? 0.0 : p.clamping.clampedLength_mm;
        std::vector<PathElement> centre;
        std::vector<PathElement> roughingCentre;
        for (const CanonicalPass &pass : passes) {
            if (pass.bore)
                continue; // the boring bar's (linuxCncBoresTheBore)
            for (const PathElement &m : pass.moves) {
                for (const ProfilePoint &tip : sampled(m, 0.05))
                    QVERIFY2(tip.z_mm >= support + 2.0 - 1e-6, qPrintable(QString::number(tip.z_mm)));
                if (pass.finishing)
                    centre.push_back(translated({m}, re, re).front());
                else
                    roughingCentre.push_back(translated({m}, re, re).front());
            }
        }
        QVERIFY(!centre.empty());
        const Contour target = targetContour(p, ContourSide::Outer);
        const std::vector<PathElement> contour = reversedElements(target.segments);
        const double closest = closestApproach(centre, contour);
        QVERIFY2(closest >= re - 0.001, qPrintable(QStringLiteral("gouge: %1").arg(closest, 0, 'f', 5)));
        // In one set-up of several the program turns from the free end to where another operation's
        // outer features begin.
        double boundary = 0.0;
        if (p.scope) {
            for (auto it = p.part.outer.segments.rbegin(); it != p.part.outer.segments.rend(); ++it) {
                if (!p.scope->cutFeatures.contains(it->id)) {
                    boundary = std::max(it->from.z_mm, it->to.z_mm);
                    break;
                }
            }
        }
        const double zFrom = std::max(support + 2.0 + re, boundary);
        const bool faced = p.clamping.method == ClampingMethod::Chuck;
        // A sharp inner corner keeps the nose radius: contour points within r_e of one are not reached.
        std::vector<ProfilePoint> innerCorners;
        for (std::size_t i = 1; i < contour.size(); ++i) {
            const ProfilePoint a = endTangent(contour[i - 1]);
            const ProfilePoint b = startTangent(contour[i]);
            if (a.z_mm * b.r_mm - a.r_mm * b.z_mm < -1e-9)
                innerCorners.push_back(contour[i].from);
        }
        // An undercut's recess is the undercut insert's: the turning program bridges it (the face
        // down to where the recess's radius crosses its z, that radius to the floor).
        // Its radius, tighter than a large nose, leaves the nose's radius in the corner: points of
        // the face and floor within r_e of it are not reached.
        QStringList undercut;
        std::vector<ProfilePoint> undercutPoints;
        for (const Segment &s : target.segments) {
            if (!s.turnsBack())
                continue;
            undercut << s.id;
            for (const ProfilePoint &q : samplePoints(s, 24))
                undercutPoints.push_back(q);
        }
        // Where the contour falls towards the headstock steeper than the trailing edge less the 2°
        // of free cutting angle (5° - 2° = 3° for a PCLNR holder, 95°, with a C insert, 80°: 180 -
        // 95 - 80 = 5°), the tool rides over it at 3°: a point below the line at 3° down from any
        // point of the contour on its right is not reached.
        const double rideSlope = std::tan(3.0 * std::numbers::pi / 180.0);
        std::vector<ProfilePoint> contourPoints;
        for (const PathElement &e : contour)
            for (const ProfilePoint &q : sampled(e, 0.05))
                contourPoints.push_back(q);
        std::vector<bool> shadowed; // in the feed direction: below the running top of r + slope z
        double top = -std::numeric_limits<double>::infinity();
        for (const ProfilePoint &q : contourPoints) {
            shadowed.push_back(q.r_mm + rideSlope * q.z_mm < top - 1e-4);
            top = std::max(top, q.r_mm + rideSlope * q.z_mm);
        }
        trailingEdgeStaysOff(centre, contourPoints, re);
        trailingEdgeStaysOff(roughingCentre, contourPoints, re);
        double farthest = 0.0;
        std::size_t sample = 0;
        for (const PathElement &e : contour) {
            for (const ProfilePoint &q : sampled(e, 0.05)) {
                if (shadowed.at(sample++))
                    continue;
                const auto within = [&](const std::vector<ProfilePoint> &points, double reach) {
                    return std::any_of(points.begin(), points.end(),
                                       [&](ProfilePoint c) { return distance(c, q) < reach; });
                };
                const bool nearInnerCorner = within(innerCorners, re + 1e-6) || within(undercutPoints, re + 1e-6);
                const bool othersFeature =
                    (p.scope && !p.scope->cutFeatures.contains(e.featureId)) || undercut.contains(e.featureId);
                if (othersFeature || q.z_mm < zFrom - 1e-9 || (!faced && std::abs(q.z_mm - length) < 1e-9) ||
                    (e.from.z_mm < zFrom && e.to.z_mm < zFrom) || nearInnerCorner)
                    continue;
                farthest = std::max(farthest, distanceToPath(centre, q));
            }
        }
        QVERIFY2(farthest <= re + 0.001, qPrintable(QStringLiteral("not reached: %1").arg(farthest, 0, 'f', 5)));
        // Nor does it touch what another operation turns (or turned): the nose centre stays right
        // of the boundary.
        double leftmost = 1e9;
        for (const PathElement &e : centre)
            for (const ProfilePoint &c : sampled(e, 0.05))
                leftmost = std::min(leftmost, c.z_mm);
        QVERIFY2(leftmost >= boundary - 0.001, qPrintable(QStringLiteral("over another operation's features: z = "
                                                                         "%1 < %2")
                                                              .arg(leftmost)
                                                              .arg(boundary)));

        o.dialect = ControlDialect::FanucHaas;
        const QString fanuc = turningProgram(p, DataLibrary::builtIn(), *d.inputs, o).text;
        o.dialect = ControlDialect::Sinumerik;
        const QString sinumerik = turningProgram(p, DataLibrary::builtIn(), *d.inputs, o).text;
        QVERIFY(fanuc.contains(QStringLiteral("G50 S")) && fanuc.contains(QStringLiteral("G99")));
        QVERIFY(sinumerik.contains(QStringLiteral("LIMS=")) && sinumerik.contains(QStringLiteral("DIAMON")) &&
                sinumerik.contains(QStringLiteral("G95")));
        QCOMPARE(programmedMoves(fanuc), programmedMoves(linuxcnc.text));
        QCOMPARE(programmedMoves(sinumerik), programmedMoves(linuxcnc.text));
    }
};

QTEST_GUILESS_MAIN(TestToolpath)
#include "tst_toolpath.moc"
