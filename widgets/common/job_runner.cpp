// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/common/job_runner.h"

namespace tolturn {

JobRunner::JobRunner(QObject *parent) : QObject(parent) {}

JobRunner::~JobRunner()
{
    m_progress.stop();
    std::unique_lock lock(m_gate->mutex);
    m_gate->closed = true;
    m_gate->idle.wait(lock, [this] { return m_gate->running == 0; });
}

bool JobRunner::Gate::enter()
{
    const std::lock_guard lock(mutex);
    if (closed)
        return false;
    ++running;
    return true;
}

void JobRunner::Gate::leave()
{
    const std::lock_guard lock(mutex);
    --running;
    idle.notify_all();
}

void JobRunner::cancel()
{
    m_progress.stop();
}

Progress JobRunner::beginJob(const std::shared_ptr<Job> &job)
{
    m_progress.stop(); // the job this one replaces
    m_currentJob = job;
    m_running = true;
    // The observer runs on the worker: it keeps the fraction and queues one update at a time.
    m_progress = Progress([this, job](double fraction) {
        job->fraction.store(fraction);
        if (!job->updateQueued.exchange(true))
            QMetaObject::invokeMethod(
                this, [this, job] { showProgress(job); }, Qt::QueuedConnection);
        return true;
    });
    return m_progress;
}

void JobRunner::showProgress(const std::shared_ptr<Job> &job)
{
    job->updateQueued.store(false);
    if (m_running && job == m_currentJob) // not an older job's late report
        Q_EMIT progressChanged(job->fraction.load());
}

bool JobRunner::endJob(const std::shared_ptr<Job> &job)
{
    if (job != m_currentJob)
        return false;
    m_running = false;
    return true;
}

void JobRunner::jobFailed(const std::shared_ptr<Job> &job, const QString &what)
{
    if (!endJob(job))
        return;
    Q_EMIT failed(what);
    Q_EMIT finished();
}

} // namespace tolturn
