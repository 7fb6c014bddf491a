// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/cad_reader_process.h"
#include "app/gui/file_controller.h"
#include "core/cad/step_import.h"

#include <QObject>

#include <memory>
#include <optional>

namespace tolturn {

class ProjectDocument;

// What the planner decides after the file is read: which body and axis, which end the chuck
// holds (flip: the model's right end becomes z = 0).
struct CadImportChoice {
    int solid = 0;
    int axis = 0;
    bool flip = false;
};

// The questions the import and export ask; the main window answers with dialogs, tests without.
class CadPrompts {
public:
    virtual ~CadPrompts() = default;
    [[nodiscard]] virtual QString chooseCadFile(const QString &startFolder) = 0;
    [[nodiscard]] virtual QString chooseStepExportFile(const QString &suggestedPath) = 0;
    // After the first read: the bodies and axes found, the profile of the default choice. Empty
    // when the planner cancels.
    [[nodiscard]] virtual std::optional<CadImportChoice> confirmImport(const QString &fileName,
                                                                       const CadImportResult &read) = 0;
    virtual void showError(const QString &title, const QString &text) = 0;
    [[nodiscard]] virtual std::unique_ptr<TaskProgress> startProgress(const QString &label) = 0;
};

// File > Import STEP/IGES and File > Export STEP. The file is read in a child process
// (CadReaderProcess: OpenCascade can take seconds on a large model, and a damaged file must not
// take the window with it) with progress and cancel; the planner confirms the body, the
// axis and the chuck end; the part then opens as a new, unsaved project with a default set-up.
// A failed or cancelled import leaves the document as it was.
class CadFileController : public QObject {
    Q_OBJECT
public:
    CadFileController(ProjectDocument &document, FileController &files, CadPrompts &prompts, QObject *parent = nullptr);
    ~CadFileController() override;

    // Asks for a file and imports it.
    void importCad();
    // Imports `path`; importFinished() follows (at once when nothing can start).
    void importFile(const QString &path);

    [[nodiscard]] bool isImporting() const { return m_reader.isRunning(); }

    void cancelImport() { cancelReading(); }

    bool exportStep();
    bool exportStepTo(const QString &path);

Q_SIGNALS:
    void importProgress(int percent);
    // `ok` when the part was opened. `diagnostics` are the import's findings either way.
    void importFinished(bool ok, const QString &heading, const tolturn::Diagnostics &diagnostics);
    void statusMessage(const QString &message);

private:
    void startReading(const CadImportOptions &options);
    void showProgress(const QString &label);
    void cancelReading();
    void readFinished();
    void openImported(const CadImportResult &result);

    ProjectDocument &m_document;
    FileController &m_files;
    CadPrompts &m_prompts;
    CadReaderProcess m_reader;
    std::unique_ptr<TaskProgress> m_progress;
    QString m_path;
    bool m_confirmed = false;       // the second read, with the planner's choice
    bool m_cancelRequested = false; // the planner cancelled this read
};

} // namespace tolturn
