// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/fe/solid_check.h"
#include "core/project/project.h"

#include <QDialog>
#include <QFutureWatcher>
#include <QTimer>

#include <memory>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace tolturn {

class LengthSpinBox;
class SolidCheckView;
struct SolidCheckRunState;

// Tools > Check with Solid FE… (docs/solid-fe.md): the beam's deflection of one set-up checked
// against a solid model meshed with gmsh and solved with CalculiX. The check runs off the GUI
// thread on a copy of the project, which it never changes, with its stage and per cent shown and
// a Cancel; closing the dialog cancels a run and waits for it to end. A failure (an engine not
// installed, a mesh or solver error, a cancelled run) is said in the dialog.
class SolidCheckDialog : public QDialog {
    Q_OBJECT
public:
    // `operation`: the set-up checked first, of a project of several (docs/operations.md).
    explicit SolidCheckDialog(const Project &project, int operation = 0, QWidget *parent = nullptr);
    ~SolidCheckDialog() override;

    SolidCheckDialog(const SolidCheckDialog &) = delete;
    SolidCheckDialog &operator=(const SolidCheckDialog &) = delete;

    // Starts the check with the stations, mesh size and operation chosen (nothing while one runs).
    void run();
    // Asks a running check to stop; it ends at its next progress report (within a fraction of a second).
    void cancel();
    [[nodiscard]] bool isRunning() const;

    [[nodiscard]] QSpinBox *stationsBox() const { return m_stations; }

    [[nodiscard]] LengthSpinBox *meshSizeBox() const { return m_meshSize; }

    [[nodiscard]] QComboBox *operationBox() const { return m_operation; }

    [[nodiscard]] QPushButton *runButton() const { return m_run; }

    [[nodiscard]] QPushButton *cancelButton() const { return m_cancel; }

    [[nodiscard]] SolidCheckView *view() const { return m_view; }

    // What the dialog says of the last run: done, or why it gave no result.
    [[nodiscard]] QString messageText() const;
    [[nodiscard]] QString progressText() const;

    // The mesh size the check uses when none is chosen, for the operation chosen.
    [[nodiscard]] double defaultMeshSize_mm() const;

    // Cancels a running check and waits for it to end, then closes (Close, Escape, the window's ×).
    void reject() override;

Q_SIGNALS:
    void checkFinished(); // a run ended: with a result, a failure, or cancelled

private:
    void buildLayout();
    [[nodiscard]] QWidget *buildControls();
    void operationChosen();
    void setRunning(bool running);
    void showProgress();
    void runFinished();
    void showFailure(const SolidCheckResult &result);
    void waitForRun();

    Project m_project; // a copy: the check never touches the document
    QComboBox *m_operation;
    QSpinBox *m_stations;
    LengthSpinBox *m_meshSize;
    QLabel *m_meshHint;
    QPushButton *m_run;
    QPushButton *m_cancel;
    QProgressBar *m_progress;
    QLabel *m_message;
    SolidCheckView *m_view;
    QFutureWatcher<SolidCheckResult> m_watcher;
    QTimer m_poll; // shows the worker's progress on the GUI thread
    std::shared_ptr<SolidCheckRunState> m_state;
    int m_runOperation = 0;
};

} // namespace tolturn
