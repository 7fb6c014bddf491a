// SPDX-License-Identifier: GPL-3.0-or-later
// The report's set-up sheet. Its clamping sketch drawn into an image: it stays inside the block the
// report gives it (the grip's label too), a bore is drawn open and the section is mirrored about
// the axis, for each kind of clamping. Its findings in words, as a machinist reads them.
#include "tests/core/test_support.h"

#include "widgets/report/setup_sheet.h"

#include <QImage>
#include <QPainter>
#include <QTest>

using namespace tolturn;

namespace {

// The block the set-up sheet gives the sketch: the page's width, 120 px high (setup_sheet.cpp),
// placed inside a larger white image so that anything drawn outside it shows.
const QRectF kBlock(60.0, 60.0, 480.0, 120.0);

QImage sketch(const char *example)
{
    QImage image(600, 300, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    report::drawClamping(painter, kBlock, test::exampleProject(example));
    painter.end();
    return image;
}

int pixelsOutsideTheBlock(const QImage &image)
{
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (!kBlock.contains(QPointF(x + 0.5, y + 0.5)) && image.pixel(x, y) != qRgb(255, 255, 255))
                ++count;
        }
    }
    return count;
}

// Pixels of the row `d` px above the axis that differ from those of the row `d` px below it, over the
// block's width: the axis is the block's middle, y = 120 (a pixel edge), so row 119 − d mirrors
// 120 + d. Rasterising the two halves may differ by a pixel at an edge, so a few are allowed.
int asymmetricPixels(const QImage &image, int rows)
{
    const int axis = static_cast<int>(kBlock.center().y());
    int count = 0;
    for (int d = 1; d < rows; ++d) { // d = 0 is the axis' own dash-dot line
        for (int x = static_cast<int>(kBlock.left()); x < static_cast<int>(kBlock.right()); ++x) {
            if (image.pixel(x, axis - 1 - d) != image.pixel(x, axis + d))
                ++count;
        }
    }
    return count;
}

} // namespace

class TestSetupSheet : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void theSketchStaysInItsBlock_data()
    {
        QTest::addColumn<QString>("example");
        for (const char *name : {"stepped-shaft-chuck.tolturn", "hollow-sleeve-tailstock.tolturn",
                                 "long-shaft-centres.tolturn", "valve-body-two-bores.tolturn"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }

    // The grip's label ("chuck: 35.0 mm in the jaws") was placed below the chuck's body, outside the
    // block, where the report's pass table overprinted it.
    void theSketchStaysInItsBlock()
    {
        QFETCH(QString, example);
        const QImage image = sketch(example.toLatin1().constData());
        QCOMPARE(pixelsOutsideTheBlock(image), 0);
    }

    // A through bore is white along the axis; a solid shaft is filled there. The section is the
    // same above and below the axis within the stock's radius (the grip's label lies below it):
    // a bore whose last point was not mirrored ran a diagonal across the bore's lower half.
    void boresAreDrawnOpenAndMirrored()
    {
        const QImage sleeve = sketch("hollow-sleeve-tailstock.tolturn");
        const QImage shaft = sketch("stepped-shaft-chuck.tolturn");
        const QPoint nearTheAxis(static_cast<int>(kBlock.center().x()), static_cast<int>(kBlock.center().y()) - 4);
        QCOMPARE(sleeve.pixel(nearTheAxis), qRgb(255, 255, 255));
        QCOMPARE(shaft.pixel(nearTheAxis), qRgb(0xdd, 0xe6, 0xf2));
        // The stock's radius is at most 120 / 3.2 px (the chuck's body is ±1.5 R of it); 25 rows of
        // 480 px are compared, and a mismatch of 1 % of them is a rasterising edge, not a shape.
        constexpr int rows = 25;
        QVERIFY2(asymmetricPixels(sleeve, rows) < rows * 480 / 100,
                 qPrintable(QString::number(asymmetricPixels(sleeve, rows))));
        QVERIFY(asymmetricPixels(shaft, rows) < rows * 480 / 100);
    }

    // Written out by hand: the passes counted from 1 and a run of them given once, other fields named
    // in words in brackets before the message (not run into it: "Warning: boring tool the part has
    // bores"), in the findings' order.
    void findingsAreToldInWords()
    {
        Diagnostics findings;
        for (int i = 0; i < 8; ++i)
            findings.push_back(makeWarning(QStringLiteral("passes[%1].cutting_speed_m_min").arg(i),
                                           QStringLiteral("200 m/min is outside the range")));
        findings.push_back(makeWarning(QStringLiteral("passes[8].feed_mm_rev"), QStringLiteral("0.1 mm/rev is low")));
        findings.push_back(makeWarning(QStringLiteral("boring_tool"), QStringLiteral("the part has bores")));
        findings.push_back(makeError(QStringLiteral("boring_tool.overhang_mm"), QStringLiteral("300 mm is long")));
        const QStringList words = report::findingsInWords(findings);
        const QStringList expected{
            QStringLiteral("Warning (passes 1–8): cutting speed 200 m/min is outside the range"),
            QStringLiteral("Warning (pass 9): feed 0.1 mm/rev is low"),
            QStringLiteral("Warning (boring tool): the part has bores"),
            QStringLiteral("Error (tool overhang): 300 mm is long"),
        };
        QCOMPARE(words, expected);
    }
};

QTEST_MAIN(TestSetupSheet)
#include "tst_setup_sheet.moc"
