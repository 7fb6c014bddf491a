// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/project.h"
#include "core/tolerance/evaluation.h"
#include "core/tolerance/range_verdicts.h"

#include <QAbstractTableModel>

#include <vector>

namespace tolturn {

// One row per tolerance of the project: what it is, the predicted value against its limit, the
// utilisation and the verdict (coloured); where the machine is a published stiffness range, the
// verdict over the range and the chuck and tailstock stiffness the tolerance needs. Tooltips give
// the deciding condition and the reason.
class ToleranceVerdictModel : public QAbstractTableModel {
    Q_OBJECT
public:
    // The verdicts come before the numbers: in a narrow dock they are what shows without scrolling.
    enum Column {
        Id,
        Characteristic,
        Feature,
        Specification,
        VerdictColumn,
        RangeColumn,    // the verdict over the machine's stiffness range
        RequiredColumn, // the chuck and tailstock stiffness the tolerance needs
        Value,
        Limit,
        Utilisation,
        ColumnCount
    };

    enum Role {
        UtilisationRole = Qt::UserRole + 1, // double, percent; invalid when there is no value
        VerdictRole,                        // int, the Verdict
        RangeVerdictRole,                   // int, the RangeVerdict
        FeatureIdRole,                      // QString
    };

    explicit ToleranceVerdictModel(QObject *parent = nullptr);

    void setVerdicts(const Project &project, std::vector<ToleranceRangeEvaluation> verdicts);

    [[nodiscard]] const ToleranceEvaluation &verdict(int row) const
    {
        return m_verdicts[static_cast<std::size_t>(row)].compliant;
    }

    [[nodiscard]] const ToleranceRangeEvaluation &rangeVerdict(int row) const
    {
        return m_verdicts[static_cast<std::size_t>(row)];
    }

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation,
                                      int role = Qt::DisplayRole) const override;

    [[nodiscard]] static QColor verdictColor(Verdict verdict);
    [[nodiscard]] static QColor rangeVerdictColor(const ToleranceRangeEvaluation &e);
    // "chuck ≥ 128 N/µm · tailstock any", or a dash where nothing was searched.
    [[nodiscard]] static QString requiredText(const ToleranceRangeEvaluation &e);
    // "h6", "+50/-50 µm", "8 µm | A": the specification as written on a drawing.
    [[nodiscard]] static QString specification(const Tolerance &tolerance);

private:
    [[nodiscard]] QVariant display(int row, int column) const;

    std::vector<Tolerance> m_tolerances;
    std::vector<ToleranceRangeEvaluation> m_verdicts;
};

} // namespace tolturn
