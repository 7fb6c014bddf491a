// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/measurements/measured_parts_model.h"

#include <QLocale>

namespace tolturn {

void MeasuredPartsModel::setParts(std::vector<MeasuredPartSummary> parts)
{
    beginResetModel();
    m_parts = std::move(parts);
    endResetModel();
}

const MeasuredPartSummary *MeasuredPartsModel::partAt(int row) const
{
    return row >= 0 && row < rowCount() ? &m_parts[static_cast<std::size_t>(row)] : nullptr;
}

int MeasuredPartsModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_parts.size());
}

int MeasuredPartsModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant MeasuredPartsModel::data(const QModelIndex &index, int role) const
{
    const MeasuredPartSummary *p = partAt(index.row());
    if (!p)
        return {};
    if (role == Qt::TextAlignmentRole && index.column() == Points)
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ToolTipRole)
        return tr("Part %1").arg(p->id);
    if (role != Qt::DisplayRole)
        return {};
    switch (index.column()) {
    case MeasuredAt:
        return QLocale().toString(p->measuredAt.toLocalTime(), QLocale::ShortFormat);
    case PartName:
        return p->partName;
    case Machine:
        return p->machineId;
    case MeasuredBy:
        return p->measuredBy;
    case Method:
        return p->method;
    case Points:
        return p->pointCount;
    default:
        return {};
    }
}

QVariant MeasuredPartsModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case MeasuredAt:
        return tr("Measured");
    case PartName:
        return tr("Part");
    case Machine:
        return tr("Machine");
    case MeasuredBy:
        return tr("By");
    case Method:
        return tr("Method");
    case Points:
        return tr("Points");
    default:
        return {};
    }
}

} // namespace tolturn
