// SPDX-License-Identifier: GPL-3.0-or-later
// The progress and cancel type of core (core/common/progress.h): parts of a task's range, nested,
// map onto the whole task's fraction; a stop, asked by the observer or from another thread, holds
// for every part.
#include "core/common/progress.h"

#include <QTest>

#include <thread>
#include <vector>

using namespace tolturn;

class TestProgress : public QObject {
    Q_OBJECT

private Q_SLOTS:

    // Nobody watching: every report is answered "go on".
    void withoutObserverGoesOn()
    {
        const Progress progress;
        QVERIFY(progress.report(0.0));
        QVERIFY(progress.report(1.0));
        QVERIFY(!progress.stopped());
    }

    // A part [0.4, 0.7] of the task and, inside it, a part [0.5, 1] of that: half of the inner
    // part is 0.4 + 0.3 × (0.5 + 0.5 × 0.5) = 0.625 of the task (worked by hand).
    void nestedPartsMapOntoTheWholeTask()
    {
        std::vector<double> seen;
        const Progress task([&seen](double f) {
            seen.push_back(f);
            return true;
        });
        const Progress stage(task, 0.4, 0.7);
        const Progress step(stage, 0.5, 1.0);
        QVERIFY(step.report(0.5));
        QVERIFY(stage.report(1.0));
        QVERIFY(task.report(0.2));
        QVERIFY(step.report(2.0)); // beyond its part: its end, not beyond
        QVERIFY(step.report(-1.0));
        QCOMPARE(seen.size(), std::size_t{5});
        QCOMPARE(seen[0], 0.625);
        QCOMPARE(seen[1], 0.7);
        QCOMPARE(seen[2], 0.2);
        QCOMPARE(seen[3], 0.7);
        QCOMPARE(seen[4], 0.55);
    }

    // The observer's "stop" holds for the whole task: every part, and every report after it.
    void observersStopHoldsForEveryPart()
    {
        int calls = 0;
        const Progress task([&calls](double f) {
            ++calls;
            return f < 0.5;
        });
        const Progress first(task, 0.0, 0.5);
        const Progress second(task, 0.5, 1.0);
        QVERIFY(first.report(0.5));   // 0.25 of the task
        QVERIFY(!second.report(0.2)); // 0.6: stop
        QVERIFY(!first.report(0.0));  // 0.0 again, but stopped
        QVERIFY(task.stopped() && first.stopped() && second.stopped());
        QCOMPARE(calls, 2); // a stopped task does not ask its observer again
    }

    // Cancel from another thread (the GUI's) stops a task running in this one, and its copies.
    void stopFromAnotherThread()
    {
        const Progress task;
        const Progress part(task, 0.0, 0.5);
        std::thread gui([copy = task] { copy.stop(); }); // the GUI holds a copy of the same task
        gui.join();
        QVERIFY(!part.report(0.1));
        QVERIFY(task.stopped());
        // A new task is not stopped.
        QVERIFY(Progress().report(0.1));
    }
};

QTEST_GUILESS_MAIN(TestProgress)
#include "tst_progress.moc"
