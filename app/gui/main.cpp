// SPDX-License-Identifier: GPL-3.0-or-later
// tolturn: the desktop program.
#include "app/gui/main_window.h"
#include "app/gui/preferences.h"
#include "core/common/library_info.h"
#include "translations/i18n.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTimer>

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("TolTurn"));
    QApplication::setApplicationName(QStringLiteral("TolTurn"));
    QApplication::setApplicationVersion(tolturn::tolturnVersion());
    QApplication::setDesktopFileName(QStringLiteral("org.tolturn.TolTurn"));
    const tolturn::Preferences preferences = tolturn::loadPreferences();
    tolturn::installTranslations(app, tolturn::translationLocale(preferences));
    tolturn::DisplaySettings::instance().setUnits(tolturn::DisplayUnits(preferences.lengthUnit));

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "Tolerance-aware planning of CNC turning."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("project"),
                                 QApplication::translate("main", "Project file to open (.tolturn)."),
                                 QStringLiteral("[project]"));
    parser.process(app);

    tolturn::MainWindow window;
    window.show();
    // Work a crash interrupted comes first; the file named on the command line otherwise.
    const bool recovered = window.fileController()->offerRecovery(tolturn::MainWindow::autosaveFolder());
    if (!recovered && !parser.positionalArguments().isEmpty())
        window.fileController()->openFile(parser.positionalArguments().constFirst());
    // For the start-up benchmark (benchmarks/bench_gui): quit as soon as the window is usable.
    if (qEnvironmentVariableIsSet("TOLTURN_QUIT_WHEN_SHOWN"))
        QTimer::singleShot(0, &app, &QCoreApplication::quit);
    return QApplication::exec();
}
