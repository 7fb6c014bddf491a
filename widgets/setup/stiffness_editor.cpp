// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/setup/stiffness_editor.h"

#include <QAbstractSpinBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace tolturn {

namespace {

QDoubleSpinBox *stiffnessBox(const QString &unit, const QString &tip)
{
    auto *box = new QDoubleSpinBox;
    box->setRange(0.0, 1e12); // entry bounds; zero means not measured
    box->setDecimals(0);
    if (!unit.isEmpty())
        box->setSuffix(QLatin1Char(' ') + unit);
    box->setSpecialValueText(StiffnessEditor::tr("—"));
    box->setButtonSymbols(QAbstractSpinBox::NoButtons); // narrow: large numbers are typed
    box->setMinimumWidth(50);
    box->setToolTip(tip);
    box->setKeyboardTracking(false);
    box->setGroupSeparatorShown(true);
    return box;
}

std::optional<SpindleSprings> springs(const std::array<QDoubleSpinBox *, 3> &row)
{
    if (row[0]->value() == 0.0 && row[1]->value() == 0.0 && row[2]->value() == 0.0)
        return std::nullopt;
    return SpindleSprings{row[0]->value(), row[1]->value(), row[2]->value()};
}

std::optional<SupportStiffness> support(const std::array<QDoubleSpinBox *, 3> &row)
{
    if (row[0]->value() == 0.0 && row[1]->value() == 0.0)
        return std::nullopt;
    return SupportStiffness{row[0]->value(), row[1]->value()};
}

} // namespace

StiffnessEditor::StiffnessEditor(QWidget *parent)
    : QGroupBox(tr("Measured machine stiffness"), parent)
    , m_source(new QLineEdit)
{
    const QString springTip = tr("Spindle–chuck springs (Valiño et al. 2008, §III, eq. 2–4): k1 radial translation "
                                 "[N/mm], k2 and k3 rotation [N·mm/rad] about the pivot Lc behind the chuck face.");
    const QString supportTip = tr("Support stiffness of the centre at the part's right (or both) ends [N/mm], as a "
                                  "spring under the workpiece beam (MODEL.md §3).");
    m_pivot =
        stiffnessBox(tr("mm"), tr("Lc: distance of the k2 spring behind the chuck face (Valiño et al. 2008, Fig. 2)."));
    m_pivot->setDecimals(1);
    m_source->setPlaceholderText(tr("who measured it, when, how"));
    auto *grid = new QGridLayout(this);
    grid->addWidget(new QLabel(tr("Source:")), 0, 0);
    grid->addWidget(m_source, 0, 1, 1, 3);
    grid->addWidget(new QLabel(tr("Lc:")), 1, 0);
    grid->addWidget(m_pivot, 1, 1, 1, 3);
    // Units in the column heads keep the boxes narrow enough for the dock.
    grid->addWidget(new QLabel(tr("k1 [N/mm]")), 2, 1);
    grid->addWidget(new QLabel(tr("k2 [N·mm/rad]")), 2, 2);
    grid->addWidget(new QLabel(tr("k3 [N·mm/rad]")), 2, 3);
    grid->addWidget(new QLabel(tr("radial [N/mm]")), 5, 1);
    grid->addWidget(new QLabel(tr("tangential [N/mm]")), 5, 2, 1, 2);
    const QString rows[] = {tr("Spindle radial"), tr("Spindle tangential"), tr("Tailstock"), tr("Centres")};
    const int gridRows[] = {3, 4, 6, 7};
    for (int r = 0; r < 4; ++r) {
        grid->addWidget(new QLabel(rows[r]), gridRows[r], 0);
        const bool spindle = r < 2;
        for (int c = 0; c < (spindle ? 3 : 2); ++c) {
            QDoubleSpinBox *box =
                spindle ? stiffnessBox(QString(), springTip)
                        : stiffnessBox(QString(), supportTip + (c == 0 ? tr(" Radial.") : tr(" Tangential.")));
            m_boxes[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] = box;
            grid->addWidget(box, gridRows[r], 1 + c);
            connect(box, &QDoubleSpinBox::valueChanged, this, [this] {
                if (!m_updating)
                    Q_EMIT edited();
            });
        }
    }
    m_fit = new QPushButton(tr("Fit from Test Bar…"));
    m_fit->setToolTip(tr("Valiño et al. 2008 §III: the open project is a stiff bar turned in the chuck; a CSV of its "
                         "measured deviation (z_mm, radial_um, optionally tangential_um) gives k1, k2, k3 for the "
                         "Lc entered above."));
    grid->addWidget(m_fit, 8, 1, 1, 3);
    connect(m_fit, &QPushButton::clicked, this, &StiffnessEditor::fitRequested);
    connect(m_pivot, &QDoubleSpinBox::valueChanged, this, [this] {
        if (!m_updating)
            Q_EMIT edited();
    });
    connect(m_source, &QLineEdit::editingFinished, this, [this] {
        if (!m_updating)
            Q_EMIT edited();
    });
}

QDoubleSpinBox *StiffnessEditor::box(int row, int column) const
{
    return m_boxes.at(static_cast<std::size_t>(row)).at(static_cast<std::size_t>(column));
}

void StiffnessEditor::showCharacterisation(const MachineCharacterisation &c)
{
    m_updating = true;
    m_source->setText(c.source);
    m_pivot->setValue(c.pivotDistance_mm.value_or(0.0));
    const std::optional<SpindleSprings> spindle[] = {c.spindleRadial, c.spindleTangential};
    for (std::size_t r = 0; r < 2; ++r) {
        m_boxes[r][0]->setValue(spindle[r] ? spindle[r]->k1_N_per_mm : 0.0);
        m_boxes[r][1]->setValue(spindle[r] ? spindle[r]->k2_Nmm_per_rad : 0.0);
        m_boxes[r][2]->setValue(spindle[r] ? spindle[r]->k3_Nmm_per_rad : 0.0);
    }
    const std::optional<SupportStiffness> supports[] = {c.tailstock, c.centres};
    for (std::size_t r = 0; r < 2; ++r) {
        m_boxes[2 + r][0]->setValue(supports[r] ? supports[r]->radial_N_per_mm : 0.0);
        m_boxes[2 + r][1]->setValue(supports[r] ? supports[r]->tangential_N_per_mm : 0.0);
    }
    m_updating = false;
}

QString StiffnessEditor::missing() const
{
    const QString rows[] = {tr("spindle radial k1, k2, k3"), tr("spindle tangential k1, k2, k3"),
                            tr("tailstock radial and tangential"), tr("centres radial and tangential")};
    bool any = false;
    bool springs = false;
    for (std::size_t r = 0; r < 4; ++r) {
        const std::size_t columns = r < 2 ? 3 : 2;
        std::size_t filled = 0;
        for (std::size_t c = 0; c < columns; ++c)
            filled += m_boxes[r][c]->value() > 0.0 ? 1U : 0U;
        if (filled > 0 && filled < columns)
            return tr("enter all of %1").arg(rows[r]);
        any = any || filled > 0;
        springs = springs || (r < 2 && filled > 0);
    }
    any = any || m_pivot->value() > 0.0;
    if (springs && m_pivot->value() <= 0.0)
        return tr("enter the pivot distance Lc of the spindle springs");
    if (any && m_source->text().trimmed().isEmpty())
        return tr("enter where the numbers come from (source)");
    return {};
}

MachineCharacterisation StiffnessEditor::characterisation(const MachineCharacterisation &current) const
{
    MachineCharacterisation c = current;
    c.source = m_source->text().trimmed();
    c.pivotDistance_mm = m_pivot->value() > 0.0 ? std::optional<double>(m_pivot->value()) : std::nullopt;
    c.spindleRadial = springs(m_boxes[0]);
    c.spindleTangential = springs(m_boxes[1]);
    c.tailstock = support(m_boxes[2]);
    c.centres = support(m_boxes[3]);
    return c;
}

} // namespace tolturn
