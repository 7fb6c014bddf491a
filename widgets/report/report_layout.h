// SPDX-License-Identifier: GPL-3.0-or-later
// The page layout of the PDF report: A4 in points, content flowed down the page and recorded as
// vector pictures, page breaks where a block would not fit.
#pragma once

#include "core/common/diagnostic.h"

#include <QFont>
#include <QFontMetricsF>
#include <QPainter>
#include <QPicture>
#include <QString>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace tolturn::report {

// A4 in points; everything is laid out in points and replayed on the PDF at its resolution.
constexpr double kPageWidth = 595.0;
constexpr double kPageHeight = 842.0;
constexpr double kMargin = 48.0;
constexpr double kBottom = kPageHeight - kMargin - 18.0; // room for the footer
constexpr double kWidth = kPageWidth - 2 * kMargin;
// Plots are laid out at this multiple of their box and scaled down: screen fonts become ~8 pt.
constexpr double kPlotTextScale = 1.5;

// A number with a fixed count of decimals, as the report's tables print it.
inline QString num(double v, int decimals)
{
    return formatFixed(v, decimals);
}

inline QFont font(double pixels, bool bold = false)
{
    QFont f(QStringLiteral("DejaVu Sans"));
    f.setPixelSize(static_cast<int>(std::lround(pixels))); // pixels = points here: no DPI surprises on replay
    f.setBold(bold);
    return f;
}

// Draws `text` wrapped in `box` at the largest size from `largest` down to `smallest` pixels at which
// it fits; at the smallest, words are dropped from the end behind an ellipsis until it does (a word
// wider than the box is shortened itself only when it is the first). A long part name is set
// smaller, and one too long even then is shortened: it is never cut through a line. Leaves the
// painter's font at the size chosen.
inline void drawFitted(QPainter &painter, const QRectF &box, const QString &text, int largest, int smallest, bool bold)
{
    Q_ASSERT(largest >= smallest);
    const int flags = Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap;
    const auto fits = [&](const QString &shown) {
        const QRectF needed = painter.boundingRect(QRectF(box.topLeft(), QSizeF(box.width(), 1e4)), flags, shown);
        return needed.height() <= box.height() && needed.width() <= box.width();
    };
    for (int pixels = largest; pixels >= smallest; --pixels) {
        painter.setFont(font(pixels, bold));
        if (fits(text))
            break;
    }
    QString shown = text;
    QStringList words = text.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    while (!fits(shown) && words.size() > 1) {
        words.removeLast();
        shown = words.join(QLatin1Char(' ')) + QChar(0x2026);
    }
    if (!fits(shown)) // one word wider than the box
        shown = QFontMetricsF(painter.font(), painter.device()).elidedText(text, Qt::ElideRight, box.width());
    painter.drawText(box, flags, shown);
}

// `line`, whose only placeholder %1 stands for `name`, with the name shortened (`mode`) as far as
// the line must be to fit `width` in the painter's font: the rest of the line (numbers, a page
// count) is never what is lost.
inline QString withNameFitted(const QPainter &painter, const QString &line, const QString &name, double width,
                              Qt::TextElideMode mode = Qt::ElideRight)
{
    const QFontMetricsF metrics(painter.font(), painter.device());
    const double forName = std::max(0.0, width - metrics.horizontalAdvance(QString(line).arg(QString())));
    return QString(line).arg(metrics.elidedText(name, mode, forName));
}

// Records the report page by page as pictures (vectors), flowing content down and breaking pages.
class Layout {
public:
    Layout() { newPage(); }

    void newPage()
    {
        if (m_painter)
            m_painter->end();
        m_pages.push_back(std::make_unique<QPicture>());
        m_painter = std::make_unique<QPainter>(m_pages.back().get());
        m_painter->setRenderHint(QPainter::Antialiasing);
        m_y = kMargin;
    }

    // The height left on the page.
    [[nodiscard]] double remaining() const { return kBottom - m_y; }

    void ensure(double height)
    {
        if (m_y + height > kBottom)
            newPage();
    }

    void heading(const QString &text)
    {
        ensure(60);
        m_y += 8;
        m_painter->setFont(font(14, true));
        m_painter->setPen(QColor(0x1f, 0x4e, 0x9a));
        m_painter->drawText(QRectF(kMargin, m_y, kWidth, 20), Qt::AlignLeft | Qt::AlignVCenter, text);
        m_y += 24;
        m_painter->setPen(Qt::black);
    }

    void paragraph(const QString &text, double size = 9.5)
    {
        m_painter->setFont(font(size));
        const QRectF bounds = m_painter->boundingRect(QRectF(kMargin, 0, kWidth, 10000), Qt::TextWordWrap, text);
        ensure(bounds.height() + 4);
        m_painter->setFont(font(size)); // a page break starts a new painter with default state
        m_painter->drawText(QRectF(kMargin, m_y, kWidth, bounds.height()), Qt::TextWordWrap, text);
        m_y += bounds.height() + 4;
    }

    // A bold line naming the figure that follows; kept on the figure's page.
    void caption(const QString &text)
    {
        ensure(200);
        m_painter->setFont(font(10, true));
        m_painter->drawText(QRectF(kMargin, m_y, kWidth, 14), Qt::AlignLeft | Qt::AlignVCenter, text);
        m_y += 16;
    }

    // Rows of cells; the first row is the header. `colours` gives optional backgrounds per row/column.
    // A cell's text wraps within its column; the row is as tall as its tallest cell.
    void table(const std::vector<QStringList> &rows, const std::vector<double> &widths,
               const std::function<QColor(int row, int column)> &background = {})
    {
        constexpr double kRowHeight = 14.0;
        const int flags = Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap;
        for (std::size_t r = 0; r < rows.size(); ++r) {
            const std::size_t columns = std::min(widths.size(), static_cast<std::size_t>(rows[r].size()));
            m_painter->setFont(font(8.2, r == 0));
            double rowHeight = kRowHeight;
            for (std::size_t c = 0; c < columns; ++c)
                rowHeight = std::max(rowHeight, m_painter
                                                        ->boundingRect(QRectF(0, 0, widths[c] - 6, 1000), flags,
                                                                       rows[r].at(static_cast<qsizetype>(c)))
                                                        .height() +
                                                    4.0);
            ensure(rowHeight);
            m_painter->setFont(font(8.2, r == 0)); // a page break starts a new painter with default state
            double x = kMargin;
            for (std::size_t c = 0; c < columns; ++c) {
                const QRectF box(x, m_y, widths[c], rowHeight);
                const QColor fill =
                    r == 0 ? QColor(0xe8, 0xec, 0xf2)
                           : (background ? background(static_cast<int>(r), static_cast<int>(c)) : QColor());
                if (fill.isValid())
                    m_painter->fillRect(box, fill);
                m_painter->setPen(QColor(0xbb, 0xbb, 0xbb));
                m_painter->drawRect(box);
                m_painter->setPen(Qt::black);
                m_painter->drawText(box.adjusted(3, 0, -3, 0), flags, rows[r].at(static_cast<qsizetype>(c)));
                x += widths[c];
            }
            m_y += rowHeight;
        }
        m_y += 6;
    }

    // The height `text` takes wrapped in `width` points.
    [[nodiscard]] double textHeight(const QString &text, const QFont &f, double width) const
    {
        m_painter->setFont(f);
        return m_painter->boundingRect(QRectF(0, 0, width, 10000), Qt::TextWordWrap, text).height();
    }

    // A block of given height drawn by `draw` into the full-width rectangle.
    void block(double height, const std::function<void(QPainter &, const QRectF &)> &draw)
    {
        ensure(height);
        draw(*m_painter, QRectF(kMargin, m_y, kWidth, height));
        m_y += height + 6;
    }

    std::vector<std::unique_ptr<QPicture>> finish()
    {
        m_painter->end();
        m_painter.reset();
        return std::move(m_pages);
    }

private:
    std::vector<std::unique_ptr<QPicture>> m_pages;
    std::unique_ptr<QPainter> m_painter;
    double m_y = kMargin;
};

} // namespace tolturn::report
