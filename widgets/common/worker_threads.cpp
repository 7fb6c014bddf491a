// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/common/worker_threads.h"

#include <QCoreApplication>
#include <QThreadPool>

namespace tolturn {

QThreadPool *workerThreads()
{
    static QThreadPool *pool = [] {
        auto *p = new QThreadPool(QCoreApplication::instance());
        p->setMaxThreadCount(2);
        // At quit, work not started yet is dropped: the program ends once what runs has ended.
        QObject::connect(QCoreApplication::instance(), &QCoreApplication::aboutToQuit, p, &QThreadPool::clear);
        return p;
    }();
    return pool;
}

} // namespace tolturn
