// SPDX-License-Identifier: GPL-3.0-or-later
// A throwaway PostgreSQL cluster for a test: initdb in a temporary folder, the server on a Unix
// socket in that folder only (no TCP port), stopped and deleted when the object goes. As root
// (CI), the cluster runs as the "postgres" user, since PostgreSQL refuses to run as root.
#pragma once

#include "core/measurements/measurement_store.h"

#include <QDir>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <grp.h>
#include <pwd.h>
#include <unistd.h>

namespace tolturn::test {

class PostgresCluster {
public:
    PostgresCluster()
    {
        const QStringList found = QDir(QStringLiteral("/usr/lib/postgresql"))
                                      .entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name | QDir::Reversed);
        if (found.isEmpty()) {
            m_error =
                QStringLiteral("PostgreSQL is not installed (Debian: postgresql; tools/bootstrap.sh installs it)");
            return;
        }
        m_bin = QStringLiteral("/usr/lib/postgresql/%1/bin/").arg(found.constFirst());
        if (!m_folder.isValid() || !handOver()) {
            m_error = QStringLiteral("cannot prepare the cluster folder %1").arg(m_folder.path());
            return;
        }
        if (!run(QStringLiteral("initdb"),
                 {QStringLiteral("-D"), dataDir(), QStringLiteral("-A"), QStringLiteral("trust"), QStringLiteral("-U"),
                  user(), QStringLiteral("--no-sync")}))
            return;
        m_started =
            run(QStringLiteral("pg_ctl"),
                {QStringLiteral("-D"), dataDir(), QStringLiteral("-l"), m_folder.filePath(QStringLiteral("log")),
                 QStringLiteral("-o"),
                 QStringLiteral("-k %1 -c listen_addresses='' -p %2 -c fsync=off").arg(m_folder.path()).arg(kPort),
                 QStringLiteral("-w"), QStringLiteral("start")});
    }

    ~PostgresCluster()
    {
        if (m_started)
            run(QStringLiteral("pg_ctl"), {QStringLiteral("-D"), dataDir(), QStringLiteral("-m"),
                                           QStringLiteral("immediate"), QStringLiteral("stop")});
    }

    PostgresCluster(const PostgresCluster &) = delete;
    PostgresCluster &operator=(const PostgresCluster &) = delete;

    [[nodiscard]] bool ok() const { return m_started; }

    [[nodiscard]] QString error() const { return m_error; }

    [[nodiscard]] StoreLocation location() const
    {
        StoreLocation l;
        l.kind = StoreLocation::Kind::PostgreSQL;
        l.host = m_folder.path(); // the socket's folder
        l.port = kPort;
        l.database = QStringLiteral("postgres");
        l.user = user();
        return l;
    }

private:
    static constexpr int kPort = 55432; // names the socket file only: no TCP port is opened

    [[nodiscard]] static bool asRoot() { return geteuid() == 0; }

    [[nodiscard]] static QString user()
    {
        return asRoot() ? QStringLiteral("postgres") : QString::fromLocal8Bit(qgetenv("USER"));
    }

    [[nodiscard]] QString dataDir() const { return m_folder.filePath(QStringLiteral("data")); }

    // As root: the folder belongs to the postgres user, who runs the cluster.
    bool handOver()
    {
        if (!asRoot())
            return true;
        const passwd *pw = getpwnam("postgres");
        return pw != nullptr && chown(QFile::encodeName(m_folder.path()).constData(), pw->pw_uid, pw->pw_gid) == 0;
    }

    bool run(const QString &tool, const QStringList &args)
    {
        QProcess p;
        if (asRoot())
            p.start(QStringLiteral("runuser"),
                    QStringList{QStringLiteral("-u"), QStringLiteral("postgres"), QStringLiteral("--"), m_bin + tool} +
                        args);
        else
            p.start(m_bin + tool, args);
        if (!p.waitForFinished(120000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
            m_error = QStringLiteral("%1 failed: %2 %3")
                          .arg(tool, QString::fromLocal8Bit(p.readAllStandardError()), p.errorString());
            return false;
        }
        return true;
    }

    QTemporaryDir m_folder;
    QString m_bin;
    QString m_error;
    bool m_started = false;
};

} // namespace tolturn::test
