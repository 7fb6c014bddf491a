// SPDX-License-Identifier: GPL-3.0-or-later
// The PDF report as a user gets it from `tolturn-cli report`, read back with poppler's
// pdfinfo/pdftotext: page size and count, the sections, and numbers checked against the
// published ISO 286-2 tables; the milled features' section against the model's own evaluation.
#include "tests/cli/cli_runner.h"

#include "core/io/project_file.h"
#include "core/io/project_json.h"
#include "core/milling/milled_features.h"
#include "core/milling/seed_ball_end_cases.h"

#include <QDate>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>

using tolturn::test::example;
using tolturn::test::Run;
using tolturn::test::runCli;
using tolturn::test::runProgram;

namespace {

QString pdfText(const QString &pdf)
{
    const Run r = runProgram(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), pdf, QStringLiteral("-")});
    if (r.exitCode != 0)
        qFatal("pdftotext failed: %s", qPrintable(r.err));
    return r.out;
}

// The line of the tolerance table that starts with `id`, split on runs of spaces.
QStringList tableRow(const QString &text, const QString &id)
{
    const QRegularExpression row(QStringLiteral("^\\s*%1\\s+.*$").arg(QRegularExpression::escape(id)),
                                 QRegularExpression::MultilineOption);
    const QString line = row.match(text).captured(0).trimmed();
    return line.split(QRegularExpression(QStringLiteral("\\s{2,}")));
}

// A word of a PDF page and its box in points, as pdftotext -bbox gives them.
struct Word {
    QString text;
    double left, top, right, bottom;
};

// The words of every page of `pdf`, page by page.
std::vector<std::vector<Word>> pageWords(const QString &pdf)
{
    const Run boxes = runProgram(QStringLiteral("pdftotext"), {QStringLiteral("-bbox"), pdf, QStringLiteral("-")});
    if (boxes.exitCode != 0)
        qFatal("pdftotext -bbox failed: %s", qPrintable(boxes.err));
    static const QRegularExpression word(
        QStringLiteral("xMin=\"([0-9.]+)\" yMin=\"([0-9.]+)\" xMax=\"([0-9.]+)\" yMax=\"([0-9.]+)\">([^<]*)</word>"));
    std::vector<std::vector<Word>> pages;
    for (const QString &page : boxes.out.split(QStringLiteral("<page ")).mid(1)) { // [0] is the document's head
        pages.emplace_back();
        for (auto it = word.globalMatch(page); it.hasNext();) {
            const QRegularExpressionMatch m = it.next();
            pages.back().push_back({m.captured(5), m.captured(1).toDouble(), m.captured(2).toDouble(),
                                    m.captured(3).toDouble(), m.captured(4).toDouble()});
        }
    }
    return pages;
}

// 001's case 1 (a slot at tilt −15°) as a flat on the stepped shaft, with a tool and holder of the
// paper's springs, made-up coefficients and a 20 µm flatness; the modulus not given (carbide's).
tolturn::MilledFeature completeFlat()
{
    using namespace tolturn;
    const SeedBallEndCase seed = seedBallEndCases().front();
    MilledFeature f;
    f.id = QStringLiteral("M1");
    f.kind = MilledFeatureKind::Flat;
    f.zFrom_mm = 20.0;
    f.zTo_mm = 50.0;
    BallEndTool tool;
    tool.diameter_mm = seed.mill.diameter_mm;
    tool.flutes = seed.mill.flutes;
    tool.helix_deg = 30.0;
    tool.overhang_mm = 50.0;
    tool.equivalentDiameter_mm = 0.8 * seed.mill.diameter_mm;
    tool.holderStiffness_N_mm = kSeedHolderStiffness_N_mm;
    tool.holderRotational_N_mm_rad = kSeedHolderRotational_N_mm_rad;
    f.tool = tool;
    MillingConditions c;
    c.cut = seed.cut.kind;
    c.direction = seed.cut.direction;
    c.axialDepth_mm = seed.cut.axialDepth_mm;
    c.feedPerTooth_mm = seed.cut.feedPerTooth_mm;
    c.spindle_rpm = seed.spindle_rpm;
    c.lead_deg = 0.0;
    c.tilt_deg = -15.0;
    f.conditions = c;
    f.coefficients = MillingForceCoefficients{2000.0, 800.0, 400.0, 20.0, 20.0, 5.0};
    f.coefficientsSource = QStringLiteral("test values");
    f.tolerance = MilledTolerance{MilledToleranceType::Flatness, 20.0, {}};
    return f;
}

} // namespace

class TestReport : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void reportOfTheSteppedShaft()
    {
        QTemporaryDir dir;
        const QString pdf = dir.filePath(QStringLiteral("shaft.pdf"));
        const Run r = runCli({QStringLiteral("report"), QStringLiteral("--planner"), QStringLiteral("A. Planner"),
                              QStringLiteral("-o"), pdf, example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(r.exitCode, 0);

        const Run info = runProgram(QStringLiteral("pdfinfo"), {pdf});
        QCOMPARE(info.exitCode, 0);
        QVERIFY2(info.out.contains(QStringLiteral("A4")), qPrintable(info.out));
        QVERIFY(info.out.contains(QStringLiteral("TolTurn report: Stepped shaft")));
        const int pages = QRegularExpression(QStringLiteral("Pages:\\s+(\\d+)")).match(info.out).captured(1).toInt();
        QVERIFY2(pages >= 3 && pages <= 8, qPrintable(info.out));
        QVERIFY(r.out.contains(QStringLiteral("%1 pages").arg(pages)));

        const QString text = pdfText(pdf);
        for (const char *section :
             {"1 Part", "2 Set-up sheet and inputs", "3 Predicted deviation", "4 Tolerances", "5 Plan", "6 Assumptions",
              "Appendix A Literature", "Appendix B Sources of the data"}) {
            const QString pattern =
                QStringLiteral("^\\f?%1$")
                    .arg( // a heading may open a page
                        QString::fromUtf8(section).replace(QLatin1Char(' '), QStringLiteral("\\s+")));
            QVERIFY2(text.contains(QRegularExpression(pattern, QRegularExpression::MultilineOption)), section);
        }
        // No milled features: no section of them, and not their model in the literature.
        QVERIFY(!text.contains(QStringLiteral("Milled features")));
        QVERIFY(!text.contains(QStringLiteral("Öztürk")));
        QVERIFY(text.contains(QStringLiteral("page %1 of %1").arg(pages)));
        // The appendices follow the assumptions, on their last page when a third of it is free (here:
        // the assumptions run over onto the last page), else on a page of their own.
        const QStringList pageTexts = text.split(QLatin1Char('\f'));
        const auto appendix = std::find_if(pageTexts.begin(), pageTexts.end(), [](const QString &page) {
            return page.contains(QStringLiteral("Appendix A"));
        });
        QVERIFY(appendix != pageTexts.end());
        const auto assumptions = [](const QString &page) {
            return page.contains(QStringLiteral("6  Assumptions")) || page.contains(QStringLiteral("6 Assumptions"));
        };
        QVERIFY(appendix->trimmed().startsWith(QStringLiteral("Appendix A")) ||
                appendix->trimmed().startsWith(QStringLiteral("•")) || assumptions(appendix->trimmed().left(20)));
        QVERIFY(appendix->contains(QStringLiteral("[3] O. Kienzle")));
        QVERIFY(assumptions(*appendix) || assumptions(*(appendix - 1)));
        // The material's and the chuck's sources, for a machine that was not measured ("stiffness" is
        // set with a ligature in the PDF's text).
        const QString dataSources = text.mid(text.indexOf(QStringLiteral("Appendix B")));
        QVERIFY(dataSources.contains(QStringLiteral("Material data (C45E-N): ISCAR")));
        QVERIFY2(dataSources.contains(QStringLiteral("range: 'Modular Design for Machine Tools'")),
                 qPrintable(dataSources));
        QVERIFY(!text.contains(QStringLiteral("tool.overhang_mm"))); // no internal keys
        QVERIFY(text.contains(QStringLiteral("C45E-N")));
        // The finishing feed below the insert's published range is said in the inputs, in words, and the
        // eight roughing passes below its speed range once.
        QVERIFY2(text.contains(QStringLiteral("Warning (pass 9): feed 0.1 mm/rev is outside the insert's")),
                 qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("Warning (passes 1–8): cutting speed 200 m/min is outside")));
        QVERIFY(!text.contains(QStringLiteral("passes[")));

        // The title block: part, drawing number and revision from the project, material, the planner,
        // the date and an approval field.
        const QString titleBlock = text.section(QLatin1Char('\f'), 0, 0).section(QStringLiteral("Verdicts"), 0, 0);
        for (const QString &field :
             {QStringLiteral("Drawing no."), QStringLiteral("TT-EX-001"), QStringLiteral("Revision"),
              QStringLiteral("Planner"), QStringLiteral("A. Planner"), QStringLiteral("Approved (name, date)"),
              QStringLiteral("C45E-N"), QDate::currentDate().toString(Qt::ISODate)})
            QVERIFY2(titleBlock.contains(field), qPrintable(field + QStringLiteral(" in ") + titleBlock));

        // The set-up sheet: every pass numbered from 1 with its speeds, power and time, and the programs'
        // checksums, which `gcode` prints too.
        QVERIFY(text.contains(QStringLiteral("n [rpm]")) && text.contains(QStringLiteral("Power [kW]")));
        QVERIFY(text.contains(QRegularExpression(QStringLiteral("^9\\s+\\S+nishing") /* "fi" may be a ligature */,
                                                 QRegularExpression::MultilineOption)));
        QTemporaryDir gdir;
        const Run gcode = runCli({QStringLiteral("gcode"), QStringLiteral("-o"), gdir.filePath(QStringLiteral("p.nc")),
                                  example("stepped-shaft-chuck.tolturn")});
        const QString checksum =
            QRegularExpression(QStringLiteral("checksum ([0-9a-f]{16})")).match(gcode.err).captured(1);
        QCOMPARE(checksum.size(), 16);
        QVERIFY2(text.contains(QStringLiteral("nominal program ") + checksum), qPrintable(checksum));
        QVERIFY(text.contains(QStringLiteral("Radial deviation of the outer contour")));
        // The feed schedule (docs/adaptive.md §5): every feature bounded by Ra 1.6 µm at
        // √(32 · 0.8 mm · 1.6 µm) = 0.202 mm/rev; the finishing pass saves time against 0.1 mm/rev.
        QVERIFY(text.contains(QRegularExpression(QStringLiteral("^\\s*O4\\s+0\\.202\\s+roughness \\(Ra\\)"),
                                                 QRegularExpression::MultilineOption)));
        QVERIFY(text.contains(QRegularExpression(QStringLiteral("s scheduled \\(-\\d+\\.\\d\\s+%\\)"))));
        QVERIFY(text.contains(QStringLiteral("Cutting window of the"))); // "fi" comes back as a ligature

        // Page 1: what the machine rests on, and the verdicts over its stiffness range.
        const QString firstPage = text.section(QLatin1Char('\f'), 0, 0);
        QVERIFY(firstPage.contains(QStringLiteral("Machine: chuck not measured")));
        QVERIFY(firstPage.contains(QStringLiteral("66–216 N/µm")));
        // T4, Ø40 g6 on O6, passes with the chuck stiffness it needs; T1, Ø50 h6 on the seat O4 at the
        // jaws, is not finished where the tool keeps 2 mm + r_e 0.8 mm from the jaw face at z 35: the
        // program leaves z 35.000–37.750 mm of O4 (sampled every 0.05 mm), and says so in the row.
        const QString firstT4 = tableRow(firstPage, QStringLiteral("T4")).join(QLatin1Char('|'));
        QVERIFY2(firstT4.contains(QStringLiteral("passes as programmed")) &&
                     firstT4.contains(QStringLiteral("chuck ≥")),
                 qPrintable(firstT4));
        QVERIFY(firstPage.contains(QStringLiteral("passes on any machine in the"))); // the cell wraps
        const QString firstT1 = tableRow(firstPage, QStringLiteral("T1")).join(QLatin1Char('|'));
        QVERIFY2(firstT1.contains(QStringLiteral("cannot be evaluated")), qPrintable(firstT1));
        QVERIFY(firstPage.contains(QStringLiteral("35.000–37.750 mm of O4")));
        // The tolerance section: T1 is h6 on the Ø50 bearing seat: ISO 286-2 Table 1 gives IT6 = 16 µm
        // for 30 < D ≤ 50.
        const QString tolerances = text.section(QStringLiteral("4 Tolerances"), 1);
        const QStringList t1 = tableRow(tolerances, QStringLiteral("T1"));
        QVERIFY2(t1.size() >= 8, qPrintable(t1.join(QLatin1Char('|'))));
        QCOMPARE(t1.at(3), QStringLiteral("h6"));
        QCOMPARE(t1.at(5), QStringLiteral("16.0")); // micrometres to 0.1 µm
        // Below the table, the condition in words: h6 on Ø50 is 49.984–50.000 mm (es = 0, ei = -16 µm).
        QVERIFY(tolerances.contains(QStringLiteral("T1: size within 49.984–50.000 mm")));
        // Programmed at the zone's middle, 49.992 mm, plus twice the seat's radial deviation of
        // 1.1-1.2 µm (section 3's curve): both ends of the predicted size read 49.994, said once.
        QVERIFY2(tolerances.contains(QStringLiteral("T1: size within 49.984–50.000 mm; predicted 49.994 mm")),
                 qPrintable(tolerances.left(3000)));
        QVERIFY(!tolerances.contains(QStringLiteral("D'_Md")));
        QVERIFY2(t1.at(7).startsWith(QStringLiteral("cannot be evaluated")), qPrintable(t1.join(QLatin1Char('|'))));
        QVERIFY(tableRow(tolerances, QStringLiteral("T4")).at(7).startsWith(QStringLiteral("passes")));
        // T5 perpendicularity 15 µm to datum A: the limit is the tolerance value itself.
        const QStringList t5 = tableRow(tolerances, QStringLiteral("T5"));
        QVERIFY2(t5.size() >= 6, qPrintable(t5.join(QLatin1Char('|'))));
        QCOMPARE(t5.at(5), QStringLiteral("15.0"));
    }

    // A mill-turn project: a complete flat (001's case 1) and one as a STEP import leaves it, with no
    // tool. The section lists both, evaluates the first as the model does and names what the second
    // lacks; section 6 pushes the assumptions to 7, and the model's paper joins the literature.
    void reportOfMilledFeatures()
    {
        using namespace tolturn;
        ProjectParseResult read = readProjectFile(example("stepped-shaft-chuck.tolturn"));
        QVERIFY(read.project);
        Project project = *read.project;
        const MilledFeature complete = completeFlat();
        MilledFeature imported;
        imported.id = QStringLiteral("M2");
        imported.kind = MilledFeatureKind::Flat;
        imported.description = QStringLiteral("faces 12, 13 of shaft.step");
        imported.zFrom_mm = 60.0;
        imported.zTo_mm = 80.0;
        project.milledFeatures = {complete, imported};
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("mill-turn.tolturn"));
        QVERIFY(tolturn::test::writeFile(file, serializeProjectJson(project)));
        const QString pdf = dir.filePath(QStringLiteral("mill-turn.pdf"));
        const Run r = runCli({QStringLiteral("report"), QStringLiteral("-o"), pdf, file});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));

        const QString text = pdfText(pdf);
        for (const char *section : {"6 Milled features", "7 Assumptions"}) {
            const QString pattern =
                QStringLiteral("^\\f?%1$")
                    .arg(QString::fromUtf8(section).replace(QLatin1Char(' '), QStringLiteral("\\s+")));
            QVERIFY2(text.contains(QRegularExpression(pattern, QRegularExpression::MultilineOption)), section);
        }
        const QString milled =
            text.section(QStringLiteral("Milled features"), 1).section(QStringLiteral("Assumptions"), 0, 0);
        QVERIFY(!tableRow(milled, QStringLiteral("M1")).isEmpty());
        QVERIFY(!tableRow(milled, QStringLiteral("M2")).isEmpty());
        QVERIFY2(milled.contains(QStringLiteral("not evaluated")), qPrintable(milled));
        QVERIFY(milled.contains(QStringLiteral("ball-end"))); // what M2 lacks, wrapped in its cell
        // M1's form error to the 0.1 µm shown and its verdict with the margin, as the model gives them.
        const MilledFeatureEvaluation e = evaluateMilledFeature(complete);
        QVERIFY(e.evaluated());
        const QString formError = QString::number(1000.0 * e.formError_mm, 'f', 1);
        QVERIFY2(
            milled.contains(QRegularExpression(QStringLiteral("\\s%1\\s").arg(QRegularExpression::escape(formError)))),
            qPrintable(formError + QStringLiteral(" in ") + milled));
        const QString verdict = e.passes ? QStringLiteral("passes by %1 µm").arg(1000.0 * e.margin_mm, 0, 'f', 1)
                                         : QStringLiteral("fails by %1 µm").arg(-1000.0 * e.margin_mm, 0, 'f', 1);
        QVERIFY2(milled.contains(verdict), qPrintable(verdict + QStringLiteral(" in ") + milled));
        // What the verdict rests on, and the plot of M1 only.
        QVERIFY(milled.contains(QStringLiteral("M1: E of the tool not given: carbide's 630 000 N/mm² (MakeItFrom)")));
        QVERIFY(milled.contains(QStringLiteral("cients: test values"))); // "ffi" may be a ligature
        QVERIFY(milled.contains(QStringLiteral("M1: surface-normal error along the path (")));
        QVERIFY(!milled.contains(QStringLiteral("M2: surface-normal error")));
        const QString literature = text.section(QStringLiteral("Appendix A"), 1);
        QVERIFY2(literature.contains(QStringLiteral("[9] E. Öztürk, E. Budak")), qPrintable(literature));
    }

    // A plan without roughing (the H7 bushing: 1 mm of radial stock, (64 - 62)/2, within the
    // insert's 0.5-2 mm depth of cut: the finishing pass takes it) says so, not "0 roughing passes".
    void planWithoutRoughingSaysSo()
    {
        QTemporaryDir dir;
        const QString pdf = dir.filePath(QStringLiteral("bushing.pdf"));
        const Run r = runCli({QStringLiteral("report"), QStringLiteral("-o"), pdf, example("bushing-bore-h7.tolturn")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString plan = pdfText(pdf).simplified().section(QStringLiteral("5 Plan"), 1);
        // ("fi" may come back from the PDF as a ligature.)
        QVERIFY2(plan.contains(QStringLiteral("no roughing: the")) &&
                     plan.contains(QStringLiteral("takes the whole stock")),
                 qPrintable(plan));
        QVERIFY(!plan.contains(QStringLiteral("0 roughing passes")));
        // The speed, 353.6 m/min at the top of the range, is on the whole m/min below it: nothing to say.
        QVERIFY2(!plan.contains(QStringLiteral("holds no value on the step")), qPrintable(plan));
    }

    // A plan that cannot meet every constraint says in the report what it would take (the valve
    // body's OP 10: Ra 1.6 µm with the bar's r 0.4 mm needs f <= sqrt(32 * 0.4 * 0.0016) = 0.143
    // mm/rev, below the range's 0.17), and the plan's own notes are there: a limit the machine data
    // do not give is named, not left out. The model's assumptions stay once, under Assumptions.
    void infeasiblePlanSaysWhatItWouldTake()
    {
        QTemporaryDir dir;
        const QString pdf = dir.filePath(QStringLiteral("valve.pdf"));
        const Run r =
            runCli({QStringLiteral("report"), QStringLiteral("-o"), pdf, example("valve-body-two-bores.tolturn")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString plan = pdfText(pdf).simplified().section(QStringLiteral("5 Plan"), 1);
        QVERIFY2(plan.contains(QStringLiteral("No plan meets every constraint")), qPrintable(plan));
        QVERIFY2(plan.contains(QStringLiteral("To meet it: Ra ≤ 1.6 µm needs a feed of at most 0.143 mm/rev")),
                 qPrintable(plan));
        QVERIFY2(plan.contains(QStringLiteral("No spindle power limit known")), qPrintable(plan));
        QVERIFY2(plan.contains(QStringLiteral("; 1 roughing pass at vc")), qPrintable(plan)); // one, not "passes"
        // Each tool's roughness under its own name, at the finishing feed 0.17 mm/rev: Ra = f²/(32 r),
        // Rz = f²/(8 r): CNMG 120408 (r 0.8) 1.13 and 4.52 µm, the bar's CCMT 09T304 (r 0.4) 2.26 and 9.03.
        const QString text = pdfText(pdf).simplified();
        QVERIFY2(text.contains(QStringLiteral("turning insert (nose radius 0.80 mm)")) &&
                     text.contains(QStringLiteral("theoretical Ra 1.13 µm, Rz 4.52 µm")),
                 qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("(nose radius 0.40 mm), same pass")) &&
                     text.contains(QStringLiteral("theoretical Ra 2.26 µm, Rz 9.03 µm")),
                 qPrintable(text));
        const QString beforeAssumptions = plan.section(QStringLiteral("Assumptions"), 0, 0);
        QVERIFY2(!beforeAssumptions.contains(QStringLiteral("Thermal drift not characterised")), qPrintable(plan));
    }

    // "-o -": the PDF on standard output (a pipe to a printer or a viewer), the page count on
    // standard error.
    void reportOnStandardOutput()
    {
        QProcess cli;
        cli.start(QStringLiteral(TOLTURN_CLI_PATH), {QStringLiteral("report"), QStringLiteral("-o"),
                                                     QStringLiteral("-"), example("stepped-shaft-chuck.tolturn")});
        QVERIFY(cli.waitForFinished(60000));
        QCOMPARE(cli.exitCode(), 0);
        const QByteArray pdf = cli.readAllStandardOutput();
        QVERIFY(pdf.startsWith("%PDF-"));
        QVERIFY(pdf.trimmed().endsWith("%%EOF"));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("piped.pdf"));
        QVERIFY(tolturn::test::writeFile(path, pdf));
        QVERIFY(pdfText(path).contains(QStringLiteral("Stepped shaft")));
        // The count said is the count of the PDF's pages (pdfinfo's).
        const Run info = runProgram(QStringLiteral("pdfinfo"), {path});
        const int pages = QRegularExpression(QStringLiteral("Pages:\\s+(\\d+)")).match(info.out).captured(1).toInt();
        QVERIFY(pages > 0);
        QVERIFY(QString::fromUtf8(cli.readAllStandardError()).contains(QStringLiteral("-: %1 pages").arg(pages)));
    }

    // Long names fit the report: set smaller or shortened, never cut through or run over. Every word
    // of the title, the Part field and the project line (by its box from pdftotext -bbox) lies inside
    // the box it is drawn in, worked out from the layout in points: the title block starts at the
    // 48 pt margin; the title is inset 10 pt left and right and 6 pt from the top, above the row of
    // fields 30 pt below the block's top; the Part field's text is inset 3 pt in a cell 17 % of the
    // 499 pt text width, 12 pt below the cell's top and 2 pt above its bottom 40 pt down; the project
    // line is inset 10 pt, 72 pt below the block's top, and keeps its dimensions at its end. In the
    // footer the name stops before the page count. A name too long for the smallest size ends in an
    // ellipsis.
    void longNamesFitTheReport_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("fileName");
        QTest::addColumn<bool>("shortened");
        QTest::newRow("three lines at 9 px")
            << QStringLiteral("Valve body bored from both ends") << QStringLiteral("valve.tolturn") << false;
        QTest::newRow("too long for any size")
            << QStringLiteral("Hydraulic cylinder piston rod with two ground bearing seats, a thread relief "
                              "groove and a cross hole for the locking pin, second revision")
            << QStringLiteral("hydraulic-cylinder-piston-rod-with-two-ground-bearing-seats-thread-relief-groove-"
                              "and-cross-hole-for-the-locking-pin-second-revision.tolturn")
            << true;
    }

    void longNamesFitTheReport()
    {
        QFETCH(QString, name);
        QFETCH(QString, fileName);
        QFETCH(bool, shortened);
        tolturn::ProjectParseResult read = tolturn::readProjectFile(example("valve-body-two-bores.tolturn"));
        QVERIFY(read.project);
        tolturn::Project project = *read.project;
        project.part.name = name;
        QTemporaryDir dir;
        const QString file = dir.filePath(fileName);
        QVERIFY(tolturn::test::writeFile(file, tolturn::serializeProjectJson(project)));
        const QString pdf = dir.filePath(QStringLiteral("r.pdf"));
        const Run r = runCli({QStringLiteral("report"), QStringLiteral("-o"), pdf, file});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const std::vector<std::vector<Word>> pages = pageWords(pdf);
        QVERIFY(!pages.empty());
        const std::vector<Word> &page = pages.front();

        struct Box {
            double left, top, right, bottom;
        };

        // The words whose top left corner is in `b` (pdftotext's glyph boxes may start a fraction of a
        // point above the line Qt set them on), each checked to end inside it.
        const auto wordsIn = [&](const Box &b) {
            QStringList words;
            for (const Word &w : page) {
                if (w.left < b.left - 1.0 || w.left > b.right || w.top < b.top - 1.0 || w.top > b.bottom)
                    continue;
                if (w.right > b.right + 0.5 || w.bottom > b.bottom + 0.5)
                    return QStringList{
                        QStringLiteral("'%1' overflows to (%2, %3)").arg(w.text).arg(w.right).arg(w.bottom)};
                words << w.text;
            }
            return words;
        };
        const double top = 48.0;
        const Box title{48.0 + 10.0, top + 6.0, 48.0 + 499.0 - 10.0, top + 30.0};
        const Box partValue{48.0 + 3.0, top + 30.0 + 12.0, 48.0 + 0.17 * 499.0 - 3.0, top + 30.0 + 40.0 - 2.0};
        const Box projectLine{48.0 + 10.0, top + 72.0, 48.0 + 499.0 - 10.0, top + 92.0 - 2.0};
        const QString titleText = wordsIn(title).join(QLatin1Char(' '));
        const QString cellText = wordsIn(partValue).join(QLatin1Char(' '));
        const QStringList projectWords = wordsIn(projectLine);
        QVERIFY2(projectWords.size() > 5 && projectWords.constLast() == QStringLiteral("mm") &&
                     projectWords.at(projectWords.size() - 3) == QStringLiteral("stock"),
                 qPrintable(projectWords.join(QLatin1Char(' '))));

        // The footer, in the bottom margin: the name's words end before the page count begins.
        constexpr double kFooterTop = 842.0 - 48.0;
        QStringList footer;
        double pageCountStart = 0.0;
        double nameEnd = 0.0;
        for (const Word &w : page) {
            if (w.top < kFooterTop - 1.0)
                continue;
            if (w.text == QStringLiteral("page"))
                pageCountStart = w.left;
            else if (pageCountStart == 0.0) {
                footer << w.text;
                nameEnd = std::max(nameEnd, w.right);
            }
        }
        QVERIFY2(pageCountStart > 0.0 && nameEnd < pageCountStart - 1.0,
                 qPrintable(QStringLiteral("%1 ends at %2, page count at %3")
                                .arg(footer.join(QLatin1Char(' ')))
                                .arg(nameEnd)
                                .arg(pageCountStart)));

        const QString expectedTitle = QStringLiteral("Tolerance report: ") + name;
        if (!shortened) {
            QCOMPARE(titleText, expectedTitle);
            QCOMPARE(cellText, name);
            QVERIFY2(projectWords.contains(fileName), qPrintable(projectWords.join(QLatin1Char(' '))));
            QVERIFY2(footer.join(QLatin1Char(' ')).endsWith(name), qPrintable(footer.join(QLatin1Char(' '))));
            return;
        }
        for (const QString &shown : {titleText, cellText, footer.join(QLatin1Char(' '))}) {
            QVERIFY2(shown.endsWith(QChar(0x2026)), qPrintable(shown));
            QVERIFY2(shown.size() > 10, qPrintable(shown));
        }
        QVERIFY2(expectedTitle.startsWith(titleText.chopped(1).trimmed()), qPrintable(titleText));
        QVERIFY2(name.startsWith(cellText.chopped(1).trimmed()), qPrintable(cellText));
        // The file name keeps its start and its extension, shortened in the middle.
        QVERIFY2(projectWords.at(1).startsWith(QStringLiteral("hydraulic-")) &&
                     projectWords.at(1).endsWith(QStringLiteral(".tolturn")) &&
                     projectWords.at(1).contains(QChar(0x2026)),
                 qPrintable(projectWords.join(QLatin1Char(' '))));
    }

    // No page holds only a few lines: on every page but the last, the content (words, by their
    // boxes from pdftotext -bbox, the footer left out) reaches below the middle of the page.
    void pagesAreFilled()
    {
        for (const char *name :
             {"stepped-shaft-chuck.tolturn", "hollow-sleeve-tailstock.tolturn", "long-shaft-centres.tolturn",
              "slender-pin-chuck.tolturn", "thin-pin-compensation.tolturn"}) {
            QTemporaryDir dir;
            const QString pdf = dir.filePath(QStringLiteral("r.pdf"));
            QCOMPARE(runCli({QStringLiteral("report"), QStringLiteral("-o"), pdf, example(name)}).exitCode, 0);
            const std::vector<std::vector<Word>> pages = pageWords(pdf);
            constexpr double kPageHeight = 842.0;             // A4 in points
            constexpr double kFooterTop = kPageHeight - 48.0; // the footer sits in the bottom margin
            for (std::size_t i = 0; i + 1 < pages.size(); ++i) {
                double bottom = 0.0;
                for (const Word &w : pages[i])
                    if (w.bottom < kFooterTop)
                        bottom = std::max(bottom, w.bottom);
                QVERIFY2(
                    bottom > kPageHeight / 2.0,
                    qPrintable(
                        QStringLiteral("%1: page %2 ends at %3 pt").arg(QLatin1String(name)).arg(i + 1).arg(bottom)));
            }
        }
    }

    void badProjectWritesNothing()
    {
        QTemporaryDir dir;
        const QString project = dir.filePath(QStringLiteral("bad.tolturn"));
        QVERIFY(tolturn::test::writeFile(project, "{\"format\": \"tolturn-project\", \"version\": 1, \"part\": 7}"));
        const QString pdf = dir.filePath(QStringLiteral("bad.pdf"));
        const Run r = runCli({QStringLiteral("report"), QStringLiteral("-o"), pdf, project});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("part")), qPrintable(r.err));
        QVERIFY(!QFile::exists(pdf));
    }

    void unwritableTargetNamesThePath()
    {
        const QString pdf = QStringLiteral("/nonexistent-directory/report.pdf");
        const Run r =
            runCli({QStringLiteral("report"), QStringLiteral("-o"), pdf, example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(pdf), qPrintable(r.err));
    }

    void missingOutputIsUsageError()
    {
        const Run r = runCli({QStringLiteral("report"), example("stepped-shaft-chuck.tolturn")});
        QCOMPARE(r.exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TestReport)
#include "tst_report.moc"
