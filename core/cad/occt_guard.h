// SPDX-License-Identifier: GPL-3.0-or-later
// Private to core/cad: OpenCascade's data exchange keeps global state (Interface_Static
// parameters such as the unit of the transferred shapes, the static controllers of STEP and
// IGES), so every use of a reader or a writer holds this lock.
#pragma once

#include "core/common/progress.h"

#include <Message_Gravity.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>
#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace tolturn::cad {

[[nodiscard]] std::mutex &occtMutex();

// Runs `work` with OpenCascade's signal handlers set (OSD::SetSignal with OCC_CATCH_SIGNALS), so
// that an invalid memory access inside OpenCascade, as a malformed file can cause in its
// translators, is thrown from here as a Standard_Failure (OSD_SIGSEGV, ...) instead of ending the
// process. The handlers the process had are restored afterwards. What `work` had on its stack at
// the fault is not destroyed (OpenCascade jumps out with longjmp): hold locks outside it.
void runGuarded(const std::function<void()> &work);

// While alive (and while the lock is held), OpenCascade's default messenger prints failures only:
// its readers and writers print transfer statistics to standard output, which would mix with
// the CLI's results (JSON). The previous trace levels are restored afterwards.
class QuietMessages {
public:
    QuietMessages();
    ~QuietMessages();
    QuietMessages(const QuietMessages &) = delete;
    QuietMessages &operator=(const QuietMessages &) = delete;

private:
    std::vector<Message_Gravity> m_levels;
};

// While alive (and while the lock is held), the Interface_Static parameter `name` (a global of
// OpenCascade's data exchange, such as "xstep.cascade.unit") has `value`; its previous value is
// restored afterwards, so TolTurn leaves no setting behind for another user of OpenCascade in the
// process. Not restored when runGuarded() jumps out of a fault, which skips destructors.
class StaticSetting {
public:
    StaticSetting(const char *name, const char *value);
    ~StaticSetting();
    StaticSetting(const StaticSetting &) = delete;
    StaticSetting &operator=(const StaticSetting &) = delete;

    // false when OpenCascade knows no such parameter or refused the value.
    [[nodiscard]] bool applied() const { return m_applied; }

private:
    std::string m_name;
    std::string m_previous;
    bool m_applied = false;
};

// Passes OpenCascade's progress (Message_ProgressRange, 7.5 and later) on to a part of the
// import's progress (as Mayo's OccProgressIndicator does), and its stop back to OpenCascade.
class ProgressBridge : public Message_ProgressIndicator {
public:
    explicit ProgressBridge(Progress part) : m_part(std::move(part)) {}

    Standard_Boolean UserBreak() override { return m_part.stopped(); }

    void Show(const Message_ProgressScope & /*scope*/, const Standard_Boolean /*force*/) override
    {
        (void)m_part.report(GetPosition());
    }

    [[nodiscard]] bool cancelled() const { return m_part.stopped(); }

private:
    Progress m_part;
};

} // namespace tolturn::cad
