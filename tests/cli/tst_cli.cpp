// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli as a user runs it: the real binary, its output streams and exit codes.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

namespace {

struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

Run runCli(const QStringList &args)
{
    QProcess process;
    process.start(QStringLiteral(TOLTURN_CLI_PATH), args);
    if (!process.waitForFinished(60000))
        qFatal("tolturn-cli did not finish");
    return {process.exitCode(), QString::fromUtf8(process.readAllStandardOutput()),
            QString::fromUtf8(process.readAllStandardError())};
}

QString example(const char *name)
{
    return QStringLiteral(TOLTURN_SOURCE_DIR "/resources/examples/") + QString::fromLatin1(name);
}

} // namespace

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
    }

    void checkValidExamples()
    {
        const Run r = runCli({QStringLiteral("check"), example("stepped-shaft-chuck.tolturn"),
                              example("hollow-sleeve-tailstock.tolturn"), example("long-shaft-centres.tolturn")});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out.count(QStringLiteral(": ok — ")), 3);
        QVERIFY(r.out.contains(QStringLiteral("part \"Hollow sleeve\", 400 mm long, 8 outer and 3 inner features, "
                                              "chuck_tailstock")));
        QVERIFY(r.err.isEmpty());
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
        QFile source(example("stepped-shaft-chuck.tolturn"));
        QVERIFY(source.open(QIODevice::ReadOnly));
        QByteArray text = source.readAll();
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

    void checkWithoutFileIsUsageError()
    {
        const Run r = runCli({QStringLiteral("check")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains(QStringLiteral("no project file given")));
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
