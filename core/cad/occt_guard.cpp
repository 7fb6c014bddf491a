// SPDX-License-Identifier: GPL-3.0-or-later
// OCC_CATCH_SIGNALS turns a signal into an exception only where OCC_CONVERT_SIGNALS is defined,
// as OpenCascade itself is built on Linux; before any OpenCascade header.
#ifndef OCC_CONVERT_SIGNALS // OpenCascade's CMake package defines it for its users
#define OCC_CONVERT_SIGNALS
#endif
#include "core/cad/occt_guard.h"

#include <Standard_ErrorHandler.hxx>

#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <OSD.hxx>
#include <array>
#include <csignal>
#include <vector>

namespace tolturn::cad {

std::mutex &occtMutex()
{
    static std::mutex mutex;
    return mutex;
}

namespace {

// The signals OpenCascade's handlers convert (OSD::SetSignal, OSD_signal.cxx for POSIX).
constexpr std::array<int, 4> kConvertedSignals{SIGSEGV, SIGBUS, SIGFPE, SIGILL};

// The handlers run on a stack of their own: a translator that recurses without end (STEP reads an
// ORIENTED_EDGE whose edge is itself by recursion, in IFSelect_WorkSession::SetModel) overflows
// the thread's stack, and a handler on that stack could not even start; the kernel would end the
// process. 256 KiB is ample for OpenCascade's handler, which builds the failure and jumps out.
constexpr std::size_t kSignalStackBytes = std::size_t{256} * 1024;

// This thread's alternate signal stack while alive; the previous one restored afterwards.
class SignalStack {
public:
    SignalStack() : m_memory(kSignalStackBytes)
    {
        stack_t own{};
        own.ss_sp = m_memory.data();
        own.ss_size = m_memory.size();
        m_set = sigaltstack(&own, &m_previous) == 0;
    }

    ~SignalStack()
    {
        if (m_set)
            sigaltstack(&m_previous, nullptr);
    }

    SignalStack(const SignalStack &) = delete;
    SignalStack &operator=(const SignalStack &) = delete;

private:
    std::vector<char> m_memory;
    stack_t m_previous{};
    bool m_set = false;
};

// OpenCascade's handler for `signal`, run on the alternate stack.
void runOnSignalStack(int signal)
{
    struct sigaction action {};

    if (sigaction(signal, nullptr, &action) == 0) {
        action.sa_flags |= SA_ONSTACK;
        sigaction(signal, &action, nullptr);
    }
}

} // namespace

void runGuarded(const std::function<void()> &work)
{
    std::array<struct sigaction, kConvertedSignals.size()> previous{};
    for (std::size_t i = 0; i < kConvertedSignals.size(); ++i)
        sigaction(kConvertedSignals[i], nullptr, &previous[i]);
    const SignalStack signalStack;
    // Without floating-point traps: an overflow inside OpenCascade is its own affair.
    OSD::SetSignal(OSD_SignalMode_Set, Standard_False);
    runOnSignalStack(SIGSEGV);
    runOnSignalStack(SIGBUS);

    struct Restore {
        const std::array<struct sigaction, kConvertedSignals.size()> &handlers;

        ~Restore()
        {
            for (std::size_t i = 0; i < kConvertedSignals.size(); ++i)
                sigaction(kConvertedSignals[i], &handlers[i], nullptr);
        }
    } restore{previous};

    OCC_CATCH_SIGNALS
    work();
}

QuietMessages::QuietMessages()
{
    for (const Handle(Message_Printer) & printer : Message::DefaultMessenger()->Printers()) {
        m_levels.push_back(printer->GetTraceLevel());
        printer->SetTraceLevel(Message_Fail);
    }
}

QuietMessages::~QuietMessages()
{
    std::size_t i = 0;
    for (const Handle(Message_Printer) & printer : Message::DefaultMessenger()->Printers()) {
        if (i < m_levels.size())
            printer->SetTraceLevel(m_levels[i++]);
    }
}

StaticSetting::StaticSetting(const char *name, const char *value) : m_name(name)
{
    if (!Interface_Static::IsPresent(name))
        return;
    // An enumeration's CVal is the name of its current value ("MM"), which SetCVal takes back.
    const char *previous = Interface_Static::CVal(name);
    m_previous = previous ? previous : "";
    m_applied = Interface_Static::SetCVal(name, value);
}

StaticSetting::~StaticSetting()
{
    if (m_applied)
        Interface_Static::SetCVal(m_name.c_str(), m_previous.c_str());
}

} // namespace tolturn::cad
