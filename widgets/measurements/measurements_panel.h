// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/learning/machine_learning.h"
#include "core/measurements/measurement_store.h"
#include "core/project/project.h"

#include <QWidget>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTableView;
class QTimer;

namespace tolturn {

class LinePlot;
class MeasuredPartsModel;

// The Measurements dock (docs/learning.md): the measured parts of the open project's machine (or
// of every machine) in the measurement store, filtered as typed; a part added by typing it in or
// from CSV, removed, exported; the selected part measured against the physics and against physics
// + what was learned, along z; Learn in the background with progress and cancel; the model's
// quality; and the switch that makes the window's predictions use what was learned.
//
// Every store access runs in a worker thread on a connection of its own (a Qt SQL connection
// belongs to the thread that opened it), so a long history or an unreachable shop database never
// blocks the window; an unreachable database is named, and the local store offered instead.
class MeasurementsPanel : public QWidget {
    Q_OBJECT
public:
    explicit MeasurementsPanel(QWidget *parent = nullptr);
    ~MeasurementsPanel() override;

    void setStoreLocation(const StoreLocation &location);

    [[nodiscard]] const StoreLocation &storeLocation() const { return m_location; }

    // The open project (none: nullptr): its machine scopes the list and the model, and a part
    // typed in keeps it as the snapshot it was cut from.
    void setProject(const Project *project);

    // The name a new part's "measured by" starts with (the planner of the preferences).
    void setDefaultMeasuredBy(const QString &name) { m_measuredBy = name; }

    // The newest model of the project's machine, when the planner switched it on; else null.
    [[nodiscard]] std::shared_ptr<const LoadedModel> activeModel() const;

    [[nodiscard]] std::shared_ptr<const LoadedModel> model() const { return m_model; }

    [[nodiscard]] bool useLearned() const;
    void setUseLearned(bool use);

    // Non-interactive forms of the buttons (the buttons ask first, then call these); each runs in
    // the background and ends with operationFinished(ok, message).
    void addPart(const MeasuredPart &part);
    void removeParts(const std::vector<qint64> &ids);
    void exportParts(const std::vector<qint64> &ids, const QString &path);
    void learn();
    void cancelLearning();
    // Lists again with the current filter.
    void reload();
    void setFilterText(const QString &text);
    void setAllMachines(bool all);
    // Shows part `id` against the predictions (as selecting its row does).
    void comparePart(qint64 id);

    [[nodiscard]] MeasuredPartsModel *partsModel() const { return m_parts; }

    [[nodiscard]] LinePlot *plot() const { return m_plot; }

    [[nodiscard]] QString statusText() const;
    [[nodiscard]] QString modelText() const;

    [[nodiscard]] bool isLearning() const { return m_learning != nullptr; }

Q_SIGNALS:
    // The model of the project's machine changed, or the switch: the predictions are to be redone.
    void learnedModelChanged();
    void listingFinished(bool ok);
    void operationFinished(bool ok, const QString &message);
    void learningFinished(bool ok, const QString &message);
    void comparisonShown(bool ok);

private:
    struct LearningState {
        std::atomic<bool> cancel{false};
        std::atomic<int> done{0};
        std::atomic<int> total{0};
    };

    void buildUi();
    void startListing();
    void loadModel();
    void showModel();
    void showStoreError(const QString &error);
    void updateButtons();
    [[nodiscard]] std::vector<qint64> selectedIds() const;
    [[nodiscard]] QString machineId() const;
    // The entry dialog; with `typed`, filled with a part the store refused.
    void promptAdd(const std::optional<MeasuredPart> &typed = std::nullopt);
    void promptRemove();
    void promptExport();
    void useLocalStore();
    void showComparison(const MeasuredPart &part, const PartComparison &comparison, const LoadedModel *model);
    void finishLearning(const MachineLearning &run, const std::optional<LoadedModel> &kept, const QString &error);

    StoreLocation m_location;
    std::optional<Project> m_project;
    QString m_measuredBy;
    std::optional<MeasuredPart> m_typedPart; // typed in the dialog, until the store has it
    std::shared_ptr<const LoadedModel> m_model;
    quint64 m_listGeneration = 0;
    quint64 m_modelGeneration = 0;
    quint64 m_compareGeneration = 0;
    std::shared_ptr<LearningState> m_learning;
    QString m_storeError;
    qint64 m_total = 0;

    QLabel *m_store = nullptr;
    QPushButton *m_useLocal = nullptr;
    QComboBox *m_scope = nullptr;
    QLineEdit *m_filter = nullptr;
    QTimer *m_filterDelay = nullptr;
    QTableView *m_view = nullptr;
    MeasuredPartsModel *m_parts = nullptr;
    QPushButton *m_add = nullptr;
    QPushButton *m_remove = nullptr;
    QPushButton *m_export = nullptr;
    QLabel *m_modelLabel = nullptr;
    QPushButton *m_learn = nullptr;
    QPushButton *m_cancel = nullptr;
    QProgressBar *m_progress = nullptr;
    QTimer *m_progressPoll = nullptr;
    QCheckBox *m_use = nullptr;
    LinePlot *m_plot = nullptr;
    QLabel *m_comparisonNote = nullptr;
};

} // namespace tolturn
