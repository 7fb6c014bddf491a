// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/common/progress.h"

#include <algorithm>
#include <utility>

namespace tolturn {

Progress::Progress() : m_task(std::make_shared<Task>()) {}

Progress::Progress(Observer observer) : m_task(std::make_shared<Task>())
{
    m_task->observer = std::move(observer);
}

Progress::Progress(const Progress &parent, double from, double to)
    : m_task(parent.m_task)
    , m_from(parent.m_from + (parent.m_to - parent.m_from) * from)
    , m_to(parent.m_from + (parent.m_to - parent.m_from) * to)
{
}

bool Progress::report(double fraction) const
{
    if (m_task->stopped.load())
        return false;
    const double whole = m_from + (m_to - m_from) * std::clamp(fraction, 0.0, 1.0);
    if (m_task->observer && !m_task->observer(whole))
        stop();
    return !m_task->stopped.load();
}

void Progress::stop() const
{
    m_task->stopped.store(true);
}

bool Progress::stopped() const
{
    return m_task->stopped.load();
}

} // namespace tolturn
