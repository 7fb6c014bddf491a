// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/fe/solid_check.h"
#include "widgets/common/display_units.h"

#include <QWidget>

#include <optional>

class QLabel;
class QTableWidget;

namespace tolturn {

class LinePlot;

// The result of a solid check (docs/solid-fe.md): the beam's and the solid's deflection at each
// station as a table and a plot along z, what the run meshed and solved, and what the comparison
// rests on. Shown in the display units of the settings.
class SolidCheckView : public QWidget {
    Q_OBJECT
public:
    explicit SolidCheckView(QWidget *parent = nullptr);

    // Shows a successful check of a part `partLength_mm` long; `clampingName` says how it was held.
    void showResult(const SolidCheckResult &result, double partLength_mm, const QString &clampingName);
    // Nothing shown: the table emptied, the plot hidden.
    void clear();

    [[nodiscard]] QTableWidget *table() const { return m_table; }

    [[nodiscard]] LinePlot *plot() const { return m_plot; }

    [[nodiscard]] QString summaryText() const;
    [[nodiscard]] QString notesText() const;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void redraw();
    // Every column as wide as its header and cells, the room left shared among them.
    void fitColumns();
    void fillTable(const DisplayUnits &units);
    void drawPlot(const DisplayUnits &units);
    [[nodiscard]] QString summary(const DisplayUnits &units) const;

    std::optional<SolidCheckResult> m_result;
    QString m_clamping;
    double m_partLength_mm = 0.0;
    QTableWidget *m_table;
    LinePlot *m_plot;
    QLabel *m_summary;
    QLabel *m_notes;
};

} // namespace tolturn
