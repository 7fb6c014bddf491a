// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the CSV readers of measured data: the test bar of the stiffness fit and the
// measured cutting forces. The first byte chooses the reader.
#include "core/deviation/stiffness_calibration.h"
#include "core/io/force_measurements.h"

#include <QString>

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const QString text = QString::fromUtf8(reinterpret_cast<const char *>(data) + 1, static_cast<qsizetype>(size - 1));
    if (data[0] % 2 == 0)
        (void)tolturn::parseTestBarMeasurements(text, QStringLiteral("fuzz.csv"));
    else
        (void)tolturn::parseForceMeasurements(text, QStringLiteral("fuzz.csv"));
    return 0;
}
