// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <atomic>
#include <functional>
#include <memory>

namespace tolturn {

// The progress of one task, from 0 to 1, and the request to stop it (EXAMPLES.md item 1, after
// Mayo's TaskProgress). A task gives each of its steps a part of its own range, Progress(parent,
// from, to); a step reports 0 … 1 of its part and learns from the answer whether to go on. One
// observer sees the whole task's fraction; the stop, asked by the observer (returning false) or by
// stop() from any thread, holds for every part. A copy is the same task: cheap to pass by value.
class Progress {
public:
    // false: stop the task. Called on the thread that reports, which may be a worker's.
    using Observer = std::function<bool(double fraction)>;

    // Nobody watches; the task runs to its end unless stop() is called.
    Progress();
    explicit Progress(Observer observer);
    // The part [from, to] (fractions of `parent`'s own range) of `parent`'s task.
    Progress(const Progress &parent, double from, double to);

    // `fraction` (0 … 1) of this part is done; false once the task is to stop.
    [[nodiscard]] bool report(double fraction) const;
    // Asks the task to stop, from any thread.
    void stop() const;
    [[nodiscard]] bool stopped() const;

private:
    struct Task {
        Observer observer;
        std::atomic<bool> stopped{false};
    };

    std::shared_ptr<Task> m_task;
    double m_from = 0.0; // this part's range in the whole task's
    double m_to = 1.0;
};

} // namespace tolturn
