// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cad/occt_guard.h"

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>

namespace tolturn::cad {

std::mutex &occtMutex()
{
    static std::mutex mutex;
    return mutex;
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
