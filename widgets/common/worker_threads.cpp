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
        return p;
    }();
    return pool;
}

} // namespace tolturn
