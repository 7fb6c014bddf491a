// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QFileDevice>
#include <QString>

namespace tolturn {

// Writes `data` to `path` atomically: into a temporary file beside it, renamed over it once
// complete (POSIX rename(2) is atomic within a file system), so that a failed or interrupted
// write leaves the previous file as it was. The file keeps the permissions of the one it replaces;
// a new one gets 0666 less the umask, as open(2) would give it. Returns the error, naming the
// file; empty on success.
[[nodiscard]] QString writeFileAtomically(const QString &path, const QByteArray &data);

// A temporary file being written, for removePendingTemporaryFile(); registered for its lifetime.
class PendingTemporaryFile {
public:
    explicit PendingTemporaryFile(const QString &path);
    ~PendingTemporaryFile();
    PendingTemporaryFile(const PendingTemporaryFile &) = delete;
    PendingTemporaryFile &operator=(const PendingTemporaryFile &) = delete;
};

// Removes the temporary file of a write in progress. Async-signal-safe: for a handler of SIGINT
// or SIGTERM, so that an interrupted program leaves no hidden file behind.
void removePendingTemporaryFile() noexcept;

// The permissions `path` is to have when written: its own if it exists, else those of a new file.
[[nodiscard]] QFileDevice::Permissions permissionsForWrite(const QString &path);

} // namespace tolturn
