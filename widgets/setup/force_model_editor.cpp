// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/setup/force_model_editor.h"

#include "widgets/common/project_fields.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>

#include <cmath>

namespace tolturn {

namespace {

struct ValueSpec {
    const char *field; // the project file's path of the value
    double min;        // the smallest valid value; one step below it means "not set"
    double max;
    int decimals;
};

// Ranges wide enough for any entry; validateProject judges the value.
constexpr std::array<ValueSpec, ForceModelEditor::kValues> kSpecs{{
    {"cutting_model.feed_to_cutting_ratio", 0.0, 5.0, 3},
    {"cutting_model.passive_to_cutting_ratio", 0.0, 5.0, 3},
    {"cutting_model.normal_pressure_MPa", 0.01, 100000.0, 2},
    {"cutting_model.friction_ratio", 0.0, 10.0, 3},
    {"environment.ambient_temperature_C", -40.0, 80.0, 1},
    {"environment.time_since_start_min", 0.0, 100000.0, 1},
}};

double step(const ValueSpec &spec)
{
    return std::pow(10.0, -spec.decimals);
}

} // namespace

ForceModelEditor::ForceModelEditor(QWidget *parent) : QGroupBox(tr("Force model and shop conditions"), parent)
{
    setObjectName(QStringLiteral("forceModelEditor"));
    m_model = new QComboBox;
    m_model->addItem(tr("Kienzle"), static_cast<int>(ForceModel::Kienzle));
    m_model->addItem(tr("Li & Du"), static_cast<int>(ForceModel::LiDu));
    m_model->setToolTip(tr("Kienzle: F_c from kc1.1 and mc of the material, F_f and F_p as ratios of it. "
                           "Li & Du (2002, eq. 15–20): normal pressure K_n and friction ratio K_f fitted to "
                           "measured forces (tolturn-cli calibrate-forces)."));
    setProjectField(*m_model, QStringLiteral("cutting_model.force_model"));
    const std::array<QString, kValues> unset{tr("material's"), tr("material's"),       tr("not fitted"),
                                             tr("not fitted"), tr("not given: 20 °C"), tr("not given: 0 (cold start)")};
    const std::array<QString, kValues> suffix{QString(), QString(), tr(" MPa"), QString(), tr(" °C"), tr(" min")};
    const std::array<QString, kValues> tips{
        tr("F_f/F_c for the Kienzle model, replacing the material data's ratio"),
        tr("F_p/F_c for the Kienzle model, replacing the material data's ratio"),
        tr("K_n of Li & Du (2002): normal pressure on the rake face"),
        tr("K_f of Li & Du (2002): friction force over normal force"),
        tr("Ambient temperature of the shop, for the thermal drift (not given: the ISO 1 reference "
           "temperature, 20 °C)"),
        tr("Time since the machine was started, for the thermal warm-up (not given: a cold machine, 0 min)")};
    auto *form = new QFormLayout(this);
    form->addRow(tr("&Model:"), m_model);
    const std::array<QString, kValues> labels{tr("F_f/F_c:"), tr("F_p/F_c:"), tr("K_n:"),
                                              tr("K_f:"),     tr("Ambient:"), tr("Since start:")};
    for (int v = 0; v < kValues; ++v) {
        const ValueSpec &spec = kSpecs[static_cast<std::size_t>(v)];
        auto *box = new QDoubleSpinBox;
        box->setDecimals(spec.decimals);
        box->setRange(spec.min - step(spec), spec.max);
        box->setSingleStep(step(spec) * 10.0);
        box->setSpecialValueText(unset[static_cast<std::size_t>(v)]);
        box->setSuffix(suffix[static_cast<std::size_t>(v)]);
        box->setToolTip(tips[static_cast<std::size_t>(v)]);
        box->setKeyboardTracking(false);
        setProjectField(*box, QLatin1String(spec.field));
        m_boxes[static_cast<std::size_t>(v)] = box;
        form->addRow(labels[static_cast<std::size_t>(v)], box);
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, v] { valueEdited(static_cast<Value>(v)); });
    }
    connect(m_model, &QComboBox::activated, this, [this] {
        if (m_updating)
            return;
        CuttingModel model = m_shownModel;
        model.forceModel = static_cast<ForceModel>(m_model->currentData().toInt());
        Q_EMIT cuttingModelEdited(model);
    });
}

void ForceModelEditor::showValues(const CuttingModel &model, const Environment &environment)
{
    m_updating = true;
    m_shownModel = model;
    m_shownEnvironment = environment;
    m_model->setCurrentIndex(m_model->findData(static_cast<int>(model.forceModel)));
    const std::array<std::optional<double>, kValues> values{
        model.feedToCuttingRatio, model.passiveToCuttingRatio,      model.normalPressure_MPa,
        model.frictionRatio,      environment.ambientTemperature_C, environment.timeSinceStart_min};
    for (std::size_t v = 0; v < values.size(); ++v)
        m_boxes[v]->setValue(values[v].value_or(m_boxes[v]->minimum()));
    const bool kienzle = model.forceModel == ForceModel::Kienzle;
    m_boxes[FeedRatio]->setEnabled(kienzle);
    m_boxes[PassiveRatio]->setEnabled(kienzle);
    m_boxes[NormalPressure]->setEnabled(!kienzle);
    m_boxes[FrictionRatio]->setEnabled(!kienzle);
    m_updating = false;
}

std::optional<double> ForceModelEditor::boxValue(Value value) const
{
    const QDoubleSpinBox *box = m_boxes[static_cast<std::size_t>(value)];
    return box->value() == box->minimum() ? std::nullopt : std::optional<double>(box->value());
}

void ForceModelEditor::valueEdited(Value value)
{
    if (m_updating)
        return;
    if (value == AmbientTemperature || value == TimeSinceStart) {
        Environment environment = m_shownEnvironment;
        (value == AmbientTemperature ? environment.ambientTemperature_C : environment.timeSinceStart_min) =
            boxValue(value);
        Q_EMIT environmentEdited(environment);
        return;
    }
    CuttingModel model = m_shownModel;
    std::optional<double> *target = value == FeedRatio        ? &model.feedToCuttingRatio
                                    : value == PassiveRatio   ? &model.passiveToCuttingRatio
                                    : value == NormalPressure ? &model.normalPressure_MPa
                                                              : &model.frictionRatio;
    *target = boxValue(value);
    Q_EMIT cuttingModelEdited(model);
}

} // namespace tolturn
