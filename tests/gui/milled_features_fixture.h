// SPDX-License-Identifier: GPL-3.0-or-later
// The milled features the GUI tests put on a part (issue 19, docs/milling.md): a flat milled with
// seed 001's tool in its holder (table 3: Ø12 mm, 2 flutes, 30° helix, k = 6306 N/mm,
// k_θ = 1.656·10⁷ N·mm/rad), force coefficients made up for the tests, flatness 3 µm; and a keyway
// as the STEP import leaves it, with its place on the part only.
#pragma once

#include "core/project/milled_feature.h"

#include <QString>

#include <optional>
#include <vector>

namespace tolturn::test {

inline std::vector<MilledFeature> flatAndImportedKeyway(const QString &coefficientsSource)
{
    MilledFeature flat;
    flat.id = QStringLiteral("M1");
    flat.zFrom_mm = 10.0;
    flat.zTo_mm = 30.0;
    flat.tool = BallEndTool{12.0, 2, 30.0, 40.0, 9.6, std::nullopt, 6306.0, 1.656e7};
    flat.conditions =
        MillingConditions{BallEndCutKind::StepOver, MillingDirection::Down, 0.5, 1.0, 0.05, 3000.0, 10.0, 0.0};
    flat.coefficients = MillingForceCoefficients{2000.0, 700.0, 400.0, 25.0, 40.0, 8.0};
    flat.coefficientsSource = coefficientsSource;
    flat.tolerance = MilledTolerance{MilledToleranceType::Flatness, 3.0, {}};
    MilledFeature keyway;
    keyway.id = QStringLiteral("M2");
    keyway.kind = MilledFeatureKind::Keyway;
    keyway.zFrom_mm = 40.0;
    keyway.zTo_mm = 60.0;
    return {flat, keyway};
}

} // namespace tolturn::test
