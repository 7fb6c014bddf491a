// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/learning/setup_prediction.h"
#include "core/tolerance/evaluation.h"
#include "core/tolerance/range_verdicts.h"

#include <QWidget>

class QLabel;
class QPushButton;
class QTableView;

namespace tolturn {

class ProjectDocument;
class ToleranceVerdictModel;

// The tolerances of the open project with their verdicts, and the commands to add, edit and
// remove them on the selected feature and to set datums. Edits go through the document (undoable).
class TolerancePanel : public QWidget {
    Q_OBJECT
public:
    explicit TolerancePanel(ProjectDocument &document, QWidget *parent = nullptr);

    void showVerdicts(std::vector<ToleranceEvaluation> verdicts);
    // The verdicts over the machine's stiffness range, with the banner saying what the supports
    // rest on (`assumption`, empty for a measured machine).
    void showVerdicts(std::vector<ToleranceRangeEvaluation> verdicts, const QString &assumption, bool optimistic);
    // ProjectAnalysis::predicted: the set-up's verdicts and what they rest on.
    void showPrediction(const Project &project, const SetupPrediction &prediction);
    // ProjectAnalysis::notPredicted: no rows without a project; else each tolerance saying `why`.
    void showNotPredicted(const QString &why);

    [[nodiscard]] QLabel *banner() const { return m_banner; }

    void setSelectedFeature(const QString &featureId);
    // Selects the row of the project's tolerance `index` (the order of the file and the table).
    void selectTolerance(int index);

    [[nodiscard]] ToleranceVerdictModel *model() const { return m_model; }

    [[nodiscard]] QTableView *table() const { return m_table; }

    void addTolerance();
    void editTolerance();
    void removeTolerance();
    void setDatum();

Q_SIGNALS:
    void featureActivated(const QString &featureId);

private:
    [[nodiscard]] int currentRow() const;
    void updateButtons();

    ProjectDocument &m_document;
    ToleranceVerdictModel *m_model;
    QTableView *m_table;
    QLabel *m_banner;
    QPushButton *m_add;
    QPushButton *m_edit;
    QPushButton *m_remove;
    QPushButton *m_datum;
    QString m_selectedFeature;
};

} // namespace tolturn
