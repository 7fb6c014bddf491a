// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"

#include <QString>

#include <optional>

namespace tolturn {

// An indexable insert decoded from its ISO 1832 designation, e.g. "CNMG 120408":
// C shape (80° rhombic), N clearance (0°), M tolerance class, G type, 12 cutting-edge length,
// 04 thickness (4.76 mm), 08 corner radius (0.8 mm). Positions 8 and 9 (edge condition, hand)
// and a maker's chip-breaker suffix are accepted and kept as text.
struct InsertGeometry {
    QString code;              // normalised "CNMG 120408"
    QChar shape;               // position 1
    double includedAngle_deg;  // corner angle of the shape; 0 for round inserts
    QChar clearanceLetter;     // position 2
    double clearanceAngle_deg; // normal clearance; negative inserts have 0
    QChar toleranceClass;      // position 3
    QChar type;                // position 4 (hole and chip-breaker form)
    double edgeLength_mm;      // position 5, nominal (exact from the inscribed circle)
    double inscribedCircle_mm; // IC
    double thickness_mm;       // position 6
    double noseRadius_mm;      // position 7; 0 for a sharp corner or a round insert
    QString suffix;            // positions 8–9 and the maker's suffix
};

struct InsertParseResult {
    std::optional<InsertGeometry> insert;
    Diagnostics diagnostics;
};

// Decodes a designation. The letter tables are those of ISO 1832:2017 (Indexable inserts for
// cutting tools — Designation), clauses 4.1–4.7. A malformed code gives one error naming the
// position, what it encodes and the characters found.
[[nodiscard]] InsertParseResult parseInsertCode(const QString &code,
                                                const QString &field = QStringLiteral("tool.insert"));

} // namespace tolturn
