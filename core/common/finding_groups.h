// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"

#include <vector>

namespace tolturn {

// Findings that say the same thing of several elements of one array, such as a cutting speed
// below the insert's range on every roughing pass ("passes[0].cutting_speed_m_min" …
// "passes[7].cutting_speed_m_min", one message), told once with the elements they apply to.
struct FindingGroup {
    Diagnostic finding;       // the first of the group, its field as written
    QString array;            // "passes"; empty for a finding whose field does not start with an indexed array
    QString member;           // "cutting_speed_m_min": the field after the index, without the leading '.'
    std::vector<int> indices; // in the order met; empty when `array` is
};

// The findings in their order, each one of a kind (same severity, array, member and message)
// gathered at the place of the first.
[[nodiscard]] std::vector<FindingGroup> groupedByIndex(const Diagnostics &findings);

// "3–7" for three or more consecutive numbers in increasing order, else "3, 5" (or "4").
[[nodiscard]] QString numberList(const std::vector<int> &numbers);

// The group as the CLI prints a finding: "warning: passes[0–7].cutting_speed_m_min: …".
[[nodiscard]] QString groupText(const FindingGroup &group);

} // namespace tolturn
