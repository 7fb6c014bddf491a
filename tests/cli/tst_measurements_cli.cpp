// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli measurements (issue 15): a measured part stored from CSV with its project, listed,
// exported with the values that went in, removed; bad files and stores named, nothing stored.
#include "tests/cli/cli_runner.h"

#include "core/data/data_library.h"
#include "core/deviation/deviation_model.h"
#include "core/io/project_file.h"
#include "core/io/project_json.h"
#include "core/tolerance/target_contour.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using tolturn::test::example;
using tolturn::test::Run;
using tolturn::test::runCli;
using tolturn::test::runProgram;
using tolturn::test::writeFile;

namespace {

// The stepped shaft measured with a micrometer at two places on the Ø50 and a dial gauge on the Ø40.
constexpr char kPoints[] = "feature,z_mm,diameter_mm,radial_deviation_um,x_mm,y_mm\n"
                           "# part 1 of the batch\n"
                           "O4,40,50.012,,,\n"
                           "O4,75,50.018,,,\n"
                           "O6,100,,6,,\n"
                           "# a CMM point on the Ø40 g6 seat: radius √(12.003² + 16.004²) = 20.005 mm\n"
                           "O6,110,,,12.003,16.004\n";

} // namespace

class TestMeasurementsCli : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

    [[nodiscard]] QString store() const { return m_dir.filePath(QStringLiteral("history.sqlite")); }

    tolturn::test::Run measurements(const QStringList &args)
    {
        return runCli(QStringList{QStringLiteral("measurements")} + args +
                      QStringList{QStringLiteral("--store"), store()});
    }

private Q_SLOTS:

    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QVERIFY(writeFile(m_dir.filePath(QStringLiteral("points.csv")), kPoints));
    }

    // In, listed, out as it went in, removed.
    void storesListsExportsAndRemoves()
    {
        const QString csv = m_dir.filePath(QStringLiteral("points.csv"));
        const auto added =
            measurements({QStringLiteral("add"), QStringLiteral("--csv"), csv, QStringLiteral("--by"),
                          QStringLiteral("A. Planner"), QStringLiteral("--method"), QStringLiteral("micrometer"),
                          QStringLiteral("--at"), QStringLiteral("2026-11-24T08:30:00Z"), QStringLiteral("--ambient"),
                          QStringLiteral("21.5"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(added.exitCode, 0);
        QVERIFY2(added.out.contains(QStringLiteral("stored part 1: Stepped shaft, 4 points")), qPrintable(added.out));
        const auto listed = measurements({QStringLiteral("list"), QStringLiteral("--json")});
        QCOMPARE(listed.exitCode, 0);
        const QJsonArray list = QJsonDocument::fromJson(listed.out.toUtf8()).array();
        QCOMPARE(list.size(), 1);
        const QJsonObject part = list.at(0).toObject();
        QCOMPARE(part.value(QStringLiteral("machine")).toString(), QStringLiteral("haas-st-20")); // the project's
        QCOMPARE(part.value(QStringLiteral("measured_at")).toString(), QStringLiteral("2026-11-24T08:30:00.000Z"));
        QCOMPARE(part.value(QStringLiteral("points")).toInt(), 4);
        const auto exported = measurements({QStringLiteral("export"), QStringLiteral("1")});
        QCOMPARE(exported.exitCode, 0);
        QCOMPARE(exported.out,
                 QStringLiteral("part,machine,measured_at,feature,z_mm,diameter_mm,radial_deviation_um,x_mm,y_mm\n"
                                "1,haas-st-20,2026-11-24T08:30:00.000Z,O4,40,50.012,,,\n"
                                "1,haas-st-20,2026-11-24T08:30:00.000Z,O4,75,50.018,,,\n"
                                "1,haas-st-20,2026-11-24T08:30:00.000Z,O6,100,,6,,\n"
                                "1,haas-st-20,2026-11-24T08:30:00.000Z,O6,110,,,12.003,16.004\n"));
        QCOMPARE(measurements({QStringLiteral("remove"), QStringLiteral("1")}).exitCode, 0);
        const auto again = measurements({QStringLiteral("remove"), QStringLiteral("1")});
        QCOMPARE(again.exitCode, 1);
        QVERIFY(again.err.contains(QStringLiteral("the store has no part 1")));
    }

    // Each wrong input named; the store keeps what it had.
    void badInputsAreNamed_data()
    {
        QTest::addColumn<QByteArray>("csv");
        QTest::addColumn<QStringList>("extra");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("message");
        QTest::newRow("bad cell") << QByteArray("feature,z_mm,diameter_mm\nO4,40,5O.01\n") << QStringList{} << 1
                                  << QStringLiteral(
                                         "points.csv:2: diameter_mm must be a number above zero, not \"5O.01\"");
        QTest::newRow("no feature column") << QByteArray("z_mm,diameter_mm\n40,50.01\n") << QStringList{} << 1
                                           << QStringLiteral("the header lacks the column \"feature\"");
        QTest::newRow("both values") << QByteArray("feature,z_mm,diameter_mm,radial_deviation_um\nO4,40,50.01,3\n")
                                     << QStringList{} << 1
                                     << QStringLiteral("points.csv:2: a line needs one of diameter_mm, "
                                                       "radial_deviation_um, or x_mm and y_mm (a CMM point)");
        QTest::newRow("half a CMM point") << QByteArray("feature,z_mm,x_mm,y_mm\nO6,100,12,\n") << QStringList{} << 1
                                          << QStringLiteral("points.csv:2: a line needs one of diameter_mm");
        QTest::newRow("CMM point off the seat")
            << QByteArray("feature,z_mm,x_mm,y_mm\nO6,100,18,24\n") << QStringList{} << 1
            << QStringLiteral("points[0].x_mm: a CMM point at radius 30 mm is not on feature O6 (R20 to R20 mm)");
        QTest::newRow("another part's diameter")
            << QByteArray("feature,z_mm,diameter_mm\nO4,40,42\n") << QStringList{} << 1
            << QStringLiteral("points[0].value_mm: a diameter of 42 mm does not fit feature O4 (Ø50 to Ø50 mm)");
        QTest::newRow("another machine")
            << QByteArray(kPoints) << QStringList{QStringLiteral("--machine"), QStringLiteral("haas-st-30")} << 1
            << QStringLiteral("machine: the part was cut on haas-st-30, but its project is planned for haas-st-20");
        QTest::newRow("hot shop") << QByteArray(kPoints)
                                  << QStringList{QStringLiteral("--ambient"), QStringLiteral("90")} << 1
                                  << QStringLiteral("ambient_C: the ambient temperature must be from -10 to 50 °C");
        QTest::newRow("bad time") << QByteArray(kPoints)
                                  << QStringList{QStringLiteral("--at"), QStringLiteral("monday")} << 2
                                  << QStringLiteral("--at takes a time as 2026-11-24T08:30:00Z, not \"monday\"");
    }

    void badInputsAreNamed()
    {
        QFETCH(QByteArray, csv);
        QFETCH(QStringList, extra);
        QFETCH(int, exitCode);
        QFETCH(QString, message);
        const QString file = m_dir.filePath(QStringLiteral("points.csv"));
        QVERIFY(writeFile(file, csv));
        const auto before = measurements({QStringLiteral("list"), QStringLiteral("--json")});
        const auto r = measurements(QStringList{QStringLiteral("add"), QStringLiteral("--csv"), file} + extra +
                                    QStringList{example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(r.exitCode, exitCode);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QCOMPARE(measurements({QStringLiteral("list"), QStringLiteral("--json")}).out, before.out);
        QVERIFY(writeFile(file, kPoints));
    }

    // Parts that came out exactly as the physics predicts plus 5 µm on the radius everywhere (a
    // machine that cuts large): the physics alone misses them by 5 µm RMS, what is learned takes
    // the 5 µm as the geometric offset and predicts parts it did not learn from.
    void learnsAConstantOffset()
    {
        const QString project = example("stepped-shaft-chuck.tolturn");
        const tolturn::Project p = *tolturn::readProjectFile(project).project;
        const tolturn::DeviationResult physics = tolturn::computeDeviation(p, tolturn::DataLibrary::builtIn(), {});
        const tolturn::ProgramTargets targets = tolturn::programTargets(p);
        QByteArray csv = "feature,z_mm,diameter_mm\n";
        for (const tolturn::FeatureDeviation &f : physics.features) {
            if (f.kind != tolturn::SegmentKind::Cylinder)
                continue;
            for (std::size_t i = 0; i < f.stations.size(); i += 5) {
                const tolturn::Station &st = f.stations[i];
                const double target = *tolturn::targetRadius_mm(targets.outer, f.featureId, st.z_mm);
                csv += f.featureId.toLatin1() + ',' + QByteArray::number(st.z_mm, 'g', 17) + ',' +
                       QByteArray::number(2.0 * (target + st.radiusError_mm + 0.005), 'g', 17) + '\n';
            }
        }
        const QString file = m_dir.filePath(QStringLiteral("offset.csv"));
        QVERIFY(writeFile(file, csv));
        const QString learnStore = m_dir.filePath(QStringLiteral("learn.sqlite"));
        for (int i = 0; i < 6; ++i) {
            const auto added =
                runCli({QStringLiteral("measurements"), QStringLiteral("add"), QStringLiteral("--csv"), file,
                        QStringLiteral("--time-since-start"), QString::number(30 * i), QStringLiteral("--ambient"),
                        QString::number(19 + i), QStringLiteral("--store"), learnStore, project});
            QCOMPARE(added.exitCode, 0);
        }
        const auto learned = runCli({QStringLiteral("learn"), QStringLiteral("--machine"), QStringLiteral("haas-st-20"),
                                     QStringLiteral("--json"), QStringLiteral("--store"), learnStore});
        QVERIFY2(learned.exitCode == 0, qPrintable(learned.err));
        const QJsonObject result = QJsonDocument::fromJson(learned.out.toUtf8()).object();
        QCOMPARE(result.value(QStringLiteral("parts")).toInt(), 6);
        // Every part at the plan's finishing feed, 0.1 mm/rev; the points' z from the stations.
        const QJsonArray feeds = result[QStringLiteral("learned_from")][QStringLiteral("feed_mm_rev")].toArray();
        QVERIFY2(feeds.size() == 2 && feeds[0].toDouble() == 0.1 && feeds[1].toDouble() == 0.1,
                 qPrintable(learned.out));
        const QJsonObject cv = result.value(QStringLiteral("cross_validation")).toObject();
        QVERIFY2(std::abs(cv.value(QStringLiteral("physics_rms_um")).toDouble() - 5.0) < 1e-6, qPrintable(learned.out));
        QVERIFY2(cv.value(QStringLiteral("learned_rms_um")).toDouble() < 0.1, qPrintable(learned.out));
        // Nothing kept yet: --learned says so; kept, the prediction adds the 5 µm at every station.
        const QStringList deflect{QStringLiteral("deflect"),
                                  QStringLiteral("--learned"),
                                  QStringLiteral("--json"),
                                  QStringLiteral("--store"),
                                  learnStore,
                                  project};
        const auto before = runCli(deflect);
        QCOMPARE(before.exitCode, 1);
        QVERIFY2(before.err.contains(QStringLiteral("nothing has been learned of haas-st-20 yet")),
                 qPrintable(before.err));
        const auto saved = runCli({QStringLiteral("learn"), QStringLiteral("--machine"), QStringLiteral("haas-st-20"),
                                   QStringLiteral("--save"), QStringLiteral("--store"), learnStore});
        QVERIFY2(saved.exitCode == 0 && saved.err.contains(QStringLiteral("kept as the model of haas-st-20")),
                 qPrintable(saved.err));
        const auto after = runCli(deflect);
        QVERIFY2(after.exitCode == 0, qPrintable(after.err));
        const QJsonObject deflected = QJsonDocument::fromJson(after.out.toUtf8()).object();
        QCOMPARE(deflected.value(QStringLiteral("learned")).toObject().value(QStringLiteral("parts")).toInt(), 6);
        int checked = 0;
        for (const auto &f : deflected.value(QStringLiteral("features")).toArray()) {
            if (f[QStringLiteral("type")].toString() != QLatin1String("cylinder"))
                continue;
            for (const auto &st : f[QStringLiteral("stations")].toArray()) {
                QVERIFY2(std::abs(st[QStringLiteral("learned_um")].toDouble() - 5.0) < 0.1,
                         qPrintable(QString::number(st[QStringLiteral("learned_um")].toDouble())));
                QCOMPARE(st[QStringLiteral("radius_error_with_learned_um")].toDouble(),
                         st[QStringLiteral("radius_error_um")].toDouble() +
                             st[QStringLiteral("learned_um")].toDouble());
                ++checked;
            }
        }
        QVERIFY(checked > 20);
        // The verdicts see it too: every predicted diameter 10 µm larger than the physics alone's.
        const auto plain = runCli({QStringLiteral("evaluate"), QStringLiteral("--json"), project});
        const auto judged = runCli({QStringLiteral("evaluate"), QStringLiteral("--learned"), QStringLiteral("--json"),
                                    QStringLiteral("--store"), learnStore, project});
        QVERIFY2(judged.exitCode == 0, qPrintable(judged.err));
        const QJsonArray without = QJsonDocument::fromJson(plain.out.toUtf8())[QStringLiteral("tolerances")].toArray();
        const QJsonArray with = QJsonDocument::fromJson(judged.out.toUtf8())[QStringLiteral("tolerances")].toArray();
        QCOMPARE(with.size(), without.size());
        int sizes = 0;
        for (qsizetype i = 0; i < with.size(); ++i) {
            if (with[i][QStringLiteral("type")].toString() != QLatin1String("diameter"))
                continue;
            const double shift = with[i][QStringLiteral("predicted_max_um")].toDouble() -
                                 without[i][QStringLiteral("predicted_max_um")].toDouble();
            QVERIFY2(std::abs(shift - 10.0) < 0.2, qPrintable(QString::number(shift)));
            ++sizes;
        }
        QVERIFY(sizes >= 2);
        // What the program does not finish is not judged with what was learned either.
        int unfinished = 0;
        for (qsizetype i = 0; i < with.size(); ++i) {
            if (without[i][QStringLiteral("range_verdict")].toString() != QLatin1String("not_finished"))
                continue;
            QCOMPARE(with[i][QStringLiteral("verdict")].toString(), QStringLiteral("cannot_evaluate"));
            QVERIFY(with[i][QStringLiteral("reason")].toString().startsWith(QStringLiteral("not finished")));
            ++unfinished;
        }
        QVERIFY(unfinished >= 1);
        // Every part was cut at the plan's finishing feed, 0.1 mm/rev: a plan at 0.2 lies outside
        // what was measured, and the verdicts say so.
        QVERIFY(QJsonDocument::fromJson(judged.out.toUtf8())[QStringLiteral("diagnostics")].toArray().isEmpty());
        tolturn::Project coarser = p;
        QCOMPARE(coarser.passes.back().feed_mm_rev, 0.1);
        coarser.passes.back().feed_mm_rev = 0.2;
        const QString coarserFile = m_dir.filePath(QStringLiteral("coarser.tolturn"));
        QVERIFY(writeFile(coarserFile, tolturn::serializeProjectJson(coarser)));
        const auto outside = runCli({QStringLiteral("evaluate"), QStringLiteral("--learned"), QStringLiteral("--json"),
                                     QStringLiteral("--store"), learnStore, coarserFile});
        QVERIFY2(outside.exitCode == 0, qPrintable(outside.err));
        const QJsonArray said = QJsonDocument::fromJson(outside.out.toUtf8())[QStringLiteral("diagnostics")].toArray();
        QVERIFY2(said.size() == 1 && said[0][QStringLiteral("message")].toString().contains(
                                         QStringLiteral("feed [mm/rev] 0.200–0.200 (measured parts 0.100–0.100)")),
                 qPrintable(outside.out));
        // The optimiser plans with it and says so; with a stiffness end as well it is a usage error.
        const auto planned = runCli({QStringLiteral("optimize"), QStringLiteral("--learned"), QStringLiteral("--json"),
                                     QStringLiteral("--time-limit"), QStringLiteral("20"), QStringLiteral("--store"),
                                     learnStore, project});
        const QJsonArray notes = QJsonDocument::fromJson(planned.out.toUtf8())[QStringLiteral("notes")].toArray();
        QVERIFY2(QJsonDocument(notes).toJson().contains("haas-st-20, model 1, 6 parts"), qPrintable(planned.out));
        const auto both =
            runCli({QStringLiteral("optimize"), QStringLiteral("--learned"), QStringLiteral("--machine-end"),
                    QStringLiteral("stiff"), QStringLiteral("--store"), learnStore, project});
        QCOMPARE(both.exitCode, 2);
        QVERIFY2(both.err.contains(QStringLiteral("--learned replaces the stiffness range")), qPrintable(both.err));
        // The report rests on it too, and says so on its first page.
        const QString pdf = m_dir.filePath(QStringLiteral("learned.pdf"));
        const auto reported = runCli({QStringLiteral("report"), QStringLiteral("--learned"), QStringLiteral("--store"),
                                      learnStore, QStringLiteral("-o"), pdf, project});
        QVERIFY2(reported.exitCode == 0, qPrintable(reported.err));
        const Run text = runProgram(QStringLiteral("pdftotext"),
                                    {QStringLiteral("-l"), QStringLiteral("1"), pdf, QStringLiteral("-")});
        QVERIFY2(text.out.simplified().contains(
                     QStringLiteral("as learned from its measured parts (haas-st-20, model 1, 6 parts")),
                 qPrintable(text.out));
        // Too few parts to leave one out: named.
        const auto none = runCli({QStringLiteral("learn"), QStringLiteral("--machine"), QStringLiteral("haas-st-30"),
                                  QStringLiteral("--store"), learnStore});
        QCOMPARE(none.exitCode, 1);
        QVERIFY2(none.err.contains(QStringLiteral("haas-st-30 has 0 stored part")), qPrintable(none.err));
    }

    // Drive readings with a part, and the forces of Li & Du's first stage: calibration cuts with
    // F_t = 40 N/A · ΔI_s and F_a = 25 N/A · ΔI_a; every part's forces then come from its currents.
    void learnsFromMotorCurrents()
    {
        QByteArray calibration = "spindle_current_A,spindle_idle_current_A,spindle_friction_current_A,"
                                 "spindle_speed_rad_s,spindle_acceleration_rad_s2,feed_current_A,feed_idle_current_A,"
                                 "feed_speed_mm_min,tangential_N,axial_N\n";
        for (int i = 0; i < 8; ++i) {
            for (int j = 0; j < 5; ++j) {
                const double spindle = 1.0 + 1.5 * i;
                const double feed = 0.5 + 0.3 * i;
                calibration += QStringLiteral("%1,5,0,%2,0,%3,1,%4,%5,%6\n")
                                   .arg(5.0 + spindle)
                                   .arg(100.0 + 20.0 * j)
                                   .arg(1.0 + feed)
                                   .arg(100.0 + 40.0 * j)
                                   .arg(40.0 * spindle)
                                   .arg(25.0 * feed)
                                   .toUtf8();
            }
        }
        const QString cal = m_dir.filePath(QStringLiteral("calibration.csv"));
        QVERIFY(writeFile(cal, calibration));
        const QString store = m_dir.filePath(QStringLiteral("currents.sqlite"));
        const QString csv = m_dir.filePath(QStringLiteral("currents-points.csv"));
        QVERIFY(writeFile(csv, kPoints));
        for (int i = 0; i < 3; ++i) {
            const QString drive = m_dir.filePath(QStringLiteral("drive%1.json").arg(i));
            QVERIFY(writeFile(drive, QStringLiteral("{\"spindle_current_A\": %1, \"spindle_idle_current_A\": 5, "
                                                    "\"spindle_friction_current_A\": 0, \"spindle_speed_rad_s\": 140, "
                                                    "\"spindle_acceleration_rad_s2\": 0, \"feed_current_A\": %2, "
                                                    "\"feed_idle_current_A\": 1, \"feed_speed_mm_min\": 180}")
                                         .arg(8.0 + i)
                                         .arg(1.8 + 0.2 * i)
                                         .toUtf8()));
            const auto added =
                runCli({QStringLiteral("measurements"), QStringLiteral("add"), QStringLiteral("--csv"), csv,
                        QStringLiteral("--drive"), drive, QStringLiteral("--time-since-start"), QString::number(20 * i),
                        QStringLiteral("--store"), store, example("stepped-shaft-chuck.tolturn")});
            QVERIFY2(added.exitCode == 0, qPrintable(added.err));
        }
        const auto learned = runCli({QStringLiteral("learn"), QStringLiteral("--machine"), QStringLiteral("haas-st-20"),
                                     QStringLiteral("--force-calibration"), cal, QStringLiteral("--store"), store});
        QVERIFY2(learned.exitCode == 0, qPrintable(learned.err));
        QVERIFY2(learned.err.contains(QStringLiteral("forces from motor currents: 40 calibration cuts")),
                 qPrintable(learned.err));
        QVERIFY2(learned.err.contains(QStringLiteral("3 of 3 parts learned from forces estimated from their motor "
                                                     "currents")),
                 qPrintable(learned.err));
        // A reading below its idle current, and a file that is not JSON: named, nothing stored.
        const QString below = m_dir.filePath(QStringLiteral("below.json"));
        QVERIFY(writeFile(below, "{\"spindle_current_A\": 4, \"spindle_idle_current_A\": 5, "
                                 "\"spindle_friction_current_A\": 0, \"spindle_speed_rad_s\": 140, "
                                 "\"spindle_acceleration_rad_s2\": 0, \"feed_current_A\": 2, "
                                 "\"feed_idle_current_A\": 1, \"feed_speed_mm_min\": 180}"));
        const auto refused = runCli({QStringLiteral("measurements"), QStringLiteral("add"), QStringLiteral("--csv"),
                                     csv, QStringLiteral("--drive"), below, QStringLiteral("--store"), store,
                                     example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(refused.exitCode, 1);
        QVERIFY2(refused.err.contains(QStringLiteral("drive.spindle_current_A")), qPrintable(refused.err));
        const QString notJson = m_dir.filePath(QStringLiteral("not.json"));
        QVERIFY(writeFile(notJson, "spindle 4 A"));
        const auto unread = runCli({QStringLiteral("measurements"), QStringLiteral("add"), QStringLiteral("--csv"), csv,
                                    QStringLiteral("--drive"), notJson, QStringLiteral("--store"), store,
                                    example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(unread.exitCode, 2);
        QVERIFY2(unread.err.contains(QStringLiteral("not.json: not a JSON object")), qPrintable(unread.err));
    }

    // Reading a store that is not there says so and makes none: before, learn and list made an
    // empty SQLite file at a mistyped path and reported no parts in it.
    void missingStoreIsNotMade()
    {
        const QString missing = m_dir.filePath(QStringLiteral("mistyped.sqlite"));
        const auto learn = runCli({QStringLiteral("learn"), QStringLiteral("--machine"), QStringLiteral("L1"),
                                   QStringLiteral("--store"), missing});
        QCOMPARE(learn.exitCode, 1);
        QVERIFY2(learn.err.contains(QStringLiteral("there is no measurement store %1").arg(missing)),
                 qPrintable(learn.err));
        const auto list =
            runCli({QStringLiteral("measurements"), QStringLiteral("list"), QStringLiteral("--store"), missing});
        QCOMPARE(list.exitCode, 1);
        QVERIFY(!QFileInfo::exists(missing));
    }

    // A database that is not there: named by its address (without the password).
    void unreachableStoreIsNamed()
    {
        const auto r = runCli({QStringLiteral("measurements"), QStringLiteral("list"), QStringLiteral("--store"),
                               QStringLiteral("postgresql://planner:secret@localhost:1/shop?host=") + m_dir.path()});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("cannot open the measurement store postgresql://planner@")),
                 qPrintable(r.err));
        QVERIFY(!r.err.contains(QStringLiteral("secret")));
    }
};

QTEST_GUILESS_MAIN(TestMeasurementsCli)
#include "tst_measurements_cli.moc"
