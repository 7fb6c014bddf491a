// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/report/report_writer.h"

#include "core/common/atomic_file.h"
#include "core/common/diagnostic.h"
#include "core/common/library_info.h"
#include "core/cutting/cutting_quantities.h"
#include "core/learning/setup_prediction.h"
#include "core/planning/feed_schedule.h"
#include "core/planning/planning_report.h"
#include "core/planning/plausibility.h"
#include "core/project/keywords.h"
#include "core/tolerance/evaluation.h"
#include "core/tolerance/range_verdicts.h"
#include "core/tooling/iso1832.h"
#include "widgets/plot/line_plot.h"
#include "widgets/plot/map_plot.h"
#include "widgets/profile/dimension_item.h"
#include "widgets/profile/profile_scene.h"
#include "widgets/report/milling_section.h"
#include "widgets/report/report_layout.h"
#include "widgets/report/setup_sheet.h"
#include "widgets/results/deflection_panel.h"
#include "widgets/tolerances/tolerance_verdict_model.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>
#include <QFontMetricsF>
#include <QGraphicsItem>
#include <QGraphicsScene>
#include <QPainter>
#include <QPdfWriter>
#include <QPicture>

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace tolturn {

namespace {

using report::drawFitted;
using report::font;
using report::kMargin;
using report::kPageHeight;
using report::kPlotTextScale;
using report::kWidth;
using report::Layout;
using report::num;
using report::withNameFitted;

struct Report {
    Q_DECLARE_TR_FUNCTIONS(Report)
};

// The title block: the part as the drawing names it, who planned it and when, and a field for the
// approval, above the project file and the program version.
void titleBlock(Layout &l, const Project &p, const ReportHeader &header)
{
    const QString dash = QStringLiteral("—");
    const MaterialData *material = DataLibrary::builtIn().material(p.materialId);
    const std::vector<std::pair<QString, QString>> fields{
        {Report::tr("Part"), p.part.name.isEmpty() ? header.projectName : p.part.name},
        {Report::tr("Drawing no."), p.part.drawingNumber.isEmpty() ? dash : p.part.drawingNumber},
        {Report::tr("Revision"), p.part.revision.isEmpty() ? dash : p.part.revision},
        {Report::tr("Material"), material ? material->id : p.materialId},
        {Report::tr("Planner"), header.planner.isEmpty() ? dash : header.planner},
        {Report::tr("Date"), QDate::currentDate().toString(Qt::ISODate)},
        {Report::tr("Approved (name, date)"), QString()},
    };
    l.block(92, [&](QPainter &painter, const QRectF &r) {
        painter.fillRect(r, QColor(0xf2, 0xf5, 0xf9));
        painter.setPen(QColor(0x1f, 0x4e, 0x9a));
        painter.drawRect(r);
        const double top = r.top() + 30; // the row of fields
        drawFitted(painter, QRectF(r.left() + 10, r.top() + 6, r.width() - 20, top - r.top() - 6),
                   Report::tr("Tolerance report: %1").arg(fields.front().second), 16, 12, true);
        const double widths[] = {0.17, 0.14, 0.08, 0.12, 0.15, 0.14, 0.20};
        double x = r.left();
        for (std::size_t i = 0; i < fields.size(); ++i) {
            const QRectF cell(x, top, widths[i] * r.width(), 40);
            painter.setPen(QColor(0xbb, 0xbb, 0xbb));
            painter.drawRect(cell);
            painter.setPen(QColor(0x55, 0x55, 0x55));
            painter.setFont(font(7));
            painter.drawText(cell.adjusted(3, 2, -3, -2), Qt::AlignLeft | Qt::AlignTop, fields[i].first);
            painter.setPen(Qt::black);
            drawFitted(painter, cell.adjusted(3, 12, -3, -2), fields[i].second, 9, 7, true);
            x += cell.width();
        }
        // A long project file name is shortened in the middle, keeping its extension; the dimensions stay.
        painter.setFont(font(8));
        const QRectF line = r.adjusted(10, 72, -10, -2);
        const QString projectLine =
            Report::tr("Project %1 · written %2 · TolTurn %3 · length %4 mm, stock Ø%5 mm")
                .arg(QStringLiteral("%1"), QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd hh:mm")),
                     tolturnVersion(), dimensionText(p.part.length_mm()), dimensionText(p.part.stockDiameter_mm));
        painter.drawText(line, Qt::AlignLeft | Qt::AlignTop,
                         withNameFitted(painter, projectLine, header.projectName, line.width(), Qt::ElideMiddle));
    });
}

// Page 1: what the supports rest on, boxed where the planner looks, and every tolerance's verdict
// over the machine's stiffness range with the stiffness it needs.
void summary(Layout &l, const Project &p, const RangeEvaluation &range, const QString &assumption)
{
    if (!assumption.isEmpty()) {
        const QColor fill = range.someSupportRigid ? QColor(0xfd, 0xe3, 0xc8) : QColor(0xe4, 0xec, 0xf7);
        const QColor edge = range.someSupportRigid ? QColor(0xd0, 0x8a, 0x3c) : QColor(0x8a, 0xa2, 0xc8);
        const QString text = Report::tr("Machine: %1.").arg(assumption);
        l.block(l.textHeight(text, font(9, true), kWidth - 16) + 12, [&](QPainter &painter, const QRectF &r) {
            painter.fillRect(r, fill);
            painter.setPen(edge);
            painter.drawRect(r);
            painter.setPen(Qt::black);
            painter.setFont(font(9, true));
            painter.drawText(r.adjusted(8, 5, -8, -5), Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, text);
        });
    }
    if (range.tolerances.empty())
        return;
    l.caption(Report::tr("Verdicts"));
    std::vector<QStringList> rows{{Report::tr("ID"), Report::tr("Characteristic"), Report::tr("Feature"),
                                   Report::tr("Verdict"), Report::tr("On the machine range"),
                                   Report::tr("Stiffness needed")}};
    for (std::size_t i = 0; i < range.tolerances.size() && i < p.tolerances.size(); ++i) {
        const ToleranceRangeEvaluation &e = range.tolerances[i];
        rows.push_back({e.compliant.toleranceId, displayName(e.compliant.type), e.compliant.featureId,
                        verdictName(e.compliant.verdict),
                        e.range == RangeVerdict::NoRange || e.range == RangeVerdict::NotDecided ? QStringLiteral("—")
                                                                                                : rangeVerdictText(e),
                        ToleranceVerdictModel::requiredText(e)});
    }
    l.table(rows, {26, 84, 40, 100, 140, kWidth - 390}, [&](int row, int column) {
        const ToleranceRangeEvaluation &e = range.tolerances[static_cast<std::size_t>(row - 1)];
        if (column == 3)
            return ToleranceVerdictModel::verdictColor(e.compliant.verdict);
        return column == 4 ? ToleranceVerdictModel::rangeVerdictColor(e) : QColor();
    });
}

void drawing(Layout &l, const Project &p)
{
    // Frames, datum boxes and dimension texts keep their size in points (they ignore the drawing's
    // scale): the drawing is fitted on the part and its dimensions, with room above and to the right
    // for the frames, and the rows of length dimensions are spaced for their labels at the scale the
    // drawing is finally shown at (found in a few passes: the pitch changes the fit a little). Page 1
    // carries the drawing: it is drawn smaller to fit there when at least 150 pt are left, and its
    // heading stays with it.
    constexpr double kHeading = 40.0;
    constexpr double kFramesAbove = 110.0; // pt
    constexpr double kFramesRight = 90.0;  // pt
    const double labelHeight = QFontMetricsF(QFont()).height();
    QGraphicsScene scene;
    QRectF source;
    double height = 0.0;
    double shown = 0.0; // points per mm as drawn
    for (int pass = 0; pass < 3; ++pass) {
        buildProfileScene(scene, p.part, p.tolerances, p.datums, DisplayUnits(),
                          shown > 0.0 ? dimensionRowPitch_mm(1.3 * labelHeight, shown) : 0.0);
        addClamping(scene, p.part, p.clamping); // page 1 shows how the part is held
        QRectF part;
        for (const QGraphicsItem *item : scene.items()) {
            const QString kind = item->data(kItemKindData).toString();
            if (kind != profile_item::kToleranceFrame && kind != profile_item::kDatum)
                part |= item->sceneBoundingRect();
        }
        const double scale = std::min(kWidth / part.width(), 170.0 / part.height()); // points per mm
        source = part.adjusted(-4, -kFramesAbove / scale, 4 + kFramesRight / scale, 4);
        height = source.height() * scale;
        if (l.remaining() - kHeading >= 150.0)
            height = std::min(height, l.remaining() - kHeading);
        shown = std::min(kWidth / source.width(), height / source.height());
    }
    l.ensure(height + kHeading);
    l.heading(Report::tr("1  Part"));
    declutterDimensionLabels(scene, QTransform::fromScale(shown, shown));
    l.block(height,
            [&](QPainter &painter, const QRectF &r) { scene.render(&painter, r, source, Qt::KeepAspectRatio); });
}

void inputs(Layout &l, const Project &p, const DeviationResult &d, const FinishingOutput &finishing)
{
    l.heading(Report::tr("2  Set-up sheet and inputs"));
    const DataLibrary &data = DataLibrary::builtIn();
    const MaterialData *m = data.material(p.materialId);
    const MachineData *machine = data.machine(p.machineId);
    const InsertParseResult insert = parseInsertCode(p.tool.insertCode);
    std::vector<QStringList> rows{{Report::tr("Input"), Report::tr("Value")}};
    rows.push_back({Report::tr("Material"), m ? QStringLiteral("%1 — %2; E %3 MPa, kc1.1 %4 N/mm², mc %5")
                                                    .arg(m->id, m->name, num(m->youngsModulus_MPa.value, 0),
                                                         num(m->kc11_MPa.value, 0), num(m->mc.value, 2))
                                              : p.materialId});
    rows.push_back({Report::tr("Machine"), machine ? machine->name : p.machineId});
    rows.push_back({Report::tr("Insert"), insert.insert
                                              ? Report::tr("%1: %2° corner, nose radius %3 mm")
                                                    .arg(insert.insert->code, num(insert.insert->includedAngle_deg, 0),
                                                         num(insert.insert->noseRadius_mm, 1))
                                              : p.tool.insertCode});
    rows.push_back(
        {Report::tr("Holder"),
         d.inputs ? Report::tr("%1: entering angle %2°").arg(p.tool.holderCode, num(d.inputs->enteringAngle_deg, 0))
                  : p.tool.holderCode});
    rows.push_back(
        {Report::tr("Clamping"), Report::tr("%1, clamped length %2 mm")
                                     .arg(displayName(p.clamping.method), dimensionText(p.clamping.clampedLength_mm))});
    rows.push_back({Report::tr("Force model"), forceModelName(keyword(p.cuttingModel.forceModel))});
    rows.push_back(
        {Report::tr("Machine characterisation"), p.characterisation.source.isEmpty()
                                                     ? Report::tr("not measured: see the machine assumption on page 1")
                                                     : p.characterisation.source});
    l.table(rows, {130, kWidth - 130});
    report::setupSheet(l, p, finishing);
    // Conditions outside the insert's published ranges or the machine's limits (checkPlausibility).
    for (const QString &finding : report::findingsInWords(checkPlausibility(p, data)))
        l.paragraph(finding, 8.5);
}

void deviationPlots(Layout &l, const Project &p, const DeviationResult &d, const std::optional<DeviationResult> &stiff,
                    const std::optional<LearnedCurves> &learned)
{
    l.heading(Report::tr("3  Predicted deviation"));
    if (!d.inputs) {
        for (const Diagnostic &x : d.diagnostics)
            l.paragraph(x.toString());
        return;
    }
    const TurningInputs &in = *d.inputs;
    // Each tool's own forces and roughness (Ra = f²/(32 r), cutting_quantities.h): a bore is cut by
    // the boring bar's insert, whose nose radius may differ.
    const double feed = in.pass.feed_mm_rev;
    l.paragraph(Report::tr("Finishing pass %1, turning insert (nose radius %2 mm): forces (%3) Fc %4 N, Ff %5 N, Fp "
                           "%6 N; theoretical Ra %7 µm, Rz %8 µm.")
                    .arg(in.passIndex + 1)
                    .arg(num(in.noseRadius_mm, 2), forceModelName(in.forceModel), num(in.forces.tangential_N, 1),
                         num(in.forces.axial_N, 1), num(in.forces.radial_N, 1),
                         num(theoreticalRa_um(feed, in.noseRadius_mm), 2),
                         num(theoreticalRz_um(feed, in.noseRadius_mm), 2)));
    if (in.boring && !p.part.inner.empty()) {
        const BoringInputs &b = *in.boring;
        l.paragraph(Report::tr("Bores, boring bar %1 (nose radius %2 mm), same pass: forces Fc %3 N, Ff %4 N, Fp %5 N; "
                               "theoretical Ra %6 µm, Rz %7 µm.")
                        .arg(b.holderCode, num(b.noseRadius_mm, 2), num(b.forces.tangential_N, 1),
                             num(b.forces.axial_N, 1), num(b.forces.radial_N, 1),
                             num(theoreticalRa_um(feed, b.noseRadius_mm), 2),
                             num(theoreticalRz_um(feed, b.noseRadius_mm), 2)));
    }
    for (const ContourSide side : {ContourSide::Outer, ContourSide::Inner}) {
        if (side == ContourSide::Inner && p.part.inner.empty())
            continue;
        LinePlot plot;
        DeflectionPanel::addContributionCurves(plot, d, side, true);
        if (stiff)
            DeflectionPanel::addRangeBand(plot, d, *stiff, side, DeflectionPanel::totalRadial_mm, Report::tr("total"));
        if (learned)
            DeflectionPanel::addLearnedTotal(plot, d, *learned, side);
        plot.setAxisLabels(p.clamping.heldEnd == PartEnd::Right ? Report::tr("z from the held (right) end [mm]")
                                                                : Report::tr("z from the part's left end [mm]"),
                           Report::tr("deviation [µm]"));
        plot.rescaleAndReplot();
        l.caption(side == ContourSide::Outer ? Report::tr("Radial deviation of the outer contour (material left)")
                                             : Report::tr("Radial deviation of the bores (material left)"));
        l.block(190, [&](QPainter &painter, const QRectF &r) { plot.render(&painter, r, kPlotTextScale); });
    }
    if (!d.faces.empty()) {
        std::vector<QStringList> rows{
            {Report::tr("Face"), Report::tr("z [mm]"), Report::tr("tan θ"), Report::tr("axial run-out e [µm]")}};
        for (const FaceConicity &f : d.faces)
            rows.push_back({f.featureId, dimensionText(f.z_mm), QString::number(f.tanTheta, 'g', 3),
                            num(1000.0 * f.axialRunout_mm, 3)});
        l.table(rows, {80, 80, 120, 140});
    }
}

// What a tolerance's verdict checked, in a machinist's words ("size within 41.975–42.000 mm"),
// with the condition of Valiño et al. (2008) it comes from in brackets.
QString conditionInWords(const ToleranceEvaluation &e)
{
    const QString source = e.condition.section(QLatin1Char(':'), 0, 0).trimmed();
    const QString from = source.isEmpty() ? QString()
                         : source.startsWith(QLatin1String("Fig."))
                             ? Report::tr(" (Valiño et al. 2008, %1)").arg(source)
                             : QStringLiteral(" (%1)").arg(source);
    const auto mm = [](double v) { return QString::number(v, 'f', 3); };
    if (e.nominal_mm && e.upper_um && e.lower_um) {
        QString text = Report::tr("size within %1–%2 mm")
                           .arg(mm(*e.nominal_mm + 1e-3 * *e.lower_um), mm(*e.nominal_mm + 1e-3 * *e.upper_um));
        if (e.predictedMin_um && e.predictedMax_um)
            text += Report::tr("; predicted %1 mm")
                        .arg(spanText(mm(*e.nominal_mm + 1e-3 * *e.predictedMin_um),
                                      mm(*e.nominal_mm + 1e-3 * *e.predictedMax_um)));
        return text + from;
    }
    if (e.value_um && e.limit_um)
        return Report::tr("%1 of %2 µm predicted against a zone of %3 µm")
                   .arg(displayName(e.type), num(*e.value_um, 1), num(*e.limit_um, 1)) +
               from;
    return {};
}

void verdicts(Layout &l, const Project &p, const std::vector<ToleranceEvaluation> &v)
{
    l.heading(Report::tr("4  Tolerances"));
    if (p.tolerances.empty()) {
        l.paragraph(Report::tr("The project has no tolerances."));
        return;
    }
    std::vector<QStringList> rows{{Report::tr("ID"), Report::tr("Characteristic"), Report::tr("Feature"),
                                   Report::tr("Specification"), Report::tr("Value [µm]"), Report::tr("Limit [µm]"),
                                   Report::tr("Use"), Report::tr("Verdict")}};
    for (std::size_t i = 0; i < v.size(); ++i) {
        const ToleranceEvaluation &e = v[i];
        rows.push_back({e.toleranceId, displayName(e.type), e.featureId,
                        ToleranceVerdictModel::specification(p.tolerances[i]),
                        e.value_um ? num(*e.value_um, 1) : QStringLiteral("—"),
                        e.limit_um ? num(*e.limit_um, 1) : QStringLiteral("—"),
                        e.utilisation_pct ? num(*e.utilisation_pct, 1) + QStringLiteral(" %") : QStringLiteral("—"),
                        verdictName(e.verdict)});
    }
    l.table(rows, {28, 82, 44, 68, 56, 58, 52, kWidth - 388}, [&](int row, int column) {
        return column == 7 ? ToleranceVerdictModel::verdictColor(v[static_cast<std::size_t>(row - 1)].verdict)
                           : QColor();
    });
    for (const ToleranceEvaluation &e : v) {
        const QString words = conditionInWords(e);
        if (!words.isEmpty() || !e.reason.isEmpty())
            l.paragraph(QStringLiteral("%1: %2 %3").arg(e.toleranceId, words, e.reason).trimmed(), 8.0);
    }
}

// The cutting window as a map: feasible points green, others coloured by their binding constraint.
void windowMap(Layout &l, const Project &project, const PlanningReport &r)
{
    const PlanResult &pl = r.plan;
    const CuttingWindow &w = r.window;
    MapPlot map;
    QImage image(w.columns, w.rows, QImage::Format_RGB32);
    for (int row = 0; row < w.rows; ++row)
        for (int column = 0; column < w.columns; ++column) {
            const WindowCell &c = w.at(column, row);
            const QColor color = c.feasible ? QColor(0x74, 0xc4, 0x76)
                                            : QColor::fromHsv(static_cast<int>(qHash(c.binding) % 360), 70, 235);
            image.setPixel(column, row, color.rgb());
        }
    map.setImage(image, w.feed.min, w.feed.max, w.other.min, w.other.max);
    for (const auto &[label, count] : w.boundaries()) {
        double x = 0, y = 0;
        for (const WindowCell &c : w.cells)
            if (!c.feasible && c.bindingLabel == label) {
                x += c.x;
                y += c.y;
            }
        map.addLabel(x / count, y / count, label);
    }
    if (pl.feasible)
        map.addMarker(pl.candidate.finishing.feed_mm_rev, pl.candidate.finishing.cuttingSpeed_m_min,
                      Report::tr("optimum"));
    bool programmedShown = true;
    if (!project.passes.empty())
        programmedShown = map.addMarker(project.passes.back().feed_mm_rev, project.passes.back().cuttingSpeed_m_min,
                                        Report::tr("programmed"), MapPlot::Marker::Programmed);
    map.setAxisLabels(Report::tr("feed f [mm/rev]"), Report::tr("cutting speed vc [m/min]"));
    map.replot();
    l.caption(Report::tr("Cutting window of the finishing pass (green: feasible)"));
    l.block(200, [&](QPainter &painter, const QRectF &rect) { map.render(&painter, rect, kPlotTextScale); });
    if (!programmedShown)
        l.paragraph(Report::tr("The programmed finishing pass (f %1 mm/rev, vc %2 m/min) lies outside this window.")
                        .arg(formatNumber(project.passes.back().feed_mm_rev),
                             formatNumber(project.passes.back().cuttingSpeed_m_min)),
                    8.5);
}

void plan(Layout &l, const Project &p, const FinishingOutput &finishing, const std::optional<PlanningReport> &planned)
{
    l.heading(Report::tr("5  Plan"));
    if (!planned) {
        l.paragraph(
            Report::tr("The project has no planning data (the insert's cutting ranges), so no plan was optimised."));
    } else {
        const PlanningReport &r = *planned;
        if (r.problem) {
            const PlanResult &pl = r.plan;
            l.paragraph((pl.feasible ? Report::tr("Optimal plan (%1): ")
                                     : Report::tr("No plan meets every constraint; the least-violating one (%1): "))
                            .arg(keyword(p.planning.objective)) +
                        Report::tr("%1 min per part; finishing vc %2 m/min, f %3 mm/rev, ap %4 mm; ")
                            .arg(num(pl.evaluation.time_min, 3), num(pl.candidate.finishing.cuttingSpeed_m_min, 0),
                                 num(pl.candidate.finishing.feed_mm_rev, 3),
                                 num(pl.candidate.finishing.depthOfCut_mm, 3)) +
                        (pl.candidate.roughingPasses > 0
                             ? Report::tr("%n roughing pass(es) at vc %1 m/min, f %2 mm/rev.", nullptr,
                                          pl.candidate.roughingPasses)
                                   .arg(num(pl.candidate.roughing.cuttingSpeed_m_min, 0),
                                        num(pl.candidate.roughing.feed_mm_rev, 3))
                             : Report::tr("no roughing: the finishing pass takes the whole stock.")));
            QStringList binding;
            for (const ConstraintValue &c : pl.binding)
                binding << c.label();
            for (const ConstraintValue &c : pl.conflicts)
                binding << Report::tr("%1 violated %2").arg(c.label(), c.violatedBy());
            if (!binding.isEmpty())
                l.paragraph(Report::tr("Binding: %1.").arg(binding.join(QStringLiteral(", "))));
            for (const QString &remedy : pl.remedies)
                l.paragraph(Report::tr("To meet it: %1").arg(remedy));
            // The plan's own notes (limits not known, tool life not in the objective, a search
            // again at the optimum's depth); the model's are under Assumptions.
            const QStringList &assumptions = r.problem->inputs().notes;
            for (const QString &note : pl.notes)
                if (!assumptions.contains(note))
                    l.paragraph(QStringLiteral("• ") + note, 8.5);
            windowMap(l, p, r);
            std::vector<QStringList> rows{{Report::tr("Rank"), Report::tr("Clamping"), Report::tr("Result")}};
            for (std::size_t i = 0; i < r.clamping.size(); ++i)
                rows.push_back({QString::number(i + 1), displayName(r.clamping[i].method), r.clamping[i].reason});
            l.table(rows, {36, 110, kWidth - 146});
        }
    }
    std::vector<QStringList> rows{{Report::tr("Feature"), Report::tr("Action"), Report::tr("Offset Ø [µm]"),
                                   Report::tr("Residual before [µm]"), Report::tr("Residual after [µm]")}};
    for (const FeatureCompensation &f : finishing.compensation.features)
        rows.push_back({f.featureId, compensationKeyword(f.action),
                        f.action == CompensationAction::ConstantOffset ? num(f.offset_um, 1) : QString(),
                        num(f.residualBefore_um, 3), num(f.residualAfter_um, 3)});
    l.paragraph(Report::tr("Compensation of the project's finishing pass, only where a tolerance needs it:"));
    l.table(rows, {70, 90, 90, 120, 120});
}

// The finishing pass's feed schedule (docs/adaptive.md §5): each feature's largest feed that holds
// its tolerances and the pass's limits, and the time it saves against the programmed feed.
struct ScheduledFinishing {
    FeedSchedule schedule;
    double before_s = 0.0; // the outer finishing pass at the programmed feed
    double after_s = 0.0;  // at the scheduled feeds
};

std::optional<ScheduledFinishing> scheduledFinishing(const Project &p,
                                                     const std::shared_ptr<const LoadedModel> &learned)
{
    if (!p.planning.feed_mm_rev)
        return std::nullopt; // no feed range: nothing to schedule within (the plan section says why)
    ScheduledFinishing f{scheduleProjectFinishingFeeds(p, DataLibrary::builtIn(), learned)};
    if (!f.schedule.ok())
        return std::nullopt;
    GCodeOptions options;
    f.before_s = 60.0 * outerFinishingTime_min(finishingOutput(p, DataLibrary::builtIn(), options).nominal.passes);
    options.finishingFeeds_mm_rev = f.schedule.feedByFeature();
    f.after_s = 60.0 * outerFinishingTime_min(finishingOutput(p, DataLibrary::builtIn(), options).nominal.passes);
    return f;
}

void feedSchedule(Layout &l, const std::optional<ScheduledFinishing> &scheduled)
{
    if (!scheduled)
        return;
    const FeedSchedule &s = scheduled->schedule;
    const double before = scheduled->before_s;
    const double after = scheduled->after_s;
    l.paragraph(
        Report::tr(
            "Feed schedule of the finishing pass (after Čuš and Župerl [8]): each feature at the largest "
            "feed of the range that holds its tolerances and the pass's limits; %1 s at the programmed %2 mm/rev, %3 s "
            "scheduled (%4 %). Programmed only on request (gcode --feed-schedule, the G-code tab).")
            .arg(num(before, 1), num(s.programmedFeed_mm_rev, 3), num(after, 1),
                 QString::asprintf("%+.1f", before > 0.0 ? 100.0 * (after - before) / before : 0.0)));
    std::vector<QStringList> rows{{Report::tr("Feature"), Report::tr("Feed [mm/rev]"), Report::tr("Limited by")}};
    for (const ScheduledFeed &f : s.features)
        rows.push_back(
            {f.featureId, num(f.feed_mm_rev, 3),
             f.held ? Report::tr("kept: %1 is not held at any feed of the range").arg(f.limitedBy) : f.limitedBy});
    l.table(rows, {70, 90, kWidth - 160});
}

void assumptions(Layout &l, const Project &p, const DeviationResult &d)
{
    // The milled features, when there are any, are section 6.
    l.heading(p.milledFeatures.empty() ? Report::tr("6  Assumptions") : Report::tr("7  Assumptions"));
    l.paragraph(Report::tr("What this prediction rests on, beyond the project's own values:"), 8.5);
    if (d.inputs) {
        for (const QString &note : d.inputs->notes)
            l.paragraph(QStringLiteral("• ") + note, 8.5);
    }
}

// The literature the model comes from, numbered, with what is used of each.
void literature(Layout &l, const Project &p)
{
    l.heading(Report::tr("Appendix A  Literature"));
    QStringList references{
        Report::tr("[1] G. Valiño, D. Blanco, B. J. Álvarez, S. Mateos: Machining error predictive model in a CAPP "
                   "system for turning: formulation and initial tests (2008). Used: eq. 2–8 (deviation), §III "
                   "(spindle–chuck springs from a test bar), §V and Fig. 4 (tolerances), §VI (optimisation)."),
        Report::tr("[2] X. Li, R. Du: Analysis and compensation of workpiece errors in turning. Int. J. Prod. Res. "
                   "40(7) (2002). Used: eq. 15–20 (forces with the nose radius), §3.4 (compensation)."),
        Report::tr("[3] O. Kienzle: Die Bestimmung von Kräften und Leistungen an spanenden Werkzeugen und "
                   "Werkzeugmaschinen. VDI-Z 94 (1952) 299–305. Used: the specific cutting force kc1.1 · h^-mc."),
        Report::tr("[4] G. R. Cowper: The shear coefficient in Timoshenko's beam theory. J. Appl. Mech. 33 (1966) "
                   "335–340. Used: the shear coefficient of solid and hollow round sections."),
        Report::tr("[5] ISO 286-1 and ISO 286-2: limits and fits (tolerance grades, fundamental deviations)."),
        Report::tr("[6] ISO 1101: geometrical tolerancing (form, orientation, location and run-out)."),
        Report::tr("[7] ISO 3002-1: basic quantities in cutting (entering and trailing edge angles)."),
        Report::tr("[8] F. Čuš, U. Župerl: Control strategy for assuring constant surface finish by controlling "
                   "cutting forces (University of Maribor, 2013). Used: eq. 1 (feed drive), §2 (20 ms constant-force "
                   "loop with feed override); TolTurn's feed schedule holds the tolerances feature by feature."),
        Report::tr("The equations as implemented, the corrections of printing errors and the validation against "
                   "closed forms: docs/model.md of TolTurn.")};
    if (!p.milledFeatures.empty()) // the milled features' model, before the closing note
        references.insert(references.size() - 1,
                          Report::tr("[9] E. Öztürk, E. Budak: 5-Eksen Frezelemede Kuvvet ve Şekil Hatalarının "
                                     "Modellenmesi (modelling the forces and form errors of 5-axis milling; in "
                                     "Turkish), Sabancı University. Used: eq. 1–11 (the forces of a ball-end mill at a "
                                     "lead and tilt), table 3 and §4 (the tool's deflection and the surface-normal "
                                     "error); the milled features' equations as implemented: docs/milling.md."));
    for (const QString &reference : references)
        l.paragraph(reference, 8.5);
}

// Where every number of the data library that this project used comes from.
void dataSources(Layout &l, const Project &p)
{
    l.heading(Report::tr("Appendix B  Sources of the data"));
    const DataLibrary &data = DataLibrary::builtIn();
    if (const MaterialData *m = data.material(p.materialId)) {
        l.paragraph(Report::tr("Material data (%1): %2").arg(m->id, data.sourceText(m->kc11_MPa.source)), 8.0);
        l.paragraph(Report::tr("Elastic constants: %1").arg(data.sourceText(m->youngsModulus_MPa.source)), 8.0);
    }
    if (p.characterisation.spindleRadial == std::nullopt) {
        if (const auto &chuck = data.uncharacterisedSupports().chuckRadial)
            l.paragraph(Report::tr("Chuck stiffness range: %1").arg(data.sourceText(chuck->compliant_N_per_mm.source)),
                        8.0);
    } else if (!p.characterisation.source.isEmpty()) {
        l.paragraph(Report::tr("Machine stiffness, measured: %1").arg(p.characterisation.source), 8.0);
    }
    if (!p.planning.rangesSource.isEmpty())
        l.paragraph(Report::tr("Cutting ranges: %1").arg(p.planning.rangesSource), 8.0);
    if (!p.planning.toolLifeSource.isEmpty())
        l.paragraph(Report::tr("Tool life: %1").arg(p.planning.toolLifeSource), 8.0);
}

ReportResult cancelledReport()
{
    ReportResult r;
    r.error = Report::tr("cancelled");
    r.cancelled = true;
    return r;
}

// The laid-out pages as an A4 PDF with the footer (program, part, page numbers) on each.
QByteArray pdfOf(const std::vector<std::unique_ptr<QPicture>> &pages, const Project &project)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter pdf(&buffer);
        pdf.setPageSize(QPageSize(QPageSize::A4));
        pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
        pdf.setResolution(600);
        pdf.setTitle(Report::tr("TolTurn report: %1").arg(project.part.name));
        pdf.setCreator(QStringLiteral("TolTurn %1").arg(tolturnVersion()));
        QPainter painter(&pdf);
        const double scale = pdf.resolution() / 72.0;
        for (std::size_t i = 0; i < pages.size(); ++i) {
            if (i > 0)
                pdf.newPage();
            painter.save();
            painter.scale(scale, scale);
            // drawPicture() rescales a picture by the ratio of the device's to the picture's
            // resolution; the page is laid out in points, so undo that ratio around the replay.
            const double replay = pages[i]->logicalDpiX() / static_cast<double>(pdf.logicalDpiX());
            painter.save();
            painter.scale(replay, replay);
            painter.drawPicture(QPointF(0, 0), *pages[i]);
            painter.restore();
            painter.setFont(font(8));
            painter.setPen(QColor(0x66, 0x66, 0x66));
            const QRectF footer(kMargin, kPageHeight - kMargin, kWidth, 14);
            const QString pageCount = Report::tr("page %1 of %2").arg(i + 1).arg(pages.size());
            const double forPageCount = QFontMetricsF(painter.font(), painter.device()).horizontalAdvance(pageCount);
            painter.drawText(
                footer, Qt::AlignLeft | Qt::AlignVCenter,
                withNameFitted(painter, QStringLiteral("TolTurn %1 — %2").arg(tolturnVersion(), QStringLiteral("%1")),
                               project.part.name, footer.width() - forPageCount - 12.0));
            painter.drawText(footer, Qt::AlignRight | Qt::AlignVCenter, pageCount);
            painter.restore();
        }
    }
    return bytes;
}

} // namespace

// What the report computes before it draws (report_writer.h).
struct ReportData {
    SetupPrediction prediction; // the verdicts, the curves and what they rest on
    FinishingOutput finishing;
    std::optional<PlanningReport> plan; // none without the insert's cutting ranges
    std::optional<ScheduledFinishing> schedule;
    std::vector<MilledFeatureEvaluation> milled;
};

std::shared_ptr<const ReportData> computeReport(const Project &project, const ReportHeader &header,
                                                const Progress &progress)
{
    auto d = std::make_shared<ReportData>();
    const DataLibrary &data = DataLibrary::builtIn();
    const LoadedModel *model = header.learned.get();
    // With what was learned: one prediction, physics + learned, for the verdicts, the compensation
    // and the plan as well. A model of another physics is left out (the first page says why).
    d->prediction = predictSetup(project, data, model);
    const std::shared_ptr<const LoadedModel> learned =
        model && learnedPhysicsMismatch(project, *model).isEmpty() ? header.learned : nullptr;
    model = learned.get();
    d->finishing =
        model ? finishingOutputFor(project, data, d->prediction.range.compliant) : finishingOutput(project, data);
    if (!progress.report(0.2))
        return nullptr;
    if (project.planning.cuttingSpeed_m_min) {
        PlanningJobOptions o;
        o.windowSize = 64;
        o.learned = learned;
        o.progress = Progress(progress, 0.2, 0.8);
        d->plan = runPlanningJob(project, data, o);
    }
    d->schedule = scheduledFinishing(project, learned);
    if (!progress.report(0.85))
        return nullptr;
    std::optional<std::vector<MilledFeatureEvaluation>> milled =
        report::evaluateMilledFeatures(project, Progress(progress, 0.85, 1.0));
    if (!milled)
        return nullptr;
    d->milled = std::move(*milled);
    (void)progress.report(1.0);
    return d;
}

RenderedReport renderReport(const Project &project, const ReportHeader &header, const ReportData &d)
{
    RenderedReport rendered;
    const SetupPrediction &prediction = d.prediction;
    std::vector<ToleranceEvaluation> verdictList;
    for (const ToleranceRangeEvaluation &e : prediction.range.tolerances)
        verdictList.push_back(e.compliant);

    Layout layout;
    titleBlock(layout, project, header);
    summary(layout, project, prediction.range, prediction.assumption);
    drawing(layout, project);
    inputs(layout, project, prediction.deviation, d.finishing);
    deviationPlots(layout, project, prediction.deviation, prediction.stiffEnd, prediction.learned);
    verdicts(layout, project, verdictList);
    plan(layout, project, d.finishing, d.plan);
    feedSchedule(layout, d.schedule);
    report::milledFeaturesSection(layout, project, Report::tr("6  Milled features"), d.milled);
    assumptions(layout, project, prediction.range.compliant);
    // The appendices (for reference, not for the shop floor) open a page unless a third of this
    // one is still free: no page is left holding a few lines.
    if (layout.remaining() < (report::kBottom - report::kMargin) / 3.0)
        layout.newPage();
    literature(layout, project);
    dataSources(layout, project);
    const std::vector<std::unique_ptr<QPicture>> pages = layout.finish();
    rendered.pdf = pdfOf(pages, project);
    rendered.pages = static_cast<int>(pages.size());
    return rendered;
}

RenderedReport renderReport(const Project &project, const ReportHeader &header, const Progress &progress)
{
    const std::shared_ptr<const ReportData> data = computeReport(project, header, progress);
    if (!data) {
        RenderedReport cancelled;
        cancelled.cancelled = true;
        return cancelled;
    }
    return renderReport(project, header, *data);
}

ReportResult writeReport(const Project &project, const ReportHeader &header, const ReportData &data,
                         const QString &pdfPath)
{
    ReportResult result;
    const RenderedReport rendered = renderReport(project, header, data);
    if (QString error = writeFileAtomically(pdfPath, rendered.pdf); !error.isEmpty()) {
        result.error = std::move(error);
        return result;
    }
    result.ok = true;
    result.pages = rendered.pages;
    return result;
}

ReportResult writeReport(const Project &project, const ReportHeader &header, const QString &pdfPath,
                         const Progress &progress)
{
    const std::shared_ptr<const ReportData> data = computeReport(project, header, progress);
    if (!data)
        return cancelledReport();
    return writeReport(project, header, *data, pdfPath);
}

} // namespace tolturn
