// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/tolerances/tolerance_dialog.h"

#include "core/project/keywords.h"
#include "core/project/project_validation.h"
#include "core/tolerance/iso286.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QRegularExpression>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <cmath>

namespace tolturn {

namespace {

QDoubleSpinBox *microns(QWidget *parent, double lo, double hi)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setRange(lo, hi);
    box->setDecimals(1);
    box->setSuffix(QStringLiteral(" µm"));
    return box;
}

QString featureDescription(const Project &p, const QString &id)
{
    const auto f = findFeature(p.part, id);
    if (!f)
        return id;
    const Segment &s = *f->segment;
    QString text = QStringLiteral("%1 — %2, %3").arg(id, displayName(s.kind), contourName(f->side));
    if (s.kind == SegmentKind::Cylinder)
        text += QStringLiteral(", Ø%1 mm").arg(formatNumber(2.0 * s.from.r_mm));
    else if (s.kind == SegmentKind::Face)
        text += QStringLiteral(", z = %1 mm").arg(formatNumber(s.from.z_mm));
    if (!s.name.isEmpty())
        text += QStringLiteral(" (") + s.name + QLatin1Char(')');
    return text;
}

} // namespace

ToleranceDialog::ToleranceDialog(const Project &project, const QString &featureId, const Tolerance &initial,
                                 Apply apply, QWidget *parent)
    : QDialog(parent)
    , m_project(project)
    , m_featureId(featureId)
    , m_initial(initial)
    , m_apply(std::move(apply))
    , m_type(new QComboBox(this))
    , m_pages(new QStackedWidget(this))
    , m_toFace(new QComboBox(this))
    , m_isoMode(new QRadioButton(tr("ISO 286 class"), this))
    , m_explicitMode(new QRadioButton(tr("Limit deviations"), this))
    , m_isoClass(new QLineEdit(this))
    , m_limits(new QLabel(this))
    , m_upper(microns(this, -100000.0, 100000.0))
    , m_lower(microns(this, -100000.0, 100000.0))
    , m_zone(microns(this, 0.0, 100000.0))
    , m_datums(new QLineEdit(this))
    , m_problems(new QLabel(this))
{
    setObjectName(QStringLiteral("toleranceDialog"));
    setWindowTitle(initial.id.isEmpty() ? tr("Add Tolerance") : tr("Edit Tolerance %1").arg(initial.id));
    const auto feature = findFeature(project.part, featureId);
    for (const QString &word : allKeywords<ToleranceType>()) {
        const ToleranceType type = *fromKeyword<ToleranceType>(word);
        if (feature && toleranceFitsFeature(type, feature->segment->kind))
            m_type->addItem(displayName(type), static_cast<int>(type));
    }
    for (const Contour *c : {&project.part.outer, &project.part.inner}) {
        for (const Segment &s : c->segments) {
            if (s.kind == SegmentKind::Face && s.id != featureId)
                m_toFace->addItem(QStringLiteral("%1 (z = %2 mm)").arg(s.id, formatNumber(s.from.z_mm)), s.id);
        }
    }

    // Size page: ISO 286 class with live limits, or explicit limits; the second face of a length.
    auto *sizePage = new QWidget(m_pages);
    auto *size = new QFormLayout(sizePage);
    size->addRow(tr("To face"), m_toFace);
    size->addRow(m_isoMode, m_isoClass);
    size->addRow(QString(), m_limits);
    size->addRow(m_explicitMode);
    size->addRow(tr("Upper deviation"), m_upper);
    size->addRow(tr("Lower deviation"), m_lower);
    m_isoClass->setPlaceholderText(tr("e.g. h6, H7, js12"));
    m_isoClass->setToolTip(tr("ISO 286-1 tolerance class: small letters for shafts, capitals for holes."));
    m_isoMode->setChecked(true);
    // Geometric page: zone and datums (ISO 1101).
    auto *geometricPage = new QWidget(m_pages);
    auto *geometric = new QFormLayout(geometricPage);
    geometric->addRow(tr("Tolerance zone t"), m_zone);
    geometric->addRow(tr("Datums"), m_datums);
    QStringList labels;
    for (const Datum &d : project.datums)
        labels << QStringLiteral("%1 (%2)").arg(d.label, d.featureId);
    m_datums->setPlaceholderText(labels.isEmpty() ? tr("no datum defined yet")
                                                  : tr("e.g. A; defined: %1").arg(labels.join(QStringLiteral(", "))));
    m_zone->setValue(10.0);
    m_pages->addWidget(sizePage);
    m_pages->addWidget(geometricPage);

    m_problems->setWordWrap(true);
    m_problems->setStyleSheet(QStringLiteral("color: #b00;"));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    auto *form = new QFormLayout;
    form->addRow(tr("Feature"), new QLabel(featureDescription(project, featureId), this));
    form->addRow(tr("Characteristic"), m_type);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_pages);
    layout->addWidget(m_problems);
    layout->addWidget(buttons);

    connect(buttons, &QDialogButtonBox::accepted, this, &ToleranceDialog::tryAccept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_type, &QComboBox::currentIndexChanged, this, &ToleranceDialog::rebuildForType);
    connect(m_isoClass, &QLineEdit::textChanged, this, &ToleranceDialog::updateLimits);
    connect(m_toFace, &QComboBox::currentIndexChanged, this, &ToleranceDialog::updateLimits);
    connect(m_isoMode, &QRadioButton::toggled, this, &ToleranceDialog::rebuildForType);

    // Start from the tolerance being edited.
    if (const int i = m_type->findData(static_cast<int>(initial.type)); i >= 0 && !initial.id.isEmpty())
        m_type->setCurrentIndex(i);
    if (!initial.toFeatureId.isEmpty())
        m_toFace->setCurrentIndex(std::max(0, m_toFace->findData(initial.toFeatureId)));
    if (!initial.iso286Class.isEmpty())
        m_isoClass->setText(initial.iso286Class);
    if (initial.upperDeviation_um && initial.lowerDeviation_um) {
        m_explicitMode->setChecked(true);
        m_upper->setValue(*initial.upperDeviation_um);
        m_lower->setValue(*initial.lowerDeviation_um);
    }
    if (initial.zone_um)
        m_zone->setValue(*initial.zone_um);
    m_datums->setText(initial.datums.join(QStringLiteral(", ")));
    rebuildForType();
    setMinimumWidth(460);
}

ToleranceType ToleranceDialog::currentType() const
{
    return static_cast<ToleranceType>(m_type->currentData().toInt());
}

void ToleranceDialog::rebuildForType()
{
    const bool sizeType = isSizeTolerance(currentType());
    m_pages->setCurrentIndex(sizeType ? 0 : 1);
    m_toFace->setEnabled(currentType() == ToleranceType::Length);
    const bool iso = m_isoMode->isChecked();
    m_isoClass->setEnabled(iso);
    m_upper->setEnabled(!iso);
    m_lower->setEnabled(!iso);
    updateLimits();
}

double ToleranceDialog::nominalSize_mm() const
{
    const auto f = findFeature(m_project.part, m_featureId);
    if (!f)
        return 0.0;
    if (currentType() == ToleranceType::Length) {
        const auto other = findFeature(m_project.part, m_toFace->currentData().toString());
        return other ? std::abs(other->segment->from.z_mm - f->segment->from.z_mm) : 0.0;
    }
    return 2.0 * f->segment->from.r_mm;
}

void ToleranceDialog::updateLimits()
{
    const QString cls = m_isoClass->text().trimmed();
    if (cls.isEmpty() || !isSizeTolerance(currentType())) {
        m_limits->clear();
        return;
    }
    const iso286::LimitsResult r = iso286::limits(nominalSize_mm(), cls);
    if (!r.limits) {
        m_limits->setText(r.diagnostics.empty() ? QString() : r.diagnostics.front().message);
        m_limits->setStyleSheet(QStringLiteral("color: #b00;"));
        return;
    }
    m_limits->setStyleSheet(QString());
    // An explicit QString: with QT_USE_QSTRINGBUILDER a deduced "a + b" would reference temporaries.
    const auto sign = [](double v) -> QString { return (v > 0.0 ? QStringLiteral("+") : QString()) + formatNumber(v); };
    m_limits->setText(tr("at %1 mm: upper %2 µm, lower %3 µm (%4 = %5 µm)")
                          .arg(formatNumber(nominalSize_mm()), sign(r.limits->upper_um), sign(r.limits->lower_um),
                               r.limits->itName, formatNumber(r.limits->it_um)));
}

Tolerance ToleranceDialog::tolerance() const
{
    Tolerance t;
    t.id = m_initial.id;
    t.type = currentType();
    t.featureId = m_featureId;
    if (t.type == ToleranceType::Length)
        t.toFeatureId = m_toFace->currentData().toString();
    if (isSizeTolerance(t.type)) {
        if (m_isoMode->isChecked()) {
            t.iso286Class = m_isoClass->text().trimmed();
        } else {
            t.upperDeviation_um = m_upper->value();
            t.lowerDeviation_um = m_lower->value();
        }
    } else {
        t.zone_um = m_zone->value();
        static const QRegularExpression separators(QStringLiteral("[,;|\\s]+"));
        t.datums = m_datums->text().toUpper().split(separators, Qt::SkipEmptyParts);
    }
    return t;
}

QString ToleranceDialog::limitsText() const
{
    return m_limits->text();
}

QString ToleranceDialog::problemsText() const
{
    return m_problems->text();
}

void ToleranceDialog::setCharacteristic(ToleranceType type)
{
    m_type->setCurrentIndex(m_type->findData(static_cast<int>(type)));
}

void ToleranceDialog::setIsoClass(const QString &isoClass)
{
    m_isoMode->setChecked(true);
    m_isoClass->setText(isoClass);
}

void ToleranceDialog::setExplicitLimits(double upper_um, double lower_um)
{
    m_explicitMode->setChecked(true);
    m_upper->setValue(upper_um);
    m_lower->setValue(lower_um);
}

void ToleranceDialog::setZone(double zone_um, const QString &datums)
{
    m_zone->setValue(zone_um);
    m_datums->setText(datums);
}

bool ToleranceDialog::tryAccept()
{
    const Diagnostics problems = m_apply(tolerance());
    if (!problems.empty()) {
        QStringList lines;
        for (const Diagnostic &d : problems)
            lines << d.message;
        m_problems->setText(lines.join(QLatin1Char('\n')));
        return false;
    }
    m_problems->clear();
    accept();
    return true;
}

} // namespace tolturn
