// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <vector>

namespace tolturn {

class ProjectDocument;

// A copy of the unsaved document that survives a crash. While the document has unsaved changes
// it is written (atomically) to the autosave folder every interval, as <session>.tolturn with a
// <session>.json naming the file it belongs to. The session holds <session>.lock while it runs;
// saving, closing or a normal exit removes the copy. A copy whose lock no running TolTurn holds
// is left from a crash and is offered for recovery at the next start.
class Autosave : public QObject {
    Q_OBJECT
public:
    // A copy left by a session that ended without removing it.
    struct Copy {
        QString autosavePath; // the .tolturn copy
        QString originalPath; // the file it was opened from; empty for a never-saved project
        QString partName;
        QDateTime savedAt;
    };

    Autosave(ProjectDocument &document, const QString &folder, QObject *parent = nullptr);
    ~Autosave() override;

    void setIntervalSeconds(int seconds);
    // Writes the copy now if the document has unsaved changes, else removes it; false on a write error.
    bool saveNow();

    [[nodiscard]] QString copyPath() const { return m_base + QStringLiteral(".tolturn"); }

    // The copies in `folder` that no running session owns, newest first.
    [[nodiscard]] static std::vector<Copy> leftOver(const QString &folder);
    // Deletes a left-over copy (after it was recovered or declined).
    static void remove(const Copy &copy);

private:
    void removeCopy() const;

    ProjectDocument &m_document;
    QString m_base; // folder/session without suffix
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
};

} // namespace tolturn
