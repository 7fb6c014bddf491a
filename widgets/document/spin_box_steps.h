// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>

class QDoubleSpinBox;
class QObject;

namespace tolturn {

class ProjectDocument;

// Runs `apply` (which edits `document`) whenever `box`'s value changes, as steps of the box
// (ProjectDocument::RepeatedEdits): the clicks on its arrows and the keys typed into it, one after
// another, are one step in Undo, until Return or the focus leaves the box. `context` ends the
// connections when it is destroyed.
void connectSpinBoxSteps(QDoubleSpinBox *box, ProjectDocument &document, QObject *context, std::function<void()> apply);

} // namespace tolturn
