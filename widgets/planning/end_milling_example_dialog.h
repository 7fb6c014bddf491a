// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/adaptive/seed_milling_example.h"

#include <QDialog>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QTableWidget;

namespace tolturn {

class LinePlot;

// Tools > Čuš & Župerl end-milling example (docs/adaptive.md §9): the paper's own system rebuilt,
// its force, feed rate, spindle speed or roughness against time with and without control beside
// what the paper reports, the PSO-NN conditions and every row of the paper's table 1. Machine noise
// and the speed's share of the chip load can be tried; a run takes under a second.
class EndMillingExampleDialog : public QDialog {
    Q_OBJECT
public:
    explicit EndMillingExampleDialog(QWidget *parent = nullptr);

    [[nodiscard]] const SeedExampleResult &result() const { return m_result; }

    [[nodiscard]] LinePlot *plot() const { return m_plot; }

    [[nodiscard]] QComboBox *quantityChoice() const { return m_quantity; }

    [[nodiscard]] QDoubleSpinBox *noise() const { return m_noise; }

    [[nodiscard]] QTableWidget *table() const { return m_table; }

    [[nodiscard]] QLabel *summary() const { return m_summary; }

private:
    void simulate();
    void showRun();
    void showTable();

    SeedExampleResult m_result;
    QComboBox *m_quantity;
    QDoubleSpinBox *m_noise;
    QDoubleSpinBox *m_speedShare;
    LinePlot *m_plot;
    QLabel *m_summary;
    QTableWidget *m_table;
};

} // namespace tolturn
