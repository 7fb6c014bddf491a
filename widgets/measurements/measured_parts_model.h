// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/measurements/measured_part.h"

#include <QAbstractTableModel>

#include <vector>

namespace tolturn {

// The measured parts of a listing, one row each, newest first as the store lists them. The rows
// are read in the background (MeasurementsPanel) and handed over whole, so that a long history
// never blocks the window.
class MeasuredPartsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { MeasuredAt, PartName, Machine, MeasuredBy, Method, Points, ColumnCount };

    using QAbstractTableModel::QAbstractTableModel;

    void setParts(std::vector<MeasuredPartSummary> parts);

    [[nodiscard]] const std::vector<MeasuredPartSummary> &parts() const { return m_parts; }

    // The part of a row; nullptr outside the rows.
    [[nodiscard]] const MeasuredPartSummary *partAt(int row) const;

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    std::vector<MeasuredPartSummary> m_parts;
};

} // namespace tolturn
