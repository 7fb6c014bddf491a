// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/autosave.h"

#include "core/common/atomic_file.h"
#include "core/io/project_file.h"
#include "widgets/document/project_document.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QUuid>

#include <algorithm>

namespace tolturn {

namespace {

constexpr int kDefaultIntervalSeconds = 60;

QString metaPath(const QString &copyPath)
{
    return copyPath.chopped(QStringLiteral(".tolturn").size()) + QStringLiteral(".json");
}

bool writeMeta(const QString &path, const ProjectDocument &document)
{
    const QJsonObject meta{{QStringLiteral("original"), document.filePath()},
                           {QStringLiteral("part"), document.project().part.name},
                           {QStringLiteral("saved"), QDateTime::currentDateTimeUtc().toString(Qt::ISODate)}};
    return writeFileAtomically(path, QJsonDocument(meta).toJson()).isEmpty();
}

// True when no running session holds the lock of this copy.
bool isLeftOver(const QString &copyPath)
{
    QLockFile lock(copyPath.chopped(QStringLiteral(".tolturn").size()) + QStringLiteral(".lock"));
    lock.setStaleLockTime(0); // a live session's lock never goes stale by age; a dead one's PID does
    if (!lock.tryLock(0))
        return false;
    lock.unlock();
    return true;
}

} // namespace

Autosave::Autosave(ProjectDocument &document, const QString &folder, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_base(QDir(folder).filePath(QUuid::createUuid().toString(QUuid::WithoutBraces)))
{
    QDir().mkpath(folder);
    m_lock = std::make_unique<QLockFile>(m_base + QStringLiteral(".lock"));
    m_lock->setStaleLockTime(0);
    (void)m_lock->tryLock(0); // a fresh name: nobody else holds it
    connect(&m_timer, &QTimer::timeout, this, &Autosave::saveNow);
    connect(&m_document, &ProjectDocument::modifiedChanged, this, [this](bool modified) {
        if (!modified)
            removeCopy(); // saved, reverted by undo, or closed
    });
    setIntervalSeconds(kDefaultIntervalSeconds);
}

Autosave::~Autosave()
{
    removeCopy(); // a normal exit leaves nothing to recover
}

void Autosave::setIntervalSeconds(int seconds)
{
    m_timer.start(seconds * 1000);
}

bool Autosave::saveNow()
{
    if (!m_document.hasProject() || !m_document.isModified()) {
        removeCopy();
        return true;
    }
    return writeProjectFile(copyPath(), m_document.project(), WriteCheck::KeepProblems).ok &&
           writeMeta(metaPath(copyPath()), m_document);
}

void Autosave::removeCopy() const
{
    QFile::remove(copyPath());
    QFile::remove(metaPath(copyPath()));
}

std::vector<Autosave::Copy> Autosave::leftOver(const QString &folder)
{
    std::vector<Copy> copies;
    const QDir dir(folder);
    for (const QString &name : dir.entryList({QStringLiteral("*.tolturn")}, QDir::Files)) {
        const QString path = dir.filePath(name);
        if (!isLeftOver(path))
            continue;
        QFile metaFile(metaPath(path));
        const QJsonObject meta =
            metaFile.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(metaFile.readAll()).object() : QJsonObject();
        copies.push_back({path, meta.value(QStringLiteral("original")).toString(),
                          meta.value(QStringLiteral("part")).toString(),
                          QDateTime::fromString(meta.value(QStringLiteral("saved")).toString(), Qt::ISODate)});
    }
    std::sort(copies.begin(), copies.end(), [](const Copy &a, const Copy &b) { return a.savedAt > b.savedAt; });
    return copies;
}

void Autosave::remove(const Copy &copy)
{
    QFile::remove(copy.autosavePath);
    QFile::remove(metaPath(copy.autosavePath));
}

} // namespace tolturn
