// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/planning/planning_data_dialog.h"

#include "core/cutting/cutting_quantities.h"
#include "core/data/data_library.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include <initializer_list>
#include <utility>

namespace tolturn {

namespace {

const QString kPrefix = QStringLiteral("planning.");

// The boxes and the settings they show, named as in the project file's "planning" block.
const std::pair<const char *, double PlanningSettings::*> kRates[] = {
    {"machine_rate_per_min", &PlanningSettings::machineRate_per_min},
    {"tool_cost_per_edge", &PlanningSettings::toolCostPerEdge},
    {"tool_change_time_min", &PlanningSettings::toolChangeTime_min},
    {"handling_time_min", &PlanningSettings::handlingTime_min}};
const std::pair<const char *, std::optional<double> PlanningSettings::*> kOptionals[] = {
    {"tool_life.C_m_min", &PlanningSettings::taylorC_m_min},
    {"tool_life.n", &PlanningSettings::taylorN},
    {"tool_life.min_minutes", &PlanningSettings::minToolLife_min},
    {"max_ra_um", &PlanningSettings::maxRa_um},
    {"max_rz_um", &PlanningSettings::maxRz_um},
    {"max_force_N", &PlanningSettings::maxForce_N},
    {"max_power_kW", &PlanningSettings::maxPower_kW},
    {"max_torque_Nm", &PlanningSettings::maxTorque_Nm},
    {"max_spindle_speed_rpm", &PlanningSettings::maxSpindleSpeed_rpm}};
const std::pair<const char *, std::optional<ValueRange> PlanningSettings::*> kRanges[] = {
    {"ranges.cutting_speed_m_min", &PlanningSettings::cuttingSpeed_m_min},
    {"ranges.feed_mm_rev", &PlanningSettings::feed_mm_rev},
    {"ranges.depth_of_cut_mm", &PlanningSettings::depthOfCut_mm}};

// The Taylor constants of a work material, when its data gives both.
std::optional<std::pair<SourcedValue, SourcedValue>> materialTaylor(const DataLibrary &library,
                                                                    const QString &materialId)
{
    const MaterialData *m = library.material(materialId);
    if (!m || !m->taylorC_m_min || !m->taylorN)
        return std::nullopt;
    return std::make_pair(*m->taylorC_m_min, *m->taylorN);
}

// "min – max" on one form row.
QWidget *rangeRow(QDoubleSpinBox *min, QDoubleSpinBox *max)
{
    auto *row = new QWidget;
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(min, 1);
    layout->addWidget(new QLabel(QStringLiteral("–")));
    layout->addWidget(max, 1);
    return row;
}

} // namespace

PlanningDataDialog::PlanningDataDialog(const PlanningSettings &settings, const DataLibrary &library,
                                       const QString &materialId, Apply apply, QWidget *parent)
    : QDialog(parent)
    , m_settings(settings)
    , m_apply(std::move(apply))
    , m_toolLifeSource(new QLineEdit)
    , m_rangesSource(new QLineEdit)
    , m_message(new QLabel)
{
    setObjectName(QStringLiteral("planningDataDialog"));
    for (QLineEdit *source : {m_toolLifeSource, m_rangesSource}) // a citation is longer than its box
        connect(source, &QLineEdit::textChanged, source, &QLineEdit::setToolTip);
    setWindowTitle(tr("Planning Data"));
    auto *intro = new QLabel(tr("What the optimiser works with (docs/planning.md). A box showing “—” is not given."));
    intro->setWordWrap(true);
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: #b00020;"));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &PlanningDataDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &PlanningDataDialog::reject);
    auto *grid = new QGridLayout;
    grid->addWidget(createRatesGroup(), 0, 0);
    grid->addWidget(createToolLifeGroup(library, materialId), 1, 0);
    grid->addWidget(createRangesGroup(), 0, 1);
    grid->addWidget(createLimitsGroup(), 1, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(grid);
    layout->addWidget(m_message);
    layout->addWidget(buttons);
    showSettings(settings);
}

QDoubleSpinBox *PlanningDataDialog::addBox(const QString &name, int decimals, double maximum, const QString &unit,
                                           const QString &tip)
{
    auto *box = new QDoubleSpinBox;
    box->setObjectName(name);
    box->setDecimals(decimals);
    box->setRange(0.0, maximum); // entry bounds; the project's validation judges the value
    box->setSpecialValueText(tr("—"));
    if (!unit.isEmpty())
        box->setSuffix(QLatin1Char(' ') + unit);
    box->setToolTip(tip);
    box->setGroupSeparatorShown(true);
    box->setMinimumWidth(110);
    m_fields.emplace(name, box);
    return box;
}

QWidget *PlanningDataDialog::createRatesGroup()
{
    auto *group = new QGroupBox(tr("Rates and times"));
    auto *form = new QFormLayout(group);
    const QString costTip = tr("Cost per part C = M·t + C_edge·edges (docs/planning.md §1); in the currency of "
                               "your choice, the same for both rates.");
    form->addRow(tr("&Machine and operator rate:"),
                 addBox(QStringLiteral("machine_rate_per_min"), 2, 1e6, tr("per min"), costTip));
    form->addRow(tr("Tool cost per &edge:"), addBox(QStringLiteral("tool_cost_per_edge"), 2, 1e6, QString(), costTip));
    form->addRow(tr("Tool change &time:"),
                 addBox(QStringLiteral("tool_change_time_min"), 2, 1e3, tr("min"),
                        tr("Time to index or change the cutting edge, t_change (docs/planning.md §1).")));
    form->addRow(tr("&Handling time per part:"),
                 addBox(QStringLiteral("handling_time_min"), 2, 1e3, tr("min"),
                        tr("Loading, unloading and idle moves per part, t_handling (docs/planning.md §1).")));
    for (const auto &rate : kRates)
        field(QLatin1String(rate.first))->setSpecialValueText(QString()); // a rate or time of zero is a value
    return group;
}

QWidget *PlanningDataDialog::createToolLifeGroup(const DataLibrary &library, const QString &materialId)
{
    auto *group = new QGroupBox(tr("Tool life (Taylor: v·Tⁿ = C)"));
    auto *form = new QFormLayout(group);
    const QString taylorTip =
        tr("Taylor (1907): v·Tⁿ = C with v in m/min and T in min; give both C and n, from the insert maker or "
           "your own tool-life tests, with their source. Without them tool life is left out of the plan.");
    form->addRow(tr("&C:"), addBox(QStringLiteral("tool_life.C_m_min"), 1, 1e5, tr("m/min"), taylorTip));
    form->addRow(tr("&n:"), addBox(QStringLiteral("tool_life.n"), 3, 0.999, QString(), taylorTip));
    form->addRow(tr("Minimum tool &life:"),
                 addBox(QStringLiteral("tool_life.min_minutes"), 1, 1e5, tr("min"),
                        tr("The tool_life constraint: T(v) at least this (docs/planning.md §2).")));
    m_toolLifeSource->setObjectName(QStringLiteral("tool_life.source"));
    m_toolLifeSource->setPlaceholderText(tr("where C and n come from"));
    form->addRow(tr("&Source:"), m_toolLifeSource);
    m_materialToolLife = new QPushButton(tr("From the Material's Data"));
    const auto taylor = materialTaylor(library, materialId);
    m_materialToolLife->setEnabled(taylor.has_value());
    m_materialToolLife->setToolTip(taylor ? tr("Fill C, n and the source from the data of %1.").arg(materialId)
                                          : tr("The data of %1 gives no Taylor constants.").arg(materialId));
    if (taylor) {
        const QString source =
            tr("%1 (material %2): C from %3; n from %4")
                .arg(tr("TolTurn material data"), materialId, library.sourceText(taylor->first.source),
                     library.sourceText(taylor->second.source));
        connect(m_materialToolLife, &QPushButton::clicked, this, [this, taylor, source] {
            field(QStringLiteral("tool_life.C_m_min"))->setValue(taylor->first.value);
            field(QStringLiteral("tool_life.n"))->setValue(taylor->second.value);
            m_toolLifeSource->setText(source);
            m_toolLifeSource->setCursorPosition(0);
        });
    }
    form->addRow(QString(), m_materialToolLife);
    addCatalogueToolLife(*form, library);
    return group;
}

// C from the insert catalogue's recommended speed at its reference tool life, with the exponent of
// tool makers' speed–life factors from the data library (docs/planning.md §1): C = v T^n.
void PlanningDataDialog::addCatalogueToolLife(QFormLayout &form, const DataLibrary &library)
{
    m_catalogueSpeed = new QDoubleSpinBox;
    m_catalogueSpeed->setObjectName(QStringLiteral("catalogue.cutting_speed_m_min"));
    m_catalogueSpeed->setRange(0.0, 5000.0);
    m_catalogueSpeed->setDecimals(1);
    m_catalogueSpeed->setSuffix(QStringLiteral(" ") + tr("m/min"));
    m_catalogueLife = new QDoubleSpinBox;
    m_catalogueLife->setObjectName(QStringLiteral("catalogue.tool_life_min"));
    m_catalogueLife->setRange(0.0, 1000.0);
    m_catalogueLife->setDecimals(1);
    m_catalogueLife->setSuffix(QStringLiteral(" ") + tr("min"));
    m_catalogueToolLife = new QPushButton(tr("Derive C"));
    const auto n = library.defaultTaylorExponent();
    m_catalogueToolLife->setEnabled(n.has_value());
    const QString why = tr("The speed the insert's catalogue recommends and the tool life it states for it (often "
                           "15 min): C = v·Tⁿ, with n from tool makers' speed–life factors.");
    for (QWidget *w : std::initializer_list<QWidget *>{m_catalogueSpeed, m_catalogueLife, m_catalogueToolLife})
        w->setToolTip(why);
    auto *row = new QHBoxLayout;
    row->addWidget(m_catalogueSpeed);
    row->addWidget(new QLabel(tr("at")));
    row->addWidget(m_catalogueLife);
    row->addWidget(m_catalogueToolLife);
    form.addRow(tr("Catalogue speed:"), row);
    if (!n)
        return;
    const QString nSource = library.sourceText(n->source).section(QLatin1Char(','), 0, 2);
    connect(m_catalogueToolLife, &QPushButton::clicked, this, [this, n = *n, nSource] {
        const double v = m_catalogueSpeed->value();
        const double t = m_catalogueLife->value();
        if (v <= 0.0 || t <= 0.0) {
            m_message->setText(tr("Catalogue speed: give the recommended speed and the tool life the catalogue "
                                  "states for it."));
            (v <= 0.0 ? m_catalogueSpeed : m_catalogueLife)->setFocus(Qt::OtherFocusReason);
            return;
        }
        m_message->clear();
        field(QStringLiteral("tool_life.C_m_min"))->setValue(taylorConstant_m_min(v, t, n.value));
        field(QStringLiteral("tool_life.n"))->setValue(n.value);
        m_toolLifeSource->setText(tr("C = %1 m/min x %2 min^%3 from the insert catalogue's recommended speed; n: %4")
                                      .arg(formatNumber(v), formatNumber(t), formatNumber(n.value), nSource));
        m_toolLifeSource->setCursorPosition(0);
    });
}

QWidget *PlanningDataDialog::createRangesGroup()
{
    auto *group = new QGroupBox(tr("Cutting ranges of the insert"));
    auto *form = new QFormLayout(group);
    const QString tip = tr("The insert maker's recommended range (catalogue), the bounds of the optimiser's "
                           "variables (docs/planning.md §2–3).");

    const struct {
        const char *name;
        QString label;
        int decimals;
        QString unit;
    } rows[] = {{"ranges.cutting_speed_m_min", tr("Cutting s&peed:"), 1, tr("m/min")},
                {"ranges.feed_mm_rev", tr("&Feed:"), 3, tr("mm/rev")},
                {"ranges.depth_of_cut_mm", tr("&Depth of cut:"), 2, tr("mm")}};

    for (const auto &row : rows) {
        const QString name = QLatin1String(row.name);
        form->addRow(row.label, rangeRow(addBox(name + QStringLiteral(".min"), row.decimals, 1e4, row.unit, tip),
                                         addBox(name + QStringLiteral(".max"), row.decimals, 1e4, row.unit, tip)));
    }
    m_rangesSource->setObjectName(QStringLiteral("ranges.source"));
    m_rangesSource->setPlaceholderText(tr("catalogue, page, chip breaker"));
    form->addRow(tr("S&ource:"), m_rangesSource);
    return group;
}

QWidget *PlanningDataDialog::createLimitsGroup()
{
    auto *group = new QGroupBox(tr("Requirements and limits"));
    auto *form = new QFormLayout(group);
    const QString machine = tr(" “—”: the machine's limit from its data, if it has one.");
    form->addRow(tr("Max. &Ra:"), addBox(QStringLiteral("max_ra_um"), 2, 1e3, tr("µm"),
                                         tr("Theoretical roughness Ra = f²/(32·rε) of the finishing pass.")));
    form->addRow(tr("Max. R&z:"), addBox(QStringLiteral("max_rz_um"), 2, 1e3, tr("µm"),
                                         tr("Theoretical roughness Rz = f²/(8·rε) of the finishing pass.")));
    form->addRow(tr("Ma&x. cutting force:"),
                 addBox(QStringLiteral("max_force_N"), 0, 1e6, tr("N"), tr("Upper limit of the cutting force F_c.")));
    form->addRow(tr("Max. po&wer:"), addBox(QStringLiteral("max_power_kW"), 2, 1e4, tr("kW"),
                                            tr("Spindle power F_c·v available.") + machine));
    form->addRow(tr("Max. tor&que:"), addBox(QStringLiteral("max_torque_Nm"), 1, 1e6, tr("N·m"),
                                             tr("Spindle torque F_c·D/2 available.") + machine));
    form->addRow(tr("Max. sp&indle speed:"),
                 addBox(QStringLiteral("max_spindle_speed_rpm"), 0, 1e6, tr("rpm"),
                        tr("Highest spindle speed: the program clamps constant surface speed at it.") + machine));
    return group;
}

QDoubleSpinBox *PlanningDataDialog::field(const QString &name) const
{
    const auto it = m_fields.find(name);
    return it == m_fields.end() ? nullptr : it->second;
}

QString PlanningDataDialog::message() const
{
    return m_message->text();
}

void PlanningDataDialog::showSettings(const PlanningSettings &s)
{
    for (const auto &[name, member] : kRates)
        field(QLatin1String(name))->setValue(s.*member);
    for (const auto &[name, member] : kOptionals)
        field(QLatin1String(name))->setValue((s.*member).value_or(0.0));
    for (const auto &[name, member] : kRanges) {
        const std::optional<ValueRange> &r = s.*member;
        field(QLatin1String(name) + QStringLiteral(".min"))->setValue(r ? r->min : 0.0);
        field(QLatin1String(name) + QStringLiteral(".max"))->setValue(r ? r->max : 0.0);
    }
    m_toolLifeSource->setText(s.toolLifeSource);
    m_rangesSource->setText(s.rangesSource);
    m_toolLifeSource->setCursorPosition(0);
    m_rangesSource->setCursorPosition(0);
}

std::optional<double> PlanningDataDialog::optionalValue(const QString &name) const
{
    const double value = field(name)->value();
    return value > 0.0 ? std::optional<double>(value) : std::nullopt;
}

std::optional<ValueRange> PlanningDataDialog::range(const QString &name) const
{
    const double min = field(name + QStringLiteral(".min"))->value();
    const double max = field(name + QStringLiteral(".max"))->value();
    if (min == 0.0 && max == 0.0)
        return std::nullopt;
    return ValueRange{min, max};
}

PlanningSettings PlanningDataDialog::settings() const
{
    PlanningSettings s = m_settings;
    for (const auto &[name, member] : kRates)
        s.*member = field(QLatin1String(name))->value();
    for (const auto &[name, member] : kOptionals)
        s.*member = optionalValue(QLatin1String(name));
    for (const auto &[name, member] : kRanges)
        s.*member = range(QLatin1String(name));
    s.toolLifeSource = m_toolLifeSource->text().trimmed();
    s.rangesSource = m_rangesSource->text().trimmed();
    return s;
}

void PlanningDataDialog::accept()
{
    QStringList errors;
    QWidget *first = nullptr;
    for (const Diagnostic &d : m_apply(settings())) {
        if (d.severity != Severity::Error)
            continue;
        errors << d.toString();
        if (first || !d.field.startsWith(kPrefix))
            continue;
        const QString name = d.field.mid(kPrefix.size());
        if (QDoubleSpinBox *box = field(name))
            first = box;
        else if (name == m_toolLifeSource->objectName())
            first = m_toolLifeSource;
        else if (name == m_rangesSource->objectName())
            first = m_rangesSource;
    }
    m_message->setText(errors.join(QLatin1Char('\n')));
    if (errors.isEmpty()) {
        QDialog::accept();
        return;
    }
    if (first)
        first->setFocus(Qt::OtherFocusReason);
}

} // namespace tolturn
