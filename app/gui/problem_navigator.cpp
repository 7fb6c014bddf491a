// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/problem_navigator.h"

#include "widgets/common/diagnostics_panel.h"
#include "widgets/common/project_fields.h"
#include "widgets/document/project_document.h"
#include "widgets/profile/feature_panel.h"
#include "widgets/profile/profile_view.h"
#include "widgets/tolerances/tolerance_panel.h"

#include <QDockWidget>
#include <QRegularExpression>

namespace tolturn {

ProblemNavigator::ProblemNavigator(ProjectDocument &document, const Views &views, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_views(views)
    , m_panel(new DiagnosticsPanel(views.window))
{
    m_panel->setObjectName(QStringLiteral("problemsPanel"));
    connect(m_panel, &DiagnosticsPanel::fieldActivated, this, &ProblemNavigator::focusField);
    update();
}

void ProblemNavigator::update()
{
    const Diagnostics problems = m_document.problems();
    m_panel->showDiagnostics(
        problems.empty() ? tr("No problems: every value of the project can be computed with.")
                         : tr("%n problem(s) stop the computation. Double-click one to go to its value; the results "
                              "return once all are repaired.",
                              nullptr, static_cast<int>(problems.size())),
        problems);
}

void ProblemNavigator::showFirst()
{
    update();
    if (m_dock) {
        m_dock->show();
        m_dock->raise();
    }
    // After the events already posted: editors made for the new project (a row per pass) are
    // shown by a queued call, and a hidden widget takes no focus.
    QMetaObject::invokeMethod(
        this,
        [this] {
            for (const Diagnostic &d : m_document.problems()) {
                if (focusField(d.field))
                    return;
            }
        },
        Qt::QueuedConnection);
}

void ProblemNavigator::selectOwner(const QString &field)
{
    static const QRegularExpression segment(QStringLiteral("^part\\.(outer|inner)\\[(\\d+)\\]"));
    static const QRegularExpression tolerance(QStringLiteral("^tolerances\\[(\\d+)\\]"));
    const Project &p = m_document.project();
    if (const QRegularExpressionMatch m = segment.match(field); m.hasMatch()) {
        const auto &segments = m.captured(1) == QLatin1String("outer") ? p.part.outer.segments : p.part.inner.segments;
        const auto index = static_cast<std::size_t>(m.captured(2).toULongLong());
        if (index < segments.size()) {
            m_views.profile->selectFeature(segments[index].id);
            m_views.feature->setFeature(segments[index].id);
        }
    } else if (const QRegularExpressionMatch t = tolerance.match(field); t.hasMatch()) {
        m_views.tolerances->selectTolerance(t.captured(1).toInt());
    }
}

bool ProblemNavigator::focusField(const QString &field)
{
    selectOwner(field);
    QWidget *editor = editorForField(*m_views.window, field);
    if (!editor)
        return false;
    focusEditor(*editor);
    return true;
}

} // namespace tolturn
