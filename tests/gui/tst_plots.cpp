// SPDX-License-Identifier: GPL-3.0-or-later
// TolTurn's plot classes: CSV of the data, the hover read-out, and PNG/SVG/PDF export.
#include "widgets/plot/line_plot.h"
#include "widgets/plot/map_plot.h"

#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

#include <limits>

using namespace tolturn;

namespace {

QByteArray head(const QString &path, int bytes)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.read(bytes) : QByteArray();
}

void twoCurves(LinePlot &plot)
{
    plot.setAxisLabels(QStringLiteral("z [mm]"), QStringLiteral("deviation [µm]"));
    plot.addCurve(QStringLiteral("total"), {0.0, 1.0, 2.0}, {0.5, 1.5, 2.5}, Qt::black);
    plot.addCurve(QStringLiteral("spindle, chuck"), {0.0, 1.0, 2.0},
                  {0.25, std::numeric_limits<double>::quiet_NaN(), 0.75}, Qt::blue);
    plot.resize(400, 300);
    plot.rescaleAndReplot();
}

} // namespace

class TestPlots : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void csvWithSharedX()
    {
        LinePlot plot;
        twoCurves(plot);
        // Written out by hand: a name with a comma is quoted, a gap (NaN) is an empty cell.
        QCOMPARE(plot.csvText(), QStringLiteral("z [mm],total — deviation [µm],\"spindle, chuck — deviation [µm]\"\n"
                                                "0,0.5,0.25\n"
                                                "1,1.5,\n"
                                                "2,2.5,0.75\n"));
    }

    void csvWithDifferentX()
    {
        LinePlot plot;
        plot.setAxisLabels(QStringLiteral("f [mm/rev]"), QStringLiteral("Ra [µm]"));
        plot.addCurve(QStringLiteral("a"), {0.1, 0.2}, {1.0, 2.0}, Qt::black);
        plot.addCurve(QStringLiteral("b"), {0.15}, {3.0}, Qt::red);
        QCOMPARE(plot.csvText(), QStringLiteral("curve,f [mm/rev],Ra [µm]\na,0.1,1\na,0.2,2\nb,0.15,3\n"));
    }

    void readoutTakesTheNearestPoint()
    {
        LinePlot plot;
        twoCurves(plot);
        // Each value with its axis's unit (thin space between number and unit).
        QCOMPARE(plot.readoutAt(1.4), QString::fromUtf8("z = 1\u2009mm\ntotal: 1.5\u2009µm\nspindle, chuck: —"));
        QCOMPARE(plot.readoutAt(1.6),
                 QString::fromUtf8("z = 2\u2009mm\ntotal: 2.5\u2009µm\nspindle, chuck: 0.75\u2009µm"));
        QCOMPARE(plot.readoutAt(-5.0),
                 QString::fromUtf8("z = 0\u2009mm\ntotal: 0.5\u2009µm\nspindle, chuck: 0.25\u2009µm"));
        // A label without a unit is shown as it is.
        plot.setAxisLabels(QStringLiteral("station"), QStringLiteral("count"));
        QCOMPARE(plot.readoutAt(1.0), QStringLiteral("station = 1\ntotal: 1.5\nspindle, chuck: —"));
    }

    void exportsPngSvgPdf()
    {
        LinePlot plot;
        twoCurves(plot);
        plot.show(); // exported at the size it has on screen
        QVERIFY(QTest::qWaitForWindowExposed(&plot));
        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("plot.png"));
        QCOMPARE(plot.exportImage(png), QString());
        const QImage image(png);
        QCOMPARE(image.size(), QSize(800, 600)); // twice the on-screen size
        const QString svg = dir.filePath(QStringLiteral("plot.svg"));
        QCOMPARE(plot.exportImage(svg), QString());
        QVERIFY(head(svg, 400).contains("<svg"));
        const QString pdf = dir.filePath(QStringLiteral("plot.pdf"));
        QCOMPARE(plot.exportImage(pdf), QString());
        QCOMPARE(head(pdf, 5), QByteArray("%PDF-"));

        MapPlot map;
        map.resize(300, 200);
        QImage cells(4, 3, QImage::Format_RGB32);
        cells.fill(Qt::green);
        map.setImage(cells, 0.1, 0.4, 100.0, 300.0);
        map.replot();
        const QString mapPdf = dir.filePath(QStringLiteral("map.pdf"));
        QCOMPARE(map.exportImage(mapPdf), QString());
        QCOMPARE(head(mapPdf, 5), QByteArray("%PDF-"));
    }

    void exportErrorsNameTheFile()
    {
        LinePlot plot;
        twoCurves(plot);
        QTemporaryDir dir;
        const QString gif = dir.filePath(QStringLiteral("plot.gif"));
        QVERIFY(plot.exportImage(gif).contains(QStringLiteral("plot.gif")));
        QVERIFY(!QFile::exists(gif));
        const QString nowhere = QStringLiteral("/nonexistent-folder/plot.png");
        QVERIFY(plot.exportImage(nowhere).contains(nowhere));
    }
};

QTEST_MAIN(TestPlots)
#include "tst_plots.moc"
