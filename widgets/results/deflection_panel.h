// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/deviation/deviation_model.h"
#include "widgets/common/display_units.h"

#include <QWidget>

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

    // Shows the deviation computed for `project`.
    void showResult(const Project &project, DeviationResult result);
    // Adds the curves of the total and of each contribution along one contour, in µm, broken at
    // the ends of the features (also used by the PDF report).
    static void addContributionCurves(LinePlot &plot, const DeviationResult &result, ContourSide side, bool radial,
                                      const DisplayUnits &units = DisplayUnits());
    void clear();

    void setSide(ContourSide side);
    void setQuantity(Quantity quantity);

    [[nodiscard]] const DeviationResult &result() const { return m_result; }

    [[nodiscard]] LinePlot *plot() const { return m_plot; }

    [[nodiscard]] QString summaryText() const;

private:
    void redraw();
    void plotContributions(bool radial);
    void plotDiameterError();
    void plotFaceConicity();
    void updateTexts();

    DeviationResult m_result;
    ContourSide m_side = ContourSide::Outer;
    Quantity m_quantity = Quantity::RadialContributions;
    QComboBox *m_sideBox;
    QComboBox *m_quantityBox;
    LinePlot *m_plot;
    QLabel *m_summary;
    QLabel *m_notes;
};

} // namespace tolturn
