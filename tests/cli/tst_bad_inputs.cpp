// SPDX-License-Identifier: GPL-3.0-or-later
// The catalogue of bad inputs (issue 14): each case runs tolturn-cli as a user would, on a file
// made bad in one way, and checks the exit code, the named error (field and value, or file and
// line) and that no file on disk changed, appeared or was left behind.
#include "tests/cli/cli_runner.h"

#include <QCryptographicHash>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QTemporaryDir>
#include <QTest>

using namespace tolturn::test;

namespace {

// Every file under `dir` (hidden ones too) with the hash of its content.
QMap<QString, QByteArray> snapshot(const QString &dir)
{
    QMap<QString, QByteArray> files;
    QDirIterator it(dir, QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        QFile f(path);
        if (f.open(QIODevice::ReadOnly))
            files.insert(path, QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256));
    }
    return files;
}

QJsonObject shaft()
{
    QFile f(example("stepped-shaft-chuck.tolturn"));
    if (!f.open(QIODevice::ReadOnly))
        qFatal("cannot read the example");
    return QJsonDocument::fromJson(f.readAll()).object();
}

// The stepped shaft with the value at `path` ("passes[8].feed_mm_rev") replaced.
QByteArray shaftWith(const QString &path, const QJsonValue &value)
{
    const QStringList keys = path.split(QLatin1Char('.'));
    std::function<QJsonValue(const QJsonValue &, int)> set = [&](const QJsonValue &node, int k) -> QJsonValue {
        QString key = keys[k];
        int index = -1;
        if (const qsizetype open = key.indexOf(QLatin1Char('[')); open >= 0) {
            index = key.mid(open + 1, key.size() - open - 2).toInt();
            key.truncate(open);
        }
        QJsonObject object = node.toObject();
        const bool last = k + 1 == keys.size();
        if (index < 0) {
            object[key] = last ? value : set(object.value(key), k + 1);
        } else {
            QJsonArray array = object.value(key).toArray();
            array[index] = last ? value : set(array.at(index), k + 1);
            object[key] = array;
        }
        return object;
    };
    return QJsonDocument(set(shaft(), 0).toObject()).toJson();
}

QByteArray stepOfThePin()
{
    QFile f(QStringLiteral(TOLTURN_SOURCE_DIR "/fuzz/corpus/cad/slender-pin.step"));
    if (!f.open(QIODevice::ReadOnly))
        qFatal("cannot read the STEP seed");
    return f.readAll();
}

QByteArray replacedFirst(QByteArray text, const QByteArray &what, const QByteArray &with)
{
    const qsizetype at = text.indexOf(what);
    if (at < 0)
        qFatal("'%s' not found", what.constData());
    return text.replace(at, what.size(), with);
}

// The pin with its first oriented edge reached through `depth` oriented edges in a row: a model
// without a cycle, nested deeper than the import accepts (core/cad/model_references.h).
QByteArray pinWithNestedEdges(int depth)
{
    QByteArray text = replacedFirst(stepOfThePin(), "#57 = ORIENTED_EDGE('',*,*,#21,.T.);",
                                    "#57 = ORIENTED_EDGE('',*,*,#100001,.T.);");
    QByteArray chain;
    for (int i = 1; i <= depth; ++i)
        chain += "#" + QByteArray::number(100000 + i) + " = ORIENTED_EDGE('',*,*,#" +
                 (i < depth ? QByteArray::number(100001 + i) : QByteArray("21")) + ",.T.);\n";
    const qsizetype end = text.lastIndexOf("ENDSEC;"); // of the DATA section
    return text.insert(end, chain);
}

QByteArray withoutLineContaining(const QByteArray &text, const QByteArray &what)
{
    QList<QByteArray> lines = text.split('\n');
    for (qsizetype i = 0; i < lines.size(); ++i) {
        if (lines[i].contains(what)) {
            lines.removeAt(i);
            break;
        }
    }
    return lines.join('\n');
}

} // namespace

class TestBadInputs : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void catalogue_data()
    {
        QTest::addColumn<QByteArray>("content"); // written to the file named IN
        QTest::addColumn<QString>("fileName");
        QTest::addColumn<QStringList>("args"); // "IN" is the file, "DIR" the folder
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("message"); // in standard error
        const QStringList check{QStringLiteral("check"), QStringLiteral("IN")};
        const QString p = QStringLiteral("p.tolturn");
        const auto row = [&](const char *name, const QByteArray &content, const QStringList &args, int code,
                             const QString &message, const QString &fileName = QStringLiteral("p.tolturn")) {
            QTest::newRow(name) << content << fileName << args << code << message;
        };
        // Files that are not projects.
        row("empty file", QByteArray(), check, 1, QStringLiteral("invalid JSON at line 1"));
        row("not JSON", "turned shaft\n", check, 1, QStringLiteral("invalid JSON at line 1"));
        row("a list", "[1, 2]", check, 1, QStringLiteral("one JSON object, not a list"));
        row("another format", R"({"format": "cad-part", "version": 1})", check, 1,
            QStringLiteral("this is not a TolTurn project: format is \"cad-part\""));
        row("a newer version", R"({"format": "tolturn-project", "version": 7})", check, 1,
            QStringLiteral("unknown format version 7"));
        row("UTF-16", QByteArray("\xff\xfe{\0}\0", 6), check, 1, QStringLiteral("invalid JSON"));
        // Values out of their range, by type, or beyond the input bounds.
        row("negative feed", shaftWith(QStringLiteral("passes[8].feed_mm_rev"), -0.1), check, 1,
            QStringLiteral("passes[8].feed_mm_rev: must be above zero, but is -0.1"));
        // Below the program's resolution (G96 S in whole m/min, F in thousandths): it would write F0.000, S0.
        row("feed the program writes as zero", shaftWith(QStringLiteral("passes[8].feed_mm_rev"), 0.0004), check, 1,
            QStringLiteral("passes[8].feed_mm_rev: 0.0004 is below 0.001, the least the program can state"));
        row("speed the program writes as zero", shaftWith(QStringLiteral("passes[0].cutting_speed_m_min"), 0.4),
            {QStringLiteral("gcode"), QStringLiteral("-o"), QStringLiteral("DIR/p.nc"), QStringLiteral("IN")}, 1,
            QStringLiteral("passes[0].cutting_speed_m_min: 0.4 is below 1"));
        // What `check` calls an error stops the other commands too: no report of it is written.
        row("report of an unknown material", shaftWith(QStringLiteral("material"), QStringLiteral("Unobtainium")),
            {QStringLiteral("report"), QStringLiteral("-o"), QStringLiteral("DIR/r.pdf"), QStringLiteral("IN")}, 1,
            QStringLiteral("material: unknown material \"Unobtainium\""));
        row("G-code with an unknown boring bar",
            shaftWith(QStringLiteral("boring_tool"),
                      QJsonObject{{QStringLiteral("holder"), QStringLiteral("XYZ 99")},
                                  {QStringLiteral("insert"), QStringLiteral("CCMT 09T304")}}),
            {QStringLiteral("gcode"), QStringLiteral("-o"), QStringLiteral("DIR/p.nc"), QStringLiteral("IN")}, 1,
            QStringLiteral("boring_tool.holder: \"XYZ 99\" is not a boring bar"));
        // A thermal drift of 10 mm per 1000 rpm: the correction (about 28 mm) is far more than the
        // finishing depth of 0.5 mm, and would program diameters below zero.
        QJsonObject drift;
        drift.insert(QStringLiteral("source"), QStringLiteral("a test"));
        drift.insert(QStringLiteral("thermal"), QJsonObject{{QStringLiteral("drift_um_per_1000rpm"), 10000.0},
                                                            {QStringLiteral("time_constant_min"), 10.0}});
        row("a correction deeper than the cut", shaftWith(QStringLiteral("characterisation"), drift),
            {QStringLiteral("gcode"), QStringLiteral("--compensated"), QStringLiteral("-o"), QStringLiteral("DIR/p.nc"),
             QStringLiteral("IN")},
            1, QStringLiteral("is larger than the finishing depth of cut 0.5 mm"));
        row("feed as text", shaftWith(QStringLiteral("passes[8].feed_mm_rev"), QStringLiteral("0.1")), check, 1,
            QStringLiteral("passes[8].feed_mm_rev"));
        row("depth 1e300", shaftWith(QStringLiteral("passes[0].depth_of_cut_mm"), 1e300), check, 1,
            QStringLiteral("passes[0].depth_of_cut_mm: 1e+300 is beyond what TolTurn computes with: at most 50 mm"));
        row("speed 1e9", shaftWith(QStringLiteral("passes[0].cutting_speed_m_min"), 1e9), check, 1,
            QStringLiteral("passes[0].cutting_speed_m_min: 1000000000 is beyond"));
        row("friction 1e308",
            shaftWith(QStringLiteral("cutting_model"),
                      QJsonObject{{QStringLiteral("force_model"), QStringLiteral("li_du")},
                                  {QStringLiteral("normal_pressure_MPa"), 2000},
                                  {QStringLiteral("friction_ratio"), 1e308}}),
            check, 1, QStringLiteral("cutting_model.friction_ratio: 1e+308 is beyond"));
        row("negative friction",
            shaftWith(QStringLiteral("cutting_model"),
                      QJsonObject{{QStringLiteral("force_model"), QStringLiteral("li_du")},
                                  {QStringLiteral("normal_pressure_MPa"), 2000},
                                  {QStringLiteral("friction_ratio"), -0.4}}),
            check, 1, QStringLiteral("cutting_model.friction_ratio: must be zero or more, but is -0.4"));
        row("stock 100 m", shaftWith(QStringLiteral("part.stock_diameter_mm"), 1e5), check, 1,
            QStringLiteral("part.stock_diameter_mm: 100000 is beyond"));
        row("stock thinner than the part", shaftWith(QStringLiteral("part.stock_diameter_mm"), 50), check, 1,
            QStringLiteral("part.stock_diameter_mm"));
        row("corner off the axis", shaftWith(QStringLiteral("part.outer[0].from.r_mm"), 5), check, 1,
            QStringLiteral("part.outer[0].from"));
        row("corner as null", shaftWith(QStringLiteral("part.outer[3].to.z_mm"), QJsonValue()), check, 1,
            QStringLiteral("part.outer[3].to.z_mm"));
        row("contour not a list", shaftWith(QStringLiteral("part.outer"), 5), check, 1, QStringLiteral("part.outer"));
        row("unknown material", shaftWith(QStringLiteral("material"), QStringLiteral("unobtainium")), check, 1,
            QStringLiteral("unobtainium"));
        row("unknown machine", shaftWith(QStringLiteral("machine"), QStringLiteral("lathe-9000")), check, 1,
            QStringLiteral("lathe-9000"));
        row("bad insert code", shaftWith(QStringLiteral("tool.insert"), QStringLiteral("XYZ")), check, 1,
            QStringLiteral("tool.insert"));
        row("clamped longer than the part", shaftWith(QStringLiteral("clamping.clamped_length_mm"), 200), check, 1,
            QStringLiteral("clamping.clamped_length_mm: the clamped length 200 mm leaves nothing to turn"));
        row("unknown clamping", shaftWith(QStringLiteral("clamping.method"), QStringLiteral("vice")), check, 1,
            QStringLiteral("clamping.method"));
        row("malformed ISO 286 class", shaftWith(QStringLiteral("tolerances[0].iso286"), QStringLiteral("h66")), check,
            1, QStringLiteral("'h66' is not an ISO 286 tolerance class"));
        row("zero zone", shaftWith(QStringLiteral("tolerances[1].value_um"), 0), check, 1,
            QStringLiteral("tolerances[1].value_um"));
        row("tolerance on no feature", shaftWith(QStringLiteral("tolerances[1].feature"), QStringLiteral("O99")), check,
            1, QStringLiteral("O99"));
        row("datum in lower case", shaftWith(QStringLiteral("datums[0].label"), QStringLiteral("a")), check, 1,
            QStringLiteral("datums[0].label"));
        row("Taylor exponent 1.5",
            shaftWith(QStringLiteral("planning.tool_life"),
                      QJsonObject{{QStringLiteral("C_m_min"), 300},
                                  {QStringLiteral("n"), 1.5},
                                  {QStringLiteral("source"), QStringLiteral("test")}}),
            check, 1, QStringLiteral("planning.tool_life.n"));
        row("range upside down", shaftWith(QStringLiteral("planning.ranges.feed_mm_rev.max"), 0.1), check, 1,
            QStringLiteral("planning.ranges.feed_mm_rev.max: must be at least the minimum 0.17, but is 0.1"));
        row("ambient below absolute zero",
            shaftWith(QStringLiteral("environment"), QJsonObject{{QStringLiteral("ambient_temperature_C"), -300}}),
            check, 1, QStringLiteral("environment.ambient_temperature_C"));
        row("too many segments",
            shaftWith(QStringLiteral("part.outer"), QJsonArray::fromVariantList(QVariantList(1001, QVariantMap{}))),
            check, 1, QStringLiteral("part.outer: holds 1001 entries, more than the 1000"));
        // A warning, not an error: passes deeper than the stock (the bar Ø60 made Ø56.2: 14.1 mm
        // down to the Ø28 chamfer, against 8 x 1.9375 + 0.5 = 16 mm of passes).
        row("passes deeper than the stock", shaftWith(QStringLiteral("part.stock_diameter_mm"), 56.2), check, 0,
            QStringLiteral("the passes cut 16 mm deep in all, but the stock is at most 14.1 mm thick on the radius"));
        // Files that are not there or not files.
        row("missing project", QByteArray("-"), {QStringLiteral("check"), QStringLiteral("DIR/none.tolturn")}, 1,
            QStringLiteral("does not exist"));
        row("a folder", QByteArray("-"), {QStringLiteral("check"), QStringLiteral("DIR")}, 1,
            QStringLiteral("is a folder, not a project file"));
        // Command lines.
        const QString shaftPath = example("stepped-shaft-chuck.tolturn");
        row("load beyond 1e6 N", QByteArray("-"),
            {QStringLiteral("deflect"), QStringLiteral("--load"), QStringLiteral("1e308,0,0"), shaftPath}, 2,
            QStringLiteral("--load takes three numbers in newtons"));
        row("load not numbers", QByteArray("-"),
            {QStringLiteral("deflect"), QStringLiteral("--load"), QStringLiteral("a,b,c"), shaftPath}, 2,
            QStringLiteral("not \"a,b,c\""));
        row("stations beyond the total", QByteArray("-"),
            {QStringLiteral("deflect"), QStringLiteral("--stations"), QStringLiteral("100000"), shaftPath}, 2,
            QStringLiteral("more than the 25000 computed at once; give at most 2272"));
        row("stations 1", QByteArray("-"),
            {QStringLiteral("deflect"), QStringLiteral("--stations"), QStringLiteral("1"), shaftPath}, 2,
            QStringLiteral("--stations must be a whole number from 2"));
        row("unknown dialect", QByteArray("-"),
            {QStringLiteral("gcode"), QStringLiteral("--dialect"), QStringLiteral("heidenhain"), QStringLiteral("-o"),
             QStringLiteral("DIR/x.nc"), shaftPath},
            2, QStringLiteral("'heidenhain'"));
        row("unknown command", QByteArray("-"), {QStringLiteral("deflekt")}, 2, QStringLiteral("deflect"));
        row("bad ISO 286 class", QByteArray("-"),
            {QStringLiteral("iso286"), QStringLiteral("50"), QStringLiteral("Q7")}, 1, QStringLiteral("Q7"));
        row("size beyond ISO 286", QByteArray("-"),
            {QStringLiteral("iso286"), QStringLiteral("5000"), QStringLiteral("H7")}, 1, QStringLiteral("5000"));
        // Measurement files.
        row("force cell not a number", "feed_mm_rev,depth_of_cut_mm,tangential_N,axial_N\n0.2,one,800,300\n",
            {QStringLiteral("calibrate-forces"), shaftPath, QStringLiteral("IN")}, 1, QStringLiteral("cuts.csv:2"),
            QStringLiteral("cuts.csv"));
        row("force of 1e300 N",
            "feed_mm_rev,depth_of_cut_mm,tangential_N,axial_N\n0.15,1.0,1e300,160\n0.25,2.0,900,420\n",
            {QStringLiteral("calibrate-forces"), shaftPath, QStringLiteral("IN")}, 1,
            QStringLiteral("tangential_N must be at most 1e9 in size, not \"1e300\""), QStringLiteral("cuts.csv"));
        row("force file without rows", "feed_mm_rev,depth_of_cut_mm,tangential_N,axial_N\n",
            {QStringLiteral("calibrate-forces"), shaftPath, QStringLiteral("IN")}, 1, QStringLiteral("cuts.csv"),
            QStringLiteral("cuts.csv"));
        row("test bar without its column", "z_mm,deviation\n40,3\n60,4\n",
            {QStringLiteral("calibrate-stiffness"), QStringLiteral("--pivot"), QStringLiteral("300"), shaftPath,
             QStringLiteral("IN")},
            1, QStringLiteral("radial_um"), QStringLiteral("bar.csv"));
        // CAD files.
        const QStringList import{QStringLiteral("import"), QStringLiteral("-o"), QStringLiteral("DIR/out.tolturn"),
                                 QStringLiteral("IN")};
        row("not a STEP file", "solid pin\n", import, 1, QStringLiteral("is not a STEP file"),
            QStringLiteral("pin.step"));
        row("truncated STEP", stepOfThePin().left(2000), import, 1, QStringLiteral("is truncated"),
            QStringLiteral("pin.step"));
        row("STEP without an edge loop", withoutLineContaining(stepOfThePin(), "EDGE_LOOP"), import, 1,
            QStringLiteral("is not a consistent model: #"), QStringLiteral("pin.step"));
        row("STEP real 1.E400", replacedFirst(stepOfThePin(), "0.,0.,0.", "1.E400,0.,0."), import, 1,
            QStringLiteral("the number '1.E400' is beyond the largest real"), QStringLiteral("pin.step"));
        row("STEP oriented edge of itself",
            replacedFirst(stepOfThePin(), "#57 = ORIENTED_EDGE('',*,*,#21,.T.);",
                          "#57 = ORIENTED_EDGE('',*,*,#57,.T.);"),
            import, 1, QStringLiteral("could not be read: OpenCascade failed"), QStringLiteral("pin.step"));
        row("STEP nested 450 deep", pinWithNestedEdges(450), import, 1,
            QStringLiteral("nests its entities 401 deep at #"), QStringLiteral("pin.step"));
        row("STEP cycle of references",
            replacedFirst(stepOfThePin(), "#68 = DEFINITIONAL_REPRESENTATION('',(#69),#73);",
                          "#68 = DEFINITIONAL_REPRESENTATION('',(#62),#73);"),
            import, 1, QStringLiteral("#68 refers to #62, which leads back to #68 (a cycle of references)"),
            QStringLiteral("pin.step"));
        row("import into no folder", stepOfThePin(),
            {QStringLiteral("import"), QStringLiteral("-o"), QStringLiteral("DIR/none/out.tolturn"),
             QStringLiteral("IN")},
            1, QStringLiteral("none/out.tolturn"), QStringLiteral("pin.step"));
        // Outputs that cannot be written leave the project as it was.
        row("report into no folder", shaft().isEmpty() ? QByteArray() : QJsonDocument(shaft()).toJson(),
            {QStringLiteral("report"), QStringLiteral("-o"), QStringLiteral("DIR/none/r.pdf"), QStringLiteral("IN")}, 1,
            QStringLiteral("none/r.pdf"));
        row("write of an infeasible plan", shaftWith(QStringLiteral("planning.max_ra_um"), 0.05),
            {QStringLiteral("optimize"), QStringLiteral("--write"), QStringLiteral("IN")}, 1,
            QStringLiteral("roughness"));
        // An output that is the input (by another spelling of its path too) would destroy it.
        const QByteArray project = QJsonDocument(shaft()).toJson();
        const QString overInput = QStringLiteral("is the input file");
        row("G-code over its project", project,
            {QStringLiteral("gcode"), QStringLiteral("-o"), QStringLiteral("IN"), QStringLiteral("IN")}, 2, overInput);
        row("report over its project", project,
            {QStringLiteral("report"), QStringLiteral("-o"), QStringLiteral("DIR/./p.tolturn"), QStringLiteral("IN")},
            2, overInput);
        row("STEP over its project", project,
            {QStringLiteral("export-step"), QStringLiteral("-o"), QStringLiteral("IN"), QStringLiteral("IN")}, 2,
            overInput);
        row("project over its STEP file", "ISO-10303-21;\n",
            {QStringLiteral("import"), QStringLiteral("-o"), QStringLiteral("IN"), QStringLiteral("IN")}, 2, overInput,
            QStringLiteral("part.step"));
        const QString overStore = QStringLiteral("is the measurement store");
        row("CSV over its measurement store", "SQLite format 3",
            {QStringLiteral("measurements"), QStringLiteral("export"), QStringLiteral("1"), QStringLiteral("--store"),
             QStringLiteral("IN"), QStringLiteral("-o"), QStringLiteral("IN")},
            2, overStore, QStringLiteral("m.sqlite"));
        // With --learned the store is an input too: the program or report must not replace it.
        const QString example = QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/stepped-shaft-chuck.tolturn");
        row("G-code over its measurement store", "SQLite format 3",
            {QStringLiteral("gcode"), QStringLiteral("--learned"), QStringLiteral("--store"), QStringLiteral("IN"),
             QStringLiteral("-o"), QStringLiteral("DIR/./m.sqlite"), example},
            2, overStore, QStringLiteral("m.sqlite"));
        row("report over its measurement store", "SQLite format 3",
            {QStringLiteral("report"), QStringLiteral("--learned"), QStringLiteral("--store"), QStringLiteral("IN"),
             QStringLiteral("-o"), QStringLiteral("IN"), example},
            2, overStore, QStringLiteral("m.sqlite"));
        row("optimiser time limit of zero", QJsonDocument(shaft()).toJson(),
            {QStringLiteral("optimize"), QStringLiteral("--time-limit"), QStringLiteral("0"), QStringLiteral("IN")}, 2,
            QStringLiteral("--time-limit is from 0.01 to 3600 seconds, not \"0\""));
    }

    void catalogue()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, fileName);
        QFETCH(QStringList, args);
        QFETCH(int, exitCode);
        QFETCH(QString, message);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString in = dir.filePath(fileName);
        if (content != "-")
            QVERIFY(writeFile(in, content));
        for (QString &a : args) {
            a.replace(QStringLiteral("DIR"), dir.path());
            if (a == QLatin1String("IN"))
                a = in;
        }
        const QMap<QString, QByteArray> before = snapshot(dir.path());
        const Run r = runCli(args);
        QVERIFY2(r.exitCode == exitCode, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.err)));
        QVERIFY2(r.err.contains(message) || r.out.contains(message), qPrintable(r.err + r.out));
        QVERIFY2(!r.out.contains(QStringLiteral("null")), qPrintable(r.out)); // no JSON with holes
        QCOMPARE(snapshot(dir.path()), before); // nothing changed, appeared or was left behind
    }
};

QTEST_GUILESS_MAIN(TestBadInputs)
#include "tst_bad_inputs.moc"
