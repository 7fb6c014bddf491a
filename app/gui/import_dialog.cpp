// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/import_dialog.h"

#include "core/common/diagnostic.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

namespace tolturn {

namespace {

QString vectorText(const double (&v)[3])
{
    return QStringLiteral("(%1, %2, %3)").arg(formatNumber(v[0]), formatNumber(v[1]), formatNumber(v[2]));
}

QString summary(const QString &fileName, const CadImportResult &read)
{
    const PartProfile &p = *read.profile;
    return ImportDialog::tr("<b>%1</b>: a turned part %2 mm long, Ø max %3 mm, with %4 outer and %5 inner "
                            "features; %6 warning(s), listed after the import.")
        .arg(fileName.toHtmlEscaped(), formatNumber(p.length_mm()), formatNumber(2.0 * p.maxOuterRadius_mm()))
        .arg(p.outer.segments.size())
        .arg(p.inner.segments.size())
        .arg(countOf(read.diagnostics, Severity::Warning));
}

} // namespace

ImportDialog::ImportDialog(const QString &fileName, const CadImportResult &read, QWidget *parent)
    : QDialog(parent)
    , m_solid(new QComboBox)
    , m_axis(new QComboBox)
    , m_flip(new QCheckBox)
{
    setObjectName(QStringLiteral("importDialog"));
    setWindowTitle(tr("Import %1").arg(fileName));
    // Bodies and axes are numbered from 0, as in the import's messages and `tolturn-cli import`.
    for (std::size_t i = 0; i < read.solids.size(); ++i)
        m_solid->addItem(tr("Body %1: %2 mm³, %3 faces")
                             .arg(i)
                             .arg(QLocale().toString(read.solids[i].volume_mm3, 'f', 0))
                             .arg(read.solids[i].faceCount));
    m_solid->setCurrentIndex(read.chosenSolid);
    m_solid->setEnabled(read.solids.size() > 1);
    for (std::size_t i = 0; i < read.axes.size(); ++i)
        m_axis->addItem(tr("Axis %1: through %2 along %3, %4 revolved faces")
                            .arg(i)
                            .arg(vectorText(read.axes[i].origin_mm), vectorText(read.axes[i].direction))
                            .arg(read.axes[i].faceCount));
    m_axis->setCurrentIndex(read.chosenAxis);
    m_axis->setEnabled(read.axes.size() > 1);
    m_axis->setToolTip(tr("The common axis of the body's cylindrical, conical, toroidal and spherical faces; "
                          "the one with the most revolved area is proposed."));
    m_flip->setText(tr("Chuck at the model's other end (turn the part end for end)"));
    m_flip->setToolTip(tr("z = 0 is the part's left end, the end held in the chuck. Tick to put the "
                          "model's right end there instead."));

    auto *about = new QLabel(summary(fileName, read));
    about->setWordWrap(true);
    auto *form = new QFormLayout;
    form->addRow(tr("&Body:"), m_solid);
    form->addRow(tr("&Axis:"), m_axis);
    form->addRow(QString(), m_flip);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Import"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(about);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

CadImportChoice ImportDialog::choice() const
{
    return {m_solid->currentIndex(), m_axis->currentIndex(), m_flip->isChecked()};
}

} // namespace tolturn
