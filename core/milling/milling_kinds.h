// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The kinds of a ball-end cut (Öztürk & Budak, seed 001 §2.2), apart from the model's Eigen types so
// that a project can name them (core/project/milled_feature.h).

namespace tolturn {

// Down milling: the tooth leaves the cut at the finished surface; up milling: it enters there.
enum class MillingDirection { Down, Up };

// What the ball cuts into (001 §2.2): a slot as wide as the ball at the axial depth, the side of
// uncut material at radial depth s (table 1), or the step-over s beside a previous pass (table 2).
enum class BallEndCutKind { Slot, SideCut, StepOver };

} // namespace tolturn
