// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli import and export-step (issue 7) as a user runs them: the bundled examples written
// as STEP solids, imported back into projects that 'check' accepts, with the same contours.
#include "tests/cli/cli_runner.h"

#include "core/cad/step_export.h"
#include "core/io/project_file.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace tolturn;
using tolturn::test::example;
using tolturn::test::Run;
using tolturn::test::runCli;

namespace {

bool sameContour(const Contour &got, const Contour &want)
{
    const auto near = [](const ProfilePoint &a, const ProfilePoint &b) {
        return std::abs(a.z_mm - b.z_mm) <= 1e-3 && std::abs(a.r_mm - b.r_mm) <= 1e-3;
    };
    if (got.segments.size() != want.segments.size())
        return false;
    for (std::size_t i = 0; i < got.segments.size(); ++i) {
        const Segment &g = got.segments[i];
        const Segment &w = want.segments[i];
        if (g.kind != w.kind || !near(g.from, w.from) || !near(g.to, w.to))
            return false;
    }
    return true;
}

PartProfile readPart(const QString &path)
{
    const ProjectParseResult read = readProjectFile(path);
    if (!read.project)
        qFatal("cannot read %s", qPrintable(path));
    return read.project->part;
}

} // namespace

class TestImportCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private Q_SLOTS:

    void exportThenImportExamples_data()
    {
        QTest::addColumn<QString>("name");
        for (const char *name : {"stepped-shaft-chuck", "hollow-sleeve-tailstock", "long-shaft-centres"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }

    void exportThenImportExamples()
    {
        QFETCH(QString, name);
        const QString source = example(qPrintable(name + QStringLiteral(".tolturn")));
        const QString step = m_dir.filePath(name + QStringLiteral(".step"));
        const QString project = m_dir.filePath(name + QStringLiteral(".tolturn"));
        const Run exported = runCli({QStringLiteral("export-step"), QStringLiteral("-o"), step, source});
        QVERIFY2(exported.exitCode == 0, qPrintable(exported.err));
        QCOMPARE(exported.out, step + QStringLiteral(": written\n"));
        const Run imported = runCli({QStringLiteral("import"), QStringLiteral("-o"), project, step});
        QVERIFY2(imported.exitCode == 0, qPrintable(imported.err));
        QVERIFY(imported.out.startsWith(project + QStringLiteral(": written")));
        const Run checked = runCli({QStringLiteral("check"), project});
        QVERIFY2(checked.exitCode == 0, qPrintable(checked.err));
        // An imported part gets one finishing pass and no tolerances yet: a singular and a plural.
        QVERIFY2(checked.out.contains(QStringLiteral("1 pass, 0 tolerances")), qPrintable(checked.out));
        const PartProfile want = readPart(source);
        const PartProfile got = readPart(project);
        QVERIFY(sameContour(got.outer, want.outer));
        QVERIFY(sameContour(got.inner, want.inner));
    }

    void importJsonListsSolidsAndAxes()
    {
        const QString step = m_dir.filePath(QStringLiteral("sleeve.step"));
        const QString project = m_dir.filePath(QStringLiteral("sleeve.tolturn"));
        QVERIFY(exportProfileToStep(readPart(example("hollow-sleeve-tailstock.tolturn")), step).ok);
        const Run r = runCli({QStringLiteral("import"), QStringLiteral("--json"), QStringLiteral("--flip"),
                              QStringLiteral("-o"), project, step});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(json.value(QStringLiteral("written")).toBool(), true);
        QCOMPARE(json.value(QStringLiteral("solids")).toArray().size(), 1);
        QCOMPARE(json.value(QStringLiteral("chosen_axis")).toInt(), 0);
        const QJsonArray direction =
            json.value(QStringLiteral("axes")).toArray().at(0).toObject().value(QStringLiteral("direction")).toArray();
        QCOMPARE(direction.at(2).toDouble(), 1.0);
        // Flipped: the counterbore (Ø45, at the right end in the example) is now at the left.
        const PartProfile got = readPart(project);
        QVERIFY(!got.inner.empty());
        QCOMPARE(got.inner.segments.front().from.r_mm, 22.5);
        QVERIFY(runCli({QStringLiteral("check"), project}).exitCode == 0);
    }

    // --choose: a result line for the first read, then one per choice on standard input, each from
    // what was read (the file is deleted after the first result); a malformed choice ends it.
    void chooseExtractsEachChoiceFromOneRead()
    {
        const QString step = m_dir.filePath(QStringLiteral("choose.step"));
        const QString project = m_dir.filePath(QStringLiteral("choose.tolturn"));
        const PartProfile sleeve = readPart(example("hollow-sleeve-tailstock.tolturn"));
        QVERIFY(exportProfileToStep(sleeve, step).ok);
        QProcess cli;
        cli.start(QStringLiteral(TOLTURN_CLI_PATH), {QStringLiteral("import"), QStringLiteral("--json"),
                                                     QStringLiteral("--choose"), QStringLiteral("-o"), project, step});
        QVERIFY(cli.waitForStarted());
        const auto nextResult = [&cli] {
            while (!cli.canReadLine() && cli.waitForReadyRead(60000)) {
            }
            return QJsonDocument::fromJson(cli.readLine()).object();
        };
        QCOMPARE(nextResult().value(QStringLiteral("written")).toBool(), true);
        QVERIFY(sameContour(readPart(project).inner, sleeve.inner));
        QVERIFY(QFile::remove(step));
        cli.write("-1 -1 1\n");
        QCOMPARE(nextResult().value(QStringLiteral("written")).toBool(), true);
        // Flipped: the counterbore (Ø45, at the right end in the example) is now at the left.
        QCOMPARE(readPart(project).inner.segments.front().from.r_mm, 22.5);
        cli.write("0 3 0\n"); // the part has one axis
        const QJsonObject none = nextResult();
        QCOMPARE(none.value(QStringLiteral("written")).toBool(), false);
        QVERIFY(QJsonDocument(none).toJson().contains("there is no axis 3"));
        cli.write("0 0 2\n");
        QVERIFY(cli.waitForFinished(60000));
        QCOMPARE(cli.exitCode(), 2);
        QVERIFY(cli.readAllStandardError().contains("SOLID AXIS FLIP"));
    }

    // A sound part that cannot be written: the reason is in its result line, for a reader that
    // takes the line before standard error.
    void chooseSaysWhyAPartWasNotWritten()
    {
        const QString step = m_dir.filePath(QStringLiteral("unwritable.step"));
        QVERIFY(exportProfileToStep(readPart(example("stepped-shaft-chuck.tolturn")), step).ok);
        QProcess cli;
        cli.start(QStringLiteral(TOLTURN_CLI_PATH),
                  {QStringLiteral("import"), QStringLiteral("--json"), QStringLiteral("--choose"), QStringLiteral("-o"),
                   QStringLiteral("/nonexistent-folder/part.tolturn"), step});
        cli.closeWriteChannel();
        QVERIFY(cli.waitForFinished(60000));
        const QJsonObject result = QJsonDocument::fromJson(cli.readLine()).object();
        QCOMPARE(result.value(QStringLiteral("written")).toBool(), false);
        const QJsonArray diagnostics = result.value(QStringLiteral("diagnostics")).toArray();
        QVERIFY(!diagnostics.isEmpty());
        const QJsonObject last = diagnostics.last().toObject();
        QCOMPARE(last.value(QStringLiteral("field")).toString(), QStringLiteral("output"));
        QVERIFY2(last.value(QStringLiteral("message")).toString().contains(QStringLiteral("/nonexistent-folder")),
                 qPrintable(last.value(QStringLiteral("message")).toString()));
    }

    // "-o -": the STEP file and the project on standard output, byte for byte what a file would
    // hold, the messages on standard error; a pipe of the two gives the example's contour back.
    void standardOutputForBoth()
    {
        const QString source = example("stepped-shaft-chuck.tolturn");
        const QString stepFile = m_dir.filePath(QStringLiteral("piped.step"));
        const Run exported = runCli({QStringLiteral("export-step"), QStringLiteral("-o"), QStringLiteral("-"), source});
        QVERIFY2(exported.exitCode == 0, qPrintable(exported.err));
        QVERIFY(exported.out.startsWith(QStringLiteral("ISO-10303-21;")));
        QVERIFY(exported.out.trimmed().endsWith(QStringLiteral("END-ISO-10303-21;")));
        QVERIFY(exported.err.contains(QStringLiteral("-: written")));
        QVERIFY(tolturn::test::writeFile(stepFile, exported.out.toUtf8()));
        const Run imported = runCli({QStringLiteral("import"), QStringLiteral("-o"), QStringLiteral("-"), stepFile});
        QVERIFY2(imported.exitCode == 0, qPrintable(imported.err));
        QVERIFY(imported.err.contains(QStringLiteral("11 outer and 0 inner features, 0 warnings")));
        const ProjectParseResult read = parseProjectJson(imported.out.toUtf8());
        QVERIFY(read.project);
        QVERIFY(sameContour(read.project->part.outer, readPart(source).outer));
        // Two outputs cannot share standard output.
        const Run both = runCli(
            {QStringLiteral("import"), QStringLiteral("--json"), QStringLiteral("-o"), QStringLiteral("-"), stepFile});
        QCOMPARE(both.exitCode, 2);
        QVERIFY(both.err.contains(QStringLiteral("--json and -o -")));
    }

    void importErrors()
    {
        const QString notStep = m_dir.filePath(QStringLiteral("notes.step"));
        QVERIFY(tolturn::test::writeFile(notStep, "not a model\n"));
        const QString project = m_dir.filePath(QStringLiteral("never.tolturn"));
        const Run bad = runCli({QStringLiteral("import"), QStringLiteral("-o"), project, notStep});
        QCOMPARE(bad.exitCode, 1);
        QVERIFY2(bad.err.contains(QStringLiteral("'%1' is not a STEP file").arg(notStep)), qPrintable(bad.err));
        QVERIFY(!QFile::exists(project));
        const Run usage = runCli({QStringLiteral("import"), notStep});
        QCOMPARE(usage.exitCode, 2);
        const Run badIndex = runCli({QStringLiteral("import"), QStringLiteral("--solid"), QStringLiteral("x"),
                                     QStringLiteral("-o"), project, notStep});
        QCOMPARE(badIndex.exitCode, 2);
    }

    // An id the data library does not know is refused before anything is written: a good project
    // at the output path stays as it was (it would otherwise be replaced by one that does not open).
    void importUnknownMaterialOrMachineKeepsTheTarget()
    {
        const QString project = m_dir.filePath(QStringLiteral("keep.tolturn"));
        QVERIFY(tolturn::test::writeFile(project, "{\"kept\": true}\n"));
        const QString step = QStringLiteral(TOLTURN_SOURCE_DIR "/fuzz/corpus/cad/slender-pin.step");
        const Run machine = runCli({QStringLiteral("import"), QStringLiteral("--machine"), QStringLiteral("nope"),
                                    QStringLiteral("-o"), project, step});
        QCOMPARE(machine.exitCode, 2);
        QVERIFY2(machine.err.contains(QStringLiteral("--machine: unknown machine \"nope\"; the machines are: ")) &&
                     machine.err.contains(QStringLiteral("haas-st-20")),
                 qPrintable(machine.err));
        const Run material = runCli({QStringLiteral("import"), QStringLiteral("--material"), QStringLiteral("cheese"),
                                     QStringLiteral("-o"), project, step});
        QCOMPARE(material.exitCode, 2);
        QVERIFY2(
            material.err.contains(QStringLiteral("--material: unknown material \"cheese\"; the materials are: ")) &&
                material.err.contains(QStringLiteral("C45E-N")),
            qPrintable(material.err));
        QFile kept(project);
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), QByteArray("{\"kept\": true}\n"));
    }
};

QTEST_GUILESS_MAIN(TestImportCli)
#include "tst_import_cli.moc"
