// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/cad_files.h"

#include <QDialog>

class QCheckBox;
class QComboBox;

namespace tolturn {

// After a STEP or IGES file is read: what was found (bodies, candidate axes, the profile of the
// first choice) and the planner's choice of body, axis and chuck end.
class ImportDialog : public QDialog {
    Q_OBJECT
public:
    ImportDialog(const QString &fileName, const CadImportResult &read, QWidget *parent = nullptr);

    [[nodiscard]] CadImportChoice choice() const;

private:
    QComboBox *m_solid;
    QComboBox *m_axis;
    QCheckBox *m_flip;
};

} // namespace tolturn
