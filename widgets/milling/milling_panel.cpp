// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/milling/milling_panel.h"

#include "core/milling/seed_ball_end_cases.h"
#include "widgets/common/worker_threads.h"
#include "widgets/milling/milled_features_box.h"
#include "widgets/plot/line_plot.h"
#include "widgets/plot/map_plot.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tolturn {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

QDoubleSpinBox *spin(double lo, double hi, int decimals, const QString &suffix, double value)
{
    auto *box = new QDoubleSpinBox;
    box->setRange(lo, hi);
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    box->setValue(value);
    box->setKeyboardTracking(false);
    return box;
}

// An angle in degrees to one decimal, without a "−0.0".
QString angleText(double rad)
{
    const double rounded = std::round(rad / kDegree * 10.0) / 10.0;
    return QString::number(rounded == 0.0 ? 0.0 : rounded, 'f', 1);
}

QVector<double> degrees(const std::vector<BallEndForceSample> &samples)
{
    QVector<double> x;
    x.reserve(static_cast<qsizetype>(samples.size()));
    for (const BallEndForceSample &s : samples)
        x.append(s.rotation_rad / kDegree);
    return x;
}

// Cells coloured by the largest feed that holds the tolerance (lighter is faster); red where no feed
// does, grey where the cut would reach the shank.
QImage windowImage(const LeadTiltWindow &w, double highestFeed)
{
    QImage image(w.columns, w.rows, QImage::Format_RGB32);
    for (int row = 0; row < w.rows; ++row)
        for (int column = 0; column < w.columns; ++column) {
            const LeadTiltCell &c = w.at(column, row);
            QColor color(190, 190, 190);
            if (c.onBall && c.largestFeed_mm <= 0.0)
                color = QColor(214, 96, 77);
            else if (c.onBall) {
                const auto t = static_cast<float>(std::clamp(c.largestFeed_mm / highestFeed, 0.0, 1.0));
                color = QColor::fromRgbF(0.15f + 0.70f * t, 0.35f + 0.55f * t, 0.55f + 0.25f * t);
            }
            image.setPixel(column, row, color.rgb());
        }
    return image;
}

} // namespace

MillingPanel::MillingPanel(ProjectDocument *document, QWidget *parent) : QWidget(parent)
{
    auto *inputs = new QWidget;
    auto *inputsLayout = new QVBoxLayout(inputs);
    inputsLayout->setContentsMargins(0, 0, 0, 0);
    if (document) {
        m_features = new MilledFeaturesBox(
            document, [this](MilledFeature f) { return completeFeature(std::move(f)); },
            [this] { return featureProblem(); });
        inputsLayout->addWidget(m_features);
        connect(m_features, &MilledFeaturesBox::featureChosen, this, &MillingPanel::loadFeature);
        connect(m_features, &MilledFeaturesBox::message, this, [this](const QString &text) {
            m_summary->setText(QStringLiteral("<b>%1</b>").arg(text.toHtmlEscaped()));
        });
    }
    inputsLayout->addWidget(createToolAndCut());
    inputsLayout->addWidget(createStructureAndTolerance());
    inputsLayout->addStretch();
    auto *scroll = new QScrollArea;
    scroll->setWidget(inputs);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setMinimumWidth(inputs->sizeHint().width() + 24);
    auto *layout = new QHBoxLayout(this);
    layout->addWidget(scroll);
    layout->addWidget(createPlots(), 1);
    connect(&m_watcher, &QFutureWatcher<MillingPlanOutcome>::finished, this, [this] {
        const MillingPlanOutcome outcome = m_watcher.result();
        m_plan = outcome.plan;
        updatePlanButton();
        if (m_plan)
            showWindow();
        else
            m_planSummary->setText(tr("No plan: %1").arg(outcome.error));
        Q_EMIT planFinished();
    });
    loadCase(1);
}

QWidget *MillingPanel::createToolAndCut()
{
    auto *box = new QGroupBox(tr("Ball-end cut"));
    auto *form = new QFormLayout(box);
    m_case = new QComboBox;
    m_case->setObjectName(QStringLiteral("millingCase"));
    for (int i = 1; i <= 4; ++i)
        m_case->addItem(tr("Öztürk & Budak, case %1").arg(i), i);
    m_case->addItem(tr("Own cut"), 0);
    m_case->setToolTip(tr("001 table 4: a DMU 50 Evolution, Ø12 mm ball-end mills with a 30° helix, Ti6Al4V"));
    form->addRow(tr("Example"), m_case);
    m_diameter = spin(0.5, 100.0, 2, tr(" mm"), 12.0);
    m_flutes = new QSpinBox;
    m_flutes->setRange(1, 12);
    m_helix = spin(0.0, 59.0, 1, tr("°"), 30.0);
    m_lead = spin(-60.0, 60.0, 2, tr("°"), 0.0);
    m_tilt = spin(-60.0, 60.0, 2, tr("°"), 0.0);
    m_kind = new QComboBox;
    m_kind->addItems({tr("Slot"), tr("Side cut (uncut material)"), tr("Step-over (beside a pass)")});
    m_direction = new QComboBox;
    m_direction->addItems({tr("Down milling"), tr("Up milling")});
    m_radialDepth = spin(0.001, 100.0, 4, tr(" mm"), 1.0);
    m_axialDepth = spin(0.001, 50.0, 3, tr(" mm"), 1.0);
    m_feedPerTooth = spin(0.0001, 2.0, 5, tr(" mm"), 0.1);
    m_spindle = spin(1.0, 100000.0, 0, tr(" 1/min"), 1000.0);
    m_coefficients = new QLineEdit;
    m_coefficients->setObjectName(QStringLiteral("millingCoefficients"));
    m_coefficients->setPlaceholderText(tr("Ktc, Krc, Kac (N/mm²), Kte, Kre, Kae (N/mm)"));
    m_coefficients->setToolTip(tr("The cutting and edge coefficients of your tool and material (001 eq. 11). "
                                  "001 prints none, and TolTurn's data library has none for ball-end milling."));
    form->addRow(tr("Diameter"), m_diameter);
    form->addRow(tr("Flutes"), m_flutes);
    form->addRow(tr("Helix"), m_helix);
    form->addRow(tr("Lead"), m_lead);
    form->addRow(tr("Tilt"), m_tilt);
    form->addRow(tr("Cut"), m_kind);
    form->addRow(tr("Direction"), m_direction);
    form->addRow(tr("Radial depth / step-over"), m_radialDepth);
    form->addRow(tr("Axial depth"), m_axialDepth);
    form->addRow(tr("Feed per tooth"), m_feedPerTooth);
    form->addRow(tr("Spindle speed"), m_spindle);
    form->addRow(tr("Coefficients"), m_coefficients);
    connect(m_case, &QComboBox::activated, this, [this] {
        if (const int n = m_case->currentData().toInt(); n > 0)
            loadCase(n);
    });
    const auto edited = [this] {
        if (m_loading)
            return;
        m_case->setCurrentIndex(m_case->count() - 1);
        compute();
    };
    for (QDoubleSpinBox *b :
         {m_diameter, m_helix, m_lead, m_tilt, m_radialDepth, m_axialDepth, m_feedPerTooth, m_spindle})
        connect(b, &QDoubleSpinBox::valueChanged, this, edited);
    connect(m_flutes, &QSpinBox::valueChanged, this, edited);
    connect(m_kind, &QComboBox::activated, this, edited);
    connect(m_direction, &QComboBox::activated, this, edited);
    connect(m_coefficients, &QLineEdit::editingFinished, this, &MillingPanel::compute);
    return box;
}

QWidget *MillingPanel::createStructureAndTolerance()
{
    auto *box = new QGroupBox(tr("Tool structure and tolerance"));
    auto *form = new QFormLayout(box);
    m_overhang = spin(0.0, 1000.0, 1, tr(" mm"), 0.0);
    m_overhang->setObjectName(QStringLiteral("millingOverhang"));
    m_overhang->setSpecialValueText(tr("not given"));
    m_overhang->setToolTip(tr("From where the holder grips the tool to its tip"));
    m_equivalentDiameter = spin(0.0, 100.0, 2, tr(" mm"), 0.0);
    m_equivalentDiameter->setObjectName(QStringLiteral("millingEquivalentDiameter"));
    m_equivalentDiameter->setSpecialValueText(tr("not given"));
    m_equivalentDiameter->setToolTip(tr("The diameter of the solid cylinder that bends like the fluted tool"));
    m_modulus = spin(1000.0, 1.2e6, 0, tr(" N/mm²"), kCarbideModulus_N_mm2);
    m_modulus->setToolTip(tr("Tungsten carbide 630 000 N/mm² (MakeItFrom); cemented carbides 530 000–700 000"));
    m_holderStiffness = spin(1.0, 1e9, 0, tr(" N/mm"), kSeedHolderStiffness_N_mm);
    m_holderRotational = spin(1.0, 1e12, 0, tr(" N·mm/rad"), kSeedHolderRotational_N_mm_rad);
    m_springSource = new QLabel;
    m_springSource->setWordWrap(true);
    m_tolerance = spin(0.01, 10000.0, 2, tr(" µm"), 20.0);
    m_zone = new QComboBox;
    m_zone->addItems({tr("Flatness"), tr("Profile without datums"), tr("Profile with datums (±t/2)")});
    m_zone->setToolTip(tr("ISO 1101: a flatness and a profile without datums float (the spread within t); a "
                          "profile with datums is located on the programmed surface (within ±t/2)"));
    m_highestFeed = spin(0.001, 2.0, 4, tr(" mm"), 0.15);
    m_highestFeed->setToolTip(tr("The largest feed per tooth the tool's maker allows"));
    m_planButton = new QPushButton(tr("Plan Lead, Tilt and Feed"));
    m_planButton->setObjectName(QStringLiteral("millingPlanButton"));
    form->addRow(tr("Overhang"), m_overhang);
    form->addRow(tr("Equivalent diameter"), m_equivalentDiameter);
    form->addRow(tr("Young's modulus"), m_modulus);
    form->addRow(tr("Holder k"), m_holderStiffness);
    form->addRow(tr("Holder k_θ"), m_holderRotational);
    form->addRow(m_springSource);
    form->addRow(tr("Surface tolerance t"), m_tolerance);
    form->addRow(tr("Zone"), m_zone);
    m_datums = new QLineEdit;
    m_datums->setObjectName(QStringLiteral("millingDatums"));
    m_datums->setPlaceholderText(tr("A, B"));
    m_datums->setEnabled(false);
    form->addRow(tr("Datums"), m_datums);
    form->addRow(tr("Largest feed per tooth"), m_highestFeed);
    for (QDoubleSpinBox *b : {m_overhang, m_equivalentDiameter, m_modulus, m_holderStiffness, m_holderRotational,
                              m_tolerance, m_highestFeed})
        connect(b, &QDoubleSpinBox::valueChanged, this, [this] {
            if (!m_loading)
                compute();
        });
    for (QDoubleSpinBox *spring : {m_holderStiffness, m_holderRotational})
        connect(spring, &QDoubleSpinBox::valueChanged, this, [this] {
            if (!m_loading)
                m_springSource->setText(tr("Holder springs: as entered."));
        });
    connect(m_zone, &QComboBox::activated, this, [this] {
        m_datums->setEnabled(m_zone->currentIndex() == 2);
        compute();
    });
    connect(m_planButton, &QPushButton::clicked, this, &MillingPanel::plan);
    return box;
}

QWidget *MillingPanel::createPlots()
{
    auto *panel = new QWidget;
    auto *layout = new QVBoxLayout(panel);
    layout->setContentsMargins(0, 0, 0, 0);
    m_summary = new QLabel;
    m_summary->setObjectName(QStringLiteral("millingSummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_tabs = new QTabWidget;
    m_forcePlot = new LinePlot;
    m_forcePlot->setAxisLabels(tr("rotation angle [°]"), tr("force on the tool [N]"));
    m_errorPlot = new LinePlot;
    m_errorPlot->setAxisLabels(tr("rotation angle [°]"), tr("surface-normal error [µm]"));
    auto *windowPage = new QWidget;
    auto *windowLayout = new QVBoxLayout(windowPage);
    m_windowPlot = new MapPlot;
    m_windowPlot->setAxisLabels(tr("lead [°]"), tr("tilt [°]"));
    m_planSummary = new QLabel(tr("Plan to see the largest feed per tooth that holds the tolerance at each lead "
                                  "and tilt."));
    m_planSummary->setObjectName(QStringLiteral("millingPlanSummary"));
    m_planSummary->setWordWrap(true);
    m_planSummary->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_planSummary->setMinimumHeight(2 * m_planSummary->fontMetrics().lineSpacing() + 4);
    auto *header = new QHBoxLayout;
    header->addWidget(m_planButton, 0, Qt::AlignTop);
    header->addWidget(m_planSummary, 1);
    windowLayout->addLayout(header);
    windowLayout->addWidget(m_windowPlot, 1);
    m_tabs->addTab(m_forcePlot, tr("Forces"));
    m_tabs->addTab(m_errorPlot, tr("Surface error"));
    m_tabs->addTab(windowPage, tr("Lead–tilt window"));
    if (m_features)
        m_tabs->addTab(m_features->pathPlot(), tr("Along the path"));
    layout->addWidget(m_summary);
    layout->addWidget(m_tabs, 1);
    return panel;
}

void MillingPanel::loadCase(int number)
{
    const std::vector<SeedBallEndCase> cases = seedBallEndCases();
    const SeedBallEndCase &c = cases.at(static_cast<std::size_t>(std::clamp(number, 1, 4) - 1));
    m_loading = true;
    m_case->setCurrentIndex(c.number - 1);
    m_diameter->setValue(c.mill.diameter_mm);
    m_flutes->setValue(c.mill.flutes);
    m_helix->setValue(c.mill.helix_rad / kDegree);
    m_lead->setValue(c.cut.lead_rad / kDegree);
    m_tilt->setValue(c.cut.tilt_rad / kDegree);
    m_kind->setCurrentIndex(static_cast<int>(c.cut.kind));
    m_direction->setCurrentIndex(static_cast<int>(c.cut.direction));
    if (c.cut.kind != BallEndCutKind::Slot)
        m_radialDepth->setValue(c.cut.radialDepth_mm);
    m_axialDepth->setValue(c.cut.axialDepth_mm);
    m_feedPerTooth->setValue(c.cut.feedPerTooth_mm);
    m_spindle->setValue(c.spindle_rpm);
    m_holderStiffness->setValue(kSeedHolderStiffness_N_mm);
    m_holderRotational->setValue(kSeedHolderRotational_N_mm_rad);
    m_springSource->setText(tr("Holder springs: 001's calibration for its Ø12 mm tool and holder, under 1000 N."));
    m_loading = false;
    compute();
}

MillingPanel::Inputs MillingPanel::inputs() const
{
    Inputs in;
    in.mill = {m_diameter->value(), m_flutes->value(), m_helix->value() * kDegree};
    in.cut.kind = static_cast<BallEndCutKind>(m_kind->currentIndex());
    in.cut.direction = static_cast<MillingDirection>(m_direction->currentIndex());
    in.cut.radialDepth_mm = m_radialDepth->value();
    in.cut.axialDepth_mm = m_axialDepth->value();
    in.cut.feedPerTooth_mm = m_feedPerTooth->value();
    in.cut.lead_rad = m_lead->value() * kDegree;
    in.cut.tilt_rad = m_tilt->value() * kDegree;
    in.spindle_rpm = m_spindle->value();
    in.coefficients = parseMillingCoefficients(m_coefficients->text());
    in.tool = {m_overhang->value(), m_equivalentDiameter->value(), m_modulus->value(), m_holderStiffness->value(),
               m_holderRotational->value()};
    in.tolerance = {m_tolerance->value() / 1000.0,
                    m_zone->currentIndex() == 2 ? SurfaceZone::Located : SurfaceZone::Floating};
    in.settings.leadLowest_rad = in.settings.tiltLowest_rad = -40.0 * kDegree;
    in.settings.leadHighest_rad = in.settings.tiltHighest_rad = 40.0 * kDegree;
    in.settings.highestFeedPerTooth_mm = m_highestFeed->value();
    return in;
}

QStringList MillingPanel::problems(const Inputs &in) const
{
    QStringList list;
    if (!in.coefficients)
        list << (m_coefficients->text().trimmed().isEmpty()
                     ? tr("Coefficients: not given. Enter Ktc, Krc, Kac, Kte, Kre, Kae of your tool and material: "
                          "Öztürk & Budak print none (theirs come from a Ti6Al4V orthogonal-cutting database), and "
                          "TolTurn's data library has none for ball-end milling.")
                     : tr("Coefficients: \"%1\" is not six numbers of at most 100 000.").arg(m_coefficients->text()));
    for (const std::string &p : validateBallEndCut(in.mill, in.cut, {}))
        list << QString::fromStdString(p);
    return list;
}

void MillingPanel::clearResults(const QString &why)
{
    m_forcePlot->clear();
    m_forcePlot->rescaleAndReplot();
    m_errorPlot->clear();
    m_errorPlot->rescaleAndReplot();
    m_summary->setText(why);
    m_planButton->setEnabled(false);
}

void MillingPanel::compute()
{
    const Inputs in = inputs();
    if (const QStringList p = problems(in); !p.isEmpty()) {
        QStringList escaped;
        for (const QString &line : p)
            escaped << line.toHtmlEscaped();
        clearResults(QStringLiteral("<b>%1</b>").arg(escaped.join(QStringLiteral("<br>"))));
        return;
    }
    const std::vector<std::string> structure = validateToolStructure(in.tool, in.mill);
    BallEndDeflection result;
    if (structure.empty())
        result = ballEndDeflection(in.mill, in.tool, *in.coefficients, in.cut, {});
    else
        result.forces = ballEndForces(in.mill, *in.coefficients, in.cut, {});
    showForces(in, result);
    if (structure.empty()) {
        showError(in, result);
    } else {
        m_errorPlot->clear();
        m_errorPlot->rescaleAndReplot();
        // A field left at "not given" is named as such, not by the 0 behind it.
        const QString missing = m_overhang->value() == 0.0             ? tr("give the tool's overhang")
                                : m_equivalentDiameter->value() == 0.0 ? tr("give the tool's equivalent diameter")
                                                                       : QString::fromStdString(structure.front());
        m_summary->setText(
            m_summary->text() +
            QStringLiteral("<br><b>%1</b>").arg(tr("No surface error: %1").arg(missing).toHtmlEscaped()));
    }
    updatePlanButton();
    if (m_plan && !isPlanning())
        m_planSummary->setText(tr("The inputs have changed since this plan: plan again."));
}

void MillingPanel::updatePlanButton()
{
    const Inputs in = inputs();
    m_planButton->setEnabled(!isPlanning() && problems(in).isEmpty() &&
                             validateToolStructure(in.tool, in.mill).empty());
}

void MillingPanel::showForces(const Inputs &in, const BallEndDeflection &result)
{
    const QVector<double> x = degrees(result.forces);
    QVector<double> f, c, n, resultant;
    for (const BallEndForceSample &s : result.forces) {
        f.append(s.workpieceFrame_N.x());
        c.append(s.workpieceFrame_N.y());
        n.append(s.workpieceFrame_N.z());
        resultant.append(s.workpieceFrame_N.norm());
    }
    m_forcePlot->clear();
    m_forcePlot->addCurve(tr("F (feed)"), x, f, QColor(31, 119, 180));
    m_forcePlot->addCurve(tr("C (cross-feed)"), x, c, QColor(255, 127, 14));
    m_forcePlot->addCurve(tr("N (normal)"), x, n, QColor(44, 160, 44));
    m_forcePlot->addCurve(tr("resultant"), x, resultant, Qt::black, Qt::DashLine);
    m_forcePlot->rescaleAndReplot();
    m_forcePlot->setXRange(0.0, 360.0);
    const BallEndForceSummary s = summarise(result.forces);
    m_summary->setText(tr("Peak resultant %1 N; mean torque %2 N·m, mean spindle power %3 W. Coefficients as "
                          "entered; only the tool deflects (001 §4).")
                           .arg(s.peakResultant_N, 0, 'f', 1)
                           .arg(s.meanTorque_N_mm / 1000.0, 0, 'f', 3)
                           .arg(spindlePower_W(s.meanTorque_N_mm, in.spindle_rpm), 0, 'f', 1));
}

void MillingPanel::showError(const Inputs &in, const BallEndDeflection &result)
{
    const QVector<double> x = degrees(result.forces);
    QVector<double> normal;
    for (const BallEndDeflectionSample &d : result.deflection)
        normal.append(1000.0 * d.surfaceNormal_mm());
    const double t_um = 1000.0 * in.tolerance.tolerance_mm;
    const bool floating = in.tolerance.zone == SurfaceZone::Floating;
    // The zone: from the least error up by t when it floats, ±t/2 about the programmed surface
    // when it is located.
    const double lower = floating ? 1000.0 * result.leastSurfaceNormal_mm : -0.5 * t_um;
    m_errorPlot->clear();
    m_errorPlot->addCurve(tr("δ_N"), x, normal, QColor(31, 119, 180));
    m_errorPlot->addCurve(tr("zone, lower"), {0.0, 360.0}, {lower, lower}, QColor(214, 39, 40), Qt::DashLine, 1.0);
    m_errorPlot->addCurve(tr("zone, upper"), {0.0, 360.0}, {lower + t_um, lower + t_um}, QColor(214, 39, 40),
                          Qt::DashLine, 1.0);
    m_errorPlot->rescaleAndReplot();
    m_errorPlot->setXRange(0.0, 360.0);
    const SurfaceErrorLine line = surfaceErrorLine(result, in.cut);
    const double error_um = 1000.0 * formError_mm(line, in.cut.feedPerTooth_mm, in.tolerance.zone);
    const QString verdict = error_um <= t_um ? tr("<b>passes</b> by %1 µm").arg(t_um - error_um, 0, 'f', 2)
                                             : tr("<b>fails</b> by %1 µm").arg(error_um - t_um, 0, 'f', 2);
    m_summary->setText(m_summary->text() +
                       tr("<br>Surface-normal error %1 to %2 µm over a revolution; against t = %3 µm (%4) it %5.")
                           .arg(1000.0 * result.leastSurfaceNormal_mm, 0, 'f', 2)
                           .arg(1000.0 * result.greatestSurfaceNormal_mm, 0, 'f', 2)
                           .arg(t_um)
                           .arg(floating ? tr("spread") : tr("±t/2"), verdict));
    for (const QString &w : ballEndValidityWarnings(in.mill, in.tool, in.cut, result))
        m_summary->setText(m_summary->text() +
                           QStringLiteral("<br><b>%1</b> %2").arg(tr("Beyond 001:"), w.toHtmlEscaped()));
}

void MillingPanel::plan()
{
    const Inputs in = inputs();
    if (!problems(in).isEmpty() || !validateToolStructure(in.tool, in.mill).empty() || isPlanning())
        return;
    m_planButton->setEnabled(false);
    m_planSummary->setText(tr("Planning: 64 × 64 leads and tilts…"));
    m_tabs->setCurrentIndex(2);
    m_planInputs = in;
    m_watcher.setFuture(QtConcurrent::run(workerThreads(), [in] {
        MillingPlanOutcome outcome;
        try {
            outcome.plan =
                planBallEndCut(in.mill, in.tool, *in.coefficients, in.cut, in.spindle_rpm, in.tolerance, in.settings);
        } catch (const std::exception &e) {
            outcome.error = QString::fromStdString(e.what());
        }
        return outcome;
    }));
}

void MillingPanel::showWindow()
{
    if (!m_plan)
        return;
    const Inputs &in = m_planInputs;
    const BallEndPlan &p = *m_plan;
    m_windowPlot->clear();
    m_windowPlot->setImage(windowImage(p.window, in.settings.highestFeedPerTooth_mm),
                           in.settings.leadLowest_rad / kDegree, in.settings.leadHighest_rad / kDegree,
                           in.settings.tiltLowest_rad / kDegree, in.settings.tiltHighest_rad / kDegree);
    if (p.feasible)
        (void)m_windowPlot->addMarker(p.cut.lead_rad / kDegree, p.cut.tilt_rad / kDegree, tr("plan"));
    (void)m_windowPlot->addMarker(in.cut.lead_rad / kDegree, in.cut.tilt_rad / kDegree, tr("as entered"),
                                  MapPlot::Marker::Programmed);
    m_windowPlot->replot();
    const QString legend = tr("Lighter: a larger feed per tooth holds the tolerance; red: none does; grey: the cut "
                              "would reach the shank above the ball.");
    m_planSummary->setText(p.feasible
                               ? tr("Plan: lead %1°, tilt %2°, feed %3 mm/tooth (%4 mm/min), form error %5 µm. %6")
                                     .arg(angleText(p.cut.lead_rad), angleText(p.cut.tilt_rad))
                                     .arg(p.cut.feedPerTooth_mm, 0, 'f', 4)
                                     .arg(p.feedRate_mm_min, 0, 'f', 0)
                                     .arg(1000.0 * p.formError_mm, 0, 'f', 2)
                                     .arg(legend)
                               : tr("No lead and tilt within ±40° holds the tolerance at any feed. %1").arg(legend));
    for (const QString &w : p.warnings)
        m_planSummary->setText(m_planSummary->text() + QLatin1Char('\n') + tr("Beyond 001: %1").arg(w));
}

void MillingPanel::loadFeature(const MilledFeature &feature)
{
    m_loading = true;
    m_case->setCurrentIndex(m_case->count() - 1);
    if (const std::optional<BallEndTool> &t = feature.tool) {
        m_diameter->setValue(t->diameter_mm);
        m_flutes->setValue(t->flutes);
        m_helix->setValue(t->helix_deg);
        m_overhang->setValue(t->overhang_mm);
        m_equivalentDiameter->setValue(t->equivalentDiameter_mm);
        m_modulus->setValue(t->youngsModulus_N_mm2.value_or(kCarbideModulus_N_mm2));
        if (t->holderStiffness_N_mm && t->holderRotational_N_mm_rad) {
            m_holderStiffness->setValue(*t->holderStiffness_N_mm);
            m_holderRotational->setValue(*t->holderRotational_N_mm_rad);
            m_springSource->setText(tr("Holder springs: feature %1's.").arg(feature.id));
        } else {
            m_springSource->setText(tr("Feature %1 has no holder springs: these are the last cut's, and saving the "
                                       "cut gives them to it.")
                                        .arg(feature.id));
        }
    }
    if (const std::optional<MillingConditions> &c = feature.conditions) {
        m_kind->setCurrentIndex(static_cast<int>(c->cut));
        m_direction->setCurrentIndex(static_cast<int>(c->direction));
        m_radialDepth->setValue(c->radialDepth_mm);
        m_axialDepth->setValue(c->axialDepth_mm);
        m_feedPerTooth->setValue(c->feedPerTooth_mm);
        m_spindle->setValue(c->spindle_rpm);
        m_lead->setValue(c->lead_deg);
        m_tilt->setValue(c->tilt_deg);
    }
    if (const std::optional<MillingForceCoefficients> &k = feature.coefficients)
        m_coefficients->setText(QStringList{
            QString::number(k->tangentialCutting_N_mm2, 'g', 12), QString::number(k->radialCutting_N_mm2, 'g', 12),
            QString::number(k->axialCutting_N_mm2, 'g', 12), QString::number(k->tangentialEdge_N_mm, 'g', 12),
            QString::number(k->radialEdge_N_mm, 'g', 12), QString::number(k->axialEdge_N_mm, 'g', 12)}
                                    .join(QStringLiteral(", ")));
    if (const std::optional<MilledTolerance> &t = feature.tolerance) {
        m_tolerance->setValue(t->zone_um);
        m_zone->setCurrentIndex(t->type == MilledToleranceType::Flatness ? 0 : t->datums.isEmpty() ? 1 : 2);
        m_datums->setText(t->datums.join(QStringLiteral(", ")));
        m_datums->setEnabled(m_zone->currentIndex() == 2);
    }
    m_loading = false;
    compute();
    QStringList missing;
    if (!milledFeatureInputs(feature, missing))
        m_summary->setText(tr("<b>%1 lacks %2</b>: the fields show the last cut; save the cut to the feature to give "
                              "it these.")
                               .arg(feature.id.toHtmlEscaped(), missing.join(QStringLiteral(", ")).toHtmlEscaped()) +
                           QStringLiteral("<br>") + m_summary->text());
    else if (feature.kind == MilledFeatureKind::Patch)
        m_summary->setText(m_summary->text() + tr("<br>A patch's lead and tilt come from its path, point by point "
                                                  "(Along the path); the fields show its conditions' own."));
}

MilledFeature MillingPanel::completeFeature(MilledFeature feature) const
{
    BallEndTool tool;
    tool.diameter_mm = m_diameter->value();
    tool.flutes = m_flutes->value();
    tool.helix_deg = m_helix->value();
    tool.overhang_mm = m_overhang->value();
    tool.equivalentDiameter_mm = m_equivalentDiameter->value();
    // Carbide's modulus stays an assumption, said in every result, unless the planner gave another.
    const bool modulusGiven = feature.tool && feature.tool->youngsModulus_N_mm2;
    if (modulusGiven || m_modulus->value() != kCarbideModulus_N_mm2)
        tool.youngsModulus_N_mm2 = m_modulus->value();
    tool.holderStiffness_N_mm = m_holderStiffness->value();
    tool.holderRotational_N_mm_rad = m_holderRotational->value();
    feature.tool = tool;
    MillingConditions c;
    c.cut = static_cast<BallEndCutKind>(m_kind->currentIndex());
    c.direction = static_cast<MillingDirection>(m_direction->currentIndex());
    c.axialDepth_mm = m_axialDepth->value();
    c.radialDepth_mm = m_radialDepth->value();
    c.feedPerTooth_mm = m_feedPerTooth->value();
    c.spindle_rpm = m_spindle->value();
    c.lead_deg = m_lead->value();
    c.tilt_deg = m_tilt->value();
    feature.conditions = c;
    feature.coefficients = parseMillingCoefficients(m_coefficients->text());
    MilledTolerance t;
    t.type = m_zone->currentIndex() == 0 ? MilledToleranceType::Flatness : MilledToleranceType::Profile;
    t.zone_um = m_tolerance->value();
    if (m_zone->currentIndex() == 2) {
        static const QRegularExpression separators(QStringLiteral("[,;\\s]+"));
        t.datums = m_datums->text().split(separators, Qt::SkipEmptyParts);
    }
    feature.tolerance = t;
    return feature;
}

QString MillingPanel::featureProblem() const
{
    if (!m_coefficients->text().trimmed().isEmpty() && !parseMillingCoefficients(m_coefficients->text()))
        return tr("Coefficients: \"%1\" is not six numbers; the feature is left as it was.")
            .arg(m_coefficients->text());
    if (m_zone->currentIndex() == 2 && m_datums->text().trimmed().isEmpty())
        return tr("A profile with datums needs its datums (A, B).");
    return {};
}

} // namespace tolturn
