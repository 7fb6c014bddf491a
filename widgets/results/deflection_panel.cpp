// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/results/deflection_panel.h"

#include "core/cutting/cutting_quantities.h"
#include "core/project/keywords.h"
#include "widgets/plot/line_plot.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <cmath>
#include <functional>
#include <limits>

namespace tolturn {

namespace {

constexpr double kUmPerMm = 1000.0;
const double kGap = std::numeric_limits<double>::quiet_NaN();

struct CurveSpec {
    QString name;
    std::function<double(const Contributions &)> value;
    QColor color;
    Qt::PenStyle style;
    double width;
};

} // namespace

DeflectionPanel::DeflectionPanel(QWidget *parent)
    : QWidget(parent)
    , m_sideBox(new QComboBox(this))
    , m_quantityBox(new QComboBox(this))
    , m_plot(new LinePlot(this))
    , m_summary(new QLabel(this))
    , m_notes(new QLabel(this))
{
    setObjectName(QStringLiteral("deflectionPanel"));
    m_sideBox->addItem(tr("Outer contour"));
    m_sideBox->addItem(tr("Inner contour (bores)"));
    m_quantityBox->addItem(tr("Radial deviation by contribution"));
    m_quantityBox->addItem(tr("Tangential deviation by contribution"));
    m_quantityBox->addItem(tr("Diameter error"));
    m_quantityBox->addItem(tr("Face conicity"));
    m_quantityBox->setToolTip(tr("Radial deviation: material left on the surface, δ_T = δ_sc + δ_tp + δ_p + δ_th "
                                 "(Valiño et al. 2008, eq. 2). Diameter error: 2 (r - r_nominal) with the radial and "
                                 "tangential deviation combined exactly. Face conicity: the axial run-out "
                                 "e = h · tan θ of each faced surface, tan θ = dδ/dz at the face (eq. 12)."));
    auto *controls = new QHBoxLayout;
    controls->addWidget(m_sideBox);
    controls->addWidget(m_quantityBox);
    controls->addStretch();
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary->setObjectName(QStringLiteral("deflectionSummary"));
    m_notes->setWordWrap(true);
    m_notes->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_notes->setStyleSheet(QStringLiteral("color: #555;"));
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addWidget(m_plot, 1);
    layout->addWidget(m_summary);
    layout->addWidget(m_notes);
    connect(m_sideBox, &QComboBox::currentIndexChanged, this,
            [this](int index) { setSide(index == 0 ? ContourSide::Outer : ContourSide::Inner); });
    connect(m_quantityBox, &QComboBox::currentIndexChanged, this,
            [this](int index) { setQuantity(static_cast<Quantity>(index)); });
    connect(&DisplaySettings::instance(), &DisplaySettings::unitsChanged, this, &DeflectionPanel::redraw);
    clear();
}

void DeflectionPanel::showResult(const Project &project, DeviationResult result,
                                 std::optional<DeviationResult> stiffEnd, std::optional<LearnedCurves> learned)
{
    m_result = std::move(result);
    m_stiffEnd = std::move(stiffEnd);
    m_learned = std::move(learned);
    m_heldAtRight = project.clamping.heldEnd == PartEnd::Right;
    m_plot->setVisible(true);
    m_sideBox->setEnabled(!project.part.inner.empty());
    if (project.part.inner.empty() && m_side == ContourSide::Inner)
        m_sideBox->setCurrentIndex(0);
    updateTexts();
    redraw();
}

void DeflectionPanel::showPrediction(const Project &project, const SetupPrediction &prediction)
{
    showResult(project, prediction.deviation, prediction.stiffEnd, prediction.learned);
}

void DeflectionPanel::clear(const QString &why)
{
    m_result = {};
    m_stiffEnd.reset();
    m_learned.reset();
    m_plot->clear();
    m_plot->rescaleAndReplot();
    m_plot->setVisible(false); // empty axes would say nothing
    m_summary->setText(why.isEmpty() ? tr("The predicted deviation of every feature appears here once a part is open.")
                                     : why);
    m_notes->clear();
}

void DeflectionPanel::setSide(ContourSide side)
{
    m_side = side;
    m_sideBox->setCurrentIndex(side == ContourSide::Outer ? 0 : 1);
    m_summary->setText(summaryText()); // the bores' own tool, when there is one
    redraw();
}

void DeflectionPanel::setQuantity(Quantity quantity)
{
    m_quantity = quantity;
    m_quantityBox->setCurrentIndex(static_cast<int>(quantity));
    redraw();
}

void DeflectionPanel::redraw()
{
    m_plot->clear();
    if (m_result.inputs) {
        switch (m_quantity) {
        case Quantity::RadialContributions:
            plotContributions(true);
            break;
        case Quantity::TangentialContributions:
            plotContributions(false);
            break;
        case Quantity::DiameterError:
            plotDiameterError();
            break;
        case Quantity::FaceConicity:
            plotFaceConicity();
            break;
        }
    }
    m_plot->rescaleAndReplot();
}

void DeflectionPanel::addContributionCurves(LinePlot &plot, const DeviationResult &result, ContourSide side,
                                            bool radial, const DisplayUnits &units)
{
    const std::vector<CurveSpec> specs{
        {tr("total"), [](const Contributions &c) { return c.total_mm(); }, QColor(0x20, 0x20, 0x20), Qt::SolidLine,
         2.4},
        {tr("spindle–chuck / supports"), [](const Contributions &c) { return c.spindleChuck_mm; },
         QColor(0x1f, 0x77, 0xb4), Qt::SolidLine, 1.5},
        {tr("workpiece"), [](const Contributions &c) { return c.workpiece_mm; }, QColor(0x2c, 0xa0, 0x2c),
         Qt::SolidLine, 1.5},
        {tr("toolpost"), [](const Contributions &c) { return c.toolpost_mm; }, QColor(0xff, 0x7f, 0x0e), Qt::DashLine,
         1.5},
        {tr("thermal"), [](const Contributions &c) { return c.thermal_mm; }, QColor(0xd6, 0x27, 0x28), Qt::DashDotLine,
         1.5},
        {tr("boring bar"), [](const Contributions &c) { return c.boringBar_mm; }, QColor(0x94, 0x67, 0xbd),
         Qt::DashLine, 1.5},
    };
    const bool bar = side == ContourSide::Inner && result.inputs && result.inputs->boring;
    for (const CurveSpec &spec : specs) {
        if (!radial && (spec.name == tr("toolpost") || spec.name == tr("thermal")))
            continue; // radial-only terms
        if (spec.name == tr("boring bar") && !bar)
            continue; // the bar cuts the bores only
        QVector<double> x;
        QVector<double> y;
        for (const FeatureDeviation &f : result.features) {
            if (f.side != side)
                continue;
            for (const Station &st : f.stations) {
                x << units.lengthFromMm(st.z_mm);
                y << units.deviationFromUm(spec.value(radial ? st.radial : st.tangential) * kUmPerMm);
            }
            x << units.lengthFromMm(f.stations.back().z_mm); // break the curve at the end of each feature
            y << kGap;
        }
        plot.addCurve(spec.name, x, y, spec.color, spec.style, spec.width);
    }
}

void DeflectionPanel::plotContributions(bool radial)
{
    const DisplayUnits units = DisplaySettings::instance().units();
    addContributionCurves(*m_plot, m_result, m_side, radial, units);
    if (m_stiffEnd)
        addRangeBand(
            *m_plot, m_result, *m_stiffEnd, m_side,
            [radial](const Station &st) { return (radial ? st.radial : st.tangential).total_mm(); }, tr("total"),
            units);
    // What was learned corrects the machined radius: as material left it is + on an outer
    // surface and − in a bore (radiusError_mm's sign convention).
    if (radial && m_learned)
        addLearnedTotal(*m_plot, m_result, *m_learned, m_side, units);
    m_plot->setTitle(radial ? tr("Radial deviation (material left on the surface)") : tr("Tangential deviation"));
    m_plot->setAxisLabels(zAxisLabel(units), tr("deviation [%1]").arg(units.deviationSymbol()));
}

void DeflectionPanel::plotDiameterError()
{
    const DisplayUnits units = DisplaySettings::instance().units();
    QVector<double> x;
    QVector<double> y;
    for (const FeatureDeviation &f : m_result.features) {
        if (f.side != m_side)
            continue;
        for (const Station &st : f.stations) {
            x << units.lengthFromMm(st.z_mm);
            y << units.deviationFromUm(2.0 * st.radiusError_mm * kUmPerMm);
        }
        x << units.lengthFromMm(f.stations.back().z_mm);
        y << kGap;
    }
    m_plot->addCurve(tr("diameter error"), x, y, QColor(0x6a, 0x3d, 0x9a), Qt::SolidLine, 2.2);
    if (m_stiffEnd)
        addRangeBand(
            *m_plot, m_result, *m_stiffEnd, m_side, [](const Station &st) { return 2.0 * st.radiusError_mm; },
            tr("diameter error"), units);
    if (m_learned)
        addLearnedCurve(
            *m_plot, m_result, *m_learned, m_side,
            [](const Station &st, double learned) { return 2.0 * (st.radiusError_mm + learned); }, 2.0,
            tr("diameter error, physics + learned"), units);
    m_plot->setTitle(tr("Diameter error: machined minus nominal"));
    m_plot->setAxisLabels(zAxisLabel(units), tr("diameter error [%1]").arg(units.deviationSymbol()));
}

void DeflectionPanel::addLearnedTotal(LinePlot &plot, const DeviationResult &result, const LearnedCurves &learned,
                                      ContourSide side, const DisplayUnits &units)
{
    // What was learned corrects the machined radius: as material left it is + on an outer
    // surface and − in a bore (radiusError_mm's sign convention).
    addLearnedCurve(
        plot, result, learned, side,
        [side](const Station &st, double l) { return st.radial.total_mm() + (side == ContourSide::Outer ? l : -l); },
        1.0, tr("total, physics + learned"), units);
}

void DeflectionPanel::addLearnedCurve(LinePlot &plot, const DeviationResult &result, const LearnedCurves &learned,
                                      ContourSide side, const std::function<double(const Station &, double)> &value,
                                      double scale, const QString &name, const DisplayUnits &units)
{
    const double u = scale * learned.uncertainty_mm;
    QVector<double> x;
    QVector<double> y;
    QVector<double> lower;
    QVector<double> upper;
    for (std::size_t f = 0; f < result.features.size() && f < learned.atStations.size(); ++f) {
        const FeatureDeviation &feature = result.features[f];
        const std::vector<double> &add = learned.atStations[f];
        if (feature.side != side || add.size() != feature.stations.size())
            continue;
        for (std::size_t i = 0; i < add.size(); ++i) {
            const double v = value(feature.stations[i], add[i]);
            x << units.lengthFromMm(feature.stations[i].z_mm);
            y << units.deviationFromUm(v * kUmPerMm);
            lower << units.deviationFromUm((v - u) * kUmPerMm);
            upper << units.deviationFromUm((v + u) * kUmPerMm);
        }
        x << units.lengthFromMm(feature.stations.back().z_mm);
        y << kGap;
        lower << kGap;
        upper << kGap;
    }
    const QString rms = QString::number(u * kUmPerMm, 'f', 1);
    plot.addBand(tr("%1 − %2 µm").arg(name, rms), tr("%1 + %2 µm").arg(name, rms), x, lower, upper,
                 QColor(0x9a, 0x6a, 0x00));
    plot.addCurve(name, x, y, QColor(0x9a, 0x6a, 0x00), Qt::SolidLine, 2.6);
}

// Where the machine is a stiffness range, the band of one quantity between the compliant end (the
// curves drawn) and the stiff end.
void DeflectionPanel::addRangeBand(LinePlot &plot, const DeviationResult &result, const DeviationResult &stiffEnd,
                                   ContourSide side, const std::function<double(const Station &)> &value,
                                   const QString &what, const DisplayUnits &units)
{
    if (stiffEnd.features.size() != result.features.size())
        return;
    QVector<double> x;
    QVector<double> compliant;
    QVector<double> stiff;
    for (std::size_t i = 0; i < result.features.size(); ++i) {
        const FeatureDeviation &f = result.features[i];
        const FeatureDeviation &g = stiffEnd.features[i];
        if (f.side != side || f.stations.size() != g.stations.size())
            continue;
        for (std::size_t j = 0; j < f.stations.size(); ++j) {
            x << units.lengthFromMm(f.stations[j].z_mm);
            compliant << units.deviationFromUm(value(f.stations[j]) * kUmPerMm);
            stiff << units.deviationFromUm(value(g.stations[j]) * kUmPerMm);
        }
        x << units.lengthFromMm(f.stations.back().z_mm);
        compliant << kGap;
        stiff << kGap;
    }
    plot.addBand(tr("%1, compliant end of the machine range").arg(what),
                 tr("%1 over the machine's stiffness range").arg(what), x, compliant, stiff, QColor(0x55, 0x55, 0x99));
}

// Each face of the chosen contour as a stem at its z: its axial run-out e (Valiño et al. 2008,
// eq. 12), the tilt tan θ of the face times its radial height.
void DeflectionPanel::plotFaceConicity()
{
    const DisplayUnits units = DisplaySettings::instance().units();
    QVector<double> x;
    QVector<double> y;
    for (const FaceConicity &f : m_result.faces) {
        if (f.side != m_side)
            continue;
        x << units.lengthFromMm(f.z_mm);
        y << units.deviationFromUm(f.axialRunout_mm * kUmPerMm);
    }
    m_plot->addStems(tr("axial run-out e of each face"), x, y, QColor(0x8c, 0x56, 0x4b));
    m_plot->setTitle(tr("Face conicity: axial run-out of each face"));
    m_plot->setAxisLabels(zAxisLabel(units), tr("axial run-out e [%1]").arg(units.deviationSymbol()));
}

// z runs from the end the set-up holds: the drawing's left end, or its right end when the part is
// held turned end for end (docs/operations.md).
QString DeflectionPanel::zAxisLabel(const DisplayUnits &units) const
{
    return m_heldAtRight ? tr("z from the held (right) end [%1]").arg(units.lengthSymbol())
                         : tr("z from the part's left end [%1]").arg(units.lengthSymbol());
}

QString DeflectionPanel::summaryText() const
{
    if (!m_result.inputs)
        return {};
    const TurningInputs &in = *m_result.inputs;
    // The roughness this side's tool leaves: the boring bar's insert in the bores.
    const double noseRadius = m_side == ContourSide::Inner && in.boring ? in.boring->noseRadius_mm : in.noseRadius_mm;
    return tr("Forces (%1): Fc %2 N, Ff %3 N, Fp %4 N · pass %5: vc %6 m/min, f %7 mm/rev, ap %8 mm · Ra %9 µm")
               .arg(forceModelName(in.forceModel), QString::number(in.forces.tangential_N, 'f', 0),
                    QString::number(in.forces.axial_N, 'f', 0), QString::number(in.forces.radial_N, 'f', 0),
                    QString::number(in.passIndex + 1), formatNumber(in.pass.cuttingSpeed_m_min),
                    formatNumber(in.pass.feed_mm_rev), formatNumber(in.pass.depthOfCut_mm),
                    QString::number(theoreticalRa_um(in.pass.feed_mm_rev, noseRadius), 'f', 2)) +
           boringSummary(in);
}

// In the bores, the boring bar's own forces and its tip compliance (docs/model.md §3.1).
QString DeflectionPanel::boringSummary(const TurningInputs &in) const
{
    if (m_side != ContourSide::Inner || !in.boring)
        return {};
    const BoringInputs &b = *in.boring;
    return tr(" · bores: bar %1, L/D %2, Fc %3 N, Ff %4 N, Fp %5 N, %6 µm/N at its tip")
        .arg(b.holderCode, QString::number(b.bar.overhangRatio(), 'f', 1),
             QString::number(b.forces.tangential_N, 'f', 0), QString::number(b.forces.axial_N, 'f', 0),
             QString::number(b.forces.radial_N, 'f', 0),
             QString::number(b.compliance.transverse_mm_per_N() * 1000.0, 'g', 3));
}

void DeflectionPanel::updateTexts()
{
    m_summary->setText(summaryText());
    QStringList lines;
    for (const Diagnostic &d : m_result.diagnostics)
        lines << (d.severity == Severity::Error ? tr("Error: ") : tr("Warning: ")) + d.toString();
    if (m_result.inputs)
        lines += m_result.inputs->notes;
    if (m_learned)
        lines << tr("Physics + learned (%1): what was learned of the machine from its measured parts is added to the "
                    "physics; the band is ± the RMS error on parts not learned from (%2 µm).")
                     .arg(m_learned->provenance, QString::number(m_learned->uncertainty_mm * kUmPerMm, 'f', 1));
    m_notes->setText(lines.join(QLatin1Char('\n')));
}

} // namespace tolturn
