// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/project.h"

#include <QGroupBox>

#include <array>
#include <optional>

class QComboBox;
class QDoubleSpinBox;

namespace tolturn {

// The force model of the project and the shop conditions of the cut (docs/project-format.md):
// Kienzle with the force ratios F_f/F_c and F_p/F_c where the project replaces the material's, or
// Li & Du (2002) with its fitted K_n and K_f (MODEL.md §2); the ambient temperature and the time since
// the machine was started, for the thermal drift (MODEL.md §5). A value left unset shows what is
// taken instead. Each box changes only its own value, so a wrong value elsewhere is never
// overwritten by what a box can show.
class ForceModelEditor : public QGroupBox {
    Q_OBJECT
public:
    enum Value { FeedRatio, PassiveRatio, NormalPressure, FrictionRatio, AmbientTemperature, TimeSinceStart, kValues };

    explicit ForceModelEditor(QWidget *parent = nullptr);

    void showValues(const CuttingModel &model, const Environment &environment);

    [[nodiscard]] QComboBox *modelBox() const { return m_model; }

    [[nodiscard]] QDoubleSpinBox *box(Value value) const { return m_boxes.at(value); }

Q_SIGNALS:
    void cuttingModelEdited(const tolturn::CuttingModel &model);
    void environmentEdited(const tolturn::Environment &environment);

private:
    void valueEdited(Value value);
    [[nodiscard]] std::optional<double> boxValue(Value value) const;

    QComboBox *m_model;
    std::array<QDoubleSpinBox *, kValues> m_boxes{};
    CuttingModel m_shownModel;
    Environment m_shownEnvironment;
    bool m_updating = false;
};

} // namespace tolturn
