// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/cad_files.h"
#include "app/gui/file_controller.h"

#include <QMainWindow>

#include <utility>
#include <vector>

class QDockWidget;
class QComboBox;
class QLabel;
class QMenu;
class QToolBar;

namespace tolturn {

struct Preferences;

class DeflectionPanel;
class DiagnosticsPanel;
class MeasurementsPanel;
class ProblemNavigator;
class Autosave;
class FeaturePanel;
class HelpBrowser;
class PlanningPanel;
class SetupPanel;
class TolerancePanel;
class ProfileView;
class ProjectAnalysis;
class ProjectDocument;
struct LoadedModel;
class RecentFiles;

// The desktop program's window: menus and status bar around the views of one document.
// File commands live in FileController; this class only wires them to actions and dialogs.
class MainWindow
    : public QMainWindow
    , public FilePrompts
    , public CadPrompts {
    Q_OBJECT
public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    [[nodiscard]] ProjectDocument *document() const { return m_document; }

    [[nodiscard]] FileController *fileController() const { return m_files; }

    [[nodiscard]] CadFileController *cadFiles() const { return m_cad; }

    [[nodiscard]] DiagnosticsPanel *importMessages() const { return m_importMessages; }

    [[nodiscard]] ProblemNavigator *problems() const { return m_problems; }

    [[nodiscard]] ProfileView *profileView() const { return m_profileView; }

    [[nodiscard]] DeflectionPanel *deflectionPanel() const { return m_deflection; }

    [[nodiscard]] TolerancePanel *tolerancePanel() const { return m_tolerances; }

    [[nodiscard]] PlanningPanel *planningPanel() const { return m_planning; }

    [[nodiscard]] SetupPanel *setupPanel() const { return m_setup; }

    [[nodiscard]] FeaturePanel *featurePanel() const { return m_feature; }

    [[nodiscard]] MeasurementsPanel *measurementsPanel() const { return m_measurements; }

    // FilePrompts
    [[nodiscard]] QString chooseFileToOpen(const QString &startFolder) override;
    [[nodiscard]] QString chooseFileToSave(const QString &suggestedPath) override;
    [[nodiscard]] QString chooseReportFile(const QString &suggestedPath) override;
    void showError(const QString &title, const QString &text) override;
    [[nodiscard]] SaveChoice askToSaveChanges(const QString &documentName) override;
    [[nodiscard]] bool askToRecover(const QString &documentName, const QDateTime &savedAt) override;
    [[nodiscard]] std::unique_ptr<TaskProgress> startProgress(const QString &label) override;
    // CadPrompts (showError and startProgress as above)
    [[nodiscard]] QString chooseCadFile(const QString &startFolder) override;
    [[nodiscard]] QString chooseStepExportFile(const QString &suggestedPath) override;
    [[nodiscard]] std::optional<CadImportChoice> confirmImport(const QString &fileName,
                                                               const CadImportResult &read) override;

    // Where the autosave copies live (per user).
    [[nodiscard]] static QString autosaveFolder();

    [[nodiscard]] Autosave *autosave() const { return m_autosave; }

    // Stores the preferences and applies what can change at once (the units).
    void applyPreferences(const Preferences &preferences);

protected:
    void closeEvent(QCloseEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    void createActions();
    void createFileMenu();
    void createEditMenu();
    void createToolsMenu();
    void createHelpMenu();
    // Tools > Check with Solid FE…: the set-up shown, checked against a solid model.
    void checkWithSolidFe();
    void showUserGuide();
    void createDocks();
    void createImportDock();
    void createProblemsDock();
    [[nodiscard]] QDockWidget *createMeasurementsDock();
    [[nodiscard]] QDockWidget *createMillingDock();
    // A project with problems: what can be shown without computing, and why the rest is not.
    void showProjectWithProblems();
    void showImportMessages(bool ok, const QString &heading, const Diagnostics &diagnostics);
    void rebuildRecentMenu();
    void updateTitle();
    // What an action needs to be enabled (Mayo's Command::getEnabledStatus): asked again by
    // updateActions() whenever the document, the selected feature or a planning run changes.
    enum class ActionNeeds {
        Project,           // an open project
        ComputableProject, // an open project without problems
        IdleProject,       // a computable project and no planning run going
        SelectedFeature,   // a feature of the drawing selected
    };
    void enableWhen(QAction *action, ActionNeeds needs);
    [[nodiscard]] bool met(ActionNeeds needs) const;
    void updateActions();
    void showProject();
    // The set-up shown, of a project of several operations (docs/operations.md).
    void updateOperationChoice();
    void editOperations();
    void updateSummary();
    void editPreferences();

    ProjectDocument *m_document;
    ProjectAnalysis *m_analysis; // the set-up's predictions, which the results' panels show
    RecentFiles *m_recentFiles;
    FileController *m_files;
    CadFileController *m_cad;
    DiagnosticsPanel *m_importMessages;
    ProfileView *m_profileView;
    DeflectionPanel *m_deflection;
    TolerancePanel *m_tolerances;
    PlanningPanel *m_planning;
    SetupPanel *m_setup;
    FeaturePanel *m_feature;
    MeasurementsPanel *m_measurements;
    Autosave *m_autosave;
    ProblemNavigator *m_problems;
    QMenu *m_recentMenu = nullptr;
    QToolBar *m_toolBar = nullptr;
    QComboBox *m_operationBox = nullptr;
    QAction *m_operationAction = nullptr; // the box in the toolbar, shown for several operations
    int m_operation = 0;
    QLabel *m_summary;
    HelpBrowser *m_help = nullptr;
    QAction *m_exportReportAction = nullptr;
    QDockWidget *m_importDock = nullptr;
    QDockWidget *m_problemsDock = nullptr;
    std::vector<std::pair<QAction *, ActionNeeds>> m_actionNeeds;
    bool m_layoutRestored = false;  // the docks as the user left them (showEvent leaves them so)
    bool m_firstLayoutDone = false; // showEvent has sized the docks to the window once
};

} // namespace tolturn
