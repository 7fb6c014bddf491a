// SPDX-License-Identifier: GPL-3.0-or-later
// The window's runner of background jobs: results on the window's thread, progress coalesced,
// cancel through the job's Progress, a newer job replacing an older one, no job outliving it.
#include "widgets/common/job_runner.h"

#include <QCoreApplication>
#include <QSignalSpy>
#include <QTest>
#include <QThread>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>

#include <chrono>
#include <future>
#include <memory>
#include <stdexcept>
#include <thread>

using namespace tolturn;

namespace {

// A job that reports until it is stopped, or gives up after ten seconds: "stopped" or "ran out".
QString runUntilStopped(const Progress &progress)
{
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < end) {
        if (!progress.report(0.5))
            return QStringLiteral("stopped");
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return QStringLiteral("ran out");
}

} // namespace

class TestJobRunner : public QObject {
    Q_OBJECT
private Q_SLOTS:

    void deliversTheResultOnTheRunnersThread()
    {
        JobRunner runner;
        QSignalSpy finished(&runner, &JobRunner::finished);
        QThread *workThread = nullptr;
        QThread *doneThread = nullptr;
        int result = 0;
        runner.start(
            [&workThread](const Progress &) {
                workThread = QThread::currentThread();
                return 6 * 7;
            },
            [&](int r) {
                doneThread = QThread::currentThread();
                result = r;
                QVERIFY(!runner.isRunning()); // over when its result is handed over
            });
        QVERIFY(runner.isRunning());
        QVERIFY(finished.wait(10000));
        QCOMPARE(result, 42);
        QCOMPARE(doneThread, QThread::currentThread());
        QVERIFY(workThread != QThread::currentThread());
        QVERIFY(!runner.isRunning());
    }

    // Every report made while one update waits is folded into it: the window sees the latest.
    void foldsProgressIntoOneUpdateAtATime()
    {
        JobRunner runner;
        QSignalSpy progress(&runner, &JobRunner::progressChanged);
        QSignalSpy finished(&runner, &JobRunner::finished);
        std::promise<void> worked;
        runner.start(
            [&worked](const Progress &p) {
                for (int i = 1; i <= 1000; ++i)
                    (void)p.report(i / 1000.0);
                worked.set_value();
                return 0;
            },
            [](int) {});
        worked.get_future().wait(); // no event loop ran meanwhile: one update was queued
        QVERIFY(finished.wait(10000));
        QCOMPARE(progress.count(), 1);
        QCOMPARE(progress.constFirst().constFirst().toDouble(), 1.0);
    }

    void cancelStopsTheJobWhichStillDelivers()
    {
        JobRunner runner;
        QSignalSpy finished(&runner, &JobRunner::finished);
        QString result;
        runner.start(runUntilStopped, [&result](const QString &r) { result = r; });
        runner.cancel();
        QVERIFY(finished.wait(20000));
        QCOMPARE(result, QStringLiteral("stopped"));
    }

    void aNewerJobReplacesTheOlder()
    {
        JobRunner runner;
        QSignalSpy finished(&runner, &JobRunner::finished);
        int olderDone = 0;
        QString newer;
        runner.start(runUntilStopped, [&olderDone](const QString &) { ++olderDone; });
        runner.start([](const Progress &) { return QStringLiteral("newer"); },
                     [&newer](const QString &r) { newer = r; });
        QVERIFY(finished.wait(20000));
        QCOMPARE(newer, QStringLiteral("newer"));
        QVERIFY(workerThreads()->waitForDone(20000)); // the older job has ended too …
        QCoreApplication::sendPostedEvents();
        QCOMPARE(olderDone, 0); // … and its result was dropped
        QCOMPARE(finished.count(), 1);
    }

    // The runner's end stops its running job and waits for it; the result goes nowhere.
    void aJobDoesNotOutliveItsRunner()
    {
        auto ended = std::make_shared<QString>(); // the job's own result, kept by the job
        std::promise<void> started;
        int done = 0;
        {
            JobRunner runner;
            runner.start(
                [ended, &started](const Progress &p) {
                    started.set_value();
                    *ended = runUntilStopped(p);
                    return *ended;
                },
                [&done](const QString &) { ++done; });
            started.get_future().wait();
        }
        QCOMPARE(*ended, QStringLiteral("stopped"));
        QCoreApplication::sendPostedEvents();
        QCOMPARE(done, 0);
    }

    // A job that throws ends with failed(), saying what it threw; its `done` is not called.
    void aJobThatThrowsFails()
    {
        JobRunner runner;
        QSignalSpy failed(&runner, &JobRunner::failed);
        QSignalSpy finished(&runner, &JobRunner::finished);
        int done = 0;
        runner.start([](const Progress &) -> int { throw std::runtime_error("out of memory in the mesh"); },
                     [&done](int) { ++done; });
        QVERIFY(finished.wait(10000));
        QCOMPARE(failed.count(), 1);
        QCOMPARE(failed.constFirst().constFirst().toString(), QStringLiteral("out of memory in the mesh"));
        QCOMPARE(done, 0);
        QVERIFY(!runner.isRunning());
    }

    // At quit the pool drops the jobs that have not started (worker_threads.cpp): the runner's end
    // does not wait for one of them.
    void aDroppedJobDoesNotHoldTheRunner()
    {
        std::promise<void> open;
        const std::shared_future<void> gate = open.get_future().share();
        for (int i = 0; i < 2; ++i) // both workers busy: the job waits in the queue
            (void)QtConcurrent::run(workerThreads(), [gate] { gate.wait(); });
        int done = 0;
        {
            JobRunner runner;
            runner.start([](const Progress &) { return 1; }, [&done](int) { ++done; });
            workerThreads()->clear(); // as at quit
            open.set_value();
        } // returns: nothing to wait for
        QVERIFY(workerThreads()->waitForDone(20000));
        QCoreApplication::sendPostedEvents();
        QCOMPARE(done, 0);
    }
};

QTEST_GUILESS_MAIN(TestJobRunner)
#include "tst_job_runner.moc"
