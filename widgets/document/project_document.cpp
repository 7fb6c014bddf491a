// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/document/project_document.h"

#include <QFileInfo>

#include <utility>

namespace tolturn {

ProjectDocument::ProjectDocument(QObject *parent) : QObject(parent) {}

QString ProjectDocument::displayName() const
{
    if (!m_filePath.isEmpty())
        return QFileInfo(m_filePath).fileName();
    if (!m_project.part.name.isEmpty())
        return m_project.part.name;
    return tr("Untitled");
}

void ProjectDocument::load(Project project, const QString &filePath)
{
    m_project = std::move(project);
    m_hasProject = true;
    const bool pathChanged = m_filePath != filePath;
    m_filePath = filePath;
    setModified(false);
    if (pathChanged)
        Q_EMIT filePathChanged(m_filePath);
    Q_EMIT projectChanged();
}

void ProjectDocument::markSaved(const QString &filePath)
{
    const bool pathChanged = m_filePath != filePath;
    m_filePath = filePath;
    setModified(false);
    if (pathChanged)
        Q_EMIT filePathChanged(m_filePath);
}

void ProjectDocument::setModified(bool modified)
{
    if (m_modified == modified)
        return;
    m_modified = modified;
    Q_EMIT modifiedChanged(m_modified);
}

} // namespace tolturn
