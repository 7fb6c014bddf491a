// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/planning/gcode.h"

#include "core/common/library_info.h"
#include "core/project/keywords.h"
#include "core/tolerance/target_contour.h"

#include <QTextStream>

#include <algorithm>
#include <cmath>

namespace tolturn {

namespace {

QString coordinate(double value_mm)
{
    const double rounded = std::round(value_mm * 1000.0) / 1000.0;
    return QString::number(rounded == 0.0 ? 0.0 : rounded, 'f', 3); // no "-0.000"
}

// Comments may not contain parentheses.
QString comment(const QString &text)
{
    QString t = text;
    t.replace(QLatin1Char('('), QLatin1Char('['));
    t.replace(QLatin1Char(')'), QLatin1Char(']'));
    return QStringLiteral("(") + t + QStringLiteral(")");
}

struct Writer {
    QTextStream &out;
    double length_mm;
    int n = 10;

    void line(const QString &text)
    {
        out << 'N' << n << ' ' << text << '\n';
        n += 10;
    }

    // Machine coordinates of a profile point: X diameter, Z from the right end face.
    [[nodiscard]] QString xz(double z_mm, double r_mm) const
    {
        return QStringLiteral("X%1 Z%2").arg(coordinate(2.0 * r_mm), coordinate(z_mm - length_mm));
    }
};

QString compensationSummary(const CompensationPlan *plan)
{
    if (plan == nullptr)
        return QStringLiteral("NO COMPENSATION: TOLERANCED DIAMETERS AT THE MIDDLE OF THEIR ZONE");
    QStringList parts;
    for (const FeatureCompensation &f : plan->features) {
        if (f.side != ContourSide::Outer)
            continue;
        if (f.action == CompensationAction::ConstantOffset)
            parts
                << QStringLiteral("%1 OFFSET %2 UM ON DIAMETER").arg(f.featureId, QString::number(f.offset_um, 'f', 1));
        else if (f.action == CompensationAction::ProfileCorrection)
            parts << QStringLiteral("%1 PROFILE CORRECTED BY THE PREDICTED DEVIATION").arg(f.featureId);
    }
    return parts.isEmpty() ? QStringLiteral("COMPENSATED PATH: NO FEATURE NEEDS A CORRECTION")
                           : QStringLiteral("COMPENSATED: ") + parts.join(QStringLiteral("; "));
}

} // namespace

QString finishingProgram(const Project &project, const GCodeOptions &options)
{
    QString text;
    QTextStream out(&text);
    const PartProfile &part = project.part;
    Writer w{out, part.length_mm()};
    const double chuckFace =
        project.clamping.method == ClampingMethod::BetweenCentres ? 0.0 : project.clamping.clampedLength_mm;
    const double clearance = 0.5 * part.stockDiameter_mm + 2.0;
    out << "%\n";
    out << 'O' << options.programNumber << ' '
        << comment(QStringLiteral("TOLTURN %1 FINISHING PASS OF %2").arg(tolturnVersion(), part.name.toUpper()))
        << '\n';
    w.line(comment(QStringLiteral("MATERIAL %1, INSERT %2, HOLDER %3, CLAMPING %4")
                       .arg(project.materialId, project.tool.insertCode, project.tool.holderCode,
                            keyword(project.clamping.method).toUpper())));
    w.line(comment(compensationSummary(options.compensation)));
    w.line(comment(QStringLiteral("Z0 AT THE RIGHT END FACE, X ON DIAMETER, G02/G03 SEEN WITH Z RIGHT AND X UP")));
    w.line(QStringLiteral("G18 G21 G90 G95"));
    w.line(QStringLiteral("T%1%1 %2").arg(options.tool, 2, 10, QLatin1Char('0')).arg(comment(project.tool.insertCode)));
    if (options.maxSpindleSpeed_rpm)
        w.line(QStringLiteral("G92 S%1 %2")
                   .arg(std::lround(*options.maxSpindleSpeed_rpm))
                   .arg(comment(QStringLiteral("SPINDLE SPEED LIMIT"))));
    w.line(QStringLiteral("G96 S%1 M03").arg(std::lround(options.finishing.cuttingSpeed_m_min)));
    w.line(QStringLiteral("G00 X%1 Z2.000").arg(coordinate(2.0 * clearance)));

    // The outer contour as aimed at (toleranced diameters at the middle of their zone, as the
    // verdicts assume), from its right end to the chuck face, in the order the tool meets it.
    const Contour target = targetContour(project, ContourSide::Outer);
    const std::vector<Segment> &segments = target.segments;
    bool first = true;
    for (std::size_t i = segments.size(); i-- > 0;) { // right to left; clang 14 cannot use views::reverse
        const Segment &s = segments[i];
        if (s.to.z_mm <= chuckFace + 1e-9 && s.from.z_mm <= chuckFace + 1e-9)
            break; // inside the jaws
        const FeatureCompensation *c = options.compensation ? options.compensation->find(s.id) : nullptr;
        if (first) {
            w.line(QStringLiteral("G00 ") + w.xz(s.to.z_mm + 2.0, s.to.r_mm));
            w.line(QStringLiteral("G01 Z%1 F%2")
                       .arg(coordinate(0.0), QString::number(options.finishing.feed_mm_rev, 'f', 3)));
            first = false;
        }
        if (c && c->action == CompensationAction::ProfileCorrection && !c->correctedPath.empty()) {
            w.line(comment(QStringLiteral("%1 CORRECTED").arg(s.id)));
            for (std::size_t j = c->correctedPath.size(); j-- > 0;)
                w.line(QStringLiteral("G01 ") + w.xz(c->correctedPath[j].z_mm, c->correctedPath[j].r_mm));
            continue;
        }
        const double shift_mm = c && c->action == CompensationAction::ConstantOffset ? 0.5e-3 * c->offset_um : 0.0;
        if (s.kind == SegmentKind::Radius) {
            // Travelled backwards, the arc turns the other way.
            const bool clockwise = s.arcDirection == ArcDirection::CounterClockwise;
            w.line(QStringLiteral("%1 %2 R%3")
                       .arg(clockwise ? QStringLiteral("G02") : QStringLiteral("G03"),
                            w.xz(s.from.z_mm, s.from.r_mm + shift_mm), coordinate(s.arcRadius_mm)));
        } else {
            if (shift_mm != 0.0) // step onto the offset radius where the feature begins
                w.line(QStringLiteral("G01 ") + w.xz(s.to.z_mm, s.to.r_mm + shift_mm));
            const double z = std::max(s.from.z_mm, chuckFace);
            w.line(
                QStringLiteral("G01 ") + w.xz(z, s.from.r_mm + shift_mm) +
                (shift_mm != 0.0 ? QStringLiteral(" ") + comment(QStringLiteral("%1 OFFSET").arg(s.id)) : QString()));
        }
    }
    w.line(QStringLiteral("G01 X%1").arg(coordinate(2.0 * clearance)));
    w.line(QStringLiteral("G00 Z2.000"));
    w.line(QStringLiteral("M05"));
    w.line(QStringLiteral("M30"));
    out << "%\n";
    out.flush();
    return text;
}

} // namespace tolturn
