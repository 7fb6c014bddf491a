// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli as a user runs it: the real binary, its output streams and exit codes.
#include "tests/cli/cli_runner.h"

#include "core/common/finding_groups.h"
#include "core/cutting/cutting_forces.h"
#include "core/io/project_file.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <numbers>

using tolturn::test::example;
using tolturn::test::exampleBytes;
using tolturn::test::exampleJson;
using tolturn::test::fileBytes;
using tolturn::test::Run;
using tolturn::test::runCli;
using tolturn::test::writeFile;

class TestCli : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void help()
    {
        const Run r = runCli({QStringLiteral("--help")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.startsWith(QStringLiteral("Usage: tolturn-cli")));
        QVERIFY(r.out.contains(QStringLiteral("check [--json] PROJECT...")));
        QVERIFY(r.err.isEmpty());
    }

    void commandHelp()
    {
        const Run r = runCli({QStringLiteral("check"), QStringLiteral("--help")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains(QStringLiteral("--json")));
    }

    // "help COMMAND" is the command's own help; and every option a command's help lists is in its
    // usage line (the short -o stands for --output; the milling commands refer to another's
    // options by name).
    void everyOptionIsInItsUsageLine()
    {
        const Run evaluate = runCli({QStringLiteral("evaluate"), QStringLiteral("--help")});
        QCOMPARE(runCli({QStringLiteral("help"), QStringLiteral("evaluate")}).out, evaluate.out);
        const QRegularExpression commandLine(QStringLiteral("^  ([a-z0-9-]+) "), QRegularExpression::MultilineOption);
        const QRegularExpression optionLine(QStringLiteral("^  (?:-[a-zA-Z], )?(--[a-z-]+)"),
                                            QRegularExpression::MultilineOption);
        int commands = 0;
        for (const auto &c : commandLine.globalMatch(runCli({QStringLiteral("--help")}).out)) {
            const Run help = runCli({c.captured(1), QStringLiteral("--help")});
            QCOMPARE(help.exitCode, 0);
            const QString usage = help.out.section(QStringLiteral("\n\n"), 0, 0);
            QVERIFY2(usage.startsWith(QStringLiteral("Usage: tolturn-cli ") + c.captured(1)), qPrintable(usage));
            ++commands;
            if (usage.contains(QStringLiteral("options]")))
                continue;
            for (const auto &o : optionLine.globalMatch(help.out)) {
                const QString option = o.captured(1);
                if (option != QLatin1String("--help") && option != QLatin1String("--output"))
                    QVERIFY2(usage.contains(option), qPrintable(c.captured(1) + QStringLiteral(": ") + option));
            }
        }
        QVERIFY(commands >= 20);
    }

    void version()
    {
        const Run r = runCli({QStringLiteral("--version")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.startsWith(QStringLiteral("tolturn-cli 0.1.0")));
        for (const char *lib : {"Qt", "Open CASCADE Technology 7.6", "NLopt 2.7", "Eigen 3.4", "QCustomPlot 2.1"})
            QVERIFY2(r.out.contains(QString::fromLatin1(lib)), lib);
    }

    void noArgumentsIsUsageError()
    {
        const Run r = runCli({});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains(QStringLiteral("Usage:")));
    }

    void unknownCommand()
    {
        const Run r = runCli({QStringLiteral("frobnicate")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains(QStringLiteral("unknown command 'frobnicate'")));
        QVERIFY(!r.err.contains(QStringLiteral("Did you mean")));
        // One letter off (evalute: a missing letter) or a prefix: the command is suggested.
        const Run typo = runCli({QStringLiteral("evalute")});
        QCOMPARE(typo.exitCode, 2);
        QVERIFY2(typo.err.contains(QStringLiteral("Did you mean 'evaluate'?")), qPrintable(typo.err));
        QVERIFY(runCli({QStringLiteral("adv")}).err.contains(QStringLiteral("Did you mean 'advise-clamping'?")));
        // The desktop program's spelling runs the same command.
        const Run optimise = runCli({QStringLiteral("optimise"), QStringLiteral("--help")});
        QCOMPARE(optimise.exitCode, 0);
        QVERIFY(optimise.out.contains(QStringLiteral("optimize")));
    }

    void checkValidExamples()
    {
        const Run r = runCli({QStringLiteral("check"), example("stepped-shaft-chuck.tolturn"),
                              example("hollow-sleeve-tailstock.tolturn"), example("long-shaft-centres.tolturn")});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out.count(QStringLiteral(": ok — ")), 3);
        // In words, not the file's keywords; plurals right.
        QVERIFY2(r.out.contains(QStringLiteral("part \"Hollow sleeve\", 400 mm long, 8 outer and 3 inner features, "
                                               "chuck + tailstock, 6 passes, 9 tolerances")), // as counted in the file
                 qPrintable(r.out));
        // Plausibility: the examples' finishing feeds (0.1 and 0.08 mm/rev) lie below the 0.17 mm/rev
        // the insert's catalogue range starts at (planning.ranges of each file): warnings, not errors.
        QVERIFY2(r.err.contains(QStringLiteral("stepped-shaft-chuck.tolturn: warning: passes[8].feed_mm_rev: 0.1 "
                                               "mm/rev is outside the insert's published range 0.17–0.399 mm/rev")),
                 qPrintable(r.err));
        QVERIFY(
            r.err.contains(QStringLiteral("hollow-sleeve-tailstock.tolturn: warning: passes[5].feed_mm_rev: 0.08")));
        // The stepped shaft roughs in passes 0–7, all at 200 m/min, below the range's 201.2 m/min: one
        // line for the eight passes, not eight lines.
        QVERIFY2(r.err.contains(QStringLiteral("stepped-shaft-chuck.tolturn: warning: passes[0–7].cutting_speed_m_min: "
                                               "200 m/min is outside the insert's published range 201.2–353.6")),
                 qPrintable(r.err));
        QCOMPARE(r.err.count(QStringLiteral("stepped-shaft-chuck.tolturn: warning: passes[")), 2);
        QVERIFY(!r.err.contains(QStringLiteral("error")));
    }

    // Findings alike but for the index of their array are told once; different messages, members,
    // severities or arrays stay apart, and the indices are listed as met.
    void repeatedFindingsAreToldOnce()
    {
        using tolturn::makeError;
        using tolturn::makeWarning;
        const tolturn::Diagnostics findings{
            makeWarning(QStringLiteral("passes[3].feed_mm_rev"), QStringLiteral("low")),
            makeWarning(QStringLiteral("material"), QStringLiteral("unknown")),
            makeWarning(QStringLiteral("passes[1].feed_mm_rev"), QStringLiteral("low")),
            makeWarning(QStringLiteral("passes[2].feed_mm_rev"), QStringLiteral("high")),
            makeError(QStringLiteral("passes[4].feed_mm_rev"), QStringLiteral("low")),
            makeWarning(QStringLiteral("passes[5].depth_of_cut_mm"), QStringLiteral("low")),
            makeWarning(QStringLiteral("further_operations[5].feed_mm_rev"), QStringLiteral("low")),
            makeWarning(QStringLiteral("passes[7].feed_mm_rev"), QStringLiteral("low")),
        };
        const std::vector<tolturn::FindingGroup> groups = tolturn::groupedByIndex(findings);
        QStringList lines;
        for (const tolturn::FindingGroup &g : groups)
            lines << tolturn::groupText(g);
        QCOMPARE(lines, QStringList({QStringLiteral("warning: passes[3, 1, 7].feed_mm_rev: low"),
                                     QStringLiteral("warning: material: unknown"),
                                     QStringLiteral("warning: passes[2].feed_mm_rev: high"),
                                     QStringLiteral("error: passes[4].feed_mm_rev: low"),
                                     QStringLiteral("warning: passes[5].depth_of_cut_mm: low"),
                                     QStringLiteral("warning: further_operations[5].feed_mm_rev: low")}));
        QCOMPARE(tolturn::numberList({2, 3, 4, 5}), QStringLiteral("2–5"));
        QCOMPARE(tolturn::numberList({2, 3}), QStringLiteral("2, 3"));
        QCOMPARE(tolturn::numberList({2, 4, 5}), QStringLiteral("2, 4, 5"));
        QCOMPARE(tolturn::numberList({1, 0, 5, 4}), QStringLiteral("1, 0, 5, 4")); // ends 4 apart, not a run
    }

    // Names that the data library does not know are errors of check, each naming what it has.
    void checkUnknownLibraryEntries()
    {
        QByteArray text = exampleBytes("stepped-shaft-chuck.tolturn");
        text.replace("\"haas-st-20\"", "\"nope-lathe\"");
        text.replace("\"C45E-N\"", "\"unobtainium\"");
        text.replace("\"PCLNR 2525M12\"", "\"XXXXR 2525M12\"");
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("unknown.tolturn"));
        QVERIFY(writeFile(path, text));
        const Run r = runCli({QStringLiteral("check"), path});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.out.isEmpty());
        QVERIFY2(r.err.contains(QStringLiteral("error: material: unknown material \"unobtainium\"; the data library "
                                               "has: C45E-N")),
                 qPrintable(r.err));
        QVERIFY(r.err.contains(QStringLiteral("error: machine: unknown machine \"nope-lathe\"")));
        QVERIFY(
            r.err.contains(QStringLiteral("error: tool.holder: holder \"XXXXR 2525M12\" is not in the data library")));
    }

    void checkMissingFile()
    {
        const Run r = runCli({QStringLiteral("check"), QStringLiteral("/nonexistent.tolturn")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains(QStringLiteral("error: file: '/nonexistent.tolturn' does not exist")));
        QVERIFY(r.out.isEmpty());
    }

    void checkBadFileNamesFieldAndValue()
    {
        QByteArray text = exampleBytes("stepped-shaft-chuck.tolturn");
        text.replace("\"method\": \"chuck\"", "\"method\": \"magnet\"");
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.tolturn"));
        QFile bad(path);
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write(text);
        bad.close();

        const Run r = runCli({QStringLiteral("check"), path});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("error: clamping.method: unknown clamping method \"magnet\"; expected "
                                               "one of: chuck, centres, chuck_tailstock")),
                 qPrintable(r.err));

        const Run json = runCli({QStringLiteral("check"), QStringLiteral("--json"), path});
        QCOMPARE(json.exitCode, 1);
        const QJsonArray reports = QJsonDocument::fromJson(json.out.toUtf8()).array();
        QCOMPARE(reports.size(), 1);
        const QJsonObject report = reports.at(0).toObject();
        QCOMPARE(report.value(QStringLiteral("valid")).toBool(true), false);
        const QJsonObject first = report.value(QStringLiteral("diagnostics")).toArray().at(0).toObject();
        QCOMPARE(first.value(QStringLiteral("field")).toString(), QStringLiteral("clamping.method"));
        QCOMPARE(first.value(QStringLiteral("severity")).toString(), QStringLiteral("error"));
    }

    // deflect --json: stations with contributions and the forces used; --load replaces the forces
    // and --workpiece-only leaves only the beam. The long shaft between rigid centres under
    // Fr = 100 N at mid-span: w = F L^3/(48 E I) + F L/(4 kappa G A) for Ø42 over 500 mm (the
    // body and journals differ by 1 mm in radius; the reference uses Ø42 throughout and the
    // tolerance covers the difference of the journals, below 5 %).
    void deflectJson()
    {
        const Run r = runCli({QStringLiteral("deflect"), QStringLiteral("--json"), QStringLiteral("--workpiece-only"),
                              QStringLiteral("--no-in-process"), QStringLiteral("--load"), QStringLiteral("100,0,0"),
                              example("long-shaft-centres.tolturn")});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(o.value(QStringLiteral("force_model")).toString(), QStringLiteral("given"));
        QCOMPARE(o.value(QStringLiteral("forces_N")).toObject().value(QStringLiteral("radial")).toDouble(), 100.0);
        double midSpan = 0.0;
        for (const QJsonValue f : o.value(QStringLiteral("features")).toArray()) {
            for (const QJsonValue st : f.toObject().value(QStringLiteral("stations")).toArray()) {
                const QJsonObject s = st.toObject();
                const QJsonObject radial = s.value(QStringLiteral("radial_um")).toObject();
                QCOMPARE(radial.value(QStringLiteral("spindle_chuck")).toDouble(), 0.0);
                QCOMPARE(radial.value(QStringLiteral("toolpost")).toDouble(), 0.0);
                if (std::abs(s.value(QStringLiteral("z_mm")).toDouble() - 250.0) < 1e-6)
                    midSpan = radial.value(QStringLiteral("total")).toDouble();
            }
        }
        const double pi = 3.14159265358979, E = 210000.0, nu = 0.3, r21 = 21.0;
        const double I = pi * r21 * r21 * r21 * r21 / 4, A = pi * r21 * r21, G = E / (2 * (1 + nu));
        const double kappa = 6 * (1 + nu) / (7 + 6 * nu);
        const double reference_um =
            1000.0 * (100.0 * 500.0 * 500.0 * 500.0 / (48 * E * I) + 100.0 * 500.0 / (4 * kappa * G * A));
        QVERIFY2(std::abs(midSpan - reference_um) < 0.05 * reference_um,
                 qPrintable(QStringLiteral("%1 vs %2").arg(midSpan).arg(reference_um)));
    }

    // The bushing's bore, bored with a Ø25 steel bar at 95 mm overhang (E = 190 000 MPa,
    // nu = 0.269 in holders.json): under a given radial load of 200 N alone the bar's part of the
    // deviation is the Timoshenko cantilever 200 (L^3/3EI + L/(kappa G A)) at every station.
    void deflectBoringBar()
    {
        const Run r = runCli({QStringLiteral("deflect"), QStringLiteral("--json"), QStringLiteral("--load"),
                              QStringLiteral("200,0,0"), example("bushing-bore-h7.tolturn")});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        const QJsonObject bar = o.value(QStringLiteral("boring_bar")).toObject();
        QCOMPARE(bar.value(QStringLiteral("holder")).toString(), QStringLiteral("S25T-PCLNR12"));
        QCOMPARE(bar.value(QStringLiteral("overhang_ratio")).toDouble(), 95.0 / 25.0);
        const double pi = 3.14159265358979, E = 190000.0, nu = 0.269, d = 25.0, L = 95.0;
        const double I = pi * d * d * d * d / 64, A = pi * d * d / 4, G = E / (2 * (1 + nu));
        const double kappa = 6 * (1 + nu) / (7 + 6 * nu);
        const double reference_um = 1000.0 * 200.0 * (L * L * L / (3 * E * I) + L / (kappa * G * A));
        int inner = 0;
        for (const QJsonValue f : o.value(QStringLiteral("features")).toArray()) {
            const bool isInner = f.toObject().value(QStringLiteral("side")).toString() == QLatin1String("inner");
            for (const QJsonValue st : f.toObject().value(QStringLiteral("stations")).toArray()) {
                const double v = st.toObject()
                                     .value(QStringLiteral("radial_um"))
                                     .toObject()
                                     .value(QStringLiteral("boring_bar"))
                                     .toDouble();
                QVERIFY2(std::abs(v - (isInner ? reference_um : 0.0)) < 1e-6 * reference_um,
                         qPrintable(QStringLiteral("%1 vs %2").arg(v).arg(reference_um)));
                inner += isInner ? 1 : 0;
            }
        }
        QVERIFY(inner > 0);
        const Run text = runCli({QStringLiteral("deflect"), example("bushing-bore-h7.tolturn")});
        QVERIFY2(text.out.contains(QStringLiteral("Boring bar S25T-PCLNR12 (steel)")), qPrintable(text.out));
    }

    // A bushing bored from both ends in two set-ups: evaluate judges each on its own; the
    // coaxiality of the two seats, cut in different set-ups, holds only if clamping again costs
    // less than its 20 µm zone (the deflection predicts none of it).
    // An option given an empty value is a usage error naming it, not its default: "--store ''"
    // would otherwise read the default measurement store, "--operation ''" take the first one,
    // "-o ''" write nowhere. Free text may be empty ("--planner ''": no name), and --help still helps.
    void emptyOptionValueIsAUsageError_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QString shaft = example("stepped-shaft-chuck.tolturn");
        QTest::newRow("evaluate --store") << QStringList{QStringLiteral("evaluate"), QStringLiteral("--learned"),
                                                         QStringLiteral("--store"), QString(), shaft}
                                          << QStringLiteral("--store: the value is empty");
        QTest::newRow("measurements list --store")
            << QStringList{QStringLiteral("measurements"), QStringLiteral("list"), QStringLiteral("--store"), QString()}
            << QStringLiteral("--store: the value is empty");
        QTest::newRow("gcode -o") << QStringList{QStringLiteral("gcode"), QStringLiteral("-o"), QString(), shaft}
                                  << QStringLiteral("-o: the value is empty");
        QTest::newRow("evaluate --operation")
            << QStringList{QStringLiteral("evaluate"), QStringLiteral("--operation"), QString(), shaft}
            << QStringLiteral("--operation: the value is empty");
    }

    void emptyOptionValueIsAUsageError()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const Run r = runCli(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }

    void emptyFreeTextIsNone()
    {
        const QString shaft = example("stepped-shaft-chuck.tolturn");
        const Run report = runCli({QStringLiteral("report"), QStringLiteral("--planner"), QString(),
                                   QStringLiteral("-o"), QStringLiteral("-"), shaft});
        QVERIFY2(report.exitCode == 0 && report.out.startsWith(QStringLiteral("%PDF")), qPrintable(report.err));
        const Run help = runCli({QStringLiteral("gcode"), QStringLiteral("-o"), QString(), QStringLiteral("--help")});
        QCOMPARE(help.exitCode, 0);
        QVERIFY(help.out.contains(QStringLiteral("Usage:")));
    }

    void evaluateOperations()
    {
        const Run r = runCli({QStringLiteral("evaluate"), example("bushing-two-setups.tolturn")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QStringLiteral("OP 10 (operation 1 of 2): chuck, the left end held")) &&
                     r.out.contains(QStringLiteral("OP 20 (operation 2 of 2): chuck, the right end held")),
                 qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("datum A on I5 is cut in OP 10, I1 in OP 20")));
        QVERIFY(r.out.contains(QStringLiteral("it holds only if the re-clamping error stays below 20.0 µm")));
        const Run json =
            runCli({QStringLiteral("evaluate"), QStringLiteral("--json"), example("bushing-two-setups.tolturn")});
        const QJsonArray ops =
            QJsonDocument::fromJson(json.out.toUtf8()).object().value(QStringLiteral("operations")).toArray();
        QCOMPARE(ops.size(), 2);
        QCOMPARE(ops.at(1).toObject().value(QStringLiteral("held_end")).toString(), QStringLiteral("right"));
        // An operation the project does not have is a usage error (exit 2) for every command that
        // takes one.
        for (const char *command : {"deflect", "optimize", "window", "advise-clamping"}) {
            const Run unknown = runCli({QString::fromLatin1(command), QStringLiteral("--operation"),
                                        QStringLiteral("OP 30"), example("bushing-two-setups.tolturn")});
            QVERIFY2(unknown.exitCode == 2, command);
            QVERIFY2(unknown.err.contains(QStringLiteral("--operation: the project has no operation \"OP 30\"; it "
                                                         "has: OP 10, OP 20")),
                     qPrintable(unknown.err));
        }
    }

    // An overhang beyond the maker's 4 x D for a steel bar is a warning of check.
    void checkBoringBarOverhang()
    {
        QByteArray text = exampleBytes("bushing-bore-h7.tolturn");
        text.replace("\"overhang_mm\": 95", "\"overhang_mm\": 110");
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("long-bar.tolturn"));
        QVERIFY(writeFile(path, text));
        const Run r = runCli({QStringLiteral("check"), path});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.err.contains(QStringLiteral("warning: boring_tool.overhang_mm: 110 mm is 4.4 times the bar's "
                                               "diameter, more than the 4 times the maker allows a steel bar")),
                 qPrintable(r.err));
    }

    void deflectText()
    {
        const Run r = runCli({QStringLiteral("deflect"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.startsWith(QStringLiteral("Forces (Kienzle)")));
        QVERIFY(r.out.contains(QStringLiteral("note: Spindle–chuck not measured: a radial spring of 66 N/µm")));
        QVERIFY(r.out.contains(QStringLiteral("face O11")));
    }

    // Passes are counted from 1 everywhere: the stepped shaft's nine passes, its last one the
    // finishing pass `deflect` takes by default and prints as "Pass 9".
    void deflectPassCountsFromOne()
    {
        const QString shaft = example("stepped-shaft-chuck.tolturn");
        const Run last = runCli({QStringLiteral("deflect"), QStringLiteral("--pass"), QStringLiteral("9"), shaft});
        QCOMPARE(last.exitCode, 0);
        QCOMPARE(last.out, runCli({QStringLiteral("deflect"), shaft}).out);
        QVERIFY(last.out.contains(QStringLiteral("Pass 9 (")));
        const Run first = runCli({QStringLiteral("deflect"), QStringLiteral("--pass"), QStringLiteral("1"), shaft});
        QCOMPARE(first.exitCode, 0);
        QVERIFY(first.out.contains(QStringLiteral("Pass 1 (")));
        const Run json = runCli({QStringLiteral("deflect"), QStringLiteral("--json"), QStringLiteral("--pass"),
                                 QStringLiteral("9"), shaft});
        const QJsonObject pass =
            QJsonDocument::fromJson(json.out.toUtf8()).object().value(QStringLiteral("pass")).toObject();
        QCOMPARE(pass.value(QStringLiteral("number")).toInt(), 9);
        QCOMPARE(pass.value(QStringLiteral("index")).toInt(), 8);
        const Run beyond = runCli({QStringLiteral("deflect"), QStringLiteral("--pass"), QStringLiteral("10"), shaft});
        QCOMPARE(beyond.exitCode, 1);
        QVERIFY2(beyond.err.contains(QStringLiteral("there is no pass 10 (the project has 9)")),
                 qPrintable(beyond.err));
        const Run zero = runCli({QStringLiteral("deflect"), QStringLiteral("--pass"), QStringLiteral("0"), shaft});
        QCOMPARE(zero.exitCode, 2);
        QVERIFY(zero.err.contains(QStringLiteral("--pass must be a pass number (1, 2, …), not \"0\"")));
    }

    void deflectBadLoad()
    {
        const Run r = runCli({QStringLiteral("deflect"), QStringLiteral("--load"), QStringLiteral("100,abc"),
                              example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains(QStringLiteral("--load takes three numbers in newtons")));
        QVERIFY(r.err.contains(QStringLiteral("\"100,abc\"")));
    }

    void deflectUnknownMaterial()
    {
        QByteArray text = exampleBytes("stepped-shaft-chuck.tolturn");
        text.replace("\"material\": \"C45E-N\"", "\"material\": \"kryptonite\"");
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.tolturn"));
        QFile bad(path);
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write(text);
        bad.close();
        const Run r = runCli({QStringLiteral("deflect"), path});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("error: material: unknown material \"kryptonite\"")), qPrintable(r.err));
    }

    // calibrate-forces recovers K_n and K_f from forces made with them for the example's tool
    // (PCLNR: kappa_r 95° so gamma_L = -5°; negative seat -6°/-6°; CNMG 120408: r_n = 0.8 mm),
    // and --write stores them so that deflect then uses the Li & Du model.
    void calibrateForcesAndWrite()
    {
        const double pi = 3.14159265358979;
        const tolturn::LiDuToolGeometry tool{-6 * pi / 180, -6 * pi / 180, -5 * pi / 180, 0.8};
        QString csv = QStringLiteral("feed_mm_rev;depth_of_cut_mm;tangential_N;axial_N\n");
        for (const auto &[f, d] : {std::pair{0.15, 1.0}, std::pair{0.25, 2.0}, std::pair{0.3, 2.5}}) {
            const tolturn::CuttingForces c = tolturn::liDuForces({2400.0, 0.55}, tool, f, d).forces;
            csv += QStringLiteral("%1;%2;%3;%4\n")
                       .arg(f)
                       .arg(d)
                       .arg(c.tangential_N, 0, 'g', 12)
                       .arg(c.axial_N, 0, 'g', 12);
        }
        QTemporaryDir dir;
        const QString cuts = dir.filePath(QStringLiteral("cuts.csv"));
        const QString project = dir.filePath(QStringLiteral("shaft.tolturn"));
        QVERIFY(QFile::copy(example("stepped-shaft-chuck.tolturn"), project));
        QFile::setPermissions(project, QFile::ReadOwner | QFile::WriteOwner);
        QVERIFY(writeFile(cuts, csv.toUtf8()));

        const Run r = runCli(
            {QStringLiteral("calibrate-forces"), QStringLiteral("--json"), QStringLiteral("--write"), project, cuts});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY(std::abs(o.value(QStringLiteral("normal_pressure_MPa")).toDouble() - 2400.0) < 1e-6);
        QVERIFY(std::abs(o.value(QStringLiteral("friction_ratio")).toDouble() - 0.55) < 1e-9);
        QVERIFY(r.err.contains(QStringLiteral("force model li_du")));

        const Run after = runCli({QStringLiteral("deflect"), QStringLiteral("--json"), project});
        QCOMPARE(after.exitCode, 0);
        QCOMPARE(QJsonDocument::fromJson(after.out.toUtf8()).object().value(QStringLiteral("force_model")).toString(),
                 QStringLiteral("li_du"));
    }

    void calibrateForcesBadFile()
    {
        QTemporaryDir dir;
        const QString cuts = dir.filePath(QStringLiteral("cuts.csv"));
        QVERIFY(writeFile(cuts, "feed_mm_rev,depth_of_cut_mm,tangential_N,axial_N\n0.2,one,500,200\n"));
        const Run r = runCli({QStringLiteral("calibrate-forces"), example("stepped-shaft-chuck.tolturn"), cuts});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("cuts.csv:2: depth_of_cut_mm must be a number above zero, not \"one\"")),
                 qPrintable(r.err));
    }

    // calibrate-stiffness inverts deflect: the deviation the model predicts along the Ø50 mm
    // feature of the example with known springs (Lc = 220 mm), given as a measured test bar, gives
    // those springs back, and --into stores them in another project with their source. The
    // independent check against hand-written closed forms is tst_deviation::spindleSpringsFromATestBar.
    void calibrateStiffnessRoundTrip()
    {
        QTemporaryDir dir;
        QJsonObject project = exampleJson("stepped-shaft-chuck.tolturn");
        const QString target = dir.filePath(QStringLiteral("part.tolturn"));
        QVERIFY(writeFile(target, QJsonDocument(project).toJson()));
        auto springs = [](double k1, double k2, double k3) {
            return QJsonObject{{QStringLiteral("k1_N_per_mm"), k1},
                               {QStringLiteral("k2_Nmm_per_rad"), k2},
                               {QStringLiteral("k3_Nmm_per_rad"), k3}};
        };
        project.insert(QStringLiteral("characterisation"),
                       QJsonObject{{QStringLiteral("source"), QStringLiteral("test")},
                                   {QStringLiteral("pivot_distance_mm"), 220.0},
                                   {QStringLiteral("spindle_radial"), springs(1.5e5, 3e9, 1e9)},
                                   {QStringLiteral("spindle_tangential"), springs(2.5e5, 6e9, 2e9)}});
        const QString bar = dir.filePath(QStringLiteral("bar.tolturn"));
        QVERIFY(writeFile(bar, QJsonDocument(project).toJson()));
        const Run deflect = runCli({QStringLiteral("deflect"), QStringLiteral("--json"), QStringLiteral("--stations"),
                                    QStringLiteral("9"), bar});
        QCOMPARE(deflect.exitCode, 0);
        QString csv = QStringLiteral("z_mm,radial_um,tangential_um\n");
        for (const QJsonValue f :
             QJsonDocument::fromJson(deflect.out.toUtf8()).object().value(QStringLiteral("features")).toArray()) {
            if (f.toObject().value(QStringLiteral("id")).toString() != QLatin1String("O4"))
                continue;
            for (const QJsonValue st : f.toObject().value(QStringLiteral("stations")).toArray()) {
                const QJsonObject o = st.toObject();
                csv +=
                    QStringLiteral("%1,%2,%3\n")
                        .arg(o.value(QStringLiteral("z_mm")).toDouble(), 0, 'g', 15)
                        .arg(o.value(QStringLiteral("radial_um")).toObject().value(QStringLiteral("total")).toDouble(),
                             0, 'g', 15)
                        .arg(o.value(QStringLiteral("tangential_um"))
                                 .toObject()
                                 .value(QStringLiteral("total"))
                                 .toDouble(),
                             0, 'g', 15);
            }
        }
        const QString measured = dir.filePath(QStringLiteral("bar.csv"));
        QVERIFY(writeFile(measured, csv.toUtf8()));
        const Run r =
            runCli({QStringLiteral("calibrate-stiffness"), QStringLiteral("--json"), QStringLiteral("--pivot"),
                    QStringLiteral("220"), QStringLiteral("--into"), target, bar, measured});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        const QJsonObject radial = o.value(QStringLiteral("radial")).toObject();
        const QJsonObject tangential = o.value(QStringLiteral("tangential")).toObject();
        auto near = [](const QJsonObject &fit, const char *key, double reference) {
            return std::abs(fit.value(QLatin1String(key)).toDouble() / reference - 1.0) < 1e-3;
        };
        QVERIFY2(near(radial, "k1_N_per_mm", 1.5e5) && near(radial, "k2_Nmm_per_rad", 3e9) &&
                     near(radial, "k3_Nmm_per_rad", 1e9),
                 qPrintable(r.out));
        QVERIFY2(near(tangential, "k1_N_per_mm", 2.5e5) && near(tangential, "k2_Nmm_per_rad", 6e9) &&
                     near(tangential, "k3_Nmm_per_rad", 2e9),
                 qPrintable(r.out));
        QCOMPARE(o.value(QStringLiteral("diameter_mm")).toDouble(), 50.0);
        QVERIFY(r.err.contains(QStringLiteral("wrote")));
        const tolturn::ProjectParseResult written = tolturn::readProjectFile(target);
        QVERIFY(written.project);
        if (!written.project)
            return;
        const tolturn::MachineCharacterisation &c = written.project->characterisation;
        QCOMPARE(c.pivotDistance_mm.value_or(0.0), 220.0);
        QVERIFY(c.spindleRadial && std::abs(c.spindleRadial->k2_Nmm_per_rad / 3e9 - 1.0) < 1e-3);
        QVERIFY(c.source.contains(QStringLiteral("calibrate-stiffness, bar.csv")));

        // A tangential fit that fails fails the command: exit 1, nothing written (the radial fit
        // alone would have been).
        QString radialOnly = QStringLiteral("z_mm,radial_um\n");
        QString fallingTangential = QStringLiteral("z_mm,radial_um,tangential_um\n");
        for (const QString &line : csv.split(QLatin1Char('\n'), Qt::SkipEmptyParts).mid(1)) {
            const QStringList cells = line.split(QLatin1Char(','));
            radialOnly += cells.at(0) + QLatin1Char(',') + cells.at(1) + QLatin1Char('\n');
            fallingTangential +=
                QStringLiteral("%1,%2,%3\n").arg(cells.at(0), cells.at(1)).arg(20.0 - 0.1 * cells.at(0).toDouble());
        }
        const QString falling = dir.filePath(QStringLiteral("falling.csv"));
        QVERIFY(writeFile(falling, fallingTangential.toUtf8()));
        const QByteArray fittedBytes = fileBytes(target);
        QVERIFY(!fittedBytes.isEmpty());
        const Run failedFit = runCli({QStringLiteral("calibrate-stiffness"), QStringLiteral("--pivot"),
                                      QStringLiteral("220"), QStringLiteral("--into"), target, bar, falling});
        QCOMPARE(failedFit.exitCode, 1);
        QVERIFY2(failedFit.err.contains(QStringLiteral("tangential fit gives k")), qPrintable(failedFit.err));
        QVERIFY(!failedFit.err.contains(QStringLiteral("wrote")));
        QCOMPARE(fileBytes(target), fittedBytes);

        // A radial fit at another Lc removes the tangential springs fitted at 220 mm, and says so.
        const QString radialCsv = dir.filePath(QStringLiteral("radial.csv"));
        QVERIFY(writeFile(radialCsv, radialOnly.toUtf8()));
        const Run newPivot = runCli({QStringLiteral("calibrate-stiffness"), QStringLiteral("--pivot"),
                                     QStringLiteral("120"), QStringLiteral("--into"), target, bar, radialCsv});
        QVERIFY2(newPivot.exitCode == 0, qPrintable(newPivot.err));
        QVERIFY2(newPivot.err.contains(QStringLiteral("fitted for Lc = 220 mm and do not hold at Lc = 120 mm")),
                 qPrintable(newPivot.err));
        const tolturn::ProjectParseResult refitted = tolturn::readProjectFile(target);
        QVERIFY(refitted.project && !refitted.project->characterisation.spindleTangential);
        QCOMPARE(refitted.project->characterisation.pivotDistance_mm.value_or(0.0), 120.0);

        // Without Lc (the example has no characterisation) the command names the field.
        const Run noPivot =
            runCli({QStringLiteral("calibrate-stiffness"), example("stepped-shaft-chuck.tolturn"), measured});
        QCOMPARE(noPivot.exitCode, 1);
        QVERIFY2(noPivot.err.contains(QStringLiteral("characterisation.pivot_distance_mm: Lc, the distance of the "
                                                     "spindle bearing behind the chuck face, is not given: give it "
                                                     "with --pivot MM")),
                 qPrintable(noPivot.err));
        const Run badLoad = runCli(
            {QStringLiteral("calibrate-stiffness"), QStringLiteral("--load"), QStringLiteral("1,2"), bar, measured});
        QCOMPARE(badLoad.exitCode, 2);

        // With --json the problems of the measurements are in the output too, not dropped.
        const QString brokenCsv = dir.filePath(QStringLiteral("broken.csv"));
        QVERIFY(writeFile(brokenCsv, "z_mm,radial_um\n10,abc\n20,3\n30,4\n"));
        const Run broken = runCli({QStringLiteral("calibrate-stiffness"), QStringLiteral("--json"),
                                   QStringLiteral("--pivot"), QStringLiteral("220"), bar, brokenCsv});
        QCOMPARE(broken.exitCode, 1);
        const QJsonArray said =
            QJsonDocument::fromJson(broken.out.toUtf8()).object().value(QStringLiteral("diagnostics")).toArray();
        QVERIFY2(!said.isEmpty() && QJsonDocument(said).toJson().contains("abc"), qPrintable(broken.out));

        // The springs are the test bar's machine's: a project for another machine is not given them.
        project.insert(QStringLiteral("machine"), QStringLiteral("okuma-ls"));
        project.remove(QStringLiteral("characterisation"));
        const QString other = dir.filePath(QStringLiteral("other.tolturn"));
        QVERIFY(writeFile(other, QJsonDocument(project).toJson()));
        const QByteArray unchanged = fileBytes(other);
        QVERIFY(!unchanged.isEmpty());
        const Run otherMachine = runCli({QStringLiteral("calibrate-stiffness"), QStringLiteral("--pivot"),
                                         QStringLiteral("220"), QStringLiteral("--into"), other, bar, measured});
        QCOMPARE(otherMachine.exitCode, 1);
        QVERIFY2(otherMachine.err.contains(QStringLiteral("is planned for machine \"okuma-ls\", but the test bar was "
                                                          "cut on \"haas-st-20\"")),
                 qPrintable(otherMachine.err));
        QCOMPARE(fileBytes(other), unchanged);
    }

    // iso286 and fit against published values: 50 H7 = +25/0 µm, IT7 = 25 µm; 50 g6 = -9/-25 µm
    // (ISO 286-2 Tables); H7/g6: max clearance 25 + 25 = 50 µm, min 0 + 9 = 9 µm.
    void iso286AndFit()
    {
        const Run h7 =
            runCli({QStringLiteral("iso286"), QStringLiteral("50"), QStringLiteral("H7"), QStringLiteral("--json")});
        QCOMPARE(h7.exitCode, 0);
        const QJsonObject l = QJsonDocument::fromJson(h7.out.toUtf8()).object();
        QCOMPARE(l.value(QStringLiteral("upper_um")).toDouble(), 25.0);
        QCOMPARE(l.value(QStringLiteral("lower_um")).toDouble(), 0.0);
        QCOMPARE(l.value(QStringLiteral("it_grade")).toString(), QStringLiteral("IT7"));
        QCOMPARE(l.value(QStringLiteral("it_um")).toDouble(), 25.0);
        QCOMPARE(l.value(QStringLiteral("nominal_mm")).toDouble(), 50.0);
        QCOMPARE(l.value(QStringLiteral("class")).toString(), QStringLiteral("H7"));

        const Run fit =
            runCli({QStringLiteral("fit"), QStringLiteral("50"), QStringLiteral("H7/g6"), QStringLiteral("--json")});
        QCOMPARE(fit.exitCode, 0);
        const QJsonObject f = QJsonDocument::fromJson(fit.out.toUtf8()).object();
        QCOMPARE(f.value(QStringLiteral("type")).toString(), QStringLiteral("clearance"));
        QCOMPARE(f.value(QStringLiteral("max_clearance_um")).toDouble(), 50.0);
        QCOMPARE(f.value(QStringLiteral("min_clearance_um")).toDouble(), 9.0);
        QCOMPARE(f.value(QStringLiteral("shaft")).toObject().value(QStringLiteral("lower_um")).toDouble(), -25.0);
    }

    void iso286BadInput()
    {
        const Run undefinedLetter = runCli({QStringLiteral("iso286"), QStringLiteral("10"), QStringLiteral("y6")});
        QCOMPARE(undefinedLetter.exitCode, 1);
        QVERIFY(undefinedLetter.err.contains(QStringLiteral("shaft y6 is not defined for a nominal size of 10 mm")));
        const Run tooLarge = runCli({QStringLiteral("iso286"), QStringLiteral("4000"), QStringLiteral("h7")});
        QCOMPARE(tooLarge.exitCode, 1);
        QVERIFY(tooLarge.err.contains(QStringLiteral("4000")));
        const Run unknown = runCli({QStringLiteral("iso286"), QStringLiteral("50"), QStringLiteral("Q7")});
        QCOMPARE(unknown.exitCode, 1);
        QVERIFY(unknown.err.contains(QStringLiteral("Q7")));
        const Run notANumber = runCli({QStringLiteral("iso286"), QStringLiteral("fifty"), QStringLiteral("H7")});
        QCOMPARE(notANumber.exitCode, 2);
        QVERIFY(notANumber.err.contains(QStringLiteral("\"fifty\"")));
        // A negative size is a size out of range, not an unknown option "-5", with --json before or after.
        for (const QStringList &args :
             {QStringList{QStringLiteral("iso286"), QStringLiteral("-5"), QStringLiteral("h6")},
              QStringList{QStringLiteral("iso286"), QStringLiteral("--json"), QStringLiteral("-5"),
                          QStringLiteral("h6")},
              QStringList{QStringLiteral("fit"), QStringLiteral("-0.5"), QStringLiteral("H7/g6")}}) {
            const Run negative = runCli(args);
            QCOMPARE(negative.exitCode, 1);
            QVERIFY2(negative.err.contains(QStringLiteral("the nominal size must be above 0 mm, but is -")),
                     qPrintable(negative.err));
        }
    }

    // A force model's warning names the pass it is about, as check does: the long shaft's fifth
    // pass, the finishing pass (index 4), cuts 0.25 mm, below the 0.5 mm of Li & Du's eq. 20.
    void forceModelWarningsNameThePass()
    {
        const Run r = runCli({QStringLiteral("evaluate"), example("long-shaft-centres.tolturn")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.err.contains(QStringLiteral("warning: passes[4].depth_of_cut_mm: depth of cut [mm] = 0.25 is "
                                               "outside the range 0.5 < depth of cut [mm] < 5")),
                 qPrintable(r.err));
    }

    // The text table names the characteristics in the desktop program's words, not the file's keys.
    void evaluateTextUsesTheCharacteristicsNames()
    {
        const Run r = runCli({QStringLiteral("evaluate"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QStringLiteral("T6         total radial run-out")), qPrintable(r.out));
        QVERIFY(!r.out.contains(QStringLiteral("total_radial_runout")));
    }

    // evaluate: every tolerance of the example with a verdict; coaxiality is "not predicted" with
    // its reason, never a pass.
    // The hollow sleeve's program does not finish everything its tolerances are on, and those
    // cannot be judged as programmed: the tool keeps 2 mm + r_e 0.8 mm from the jaws at z 40, so the
    // body O4 is turned from z 42.8 (sampled every 0.05 mm: 40.000–42.750 left) and the shoulder O3
    // at the jaw face is not faced; the project has no boring bar, so the bores I1 and I3 are not
    // in the program (I1 from z 0: inside the jaws a bore is the bar's to reach); the right end face O8 sits on the
    // tailstock's centre and is not faced. The journal O6 is turned whole: its size passes, its coaxiality is not
    // predicted (§V.H).
    void evaluateExample()
    {
        const Run r =
            runCli({QStringLiteral("evaluate"), QStringLiteral("--json"), example("hollow-sleeve-tailstock.tolturn")});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray list =
            QJsonDocument::fromJson(r.out.toUtf8()).object().value(QStringLiteral("tolerances")).toArray();
        QCOMPARE(list.size(), 9);
        const QStringList unfinished{QStringLiteral("O4"), QStringLiteral("O3"), QStringLiteral("I1"),
                                     QStringLiteral("I3"), QStringLiteral("O8")};
        for (const QJsonValue v : list) {
            const QJsonObject t = v.toObject();
            const QString feature = t.value(QStringLiteral("feature")).toString();
            const QString reason = t.value(QStringLiteral("reason")).toString();
            if (unfinished.contains(feature)) {
                QCOMPARE(t.value(QStringLiteral("verdict")).toString(), QStringLiteral("cannot_evaluate"));
                QVERIFY2(reason.startsWith(QStringLiteral("not finished by this set-up's program")),
                         qPrintable(reason));
            } else if (t.value(QStringLiteral("type")).toString() == QLatin1String("coaxiality")) {
                QCOMPARE(t.value(QStringLiteral("verdict")).toString(), QStringLiteral("not_predicted"));
                QVERIFY(reason.contains(QStringLiteral("§V.H")));
            } else {
                QCOMPARE(feature, QStringLiteral("O6"));
                QCOMPARE(t.value(QStringLiteral("verdict")).toString(), QStringLiteral("passes"));
                QVERIFY(t.contains(QStringLiteral("utilisation_pct")));
                QVERIFY(!t.value(QStringLiteral("condition")).toString().isEmpty());
            }
            const QJsonArray left = t.value(QStringLiteral("unfinished")).toArray();
            QCOMPARE(t.value(QStringLiteral("range_verdict")).toString() == QLatin1String("not_finished"),
                     unfinished.contains(feature));
            if (feature == QLatin1String("O4"))
                QCOMPARE(left, QJsonArray{QStringLiteral("z 40.000–42.750 mm of O4")});
            if (feature == QLatin1String("I1"))
                QCOMPARE(left, QJsonArray{QStringLiteral("z 0.000–300.000 mm of I1")});
        }
    }

    // optimize: the stepped shaft's optimum sits on its Ra 1.6 µm requirement, f = sqrt(32 r_eps Ra)
    // = sqrt(32 * 0.8 * 0.0016) = 0.20239 mm/rev, stated on the 0.001 mm/rev below it (0.202), with
    // the roughing depth at the insert's 2 mm.
    void optimizeJson()
    {
        const Run r =
            runCli({QStringLiteral("optimize"), QStringLiteral("--json"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY(o.value(QStringLiteral("feasible")).toBool());
        QCOMPARE(o.value(QStringLiteral("objective")).toString(), QStringLiteral("time"));
        const double feed =
            o.value(QStringLiteral("finishing")).toObject().value(QStringLiteral("feed_mm_rev")).toDouble();
        QVERIFY(std::abs(feed - 0.202) < 1e-9);
        const QJsonObject rough = o.value(QStringLiteral("roughing")).toObject();
        QVERIFY(rough.value(QStringLiteral("passes")).toInt() >= 1);
        QVERIFY(std::abs(
                    rough.value(QStringLiteral("pass")).toObject().value(QStringLiteral("depth_of_cut_mm")).toDouble() -
                    2.0) < 1e-6);
        bool roughness = false;
        for (const QJsonValue b : o.value(QStringLiteral("binding")).toArray())
            roughness =
                roughness || b.toObject().value(QStringLiteral("name")).toString() == QLatin1String("roughness");
        QVERIFY(roughness);
    }

    // An infeasible plan: exit code 1, the violated roughness in `conflicts` and what it would take
    // in `what_it_would_take` (the valve body's OP 10, f <= sqrt(32 * 0.4 * 0.0016) = 0.143 mm/rev),
    // and in the text after "to meet it:".
    void optimizeSaysWhatItWouldTake()
    {
        const Run json =
            runCli({QStringLiteral("optimize"), QStringLiteral("--json"), example("valve-body-two-bores.tolturn")});
        QCOMPARE(json.exitCode, 1);
        const QJsonObject o = QJsonDocument::fromJson(json.out.toUtf8()).object();
        QVERIFY(!o.value(QStringLiteral("feasible")).toBool(true));
        const QJsonArray conflicts = o.value(QStringLiteral("conflicts")).toArray();
        QCOMPARE(conflicts.size(), 1);
        QCOMPARE(conflicts.at(0).toObject().value(QStringLiteral("name")).toString(), QStringLiteral("roughness"));
        const QJsonArray remedies = o.value(QStringLiteral("what_it_would_take")).toArray();
        QCOMPARE(remedies.size(), 1);
        QVERIFY2(remedies.at(0).toString().contains(QStringLiteral("at most 0.143 mm/rev")),
                 qPrintable(remedies.at(0).toString()));
        const Run text = runCli({QStringLiteral("optimize"), example("valve-body-two-bores.tolturn")});
        QVERIFY2(text.out.contains(QStringLiteral("  to meet it: Ra ≤ 1.6 µm needs a feed of at most 0.143 mm/rev")),
                 qPrintable(text.out));
        // One roughing pass takes the valve body's 2 mm of stock above the finishing allowance.
        QVERIFY2(text.out.contains(QStringLiteral("  roughing: 1 pass of ap 2.000 mm")), qPrintable(text.out));
    }

    void optimizeWithoutRangesIsAnError()
    {
        QJsonObject doc = exampleJson("stepped-shaft-chuck.tolturn");
        QJsonObject planning = doc.value(QStringLiteral("planning")).toObject();
        planning.remove(QStringLiteral("ranges"));
        doc.insert(QStringLiteral("planning"), planning);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("p.tolturn"));
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(QJsonDocument(doc).toJson());
        out.close();
        const Run r = runCli({QStringLiteral("optimize"), path});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains(QStringLiteral("planning.ranges")));
    }

    // A project without passes is the optimiser's to plan: --write gives it passes, each with the
    // cutting data the plan chose (check calls the missing passes an error; optimize does not).
    void optimizePlansAProjectWithoutPasses()
    {
        QJsonObject doc = exampleJson("stepped-shaft-chuck.tolturn");
        doc.insert(QStringLiteral("passes"), QJsonArray());
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("p.tolturn"));
        QVERIFY(writeFile(path, QJsonDocument(doc).toJson()));
        QCOMPARE(runCli({QStringLiteral("check"), path}).exitCode, 1);
        const Run r = runCli({QStringLiteral("optimize"), QStringLiteral("--time-limit"), QStringLiteral("5"),
                              QStringLiteral("--write"), path});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile written(path);
        QVERIFY(written.open(QIODevice::ReadOnly));
        QVERIFY(
            !QJsonDocument::fromJson(written.readAll()).object().value(QStringLiteral("passes")).toArray().isEmpty());
    }

    // The same for a later set-up: OP 20 of the two-set-up bushing without passes is planned by
    // optimize, window and advise-clamping, and refused by every command that cuts it as it is.
    void optimizePlansAnOperationWithoutPasses()
    {
        QJsonObject doc = exampleJson("bushing-two-setups.tolturn");
        QJsonArray operations = doc.value(QStringLiteral("further_operations")).toArray();
        QJsonObject op20 = operations.at(0).toObject();
        op20.insert(QStringLiteral("passes"), QJsonArray());
        operations.replace(0, op20);
        doc.insert(QStringLiteral("further_operations"), operations);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("p.tolturn"));
        QVERIFY(writeFile(path, QJsonDocument(doc).toJson()));
        const QString op = QStringLiteral("OP 20");
        const Run check = runCli({QStringLiteral("check"), path});
        QCOMPARE(check.exitCode, 1);
        QVERIFY2(check.out.contains(QStringLiteral("further_operations[0].passes")) ||
                     check.err.contains(QStringLiteral("further_operations[0].passes")),
                 qPrintable(check.out + check.err));
        for (const QString &command :
             {QStringLiteral("optimize"), QStringLiteral("window"), QStringLiteral("advise-clamping")}) {
            const Run r = runCli({command, QStringLiteral("--operation"), op, path});
            QVERIFY2(r.exitCode == 0, qPrintable(command + QLatin1Char(' ') + r.err));
        }
        const Run gcode = runCli({QStringLiteral("gcode"), QStringLiteral("--operation"), op, QStringLiteral("-o"),
                                  dir.filePath(QStringLiteral("p.nc")), path});
        QCOMPARE(gcode.exitCode, 1);
        QVERIFY2(gcode.err.contains(QStringLiteral("further_operations[0].passes")), qPrintable(gcode.err));
        QCOMPARE(runCli({QStringLiteral("evaluate"), QStringLiteral("--operation"), op, path}).exitCode, 1);
    }

    // optimize --write replaces the passes: a field this program does not know on an old pass is
    // dropped and named (it belongs to no new pass), while one elsewhere in the file is kept.
    void optimizeWriteNamesTheFieldsOfReplacedPasses()
    {
        QJsonObject doc = exampleJson("stepped-shaft-chuck.tolturn");
        QJsonArray passes = doc.value(QStringLiteral("passes")).toArray();
        QJsonObject last = passes.last().toObject();
        last.insert(QStringLiteral("coolant"), QStringLiteral("flood"));
        passes.replace(passes.size() - 1, last);
        doc.insert(QStringLiteral("passes"), passes);
        doc.insert(QStringLiteral("shop_note"), QStringLiteral("kept"));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("p.tolturn"));
        QVERIFY(writeFile(path, QJsonDocument(doc).toJson()));
        const Run r = runCli({QStringLiteral("optimize"), QStringLiteral("--write"), path});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.err.contains(QStringLiteral("warning: passes[%1].coolant: dropped with the passes it was on")
                                    .arg(passes.size() - 1)),
                 qPrintable(r.err));
        QFile written(path);
        QVERIFY(written.open(QIODevice::ReadOnly));
        const QJsonObject after = QJsonDocument::fromJson(written.readAll()).object();
        QCOMPARE(after.value(QStringLiteral("shop_note")).toString(), QStringLiteral("kept"));
        for (const QJsonValue pass : after.value(QStringLiteral("passes")).toArray())
            QVERIFY(!pass.toObject().contains(QStringLiteral("coolant")));
    }

    void windowCsv()
    {
        const Run r = runCli({QStringLiteral("window"), QStringLiteral("--plane"), QStringLiteral("feed-speed"),
                              QStringLiteral("--csv"), QStringLiteral("--size"), QStringLiteral("8"),
                              example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(r.exitCode, 0);
        const QStringList lines = r.out.trimmed().split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), 1 + 64);
        QCOMPARE(lines.first(), QStringLiteral("feed_mm_rev,cutting_speed_m_min,objective,feasible,binding"));
        // At the largest feed (0.399 mm/rev) Ra = 0.399^2/(32*0.8) mm = 6.2 µm > 1.6: bounded by roughness.
        QVERIFY(lines.at(8).startsWith(QStringLiteral("0.399,")));
        QVERIFY(lines.at(8).endsWith(QStringLiteral(",0,roughness (Ra)")));
        QVERIFY(lines.at(1).startsWith(QStringLiteral("0.17,201.2,")));
        QVERIFY(lines.at(1).endsWith(QStringLiteral(",1,")));
        // The summary names the optimum with the output's symbols: the largest feed that leaves Ra
        // 1.6 µm with r 0.8 mm, f = sqrt(32 r Ra) = sqrt(32 x 0.8 x 0.0016) = 0.2024 mm/rev, at the
        // top of the speed range (least time, no tool life), 353.6 m/min; both on the steps a
        // program states below them: 0.202 mm/rev, 353 m/min.
        const Run summary = runCli({QStringLiteral("window"), QStringLiteral("--size"), QStringLiteral("8"),
                                    example("stepped-shaft-chuck.tolturn")});
        QVERIFY2(summary.out.contains(QStringLiteral("; optimum at f = 0.202 mm/rev, vc = 353 m/min\n")),
                 qPrintable(summary.out));
        const Run bad = runCli({QStringLiteral("window"), QStringLiteral("--plane"), QStringLiteral("speed-depth"),
                                example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(bad.exitCode, 2);
    }

    // A binding constraint's label is one CSV field (RFC 4180 §2.6-2.7) even when the tolerance's id
    // holds a quote and a comma: the long shaft on a cold machine whose spindle drifts 200 µm per
    // 1000 rpm (an illustrative value, made large so that tolerance T4 binds).
    void windowCsvQuotesTheBindingLabel()
    {
        QTemporaryDir dir;
        QJsonObject project = exampleJson("long-shaft-centres.tolturn");
        project.insert(
            QStringLiteral("characterisation"),
            QJsonObject{{QStringLiteral("source"), QStringLiteral("test")},
                        {QStringLiteral("thermal"), QJsonObject{{QStringLiteral("drift_um_per_1000rpm"), 200.0},
                                                                {QStringLiteral("time_constant_min"), 5.0}}}});
        project.insert(QStringLiteral("environment"), QJsonObject{{QStringLiteral("time_since_start_min"), 0.0}});
        QJsonArray tolerances = project.value(QStringLiteral("tolerances")).toArray();
        QJsonObject t4 = tolerances.at(3).toObject();
        QCOMPARE(t4.value(QStringLiteral("id")).toString(), QStringLiteral("T4"));
        t4.insert(QStringLiteral("id"), QStringLiteral("T\"4,k6"));
        tolerances.replace(3, t4);
        project.insert(QStringLiteral("tolerances"), tolerances);
        const QString file = dir.filePath(QStringLiteral("quoted.tolturn"));
        QVERIFY(writeFile(file, QJsonDocument(project).toJson()));
        const Run r = runCli({QStringLiteral("window"), QStringLiteral("--plane"), QStringLiteral("feed-speed"),
                              QStringLiteral("--csv"), QStringLiteral("--size"), QStringLiteral("6"), file});
        QCOMPARE(r.exitCode, 0);
        int quoted = 0;
        for (const QString &line : r.out.trimmed().split(QLatin1Char('\n')))
            quoted += line.endsWith(QStringLiteral(",0,\"tolerance T\"\"4,k6\"")) ? 1 : 0;
        QVERIFY2(quoted > 0, qPrintable(r.out));
        // No point of this window is feasible: its centre is not called an optimum.
        const Run summary = runCli({QStringLiteral("window"), QStringLiteral("--size"), QStringLiteral("6"), file});
        QCOMPARE(summary.exitCode, 0);
        QVERIFY2(summary.out.startsWith(QStringLiteral("6 × 6 window, 0.0 % feasible; no plan meets every "
                                                       "constraint; the one that violates them least at f = ")),
                 qPrintable(summary.out));
    }

    // The time per part is the sum of its parts, as planning_problem.cpp adds them: the stepped
    // shaft's handling_time_min is 0.5, its rate 1.2 per min, and it has no Taylor constants, so
    // tool edges and tool changes are not known (not printed as zero) and the cost is the time x 1.2.
    void optimizeTimeAddsUp()
    {
        const Run r = runCli({QStringLiteral("optimize"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(r.exitCode, 0);
        const QRegularExpression line(QStringLiteral(
            "time per part ([0-9.]+) min \\(finishing ([0-9.]+), roughing ([0-9.]+), handling ([0-9.]+), "
            "tool changes not known\\), cost ([0-9.]+) at 1.2 per min, tool edges per part not known"));
        const QRegularExpressionMatch m = line.match(r.out);
        QVERIFY2(m.hasMatch(), qPrintable(r.out));
        const auto at = [&m](int i) { return m.captured(i).toDouble(); };
        QCOMPARE(m.captured(4), QStringLiteral("0.500"));
        QVERIFY2(std::abs(at(2) + at(3) + at(4) - at(1)) <= 0.002, qPrintable(m.captured(0)));
        QVERIFY2(std::abs(at(5) - 1.2 * at(1)) <= 0.006, qPrintable(m.captured(0)));
        const Run json =
            runCli({QStringLiteral("optimize"), QStringLiteral("--json"), example("stepped-shaft-chuck.tolturn")});
        const QJsonObject o = QJsonDocument::fromJson(json.out.toUtf8()).object();
        QVERIFY(o.value(QStringLiteral("tool_edges_per_part")).isNull());
        QVERIFY(o.value(QStringLiteral("tool_change_time_min")).isNull());
        QCOMPARE(o.value(QStringLiteral("handling_time_min")).toDouble(), 0.5);
        const double parts = o.value(QStringLiteral("finishing_time_min")).toDouble() +
                             o.value(QStringLiteral("roughing_time_min")).toDouble() +
                             o.value(QStringLiteral("handling_time_min")).toDouble();
        QVERIFY(std::abs(parts - o.value(QStringLiteral("time_min")).toDouble()) < 1e-9);
    }

    // Degenerate Taylor data (C = 0.5 m/min, n = 0.01: T = (C/v)^(1/n) ≈ 10^-260 min at 201 m/min)
    // makes the time per part astronomically large: printed to four digits with its exponent, not as
    // a row of 260 digits.
    void optimizePrintsAHugeTimeReadably()
    {
        QTemporaryDir dir;
        QJsonObject project = exampleJson("stepped-shaft-chuck.tolturn");
        QJsonObject planning = project.value(QStringLiteral("planning")).toObject();
        planning.insert(QStringLiteral("tool_life"), QJsonObject{{QStringLiteral("C_m_min"), 0.5},
                                                                 {QStringLiteral("n"), 0.01},
                                                                 {QStringLiteral("min_minutes"), 15.0},
                                                                 {QStringLiteral("source"), QStringLiteral("test")}});
        project.insert(QStringLiteral("planning"), planning);
        const QString file = dir.filePath(QStringLiteral("degenerate.tolturn"));
        QVERIFY(writeFile(file, QJsonDocument(project).toJson()));
        const Run r = runCli({QStringLiteral("optimize"), QStringLiteral("--time-limit"), QStringLiteral("5"), file});
        QCOMPARE(r.exitCode, 1);
        const QRegularExpression time(
            QStringLiteral("time per part \\d\\.\\d{0,3}e\\+\\d{2,3} min \\(finishing \\d+\\.\\d{3}, roughing "));
        QVERIFY2(time.match(r.out).hasMatch(), qPrintable(r.out));
        QVERIFY2(!QRegularExpression(QStringLiteral("\\d{12}")).match(r.out).hasMatch(), qPrintable(r.out));
    }

    void adviseClampingJson()
    {
        const Run r = runCli(
            {QStringLiteral("advise-clamping"), QStringLiteral("--json"), example("long-shaft-centres.tolturn")});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray ranking =
            QJsonDocument::fromJson(r.out.toUtf8()).object().value(QStringLiteral("ranking")).toArray();
        QCOMPARE(ranking.size(), 3);
        QCOMPARE(ranking.at(0).toObject().value(QStringLiteral("rank")).toInt(), 1);
        QVERIFY(ranking.at(0).toObject().value(QStringLiteral("feasible")).toBool());
        QCOMPARE(ranking.at(2).toObject().value(QStringLiteral("method")).toString(), QStringLiteral("chuck"));
        QVERIFY(!ranking.at(2).toObject().value(QStringLiteral("reason")).toString().isEmpty());
    }

    // Without the insert's ranges no method can be planned: each says why, and the exit code says
    // the input has a problem, as optimize's does.
    void adviseClampingWithoutRangesIsAProblem()
    {
        QTemporaryDir dir;
        QJsonObject project = exampleJson("stepped-shaft-chuck.tolturn");
        QJsonObject planning = project.value(QStringLiteral("planning")).toObject();
        planning.remove(QStringLiteral("ranges"));
        project.insert(QStringLiteral("planning"), planning);
        const QString file = dir.filePath(QStringLiteral("no-ranges.tolturn"));
        QVERIFY(writeFile(file, QJsonDocument(project).toJson()));
        const Run r = runCli({QStringLiteral("advise-clamping"), file});
        QCOMPARE(r.exitCode, 1);
        const QStringList lines = r.out.trimmed().split(QLatin1Char('\n'));
        QVERIFY2(lines.size() >= 3, qPrintable(r.out)); // the three methods, then the split the jaws call for
        for (int i = 0; i < 3; ++i)
            QVERIFY2(lines.at(i).contains(QStringLiteral("planning.ranges")), qPrintable(lines.at(i)));
        const Run json = runCli({QStringLiteral("advise-clamping"), QStringLiteral("--json"), file});
        QCOMPARE(json.exitCode, 1);
    }

    // gcode --feed-schedule --compensated on the thin pin: O4 (T1 Ø20 h7, held at no feed of the
    // range) keeps 0.170 mm/rev and its profile correction (the pin starts at X19.960, as
    // tst_feed_schedule machines it: the chamfer, at 0.202 mm/rev like the other features, ends
    // there, with no radial step of its own), then runs on at 0.170.
    void gcodeScheduledAndCompensated()
    {
        const Run r =
            runCli({QStringLiteral("gcode"), QStringLiteral("--feed-schedule"), QStringLiteral("--compensated"),
                    QStringLiteral("-o"), QStringLiteral("-"), example("thin-pin-compensation.tolturn")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("X17.990 Z0.000 F0.202\n")), qPrintable(r.out));
        const qsizetype pinStart = r.out.indexOf(QStringLiteral("X19.960 Z-1.000\n"));
        QVERIFY(pinStart > 0);
        const QString alongThePin = r.out.mid(pinStart).section(QLatin1Char('\n'), 1, 1);
        QVERIFY2(alongThePin.endsWith(QStringLiteral(" F0.170")), qPrintable(alongThePin));
        QVERIFY2(r.err.contains(QStringLiteral("feed schedule: O4 kept at the programmed 0.170 mm/rev")),
                 qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("thin-pin-compensation.tolturn: compensation: O4 profile, residual ")),
                 qPrintable(r.err));
    }

    void gcodeFile()
    {
        QTemporaryDir dir;
        const QString nc = dir.filePath(QStringLiteral("shaft.nc"));
        const Run r = runCli({QStringLiteral("gcode"), QStringLiteral("-o"), nc, QStringLiteral("--compensated"),
                              example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(r.exitCode, 0);
        QFile file(nc);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString program = QString::fromUtf8(file.readAll());
        // The Haas ST-20 of the example has a Fanuc-style control: G50 spindle limit, G99 feed per
        // revolution, G42 nose radius compensation; eight roughing passes at 200 m/min, then the
        // finishing pass at 250 m/min.
        QVERIFY(program.startsWith(QStringLiteral("%\nO01000\n(TOLTURN")));
        QVERIFY(program.contains(QStringLiteral("COMPENSATED")));
        QVERIFY(program.contains(QStringLiteral("G18 G21 G40 G99")));
        QVERIFY(program.contains(QStringLiteral("G50 S")));
        QVERIFY(program.contains(QStringLiteral("G96 S200 M03")));
        QVERIFY(program.contains(QStringLiteral("G96 S250\n")));
        QVERIFY(program.contains(QStringLiteral("G42 G01")));
        QVERIFY(program.contains(QStringLiteral("G40 G01")));
        QVERIFY(program.contains(QStringLiteral("(PASS 9, FINISHING")));
        QVERIFY(program.contains(QStringLiteral("M30")));
        // Comments wrap at 72 characters but keep a quantity whole: the conditions line breaks
        // before "AP 1.938 MM", not between "AP" and "1.938" or "1.938" and "MM".
        QVERIFY2(program.contains(QStringLiteral("\n(AP 1.938 MM, PASS 9 FINISHING")), qPrintable(program));
        QVERIFY(!program.contains(QStringLiteral("\n(MM")) && !program.contains(QStringLiteral(" AP)\n")));
        QVERIFY(r.err.contains(QStringLiteral("the control of machine haas-st-20")));
        // Every tolerance of the stepped shaft holds as programmed: nothing to correct, and it says so.
        QVERIFY2(r.err.contains(QStringLiteral("stepped-shaft-chuck.tolturn: compensation: no tolerance needs a "
                                               "correction")),
                 qPrintable(r.err));
        const Run usage = runCli({QStringLiteral("gcode"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(usage.exitCode, 2); // -o is required
        // "-o -" writes to standard output; another dialect on request; an unknown one is refused.
        const Run sinumerik =
            runCli({QStringLiteral("gcode"), QStringLiteral("--dialect"), QStringLiteral("sinumerik"),
                    QStringLiteral("-o"), QStringLiteral("-"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(sinumerik.exitCode, 0);
        QVERIFY(sinumerik.out.contains(QStringLiteral("LIMS=")));
        QVERIFY(sinumerik.out.contains(QStringLiteral("G18 G71 G90 DIAMON G95 G40")));
        const Run unknown = runCli({QStringLiteral("gcode"), QStringLiteral("--dialect"), QStringLiteral("heidenhain"),
                                    QStringLiteral("-o"), QStringLiteral("-"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(unknown.exitCode, 2);
        QVERIFY(unknown.err.contains(QStringLiteral("'heidenhain'")));
    }

    void checkWithoutFileIsUsageError()
    {
        const Run r = runCli({QStringLiteral("check")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains(QStringLiteral("no project file given")));
    }

    // simulate-control (issue 18) on the stepped shaft: stock Ø60, chuck over 35 mm, so the tool
    // runs from z 150 to 37 (2 mm clear of the jaws). Pass 1 (a_p 1.9375 mm, f 0.3, vc 200) cuts
    // Ø56.125 over the whole 113 mm: n = 200000 / (π 56.125) = 1134.3 1/min, 113 / (0.3 · 1134.3)
    // min = 19.92 s, at its nominal depth throughout, so the loop has nothing to change. The
    // finishing pass (f 0.1, vc 250 at the contour's diameter) takes 60 π Σ D Δz / (1000 · 250 · 0.1)
    // with Σ D Δz = 43·50 + 10·45 + 28·40 + 2 (2·18 + π) + 29·30 + 1·29 = 4697.28 mm²: 35.41 s; its
    // feed may not pass √(32 · 0.8 mm · 1.6 µm) = 0.202 mm/rev (Ra 1.6 µm).
    void simulateControlOnTheSteppedShaft()
    {
        const Run r = runCli(
            {QStringLiteral("simulate-control"), QStringLiteral("--json"), example("stepped-shaft-chuck.tolturn")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        const QJsonArray passes = json.value(QStringLiteral("passes")).toArray();
        QCOMPARE(passes.size(), 9);
        const QJsonObject first = passes.first().toObject();
        for (const char *run : {"constant_feed", "adaptive"})
            QVERIFY(std::abs(first.value(QLatin1String(run)).toObject().value(QStringLiteral("time_s")).toDouble() -
                             19.92) < 0.04);
        const QJsonObject finishing = passes.last().toObject();
        QCOMPARE(finishing.value(QStringLiteral("kind")).toString(), QStringLiteral("finishing"));
        const double finishingTime =
            finishing.value(QStringLiteral("constant_feed")).toObject().value(QStringLiteral("time_s")).toDouble();
        QVERIFY2(std::abs(finishingTime - 35.41) < 0.04, qPrintable(QString::number(finishingTime)));
        for (const auto &p : passes) {
            const QJsonObject o = p.toObject();
            // Set at the programmed feed's force at the nominal depth, and no pass cuts deeper.
            QVERIFY(o.value(QStringLiteral("time_saved_pct")).toDouble() >= 0.0);
            QVERIFY(o.value(QStringLiteral("adaptive")).toObject().value(QStringLiteral("peak_force_N")).toDouble() <=
                    1.001 * o.value(QStringLiteral("set_force_N")).toDouble());
        }
        const QString notes = json.value(QStringLiteral("notes")).toVariant().toStringList().join(QLatin1Char('\n'));
        QVERIFY2(notes.contains(QStringLiteral("Pass 9: the feed is held at or below 0.202 mm/rev for Ra 1.6 µm")),
                 qPrintable(notes));
        QVERIFY(notes.contains(QStringLiteral("Machine noise: none")));
    }

    void simulateControlCsvAndErrors()
    {
        const Run csv = runCli({QStringLiteral("simulate-control"), QStringLiteral("--csv"), QStringLiteral("--pass"),
                                QStringLiteral("1"), QStringLiteral("--noise"), QStringLiteral("3"),
                                example("stepped-shaft-chuck.tolturn")});
        QVERIFY2(csv.exitCode == 0, qPrintable(csv.err));
        const QStringList lines = csv.out.trimmed().split(QLatin1Char('\n'));
        QVERIFY(lines.first().startsWith(QStringLiteral("run,pass,t_s,z_mm,depth_mm,")));
        // 19.92 s at 20 ms a period, both runs.
        QVERIFY2(std::abs(static_cast<double>(lines.size() - 1) - 2 * 19.92 / 0.02) < 6,
                 qPrintable(QString::number(lines.size())));
        const Run badPass = runCli({QStringLiteral("simulate-control"), QStringLiteral("--pass"), QStringLiteral("10"),
                                    example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(badPass.exitCode, 1);
        QVERIFY2(badPass.err.contains(QStringLiteral("passes: pass 10 does not exist: the plan has 9 passes")),
                 qPrintable(badPass.err));
        const Run badNoise = runCli({QStringLiteral("simulate-control"), QStringLiteral("--noise"),
                                     QStringLiteral("lots"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(badNoise.exitCode, 2);
        QVERIFY2(badNoise.err.contains(QStringLiteral("--noise: \"lots\" is not a number from 0 to 50")),
                 qPrintable(badNoise.err));
    }

    // tune-control (issue 18): pass 3 of the stepped shaft with 5 % noise. The methods' accuracy is
    // tested in tst_controller_tuning; here the command: every method named keeps to its budget,
    // finds gains inside the bounds that do better than the untuned loop, and bad options are named.
    void tuneControlComparesTheMethods()
    {
        const Run r = runCli(
            {QStringLiteral("tune-control"), QStringLiteral("--json"), QStringLiteral("--pass"), QStringLiteral("3"),
             QStringLiteral("--noise"), QStringLiteral("5"), QStringLiteral("--methods"), QStringLiteral("pso,cobyla"),
             QStringLiteral("--evaluations"), QStringLiteral("100"), example("stepped-shaft-chuck.tolturn")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(json.value(QStringLiteral("pass")).toInt(), 3);
        const double untuned = json.value(QStringLiteral("untuned_rms_force_error")).toDouble();
        const QJsonArray methods = json.value(QStringLiteral("methods")).toArray();
        QCOMPARE(methods.size(), 2);
        QCOMPARE(methods[0].toObject().value(QStringLiteral("library")).toString(), QStringLiteral("pagmo2 pso"));
        QCOMPARE(methods[1].toObject().value(QStringLiteral("library")).toString(), QStringLiteral("NLopt LN_COBYLA"));
        for (const auto &m : methods) {
            const QJsonObject o = m.toObject();
            QVERIFY(o.value(QStringLiteral("evaluations")).toInt() <= 100);
            QVERIFY(o.value(QStringLiteral("rms_force_error")).toDouble() < untuned);
            const double lambda = o.value(QStringLiteral("estimator_gain")).toDouble();
            const double g = o.value(QStringLiteral("command_gain")).toDouble();
            QVERIFY(lambda >= 0.02 && lambda <= 1.0 && g >= 0.1 && g <= 2.0);
        }
        const Run badMethod = runCli({QStringLiteral("tune-control"), QStringLiteral("--methods"),
                                      QStringLiteral("pso,genetic"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(badMethod.exitCode, 2);
        QVERIFY2(badMethod.err.contains(QStringLiteral("--methods: \"genetic\" is not a method (pso, cobyla,")),
                 qPrintable(badMethod.err));
        const Run badPass = runCli({QStringLiteral("tune-control"), QStringLiteral("--pass"), QStringLiteral("2.5"),
                                    example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(badPass.exitCode, 2);
        QVERIFY2(badPass.err.contains(QStringLiteral("--pass: \"2.5\" is not a whole number from 1 to 1000")),
                 qPrintable(badPass.err));
        const Run noMethod = runCli({QStringLiteral("tune-control"), QStringLiteral("--methods"), QStringLiteral(","),
                                     example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(noMethod.exitCode, 2);
        QVERIFY2(noMethod.err.contains(QStringLiteral("--methods: no method named")), qPrintable(noMethod.err));
        // Above 1 the command would alternate about its target every period (docs/adaptive.md §8).
        const Run badGain = runCli({QStringLiteral("simulate-control"), QStringLiteral("--command-gain"),
                                    QStringLiteral("1.5"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(badGain.exitCode, 2);
        QVERIFY2(badGain.err.contains(QStringLiteral("--command-gain: \"1.5\" is not a number from 0.1 to 1")),
                 qPrintable(badGain.err));
    }

    // control-example (issue 18): the paper's own end-milling system. Its numbers are tested in
    // tst_seed_milling; here the command: the loop settles at table 1's 181.1 N, all eight rows and
    // all methods are reported, the CSV has both runs, and a bad option is named.
    void controlExampleRebuildsThePaper()
    {
        const Run r = runCli({QStringLiteral("control-example"), QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY(
            std::abs(
                json.value(QStringLiteral("adaptive_settled")).toObject().value(QStringLiteral("force_N")).toDouble() -
                181.1) < 0.05);
        QCOMPARE(json.value(QStringLiteral("table1")).toArray().size(), 8);
        QCOMPARE(json.value(QStringLiteral("conditions")).toArray().size(), 8);
        QVERIFY(json.value(QStringLiteral("network_unseen_rms_error")).toDouble() < 0.01);
        const Run csv = runCli({QStringLiteral("control-example"), QStringLiteral("--csv"),
                                QStringLiteral("--duration"), QStringLiteral("1")});
        QVERIFY2(csv.exitCode == 0, qPrintable(csv.err));
        QCOMPARE(csv.out.trimmed().split(QLatin1Char('\n')).size(), 1 + 2 * 50);
        const Run bad =
            runCli({QStringLiteral("control-example"), QStringLiteral("--speed-share"), QStringLiteral("2")});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains(QStringLiteral("--speed-share: \"2\" is not a number from 0 to 1")),
                 qPrintable(bad.err));
    }

    // mill-forces and mill-deflect (issue 19): the model is tested in tst_ball_end_forces; here the
    // commands. 001 case 2 (one flute, lead and tilt 15°, slot, a = 3 mm, 0.1 mm/rev, 269 1/min) with
    // K_tc only: the mean torque is K_tc f_t ∫R dz / π at any lead and tilt, ∫₀³ R dz = 9π − (3/2)√27
    // − 18 asin(1/2) = 6π − 7.7942 = 11.0553 mm² (R_o = 6), so 1000 · 0.1 · 11.0553 / π = 351.90
    // N·mm, and the power 0.35190 N·m · 2π · 269 / 60 = 9.913 W.
    void millingCommandsFollowThePaper()
    {
        constexpr double kPi = std::numbers::pi;
        const QStringList case2 = {QStringLiteral("--case"), QStringLiteral("2"), QStringLiteral("--coefficients"),
                                   QStringLiteral("1000,0,0,0,0,0")};
        const Run r = runCli(QStringList{QStringLiteral("mill-forces"), QStringLiteral("--json")} + case2);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        const double integral = 6.0 * kPi - 1.5 * std::sqrt(27.0);
        const double torque = 1000.0 * 0.1 * integral / kPi;
        QVERIFY2(std::abs(json.value(QStringLiteral("mean_torque_N_mm")).toDouble() / torque - 1.0) < 2e-3,
                 qPrintable(r.out.left(400)));
        QVERIFY(std::abs(json.value(QStringLiteral("mean_power_W")).toDouble() -
                         torque * 1e-3 * 2.0 * kPi * 269.0 / 60.0) < 0.03);
        QCOMPARE(json.value(QStringLiteral("samples")).toArray().size(), 360);
        const Run csv = runCli(QStringList{QStringLiteral("mill-forces"), QStringLiteral("--csv"),
                                           QStringLiteral("--angles"), QStringLiteral("90")} +
                               case2);
        QVERIFY2(csv.exitCode == 0, qPrintable(csv.err));
        QCOMPARE(csv.out.trimmed().split(QLatin1Char('\n')).size(), 1 + 90);

        const Run noData = runCli({QStringLiteral("mill-forces"), QStringLiteral("--case"), QStringLiteral("1")});
        QCOMPARE(noData.exitCode, 2);
        QVERIFY2(noData.err.contains(QStringLiteral("--coefficients")), qPrintable(noData.err));
        const Run deep = runCli(
            QStringList{QStringLiteral("mill-forces"), QStringLiteral("--axial-depth"), QStringLiteral("5")} + case2);
        QCOMPARE(deep.exitCode, 2);
        QVERIFY2(deep.err.contains(QStringLiteral("axial depth: 5 mm is not within the ball")), qPrintable(deep.err));
        const Run noTool = runCli({QStringLiteral("mill-forces"), QStringLiteral("--diameter"), QStringLiteral("10")});
        QCOMPARE(noTool.exitCode, 2);
        QVERIFY2(
            noTool.err.contains(QStringLiteral("--flutes, --axial-depth, --feed-per-tooth, --spindle-speed missing")),
            qPrintable(noTool.err));

        // mill-deflect: a structure is needed; with --case the paper's springs are used and said to be.
        const Run noStructure = runCli(QStringList{QStringLiteral("mill-deflect")} + case2);
        QCOMPARE(noStructure.exitCode, 2);
        QVERIFY2(noStructure.err.contains(QStringLiteral("--overhang, --equivalent-diameter missing")),
                 qPrintable(noStructure.err));
        const QStringList structure = {QStringLiteral("--overhang"), QStringLiteral("40"),
                                       QStringLiteral("--equivalent-diameter"), QStringLiteral("9.6")};
        const Run text = runCli(QStringList{QStringLiteral("mill-deflect")} + case2 + structure);
        QVERIFY2(text.exitCode == 0, qPrintable(text.err));
        QVERIFY2(text.out.contains(QStringLiteral("k = 6306 N/mm")) &&
                     text.out.contains(QStringLiteral("001's calibration")),
                 qPrintable(text.out));
        const Run deflection =
            runCli(QStringList{QStringLiteral("mill-deflect"), QStringLiteral("--json")} + case2 + structure);
        QVERIFY2(deflection.exitCode == 0, qPrintable(deflection.err));
        const QJsonObject d = QJsonDocument::fromJson(deflection.out.toUtf8()).object();
        const QJsonObject range = d.value(QStringLiteral("surface_normal_error_um")).toObject();
        QVERIFY(range.value(QStringLiteral("least")).toDouble() < range.value(QStringLiteral("greatest")).toDouble());
        // The generating point of a 15°/15° tool: R_o (1 − cos²15°) = 6 · 0.066987 = 0.40192 mm.
        QVERIFY(std::abs(d.value(QStringLiteral("generating_point_height_mm")).toDouble() - 0.401924) < 1e-5);
        const Run badHolder =
            runCli(QStringList{QStringLiteral("mill-deflect"), QStringLiteral("--holder"), QStringLiteral("6306")} +
                   case2 + structure);
        QCOMPARE(badHolder.exitCode, 2);
        QVERIFY2(badHolder.err.contains(QStringLiteral("--holder: \"6306\" is not two numbers")),
                 qPrintable(badHolder.err));
    }

    // mill-optimize (issue 19): its planning is tested in tst_ball_end_planning; here the command. The
    // planned lead, tilt and feed, given back to mill-deflect, leave a spread of the normal error
    // within the tolerance; the window has the cells asked for; what it needs is named.
    void millOptimizeHoldsTheTolerance()
    {
        const QStringList cut = {QStringLiteral("--case"),
                                 QStringLiteral("1"),
                                 QStringLiteral("--coefficients"),
                                 QStringLiteral("2000,700,400,25,40,8"),
                                 QStringLiteral("--overhang"),
                                 QStringLiteral("40"),
                                 QStringLiteral("--equivalent-diameter"),
                                 QStringLiteral("9.6")};
        const Run r =
            runCli(QStringList{QStringLiteral("mill-optimize"), QStringLiteral("--json"), QStringLiteral("--tolerance"),
                               QStringLiteral("0.02"), QStringLiteral("--max-feed-per-tooth"), QStringLiteral("0.15"),
                               QStringLiteral("--lead-range"), QStringLiteral("5,30"), QStringLiteral("--tilt-range"),
                               QStringLiteral("5,30"), QStringLiteral("--cells"), QStringLiteral("8")} +
                   cut);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject plan = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY(plan.value(QStringLiteral("feasible")).toBool());
        QCOMPARE(plan.value(QStringLiteral("window")).toArray().size(), 64);
        const auto value = [&](const char *key) {
            return QString::number(plan.value(QLatin1String(key)).toDouble(), 'g', 17);
        };
        const Run check =
            runCli(QStringList{QStringLiteral("mill-deflect"), QStringLiteral("--json"), QStringLiteral("--lead"),
                               value("lead_deg"), QStringLiteral("--tilt"), value("tilt_deg"),
                               QStringLiteral("--feed-per-tooth"), value("feed_per_tooth_mm")} +
                   cut);
        QVERIFY2(check.exitCode == 0, qPrintable(check.err));
        const QJsonObject range = QJsonDocument::fromJson(check.out.toUtf8())
                                      .object()
                                      .value(QStringLiteral("surface_normal_error_um"))
                                      .toObject();
        const double spread =
            range.value(QStringLiteral("greatest")).toDouble() - range.value(QStringLiteral("least")).toDouble();
        QVERIFY2(spread <= 20.0 + 1e-6, qPrintable(QString::number(spread)));
        QVERIFY(spread > 19.0); // the feed is bound by the tolerance, not the maker's 0.15 mm

        const Run noTolerance = runCli(QStringList{QStringLiteral("mill-optimize"),
                                                   QStringLiteral("--max-feed-per-tooth"), QStringLiteral("0.1")} +
                                       cut);
        QCOMPARE(noTolerance.exitCode, 2);
        QVERIFY2(noTolerance.err.contains(QStringLiteral("--tolerance is required")), qPrintable(noTolerance.err));
        const Run noFeed = runCli(
            QStringList{QStringLiteral("mill-optimize"), QStringLiteral("--tolerance"), QStringLiteral("0.01")} + cut);
        QCOMPARE(noFeed.exitCode, 2);
        QVERIFY2(noFeed.err.contains(QStringLiteral("--max-feed-per-tooth is required")), qPrintable(noFeed.err));
    }

    // Milled features in a project (issue 19): evaluate judges each against its tolerance (the
    // margin is t = 3 µm − form error; a flat's path runs its z range, here 20 mm) and names what an
    // incomplete one lacks; mill-deflect computes the feature's own cut, whose spread over a
    // revolution is the flat's form error; mill-optimize --save writes its plan into the file,
    // which then holds the tolerance with the feed bound by it; options that would change the
    // feature's cut are refused.
    void milledFeaturesOfAProject()
    {
        QJsonObject project = QJsonDocument::fromJson([] {
                                  QFile f(example("stepped-shaft-chuck.tolturn"));
                                  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
                              }())
                                  .object();
        const QByteArray flat = R"({"id": "M1", "kind": "flat", "z_from_mm": 10, "z_to_mm": 30,
            "tool": {"diameter_mm": 12, "flutes": 2, "helix_deg": 30, "overhang_mm": 40,
                     "equivalent_diameter_mm": 9.6, "holder_stiffness_N_mm": 6306,
                     "holder_rotational_Nmm_rad": 1.656e7},
            "conditions": {"cut": "step_over", "radial_depth_mm": 1.0, "axial_depth_mm": 0.5,
                           "feed_per_tooth_mm": 0.05, "spindle_rpm": 3000, "lead_deg": 10, "tilt_deg": 0},
            "coefficients": {"Ktc_N_mm2": 2000, "Krc_N_mm2": 700, "Kac_N_mm2": 400, "Kte_N_mm": 25,
                             "Kre_N_mm": 40, "Kae_N_mm": 8, "source": "test values"},
            "tolerance": {"type": "flatness", "value_um": 3}})";
        project.insert(QStringLiteral("milled_features"),
                       QJsonArray{QJsonDocument::fromJson(flat).object(),
                                  QJsonObject{{QStringLiteral("id"), QStringLiteral("M2")},
                                              {QStringLiteral("kind"), QStringLiteral("keyway")},
                                              {QStringLiteral("z_from_mm"), 5},
                                              {QStringLiteral("z_to_mm"), 25}}});
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("milled.tolturn"));
        QVERIFY(writeFile(file, QJsonDocument(project).toJson()));

        const Run r = runCli({QStringLiteral("evaluate"), QStringLiteral("--json"), file});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonArray milled =
            QJsonDocument::fromJson(r.out.toUtf8()).object().value(QStringLiteral("milled_features")).toArray();
        QCOMPARE(milled.size(), 2);
        const QJsonObject m1 = milled.at(0).toObject();
        const double formError = m1.value(QStringLiteral("form_error_um")).toDouble();
        QVERIFY(m1.value(QStringLiteral("passes")).toBool());
        QVERIFY(std::abs(m1.value(QStringLiteral("margin_um")).toDouble() - (3.0 - formError)) < 1e-9);
        QCOMPARE(m1.value(QStringLiteral("path")).toArray().last().toObject().value(QStringLiteral("arc_length_mm")),
                 20.0);
        const QJsonObject m2 = milled.at(1).toObject();
        QVERIFY(!m2.value(QStringLiteral("evaluated")).toBool());
        QCOMPARE(m2.value(QStringLiteral("missing")).toArray().size(), 4);

        const Run deflect = runCli({QStringLiteral("mill-deflect"), QStringLiteral("--json"), file,
                                    QStringLiteral("--feature"), QStringLiteral("M1")});
        QVERIFY2(deflect.exitCode == 0, qPrintable(deflect.err));
        const QJsonObject range = QJsonDocument::fromJson(deflect.out.toUtf8())
                                      .object()
                                      .value(QStringLiteral("surface_normal_error_um"))
                                      .toObject();
        const double spread =
            range.value(QStringLiteral("greatest")).toDouble() - range.value(QStringLiteral("least")).toDouble();
        QVERIFY2(std::abs(spread - formError) < 1e-9, qPrintable(QStringLiteral("%1 %2").arg(spread).arg(formError)));

        const Run plan =
            runCli({QStringLiteral("mill-optimize"), file, QStringLiteral("--feature"), QStringLiteral("M1"),
                    QStringLiteral("--max-feed-per-tooth"), QStringLiteral("0.15"), QStringLiteral("--lead-range"),
                    QStringLiteral("5,30"), QStringLiteral("--tilt-range"), QStringLiteral("5,30"),
                    QStringLiteral("--cells"), QStringLiteral("6"), QStringLiteral("--save")});
        QVERIFY2(plan.exitCode == 0, qPrintable(plan.err + plan.out));
        QVERIFY2(plan.out.contains(QStringLiteral("saved")), qPrintable(plan.out));
        const auto saved = tolturn::readProjectFile(file);
        QVERIFY(saved.project.has_value());
        const tolturn::MillingConditions &c = *saved.project->milledFeatures.front().conditions;
        QVERIFY(c.lead_deg >= 5.0 && c.lead_deg <= 30.0 && c.tilt_deg >= 5.0 && c.tilt_deg <= 30.0);
        QVERIFY(c.feedPerTooth_mm > 0.0 && c.feedPerTooth_mm < 0.15);
        const Run again = runCli({QStringLiteral("evaluate"), QStringLiteral("--json"), file});
        QVERIFY2(again.exitCode == 0, qPrintable(again.err));
        const QJsonObject planned = QJsonDocument::fromJson(again.out.toUtf8())
                                        .object()
                                        .value(QStringLiteral("milled_features"))
                                        .toArray()
                                        .at(0)
                                        .toObject();
        const double plannedError = planned.value(QStringLiteral("form_error_um")).toDouble();
        QVERIFY2(plannedError <= 3.0 && plannedError > 2.85, qPrintable(QString::number(plannedError)));
        QVERIFY(planned.value(QStringLiteral("passes")).toBool()); // the saved feed, rounded down, holds

        const Run clash = runCli({QStringLiteral("mill-forces"), file, QStringLiteral("--feature"),
                                  QStringLiteral("M1"), QStringLiteral("--diameter"), QStringLiteral("10")});
        QCOMPARE(clash.exitCode, 2);
        QVERIFY2(clash.err.contains(QStringLiteral("--diameter")), qPrintable(clash.err));
        const Run unknown =
            runCli({QStringLiteral("mill-forces"), file, QStringLiteral("--feature"), QStringLiteral("M9")});
        QCOMPARE(unknown.exitCode, 2);
        QVERIFY2(unknown.err.contains(QStringLiteral("M9")), qPrintable(unknown.err));
        const Run lacking =
            runCli({QStringLiteral("mill-forces"), file, QStringLiteral("--feature"), QStringLiteral("M2")});
        QCOMPARE(lacking.exitCode, 2);
        QVERIFY2(lacking.err.contains(QStringLiteral("coefficients")), qPrintable(lacking.err));
    }

    // verify-fe (issue 17): the solid check from the command line on a coarse mesh. Its accuracy
    // is tested in tst_solid_fe; here the command: its table, its JSON and its errors.
    void verifyFeComparesBeamAndSolid()
    {
        const Run r = runCli({QStringLiteral("verify-fe"), QStringLiteral("--json"), QStringLiteral("--stations"),
                              QStringLiteral("2"), QStringLiteral("--mesh-size"), QStringLiteral("8"),
                              example("stepped-shaft-chuck.tolturn")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        const QJsonArray stations = json.value(QStringLiteral("stations")).toArray();
        QCOMPARE(stations.size(), 2);
        for (const auto &v : stations) {
            const double beam = v.toObject().value(QStringLiteral("beam_radial_um")).toDouble();
            const double solid = v.toObject().value(QStringLiteral("solid_radial_um")).toDouble();
            QVERIFY2(beam > 0.0 && solid > 0.0 && std::abs(beam / solid - 1.0) < 0.3,
                     qPrintable(QStringLiteral("beam %1 µm, solid %2 µm").arg(beam).arg(solid)));
            QCOMPARE(v.toObject().value(QStringLiteral("radial_difference_pct")).toDouble(),
                     100.0 * (beam - solid) / solid);
        }
        const QJsonObject mesh = json.value(QStringLiteral("mesh")).toObject();
        QCOMPARE(mesh.value(QStringLiteral("size_mm")).toDouble(), 8.0);
        QVERIFY(mesh.value(QStringLiteral("degrees_of_freedom")).toInt() <
                3 * mesh.value(QStringLiteral("nodes")).toInt());
        const Run table =
            runCli({QStringLiteral("verify-fe"), QStringLiteral("--stations"), QStringLiteral("1"),
                    QStringLiteral("--mesh-size"), QStringLiteral("8"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(table.exitCode, 0);
        QVERIFY(table.out.contains(QStringLiteral("beam-solid [%]")));
    }

    void verifyFeRefusesBadOptions_data()
    {
        QTest::addColumn<QStringList>("options");
        QTest::addColumn<QString>("message");
        QTest::newRow("no stations") << QStringList{QStringLiteral("--stations"), QStringLiteral("0")}
                                     << QStringLiteral("--stations: \"0\"");
        QTest::newRow("mesh size text") << QStringList{QStringLiteral("--mesh-size"), QStringLiteral("fine")}
                                        << QStringLiteral("--mesh-size: \"fine\"");
        QTest::newRow("bad load") << QStringList{QStringLiteral("--load"), QStringLiteral("1,2")}
                                  << QStringLiteral("--load: \"1,2\"");
    }

    void verifyFeRefusesBadOptions()
    {
        QFETCH(QStringList, options);
        QFETCH(QString, message);
        const Run r = runCli(QStringList{QStringLiteral("verify-fe")} + options +
                             QStringList{example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
    }

    void verifyFeWithoutCalculixSaysHowToInstallIt()
    {
        qputenv("TOLTURN_CCX", "/nonexistent/ccx");
        const Run r = runCli({QStringLiteral("verify-fe"), example("stepped-shaft-chuck.tolturn")});
        qunsetenv("TOLTURN_CCX");
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("sudo apt install calculix-ccx")), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
