// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/common/diagnostic.h"

#include <QString>

class QWidget;

namespace tolturn {

// An editor of one value of the project carries the value's field path, as findings name it
// (Diagnostic::field: "tool.overhang_mm", "passes[1].feed_mm_rev"), so that a finding can be
// shown on the editor and a problem taken to it. An editor of a whole record (the stiffness
// editor: "characterisation") answers for every field under it.
void setProjectField(QWidget &editor, const QString &field);
[[nodiscard]] QString projectField(const QWidget &editor);

// True when `field` is `editorField` or lies under it ("tool" covers "tool.insert" and
// "passes[1]" covers "passes[1].feed_mm_rev", but "tool" does not cover "tooling").
[[nodiscard]] bool fieldCovers(const QString &editorField, const QString &field);

// Marks every editor under `root` that a finding names: red for an error, amber for a warning,
// with the findings' messages after its own tooltip; the others are shown plain again.
void markFindings(QWidget &root, const Diagnostics &findings);

// The visible-or-not editor under `root` whose field covers `field` most closely; null if none.
[[nodiscard]] QWidget *editorForField(QWidget &root, const QString &field);

// Brings `editor` in front (its dock shown and raised, its tab current, scrolled into view) and
// gives it the keyboard focus with its text selected.
void focusEditor(QWidget &editor);

} // namespace tolturn
