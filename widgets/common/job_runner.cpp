// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/common/job_runner.h"

#include <algorithm>

namespace tolturn {

JobRunner::JobRunner(QObject *parent) : QObject(parent) {}

JobRunner::~JobRunner()
{
    m_progress.stop();
    waitForJobs();
}

void JobRunner::cancel()
{
    m_progress.stop();
}

Progress JobRunner::beginJob(const std::shared_ptr<Job> &job)
{
    m_progress.stop(); // the job this one replaces
    std::erase_if(m_futures, [](const QFuture<void> &f) { return f.isFinished(); });
    ++m_currentId;
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

bool JobRunner::endJob(unsigned id)
{
    if (id != m_currentId)
        return false;
    m_running = false;
    return true;
}

void JobRunner::waitForJobs()
{
    for (QFuture<void> &f : m_futures)
        f.waitForFinished();
    m_futures.clear();
}

} // namespace tolturn
