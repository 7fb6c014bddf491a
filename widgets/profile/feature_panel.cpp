// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/profile/feature_panel.h"

#include "core/common/diagnostic.h"
#include "core/part/undercuts.h"
#include "core/project/keywords.h"
#include "widgets/common/length_spin_box.h"
#include "widgets/common/project_fields.h"
#include "widgets/document/project_document.h"
#include "widgets/document/spin_box_steps.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace tolturn {

namespace {

// Entry bounds of every length; the profile validation judges the value.
constexpr double kMaxEntry_mm = 10000.0;

LengthSpinBox *millimetres(const QString &tip)
{
    return new LengthSpinBox(kMaxEntry_mm, tip);
}

// The kind-change button's text for a feature of `kind`.
QString kindChangeText(SegmentKind kind)
{
    switch (kind) {
    case SegmentKind::Cone:
        return FeaturePanel::tr("Make C&ylinder");
    case SegmentKind::Chamfer:
        return FeaturePanel::tr("Make R&ound");
    case SegmentKind::Radius:
        return FeaturePanel::tr("Make C&hamfer");
    default:
        return FeaturePanel::tr("Make C&one");
    }
}

} // namespace

FeaturePanel::FeaturePanel(ProjectDocument &document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_title(new QLabel)
    , m_startZ(millimetres(tr("z of the start, from the part's left end")))
    , m_startD(millimetres(tr("Diameter at the start")))
    , m_endZ(millimetres(tr("z of the end")))
    , m_endD(millimetres(tr("Diameter at the end")))
    , m_stepZ(millimetres(tr("Where the step is, inside the cylinder")))
    , m_stepD(millimetres(tr("Diameter after the step")))
    , m_insertStep(new QPushButton(tr("Insert &Step")))
    , m_cornerSize(millimetres(tr("Chamfer leg (45°) or radius")))
    , m_delete(new QPushButton(tr("&Delete Feature")))
    , m_changeKind(new QPushButton(tr("Make C&one")))
    , m_boreDepth(millimetres(tr("Depth of the bore from this end face; the part's length bores through")))
    , m_boreD(millimetres(tr("Diameter of the bore")))
    , m_bore(new QPushButton(tr("&Bore from This Face")))
    , m_grooveZ(millimetres(tr("Where the groove starts, inside the cylinder (its left flank)")))
    , m_grooveWidth(millimetres(tr("Width of the groove along z")))
    , m_grooveDepth(millimetres(tr("Depth of the groove, radially")))
    , m_insertGroove(new QPushButton(tr("Insert &Groove")))
    , m_undercutForm(new QComboBox)
    , m_undercutStart(new QPushButton(tr("Undercut start")))
    , m_undercutEnd(new QPushButton(tr("Undercut end")))
    , m_message(new QLabel)
{
    setObjectName(QStringLiteral("featurePanel"));
    m_title->setWordWrap(true);
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: #b00020;"));
    auto *geometry = new QGroupBox(tr("Corners"));
    auto *form = new QFormLayout(geometry);
    form->addRow(tr("Start z:"), m_startZ);
    form->addRow(tr("Start Ø:"), m_startD);
    form->addRow(tr("End z:"), m_endZ);
    form->addRow(tr("End Ø:"), m_endD);
    auto *step = new QGroupBox(tr("Step (cylinders)"));
    auto *stepForm = new QFormLayout(step);
    stepForm->addRow(tr("At z:"), m_stepZ);
    stepForm->addRow(tr("To Ø:"), m_stepD);
    stepForm->addRow(QString(), m_insertStep);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(geometry);
    layout->addWidget(step);
    layout->addWidget(createCornerRow());
    layout->addWidget(m_changeKind);
    layout->addWidget(createGrooveGroup());
    layout->addWidget(createBoreGroup());
    layout->addWidget(m_delete);
    layout->addWidget(m_message);
    layout->addStretch(1);
    m_cornerSize->setMillimetres(1.0);
    for (QDoubleSpinBox *box : {m_startZ, m_startD})
        connectSpinBoxSteps(box, m_document, this, [this] { moveCorner(false); });
    for (QDoubleSpinBox *box : {m_endZ, m_endD})
        connectSpinBoxSteps(box, m_document, this, [this] { moveCorner(true); });
    connect(m_insertStep, &QPushButton::clicked, this, &FeaturePanel::insertStep);
    connect(m_delete, &QPushButton::clicked, this, &FeaturePanel::deleteFeature);
    connect(m_changeKind, &QPushButton::clicked, this, &FeaturePanel::changeKind);
    connect(&m_document, &ProjectDocument::projectChanged, this, &FeaturePanel::showFeature);
    showFeature();
}

QWidget *FeaturePanel::createCornerRow()
{
    auto *group = new QGroupBox(tr("Break a corner"));
    auto *grid = new QGridLayout(group);
    grid->addWidget(new QLabel(tr("Size:")), 0, 0);
    grid->addWidget(m_cornerSize, 0, 1, 1, 2);

    const struct {
        QString text;
        bool atEnd;
        bool round;
    } commands[] = {{tr("Chamfer start"), false, false},
                    {tr("Chamfer end"), true, false},
                    {tr("Round start"), false, true},
                    {tr("Round end"), true, true}};

    int i = 0;
    for (const auto &c : commands) {
        auto *button = new QPushButton(c.text);
        grid->addWidget(button, 1 + i / 2, 1 + i % 2);
        connect(button, &QPushButton::clicked, this, [this, c] { breakCorner(c.atEnd, c.round); });
        ++i;
    }
    return group;
}

QWidget *FeaturePanel::createGrooveGroup()
{
    auto *group = new QGroupBox(tr("Groove and undercut (cylinders)"));
    auto *grid = new QGridLayout(group);
    grid->addWidget(new QLabel(tr("At z:")), 0, 0);
    grid->addWidget(m_grooveZ, 0, 1);
    grid->addWidget(new QLabel(tr("Width:")), 0, 2);
    grid->addWidget(m_grooveWidth, 0, 3);
    grid->addWidget(new QLabel(tr("Depth:")), 1, 0);
    grid->addWidget(m_grooveDepth, 1, 1);
    grid->addWidget(m_insertGroove, 1, 2, 1, 2);
    m_undercutForm->addItem(tr("DIN 509 form E (cylinder)"), static_cast<int>(UndercutForm::E));
    m_undercutForm->addItem(tr("DIN 509 form F (cylinder and face)"), static_cast<int>(UndercutForm::F));
    m_undercutForm->setToolTip(tr("The undercut is sized for the cylinder's diameter by DIN 509 Table 1 and cut "
                                  "into the corner where the cylinder meets a shoulder"));
    grid->addWidget(m_undercutForm, 2, 0, 1, 4);
    grid->addWidget(m_undercutStart, 3, 0, 1, 2);
    grid->addWidget(m_undercutEnd, 3, 2, 1, 2);
    m_grooveWidth->setMillimetres(3.0);
    m_grooveDepth->setMillimetres(1.0);
    connect(m_insertGroove, &QPushButton::clicked, this, &FeaturePanel::insertGroove);
    connect(m_undercutStart, &QPushButton::clicked, this, [this] { insertUndercut(false); });
    connect(m_undercutEnd, &QPushButton::clicked, this, [this] { insertUndercut(true); });
    return group;
}

QWidget *FeaturePanel::createBoreGroup()
{
    auto *group = new QGroupBox(tr("Bore (solid part, end face)"));
    auto *form = new QFormLayout(group);
    form->addRow(tr("Depth:"), m_boreDepth);
    form->addRow(tr("Ø:"), m_boreD);
    form->addRow(QString(), m_bore);
    connect(m_bore, &QPushButton::clicked, this, &FeaturePanel::addBore);
    return group;
}

void FeaturePanel::setFeature(const QString &featureId)
{
    if (featureId != m_featureId)
        m_document.endRepeatedEdits(); // the corner boxes now edit another feature
    m_featureId = featureId;
    m_message->clear();
    showFeature();
}

QString FeaturePanel::message() const
{
    return m_message->text();
}

void FeaturePanel::showFeature()
{
    const std::optional<FeatureRef> ref =
        m_document.hasProject() ? findFeature(m_document.project().part, m_featureId) : std::nullopt;
    setEnabled(ref.has_value());
    if (!ref) {
        m_title->setText(tr("Click a feature of the drawing to edit it."));
        setProjectField(*this, QString());
        return;
    }
    const Segment &s = *ref->segment;
    m_updating = true;
    const QString field = QStringLiteral("part.%1[%2]")
                              .arg(ref->side == ContourSide::Outer ? QStringLiteral("outer") : QStringLiteral("inner"))
                              .arg(ref->index);
    setProjectField(*this, field);
    setProjectField(*m_startZ, field + QStringLiteral(".from.z_mm"));
    setProjectField(*m_startD, field + QStringLiteral(".from.r_mm"));
    setProjectField(*m_endZ, field + QStringLiteral(".to.z_mm"));
    setProjectField(*m_endD, field + QStringLiteral(".to.r_mm"));
    markFindings(*this, m_document.problems());
    m_title->setText(
        tr("<b>%1</b> %2 — %3, %4 contour").arg(s.id, s.name, displayName(s.kind), contourName(ref->side)));
    m_startZ->setMillimetres(s.from.z_mm);
    m_startD->setMillimetres(2.0 * s.from.r_mm);
    m_endZ->setMillimetres(s.to.z_mm);
    m_endD->setMillimetres(2.0 * s.to.r_mm);
    const bool cylinder = s.kind == SegmentKind::Cylinder;
    m_insertStep->setEnabled(cylinder);
    const bool edgeBreak = s.kind == SegmentKind::Chamfer || s.kind == SegmentKind::Radius;
    m_changeKind->setEnabled(cylinder || s.kind == SegmentKind::Cone || edgeBreak);
    const std::vector<Segment> &outer = m_document.project().part.outer.segments;
    const bool endFace =
        ref->side == ContourSide::Outer && (ref->index == 0 || ref->index + 1 == static_cast<int>(outer.size()));
    // An end face still closed to the axis can be bored, though the other end is bored already.
    const bool closed = ref->index == 0 ? s.from.r_mm <= 0.0 : s.to.r_mm <= 0.0;
    m_bore->setEnabled(endFace && closed);
    m_insertGroove->setEnabled(cylinder);
    m_undercutStart->setEnabled(cylinder);
    m_undercutEnd->setEnabled(cylinder);
    if (const auto size = undercutSizeFor(2.0 * s.from.r_mm); cylinder && size)
        m_undercutForm->setToolTip(tr("DIN 509 Table 1 for Ø%1 mm: E or F %2 × %3 (r × t1), width f %4 mm, recess "
                                      "into the face t2 %5 mm (form F)")
                                       .arg(formatNumber(2.0 * s.from.r_mm), formatNumber(size->radius_mm),
                                            formatNumber(size->depth_mm), formatNumber(size->width_mm),
                                            formatNumber(size->faceDepth_mm)));
    m_changeKind->setText(kindChangeText(s.kind));
    if (cylinder) {
        m_grooveZ->setMillimetres(0.5 * (s.from.z_mm + s.to.z_mm));
        m_stepZ->setMillimetres(0.5 * (s.from.z_mm + s.to.z_mm));
        m_stepD->setMillimetres(2.0 * s.from.r_mm - 2.0 * m_cornerSize->millimetres());
    }
    m_updating = false;
}

void FeaturePanel::moveCorner(bool atEnd)
{
    if (m_updating)
        return;
    const std::optional<FeatureRef> ref = findFeature(m_document.project().part, m_featureId);
    if (!ref)
        return;
    const ProfilePoint to = atEnd ? ProfilePoint{m_endZ->millimetres(), m_endD->millimetres() / 2.0}
                                  : ProfilePoint{m_startZ->millimetres(), m_startD->millimetres() / 2.0};
    apply(moveVertex(m_document.project().part, ref->side, ref->index + (atEnd ? 1 : 0), to,
                     atEnd ? AtBreak::EndOfSegment : AtBreak::StartOfSegment),
          tr("Move corner of %1").arg(m_featureId));
}

bool FeaturePanel::moveVertexTo(ContourSide side, int vertex, ProfilePoint to, AtBreak atBreak)
{
    return apply(moveVertex(m_document.project().part, side, vertex, to, atBreak),
                 tr("Move corner to z %1, Ø %2").arg(formatNumber(to.z_mm), formatNumber(2.0 * to.r_mm)));
}

void FeaturePanel::insertStep()
{
    const QString cylinder = m_featureId;
    if (apply(tolturn::insertStep(m_document.project().part, cylinder, m_stepZ->millimetres(), m_stepD->millimetres()),
              tr("Insert step into %1").arg(cylinder)))
        Q_EMIT featureChosen(cylinder);
}

void FeaturePanel::breakCorner(bool atEnd, bool round)
{
    const std::optional<FeatureRef> ref = findFeature(m_document.project().part, m_featureId);
    if (!ref)
        return;
    apply(tolturn::breakCorner(m_document.project().part, ref->side, ref->index + (atEnd ? 1 : 0),
                               m_cornerSize->millimetres(), round),
          round ? tr("Round corner of %1").arg(m_featureId) : tr("Chamfer corner of %1").arg(m_featureId));
}

void FeaturePanel::changeKind()
{
    const std::optional<FeatureRef> ref = findFeature(m_document.project().part, m_featureId);
    if (!ref)
        return;
    if (ref->segment->kind == SegmentKind::Chamfer || ref->segment->kind == SegmentKind::Radius) {
        apply(swapCornerBreak(m_document.project().part, m_featureId),
              ref->segment->kind == SegmentKind::Chamfer ? tr("Make %1 an edge round").arg(m_featureId)
                                                         : tr("Make %1 a chamfer").arg(m_featureId));
        return;
    }
    if (ref->segment->kind == SegmentKind::Cone) {
        apply(makeCylinder(m_document.project().part, m_featureId), tr("Make %1 a cylinder").arg(m_featureId));
        return;
    }
    // The taper ends at the step diameter field's value (by default one corner size smaller).
    apply(makeCone(m_document.project().part, m_featureId, m_stepD->millimetres()),
          tr("Make %1 a cone").arg(m_featureId));
}

void FeaturePanel::addBore()
{
    apply(tolturn::addBore(m_document.project().part, m_featureId, m_boreDepth->millimetres(), m_boreD->millimetres()),
          tr("Bore from %1").arg(m_featureId));
}

void FeaturePanel::insertGroove()
{
    const QString cylinder = m_featureId;
    if (apply(tolturn::insertGroove(m_document.project().part, cylinder, m_grooveZ->millimetres(),
                                    m_grooveWidth->millimetres(), m_grooveDepth->millimetres()),
              tr("Insert groove into %1").arg(cylinder)))
        Q_EMIT featureChosen(cylinder);
}

void FeaturePanel::insertUndercut(bool atEnd)
{
    const std::optional<FeatureRef> ref = findFeature(m_document.project().part, m_featureId);
    if (!ref)
        return;
    const auto form = static_cast<UndercutForm>(m_undercutForm->currentData().toInt());
    const QString cylinder = m_featureId;
    if (apply(tolturn::insertUndercut(m_document.project().part, ref->side, ref->index + (atEnd ? 1 : 0), form),
              tr("Insert DIN 509 undercut at %1").arg(cylinder)))
        Q_EMIT featureChosen(cylinder);
}

void FeaturePanel::deleteFeature()
{
    const QString removed = m_featureId;
    if (apply(tolturn::deleteFeature(m_document.project().part, removed), tr("Delete %1").arg(removed)))
        Q_EMIT featureChosen(QString());
}

bool FeaturePanel::apply(const ProfileEdit &edit, const QString &description)
{
    if (const auto *refusal = std::get_if<QString>(&edit)) {
        m_message->setText(*refusal);
        showFeature();
        return false;
    }
    QStringList errors;
    for (const Diagnostic &d : m_document.setPart(std::get<PartProfile>(edit), description))
        if (d.severity == Severity::Error)
            errors << d.toString();
    m_message->setText(errors.join(QLatin1Char('\n')));
    if (!errors.isEmpty())
        showFeature(); // the part is as it was: show its values again
    return errors.isEmpty();
}

} // namespace tolturn
