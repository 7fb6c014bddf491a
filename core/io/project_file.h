// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/io/project_json.h"

#include <QString>

namespace tolturn {

// Largest project file read (a profile of thousands of segments is well below a megabyte).
inline constexpr qint64 kMaxProjectFileBytes = 64LL * 1024 * 1024;

// Reads and validates a project file. A missing, unreadable or oversized file is an error with
// the path and the system's reason.
[[nodiscard]] ProjectParseResult readProjectFile(const QString &path);

struct WriteResult {
    bool ok = false;
    QString error; // what went wrong, naming the file; empty when ok
};

// Writes atomically (QSaveFile: a temporary file renamed over the target on success), so a
// failed save leaves the previous file untouched.
[[nodiscard]] WriteResult writeProjectFile(const QString &path, const Project &project);

} // namespace tolturn
