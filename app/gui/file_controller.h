// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>

namespace tolturn {

class ProjectDocument;
class RecentFiles;

// What file commands need from the user: a path chosen, an error shown. The main window answers
// with dialogs; tests answer with fixed paths and record the errors.
class FilePrompts {
public:
    virtual ~FilePrompts() = default;
    [[nodiscard]] virtual QString chooseFileToOpen(const QString &startFolder) = 0;
    [[nodiscard]] virtual QString chooseFileToSave(const QString &suggestedPath) = 0;
    virtual void showError(const QString &title, const QString &text) = 0;
};

// File > Open, Save, Save As and the recent-file list. Choosing a path and writing a file are
// separate steps; a failed open leaves the document as it was, a failed save leaves both the
// document (still modified) and the file on disk as they were.
class FileController : public QObject {
    Q_OBJECT
public:
    FileController(ProjectDocument &document, RecentFiles &recentFiles, FilePrompts &prompts,
                   QObject *parent = nullptr);

    bool open();
    bool openFile(const QString &path);
    // Opens a bundled example (a Qt resource path) as a new, unsaved document.
    bool openExample(const QString &resourcePath);
    bool save();
    bool saveAs();
    bool saveTo(const QString &path);

    // File name filter for dialogs.
    [[nodiscard]] static QString fileFilter();

    [[nodiscard]] static QString fileSuffix() { return QStringLiteral("tolturn"); }

Q_SIGNALS:
    void statusMessage(const QString &message);

private:
    bool loadFrom(const QString &readPath, const QString &documentPath);

    ProjectDocument &m_document;
    RecentFiles &m_recentFiles;
    FilePrompts &m_prompts;
};

} // namespace tolturn
