// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/project/project.h"

#include <QGroupBox>

#include <array>

class QDoubleSpinBox;
class QLineEdit;
class QPushButton;

namespace tolturn {

// The measured stiffness of the machine (the project's characterisation): the spindle–chuck
// springs k1, k2, k3 of Valiño et al. (2008) §III radially and tangentially with the pivot
// distance Lc, the tailstock and centre supports, and where the numbers come from. A row left at
// zero is not measured; with nothing measured the supports are taken as rigid. Thermal drift is
// kept as the file gives it.
class StiffnessEditor : public QGroupBox {
    Q_OBJECT
public:
    explicit StiffnessEditor(QWidget *parent = nullptr);

    void showCharacterisation(const MachineCharacterisation &c);
    // The characterisation the fields describe, on top of `current` (whose thermal data it keeps).
    [[nodiscard]] MachineCharacterisation characterisation(const MachineCharacterisation &current) const;

    // What must still be entered before the fields describe a whole characterisation (a row
    // partly filled, springs without Lc, numbers without a source); empty when complete.
    [[nodiscard]] QString missing() const;

    [[nodiscard]] QLineEdit *sourceEdit() const { return m_source; }

    [[nodiscard]] QDoubleSpinBox *pivotBox() const { return m_pivot; }

    // "Fit from Test Bar…": asks for the springs from a measured test bar (Valiño et al. 2008 §III).
    [[nodiscard]] QPushButton *fitButton() const { return m_fit; }

    // Row 0/1: spindle radial/tangential k1, k2, k3; row 2/3: tailstock/centres radial, tangential.
    [[nodiscard]] QDoubleSpinBox *box(int row, int column) const;

Q_SIGNALS:
    void edited();       // a field was changed by the user
    void fitRequested(); // the user asked to fit the springs to a measured test bar

private:
    QLineEdit *m_source;
    QDoubleSpinBox *m_pivot = nullptr;
    QPushButton *m_fit = nullptr;
    std::array<std::array<QDoubleSpinBox *, 3>, 4> m_boxes{};
    bool m_updating = false;
};

} // namespace tolturn
