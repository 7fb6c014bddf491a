// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/part/profile.h"
#include "core/project/project.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace tolturn {

// The words used for enumerations in project files, on the command line and in messages.
// One table per enumeration; keyword() and fromKeyword() are exact inverses.
[[nodiscard]] QString keyword(SegmentKind value);
[[nodiscard]] QString keyword(ArcDirection value);
[[nodiscard]] QString keyword(ClampingMethod value);
[[nodiscard]] QString keyword(PartEnd value);
[[nodiscard]] QString keyword(PassKind value);
[[nodiscard]] QString keyword(ToleranceType value);
[[nodiscard]] QString keyword(ForceModel value);
[[nodiscard]] QString keyword(PlanningObjective value);
[[nodiscard]] QString keyword(MilledFeatureKind value);
[[nodiscard]] QString keyword(MilledToleranceType value);
[[nodiscard]] QString keyword(BallEndCutKind value);
[[nodiscard]] QString keyword(MillingDirection value);

// Names for people, translated: "chuck + tailstock" where the file says "chuck_tailstock".
[[nodiscard]] QString displayName(ClampingMethod value);
[[nodiscard]] QString displayName(PartEnd value); // "left", "right", translated
[[nodiscard]] QString displayName(SegmentKind value);
[[nodiscard]] QString displayName(ToleranceType value);
[[nodiscard]] QString displayName(MilledFeatureKind value); // "flat", "keyway", "surface patch"
[[nodiscard]] QString displayName(BallEndCutKind value);

// The constraints of the cutting-condition optimiser, as named in files, on the command line
// and in results (docs/planning.md): tolerances, roughness, power, torque, force, spindle_speed,
// tool_life, roughing_depth.
[[nodiscard]] const QStringList &planningConstraintKeywords();

template <typename Enum>
[[nodiscard]] std::optional<Enum> fromKeyword(const QString &word);
template <typename Enum>
[[nodiscard]] QStringList allKeywords();

} // namespace tolturn
