// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>

class QDockWidget;
class QWidget;

namespace tolturn {

class DiagnosticsPanel;
class FeaturePanel;
class ProfileView;
class ProjectDocument;
class TolerancePanel;

// The Problems list of a project opened with wrong values (ProjectDocument::problems()), and the
// way from a problem to the editor of its value: the feature or tolerance it names is selected,
// the editor's dock raised and the editor focused with its text selected.
class ProblemNavigator : public QObject {
    Q_OBJECT
public:
    struct Views {
        QWidget *window;
        ProfileView *profile;
        FeaturePanel *feature;
        TolerancePanel *tolerances;
    };

    ProblemNavigator(ProjectDocument &document, const Views &views, QObject *parent = nullptr);

    [[nodiscard]] DiagnosticsPanel *panel() const { return m_panel; }

    // The dock of the list, once the window has made one.
    void setDock(QDockWidget *dock) { m_dock = dock; }

    // Shows the document's problems in the list (after every change).
    void update();
    // After a file with problems was opened: the list in front and the first problem's value
    // focused.
    void showFirst();
    // Takes the user to the editor of `field`; false when no editor holds it.
    bool focusField(const QString &field);

private:
    // Selects the feature or tolerance a field lies in, so that its editor shows it.
    void selectOwner(const QString &field);

    ProjectDocument &m_document;
    Views m_views;
    DiagnosticsPanel *m_panel;
    QDockWidget *m_dock = nullptr;
};

} // namespace tolturn
