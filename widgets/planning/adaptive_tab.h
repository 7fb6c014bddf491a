// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/adaptive/project_control.h"
#include "core/learning/machine_learning.h"
#include "core/planning/feed_schedule.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QTableWidget;

namespace tolturn {

class LinePlot;

// The Planning dock's Adaptive tab (docs/adaptive.md): a pass of the plan simulated under the
// constant-force loop against the programmed feed, its force, feed, deviation or roughness along
// the part; and the feed schedule of the finishing pass, feature by feature, with the time it
// saves. Both take milliseconds and are computed when the project changes.
class AdaptiveTab : public QWidget {
    Q_OBJECT
public:
    explicit AdaptiveTab(QWidget *parent = nullptr);

    // The project of the operation planned and what was learned of its machine (may be null).
    void setProject(const Project &project, std::shared_ptr<const LoadedModel> learned);
    void clear(const QString &why);

    [[nodiscard]] const FeedSchedule &schedule() const { return m_schedule; }

    [[nodiscard]] const ProjectControlResult &control() const { return m_control; }

    [[nodiscard]] LinePlot *plot() const { return m_plot; }

    [[nodiscard]] QTableWidget *scheduleTable() const { return m_table; }

    [[nodiscard]] QLabel *controlSummary() const { return m_controlSummary; }

    [[nodiscard]] QLabel *scheduleSummary() const { return m_scheduleSummary; }

    [[nodiscard]] QComboBox *passChoice() const { return m_pass; }

    [[nodiscard]] QComboBox *quantityChoice() const { return m_quantity; }

private:
    void simulate();
    void showRun();
    void showSchedule();

    Project m_project;
    std::shared_ptr<const LoadedModel> m_learned;
    bool m_hasProject = false;
    ProjectControlResult m_control;
    FeedSchedule m_schedule;
    double m_constantTime_s = 0.0;
    double m_scheduledTime_s = 0.0;
    QComboBox *m_pass;
    QComboBox *m_quantity;
    QDoubleSpinBox *m_noise;
    LinePlot *m_plot;
    QLabel *m_controlSummary;
    QTableWidget *m_table;
    QLabel *m_scheduleSummary;
};

} // namespace tolturn
