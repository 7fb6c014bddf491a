// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/fe/external_tools.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QProcess>
#include <QProcessEnvironment>
#include <QStandardPaths>

namespace tolturn {

namespace {

struct ExternalTools {
    Q_DECLARE_TR_FUNCTIONS(ExternalTools)
};

ExternalTool find(const QString &name, const QString &executable, const QString &package, const QString &variable)
{
    ExternalTool tool{name, executable, package, variable, QString()};
    const QString override = qEnvironmentVariable(variable.toLatin1().constData());
    if (!override.isEmpty()) {
        const QFileInfo info(override);
        if (info.isFile() && info.isExecutable())
            tool.path = info.absoluteFilePath();
        return tool;
    }
    tool.path = QStandardPaths::findExecutable(executable);
    return tool;
}

} // namespace

QString ExternalTool::missingMessage() const
{
    const QString override = qEnvironmentVariable(envVariable.toLatin1().constData());
    const QString where =
        override.isEmpty()
            ? ExternalTools::tr("\"%1\" is not on the PATH").arg(executable)
            : ExternalTools::tr("%1 is set to \"%2\", which is not an executable file").arg(envVariable, override);
    return ExternalTools::tr("%1 was not found: %2. Install it with: sudo apt install %3 "
                             "(or run tools/bootstrap.sh), or set %4 to its executable.")
        .arg(name, where, package, envVariable);
}

ExternalTool findGmsh()
{
    return find(QStringLiteral("gmsh"), QStringLiteral("gmsh"), QStringLiteral("gmsh"), QStringLiteral("TOLTURN_GMSH"));
}

ExternalTool findCalculix()
{
    return find(QStringLiteral("CalculiX"), QStringLiteral("ccx"), QStringLiteral("calculix-ccx"),
                QStringLiteral("TOLTURN_CCX"));
}

ProcessRun runExternal(const QString &program, const QStringList &arguments, const QString &workingDirectory,
                       const QStringList &environment, const std::function<bool(const QByteArray &)> &keepGoing)
{
    ProcessRun run;
    QProcess process;
    process.setWorkingDirectory(workingDirectory);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const QString &entry : environment)
        env.insert(entry.section(QLatin1Char('='), 0, 0), entry.section(QLatin1Char('='), 1));
    process.setProcessEnvironment(env);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    if (!process.waitForStarted()) {
        run.crashed = true;
        run.output = process.errorString().toUtf8();
        return run;
    }
    while (!process.waitForFinished(100)) {
        const QByteArray piece = process.readAll();
        run.output += piece;
        if (keepGoing && !keepGoing(piece)) {
            process.kill();
            process.waitForFinished();
            run.cancelled = true;
            return run;
        }
        if (process.state() == QProcess::NotRunning)
            break;
    }
    const QByteArray rest = process.readAll();
    run.output += rest;
    if (keepGoing && !rest.isEmpty())
        static_cast<void>(keepGoing(rest));
    run.crashed = process.exitStatus() == QProcess::CrashExit;
    run.exitCode = process.exitCode();
    return run;
}

} // namespace tolturn
