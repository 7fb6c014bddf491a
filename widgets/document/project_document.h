// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"
#include "core/project/project.h"

#include <QJsonValue>
#include <QObject>
#include <QString>

class QUndoStack;

namespace tolturn {

// The open project: its data, the file it came from, its edit history and whether it has unsaved
// changes (the undo stack is not at its clean state). Views observe it through projectChanged();
// nothing here touches files or dialogs. Every edit goes through a small QUndoCommand that keeps
// only the member it changes; repeated edits of one member under one name are one step in Undo.
class ProjectDocument : public QObject {
    Q_OBJECT
public:
    explicit ProjectDocument(QObject *parent = nullptr);
    ~ProjectDocument() override;

    [[nodiscard]] const Project &project() const { return m_project; }

    [[nodiscard]] bool hasProject() const { return m_hasProject; }

    [[nodiscard]] const QString &filePath() const { return m_filePath; }

    [[nodiscard]] bool isModified() const;
    // File name without folder, or the part name for an unsaved project.
    [[nodiscard]] QString displayName() const;

    [[nodiscard]] QUndoStack *undoStack() const { return m_undoStack; }

    // Replaces the whole document, e.g. after an open. Not an edit: clears the history.
    // `readProblems` are the errors of a file opened to be repaired (ProjectParseResult::repairable):
    // those validateProject() cannot see again, such as a value that could not be read and was left
    // at its default, stay in problems() until the field is given a value or the document is saved.
    void load(Project project, const QString &filePath, const Diagnostics &readProblems = {});
    // Empties the document (File > Close).
    void clear();
    // Marks a document restored from an autosave copy as modified: it differs from its file.
    void markRecovered();
    // Records that the document now lives in (was just saved to) `filePath`.
    void markSaved(const QString &filePath);

    // What stops the project from being computed: the errors found when it was read and those of
    // validateProject() now. Empty for a sound project; a file with problems is opened to be
    // repaired one value at a time, and nothing is computed until this is empty.
    [[nodiscard]] Diagnostics problems() const;

    [[nodiscard]] bool hasProblems() const { return !problems().empty(); }

    // Edits. Each checks the project that would result (validateProject) and, when that has errors
    // the project did not have before, changes nothing and returns them; otherwise it is pushed on
    // the undo stack. A project opened with problems can so be repaired in any order.
    Diagnostics addTolerance(const Tolerance &tolerance);
    Diagnostics replaceTolerance(int index, const Tolerance &tolerance);
    Diagnostics removeTolerance(int index);
    // Sets datum `label` on a feature (a new datum, or the same letter moved to another feature).
    Diagnostics setDatum(const Datum &datum);
    Diagnostics setPlanning(const PlanningSettings &planning);
    Diagnostics setPasses(const std::vector<CuttingPass> &passes, const QString &description);
    // The operations after the first (docs/operations.md), as one undoable edit.
    Diagnostics setFurtherOperations(const std::vector<Operation> &operations);
    // The tool, boring tool and clamping of operation `index` (0: the project's own).
    Diagnostics setOperationTool(int index, const Tool &tool);
    Diagnostics setOperationBoringTool(int index, const std::optional<Tool> &tool);
    Diagnostics setOperationClamping(int index, const Clamping &clamping);
    // The passes of operation `index` (0: the project's own, docs/operations.md).
    Diagnostics setOperationPasses(int index, const std::vector<CuttingPass> &passes, const QString &description);
    Diagnostics setMaterial(const QString &materialId);
    Diagnostics setMachine(const QString &machineId);
    Diagnostics setTool(const Tool &tool);
    Diagnostics setBoringTool(const std::optional<Tool> &tool); // nullopt: no boring bar
    Diagnostics setCuttingModel(const CuttingModel &model);
    Diagnostics setEnvironment(const Environment &environment);
    Diagnostics setClamping(const Clamping &clamping);
    Diagnostics setCharacterisation(const MachineCharacterisation &characterisation);
    // The milled features of a mill-turn part (docs/milling.md), as one undoable edit.
    Diagnostics setMilledFeatures(const std::vector<MilledFeature> &features, const QString &description);
    // The part's profile after an edit of the profile editor, named by `description` in Undo.
    Diagnostics setPart(const PartProfile &part, const QString &description);

    // A tolerance id not used yet: "T1", "T2", ...
    [[nodiscard]] QString nextToleranceId() const;

    // While alive, the document's edits are steps of `control` (a spin box being stepped with its
    // arrows or typed into): such edits of one member under one name, one after another, are one
    // step in Undo, which takes the member back to where the first of them found it. Outside such
    // a scope, from another control, and after endRepeatedEdits(), an edit is a step of its own.
    class RepeatedEdits {
    public:
        RepeatedEdits(ProjectDocument &document, const QObject *control);
        ~RepeatedEdits();
        RepeatedEdits(const RepeatedEdits &) = delete;
        RepeatedEdits &operator=(const RepeatedEdits &) = delete;

    private:
        ProjectDocument &m_document;
        const QObject *m_previous;
    };

    // The next steps of any control start a step of their own: the control has lost the focus,
    // or now edits something else (another feature, another set-up), or was rebuilt.
    void endRepeatedEdits() { ++m_editRun; }

Q_SIGNALS:
    void projectChanged();
    void filePathChanged(const QString &filePath);
    void modifiedChanged(bool modified);

private:
    template <typename T>
    friend class FieldCommand;

    Diagnostics check(const Project &candidate) const;
    // projectChanged() once for the commands applied since the last (EXAMPLES.md item 6, after KDE
    // Step's emitChanged): at the end of a push, an undo, a redo or a jump through the history.
    void emitChange();
    // Pushes the edit of one member, unchecked (editField checks first).
    template <typename T>
    void pushField(T Project::*field, const T &value, const QString &description);
    template <typename T>
    Diagnostics editField(T Project::*field, const T &value, const QString &description);
    // One field of a set-up after the first (index >= 1), as one undoable edit of the operations.
    template <typename T>
    Diagnostics editOperation(int index, T Operation::*field, const T &value, const QString &description);

    Project m_project;
    bool m_changePending = false; // a command changed m_project since the last projectChanged()

    struct ReadProblem {
        Diagnostic diagnostic;
        QJsonValue valueAsRead; // the field's value as the document holds it after the read
    };

    std::vector<ReadProblem> m_readProblems;
    const QObject *m_repeatingControl = nullptr; // RepeatedEdits
    quint64 m_editRun = 0;                       // endRepeatedEdits

    bool m_hasProject = false;
    QString m_filePath;
    QUndoStack *m_undoStack;
};

} // namespace tolturn
