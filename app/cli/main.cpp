// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli: the command-line front end.
#include "app/cli/command_line.h"
#include "core/common/atomic_file.h"
#include "core/common/library_info.h"
#include "translations/i18n.h"

#include <QApplication>
#include <QCoreApplication>
#include <QTextStream>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <memory>

namespace {

// The report draws the part and the plots with the widgets' painters, which need a
// QApplication; every other command stays a console program without a display. Without an
// explicit QT_QPA_PLATFORM the report renders offscreen, so batch runs need no X server.
std::unique_ptr<QCoreApplication> makeApplication(int &argc, char *argv[])
{
    if (argc > 1 && std::strcmp(argv[1], "report") == 0) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
        return std::make_unique<QApplication>(argc, argv);
    }
    return std::make_unique<QCoreApplication>(argc, argv);
}

// Ctrl+C or a kill while a file is being written: the temporary file goes (the target was never
// touched), then the signal ends the process as it would have.
extern "C" void removeTemporariesAndDie(int signal)
{
    tolturn::removePendingTemporaryFile();
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

void removeTemporariesOnTermination()
{
    for (const int signal : {SIGINT, SIGTERM, SIGHUP})
        std::signal(signal, removeTemporariesAndDie);
}

} // namespace

int main(int argc, char *argv[])
{
    removeTemporariesOnTermination();
    const std::unique_ptr<QCoreApplication> app = makeApplication(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("TolTurn"));
    QCoreApplication::setApplicationName(QStringLiteral("tolturn-cli"));
    QCoreApplication::setApplicationVersion(tolturn::tolturnVersion());
    tolturn::installTranslations(*app);
    QTextStream out(stdout);
    QTextStream err(stderr);
    const int code = tolturn::runCommandLine(QCoreApplication::arguments(), out, err);
    out.flush();
    err.flush();
    return code;
}
