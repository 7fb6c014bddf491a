// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/post_processor.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace tolturn {

namespace {

struct Post {
    Q_DECLARE_TR_FUNCTIONS(PostProcessor)
};

QString coordinate(double value_mm)
{
    const double rounded = std::round(value_mm * 1000.0) / 1000.0;
    return QString::number(rounded == 0.0 ? 0.0 : rounded, 'f', 3); // no "-0.000"
}

// Controls read comments as ISO 646 text: no umlauts, degree signs or micro signs.
QString asciiText(const QString &text)
{
    QString t = text;
    const std::pair<const char16_t *, const char *> spelled[] = {
        {u"\u00b0", " deg"}, {u"\u00b5", "u"},  {u"\u00e4", "ae"}, {u"\u00f6", "oe"},
        {u"\u00fc", "ue"},   {u"\u00c4", "Ae"}, {u"\u00d6", "Oe"}, {u"\u00dc", "Ue"},
        {u"\u00df", "ss"},   {u"\u2013", "-"},  {u"\u00d8", "D"},  {u"\u2300", "D"}}; // Ø, the diameter sign
    for (const auto &[from, to] : spelled)
        t.replace(QString::fromUtf16(from), QLatin1String(to));
    t = t.normalized(QString::NormalizationForm_KD);
    QString out;
    for (const QChar c : t)
        if (c.unicode() >= 32 && c.unicode() < 127)
            out += c;
    return out;
}

// What differs between the dialects; everything else is ISO 6983-1.
struct Dialect {
    ControlDialect id;
    bool parenthesisComments = true; // ( … ) or ; …
    QString setup;                   // modal state at the start
    QString rapid, feed, clockwise, counterClockwise, arcRadiusWord;
    QString compensationLeft, compensationRight, compensationOff;
    QString programEnd;
};

Dialect dialect(ControlDialect id)
{
    switch (id) {
    case ControlDialect::Sinumerik:
        return {id,
                false,
                QStringLiteral("G18 G71 G90 DIAMON G95 G40"),
                QStringLiteral("G0"),
                QStringLiteral("G1"),
                QStringLiteral("G2"),
                QStringLiteral("G3"),
                QStringLiteral("CR="),
                QStringLiteral("G41"),
                QStringLiteral("G42"),
                QStringLiteral("G40"),
                QStringLiteral("M30")};
    case ControlDialect::LinuxCnc:
        return {id,
                true,
                QStringLiteral("G18 G21 G90 G95 G7 G40"),
                QStringLiteral("G0"),
                QStringLiteral("G1"),
                QStringLiteral("G2"),
                QStringLiteral("G3"),
                QStringLiteral("R"),
                QStringLiteral("G41"),
                QStringLiteral("G42"),
                QStringLiteral("G40"),
                QStringLiteral("M2")};
    case ControlDialect::FanucHaas:
        break;
    }
    return {ControlDialect::FanucHaas,
            true,
            QStringLiteral("G18 G21 G40 G99"),
            QStringLiteral("G00"),
            QStringLiteral("G01"),
            QStringLiteral("G02"),
            QStringLiteral("G03"),
            QStringLiteral("R"),
            QStringLiteral("G41"),
            QStringLiteral("G42"),
            QStringLiteral("G40"),
            QStringLiteral("M30")};
}

constexpr qsizetype kCommentWidth = 70; // the text; with its parentheses a line of 72 characters

class Writer {
public:
    Writer(QTextStream &out, const Dialect &d, double length_mm) : m_out(out), m_d(d), m_length(length_mm) {}

    void line(const QString &text, const QString &remark = {})
    {
        m_out << 'N' << m_n << ' ' << text;
        if (!remark.isEmpty())
            m_out << ' ' << comment(remark);
        m_out << '\n';
        m_n += 10;
    }

    // Comment lines of at most 72 characters with their parentheses (LinuxCNC refuses blocks of over
    // 256, and a control's screen is narrow), wrapped at spaces, never between a number and its unit.
    void commentLine(const QString &text)
    {
        QString rest = asciiText(text);
        while (rest.size() > kCommentWidth) {
            qsizetype cut = rest.lastIndexOf(QLatin1Char(' '), kCommentWidth);
            while (cut > 0 && splitsAQuantity(rest, cut))
                cut = rest.lastIndexOf(QLatin1Char(' '), cut - 1);
            if (cut <= 0)
                cut = kCommentWidth;
            m_out << comment(rest.left(cut)) << '\n';
            rest = rest.mid(cut).trimmed();
        }
        m_out << comment(rest) << '\n';
    }

    // Whether a break at the space `at` would split a quantity: a number from its unit ("1.938" /
    // "mm") or a symbol from its number ("ap" / "1.938").
    [[nodiscard]] static bool splitsAQuantity(const QString &text, qsizetype at)
    {
        static const QRegularExpression numberBefore(QStringLiteral("[0-9]$"));
        static const QRegularExpression unitAfter(QStringLiteral("^(mm|mm/rev|m/min|rpm|um|kW|N|s|min|%|deg)\\b"),
                                                  QRegularExpression::CaseInsensitiveOption);
        static const QRegularExpression symbolBefore(QStringLiteral("(^|[ (])[A-Za-z]{1,2}$"));
        static const QRegularExpression numberAfter(QStringLiteral("^[-+]?[0-9]"));
        const QString before = text.left(at);
        const QString after = text.mid(at + 1);
        return (numberBefore.match(before).hasMatch() && unitAfter.match(after).hasMatch()) ||
               (symbolBefore.match(before).hasMatch() && numberAfter.match(after).hasMatch());
    }

    [[nodiscard]] QString comment(const QString &text) const
    {
        QString t = asciiText(text).toUpper();
        t.replace(QLatin1Char('('), QLatin1Char('['));
        t.replace(QLatin1Char(')'), QLatin1Char(']'));
        t.replace(QLatin1Char(';'), QLatin1Char(','));
        return m_d.parenthesisComments ? QString(QStringLiteral("(") + t + QStringLiteral(")"))
                                       : QString(QStringLiteral("; ") + t);
    }

    [[nodiscard]] QString xz(ProfilePoint p) const
    {
        return QStringLiteral("X%1 Z%2").arg(coordinate(2.0 * p.r_mm), coordinate(p.z_mm - m_length));
    }

    // A rapid retract to `to`, along x first and then along z (the tool leaves the part first).
    void retract(ProfilePoint to)
    {
        line(m_d.rapid + QStringLiteral(" X") + coordinate(2.0 * to.r_mm));
        line(m_d.rapid + QStringLiteral(" Z") + coordinate(to.z_mm - m_length));
        m_at = to;
    }

    // The moves of a pass; the nose is compensated to the right of the travel on an outer contour
    // (G42) and to the left in a bore (G41).
    void moves(const PassPath &pass, ContourSide side)
    {
        const QString &compensationOn = side == ContourSide::Inner ? m_d.compensationLeft : m_d.compensationRight;
        std::optional<double> feedStated;
        for (const ToolMove &m : pass.moves) {
            const bool stays =
                m_at && std::abs(m_at->z_mm - m.to.z_mm) < 5e-4 && std::abs(m_at->r_mm - m.to.r_mm) < 5e-4;
            if (stays && !m.startsNoseCompensation && !m.endsNoseCompensation)
                continue; // a move to where the tool is
            m_at = m.to;
            QString word;
            switch (m.kind) {
            case MoveKind::Rapid:
                word = m_d.rapid;
                break;
            case MoveKind::Feed:
                word = m_d.feed;
                break;
            case MoveKind::ArcClockwise:
                word = m_d.clockwise;
                break;
            case MoveKind::ArcCounterClockwise:
                word = m_d.counterClockwise;
                break;
            }
            if (m.startsNoseCompensation)
                word = compensationOn + QLatin1Char(' ') + word;
            if (m.endsNoseCompensation)
                word = m_d.compensationOff + QLatin1Char(' ') + word;
            QString text = word + QLatin1Char(' ') + xz(m.to);
            if (m.kind == MoveKind::ArcClockwise || m.kind == MoveKind::ArcCounterClockwise)
                text += QLatin1Char(' ') + m_d.arcRadiusWord + coordinate(m.radius_mm);
            const double feed = m.feed_mm_rev.value_or(pass.conditions.feed_mm_rev);
            if (m.kind != MoveKind::Rapid && (!feedStated || std::abs(*feedStated - feed) > 5e-4)) {
                text += QStringLiteral(" F") + QString::number(feed, 'f', 3);
                feedStated = feed;
            }
            line(text);
        }
    }

private:
    QTextStream &m_out;
    const Dialect &m_d;
    double m_length;
    int m_n = 10;
    std::optional<ProfilePoint> m_at; // where the tool is
};

QString toolCall(const Dialect &d, int tool)
{
    switch (d.id) {
    case ControlDialect::Sinumerik:
        return QStringLiteral("T%1 D1").arg(tool);
    case ControlDialect::LinuxCnc:
        return QStringLiteral("T%1 M6 G43").arg(tool);
    case ControlDialect::FanucHaas:
        break;
    }
    return QStringLiteral("T%1%1").arg(tool, 2, 10, QLatin1Char('0'));
}

QString spindleLimitWord(const Dialect &d, long rpm)
{
    switch (d.id) {
    case ControlDialect::Sinumerik:
        return QStringLiteral("LIMS=%1").arg(rpm);
    case ControlDialect::LinuxCnc:
        return {}; // G96 carries it as D
    case ControlDialect::FanucHaas:
        break;
    }
    return QStringLiteral("G50 S%1").arg(rpm);
}

QString constantSurfaceSpeed(const Dialect &d, double vc, long limit, bool first)
{
    const QString spindleOn = d.id == ControlDialect::Sinumerik ? QStringLiteral("M3") : QStringLiteral("M03");
    const QString start = first ? QLatin1Char(' ') + spindleOn : QString();
    if (d.id == ControlDialect::LinuxCnc)
        return QStringLiteral("G96 D%1 S%2%3")
            .arg(limit)
            .arg(std::lround(vc))
            .arg(first ? QStringLiteral(" M3") : QString());
    return QStringLiteral("G96 S%1%2").arg(std::lround(vc)).arg(start);
}

// The imaginary tool tip of an outer turning tool is r_e below and r_e left of the nose centre
// (Z to the right, X up): tip 3 on Fanuc-style controls and cutting edge position 3 on Sinumerik,
// orientation 2 in LinuxCNC's tool table. A boring bar's is r_e above and r_e left: tip 2, cutting
// edge position 2, LinuxCNC orientation 3 (the orientations of LinuxCNC's lathe tool table are
// read back by its interpreter in tst_toolpath).
QString noseLine(const Toolpath &path, ControlDialect d)
{
    const QString r = coordinate(path.noseRadius_mm);
    if (path.nose == NoseHandling::TipPath && path.side == ContourSide::Inner)
        return Post::tr("Boring bar: path of the imaginary tool tip for nose radius %1 mm (tip 2), computed by "
                        "TolTurn: no G41/G42; set the nose radius to 0 in its tool offsets")
            .arg(r);
    if (path.nose == NoseHandling::TipPath)
        return Post::tr("Path of the imaginary tool tip for nose radius %1 mm, computed by TolTurn: no G41/G42; set "
                        "the nose radius to 0 in the tool offsets")
            .arg(r);
    if (path.side == ContourSide::Inner) {
        switch (d) {
        case ControlDialect::Sinumerik:
            return Post::tr("G41 nose radius compensation: tool edge D1 with radius %1 mm, cutting edge position 2")
                .arg(r);
        case ControlDialect::LinuxCnc:
            return Post::tr("G41 nose radius compensation: tool table diameter D%1, orientation Q3")
                .arg(coordinate(2.0 * path.noseRadius_mm));
        case ControlDialect::FanucHaas:
            break;
        }
        return Post::tr("G41 nose radius compensation: radius %1 mm and tip 2 in the tool geometry offset").arg(r);
    }
    switch (d) {
    case ControlDialect::Sinumerik:
        return Post::tr("G42 nose radius compensation: tool edge D1 with radius %1 mm, cutting edge position 3").arg(r);
    case ControlDialect::LinuxCnc:
        return Post::tr("G42 nose radius compensation: tool table diameter D%1, orientation Q2")
            .arg(coordinate(2.0 * path.noseRadius_mm));
    case ControlDialect::FanucHaas:
        break;
    }
    return Post::tr("G42 nose radius compensation: radius %1 mm and tip 3 in the tool geometry offset").arg(r);
}

QString passLine(const PassPath &pass, bool finishing, ContourSide side)
{
    const QString text = side == ContourSide::Inner ? Post::tr("Bore pass %1, %2: vc %3 m/min, f %4 mm/rev, ap %5 mm")
                                                    : Post::tr("Pass %1, %2: vc %3 m/min, f %4 mm/rev, ap %5 mm");
    return text.arg(pass.number)
        .arg(finishing ? Post::tr("finishing") : Post::tr("roughing"))
        .arg(QString::number(pass.conditions.cuttingSpeed_m_min, 'f', 0),
             QString::number(pass.conditions.feed_mm_rev, 'f', 3),
             QString::number(pass.conditions.depthOfCut_mm, 'f', 3));
}

} // namespace

QString keyword(ControlDialect dialect)
{
    switch (dialect) {
    case ControlDialect::Sinumerik:
        return QStringLiteral("sinumerik");
    case ControlDialect::LinuxCnc:
        return QStringLiteral("linuxcnc");
    case ControlDialect::FanucHaas:
        break;
    }
    return QStringLiteral("fanuc");
}

std::optional<ControlDialect> controlDialectFromKeyword(const QString &text)
{
    const QString t = text.trimmed().toLower();
    if (t == QLatin1String("fanuc") || t == QLatin1String("haas"))
        return ControlDialect::FanucHaas;
    if (t == QLatin1String("sinumerik") || t == QLatin1String("siemens"))
        return ControlDialect::Sinumerik;
    if (t == QLatin1String("linuxcnc"))
        return ControlDialect::LinuxCnc;
    return std::nullopt;
}

QString displayName(ControlDialect dialect)
{
    switch (dialect) {
    case ControlDialect::Sinumerik:
        return Post::tr("Siemens Sinumerik");
    case ControlDialect::LinuxCnc:
        return Post::tr("LinuxCNC");
    case ControlDialect::FanucHaas:
        break;
    }
    return Post::tr("Fanuc / Haas");
}

double speedLimitingDiameter_mm(const PassPath &pass)
{
    // A pass that only faces has no smallest turned diameter: under G96 its speed would run up to
    // the machine's at the axis. Its limit is the speed at the largest diameter it faces, so the
    // spindle holds that speed inwards (the cutting speed falls towards the axis).
    if (std::isfinite(pass.smallestDiameter_mm) && pass.smallestDiameter_mm > 0.0)
        return pass.smallestDiameter_mm;
    double diameter = 0.0;
    for (const ToolMove &m : pass.moves)
        if (m.kind != MoveKind::Rapid && !m.featureId.isEmpty()) // a cut, not the entry or exit
            diameter = std::max(diameter, 2.0 * std::abs(m.to.r_mm));
    return diameter;
}

SpindleLimit spindleLimit(const std::vector<const Toolpath *> &paths, std::optional<double> machineLimit_rpm)
{
    double needed = 0.0;
    double atDiameter = 0.0;
    double atSpeed = 0.0;
    auto consider = [&](const PassPath &p) {
        const double diameter = p.moves.empty() ? 0.0 : speedLimitingDiameter_mm(p);
        if (diameter <= 0.0)
            return;
        const double n = 1000.0 * p.conditions.cuttingSpeed_m_min / (std::numbers::pi * diameter);
        if (n > needed) {
            needed = n;
            atDiameter = diameter;
            atSpeed = p.conditions.cuttingSpeed_m_min;
        }
    };
    for (const Toolpath *path : paths) {
        for (const PassPath &p : path->roughing)
            consider(p);
        consider(path->finishing);
    }
    SpindleLimit limit;
    limit.speed_rpm = std::ceil(needed);
    limit.reason = Post::tr("Highest speed the plan needs: vc %1 m/min on D%2 mm")
                       .arg(QString::number(atSpeed, 'f', 0), coordinate(atDiameter));
    if (machineLimit_rpm && *machineLimit_rpm < limit.speed_rpm) {
        limit.speed_rpm = *machineLimit_rpm;
        limit.reason = Post::tr("Machine limit %1 rpm; the plan would need %2 rpm on D%3 mm")
                           .arg(QString::number(*machineLimit_rpm, 'f', 0), QString::number(std::ceil(needed), 'f', 0),
                                coordinate(atDiameter));
    } else if (machineLimit_rpm) {
        limit.reason += Post::tr("; machine limit %1 rpm").arg(QString::number(*machineLimit_rpm, 'f', 0));
    } else {
        limit.reason += Post::tr("; the machine's limit is not known");
    }
    return limit;
}

QString postProcess(const Toolpath &path, const Toolpath *boring, double partLength_mm, const PostOptions &options)
{
    const Dialect d = dialect(options.dialect);
    QString text;
    QTextStream out(&text);
    Writer w(out, d, partLength_mm);
    if (d.id != ControlDialect::Sinumerik)
        out << "%\n";
    if (d.id == ControlDialect::FanucHaas)
        out << programNumberWord(options.programNumber) << '\n';
    for (const QString &h : options.header)
        w.commentLine(h);
    w.commentLine(noseLine(path, options.dialect));
    if (boring != nullptr)
        w.commentLine(noseLine(*boring, options.dialect));
    w.commentLine(Post::tr("Z0 at the right end face, X on diameter, G02/G03 seen with Z to the right and X up"));
    for (const Toolpath *p : {&path, boring}) {
        for (const QString &n : p != nullptr ? p->notes : QStringList())
            w.commentLine(n);
        for (const QString &warning : p != nullptr ? p->warnings : QStringList())
            w.commentLine(Post::tr("Warning: %1").arg(warning));
    }
    w.line(d.setup);
    w.line(toolCall(d, options.tool));
    const long limit = std::lround(options.spindle.speed_rpm);
    // No pass that cuts, no speed to limit: a limit of 0 rpm would be a word the control takes literally.
    // Why the spindle is limited where it is, on the comment lines above the limit (too long to
    // follow the block on one line).
    w.commentLine(options.spindle.reason);
    if (const QString word = limit > 0 ? spindleLimitWord(d, limit) : QString(); !word.isEmpty())
        w.line(word);
    bool first = true;
    auto cut = [&](const PassPath &pass, bool finishing, ContourSide side) {
        if (pass.moves.empty())
            return;
        w.commentLine(passLine(pass, finishing, side));
        w.line(constantSurfaceSpeed(d, pass.conditions.cuttingSpeed_m_min, limit, first));
        first = false;
        w.moves(pass, side);
    };
    for (const PassPath &p : path.roughing)
        cut(p, false, path.side);
    cut(path.finishing, true, path.side);
    if (boring != nullptr) {
        w.commentLine(Post::tr("Clear of the part for the tool change: the boring bar's overhang and the clearance "
                               "off the end face, above the turning path (or the machine's own tool-change "
                               "position)"));
        w.retract(options.toolChangeAt);
        w.commentLine(options.boringToolLine);
        w.line(toolCall(d, options.boringTool));
        for (const PassPath &p : boring->roughing)
            cut(p, false, boring->side);
        cut(boring->finishing, true, boring->side);
    }
    w.line(d.id == ControlDialect::Sinumerik ? QStringLiteral("M5") : QStringLiteral("M05"));
    w.line(d.programEnd);
    if (d.id != ControlDialect::Sinumerik)
        out << "%\n";
    out.flush();
    return text;
}

QString programNumberWord(int programNumber)
{
    return QStringLiteral("O%1").arg(programNumber, 5, 10, QLatin1Char('0'));
}

} // namespace tolturn
