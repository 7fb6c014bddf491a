// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/learning/machine_learning.h"
#include "core/planning/planning_report.h"
#include "widgets/common/job_runner.h"

#include <QWidget>

#include <memory>

class QCheckBox;
class QComboBox;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTabWidget;

namespace tolturn {

class AdaptiveTab;
class MapPlot;
class ProjectDocument;

// Planning for the open project: the objective and the constraints switched on, the optimisation
// run off the GUI thread with progress and cancel, and its results: the plan (which can be applied
// to the project's passes), the cutting window with labelled boundaries and the optimum, the
// clamping ranking, the compensation of the finishing pass feature by feature, the constant-force
// control and the feed schedule (Adaptive), and its G-code.
class PlanningPanel : public QWidget {
    Q_OBJECT
public:
    explicit PlanningPanel(ProjectDocument &document, QWidget *parent = nullptr);
    ~PlanningPanel() override;

    // Starts the optimisation (does nothing while one runs).
    void optimise();
    void cancel();
    [[nodiscard]] bool isRunning() const;
    // Replaces the project's passes with the optimal ones (undoable).
    void applyPlan();
    // Opens the planning data (rates, tool life, cutting ranges, limits) for editing; OK applies
    // them as one undoable edit.
    void editPlanningData();
    // Writes the G-code shown (nominal or compensated) to a file atomically; returns the error, if any.
    [[nodiscard]] QString exportGCode(const QString &path) const;

    [[nodiscard]] const PlanningReport *report() const { return m_report.get(); }

    [[nodiscard]] MapPlot *windowPlot() const { return m_map; }

    [[nodiscard]] QTableWidget *clampingTable() const { return m_clamping; }

    [[nodiscard]] QLabel *splitLabel() const { return m_split; }

    [[nodiscard]] QPushButton *applySplitButton() const { return m_applySplit; }

    [[nodiscard]] QTableWidget *compensationTable() const { return m_compensation; }

    [[nodiscard]] AdaptiveTab *adaptiveTab() const { return m_adaptive; }

    [[nodiscard]] QCheckBox *feedScheduleBox() const { return m_scheduled; }

    [[nodiscard]] QString gcodeText() const;
    [[nodiscard]] QString planText() const;

    // Refreshes what follows the project directly (settings, compensation, G-code).
    void showProjectOutputs();
    // The operation (set-up) planned, of a project of several (docs/operations.md); 0: the first.
    void setOperation(int index);

    // The currency costs are given in (the preferences); empty: not stated.
    void setCurrency(const QString &currency);
    // What was learned of the machine, when the planner uses it (Measurements dock): the plan's
    // tolerance constraints, the compensation and the program then rest on physics + learned.
    void setLearnedModel(std::shared_ptr<const LoadedModel> model);

    [[nodiscard]] const std::shared_ptr<const LoadedModel> &learnedModel() const { return m_learned; }

    [[nodiscard]] QTableWidget *planPassesTable() const { return m_planPasses; }

    // The Plan tab's text before the first run.
    [[nodiscard]] static QString notRunText();
    // Shown instead of the plan and the program while the project has problems to repair.
    [[nodiscard]] static QString problemsText();

Q_SIGNALS:
    void started();  // a run began (isRunning() is true)
    void finished(); // a run ended, completed or cancelled

private:
    void buildControls();
    void settingsEdited();
    void planFinished(PlanningReport report);
    void showReport();
    void showWindow();
    void showClamping();
    void showFinishing();
    void showPlanPasses();
    void showSplit();
    void applySplit();
    // The project of the operation planned: what the optimiser, the program and the markers use.
    [[nodiscard]] Project operationProject() const;
    [[nodiscard]] std::shared_ptr<const LoadedModel> learnedFor(const Project &project) const;

    ProjectDocument &m_document;
    int m_operation = 0;
    int m_runOperation = 0; // the set-up the running (or last) optimisation is for
    std::shared_ptr<const LoadedModel> m_learned;
    QComboBox *m_objective;
    QComboBox *m_plane;
    std::vector<QCheckBox *> m_constraints;
    QPushButton *m_run;
    QPushButton *m_cancel;
    QPushButton *m_apply;
    QPushButton *m_data;
    QProgressBar *m_progress;
    QTabWidget *m_tabs;
    QLabel *m_plan;
    QTableWidget *m_planPasses = nullptr; // the optimal plan per pass, along its tool path
    QString m_currency;
    MapPlot *m_map;
    QLabel *m_legend;
    QTableWidget *m_clamping;
    QLabel *m_split = nullptr;
    QPushButton *m_applySplit = nullptr;
    QTableWidget *m_compensation;
    QCheckBox *m_compensated;
    QCheckBox *m_scheduled; // the finishing pass cut at the Adaptive tab's feed schedule
    AdaptiveTab *m_adaptive;
    QComboBox *m_dialect;
    QComboBox *m_nose;
    QLabel *m_gcodeConditions;
    QPlainTextEdit *m_gcode;
    QPushButton *m_export;
    JobRunner m_runner; // the optimisation, off the window's thread
    std::unique_ptr<PlanningReport> m_report;
    FinishingOutput m_finishing;
    bool m_updatingControls = false;
};

} // namespace tolturn
