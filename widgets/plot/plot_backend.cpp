// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/plot/plot_backend.h"

#include <QPainter>
#include <QPicture>
#include <QRectF>
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

} // namespace tolturn
