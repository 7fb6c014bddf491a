// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/progress.h"
#include "widgets/common/worker_threads.h"

#include <QMetaObject>
#include <QObject>
#include <QString>
#include <QThread>
#include <QtConcurrent/QtConcurrentRun>

#include <atomic>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <type_traits>
#include <utility>

namespace tolturn {

// Runs the desktop program's long computations on workerThreads() and hands their results back on
// the thread the runner lives in (EXAMPLES.md item 2, after hotspot's JobTracker). One job at a
// time: a job started while another runs replaces it; the older one is stopped and its result
// dropped. The job's Progress reaches the window as progressChanged(), at most one update waiting
// at a time, so a job that reports often does not flood the event loop; nothing here ever runs the
// event loop itself. Cancel stops the job through its Progress: the job returns what it has (a
// result marked cancelled), which is delivered like any other.
class JobRunner : public QObject {
    Q_OBJECT
public:
    explicit JobRunner(QObject *parent = nullptr);
    // Stops the jobs still running and waits for them: a job never outlives what it reports to. A
    // job that has not started yet (the pool is cleared at quit) never will.
    ~JobRunner() override;

    JobRunner(const JobRunner &) = delete;
    JobRunner &operator=(const JobRunner &) = delete;

    // From start() until the job's `done` is called (or failed() is emitted).
    [[nodiscard]] bool isRunning() const { return m_running; }

    // Asks the running job to stop; it still ends through its `done`.
    void cancel();

    // Runs `work(const Progress &)` on a worker thread; `done(result)` then runs on this object's
    // thread, unless a newer job has replaced this one or the runner is gone. `work` must not touch
    // anything the window owns: give it copies.
    template <class Work, class Done>
    void start(Work work, Done done);

Q_SIGNALS:
    void progressChanged(double fraction);
    // The job threw instead of returning (`what` says what it threw); `done` is not called.
    void failed(const QString &what);
    // After a job's `done` has run, or after failed() (isRunning() is false again).
    void finished();

private:
    struct Job {
        std::atomic<double> fraction{0.0};
        std::atomic<bool> updateQueued{false};
    };

    // The jobs that run on the workers, which the destructor waits for, and whether the runner
    // still takes their reports.
    struct Gate {
        std::mutex mutex;
        std::condition_variable idle;
        int running = 0;
        bool closed = false;
        // True, and counted, unless the runner is gone.
        [[nodiscard]] bool enter();
        void leave();
    };

    // A new job: the older one stopped, a Progress whose reports become progressChanged().
    [[nodiscard]] Progress beginJob(const std::shared_ptr<Job> &job);
    void showProgress(const std::shared_ptr<Job> &job);
    // Whether `job` is still the current one; ends it when so.
    [[nodiscard]] bool endJob(const std::shared_ptr<Job> &job);
    void jobFailed(const std::shared_ptr<Job> &job, const QString &what);

    std::shared_ptr<Job> m_currentJob;
    bool m_running = false;
    Progress m_progress; // the current job's, which cancel() stops
    std::shared_ptr<Gate> m_gate = std::make_shared<Gate>();
};

template <class Work, class Done>
void JobRunner::start(Work work, Done done)
{
    using Result = std::invoke_result_t<Work &, const Progress &>;
    auto job = std::make_shared<Job>();
    const Progress progress = beginJob(job);
    // Not waited for through its QFuture: a job the pool drops before it starts never finishes one.
    (void)QtConcurrent::run(workerThreads(), [this, gate = m_gate, job, progress, work = std::move(work),
                                              done = std::move(done)]() mutable {
        if (!gate->enter())
            return; // the runner is gone: nothing to report to
        try {
            auto result = std::make_shared<Result>(work(progress));
            // Queued: the runner waits for this job before it goes, and drops its pending calls.
            QMetaObject::invokeMethod(
                this,
                [this, job, result, done = std::move(done)]() mutable {
                    Q_ASSERT(QThread::currentThread() == thread());
                    if (!endJob(job))
                        return; // replaced by a newer job
                    done(std::move(*result));
                    Q_EMIT finished();
                },
                Qt::QueuedConnection);
        } catch (const std::exception &e) {
            QMetaObject::invokeMethod(
                this, [this, job, what = QString::fromLocal8Bit(e.what())] { jobFailed(job, what); },
                Qt::QueuedConnection);
        } catch (...) {
            QMetaObject::invokeMethod(
                this, [this, job] { jobFailed(job, QStringLiteral("unknown exception")); }, Qt::QueuedConnection);
        }
        gate->leave();
    });
}

} // namespace tolturn
