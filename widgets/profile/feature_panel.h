// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/part/profile_editing.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace tolturn {

class LengthSpinBox;

class ProjectDocument;

// The selected feature of the profile with exact numeric entry: its name, the z and diameter of
// its start and end (moving a corner keeps cylinders and faces what they are), and the edits of
// the profile editor: insert a step into a cylinder, chamfer or round its corners, delete it.
// Each is one undoable edit; a refused one leaves the part as it was and says why.
class FeaturePanel : public QWidget {
    Q_OBJECT
public:
    explicit FeaturePanel(ProjectDocument &document, QWidget *parent = nullptr);

    void setFeature(const QString &featureId);

    [[nodiscard]] QString feature() const { return m_featureId; }

    [[nodiscard]] QString message() const;

    // The entry fields and commands, for the window's menus and for tests.
    [[nodiscard]] LengthSpinBox *startZBox() const { return m_startZ; }

    [[nodiscard]] LengthSpinBox *startDiameterBox() const { return m_startD; }

    [[nodiscard]] LengthSpinBox *endZBox() const { return m_endZ; }

    [[nodiscard]] LengthSpinBox *endDiameterBox() const { return m_endD; }

    [[nodiscard]] LengthSpinBox *stepZBox() const { return m_stepZ; }

    [[nodiscard]] LengthSpinBox *stepDiameterBox() const { return m_stepD; }

    [[nodiscard]] LengthSpinBox *cornerSizeBox() const { return m_cornerSize; }

    [[nodiscard]] LengthSpinBox *boreDepthBox() const { return m_boreDepth; }

    [[nodiscard]] LengthSpinBox *boreDiameterBox() const { return m_boreD; }

    [[nodiscard]] LengthSpinBox *grooveZBox() const { return m_grooveZ; }

    [[nodiscard]] LengthSpinBox *grooveWidthBox() const { return m_grooveWidth; }

    [[nodiscard]] LengthSpinBox *grooveDepthBox() const { return m_grooveDepth; }

    [[nodiscard]] QComboBox *undercutFormBox() const { return m_undercutForm; }

    // Moves corner `vertex` of a contour (a drag in the drawing ends here).
    bool moveVertexTo(ContourSide side, int vertex, ProfilePoint to, AtBreak atBreak = AtBreak::StartOfSegment);
    void insertStep();
    void breakCorner(bool atEnd, bool round);
    void deleteFeature();
    // Bores the solid part from the selected end face (or, when the part is bored from the other
    // end only, adds a bore from this one with solid between).
    void addBore();
    // Cuts a square groove into the selected cylinder (groove z, width and depth fields).
    void insertGroove();
    // Cuts a DIN 509 undercut of the chosen form into the corner at the start or end of the
    // selected cylinder, where it meets a shoulder face.
    void insertUndercut(bool atEnd);
    // Changes the feature's kind: a cylinder becomes a cone, a cone of one diameter a cylinder;
    // a chamfer becomes an edge round of the same size, a round a chamfer.
    void changeKind();

Q_SIGNALS:
    // The feature to select after an edit (a new one, or none after a delete).
    void featureChosen(const QString &featureId);

private:
    QWidget *createCornerRow();
    QWidget *createBoreGroup();
    QWidget *createGrooveGroup();
    void showFeature();
    void moveCorner(bool atEnd);
    // Applies an edit: the new part to the document, or the refusal to the message line.
    bool apply(const ProfileEdit &edit, const QString &description);

    ProjectDocument &m_document;
    QString m_featureId;
    bool m_updating = false;
    QLabel *m_title;
    LengthSpinBox *m_startZ;
    LengthSpinBox *m_startD;
    LengthSpinBox *m_endZ;
    LengthSpinBox *m_endD;
    LengthSpinBox *m_stepZ;
    LengthSpinBox *m_stepD;
    QPushButton *m_insertStep;
    LengthSpinBox *m_cornerSize;
    QPushButton *m_delete;
    QPushButton *m_changeKind;
    LengthSpinBox *m_boreDepth;
    LengthSpinBox *m_boreD;
    QPushButton *m_bore;
    LengthSpinBox *m_grooveZ;
    LengthSpinBox *m_grooveWidth;
    LengthSpinBox *m_grooveDepth;
    QPushButton *m_insertGroove;
    QComboBox *m_undercutForm;
    QPushButton *m_undercutStart;
    QPushButton *m_undercutEnd;
    QLabel *m_message;
};

} // namespace tolturn
