// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/milling/milled_features.h"

#include <QFutureWatcher>
#include <QGroupBox>

#include <functional>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace tolturn {

class LinePlot;
class ProjectDocument;

// The milled features of the open project in the Milling dock (issue 19, docs/milling.md): one row
// per feature with its tolerance and verdict, evaluated on a worker thread; its kind, place on the
// part, datums and the source of its coefficients; the surface error along its path. The cut of the
// dock's fields is added as a new feature, saved to the chosen one, or the chosen one removed, each
// an undoable edit of the document. What is chosen is loaded into the dock's fields.
class MilledFeaturesBox : public QGroupBox {
    Q_OBJECT
public:
    // `completeFromFields` gives a feature the tool, conditions, coefficients and tolerance of the
    // dock's fields; `fieldsProblem` says why the fields cannot make a feature (empty when they can).
    MilledFeaturesBox(ProjectDocument *document, std::function<MilledFeature(MilledFeature)> completeFromFields,
                      std::function<QString()> fieldsProblem, QWidget *parent = nullptr);

    [[nodiscard]] QTableWidget *table() const { return m_table; }

    [[nodiscard]] LinePlot *pathPlot() const { return m_pathPlot; }

    [[nodiscard]] QPushButton *addButton() const { return m_add; }

    [[nodiscard]] QPushButton *saveButton() const { return m_save; }

    [[nodiscard]] QPushButton *removeButton() const { return m_remove; }

    [[nodiscard]] bool isEvaluating() const { return m_watcher.isRunning(); }

    [[nodiscard]] const std::vector<MilledFeatureEvaluation> &evaluations() const { return m_evaluations; }

    // Adds the dock's cut as a new feature (the kind, z range and coefficients' source of the fields
    // below the table); a message for the dock's summary when the project refuses it, else empty.
    QString addFromFields();
    // Saves the dock's cut into the chosen feature.
    QString saveToChosen();
    QString removeChosen();

Q_SIGNALS:
    // A feature was chosen in the table: the dock loads it into its fields.
    void featureChosen(const MilledFeature &feature);
    // Every feature of the project has its verdict (the worker is done).
    void evaluated();
    // What the document refused, or what a chosen feature lacks, for the dock's summary.
    void message(const QString &text);

private:
    void refresh();
    void evaluate();
    void showEvaluations();
    void showPath(int row);
    void choose(int row);
    [[nodiscard]] int chosenRow() const;
    [[nodiscard]] const MilledFeatureEvaluation *evaluationOf(int row) const;
    [[nodiscard]] MilledFeature propertiesFromFields(MilledFeature feature) const;
    [[nodiscard]] static QString sourceWithoutCoefficients(const MilledFeature &f);
    [[nodiscard]] QString nextId() const;
    QString apply(const std::vector<MilledFeature> &features, const QString &description);

    ProjectDocument *m_document;
    std::function<MilledFeature(MilledFeature)> m_completeFromFields;
    std::function<QString()> m_fieldsProblem;
    QTableWidget *m_table;
    QComboBox *m_kind;
    QDoubleSpinBox *m_zFrom;
    QDoubleSpinBox *m_zTo;
    QLineEdit *m_coefficientsSource;
    QPushButton *m_add;
    QPushButton *m_save;
    QPushButton *m_remove;
    LinePlot *m_pathPlot;
    QFutureWatcher<std::vector<MilledFeatureEvaluation>> m_watcher;
    std::vector<MilledFeatureEvaluation> m_evaluations;
    bool m_stale = false; // the project changed while the worker ran
};

} // namespace tolturn
