// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"

#include <QWidget>

#include <cstddef>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QLineEdit;

namespace tolturn {

class LengthSpinBox;

struct Project;
class ProjectDocument;
class ForceModelEditor;
class StiffnessEditor;

// The set-up of the open project: material, machine (and what is known of its stiffness),
// insert (ISO 1832 code) and holder, clamping (method, clamped length, tool overhang) and the
// cutting conditions of each pass. Every change is one undoable edit of the document; a value
// the document refuses is put back and the reason shown, naming the field and the value.
class SetupPanel : public QWidget {
    Q_OBJECT
public:
    explicit SetupPanel(ProjectDocument &document, QWidget *parent = nullptr);

    // Shows the document's values (after loads, edits, undo and redo).
    void showDocumentValues();

    [[nodiscard]] QComboBox *materialBox() const { return m_material; }

    [[nodiscard]] QComboBox *machineBox() const { return m_machine; }

    [[nodiscard]] QLineEdit *insertEdit() const { return m_insert; }

    [[nodiscard]] QComboBox *holderBox() const { return m_holder; }

    [[nodiscard]] QComboBox *clampingBox() const { return m_clamping; }

    [[nodiscard]] LengthSpinBox *clampedLengthBox() const { return m_clampedLength; }

    [[nodiscard]] LengthSpinBox *overhangBox() const { return m_overhang; }

    // The operation (set-up) whose clamping, tools and passes the dock shows and edits.
    void setOperation(int index);

    [[nodiscard]] QComboBox *heldEndBox() const { return m_heldEnd; }

    [[nodiscard]] QComboBox *boringBarBox() const { return m_boringBar; }

    [[nodiscard]] QLineEdit *boringInsertEdit() const { return m_boringInsert; }

    [[nodiscard]] LengthSpinBox *boringOverhangBox() const { return m_boringOverhang; }

    [[nodiscard]] LengthSpinBox *boringEdgeOffsetBox() const { return m_boringEdgeOffset; }

    [[nodiscard]] LengthSpinBox *pilotHoleBox() const { return m_pilotHole; }

    [[nodiscard]] QLabel *boringBarSummary() const { return m_boringSummary; }

    [[nodiscard]] StiffnessEditor *stiffnessEditor() const { return m_stiffness; }

    [[nodiscard]] ForceModelEditor *forceModelEditor() const { return m_forceModel; }

    // Cutting speed, feed and depth of cut of pass `index`.
    [[nodiscard]] QDoubleSpinBox *passBox(int index, int column) const;

    // Fits the spindle–chuck springs to the measured test bar in `csvPath`, the open project being
    // that bar as it was cut, with the Lc of the stiffness editor (or the project's); the springs
    // are stored as one undoable edit and the result shown. False with the reason shown otherwise.
    bool fitStiffnessFromTestBar(const QString &csvPath);

    // The reason the last change was refused; empty after an accepted one.
    [[nodiscard]] QString message() const;

private:
    // Marks the boxes of values with problems (red) or outside the insert's published ranges or
    // the machine's limits (amber, checkPlausibility), with the reason in the tooltip.
    void markFindings();
    QWidget *createPartGroup();
    QWidget *createDrawingGroup();
    void applyDrawing();
    QWidget *createToolGroup();
    QWidget *createClampingGroup();
    QWidget *createPassesGroup();
    void fillChoices();
    void showValues();
    void showMachineStiffness();
    void rebuildPassRows(int count);

    void applyMaterial();
    void applyMachine();
    void applyTool();
    void applyBoringTool();
    [[nodiscard]] Project operationProject() const;
    void showBoringTool(const Project &p);
    QWidget *createBoringGroup();
    void applyClamping();
    void applyPassValue(std::size_t pass, int column);
    void applyStiffness();
    // Shows the outcome of an edit: the errors of a refused one (and the document's values again).
    void showOutcome(const Diagnostics &diagnostics);

    ProjectDocument &m_document;
    bool m_updating = false;
    double m_lastChuckLength_mm = 0.0;
    QComboBox *m_material;
    QComboBox *m_machine;
    QLabel *m_machineStiffness;
    StiffnessEditor *m_stiffness;
    QLineEdit *m_partName = nullptr;
    QLineEdit *m_drawingNumber = nullptr;
    QLineEdit *m_revision = nullptr;
    LengthSpinBox *m_stockDiameter = nullptr;
    QLineEdit *m_insert;
    QLabel *m_insertDecoded;
    QComboBox *m_holder;
    QComboBox *m_clamping;
    LengthSpinBox *m_clampedLength;
    LengthSpinBox *m_overhang;
    int m_operation = 0;
    QComboBox *m_heldEnd = nullptr;
    QComboBox *m_boringBar = nullptr;
    QLineEdit *m_boringInsert = nullptr;
    LengthSpinBox *m_boringOverhang = nullptr;
    LengthSpinBox *m_boringEdgeOffset = nullptr;
    LengthSpinBox *m_pilotHole = nullptr;
    QLabel *m_boringSummary = nullptr;
    QGridLayout *m_passGrid = nullptr;
    std::vector<std::vector<QDoubleSpinBox *>> m_passBoxes;
    std::vector<QLabel *> m_passLabels;
    ForceModelEditor *m_forceModel;
    QLabel *m_message;
};

} // namespace tolturn
