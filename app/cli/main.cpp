// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn-cli: the command-line front end.
#include "app/cli/command_line.h"
#include "core/common/library_info.h"
#include "translations/i18n.h"

#include <QCoreApplication>
#include <QTextStream>

#include <cstdio>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("TolTurn"));
    QCoreApplication::setApplicationName(QStringLiteral("tolturn-cli"));
    QCoreApplication::setApplicationVersion(tolturn::tolturnVersion());
    tolturn::installTranslations(app);
    QTextStream out(stdout);
    QTextStream err(stderr);
    const int code = tolturn::runCommandLine(QCoreApplication::arguments(), out, err);
    out.flush();
    err.flush();
    return code;
}
