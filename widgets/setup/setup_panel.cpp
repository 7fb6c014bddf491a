// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/setup/setup_panel.h"

#include "core/data/data_library.h"
#include "core/deviation/stiffness_calibration.h"
#include "core/planning/plausibility.h"
#include "core/project/keywords.h"
#include "core/project/operations.h"
#include "core/tooling/iso1832.h"
#include "widgets/common/length_spin_box.h"
#include "widgets/common/project_fields.h"
#include "widgets/document/project_document.h"
#include "widgets/document/spin_box_steps.h"
#include "widgets/setup/force_model_editor.h"
#include "widgets/setup/stiffness_editor.h"

#include <QComboBox>
#include <QDate>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QVBoxLayout>

#include <array>
#include <cmath>

namespace tolturn {

namespace {

enum PassColumn { kSpeed = 0, kFeed = 1, kDepth = 2 };

// The project file's keys of the pass columns, the fields findings name.
constexpr std::array<const char *, 3> kPassKeys{"cutting_speed_m_min", "feed_mm_rev", "depth_of_cut_mm"};

QString sourced(const DataLibrary &data, const QString &what, const SourcedValue &v)
{
    return QStringLiteral("%1 = %2 (%3)").arg(what).arg(v.value).arg(data.sourceText(v.source).left(160));
}

QString materialTip(const DataLibrary &data, const MaterialData &m)
{
    return QStringList{m.name, sourced(data, QStringLiteral("kc1.1 [N/mm²]"), m.kc11_MPa),
                       sourced(data, QStringLiteral("mc"), m.mc),
                       sourced(data, QStringLiteral("E [MPa]"), m.youngsModulus_MPa),
                       SetupPanel::tr("Kienzle: Fc = kc1.1 · b · h^(1 − mc) (MODEL.md §2, Kienzle 1952).")}
        .join(QLatin1Char('\n'));
}

// Entry bounds of a spin box: wide enough for any lathe; the document's validation judges the value.
QDoubleSpinBox *spinBox(double min, double max, int decimals, const QString &suffix, const QString &tip)
{
    auto *box = new QDoubleSpinBox;
    box->setRange(min, max);
    box->setDecimals(decimals);
    box->setSuffix(suffix);
    box->setToolTip(tip);
    box->setKeyboardTracking(false); // one edit when the value is finished, not per keystroke
    return box;
}

// The length of the first cylinder of the outer contour: where a chuck usually grips.
double firstCylinderLength(const PartProfile &part)
{
    for (const Segment &s : part.outer.segments)
        if (s.kind == SegmentKind::Cylinder)
            return std::abs(s.to.z_mm - s.from.z_mm);
    return 0.0;
}

// Selects the item whose data is `value`, adding it (marked unknown) when the list lacks it.
void selectData(QComboBox *box, const QString &value)
{
    int index = box->findData(value);
    if (index < 0 && !value.isEmpty()) {
        box->addItem(SetupPanel::tr("%1 (not in the data library)").arg(value), value);
        index = box->count() - 1;
    }
    box->setCurrentIndex(index);
}

} // namespace

SetupPanel::SetupPanel(ProjectDocument &document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_material(new QComboBox)
    , m_machine(new QComboBox)
    , m_machineStiffness(new QLabel)
    , m_stiffness(new StiffnessEditor)
    , m_insert(new QLineEdit)
    , m_insertDecoded(new QLabel)
    , m_holder(new QComboBox)
    , m_clamping(new QComboBox)
    , m_clampedLength(new LengthSpinBox(
          10000.0, tr("Length of the part in the jaws from its left end; the chuck face is at this z. "
                      "The part is a beam built in there (Valiño et al. 2008, eq. 2–5).")))
    , m_overhang(new LengthSpinBox(
          1000.0, tr("Tool length out of the turret for the toolpost term (Valiño et al. 2008, eq. 6); "
                     "'from holder' uses the holder's length.")))
    , m_forceModel(new ForceModelEditor)
    , m_message(new QLabel)
{
    setObjectName(QStringLiteral("setupPanel"));
    m_overhang->setSpecialValueText(tr("from holder"));
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: #b00020;"));
    m_message->setObjectName(QStringLiteral("setupMessage"));
    auto *content = new QWidget;
    auto *column = new QVBoxLayout(content);
    column->addWidget(createDrawingGroup());
    column->addWidget(createPartGroup());
    column->addWidget(m_stiffness);
    column->addWidget(createToolGroup());
    column->addWidget(createBoringGroup());
    column->addWidget(createClampingGroup());
    column->addWidget(createPassesGroup());
    column->addWidget(m_forceModel);
    column->addWidget(m_message);
    column->addStretch(1);
    auto *scroll = new QScrollArea;
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);
    for (QComboBox *box : {m_material, m_machine, m_holder}) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon); // long names elide
        box->setMinimumContentsLength(14);
    }
    fillChoices();
    setProjectField(*m_material, QStringLiteral("material"));
    setProjectField(*m_machine, QStringLiteral("machine"));
    setProjectField(*m_stiffness, QStringLiteral("characterisation"));
    setProjectField(*m_insert, QStringLiteral("tool.insert"));
    setProjectField(*m_holder, QStringLiteral("tool.holder"));
    setProjectField(*m_overhang, QStringLiteral("tool.overhang_mm"));
    setProjectField(*m_clamping, QStringLiteral("clamping.method"));
    setProjectField(*m_clampedLength, QStringLiteral("clamping.clamped_length_mm"));
    connect(m_forceModel, &ForceModelEditor::cuttingModelEdited, this,
            [this](const CuttingModel &model) { showOutcome(m_document.setCuttingModel(model)); });
    connect(m_forceModel, &ForceModelEditor::environmentEdited, this,
            [this](const Environment &environment) { showOutcome(m_document.setEnvironment(environment)); });
    connect(&m_document, &ProjectDocument::projectChanged, this, &SetupPanel::showDocumentValues);
    showDocumentValues();
}

QWidget *SetupPanel::createPartGroup()
{
    auto *group = new QGroupBox(tr("Material and machine"));
    auto *form = new QFormLayout(group);
    form->addRow(tr("&Material:"), m_material);
    form->addRow(tr("Mac&hine:"), m_machine);
    form->addRow(tr("Stiffness:"), m_machineStiffness);
    m_machineStiffness->setWordWrap(true);
    connect(m_material, &QComboBox::activated, this, &SetupPanel::applyMaterial);
    connect(m_machine, &QComboBox::activated, this, &SetupPanel::applyMachine);
    connect(m_stiffness, &StiffnessEditor::edited, this, &SetupPanel::applyStiffness);
    connect(m_stiffness, &StiffnessEditor::fitRequested, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Measured Test Bar"), QString(),
                                                          tr("Measurements (*.csv *.txt);;All files (*)"));
        if (!path.isEmpty())
            (void)fitStiffnessFromTestBar(path);
    });
    return group;
}

// The part as its drawing names it, for the report's title block.
QWidget *SetupPanel::createDrawingGroup()
{
    auto *group = new QGroupBox(tr("Part"));
    auto *form = new QFormLayout(group);
    m_partName = new QLineEdit;
    m_drawingNumber = new QLineEdit;
    m_revision = new QLineEdit;
    m_partName->setObjectName(QStringLiteral("partName"));
    m_drawingNumber->setObjectName(QStringLiteral("drawingNumber"));
    m_revision->setObjectName(QStringLiteral("drawingRevision"));
    m_stockDiameter = new LengthSpinBox(
        10000.0, tr("Diameter of the bar the part is turned from: the roughing passes remove the stock between it and "
                    "the profile."));
    m_stockDiameter->setObjectName(QStringLiteral("stockDiameter"));
    m_drawingNumber->setToolTip(tr("The number of the part drawing the tolerances come from (report title block)"));
    form->addRow(tr("&Name:"), m_partName);
    form->addRow(tr("&Drawing no.:"), m_drawingNumber);
    form->addRow(tr("&Revision:"), m_revision);
    form->addRow(tr("&Stock Ø:"), m_stockDiameter);
    for (QLineEdit *edit : {m_partName, m_drawingNumber, m_revision})
        connect(edit, &QLineEdit::editingFinished, this, &SetupPanel::applyDrawing);
    connectSpinBoxSteps(m_stockDiameter, m_document, this, [this] { applyDrawing(); });
    setProjectField(*m_partName, QStringLiteral("part.name"));
    setProjectField(*m_drawingNumber, QStringLiteral("part.drawing_number"));
    setProjectField(*m_revision, QStringLiteral("part.revision"));
    setProjectField(*m_stockDiameter, QStringLiteral("part.stock_diameter_mm"));
    return group;
}

void SetupPanel::applyDrawing()
{
    if (m_updating)
        return;
    PartProfile part = m_document.project().part;
    part.name = m_partName->text().trimmed();
    part.drawingNumber = m_drawingNumber->text().trimmed();
    part.revision = m_revision->text().trimmed();
    part.stockDiameter_mm = m_stockDiameter->millimetres();
    if (part == m_document.project().part)
        return;
    showOutcome(m_document.setPart(part, tr("Change part name, drawing or stock")));
}

QWidget *SetupPanel::createToolGroup()
{
    auto *group = new QGroupBox(tr("Tool"));
    auto *form = new QFormLayout(group);
    m_insert->setToolTip(tr("ISO 1832 designation, e.g. CNMG 120408: shape, clearance, tolerance, type, size, "
                            "thickness, corner radius."));
    m_insert->setPlaceholderText(QStringLiteral("CNMG 120408"));
    form->addRow(tr("&Insert (ISO 1832):"), m_insert);
    form->addRow(QString(), m_insertDecoded);
    form->addRow(tr("H&older (ISO 5608):"), m_holder);
    form->addRow(tr("&Overhang:"), m_overhang);
    connect(m_insert, &QLineEdit::editingFinished, this, &SetupPanel::applyTool);
    connect(m_holder, &QComboBox::activated, this, &SetupPanel::applyTool);
    connectSpinBoxSteps(m_overhang, m_document, this, [this] { applyTool(); });
    return group;
}

// The boring bar that cuts the bores (docs/model.md §3.1): none, or a bar of the data library with
// its insert, overhang and the cutting edge's offset from its axis.
QWidget *SetupPanel::createBoringGroup()
{
    auto *group = new QGroupBox(tr("Boring bar"));
    auto *form = new QFormLayout(group);
    m_boringBar = new QComboBox;
    m_boringBar->setObjectName(QStringLiteral("boringBar"));
    m_boringBar->setToolTip(tr("The bar that cuts the inner contour. Without one the bores are computed as if cut by "
                               "the turning tool, without the bending of a bar."));
    m_boringBar->addItem(tr("none"), QString());
    const DataLibrary &library = DataLibrary::builtIn();
    for (const HolderData &h : library.holders()) {
        if (!h.isBoringBar() || !h.barDiameter_mm)
            continue;
        const BoringBarMaterialData *m = library.boringBarMaterial(h);
        m_boringBar->addItem(
            tr("%1 (Ø%2 mm, %3)")
                .arg(h.code, formatNumber(h.barDiameter_mm->value), m ? m->id : tr("material unknown")),
            h.code);
    }
    m_boringBar->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_boringBar->setMinimumContentsLength(14);
    m_boringInsert = new QLineEdit;
    m_boringInsert->setObjectName(QStringLiteral("boringInsert"));
    m_boringInsert->setPlaceholderText(QStringLiteral("CCMT 09T304"));
    m_boringInsert->setToolTip(tr("ISO 1832 designation of the boring bar's insert: its nose radius and the bar's "
                                  "entering angle give the forces in the bores."));
    m_boringOverhang = new LengthSpinBox(
        2000.0, tr("Length of the bar out of its clamping to the cutting edge. 'bore depth' takes the least "
                   "that reaches the deepest bore from the right end face, with the turret 2 mm off it."));
    m_boringOverhang->setObjectName(QStringLiteral("boringOverhang"));
    m_boringOverhang->setSpecialValueText(tr("bore depth"));
    m_boringEdgeOffset = new LengthSpinBox(
        500.0, tr("The cutting edge's distance from the bar's axis, the maker's dimension f: the arm of the torque "
                  "that twists the bar. 'bar radius' takes the least it can be."));
    m_boringEdgeOffset->setObjectName(QStringLiteral("boringEdgeOffset"));
    m_boringEdgeOffset->setSpecialValueText(tr("bar radius"));
    m_pilotHole = new LengthSpinBox(
        2000.0, tr("Diameter of the hole drilled (or cored) before the bar starts: the program roughs the bore from "
                   "it. 'not given' takes the bore as roughed to its finishing allowance before the program."));
    m_pilotHole->setObjectName(QStringLiteral("pilotHole"));
    m_pilotHole->setSpecialValueText(tr("not given"));
    m_boringSummary = new QLabel;
    m_boringSummary->setObjectName(QStringLiteral("boringSummary"));
    m_boringSummary->setWordWrap(true);
    form->addRow(tr("&Bar:"), m_boringBar);
    form->addRow(tr("Insert (ISO 1832):"), m_boringInsert);
    form->addRow(tr("Bar o&verhang:"), m_boringOverhang);
    form->addRow(tr("Edge offset f:"), m_boringEdgeOffset);
    form->addRow(tr("Pilot &hole Ø:"), m_pilotHole);
    form->addRow(QString(), m_boringSummary);
    setProjectField(*m_boringBar, QStringLiteral("boring_tool.holder"));
    setProjectField(*m_boringInsert, QStringLiteral("boring_tool.insert"));
    setProjectField(*m_boringOverhang, QStringLiteral("boring_tool.overhang_mm"));
    setProjectField(*m_boringEdgeOffset, QStringLiteral("boring_tool.edge_offset_mm"));
    setProjectField(*m_pilotHole, QStringLiteral("boring_tool.pilot_hole_diameter_mm"));
    connect(m_boringBar, &QComboBox::activated, this, &SetupPanel::applyBoringTool);
    connect(m_boringInsert, &QLineEdit::editingFinished, this, &SetupPanel::applyBoringTool);
    for (QDoubleSpinBox *box : {m_boringOverhang, m_boringEdgeOffset, m_pilotHole})
        connectSpinBoxSteps(box, m_document, this, [this] { applyBoringTool(); });
    return group;
}

QWidget *SetupPanel::createClampingGroup()
{
    auto *group = new QGroupBox(tr("Clamping"));
    auto *form = new QFormLayout(group);
    for (const ClampingMethod m : {ClampingMethod::Chuck, ClampingMethod::ChuckTailstock,
                                   ClampingMethod::BetweenCentres, ClampingMethod::Collet})
        m_clamping->addItem(displayName(m), static_cast<int>(m));
    m_clamping->setToolTip(tr("Boundary conditions of the workpiece beam: built in at the chuck face, supported "
                              "by the tailstock centre, or by two centres (MODEL.md §3); a collet is built in at "
                              "its face, its stiffness not published (taken as rigid, said in the verdicts)."));
    m_heldEnd = new QComboBox;
    m_heldEnd->setObjectName(QStringLiteral("heldEnd"));
    m_heldEnd->addItem(tr("left end (as drawn)"), static_cast<int>(PartEnd::Left));
    m_heldEnd->addItem(tr("right end (turned end for end)"), static_cast<int>(PartEnd::Right));
    m_heldEnd->setToolTip(tr("The end of the drawing the chuck holds (between centres: the driven end). Held at its "
                             "right end, the part is computed and programmed turned end for end."));
    form->addRow(tr("&Method:"), m_clamping);
    form->addRow(tr("Held &end:"), m_heldEnd);
    form->addRow(tr("Clamped &length:"), m_clampedLength);
    connect(m_heldEnd, &QComboBox::activated, this, &SetupPanel::applyClamping);
    connect(m_clamping, &QComboBox::activated, this, &SetupPanel::applyClamping);
    connectSpinBoxSteps(m_clampedLength, m_document, this, [this] { applyClamping(); });
    return group;
}

QWidget *SetupPanel::createPassesGroup()
{
    auto *group = new QGroupBox(tr("Cutting conditions"));
    m_passGrid = new QGridLayout(group);
    m_passGrid->addWidget(new QLabel(tr("Pass")), 0, 0);
    m_passGrid->addWidget(new QLabel(tr("vc [m/min]")), 0, 1 + kSpeed);
    m_passGrid->addWidget(new QLabel(tr("f [mm/rev]")), 0, 1 + kFeed);
    m_passGrid->addWidget(new QLabel(tr("ap [mm]")), 0, 1 + kDepth);
    return group;
}

void SetupPanel::fillChoices()
{
    const DataLibrary &library = DataLibrary::builtIn();
    for (const MaterialData &m : library.materials()) {
        m_material->addItem(QStringLiteral("%1 — %2").arg(m.id, m.name), m.id);
        m_material->setItemData(m_material->count() - 1, materialTip(library, m), Qt::ToolTipRole);
    }
    for (const MachineData &m : library.machines())
        m_machine->addItem(m.name, m.id);
    for (const HolderData &h : library.holders())
        m_holder->addItem(QStringLiteral("%1 (%2, κr %3°)").arg(h.code, h.kind).arg(h.enteringAngle_deg.value), h.code);
}

void SetupPanel::rebuildPassRows(int count)
{
    if (static_cast<int>(m_passBoxes.size()) != count)
        m_document.endRepeatedEdits(); // a new box may take a deleted one's address
    while (static_cast<int>(m_passBoxes.size()) > count) {
        for (QDoubleSpinBox *box : m_passBoxes.back())
            delete box;
        delete m_passLabels.back();
        m_passBoxes.pop_back();
        m_passLabels.pop_back();
    }
    while (static_cast<int>(m_passBoxes.size()) < count) {
        const int row = static_cast<int>(m_passBoxes.size()) + 1;
        std::vector<QDoubleSpinBox *> boxes{
            spinBox(1.0, 2000.0, 1, QString(), tr("Cutting speed vc: spindle speed n = 1000 vc / (π D).")),
            spinBox(0.001, 5.0, 3, QString(),
                    tr("Feed f: chip thickness h = f sin κr (Kienzle); Ra ≈ f² / (32 rε) (MODEL.md §2).")),
            spinBox(0.001, 50.0, 3, QString(), tr("Depth of cut ap: chip width b = ap / sin κr (Kienzle)."))};
        auto *label = new QLabel;
        m_passGrid->addWidget(label, row, 0);
        for (int c = 0; c < 3; ++c) {
            m_passGrid->addWidget(boxes[static_cast<std::size_t>(c)], row, 1 + c);
            QDoubleSpinBox *box = boxes[static_cast<std::size_t>(c)];
            setProjectField(*box, QStringLiteral("passes[%1].%2")
                                      .arg(row - 1)
                                      .arg(QLatin1String(kPassKeys[static_cast<std::size_t>(c)])));
            connectSpinBoxSteps(box, m_document, this,
                                [this, pass = static_cast<std::size_t>(row - 1), c] { applyPassValue(pass, c); });
        }
        m_passBoxes.push_back(std::move(boxes));
        m_passLabels.push_back(label);
    }
}

QDoubleSpinBox *SetupPanel::passBox(int index, int column) const
{
    return m_passBoxes.at(static_cast<std::size_t>(index)).at(static_cast<std::size_t>(column));
}

QString SetupPanel::message() const
{
    return m_message->text();
}

void SetupPanel::showDocumentValues()
{
    setEnabled(m_document.hasProject());
    if (m_document.hasProject())
        showValues();
}

void SetupPanel::showValues()
{
    m_updating = true;
    const Project p = operationProject();
    m_partName->setText(p.part.name);
    m_drawingNumber->setText(p.part.drawingNumber);
    m_revision->setText(p.part.revision);
    m_stockDiameter->setMillimetres(p.part.stockDiameter_mm);
    selectData(m_material, p.materialId);
    selectData(m_machine, p.machineId);
    selectData(m_holder, p.tool.holderCode);
    m_insert->setText(p.tool.insertCode);
    const InsertParseResult insert = parseInsertCode(p.tool.insertCode);
    m_insertDecoded->setText(insert.insert ? tr("corner %1°, nose radius %2 mm")
                                                 .arg(insert.insert->includedAngle_deg)
                                                 .arg(insert.insert->noseRadius_mm)
                                           : QString());
    m_overhang->setMillimetres(p.tool.overhang_mm.value_or(0.0));
    showBoringTool(p);
    m_clamping->setCurrentIndex(m_clamping->findData(static_cast<int>(p.clamping.method)));
    m_heldEnd->setCurrentIndex(m_heldEnd->findData(static_cast<int>(p.clamping.heldEnd)));
    m_clampedLength->setMillimetres(p.clamping.clampedLength_mm);
    m_clampedLength->setEnabled(p.clamping.method != ClampingMethod::BetweenCentres);
    if (p.clamping.clampedLength_mm > 0.0)
        m_lastChuckLength_mm = p.clamping.clampedLength_mm;
    rebuildPassRows(static_cast<int>(p.passes.size()));
    for (std::size_t i = 0; i < p.passes.size(); ++i) {
        const CuttingPass &pass = p.passes[i];
        m_passLabels[i]->setText(
            tr("%1 %2").arg(i + 1).arg(pass.kind == PassKind::Roughing ? tr("roughing") : tr("finishing")));
        m_passBoxes[i][kSpeed]->setValue(pass.cuttingSpeed_m_min);
        m_passBoxes[i][kFeed]->setValue(pass.feed_mm_rev);
        m_passBoxes[i][kDepth]->setValue(pass.depthOfCut_mm);
    }
    markFindings();
    showMachineStiffness();
    m_stiffness->showCharacterisation(p.characterisation);
    m_forceModel->showValues(p.cuttingModel, p.environment);
    m_updating = false;
}

void SetupPanel::markFindings()
{
    Diagnostics findings = m_document.problems();
    if (findings.empty()) {
        const Diagnostics plausibility = checkPlausibility(m_document.project(), DataLibrary::builtIn());
        findings.insert(findings.end(), plausibility.begin(), plausibility.end());
    }
    tolturn::markFindings(*this, findings);
}

void SetupPanel::showMachineStiffness()
{
    const MachineCharacterisation &c = m_document.project().characterisation;
    if (!c.spindleRadial && !c.tailstock && !c.centres) {
        m_machineStiffness->setText(
            tr("not measured: the chuck is the published range of chuck stiffness, results at both ends; "
               "tailstock and centres are rigid for want of data (see the banner above the verdicts). Measure "
               "k1, k2, k3 (Valiño et al. 2008 §III) below or fit them to a test bar."));
        return;
    }
    QStringList parts;
    if (c.spindleRadial)
        parts << tr("spindle k1 %1 N/mm, k2 %2 N·mm/rad, k3 %3 N·mm/rad")
                     .arg(c.spindleRadial->k1_N_per_mm)
                     .arg(c.spindleRadial->k2_Nmm_per_rad)
                     .arg(c.spindleRadial->k3_Nmm_per_rad);
    if (c.tailstock)
        parts << tr("tailstock %1 N/mm").arg(c.tailstock->radial_N_per_mm);
    if (c.centres)
        parts << tr("centres %1 N/mm").arg(c.centres->radial_N_per_mm);
    m_machineStiffness->setText(tr("measured (%1): %2").arg(c.source, parts.join(QStringLiteral("; "))));
}

void SetupPanel::applyMaterial()
{
    if (!m_updating)
        showOutcome(m_document.setMaterial(m_material->currentData().toString()));
}

void SetupPanel::applyMachine()
{
    if (!m_updating)
        showOutcome(m_document.setMachine(m_machine->currentData().toString()));
}

void SetupPanel::applyTool()
{
    if (m_updating)
        return;
    const InsertParseResult insert = parseInsertCode(m_insert->text());
    if (!insert.insert) {
        showOutcome(insert.diagnostics);
        return;
    }
    Tool tool = operationProject().tool;
    tool.insertCode = insert.insert->code;
    tool.holderCode = m_holder->currentData().toString();
    // millimetres() keeps a value the box cannot show (a negative one from a file to be repaired).
    const double overhang_mm = m_overhang->millimetres();
    tool.overhang_mm = overhang_mm != 0.0 ? std::optional<double>(overhang_mm) : std::nullopt;
    showOutcome(m_document.setOperationTool(m_operation, tool));
}

void SetupPanel::setOperation(int index)
{
    if (index == m_operation)
        return;
    m_document.endRepeatedEdits(); // the boxes now edit another set-up
    m_operation = index;
    showDocumentValues();
}

Project SetupPanel::operationProject() const
{
    const Project &project = m_document.project();
    return operationView(project, std::min(m_operation, operationCount(project) - 1));
}

void SetupPanel::showBoringTool(const Project &p)
{
    const bool bar = p.boringTool.has_value();
    selectData(m_boringBar, bar ? p.boringTool->holderCode : QString());
    m_boringInsert->setText(bar ? p.boringTool->insertCode : QString());
    m_boringOverhang->setMillimetres(bar ? p.boringTool->overhang_mm.value_or(0.0) : 0.0);
    m_boringEdgeOffset->setMillimetres(bar ? p.boringTool->edgeOffset_mm.value_or(0.0) : 0.0);
    m_pilotHole->setMillimetres(bar ? p.boringTool->pilotHoleDiameter_mm.value_or(0.0) : 0.0);
    for (QWidget *w :
         std::initializer_list<QWidget *>{m_boringInsert, m_boringOverhang, m_boringEdgeOffset, m_pilotHole})
        w->setEnabled(bar);
    const DataLibrary &library = DataLibrary::builtIn();
    const HolderData *h = bar ? library.holder(p.boringTool->holderCode) : nullptr;
    const BoringBarMaterialData *m = h != nullptr ? library.boringBarMaterial(*h) : nullptr;
    if (!bar) {
        m_boringSummary->setText(p.part.inner.empty()
                                     ? QString()
                                     : tr("The part has bores: without a boring bar they are computed as if cut by "
                                          "the turning tool, without the bending of a bar."));
    } else if (h == nullptr || m == nullptr || !h->barDiameter_mm) {
        m_boringSummary->setText(tr("\"%1\" is not a boring bar of the data library.").arg(p.boringTool->holderCode));
    } else {
        const QString overhang =
            p.boringTool->overhang_mm
                ? tr("L/D %1").arg(QString::number(*p.boringTool->overhang_mm / h->barDiameter_mm->value, 'f', 1))
                : tr("L/D from the reach of the bore");
        m_boringSummary->setText(
            tr("%1 bar, E = %2 GPa; %3; the maker allows up to %4 × D (%5).")
                .arg(m->id, formatNumber(m->youngsModulus_MPa.value / 1000.0), overhang,
                     formatNumber(m->maxOverhangRatio.value),
                     library.sourceText(m->maxOverhangRatio.source).section(QLatin1Char(','), 0, 0)));
    }
}

void SetupPanel::applyBoringTool()
{
    if (m_updating)
        return;
    const QString code = m_boringBar->currentData().toString();
    if (code.isEmpty()) {
        showOutcome(m_document.setOperationBoringTool(m_operation, std::nullopt));
        return;
    }
    const Project project = operationProject();
    const std::optional<Tool> &before = project.boringTool;
    Tool tool = before.value_or(Tool{});
    tool.holderCode = code;
    // A new bar starts with the turning tool's insert; the planner changes it where it differs.
    const QString typed = m_boringInsert->text().trimmed();
    tool.insertCode = typed.isEmpty() ? project.tool.insertCode : typed;
    const InsertParseResult insert = parseInsertCode(tool.insertCode);
    if (!insert.insert) {
        showOutcome(insert.diagnostics);
        return;
    }
    tool.insertCode = insert.insert->code;
    const double overhang_mm = m_boringOverhang->millimetres();
    tool.overhang_mm = overhang_mm != 0.0 ? std::optional<double>(overhang_mm) : std::nullopt;
    const double offset_mm = m_boringEdgeOffset->millimetres();
    tool.edgeOffset_mm = offset_mm != 0.0 ? std::optional<double>(offset_mm) : std::nullopt;
    const double pilot_mm = m_pilotHole->millimetres();
    tool.pilotHoleDiameter_mm = pilot_mm != 0.0 ? std::optional<double>(pilot_mm) : std::nullopt;
    if (before && tool == *before)
        return;
    showOutcome(m_document.setOperationBoringTool(m_operation, tool));
}

void SetupPanel::applyClamping()
{
    if (m_updating)
        return;
    const Project project = operationProject();
    const Clamping before = project.clamping;
    Clamping clamping;
    clamping.method = static_cast<ClampingMethod>(m_clamping->currentData().toInt());
    clamping.heldEnd = static_cast<PartEnd>(m_heldEnd->currentData().toInt());
    clamping.clampedLength_mm = m_clampedLength->millimetres();
    if (clamping.method == ClampingMethod::BetweenCentres) {
        clamping.clampedLength_mm = 0.0; // nothing is gripped between centres
    } else if (before.method == ClampingMethod::BetweenCentres) {
        // From centres to a chuck: grip where it gripped before, else the first cylinder.
        clamping.clampedLength_mm =
            m_lastChuckLength_mm > 0.0 ? m_lastChuckLength_mm : firstCylinderLength(project.part);
    }
    showOutcome(m_document.setOperationClamping(m_operation, clamping));
}

// Only the value the user changed: another pass's box may show a value the project holds
// outside the box's range (a file opened to be repaired), which must not be written back.
void SetupPanel::applyPassValue(std::size_t pass, int column)
{
    const Project project = operationProject();
    if (m_updating || pass >= project.passes.size())
        return;
    std::vector<CuttingPass> passes = project.passes;
    const double value = m_passBoxes[pass][static_cast<std::size_t>(column)]->value();
    CuttingPass &p = passes[pass];
    (column == kSpeed ? p.cuttingSpeed_m_min : column == kFeed ? p.feed_mm_rev : p.depthOfCut_mm) = value;
    showOutcome(m_document.setOperationPasses(m_operation, passes, tr("Change cutting conditions")));
}

void SetupPanel::applyStiffness()
{
    if (m_updating)
        return;
    // A measurement is entered field by field: wait for a whole one before editing the project.
    if (const QString missing = m_stiffness->missing(); !missing.isEmpty()) {
        m_message->setText(tr("Machine stiffness not applied yet: %1.").arg(missing));
        return;
    }
    showOutcome(m_document.setCharacterisation(m_stiffness->characterisation(m_document.project().characterisation)));
}

bool SetupPanel::fitStiffnessFromTestBar(const QString &csvPath)
{
    const TestBarReadResult bar = readTestBarMeasurements(csvPath);
    const Project &project = m_document.project();
    const double pivot = m_stiffness->pivotBox()->value() > 0.0
                             ? m_stiffness->pivotBox()->value()
                             : project.characterisation.pivotDistance_mm.value_or(0.0);
    if (!(pivot > 0.0)) {
        m_message->setText(tr("Enter Lc, the distance of the front spindle bearing behind the chuck face, before "
                              "fitting the springs."));
        return false;
    }
    StiffnessCalibration cal;
    if (bar.points)
        cal = calibrateSpindleChuck(project, DataLibrary::builtIn(), *bar.points, pivot);
    Diagnostics found = bar.diagnostics;
    found.insert(found.end(), cal.diagnostics.begin(), cal.diagnostics.end());
    QStringList errors;
    for (const Diagnostic &d : found)
        errors << d.toString();
    if (!cal.radial) {
        m_message->setText(tr("No springs fitted: %1").arg(errors.join(QLatin1Char('\n'))));
        return false;
    }
    const QString source =
        tr("Test bar fit (Valiño et al. 2008 §III) of %1, %2: %3 points, RMS residual %4 µm, forces of the "
           "project's model")
            .arg(QFileInfo(csvPath).fileName(), QDate::currentDate().toString(Qt::ISODate))
            .arg(cal.radial->points)
            .arg(QString::number(cal.radial->rmsResidual_um, 'f', 2));
    if (const QString stale = staleTangentialSprings(project.characterisation, cal); !stale.isEmpty())
        errors << stale;
    const MachineCharacterisation c = withFittedSprings(project.characterisation, cal, source);
    const Diagnostics refused = m_document.setCharacterisation(c);
    if (hasErrors(refused)) {
        showOutcome(refused);
        return false;
    }
    errors.prepend(tr("Springs fitted to %1 points (RMS %2 µm)%3; the bar's own bending was %4 % of the deviation "
                      "at its far end.")
                       .arg(cal.radial->points)
                       .arg(QString::number(cal.radial->rmsResidual_um, 'f', 2),
                            cal.tangential ? tr(", radial and tangential") : tr(", radial only"),
                            QString::number(100.0 * cal.barShareAtEnd, 'f', 0)));
    m_message->setText(errors.join(QLatin1Char('\n')));
    return true;
}

void SetupPanel::showOutcome(const Diagnostics &diagnostics)
{
    QStringList errors;
    for (const Diagnostic &d : diagnostics)
        if (d.severity == Severity::Error)
            errors << d.toString();
    m_message->setText(errors.join(QLatin1Char('\n')));
    if (!errors.isEmpty())
        showValues(); // put the refused value back
}

} // namespace tolturn
