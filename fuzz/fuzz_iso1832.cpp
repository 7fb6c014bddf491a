// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: ISO 1832 insert designations ("CNMG 120408").
#include "core/tooling/iso1832.h"

#include <QString>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QString text = QString::fromUtf8(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size));
    const tolturn::InsertParseResult r = tolturn::parseInsertCode(text);
    if (r.insert && (!std::isfinite(r.insert->noseRadius_mm) || r.insert->noseRadius_mm < 0.0))
        std::abort();
    return 0;
}
