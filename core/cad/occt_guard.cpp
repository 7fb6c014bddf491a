// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/cad/occt_guard.h"

namespace tolturn::cad {

std::mutex &occtMutex()
{
    static std::mutex mutex;
    return mutex;
}

} // namespace tolturn::cad
