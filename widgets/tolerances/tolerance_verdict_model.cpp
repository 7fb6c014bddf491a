// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/tolerances/tolerance_verdict_model.h"

#include "core/project/keywords.h"
#include "core/project/operations.h"
#include "widgets/common/display_units.h"

#include <QColor>

#include <algorithm>

namespace tolturn {

namespace {

// A deviation in µm in the display unit (µm, or µin with no decimals), or a dash.
QString deviation(const std::optional<double> &value_um, const DisplayUnits &units)
{
    if (!value_um)
        return QStringLiteral("—");
    const int decimals = units.lengthUnit() == LengthUnit::Inch ? 0 : 3;
    return QString::number(units.deviationFromUm(*value_um), 'f', decimals);
}

QString signedNumber(double v)
{
    return (v > 0.0 ? QStringLiteral("+") : QString()) + formatNumber(v);
}

} // namespace

ToleranceVerdictModel::ToleranceVerdictModel(QObject *parent) : QAbstractTableModel(parent)
{
    connect(&DisplaySettings::instance(), &DisplaySettings::unitsChanged, this, [this] {
        if (rowCount() > 0)
            Q_EMIT dataChanged(index(0, Value), index(rowCount() - 1, Limit), {Qt::DisplayRole});
        Q_EMIT headerDataChanged(Qt::Horizontal, Value, Limit);
    });
}

void ToleranceVerdictModel::setVerdicts(const Project &project, std::vector<ToleranceRangeEvaluation> verdicts)
{
    beginResetModel();
    m_tolerances = project.tolerances;
    // One row per tolerance of the project, its verdict found by id: a project of several
    // operations is judged one set-up at a time, and the others' rows say where they are judged.
    m_verdicts.clear();
    m_verdicts.reserve(m_tolerances.size());
    for (const Tolerance &t : m_tolerances) {
        const auto it = std::find_if(verdicts.begin(), verdicts.end(), [&t](const ToleranceRangeEvaluation &e) {
            return e.compliant.toleranceId == t.id;
        });
        if (it != verdicts.end()) {
            m_verdicts.push_back(std::move(*it));
            continue;
        }
        ToleranceRangeEvaluation other;
        other.compliant.toleranceId = t.id;
        other.compliant.type = t.type;
        other.compliant.featureId = t.featureId;
        if (operationCount(project) > 1)
            other.compliant.reason = tr("%1 is cut in %2: choose that set-up to see its verdict")
                                         .arg(t.featureId, operationName(project, operationOf(project, t.featureId)));
        m_verdicts.push_back(std::move(other));
    }
    endResetModel();
}

QString ToleranceVerdictModel::requiredText(const ToleranceRangeEvaluation &e)
{
    QStringList parts;
    if (e.chuck)
        parts << (e.collet ? tr("collet %1") : tr("chuck %1")).arg(requiredStiffnessText(*e.chuck));
    if (e.tailstock)
        parts << tr("tailstock %1").arg(requiredStiffnessText(*e.tailstock));
    return parts.isEmpty() ? QStringLiteral("—") : parts.join(QStringLiteral(" · "));
}

int ToleranceVerdictModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_verdicts.size());
}

int ToleranceVerdictModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString ToleranceVerdictModel::specification(const Tolerance &t)
{
    if (isSizeTolerance(t.type)) {
        if (!t.iso286Class.isEmpty())
            return t.iso286Class;
        if (t.upperDeviation_um && t.lowerDeviation_um)
            return tr("%1/%2 µm").arg(signedNumber(*t.upperDeviation_um), signedNumber(*t.lowerDeviation_um));
        return {};
    }
    QString text = t.zone_um ? tr("%1 µm").arg(formatNumber(*t.zone_um)) : QString();
    if (!t.datums.isEmpty())
        text += QStringLiteral(" | ") + t.datums.join(QStringLiteral(" | "));
    return text;
}

QVariant ToleranceVerdictModel::display(int row, int column) const
{
    const Tolerance &t = m_tolerances[static_cast<std::size_t>(row)];
    const ToleranceRangeEvaluation &r = m_verdicts[static_cast<std::size_t>(row)];
    const ToleranceEvaluation &e = r.compliant;
    switch (column) {
    case Id:
        return t.id;
    case Characteristic:
        return displayName(t.type);
    case Feature:
        return t.type == ToleranceType::Length ? t.featureId + QStringLiteral(" – ") + t.toFeatureId : t.featureId;
    case Specification:
        return specification(t);
    case Value:
        return deviation(e.value_um, DisplaySettings::instance().units());
    case Limit:
        return deviation(e.limit_um, DisplaySettings::instance().units());
    case Utilisation:
        return e.utilisation_pct ? QStringLiteral("%1 %").arg(*e.utilisation_pct, 0, 'f', 1) : QStringLiteral("—");
    case VerdictColumn:
        return verdictName(e.verdict);
    case RangeColumn:
        return r.range == RangeVerdict::NoRange || r.range == RangeVerdict::NotDecided ? QStringLiteral("—")
                                                                                       : rangeVerdictText(r);
    case RequiredColumn:
        return requiredText(r);
    default:
        return {};
    }
}

QVariant ToleranceVerdictModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount() || index.column() >= ColumnCount)
        return {};
    const ToleranceRangeEvaluation &r = m_verdicts[static_cast<std::size_t>(index.row())];
    const ToleranceEvaluation &e = r.compliant;
    switch (role) {
    case Qt::DisplayRole:
        return display(index.row(), index.column());
    case Qt::BackgroundRole:
        if (index.column() == VerdictColumn)
            return verdictColor(e.verdict);
        if (index.column() == RangeColumn) {
            const QColor c = rangeVerdictColor(r);
            return c.isValid() ? QVariant(c) : QVariant(); // an invalid colour would paint the cell black
        }
        return {};
    case Qt::TextAlignmentRole:
        return index.column() >= Value && index.column() <= Utilisation
                   ? QVariant(int(Qt::AlignRight | Qt::AlignVCenter))
                   : QVariant();
    case Qt::ToolTipRole: {
        if (index.column() == RequiredColumn)
            return tr("The smallest radial stiffness of the chuck (at its face) and of the tailstock (or of both "
                      "centres) with which this tolerance passes as programmed at the planned conditions, the other "
                      "supports as assumed.");
        QString tip = e.condition;
        if (!e.reason.isEmpty())
            tip += (tip.isEmpty() ? QString() : QStringLiteral("\n")) + e.reason;
        for (const Diagnostic &d : e.diagnostics)
            tip += QStringLiteral("\n") + d.toString();
        return tip;
    }
    case UtilisationRole:
        return e.utilisation_pct ? QVariant(*e.utilisation_pct) : QVariant();
    case VerdictRole:
        return static_cast<int>(e.verdict);
    case RangeVerdictRole:
        return static_cast<int>(r.range);
    case FeatureIdRole:
        return e.featureId;
    default:
        return {};
    }
}

QVariant ToleranceVerdictModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Id:
        return tr("ID");
    case Characteristic:
        return tr("Characteristic");
    case Feature:
        return tr("Feature");
    case Specification:
        return tr("Specification");
    case Value:
        return tr("Predicted [%1]").arg(DisplaySettings::instance().units().deviationSymbol());
    case Limit:
        return tr("Limit [%1]").arg(DisplaySettings::instance().units().deviationSymbol());
    case Utilisation:
        return tr("Utilisation");
    case VerdictColumn:
        return tr("Verdict");
    case RangeColumn:
        return tr("On the machine range");
    case RequiredColumn:
        return tr("Stiffness needed");
    default:
        return {};
    }
}

QColor ToleranceVerdictModel::rangeVerdictColor(const ToleranceRangeEvaluation &e)
{
    switch (e.range) {
    case RangeVerdict::PassesOnAnyMachine:
        return verdictColor(Verdict::PassesAsProgrammed);
    case RangeVerdict::PassesIfStiffer:
    case RangeVerdict::PassesOnPartOfRange:
    case RangeVerdict::PassesAfterOffsetOnAnyMachine:
        return verdictColor(Verdict::PassesAfterOffset);
    case RangeVerdict::FailsEvenOnStiffest:
    case RangeVerdict::NotFinished:
        return verdictColor(Verdict::NeedsProfileCorrection);
    case RangeVerdict::NoRange:
    case RangeVerdict::NotDecided:
        return {};
    }
    return {};
}

QColor ToleranceVerdictModel::verdictColor(Verdict verdict)
{
    switch (verdict) {
    case Verdict::PassesAsProgrammed:
        return {0xc7, 0xe9, 0xc0};
    case Verdict::PassesAfterOffset:
        return {0xff, 0xe8, 0xa3};
    case Verdict::NeedsProfileCorrection:
        return {0xfc, 0xae, 0x91};
    case Verdict::NotPredicted:
        return {0xdd, 0xdd, 0xdd};
    case Verdict::CannotEvaluate:
        return {0xee, 0xee, 0xee};
    }
    return {};
}

} // namespace tolturn
