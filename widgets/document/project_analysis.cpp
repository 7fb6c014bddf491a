// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/document/project_analysis.h"

#include "core/project/operations.h"
#include "widgets/document/project_document.h"

#include <algorithm>

namespace tolturn {

ProjectAnalysis::ProjectAnalysis(ProjectDocument &document, QObject *parent) : QObject(parent), m_document(document) {}

QString ProjectAnalysis::notComputedText(int problems)
{
    return tr("Not computed: the project has %n problem(s), listed under Problems. Double-click one to go to its "
              "value.",
              nullptr, problems);
}

void ProjectAnalysis::recompute()
{
    if (!m_document.hasProject()) {
        Q_EMIT notPredicted(QString());
        return;
    }
    if (m_document.hasProblems()) {
        Q_EMIT notPredicted(notComputedText(static_cast<int>(m_document.problems().size())));
        return;
    }
    const Project &document = m_document.project();
    const Project project = operationView(document, std::clamp(m_operation, 0, operationCount(document) - 1));
    Q_EMIT predicted(project, predictSetup(project, DataLibrary::builtIn(), m_learned.get()));
}

} // namespace tolturn
