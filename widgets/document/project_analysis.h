// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/learning/setup_prediction.h"
#include "core/project/project.h"

#include <QObject>
#include <QString>

#include <memory>

namespace tolturn {

class ProjectDocument;

// The predictions of the set-up on show, with one owner (EXAMPLES.md item 7, after hotspot's parser
// and its typed signals): recompute() predicts the set-up (predictSetup, with what was learned of
// the machine when the planner uses it) and hands the result to the panels that subscribe; the
// panels no longer have it pushed into them one by one.
class ProjectAnalysis : public QObject {
    Q_OBJECT
public:
    explicit ProjectAnalysis(ProjectDocument &document, QObject *parent = nullptr);

    // The set-up predicted, for a project of several (docs/operations.md); taken at recompute().
    void setOperation(int index) { m_operation = index; }

    // What was learned of the machine, when the planner uses it; nullptr: the stiffness range.
    void setLearnedModel(std::shared_ptr<const LoadedModel> model) { m_learned = std::move(model); }

    // Predicts the document's project as it is now: predicted() for a project that can be
    // computed, notPredicted() otherwise.
    void recompute();

    // Why a project with `problems` problems is not predicted (notPredicted's `why`).
    [[nodiscard]] static QString notComputedText(int problems);

Q_SIGNALS:
    // `project`: the set-up as held (operationView); `prediction`: its verdicts and curves.
    void predicted(const tolturn::Project &project, const tolturn::SetupPrediction &prediction);
    // No prediction: no project (`why` empty), or a project with problems (`why` says so).
    void notPredicted(const QString &why);

private:
    ProjectDocument &m_document;
    int m_operation = 0;
    std::shared_ptr<const LoadedModel> m_learned;
};

} // namespace tolturn
