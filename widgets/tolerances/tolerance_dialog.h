// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/project/project.h"

#include <QDialog>

#include <functional>

class QButtonGroup;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QRadioButton;
class QStackedWidget;

namespace tolturn {

// Adds or edits one tolerance on a feature: the characteristic (only those that fit the
// feature), for sizes an ISO 286 class with its limits shown as typed, or explicit limits; for
// geometric tolerances the zone and its datums. On OK the tolerance goes to `apply`, which
// returns the problems of the resulting project; the dialog stays open and shows them.
class ToleranceDialog : public QDialog {
    Q_OBJECT
public:
    using Apply = std::function<Diagnostics(const Tolerance &)>;

    ToleranceDialog(const Project &project, const QString &featureId, const Tolerance &initial, Apply apply,
                    QWidget *parent = nullptr);

    [[nodiscard]] Tolerance tolerance() const;
    // The live limits text under the ISO 286 class ("upper +0 µm, lower -16 µm (IT6 = 16 µm)").
    [[nodiscard]] QString limitsText() const;
    [[nodiscard]] QString problemsText() const;

    // For tests and scripting: set the fields as a user would.
    void setCharacteristic(ToleranceType type);
    void setIsoClass(const QString &isoClass);
    void setExplicitLimits(double upper_um, double lower_um);
    void setZone(double zone_um, const QString &datums);
    bool tryAccept();

private:
    void rebuildForType();
    void updateLimits();
    [[nodiscard]] ToleranceType currentType() const;
    [[nodiscard]] double nominalSize_mm() const;

    const Project &m_project;
    QString m_featureId;
    Tolerance m_initial;
    Apply m_apply;
    QComboBox *m_type;
    QStackedWidget *m_pages;
    QComboBox *m_toFace;
    QRadioButton *m_isoMode;
    QRadioButton *m_explicitMode;
    QLineEdit *m_isoClass;
    QLabel *m_limits;
    QDoubleSpinBox *m_upper;
    QDoubleSpinBox *m_lower;
    QDoubleSpinBox *m_zone;
    QLineEdit *m_datums;
    QLabel *m_problems;
};

} // namespace tolturn
