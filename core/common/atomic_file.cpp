// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/common/atomic_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryFile>

#include <array>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace tolturn {

namespace {

struct AtomicFile {
    Q_DECLARE_TR_FUNCTIONS(AtomicFile)
};

// The temporary file of the write in progress: a fixed buffer that a signal handler may read.
std::array<char, 4096> g_pendingPath{};
volatile std::sig_atomic_t g_pending = 0;

} // namespace

PendingTemporaryFile::PendingTemporaryFile(const QString &path)
{
    const QByteArray name = QFile::encodeName(path);
    if (name.size() >= static_cast<qsizetype>(g_pendingPath.size()))
        return;
    std::memcpy(g_pendingPath.data(), name.constData(), static_cast<std::size_t>(name.size()) + 1);
    g_pending = 1;
}

PendingTemporaryFile::~PendingTemporaryFile()
{
    g_pending = 0;
}

void removePendingTemporaryFile() noexcept
{
    if (g_pending)
        ::unlink(g_pendingPath.data());
}

QFileDevice::Permissions permissionsForWrite(const QString &path)
{
    if (QFileInfo::exists(path))
        return QFile::permissions(path);
    const mode_t mask = ::umask(0);
    ::umask(mask);
    const mode_t mode = 0666 & ~mask;
    QFileDevice::Permissions p;
    const std::pair<mode_t, QFileDevice::Permissions> bits[] = {
        {S_IRUSR, QFileDevice::ReadOwner | QFileDevice::ReadUser},
        {S_IWUSR, QFileDevice::WriteOwner | QFileDevice::WriteUser},
        {S_IRGRP, QFileDevice::ReadGroup},
        {S_IWGRP, QFileDevice::WriteGroup},
        {S_IROTH, QFileDevice::ReadOther},
        {S_IWOTH, QFileDevice::WriteOther}};
    for (const auto &[bit, permission] : bits) {
        if (mode & bit)
            p |= permission;
    }
    return p;
}

QString writeFileAtomically(const QString &givenPath, const QByteArray &data)
{
    // A link is followed: the file it names is replaced, not the link by a file of its own.
    const QFileInfo given(givenPath);
    const QString resolved = given.isSymLink() ? given.canonicalFilePath() : QString();
    const QString path = !given.isSymLink() ? givenPath : resolved.isEmpty() ? given.symLinkTarget() : resolved;
    if (QFileInfo target(path); target.exists() && !target.isFile())
        return AtomicFile::tr("cannot write '%1': it is not a regular file (a folder, a device or a pipe)")
            .arg(givenPath);
    QTemporaryFile temp(QFileInfo(path).absoluteDir().filePath(QStringLiteral(".tolturn-XXXXXX")));
    if (!temp.open())
        return AtomicFile::tr("cannot write '%1': %2").arg(path, temp.errorString());
    const PendingTemporaryFile pending(temp.fileName());
    if (temp.write(data) != data.size() || !temp.flush()) {
        const QString reason = temp.errorString();
        return AtomicFile::tr("cannot write '%1': %2").arg(path, reason);
    }
    if (::fsync(temp.handle()) != 0)
        return AtomicFile::tr("cannot write '%1': the data did not reach the disk").arg(path);
    if (!temp.setPermissions(permissionsForWrite(path)))
        return AtomicFile::tr("cannot set the permissions of '%1': %2").arg(path, temp.errorString());
    temp.close();
    if (std::rename(QFile::encodeName(temp.fileName()).constData(), QFile::encodeName(path).constData()) != 0)
        return AtomicFile::tr("cannot save '%1': %2").arg(path, QString::fromLocal8Bit(std::strerror(errno)));
    temp.setAutoRemove(false); // it is the target now
    return {};
}

} // namespace tolturn
