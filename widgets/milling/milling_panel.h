// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/milling/ball_end_planning.h"
#include "core/project/milled_feature.h"

#include <QFutureWatcher>
#include <QWidget>

#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTabWidget;

namespace tolturn {

class LinePlot;
class MapPlot;
class MilledFeaturesBox;
class ProjectDocument;

// What a plan on the worker thread gives back: the plan, or why there is none.
struct MillingPlanOutcome {
    std::optional<BallEndPlan> plan;
    QString error;
};

// The Milling dock (issue 19, docs/milling.md): a five-axis ball-end cut after Öztürk & Budak, its
// forces against the rotation angle, the surface-normal error it leaves against the tolerance, and
// the lead–tilt window with the plan of least time. Starts from 001's case 1; the cutting
// coefficients are the planner's to give, as 001 prints none and TolTurn bundles none.
class MillingPanel : public QWidget {
    Q_OBJECT
public:
    // With a document, the project's milled features are listed above the cut, and a feature can
    // be loaded into the fields, added from them or saved from them.
    explicit MillingPanel(ProjectDocument *document = nullptr, QWidget *parent = nullptr);

    // Fills the fields from a project's milled feature; what it does not have yet is left as it is.
    void loadFeature(const MilledFeature &feature);
    // `feature` with the tool, conditions, coefficients and tolerance of the fields.
    [[nodiscard]] MilledFeature completeFeature(MilledFeature feature) const;
    // Why the fields cannot be saved to a feature (coefficients that do not read, a located profile
    // without datums); empty when they can.
    [[nodiscard]] QString featureProblem() const;

    [[nodiscard]] MilledFeaturesBox *features() const { return m_features; }

    // Fills the tool, cut, speed and holder springs from 001 table 4's case 1–4.
    void loadCase(int number);
    // Forces and deflection of the cut as entered, at once (under a millisecond).
    void compute();
    // The lead–tilt window and the plan, on a worker thread; planFinished() when done.
    void plan();

    [[nodiscard]] bool isPlanning() const { return m_watcher.isRunning(); }

    [[nodiscard]] const std::optional<BallEndPlan> &lastPlan() const { return m_plan; }

    [[nodiscard]] QComboBox *caseChoice() const { return m_case; }

    [[nodiscard]] QLineEdit *coefficients() const { return m_coefficients; }

    [[nodiscard]] QDoubleSpinBox *lead() const { return m_lead; }

    [[nodiscard]] QDoubleSpinBox *tolerance() const { return m_tolerance; }

    [[nodiscard]] QPushButton *planButton() const { return m_planButton; }

    [[nodiscard]] LinePlot *forcePlot() const { return m_forcePlot; }

    [[nodiscard]] LinePlot *errorPlot() const { return m_errorPlot; }

    [[nodiscard]] MapPlot *windowPlot() const { return m_windowPlot; }

    [[nodiscard]] QTabWidget *plots() const { return m_tabs; }

    [[nodiscard]] QLabel *summary() const { return m_summary; }

Q_SIGNALS:
    void planFinished();

private:
    struct Inputs {
        BallEndMill mill;
        BallEndCut cut;
        double spindle_rpm = 0.0;
        std::optional<MillingForceCoefficients> coefficients;
        BallEndToolStructure tool;
        MilledSurfaceTolerance tolerance;
        BallEndPlanSettings settings;
    };

    QWidget *createToolAndCut();
    QWidget *createStructureAndTolerance();
    QWidget *createPlots();
    [[nodiscard]] Inputs inputs() const;
    // What keeps the model from running, one line per field; empty when it can.
    [[nodiscard]] QStringList problems(const Inputs &in) const;
    void showForces(const Inputs &in, const BallEndDeflection &result);
    void showError(const Inputs &in, const BallEndDeflection &result);
    void showWindow();
    void clearResults(const QString &why);
    void updatePlanButton();

    QComboBox *m_case;
    QDoubleSpinBox *m_diameter;
    QSpinBox *m_flutes;
    QDoubleSpinBox *m_helix;
    QDoubleSpinBox *m_lead;
    QDoubleSpinBox *m_tilt;
    QComboBox *m_kind;
    QComboBox *m_direction;
    QDoubleSpinBox *m_radialDepth;
    QDoubleSpinBox *m_axialDepth;
    QDoubleSpinBox *m_feedPerTooth;
    QDoubleSpinBox *m_spindle;
    QLineEdit *m_coefficients;
    QDoubleSpinBox *m_overhang;
    QDoubleSpinBox *m_equivalentDiameter;
    QDoubleSpinBox *m_modulus;
    QDoubleSpinBox *m_holderStiffness;
    QDoubleSpinBox *m_holderRotational;
    QLabel *m_springSource;
    QDoubleSpinBox *m_tolerance;
    QComboBox *m_zone;
    QLineEdit *m_datums;
    QDoubleSpinBox *m_highestFeed;
    QPushButton *m_planButton;
    QTabWidget *m_tabs;
    LinePlot *m_forcePlot;
    LinePlot *m_errorPlot;
    MapPlot *m_windowPlot;
    QLabel *m_summary;
    QLabel *m_planSummary;
    MilledFeaturesBox *m_features = nullptr;
    QFutureWatcher<MillingPlanOutcome> m_watcher;
    std::optional<BallEndPlan> m_plan;
    Inputs m_planInputs; // what the plan was made for
    bool m_loading = false;
};

} // namespace tolturn
