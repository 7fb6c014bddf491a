// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/deviation/deviation_model.h"
#include "core/learning/setup_prediction.h"
#include "widgets/common/display_units.h"

#include <QWidget>

#include <functional>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;

namespace tolturn {

class LinePlot;

// Predicted deviation along z for the open project: total and each contribution (spindle–chuck,
// toolpost, workpiece, thermal) for the outer or the inner contour, or the diameter error, with
// the forces used and the assumptions the result rests on.
class DeflectionPanel : public QWidget {
    Q_OBJECT
public:
    enum class Quantity { RadialContributions, TangentialContributions, DiameterError, FaceConicity };

    explicit DeflectionPanel(QWidget *parent = nullptr);

    // Shows the deviation computed for `project`; `stiffEnd`, where the machine is a published
    // stiffness range, is the same at the stiff end, drawn as a band with the total.
    // With `learned`, `result` is the physics alone and the curves of physics + learned, with
    // their uncertainty band, are drawn beside it.
    void showResult(const Project &project, DeviationResult result, std::optional<DeviationResult> stiffEnd = {},
                    std::optional<LearnedCurves> learned = {});
    // Adds the curves of the total and of each contribution along one contour, in µm, broken at
    // the ends of the features (also used by the PDF report).
    static void addContributionCurves(LinePlot &plot, const DeviationResult &result, ContourSide side, bool radial,
                                      const DisplayUnits &units = DisplayUnits());
    // Where the machine is a stiffness range: the band of one quantity of a station (in mm) between
    // the compliant end `result` and the stiff end, along one contour (also used by the report).
    static void addRangeBand(LinePlot &plot, const DeviationResult &result, const DeviationResult &stiffEnd,
                             ContourSide side, const std::function<double(const Station &)> &value, const QString &what,
                             const DisplayUnits &units = DisplayUnits());

    // The total radial deviation with what was learned added (material left: + outer, − bores),
    // with its band of ± the uncertainty (also used by the PDF report).
    static void addLearnedTotal(LinePlot &plot, const DeviationResult &result, const LearnedCurves &learned,
                                ContourSide side, const DisplayUnits &units = DisplayUnits());

    // The band of the total radial deviation.
    static double totalRadial_mm(const Station &st) { return st.radial.total_mm(); }

    // No result: the plot hidden and `why` said (by default, that no part is open).
    // ProjectAnalysis::predicted: the set-up's curves (its range as a band, or what was learned).
    void showPrediction(const Project &project, const SetupPrediction &prediction);
    void clear(const QString &why = QString());

    void setSide(ContourSide side);
    void setQuantity(Quantity quantity);

    [[nodiscard]] const DeviationResult &result() const { return m_result; }

    [[nodiscard]] const std::optional<DeviationResult> &stiffEnd() const { return m_stiffEnd; }

    [[nodiscard]] const std::optional<LearnedCurves> &learned() const { return m_learned; }

    [[nodiscard]] LinePlot *plot() const { return m_plot; }

    [[nodiscard]] QString summaryText() const;
    [[nodiscard]] QString boringSummary(const TurningInputs &in) const;
    [[nodiscard]] QString zAxisLabel(const DisplayUnits &units) const;

private:
    void redraw();
    void plotContributions(bool radial);
    void plotDiameterError();
    void plotFaceConicity();
    void updateTexts();
    // Physics + learned of one quantity along one contour, with its band of ± the uncertainty;
    // `scale` 1 for the material left (radial), 2 for the diameter error.
    static void addLearnedCurve(LinePlot &plot, const DeviationResult &result, const LearnedCurves &learned,
                                ContourSide side,
                                const std::function<double(const Station &, double learned_mm)> &value, double scale,
                                const QString &name, const DisplayUnits &units);

    DeviationResult m_result;
    std::optional<DeviationResult> m_stiffEnd;
    std::optional<LearnedCurves> m_learned;
    ContourSide m_side = ContourSide::Outer;
    bool m_heldAtRight = false; // the set-up holds the drawing's right end: z from there
    Quantity m_quantity = Quantity::RadialContributions;
    QComboBox *m_sideBox;
    QComboBox *m_quantityBox;
    LinePlot *m_plot;
    QLabel *m_summary;
    QLabel *m_notes;
};

} // namespace tolturn
