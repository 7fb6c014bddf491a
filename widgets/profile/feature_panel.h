// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/part/profile_editing.h"

#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace tolturn {

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
    [[nodiscard]] QDoubleSpinBox *startZBox() const { return m_startZ; }

    [[nodiscard]] QDoubleSpinBox *startDiameterBox() const { return m_startD; }

    [[nodiscard]] QDoubleSpinBox *endZBox() const { return m_endZ; }

    [[nodiscard]] QDoubleSpinBox *endDiameterBox() const { return m_endD; }

    [[nodiscard]] QDoubleSpinBox *stepZBox() const { return m_stepZ; }

    [[nodiscard]] QDoubleSpinBox *stepDiameterBox() const { return m_stepD; }

    [[nodiscard]] QDoubleSpinBox *cornerSizeBox() const { return m_cornerSize; }

    [[nodiscard]] QDoubleSpinBox *boreDepthBox() const { return m_boreDepth; }

    [[nodiscard]] QDoubleSpinBox *boreDiameterBox() const { return m_boreD; }

    // Moves corner `vertex` of a contour (a drag in the drawing ends here).
    bool moveVertexTo(ContourSide side, int vertex, ProfilePoint to);
    void insertStep();
    void breakCorner(bool atEnd, bool round);
    void deleteFeature();
    // Bores the solid part from the selected end face.
    void addBore();
    // A cylinder becomes a cone, a cone of one diameter a cylinder.
    void toggleCone();

Q_SIGNALS:
    // The feature to select after an edit (a new one, or none after a delete).
    void featureChosen(const QString &featureId);

private:
    QWidget *createCornerRow();
    QWidget *createBoreGroup();
    void showFeature();
    void moveCorner(bool atEnd);
    // Applies an edit: the new part to the document, or the refusal to the message line.
    bool apply(const ProfileEdit &edit, const QString &description);

    ProjectDocument &m_document;
    QString m_featureId;
    bool m_updating = false;
    QLabel *m_title;
    QDoubleSpinBox *m_startZ;
    QDoubleSpinBox *m_startD;
    QDoubleSpinBox *m_endZ;
    QDoubleSpinBox *m_endD;
    QDoubleSpinBox *m_stepZ;
    QDoubleSpinBox *m_stepD;
    QPushButton *m_insertStep;
    QDoubleSpinBox *m_cornerSize;
    QPushButton *m_delete;
    QPushButton *m_cone;
    QDoubleSpinBox *m_boreDepth;
    QDoubleSpinBox *m_boreD;
    QPushButton *m_bore;
    QLabel *m_message;
};

} // namespace tolturn
