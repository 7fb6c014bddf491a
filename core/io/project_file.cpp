// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/project_file.h"

#include "core/common/atomic_file.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

#include <algorithm>

namespace tolturn {

namespace {

struct ProjectFile {
    Q_DECLARE_TR_FUNCTIONS(ProjectFile)
};

constexpr qint64 kBytesPerMiB = 1024LL * 1024LL;

ProjectParseResult fileError(const QString &message)
{
    ProjectParseResult result;
    result.diagnostics.push_back(makeError(QStringLiteral("file"), message));
    return result;
}

} // namespace

ProjectParseResult readProjectFile(const QString &path)
{
    const QFileInfo info(path);
    if (!info.exists())
        return fileError(ProjectFile::tr("'%1' does not exist").arg(path));
    if (info.isDir())
        return fileError(ProjectFile::tr("'%1' is a folder, not a project file").arg(path));
    if (info.size() > kMaxProjectFileBytes)
        return fileError(ProjectFile::tr("'%1' is %2 MiB, more than the %3 MiB a project file may have")
                             .arg(path)
                             .arg(info.size() / kBytesPerMiB)
                             .arg(kMaxProjectFileBytes / kBytesPerMiB));
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fileError(ProjectFile::tr("cannot open '%1': %2").arg(path, file.errorString()));
    return parseProjectJson(file.readAll());
}

WriteResult writeProjectFile(const QString &path, const Project &project, WriteCheck check)
{
    const QByteArray bytes = serializeProjectJson(project);
    if (check == WriteCheck::RefuseInvalid) {
        const ProjectParseResult again = parseProjectJson(bytes);
        const auto error = std::find_if(again.diagnostics.begin(), again.diagnostics.end(),
                                        [](const Diagnostic &d) { return d.severity == Severity::Error; });
        if (!again.project && error != again.diagnostics.end())
            return {false, ProjectFile::tr("'%1' not written: the project would not open again (%2)")
                               .arg(path, error->toString())};
    }
    QString error = writeFileAtomically(path, bytes);
    return {error.isEmpty(), error};
}

} // namespace tolturn
