// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/part/profile.h"

#include <QString>

namespace tolturn {

struct StepExportResult {
    bool ok = false;
    QString error; // what went wrong, naming the file; empty when ok
};

// Writes the profile as a solid revolved about the z axis (the face bounded by the outer contour,
// the axis and the inner contour, turned a full revolution) to a STEP file in millimetres.
// Atomic: written to a temporary file in the same folder, then renamed over `path`.
// The file gets the permissions of the file it replaces, or those a new file gets (0666 less
// the umask), not the 0600 of a temporary file.
[[nodiscard]] StepExportResult exportProfileToStep(const PartProfile &profile, const QString &path);

} // namespace tolturn
