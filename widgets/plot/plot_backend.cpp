// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/plot/plot_backend.h"

#include "core/common/atomic_file.h"

#include <QApplication>
#include <QBuffer>
#include <QClipboard>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QPainter>
#include <QPdfWriter>
#include <QPicture>
#include <QRectF>
#include <QSvgGenerator>
#include <qcustomplot.h>

namespace tolturn {

LibraryInfo plotBackendInfo()
{
    return {QStringLiteral("QCustomPlot"), QStringLiteral(QCUSTOMPLOT_VERSION_STR), QStringLiteral("GPL-3.0-or-later")};
}

void renderPlot(QCustomPlot &plot, QPainter &painter, const QRectF &target, double textScale)
{
    // QCustomPlot draws through its own painter class: record it as a picture (vectors), then
    // replay the picture on the caller's painter at the requested scale.
    const int width = qRound(target.width() * textScale);
    const int height = qRound(target.height() * textScale);
    QPicture picture;
    QCPPainter recorder(&picture);
    plot.toPainter(&recorder, width, height);
    recorder.end();
    painter.save();
    painter.translate(target.topLeft());
    painter.scale(1.0 / textScale, 1.0 / textScale);
    painter.drawPicture(QPointF(0, 0), picture);
    painter.restore();
}

namespace {

QByteArray vectorBytes(QCustomPlot &plot, bool pdf)
{
    const QRectF box(0, 0, plot.width(), plot.height());
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (pdf) {
        QPdfWriter writer(&buffer);
        writer.setPageSize(QPageSize(box.size(), QPageSize::Point));
        writer.setPageMargins(QMarginsF(0, 0, 0, 0));
        writer.setResolution(72); // one plot pixel per point
        QPainter painter(&writer);
        renderPlot(plot, painter, box);
    } else {
        QSvgGenerator svg;
        svg.setOutputDevice(&buffer);
        svg.setSize(box.size().toSize());
        svg.setViewBox(box);
        svg.setTitle(QStringLiteral("TolTurn plot"));
        QPainter painter(&svg);
        renderPlot(plot, painter, box);
    }
    return bytes;
}

} // namespace

QString exportPlot(QCustomPlot &plot, const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    QByteArray bytes;
    if (suffix == QLatin1String("png")) {
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        plot.toPixmap(plot.width(), plot.height(), 2.0).save(&buffer, "PNG");
    } else if (suffix == QLatin1String("svg") || suffix == QLatin1String("pdf")) {
        bytes = vectorBytes(plot, suffix == QLatin1String("pdf"));
    } else {
        return QCoreApplication::translate("PlotExport", "cannot export a plot as '%1': use .png, .svg or .pdf")
            .arg(QFileInfo(path).fileName());
    }
    return writeFileAtomically(path, bytes);
}

QString plotExportFilter()
{
    return QCoreApplication::translate("PlotExport", "PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)");
}

void addPlotContextMenu(QCustomPlot &plot, const std::function<QString()> &csv)
{
    plot.setContextMenuPolicy(Qt::CustomContextMenu);
    QObject::connect(&plot, &QWidget::customContextMenuRequested, &plot, [&plot, csv](const QPoint &at) {
        QMenu menu(&plot);
        if (csv) {
            QObject::connect(menu.addAction(QCoreApplication::translate("PlotExport", "Copy Data as CSV")),
                             &QAction::triggered, &plot, [csv] { QApplication::clipboard()->setText(csv()); });
        }
        QObject::connect(
            menu.addAction(QCoreApplication::translate("PlotExport", "Export Image…")), &QAction::triggered, &plot,
            [&plot] {
                const QString path = QFileDialog::getSaveFileName(
                    &plot, QCoreApplication::translate("PlotExport", "Export Plot"), QString(), plotExportFilter());
                if (path.isEmpty())
                    return;
                if (const QString error = exportPlot(plot, path); !error.isEmpty())
                    QMessageBox::warning(&plot, QCoreApplication::translate("PlotExport", "Export Plot"), error);
            });
        menu.exec(plot.mapToGlobal(at));
    });
}

} // namespace tolturn
