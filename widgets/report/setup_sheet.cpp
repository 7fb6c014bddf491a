// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/report/setup_sheet.h"

#include "core/common/diagnostic.h"
#include "core/common/finding_groups.h"
#include "core/data/data_library.h"
#include "core/planning/post_processor.h"
#include "core/project/keywords.h"
#include "core/tooling/iso1832.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPainterPath>
#include <QRegularExpression>

#include <algorithm>
#include <functional>
#include <map>

namespace tolturn::report {

namespace {

struct SetupSheet {
    Q_DECLARE_TR_FUNCTIONS(SetupSheet)
};

// A field key of a project file in words: "cutting_speed_m_min" -> "cutting speed".
QString fieldWords(const QString &key)
{
    static const std::map<QString, const char *> names{
        {QStringLiteral("cutting_speed_m_min"), QT_TRANSLATE_NOOP("SetupSheet", "cutting speed")},
        {QStringLiteral("feed_mm_rev"), QT_TRANSLATE_NOOP("SetupSheet", "feed")},
        {QStringLiteral("depth_of_cut_mm"), QT_TRANSLATE_NOOP("SetupSheet", "depth of cut")},
        {QStringLiteral("overhang_mm"), QT_TRANSLATE_NOOP("SetupSheet", "tool overhang")},
        {QStringLiteral("clamped_length_mm"), QT_TRANSLATE_NOOP("SetupSheet", "clamped length")},
        {QStringLiteral("stock_diameter_mm"), QT_TRANSLATE_NOOP("SetupSheet", "stock diameter")},
    };
    const QString last = key.section(QLatin1Char('.'), -1);
    if (const auto it = names.find(last); it != names.end())
        return SetupSheet::tr(it->second);
    QString words = last;
    static const QRegularExpression unit(QStringLiteral("_(mm|rpm|kW|Nm|N|um|min|m_min|mm_rev|deg)$"));
    words.remove(unit);
    return words.replace(QLatin1Char('_'), QLatin1Char(' '));
}

// The section of segments [first, last) mirrored about the axis: the part's outline, or a bore's.
QPainterPath silhouette(const std::vector<Segment> &segments, std::size_t first, std::size_t last,
                        const std::function<QPointF(double, double)> &at)
{
    QPainterPath path;
    if (first >= last)
        return path;
    path.moveTo(at(segments[first].from.z_mm, segments[first].from.r_mm));
    for (std::size_t i = first; i < last; ++i)
        path.lineTo(at(segments[i].to.z_mm, segments[i].to.r_mm));
    path.lineTo(at(segments[last - 1].to.z_mm, -segments[last - 1].to.r_mm));
    for (std::size_t i = last; i-- > first;) // clang 14 cannot use views::reverse
        path.lineTo(at(segments[i].from.z_mm, -segments[i].from.r_mm));
    path.closeSubpath();
    return path;
}

void drawCentre(QPainter &painter, QPointF tip, double size, bool pointingRight)
{
    const double d = pointingRight ? -size : size;
    QPolygonF cone;
    cone << tip << QPointF(tip.x() + d, tip.y() - 0.6 * size) << QPointF(tip.x() + d, tip.y() + 0.6 * size);
    painter.drawPolygon(cone);
    painter.drawRect(QRectF(QPointF(tip.x() + d, tip.y() - 0.45 * size), QSizeF(d, 0.9 * size)).normalized());
}

} // namespace

void drawClamping(QPainter &painter, const QRectF &rect, const Project &project)
{
    const double length = project.part.length_mm();
    const double radius = 0.5 * project.part.stockDiameter_mm;
    if (length <= 0.0 || radius <= 0.0)
        return;
    painter.save();
    painter.setFont(font(7.5));
    // The chuck body spans ±1.5 R; a line of text below it (the grip) must stay inside the block.
    const double textHeight = QFontMetricsF(painter.font()).height() + 2.0;
    const double margin = 0.14 * length;
    const double scale = std::min(rect.width() / (length + 2.0 * margin),
                                  std::max(rect.height() - 2.0 * textHeight, 1.0) / (3.0 * radius));
    const QPointF origin(rect.center().x() - 0.5 * length * scale, rect.center().y());
    auto at = [&](double z, double r) { return QPointF(origin.x() + z * scale, origin.y() - r * scale); };
    painter.setPen(QPen(QColor(0x1f, 0x4e, 0x9a), 1.0));
    painter.setBrush(QColor(0xdd, 0xe6, 0xf2));
    const std::vector<Segment> &outer = project.part.outer.segments;
    painter.drawPath(silhouette(outer, 0, outer.size(), at));
    painter.setBrush(Qt::white);
    for (const auto &[first, last] : project.part.inner.pieces()) // the bores
        painter.drawPath(silhouette(project.part.inner.segments, first, last, at));
    painter.setPen(QPen(QColor(0xcc, 0x33, 0x33), 0.6, Qt::DashDotLine));
    painter.drawLine(at(-0.5 * margin, 0.0), at(length + 0.5 * margin, 0.0)); // axis
    painter.setPen(QPen(Qt::black, 0.8));
    painter.setBrush(QColor(0x99, 0x99, 0x99));
    const ClampingMethod method = project.clamping.method;
    const double grip = project.clamping.clampedLength_mm;
    if (method != ClampingMethod::BetweenCentres) {
        const double jaw = 0.45 * radius;
        const double gripRadius = project.part.gripRadius_mm(grip);
        for (const double side : {1.0, -1.0})
            painter.drawRect(QRectF(at(0.0, side * (gripRadius + jaw)), at(grip, side * gripRadius)).normalized());
        painter.setBrush(QColor(0xbb, 0xbb, 0xbb));
        painter.drawRect(QRectF(at(-margin * 0.6, 1.5 * radius), at(0.0, -1.5 * radius)).normalized()); // chuck body
        painter.drawText(QRectF(at(-margin, -1.5 * radius) + QPointF(0.0, 2.0), QSizeF(rect.width() / 2.0, textHeight)),
                         Qt::AlignLeft | Qt::AlignTop,
                         method == ClampingMethod::Collet
                             ? SetupSheet::tr("collet: %1 mm held").arg(num(grip, 1))
                             : SetupSheet::tr("chuck: %1 mm in the jaws").arg(num(grip, 1)));
    } else {
        drawCentre(painter, at(0.0, 0.0), 0.35 * margin * scale, true);
        painter.drawText(QRectF(at(-margin, -1.1 * radius), QSizeF(scale * 2.0 * margin, 12)), Qt::AlignLeft,
                         SetupSheet::tr("centre and driver"));
    }
    if (!holdsOneEndOnly(method)) {
        drawCentre(painter, at(length, 0.0), 0.35 * margin * scale, false);
        painter.drawText(
            QRectF(at(length - 0.5 * margin, -1.1 * radius), QSizeF(scale * 1.5 * margin, 12)), Qt::AlignRight,
            method == ClampingMethod::ChuckTailstock ? SetupSheet::tr("tailstock centre") : SetupSheet::tr("centre"));
    }
    painter.restore();
}

void setupSheet(Layout &l, const Project &p, const FinishingOutput &finishing)
{
    l.block(120, [&](QPainter &painter, const QRectF &rect) { drawClamping(painter, rect, p); });
    const TurningProgram &program = finishing.nominal;
    std::vector<QStringList> rows{{SetupSheet::tr("Pass"), SetupSheet::tr("Kind"), SetupSheet::tr("n [rpm]"),
                                   SetupSheet::tr("vc [m/min]"), SetupSheet::tr("f [mm/rev]"),
                                   SetupSheet::tr("ap [mm]"), SetupSheet::tr("Power [kW]"),
                                   SetupSheet::tr("Time [min]")}};
    double total = 0.0;
    for (const PassSummary &s : program.passes) {
        rows.push_back({QString::number(s.number), passKindText(s),
                        spanText(num(s.lowestSpeed_rpm, 0), num(s.highestSpeed_rpm, 0)),
                        num(s.conditions.cuttingSpeed_m_min, 0), num(s.conditions.feed_mm_rev, 3),
                        num(s.conditions.depthOfCut_mm, 3), s.power_kW ? num(*s.power_kW, 2) : SetupSheet::tr("—"),
                        num(s.time_min, 2)});
        total += s.time_min;
    }
    rows.push_back({QString(), SetupSheet::tr("total cutting"), QString(), QString(), QString(), QString(), QString(),
                    num(total, 2)});
    l.table(rows, {34, 70, 72, 60, 60, 54, 70, kWidth - 420});
    l.paragraph(SetupSheet::tr("Program %1 for %2, %n pass(es); spindle limit %3 rpm (%4). Checksum (SHA-256, "
                               "first 16 digits) of the nominal program %5, of the compensated program %6: compare "
                               "them with `tolturn-cli gcode` or the G-code tab before running.",
                               nullptr, static_cast<int>(program.passes.size()))
                    .arg(programNumberWord(program.programNumber), program.dialectReason)
                    .arg(num(program.spindle.speed_rpm, 0), program.spindle.reason, program.checksum,
                         finishing.compensated.checksum),
                8.5);
    for (const QString &w : program.warnings())
        l.paragraph(SetupSheet::tr("Program warning: %1").arg(w), 8.5);
}

QStringList findingsInWords(const Diagnostics &findings)
{
    QStringList out;
    for (const FindingGroup &g : groupedByIndex(findings)) {
        const Diagnostic &d = g.finding;
        const QString severity = d.severity == Severity::Error ? SetupSheet::tr("Error") : SetupSheet::tr("Warning");
        if (g.array != QLatin1String("passes")) {
            for (const int i : g.indices.empty() ? std::vector<int>{-1} : g.indices) {
                const QString field = i < 0 ? d.field : QStringLiteral("%1[%2].%3").arg(g.array).arg(i).arg(g.member);
                out << QStringLiteral("%1 (%2): %3").arg(severity, fieldWords(field), d.message);
            }
            continue;
        }
        std::vector<int> numbers; // pass numbers count from 1
        numbers.reserve(g.indices.size());
        for (const int i : g.indices)
            numbers.push_back(i + 1);
        const QString passes = numbers.size() == 1 ? SetupSheet::tr("pass %1").arg(numbers.front())
                                                   : SetupSheet::tr("passes %1").arg(numberList(numbers));
        out << QStringLiteral("%1 (%2): %3 %4").arg(severity, passes, fieldWords(g.member), d.message);
    }
    return out;
}

} // namespace tolturn::report
