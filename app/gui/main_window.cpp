// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/main_window.h"

#include "app/gui/autosave.h"
#include "app/gui/import_dialog.h"
#include "app/gui/problem_navigator.h"
#include "app/gui/recent_files.h"
#include "app/gui/settings_dialog.h"
#include "core/project/keywords.h"
#include "core/project/operations.h"
#include "core/tolerance/evaluation.h"
#include "core/tolerance/range_verdicts.h"
#include "resources/bundled.h"
#include "widgets/common/diagnostics_panel.h"
#include "widgets/common/project_fields.h"
#include "widgets/dialogs/about_dialog.h"
#include "widgets/dialogs/help_browser.h"
#include "widgets/document/project_analysis.h"
#include "widgets/document/project_document.h"
#include "widgets/fe/solid_check_dialog.h"
#include "widgets/measurements/measurements_panel.h"
#include "widgets/milling/milling_panel.h"
#include "widgets/planning/end_milling_example_dialog.h"
#include "widgets/planning/planning_panel.h"
#include "widgets/profile/feature_panel.h"
#include "widgets/profile/profile_scene.h"
#include "widgets/profile/profile_view.h"
#include "widgets/results/deflection_panel.h"
#include "widgets/setup/operations_dialog.h"
#include "widgets/setup/setup_panel.h"
#include "widgets/tolerances/tolerance_panel.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QShowEvent>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

namespace tolturn {

namespace {

// The dock layout's version for saveState/restoreState: raised when the first layout changes, so
// that a layout saved by an older version is not restored over it (1: the verdict table's 42 %).
constexpr int kLayoutVersion = 1;

// TolTurn's own SVG icons (resources/icons), sharp at any screen scale, the same on every desktop.
QIcon actionIcon(const char *name)
{
    return QIcon(QStringLiteral(":/icons/%1.svg").arg(QLatin1String(name)));
}

} // namespace

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_document(new ProjectDocument(this))
    , m_analysis(new ProjectAnalysis(*m_document, this))
    , m_recentFiles(new RecentFiles(this))
    , m_files(new FileController(*m_document, *m_recentFiles, *this, this))
    , m_cad(new CadFileController(*m_document, *m_files, *this, this))
    , m_importMessages(new DiagnosticsPanel(this))
    , m_profileView(new ProfileView(this))
    , m_deflection(new DeflectionPanel(this))
    , m_tolerances(new TolerancePanel(*m_document, this))
    , m_planning(new PlanningPanel(*m_document, this))
    , m_setup(new SetupPanel(*m_document, this))
    , m_feature(new FeaturePanel(*m_document, this))
    , m_measurements(new MeasurementsPanel(this))
    , m_autosave(new Autosave(*m_document, autosaveFolder(), this))
    , m_problems(new ProblemNavigator(*m_document, {this, m_profileView, m_feature, m_tolerances}, this))
    , m_summary(new QLabel(this))
{
    setObjectName(QStringLiteral("MainWindow"));
    setWindowIcon(QIcon(applicationIconPath()));
    m_profileView->setObjectName(QStringLiteral("profileView"));
    setCentralWidget(m_profileView);
    // The drawing keeps room for a legible part when the window is small (a laptop): the docks give
    // way first.
    m_profileView->setMinimumSize(520, 240);
    statusBar()->addPermanentWidget(m_summary);
    statusBar()->showMessage(tr("Open a project (File > Open) or an example part (File > Open Example)."));

    createActions();
    const Preferences preferences = loadPreferences();
    m_planning->setCurrency(preferences.currency);
    m_measurements->setDefaultMeasuredBy(preferences.planner);
    m_measurements->setStoreLocation(measurementStoreLocation(preferences));
    connect(m_measurements, &MeasurementsPanel::learnedModelChanged, this, &MainWindow::showProject);
    m_files->setLearnedModelSource([this] { return m_measurements->activeModel(); });
    connect(m_files, &FileController::statusMessage, this,
            [this](const QString &message) { statusBar()->showMessage(message, 5000); });
    connect(m_cad, &CadFileController::statusMessage, this,
            [this](const QString &message) { statusBar()->showMessage(message, 8000); });
    connect(m_cad, &CadFileController::importFinished, this, &MainWindow::showImportMessages);
    connect(m_files, &FileController::openedWithProblems, m_problems, &ProblemNavigator::showFirst);
    connect(m_document, &ProjectDocument::projectChanged, this, &MainWindow::showProject);
    connect(m_analysis, &ProjectAnalysis::predicted, m_tolerances, &TolerancePanel::showPrediction);
    connect(m_analysis, &ProjectAnalysis::notPredicted, m_tolerances, &TolerancePanel::showNotPredicted);
    connect(m_analysis, &ProjectAnalysis::predicted, m_deflection, &DeflectionPanel::showPrediction);
    connect(m_analysis, &ProjectAnalysis::notPredicted, m_deflection, &DeflectionPanel::clear);
    connect(m_document, &ProjectDocument::filePathChanged, this, &MainWindow::updateTitle);
    connect(m_document, &ProjectDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_recentFiles, &RecentFiles::changed, this, &MainWindow::rebuildRecentMenu);
    connect(m_profileView, &ProfileView::featureSelected, m_tolerances, &TolerancePanel::setSelectedFeature);
    connect(m_profileView, &ProfileView::featureSelected, m_feature, &FeaturePanel::setFeature);
    connect(m_feature, &FeaturePanel::featureChosen, m_profileView, &ProfileView::selectFeature);
    connect(m_profileView, &ProfileView::vertexDragged, this,
            [this](ContourSide side, int vertex, ProfilePoint to, bool atSegmentEnd) {
                // The drawing shows the set-up as held: turned end for end, its corners count from the
                // other end, z runs from the right end of the drawing and a feature's end is its start.
                const Project &project = m_document->project();
                if (operationClamping(project, std::min(m_operation, operationCount(project) - 1)).heldEnd ==
                    PartEnd::Right) {
                    const Contour &contour = project.part.contour(side);
                    vertex = static_cast<int>(contour.segments.size()) - vertex;
                    to.z_mm = project.part.length_mm() - to.z_mm;
                    atSegmentEnd = !atSegmentEnd;
                }
                if (!m_feature->moveVertexTo(side, vertex, to,
                                             atSegmentEnd ? AtBreak::EndOfSegment : AtBreak::StartOfSegment))
                    statusBar()->showMessage(m_feature->message(), 8000);
            });
    connect(m_tolerances, &TolerancePanel::featureActivated, m_profileView, &ProfileView::selectFeature);
    connect(&DisplaySettings::instance(), &DisplaySettings::unitsChanged, this, &MainWindow::updateSummary);
    rebuildRecentMenu();
    updateTitle();
    resize(1600, 950);
    // Docks and window as the user left them.
    const QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    m_layoutRestored = restoreState(settings.value(QStringLiteral("window/state")).toByteArray(), kLayoutVersion);
}

// The first layout, at the window's real width: the verdict table, with its range and stiffness
// columns, takes as much of it as the drawing (sizes given before the window is shown are scaled
// down by the layout).
void MainWindow::showEvent(QShowEvent *event)
{
    QMainWindow::showEvent(event);
    if (m_layoutRestored || m_firstLayoutDone)
        return;
    m_firstLayoutDone = true;
    auto *setup = findChild<QDockWidget *>(QStringLiteral("setupDock"));
    auto *tolerances = findChild<QDockWidget *>(QStringLiteral("tolerancesDock"));
    if (setup == nullptr || tolerances == nullptr)
        return;
    resizeDocks({setup, tolerances}, {width() * 22 / 100, width() * 42 / 100}, Qt::Horizontal);
}

MainWindow::~MainWindow() = default;

void MainWindow::createActions()
{
    m_toolBar = addToolBar(tr("Main Toolbar"));
    m_toolBar->setObjectName(QStringLiteral("mainToolBar"));
    createFileMenu();
    createEditMenu();
    createDocks();
    createToolsMenu();
    createHelpMenu();
}

void MainWindow::createEditMenu()
{
    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    QAction *undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction *redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    undo->setIcon(actionIcon("edit-undo"));
    redo->setIcon(actionIcon("edit-redo"));
    edit->addAction(undo);
    edit->addAction(redo);
    m_toolBar->addActions({undo, redo});
    m_toolBar->addSeparator();
    edit->addSeparator();
    // The selected feature of the drawing (the Feature dock's Delete, from the keyboard).
    QAction *deleteFeature = edit->addAction(tr("&Delete Feature"));
    deleteFeature->setObjectName(QStringLiteral("deleteFeatureAction"));
    deleteFeature->setShortcut(QKeySequence::Delete);
    enableWhen(deleteFeature, ActionNeeds::SelectedFeature);
    connect(deleteFeature, &QAction::triggered, m_feature, &FeaturePanel::deleteFeature);
    connect(m_profileView, &ProfileView::featureSelected, this, &MainWindow::updateActions);
    edit->addSeparator();
    QAction *operations = edit->addAction(tr("&Operations…"));
    operations->setObjectName(QStringLiteral("operationsAction"));
    operations->setToolTip(tr("The set-ups the part is turned in and the features each cuts"));
    enableWhen(operations, ActionNeeds::Project);
    connect(operations, &QAction::triggered, this, &MainWindow::editOperations);
    edit->addSeparator();
    QAction *preferences = edit->addAction(actionIcon("preferences"), tr("Pre&ferences…"));
    preferences->setObjectName(QStringLiteral("preferencesAction"));
    preferences->setShortcut(QKeySequence::Preferences);
    preferences->setMenuRole(QAction::PreferencesRole);
    connect(preferences, &QAction::triggered, this, &MainWindow::editPreferences);
}

void MainWindow::editPreferences()
{
    SettingsDialog dialog(loadPreferences(), this);
    if (dialog.exec() == QDialog::Accepted)
        applyPreferences(dialog.preferences());
}

void MainWindow::applyPreferences(const Preferences &preferences)
{
    const Preferences before = loadPreferences();
    savePreferences(preferences);
    DisplaySettings::instance().setUnits(DisplayUnits(preferences.lengthUnit));
    m_planning->setCurrency(preferences.currency);
    m_measurements->setDefaultMeasuredBy(preferences.planner);
    if (measurementStoreLocation(preferences).describe() != m_measurements->storeLocation().describe())
        m_measurements->setStoreLocation(measurementStoreLocation(preferences));
    if (preferences.language != before.language)
        statusBar()->showMessage(tr("The new language is used when TolTurn is next started."), 8000);
}

void MainWindow::createDocks()
{
    auto *setup = new QDockWidget(tr("Set-up"), this);
    setup->setObjectName(QStringLiteral("setupDock"));
    setup->setWidget(m_setup);
    addDockWidget(Qt::LeftDockWidgetArea, setup);
    auto *feature = new QDockWidget(tr("Feature"), this);
    feature->setObjectName(QStringLiteral("featureDock"));
    auto *featureScroll = new QScrollArea;
    featureScroll->setWidget(m_feature);
    featureScroll->setWidgetResizable(true);
    featureScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    feature->setWidget(featureScroll);
    addDockWidget(Qt::LeftDockWidgetArea, feature);
    tabifyDockWidget(setup, feature);
    setup->raise();
    auto *tolerances = new QDockWidget(tr("Tolerances"), this);
    tolerances->setObjectName(QStringLiteral("tolerancesDock"));
    tolerances->setWidget(m_tolerances);
    addDockWidget(Qt::RightDockWidgetArea, tolerances);
    auto *dock = new QDockWidget(tr("Deflection"), this);
    dock->setObjectName(QStringLiteral("deflectionDock"));
    dock->setWidget(m_deflection);
    dock->setAllowedAreas(Qt::BottomDockWidgetArea | Qt::RightDockWidgetArea);
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    auto *planning = new QDockWidget(tr("Planning"), this);
    planning->setObjectName(QStringLiteral("planningDock"));
    planning->setWidget(m_planning);
    addDockWidget(Qt::BottomDockWidgetArea, planning);
    tabifyDockWidget(dock, planning);
    dock->raise();
    createImportDock();
    tabifyDockWidget(planning, m_importDock);
    createProblemsDock();
    tabifyDockWidget(m_importDock, m_problemsDock);
    QDockWidget *measurements = createMeasurementsDock();
    tabifyDockWidget(m_problemsDock, measurements);
    QDockWidget *milling = createMillingDock();
    tabifyDockWidget(measurements, milling);
    dock->raise();
    resizeDocks({setup, tolerances}, {440, 660}, Qt::Horizontal);
    resizeDocks({dock}, {380}, Qt::Vertical);
    QMenu *view = menuBar()->addMenu(tr("&View"));
    QAction *fit = view->addAction(actionIcon("zoom-fit"), tr("&Fit Part"));
    fit->setObjectName(QStringLiteral("fitPartAction"));
    fit->setShortcut(Qt::CTRL | Qt::Key_0);
    fit->setToolTip(tr("Show the whole part in the drawing (Ctrl+0, or double-click the drawing)"));
    enableWhen(fit, ActionNeeds::Project);
    connect(fit, &QAction::triggered, m_profileView, &ProfileView::fitPart);
    QAction *optimise = view->addAction(actionIcon("optimise"), tr("&Optimise Cutting Conditions"));
    optimise->setObjectName(QStringLiteral("optimiseAction"));
    optimise->setShortcut(Qt::Key_F5);
    optimise->setToolTip(tr("Find the cutting conditions that hold every tolerance at least time or cost (F5)"));
    enableWhen(optimise, ActionNeeds::IdleProject);
    connect(optimise, &QAction::triggered, this, [this, planning] {
        planning->raise();
        m_planning->optimise();
    });
    connect(m_planning, &PlanningPanel::started, this, &MainWindow::updateActions);
    connect(m_planning, &PlanningPanel::finished, this, &MainWindow::updateActions);
    QAction *planningData = view->addAction(tr("Planning &Data…"));
    planningData->setObjectName(QStringLiteral("planningDataAction"));
    planningData->setToolTip(
        tr("Rates, tool life, the insert's cutting ranges and the part's limits for the optimiser"));
    enableWhen(planningData, ActionNeeds::Project);
    connect(planningData, &QAction::triggered, this, [this, planning] {
        planning->raise();
        m_planning->editPlanningData();
    });
    m_toolBar->addAction(fit);
    m_toolBar->addSeparator();
    m_toolBar->addActions({optimise, m_exportReportAction});
    m_operationBox = new QComboBox(this);
    m_operationBox->setObjectName(QStringLiteral("operationBox"));
    m_operationBox->setToolTip(tr("The set-up shown: its part as held, its deflection, verdicts, plan and program"));
    m_operationAction = m_toolBar->addWidget(m_operationBox);
    m_operationAction->setVisible(false);
    connect(m_operationBox, &QComboBox::activated, this, [this](int index) {
        m_operation = index;
        m_planning->setOperation(index);
        m_setup->setOperation(index);
        m_files->setOperation(index);
        showProject();
    });
    view->addSeparator();
    view->addAction(m_toolBar->toggleViewAction());
    view->addAction(setup->toggleViewAction());
    view->addAction(feature->toggleViewAction());
    view->addAction(dock->toggleViewAction());
    view->addAction(tolerances->toggleViewAction());
    view->addAction(planning->toggleViewAction());
    view->addAction(m_importDock->toggleViewAction());
    view->addAction(m_problemsDock->toggleViewAction());
    view->addAction(measurements->toggleViewAction());
    view->addAction(milling->toggleViewAction());
}

QDockWidget *MainWindow::createMeasurementsDock()
{
    auto *dock = new QDockWidget(tr("Measurements"), this);
    dock->setObjectName(QStringLiteral("measurementsDock"));
    // In a scroll area, so that its list, buttons and plot never make the bottom docks (and the
    // window) taller than a laptop screen allows.
    auto *scroll = new QScrollArea;
    scroll->setWidget(m_measurements);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    dock->setWidget(scroll);
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    return dock;
}

QDockWidget *MainWindow::createMillingDock()
{
    auto *dock = new QDockWidget(tr("Milling"), this);
    dock->setObjectName(QStringLiteral("millingDock"));
    dock->setWidget(new MillingPanel(m_document));
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    return dock;
}

void MainWindow::createFileMenu()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QAction *newProject = file->addAction(actionIcon("document-new"), tr("&New"));
    newProject->setShortcut(QKeySequence::New);
    connect(newProject, &QAction::triggered, m_files, [this] { m_files->newProject(); });
    QAction *open = file->addAction(actionIcon("document-open"), tr("&Open…"));
    open->setShortcut(QKeySequence::Open);
    connect(open, &QAction::triggered, m_files, [this] { m_files->open(); });
    QAction *importCad = file->addAction(actionIcon("import-step"), tr("&Import STEP/IGES…"));
    importCad->setObjectName(QStringLiteral("importCadAction"));
    importCad->setShortcut(Qt::CTRL | Qt::Key_I);
    importCad->setToolTip(tr("Read a turned part from a STEP or IGES solid (Ctrl+I)"));
    connect(importCad, &QAction::triggered, m_cad, &CadFileController::importCad);

    m_recentMenu = file->addMenu(tr("Open &Recent"));
    QMenu *examples = file->addMenu(tr("Open &Example"));
    for (const QString &path : bundledExamplePaths()) {
        QAction *example = examples->addAction(QFileInfo(path).completeBaseName());
        connect(example, &QAction::triggered, m_files, [this, path] { m_files->openExample(path); });
    }
    file->addSeparator();

    QAction *save = file->addAction(actionIcon("document-save"), tr("&Save"));
    save->setShortcut(QKeySequence::Save);
    save->setObjectName(QStringLiteral("saveAction"));
    enableWhen(save, ActionNeeds::Project);
    connect(save, &QAction::triggered, m_files, [this] { m_files->save(); });
    QAction *saveAs = file->addAction(tr("Save &As…"));
    saveAs->setShortcut(QKeySequence::SaveAs);
    saveAs->setObjectName(QStringLiteral("saveAsAction"));
    enableWhen(saveAs, ActionNeeds::Project);
    connect(saveAs, &QAction::triggered, m_files, [this] { m_files->saveAs(); });
    m_exportReportAction = file->addAction(actionIcon("export-report"), tr("Export &Report…"));
    m_exportReportAction->setShortcut(Qt::CTRL | Qt::Key_P);
    m_exportReportAction->setObjectName(QStringLiteral("exportReportAction"));
    enableWhen(m_exportReportAction, ActionNeeds::ComputableProject);
    connect(m_exportReportAction, &QAction::triggered, m_files, [this] { m_files->exportReport(); });
    QAction *exportStep = file->addAction(tr("Export S&TEP…"));
    exportStep->setObjectName(QStringLiteral("exportStepAction"));
    exportStep->setToolTip(tr("Write the part as a solid revolved about its axis (STEP, mm)"));
    enableWhen(exportStep, ActionNeeds::ComputableProject);
    connect(exportStep, &QAction::triggered, m_cad, [this] { m_cad->exportStep(); });
    m_toolBar->addActions({newProject, open, importCad, save});
    m_toolBar->addSeparator();
    QAction *closeAction = file->addAction(tr("&Close"));
    closeAction->setShortcut(QKeySequence::Close);
    connect(closeAction, &QAction::triggered, m_files, [this] { m_files->close(); });
    file->addSeparator();

    QAction *quit = file->addAction(tr("&Quit"));
    quit->setShortcut(QKeySequence::Quit);
    quit->setMenuRole(QAction::QuitRole);
    connect(quit, &QAction::triggered, this, &QWidget::close);
}

void MainWindow::createToolsMenu()
{
    QMenu *tools = menuBar()->addMenu(tr("&Tools"));
    QAction *solidCheck = tools->addAction(tr("Check with &Solid FE…"));
    solidCheck->setObjectName(QStringLiteral("solidCheckAction"));
    solidCheck->setToolTip(
        tr("Check the beam's deflection of the part against a solid model meshed with gmsh and solved with CalculiX"));
    enableWhen(solidCheck, ActionNeeds::ComputableProject);
    connect(solidCheck, &QAction::triggered, this, &MainWindow::checkWithSolidFe);
    tools->addSeparator();
    QAction *milling = tools->addAction(tr("Čuš && Župerl &End-Milling Example…"));
    milling->setObjectName(QStringLiteral("endMillingExampleAction"));
    milling->setToolTip(tr("The constant-force control paper's own end-milling system rebuilt, beside its results"));
    connect(milling, &QAction::triggered, this, [this] {
        EndMillingExampleDialog dialog(this);
        dialog.exec();
    });
}

void MainWindow::checkWithSolidFe()
{
    if (!m_document->hasProject() || m_document->hasProblems())
        return;
    SolidCheckDialog dialog(m_document->project(), m_operation, this);
    dialog.exec();
}

// The guide's page for where the focus is: the dock that holds it, or the drawing.
void MainWindow::showUserGuide()
{
    QString place;
    for (QWidget *w = QApplication::focusWidget(); w != nullptr; w = w->parentWidget()) {
        if (qobject_cast<QDockWidget *>(w) != nullptr || w == m_profileView) {
            place = w->objectName();
            break;
        }
    }
    if (m_help == nullptr)
        m_help = new HelpBrowser(this);
    m_help->showPage(HelpBrowser::pageForDock(place));
    m_help->show();
    m_help->raise();
}

void MainWindow::createHelpMenu()
{
    QMenu *help = menuBar()->addMenu(tr("&Help"));
    QAction *guide = help->addAction(tr("&User Guide"));
    guide->setObjectName(QStringLiteral("userGuideAction"));
    guide->setShortcut(QKeySequence::HelpContents);
    guide->setToolTip(tr("The user guide, at the page of the dock you are in (F1)"));
    connect(guide, &QAction::triggered, this, [this] { showUserGuide(); });
    help->addSeparator();
    QAction *about = help->addAction(tr("&About TolTurn"));
    about->setMenuRole(QAction::AboutRole);
    connect(about, &QAction::triggered, this, [this] {
        AboutDialog dialog(this);
        dialog.exec();
    });
    QAction *aboutQt = help->addAction(tr("About &Qt"));
    aboutQt->setMenuRole(QAction::AboutQtRole);
    connect(aboutQt, &QAction::triggered, qApp, &QApplication::aboutQt);
}

void MainWindow::rebuildRecentMenu()
{
    m_recentMenu->clear();
    const QStringList files = m_recentFiles->files();
    for (int i = 0; i < files.size(); ++i) {
        const QString &path = files.at(i);
        const QString label = QStringLiteral("&%1 %2").arg(i + 1).arg(QDir::toNativeSeparators(path));
        QAction *action = m_recentMenu->addAction(label);
        connect(action, &QAction::triggered, m_files, [this, path] { m_files->openFile(path); });
    }
    if (!files.isEmpty()) {
        m_recentMenu->addSeparator();
        connect(m_recentMenu->addAction(tr("&Clear List")), &QAction::triggered, m_recentFiles, &RecentFiles::clear);
    }
    m_recentMenu->setEnabled(!files.isEmpty());
}

void MainWindow::updateTitle()
{
    updateActions();
    setWindowModified(m_document->isModified());
    setWindowTitle(m_document->hasProject() ? tr("%1[*] — TolTurn").arg(m_document->displayName())
                                            : QStringLiteral("TolTurn"));
}

// Set when the window is built (updateTitle() at the end of the constructor) and on every change.
void MainWindow::enableWhen(QAction *action, ActionNeeds needs)
{
    m_actionNeeds.emplace_back(action, needs);
}

bool MainWindow::met(ActionNeeds needs) const
{
    const bool computable = m_document->hasProject() && !m_document->hasProblems();
    switch (needs) {
    case ActionNeeds::Project:
        return m_document->hasProject();
    case ActionNeeds::ComputableProject:
        return computable;
    case ActionNeeds::IdleProject:
        return computable && !m_planning->isRunning();
    case ActionNeeds::SelectedFeature:
        return m_document->hasProject() && !m_profileView->selectedFeature().isEmpty();
    }
    return false;
}

void MainWindow::updateActions()
{
    for (const auto &[action, needs] : m_actionNeeds)
        action->setEnabled(met(needs));
}

void MainWindow::showProject()
{
    if (!m_document->hasProject()) {
        m_measurements->setProject(nullptr);
        m_planning->setLearnedModel(nullptr);
        m_profileView->clearProfile();
        m_analysis->recompute(); // the results' panels are cleared
        m_summary->clear();
        updateTitle();
        return;
    }
    m_problems->update();
    updateOperationChoice(); // first: the panels must not keep a set-up the project no longer has
    if (m_document->hasProblems()) {
        showProjectWithProblems();
        return;
    }
    // One set-up at a time: the part as it is held there, its features and tolerances.
    const Project project = operationView(m_document->project(), m_operation);
    m_profileView->setClamping(project.clamping);
    m_profileView->setProfile(project.part, project.tolerances, project.datums);
    m_measurements->setProject(&m_document->project());
    const std::shared_ptr<const LoadedModel> learned = m_measurements->activeModel();
    m_planning->setLearnedModel(learned);
    m_analysis->setLearnedModel(learned);
    m_analysis->recompute();
    m_planning->showProjectOutputs();
    updateSummary();
    updateTitle();
}

void MainWindow::editOperations()
{
    if (!m_document->hasProject())
        return;
    OperationsDialog dialog(
        m_document->project(),
        [this](const std::vector<Operation> &operations) { return m_document->setFurtherOperations(operations); },
        this);
    dialog.exec();
}

void MainWindow::updateOperationChoice()
{
    const Project &project = m_document->project();
    const int count = operationCount(project);
    m_operation = std::min(m_operation, count - 1);
    m_operationBox->clear();
    for (int k = 0; k < count; ++k)
        m_operationBox->addItem(tr("%1: %2, %3 end held")
                                    .arg(operationName(project, k), displayName(operationClamping(project, k).method),
                                         displayName(operationClamping(project, k).heldEnd)));
    m_operationBox->setCurrentIndex(m_operation);
    m_operationAction->setVisible(count > 1);
    m_planning->setOperation(m_operation);
    m_analysis->setOperation(m_operation);
    m_setup->setOperation(m_operation);
    m_files->setOperation(m_operation);
}

void MainWindow::showProjectWithProblems()
{
    const Project &project = m_document->project();
    const Diagnostics problems = m_document->problems();
    auto under = [&problems](const QString &field) {
        return std::any_of(problems.begin(), problems.end(),
                           [&field](const Diagnostic &d) { return fieldCovers(field, d.field) || d.field.isEmpty(); });
    };
    // The drawing only of a sound profile; the annotations only where they are sound too.
    if (under(QStringLiteral("part"))) {
        m_profileView->clearProfile(ProjectAnalysis::notComputedText(static_cast<int>(problems.size())));
    } else {
        const bool annotations = !under(QStringLiteral("tolerances")) && !under(QStringLiteral("datums"));
        m_profileView->setClamping(under(QStringLiteral("clamping")) ? std::nullopt
                                                                     : std::optional<Clamping>(project.clamping));
        m_profileView->setProfile(project.part, annotations ? project.tolerances : std::vector<Tolerance>{},
                                  annotations ? project.datums : std::vector<Datum>{});
    }
    m_analysis->recompute(); // not predicted: the results' panels say why
    m_planning->showProjectOutputs();
    updateSummary();
    updateTitle();
}

void MainWindow::updateSummary()
{
    if (!m_document->hasProject())
        return;
    const Project &project = m_document->project();
    const PartProfile &part = project.part;
    const DisplayUnits units = DisplaySettings::instance().units();
    m_summary->setText(tr("%1 — length %2 %7, Ø max %3 %7, %4 outer / %5 inner features, clamping: %6")
                           .arg(part.name.isEmpty() ? tr("Part") : part.name, units.lengthText(part.length_mm()),
                                units.lengthText(2.0 * part.maxOuterRadius_mm()))
                           .arg(part.outer.segments.size())
                           .arg(part.inner.segments.size())
                           .arg(displayName(project.clamping.method), units.lengthSymbol()));
}

QString MainWindow::chooseFileToOpen(const QString &startFolder)
{
    return QFileDialog::getOpenFileName(this, tr("Open Project"), startFolder, FileController::fileFilter());
}

QString MainWindow::chooseFileToSave(const QString &suggestedPath)
{
    return QFileDialog::getSaveFileName(this, tr("Save Project As"), suggestedPath, FileController::fileFilter());
}

QString MainWindow::chooseReportFile(const QString &suggestedPath)
{
    return QFileDialog::getSaveFileName(this, tr("Export Report"), suggestedPath, tr("PDF documents (*.pdf)"));
}

QString MainWindow::autosaveFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/autosave");
}

void MainWindow::createProblemsDock()
{
    m_problemsDock = new QDockWidget(tr("Problems"), this);
    m_problemsDock->setObjectName(QStringLiteral("problemsDock"));
    m_problemsDock->setWidget(m_problems->panel());
    addDockWidget(Qt::BottomDockWidgetArea, m_problemsDock);
    m_problems->setDock(m_problemsDock);
}

void MainWindow::createImportDock()
{
    m_importDock = new QDockWidget(tr("Import Messages"), this);
    m_importDock->setObjectName(QStringLiteral("importDock"));
    m_importDock->setWidget(m_importMessages);
    addDockWidget(Qt::BottomDockWidgetArea, m_importDock);
    m_importMessages->showDiagnostics(tr("No STEP or IGES file imported in this session."), {});
}

// After an import: what it left out of the profile, or why it failed, in the dock in front.
void MainWindow::showImportMessages(bool ok, const QString &heading, const Diagnostics &diagnostics)
{
    Q_UNUSED(ok);
    m_importMessages->showDiagnostics(heading, diagnostics);
    if (!diagnostics.empty()) {
        m_importDock->show();
        m_importDock->raise();
    }
}

QString MainWindow::chooseCadFile(const QString &startFolder)
{
    return QFileDialog::getOpenFileName(this, tr("Import STEP or IGES"), startFolder,
                                        tr("STEP and IGES files (*.step *.stp *.iges *.igs);;All files (*)"));
}

QString MainWindow::chooseStepExportFile(const QString &suggestedPath)
{
    return QFileDialog::getSaveFileName(this, tr("Export STEP"), suggestedPath, tr("STEP files (*.step *.stp)"));
}

std::optional<CadImportChoice> MainWindow::confirmImport(const QString &fileName, const CadImportResult &read)
{
    ImportDialog dialog(fileName, read, this);
    if (dialog.exec() != QDialog::Accepted)
        return std::nullopt;
    return dialog.choice();
}

namespace {

// A window-modal dialog with a bar and Cancel for a task that runs elsewhere (EXAMPLES.md item 2,
// after Mayo's task manager dialog): update() only sets the bar, and the window's event loop,
// running as ever, draws it and delivers Cancel. Shown after 300 ms, so a quick task shows nothing.
class DialogProgress : public TaskProgress {
public:
    DialogProgress(const QString &label, QWidget *parent) : m_dialog(parent), m_bar(new QProgressBar(&m_dialog))
    {
        m_dialog.setObjectName(QStringLiteral("progressDialog"));
        m_dialog.setWindowTitle(QCoreApplication::applicationName());
        m_dialog.setWindowModality(Qt::WindowModal);
        m_dialog.setMinimumWidth(360);
        m_bar->setRange(0, 100);
        auto *buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, &m_dialog);
        buttons->button(QDialogButtonBox::Cancel)->setText(MainWindow::tr("Cancel")); // without Qt's catalogues too
        auto *layout = new QVBoxLayout(&m_dialog);
        layout->addWidget(new QLabel(label, &m_dialog));
        layout->addWidget(m_bar);
        layout->addWidget(buttons);
        // Cancel, Escape and the close button all reject.
        QObject::connect(buttons, &QDialogButtonBox::rejected, &m_dialog, &QDialog::reject);
        QObject::connect(&m_dialog, &QDialog::rejected, &m_dialog, [this] { m_cancelled = true; });
        m_delay.setSingleShot(true);
        QObject::connect(&m_delay, &QTimer::timeout, &m_dialog, &QDialog::show);
        m_delay.start(300);
    }

    bool update(double fraction) override
    {
        m_bar->setValue(static_cast<int>(100.0 * fraction));
        return !m_cancelled;
    }

    void onCancel(const std::function<void()> &handler) override
    {
        QObject::connect(&m_dialog, &QDialog::rejected, &m_dialog, handler);
    }

private:
    QDialog m_dialog;
    QProgressBar *m_bar;
    QTimer m_delay;
    bool m_cancelled = false;
};

} // namespace

std::unique_ptr<TaskProgress> MainWindow::startProgress(const QString &label)
{
    return std::make_unique<DialogProgress>(label, this);
}

bool MainWindow::askToRecover(const QString &documentName, const QDateTime &savedAt)
{
    QMessageBox box(QMessageBox::Question, tr("Recover Unsaved Changes"),
                    tr("TolTurn did not close normally. A copy of %1 with unsaved changes was kept at %2.")
                        .arg(documentName, QLocale().toString(savedAt, QLocale::ShortFormat)),
                    QMessageBox::NoButton, this);
    box.setObjectName(QStringLiteral("recoverDialog"));
    box.setInformativeText(tr("Recover it? A discarded copy is deleted."));
    QPushButton *recover = box.addButton(tr("&Recover"), QMessageBox::AcceptRole);
    box.addButton(tr("&Discard"), QMessageBox::DestructiveRole);
    box.setDefaultButton(recover);
    box.exec();
    return box.clickedButton() == recover;
}

FilePrompts::SaveChoice MainWindow::askToSaveChanges(const QString &documentName)
{
    QMessageBox box(QMessageBox::Warning, tr("Unsaved Changes"),
                    tr("%1 has changes that are not saved.").arg(documentName),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
    box.setObjectName(QStringLiteral("saveChangesDialog"));
    box.setInformativeText(tr("Save them before going on?"));
    box.setDefaultButton(QMessageBox::Save);
    switch (box.exec()) {
    case QMessageBox::Save:
        return SaveChoice::Save;
    case QMessageBox::Discard:
        return SaveChoice::Discard;
    default:
        return SaveChoice::Cancel;
    }
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (!m_files->maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState(kLayoutVersion));
    event->accept();
}

void MainWindow::showError(const QString &title, const QString &text)
{
    QMessageBox box(QMessageBox::Critical, title, text, QMessageBox::Ok, this);
    box.setObjectName(QStringLiteral("errorDialog"));
    box.exec();
}

} // namespace tolturn
