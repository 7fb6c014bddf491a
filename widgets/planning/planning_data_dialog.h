// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/project/project.h"

#include <QDialog>

#include <functional>
#include <map>

class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPushButton;

namespace tolturn {

class DataLibrary;

// The planner's data for the optimiser (docs/planning.md §1): machine and tool rates, handling
// and tool-change times, Taylor tool life with its source, the insert maker's ranges of cutting
// speed, feed and depth of cut with their source, and the part's requirements and limits. A box
// left at "—" is not given. OK hands the settings to `apply`, which answers with the refusals;
// the dialog stays open on a refusal, names the field and focuses its box, so nothing typed is lost.
class PlanningDataDialog : public QDialog {
    Q_OBJECT
public:
    using Apply = std::function<Diagnostics(const PlanningSettings &)>;

    PlanningDataDialog(const PlanningSettings &settings, const DataLibrary &library, const QString &materialId,
                       Apply apply, QWidget *parent = nullptr);

    // The settings the fields describe (objective and switched-off constraints kept as given).
    [[nodiscard]] PlanningSettings settings() const;

    // The box of a field, named as in the project file's "planning" block without the prefix:
    // "machine_rate_per_min", "tool_life.C_m_min", "ranges.feed_mm_rev.max", "max_ra_um", ...
    [[nodiscard]] QDoubleSpinBox *field(const QString &name) const;

    [[nodiscard]] QLineEdit *toolLifeSourceEdit() const { return m_toolLifeSource; }

    [[nodiscard]] QLineEdit *rangesSourceEdit() const { return m_rangesSource; }

    // Fills Taylor C, n and their source from the work material's data (enabled when it has them).
    [[nodiscard]] QPushButton *materialToolLifeButton() const { return m_materialToolLife; }

    // Fills C from the catalogue's recommended speed at its tool life and n from the data library.
    [[nodiscard]] QPushButton *catalogueToolLifeButton() const { return m_catalogueToolLife; }

    [[nodiscard]] QDoubleSpinBox *catalogueSpeedBox() const { return m_catalogueSpeed; }

    [[nodiscard]] QDoubleSpinBox *catalogueLifeBox() const { return m_catalogueLife; }

    [[nodiscard]] QString message() const;

    void accept() override;

private:
    QWidget *createRatesGroup();
    QWidget *createToolLifeGroup(const DataLibrary &library, const QString &materialId);
    void addCatalogueToolLife(QFormLayout &form, const DataLibrary &library);
    QWidget *createRangesGroup();
    QWidget *createLimitsGroup();
    QDoubleSpinBox *addBox(const QString &name, int decimals, double maximum, const QString &unit, const QString &tip);
    void showSettings(const PlanningSettings &s);
    [[nodiscard]] std::optional<ValueRange> range(const QString &name) const;
    [[nodiscard]] std::optional<double> optionalValue(const QString &name) const;

    PlanningSettings m_settings;
    Apply m_apply;
    std::map<QString, QDoubleSpinBox *> m_fields;
    QLineEdit *m_toolLifeSource;
    QLineEdit *m_rangesSource;
    QPushButton *m_materialToolLife = nullptr;
    QPushButton *m_catalogueToolLife = nullptr;
    QDoubleSpinBox *m_catalogueSpeed = nullptr;
    QDoubleSpinBox *m_catalogueLife = nullptr;
    QLabel *m_message;
};

} // namespace tolturn
