// SPDX-License-Identifier: GPL-3.0-or-later
// OCC_CATCH_SIGNALS turns a signal into an exception only where OCC_CONVERT_SIGNALS is defined,
// as OpenCascade itself is built on Linux; before any OpenCascade header.
#define OCC_CONVERT_SIGNALS
#include "core/cad/occt_guard.h"

#include <Standard_ErrorHandler.hxx>

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <OSD.hxx>
#include <array>
#include <csignal>

namespace tolturn::cad {

std::mutex &occtMutex()
{
    static std::mutex mutex;
    return mutex;
}

namespace {

// The signals OpenCascade's handlers convert (OSD::SetSignal, OSD_signal.cxx for POSIX).
constexpr std::array<int, 4> kConvertedSignals{SIGSEGV, SIGBUS, SIGFPE, SIGILL};

} // namespace

void runGuarded(const std::function<void()> &work)
{
    std::array<struct sigaction, kConvertedSignals.size()> previous{};
    for (std::size_t i = 0; i < kConvertedSignals.size(); ++i)
        sigaction(kConvertedSignals[i], nullptr, &previous[i]);
    // Without floating-point traps: an overflow inside OpenCascade is its own affair.
    OSD::SetSignal(OSD_SignalMode_Set, Standard_False);

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

} // namespace tolturn::cad
