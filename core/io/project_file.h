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

// Whether a project that reading would not take as it is may be written: the desktop program
// saves a project opened with problems (it opens it again to be repaired); the commands do not.
enum class WriteCheck { RefuseInvalid, KeepProblems };

// Writes atomically (QSaveFile: a temporary file renamed over the target on success), so a
// failed save leaves the previous file untouched; an existing file keeps its permissions. The
// document is read back before it is written: with RefuseInvalid, one that would not open again
// (a fitted constant out of its bounds, say) is not written, and the error names the field.
[[nodiscard]] WriteResult writeProjectFile(const QString &path, const Project &project,
                                           WriteCheck check = WriteCheck::RefuseInvalid);

} // namespace tolturn
