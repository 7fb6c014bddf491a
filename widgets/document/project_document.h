// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/project.h"

#include <QObject>
#include <QString>

namespace tolturn {

// The open project: its data, the file it came from and whether it has unsaved changes.
// Views observe it through changed(); nothing here touches files or dialogs.
class ProjectDocument : public QObject {
    Q_OBJECT
public:
    explicit ProjectDocument(QObject *parent = nullptr);

    [[nodiscard]] const Project &project() const { return m_project; }

    [[nodiscard]] bool hasProject() const { return m_hasProject; }

    [[nodiscard]] const QString &filePath() const { return m_filePath; }

    [[nodiscard]] bool isModified() const { return m_modified; }

    // File name without folder, or the part name for an unsaved project.
    [[nodiscard]] QString displayName() const;

    // Replaces the whole document, e.g. after a successful open. Not an edit: not modified.
    void load(Project project, const QString &filePath);
    // Records that the document now lives in (was just saved to) `filePath`.
    void markSaved(const QString &filePath);

Q_SIGNALS:
    void projectChanged();
    void filePathChanged(const QString &filePath);
    void modifiedChanged(bool modified);

private:
    void setModified(bool modified);

    Project m_project;
    bool m_hasProject = false;
    QString m_filePath;
    bool m_modified = false;
};

} // namespace tolturn
