// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: ISO 286 designations as people write them ("Ø50 H7/g6") and their limits.
#include "core/tolerance/iso286.h"

#include <QString>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QString text = QString::fromUtf8(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size));
    const tolturn::iso286::DesignationLimits r = tolturn::iso286::evaluate(text, 50.0);
    // Limits that are given are numbers: upper above lower, both finite.
    if (r.limits && (!std::isfinite(r.limits->upper_um) || !std::isfinite(r.limits->lower_um) ||
                     r.limits->upper_um < r.limits->lower_um))
        std::abort();
    return 0;
}
