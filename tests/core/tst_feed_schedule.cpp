// SPDX-License-Identifier: GPL-3.0-or-later
// The feed schedule of the finishing pass (issue 18, docs/adaptive.md §5): every feature at the
// largest feed of the range that holds its tolerances, checked through the verdicts' own path
// (computeDeviation at that feed) and through the program it writes.
#include "tests/core/test_support.h"

#include "core/io/project_file.h"
#include "core/planning/feed_schedule.h"
#include "core/planning/planning_report.h"
#include "core/tolerance/evaluation.h"

#include <QTest>

#include <algorithm>

using namespace tolturn;

namespace {

// The slender pin example (Ø30 pin out of a chuck, T1 Ø h9 and T2 cylindricity on O4, feed range
// 0.170–0.399 mm/rev) without its Ra requirement, so that only the tolerances and the range bound
// the feed, and with T2's zone as given.
Project slenderPin(double cylindricity_um)
{
    const ProjectParseResult read =
        readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/slender-pin-chuck.tolturn"));
    Q_ASSERT(read.project);
    Project p = *read.project;
    p.planning.maxRa_um.reset();
    p.planning.maxRz_um.reset();
    for (Tolerance &t : p.tolerances)
        if (t.id == QLatin1String("T2"))
            t.zone_um = cylindricity_um;
    return p;
}

CuttingPass &finishingPass(Project &p)
{
    return *std::find_if(p.passes.begin(), p.passes.end(),
                         [](const CuttingPass &c) { return c.kind == PassKind::Finishing; });
}

// T2's predicted cylindricity with the whole finishing pass at feed f, the way the verdicts
// compute it (its stations are O4's alone, so only O4's feed matters).
double cylindricityAt(Project p, double feed)
{
    finishingPass(p).feed_mm_rev = feed;
    const DeviationResult d = computeDeviation(p, DataLibrary::builtIn());
    for (const ToleranceEvaluation &e : evaluateTolerances(p, d))
        if (e.toleranceId == QLatin1String("T2"))
            return e.value_um.value_or(-1.0);
    return -1.0;
}

FeedSchedule scheduleOf(const Project &p)
{
    const PlanningProblem::BuildResult built = PlanningProblem::build(p, DataLibrary::builtIn());
    Q_ASSERT(built.problem);
    Project copy = p;
    return scheduleFinishingFeeds(*built.problem, finishingPass(copy));
}

const ScheduledFeed &feedOf(const FeedSchedule &s, const char *feature)
{
    return *std::find_if(s.features.begin(), s.features.end(),
                         [&](const ScheduledFeed &f) { return f.featureId == QLatin1String(feature); });
}

double finishingMinutes(const TurningProgram &program)
{
    double t = 0.0;
    for (const PassSummary &p : program.passes)
        if (p.kind == PassKind::Finishing)
            t += p.time_min;
    return t;
}

} // namespace

class TestFeedSchedule : public QObject {
    Q_OBJECT

private Q_SLOTS:

    // T2 at 8 µm binds inside the range on O4 (7.3 µm at the programmed 0.25 mm/rev); the other
    // features carry no tolerance and go to the top of the range.
    void everyFeatureAtTheLargestFeedItsTolerancesHold()
    {
        const Project p = slenderPin(8.0);
        const FeedSchedule s = scheduleOf(p);
        QVERIFY2(s.ok(), qPrintable(test::dump(s.diagnostics)));
        const ScheduledFeed &o4 = feedOf(s, "O4");
        QVERIFY2(o4.feed_mm_rev > 0.25 && o4.feed_mm_rev < 0.399, qPrintable(QString::number(o4.feed_mm_rev)));
        QVERIFY(!o4.held);
        QVERIFY2(o4.limitedBy.contains(QLatin1String("T2")), qPrintable(o4.limitedBy));
        // Through the verdicts: inside at the scheduled feed, outside a program step (0.001) above.
        QVERIFY2(cylindricityAt(p, o4.feed_mm_rev) <= 8.0,
                 qPrintable(QString::number(cylindricityAt(p, o4.feed_mm_rev))));
        QVERIFY2(cylindricityAt(p, o4.feed_mm_rev + 0.001) > 8.0,
                 qPrintable(QString::number(cylindricityAt(p, o4.feed_mm_rev + 0.001))));
        for (const ScheduledFeed &f : s.features)
            if (f.featureId != QLatin1String("O4"))
                QCOMPARE(f.feed_mm_rev, 0.399);
    }

    // The program cuts O4 at its feed and the rest at theirs, and, every scheduled feed being
    // above the programmed one, its finishing pass takes less time than the constant-feed one.
    void theProgramCutsTheSchedule()
    {
        const Project p = slenderPin(8.0);
        const FeedSchedule s = scheduleOf(p);
        GCodeOptions options;
        options.finishingFeeds_mm_rev = s.feedByFeature();
        const TurningProgram scheduled = finishingOutput(p, DataLibrary::builtIn(), options).nominal;
        const TurningProgram constant = finishingOutput(p, DataLibrary::builtIn()).nominal;
        const double o4 = feedOf(s, "O4").feed_mm_rev;
        int o4Moves = 0;
        for (const ToolMove &m : scheduled.path.finishing.moves) {
            if (m.featureId == QLatin1String("O4")) {
                QCOMPARE(m.feed_mm_rev.value_or(-1.0), o4);
                ++o4Moves;
            }
        }
        QVERIFY(o4Moves > 0);
        QVERIFY(scheduled.text.contains(QStringLiteral(" F%1\n").arg(o4, 0, 'f', 3)));
        QVERIFY(scheduled.text.contains(QStringLiteral(" F0.399\n")));
        QVERIFY(!constant.text.contains(QStringLiteral(" F0.399\n")));
        QVERIFY2(
            finishingMinutes(scheduled) < finishingMinutes(constant),
            qPrintable(QStringLiteral("%1 vs %2").arg(finishingMinutes(scheduled)).arg(finishingMinutes(constant))));
    }

    // T2 at 4 µm is not held at any feed of the range (5.4 µm at 0.17): O4 keeps the programmed
    // feed, which its compensation is computed at, and says why.
    void aToleranceNoFeedHoldsKeepsTheProgrammedFeed()
    {
        const Project p = slenderPin(4.0);
        QVERIFY(cylindricityAt(p, 0.17) > 4.0);
        const FeedSchedule s = scheduleOf(p);
        const ScheduledFeed &o4 = feedOf(s, "O4");
        QVERIFY(o4.held);
        QCOMPARE(o4.feed_mm_rev, 0.25);
        QVERIFY(o4.limitedBy.contains(QLatin1String("T2")));
        QCOMPARE(feedOf(s, "O5").feed_mm_rev, 0.399);
    }

    // Scheduled and compensated, on the thin pin (T1 Ø20 h7 on O4, which no feed of the range holds):
    // O4 keeps the programmed 0.170 mm/rev and is compensated there, the other features run at
    // their scheduled feed. "Machined" through the model (the size cut at a station = the programmed
    // diameter + twice the radius error predicted at 0.170 mm/rev by computeDeviation), every station
    // of O4 the tool reaches lands in Ø20 h7 = 19.979–20.000 mm (IT7 = 21 µm over 18 up to 30 mm,
    // es = 0; ISO 286-1 table 1, ISO 286-2); without the compensation some station does not.
    void scheduledProgramIsCompensatedWhereNoFeedHolds()
    {
        const ProjectParseResult read =
            readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/thin-pin-compensation.tolturn"));
        QVERIFY(read.project);
        const Project &p = *read.project;
        const FeedSchedule s = scheduleProjectFinishingFeeds(p, DataLibrary::builtIn());
        QVERIFY(s.ok());
        QVERIFY(feedOf(s, "O4").held);
        QCOMPARE(feedOf(s, "O4").feed_mm_rev, 0.17);
        QVERIFY(feedOf(s, "O6").feed_mm_rev > 0.17);
        GCodeOptions options;
        options.finishingFeeds_mm_rev = s.feedByFeature();
        options.roughingFeedSchedule = true;
        const DeviationResult atProgrammed = computeDeviation(p, DataLibrary::builtIn());
        const FinishingOutput out =
            finishingOutputFor(p, DataLibrary::builtIn(), scheduledDeviation(s, atProgrammed), options);
        for (const FeatureCompensation &f : out.compensation.features)
            QVERIFY2((f.featureId == QLatin1String("O4")) == (f.action != CompensationAction::None),
                     qPrintable(f.featureId));
        QVERIFY(out.compensated.text.contains(QStringLiteral(" F0.202")));
        // The compensation was planned from the scheduled pass: the end face O6 deflects as at its own
        // 0.202 mm/rev (computeDeviation with the whole pass there), not as at the programmed feed.
        Project at202 = p;
        finishingPass(at202).feed_mm_rev = 0.202;
        const auto faceO6 = [](const DeviationResult &d) {
            return *std::find_if(d.faces.begin(), d.faces.end(),
                                 [](const FaceConicity &f) { return f.featureId == QLatin1String("O6"); });
        };
        const double scheduledTilt = faceO6(out.deviation).tanTheta;
        QVERIFY(std::abs(scheduledTilt - faceO6(computeDeviation(at202, DataLibrary::builtIn())).tanTheta) <
                1e-3 * std::abs(scheduledTilt));
        QVERIFY(std::abs(scheduledTilt - faceO6(atProgrammed).tanTheta) > 0.05 * std::abs(scheduledTilt));
        const FeatureDeviation *o4 = nullptr;
        for (const FeatureDeviation &f : atProgrammed.features)
            o4 = f.featureId == QLatin1String("O4") ? &f : o4;
        QVERIFY(o4);
        const auto machinedInside = [&](const TurningProgram &program) {
            const std::vector<test::Move> moves = test::finishingMoves(program.text);
            int checked = 0;
            for (const Station &st : o4->stations) {
                if (!test::reachedByTheTool(p, st.z_mm))
                    continue;
                // The programmed diameter at the station: the first move on the pin (travelling towards
                // the chuck) that ends at or beyond it, after any step in X at that Z (where the
                // corrected pin starts below the chamfer's end).
                const double z = st.z_mm - p.part.length_mm();
                auto m = std::find_if(moves.begin(), moves.end(), [&](const test::Move &mv) {
                    return mv.g == 1 && std::abs(mv.x - 20.0) < 0.2 && mv.z <= z + 1e-9;
                });
                if (m == moves.end())
                    return false;
                while (std::next(m) != moves.end() && std::abs(std::next(m)->z - m->z) < 1e-9 &&
                       std::abs(std::next(m)->x - 20.0) < 0.2)
                    ++m;
                const double machined = m->x + 2.0 * st.radiusError_mm;
                if (machined < 19.979 - 1e-6 || machined > 20.000 + 1e-6) {
                    qInfo("z %.3f: programmed %.4f, machined %.4f", st.z_mm, m->x, machined);
                    return false;
                }
                ++checked;
            }
            return checked > 10;
        };
        QVERIFY(machinedInside(out.compensated));
        QVERIFY(!machinedInside(out.nominal));
    }

    // The stepped shaft's third roughing level (r 30 − 3 · 1.9375 = 24.1875) meets the allowance of
    // the Ø50 seat (r 25 + 0.5) over z 37–80, where the level above left r 26.125: it cuts
    // 0.625 mm there instead of 1.9375. Kienzle (F ∝ a f^(1 − m), m ≈ 0.2) puts the feed of the
    // planned force at about 0.3 · 3.1^1.25 = 1.2 mm/rev, so the top of the range, 0.399, holds it;
    // from the right end to the cone (z 82) the level cuts its full depth and keeps 0.3.
    void roughingRunsFasterWhereALevelCutsLess()
    {
        const ProjectParseResult read =
            readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/stepped-shaft-chuck.tolturn"));
        QVERIFY(read.project);
        GCodeOptions options;
        options.roughingFeedSchedule = true;
        const TurningProgram scheduled = finishingOutput(*read.project, DataLibrary::builtIn(), options).nominal;
        const TurningProgram constant = finishingOutput(*read.project, DataLibrary::builtIn()).nominal;
        const PassPath &third = scheduled.path.roughing.at(2);
        int seat = 0;
        int full = 0;
        std::optional<ProfilePoint> at;
        for (const ToolMove &m : third.moves) {
            const std::optional<ProfilePoint> from = at;
            at = m.to;
            if (m.kind != MoveKind::Feed || !from || std::abs(m.to.z_mm - from->z_mm) < 1.0)
                continue;
            const double lo = std::min(from->z_mm, m.to.z_mm);
            const double hi = std::max(from->z_mm, m.to.z_mm);
            if (lo >= 37.0 && hi <= 80.0) {
                QCOMPARE(m.feed_mm_rev.value_or(-1.0), 0.399);
                ++seat;
            } else if (lo > 81.0) { // from the right end face to where the level meets the cone
                QVERIFY(!m.feed_mm_rev);
                ++full;
            }
        }
        QCOMPARE(seat, 1);
        QVERIFY(full >= 1);
        QVERIFY(scheduled.text.contains(QStringLiteral(" F0.399\n")));
        QVERIFY(outerRoughingTime_min(scheduled.passes) < outerRoughingTime_min(constant.passes));
        for (const PassPath &pass : scheduled.path.roughing)
            for (const ToolMove &m : pass.moves)
                QVERIFY(!m.feed_mm_rev || (*m.feed_mm_rev > 0.3 && *m.feed_mm_rev <= 0.399));
    }

    void everyKeptToleranceHoldsOnTheExamples_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<bool>("withRa");
        for (const char *name : {"stepped-shaft-chuck", "long-shaft-centres", "slender-pin-chuck",
                                 "hollow-sleeve-tailstock", "thin-pin-compensation"}) {
            QTest::addRow("%s", name) << QString::fromLatin1(name) << true;
            QTest::addRow("%s without Ra", name) << QString::fromLatin1(name) << false;
        }
    }

    // Whatever binds, the scheduled pass holds every tolerance whose features it schedules: a
    // tolerance that fails on it must have a feature kept at the programmed feed (the case for
    // compensation).
    void everyKeptToleranceHoldsOnTheExamples()
    {
        QFETCH(QString, file);
        QFETCH(bool, withRa);
        const ProjectParseResult read =
            readProjectFile(QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/%1.tolturn").arg(file));
        QVERIFY(read.project);
        Project p = *read.project;
        if (!withRa) {
            p.planning.maxRa_um.reset();
            p.planning.maxRz_um.reset();
        }
        const FeedSchedule s = scheduleOf(p);
        QVERIFY2(s.ok(), qPrintable(test::dump(s.diagnostics)));
        QVERIFY(!s.features.empty());
        for (const ConstraintValue &c : s.tolerances) {
            if (c.violation() <= 1e-9)
                continue;
            QStringList features; // the tolerance's own, a length's second face, its datums'
            for (const Tolerance &t : p.tolerances) {
                if (t.id != c.subject)
                    continue;
                features << t.featureId << t.toFeatureId;
                for (const Datum &d : p.datums)
                    if (t.datums.contains(d.label))
                        features << d.featureId;
            }
            bool held = false;
            for (const ScheduledFeed &f : s.features)
                held = held || (f.held && features.contains(f.featureId));
            QVERIFY2(held, qPrintable(c.label()));
        }
    }
};

QTEST_GUILESS_MAIN(TestFeedSchedule)
#include "tst_feed_schedule.moc"
