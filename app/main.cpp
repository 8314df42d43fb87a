// ocu: the console. See README.md for the two commands and docs/site-config.md for the configuration.
#include "app/CommandLine.h"
#include "app/ConsoleApp.h"
#include "app/LogFormat.h"
#include "app/Version.h"
#include "protocols/common/ThreadPriority.h"

#include <QApplication>
#include <QByteArray>

#include <cstdio>

int main(int argc, char** argv) {
    // First, before any thread or library (SDL) installs its own: SIGINT/SIGTERM/SIGHUP quit cleanly.
    ocu::installQuitSignalHandlers();
    // The console's stop-path threads (stacks' io threads, the headless stdin reader) ahead of ordinary
    // threads where the OS permits (docs/decisions/stop-from-callers-thread.md).
    ocu::enableStopPathPriority();
    // Log lines for a terminal, a file or the systemd journal (app/LogFormat.h).
    ocu::installConsoleLogFormat();
    // --headless, --help and --version need no display at all, nor does --screenshot when there is none;
    // decide the platform before QApplication exists.
    const bool haveDisplay =
        !qEnvironmentVariableIsEmpty("DISPLAY") || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
    bool noWindowNeeded = false, screenshot = false;
    for (int i = 1; i < argc; ++i) {
        const QByteArray a(argv[i]);
        if (a == "--headless" || a == "--help" || a == "-h" || a == "--version" || a == "-v" ||
            a == "--help-all" || a.startsWith("--export-") || a.startsWith("--check-config"))
            noWindowNeeded = true;
        if (a == "--screenshot" || a.startsWith("--screenshot="))
            screenshot = true;
    }
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && (noWindowNeeded || (screenshot && !haveDisplay)))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && !haveDisplay) {
        std::fputs("ocu: no display (DISPLAY is not set). Run it under xvfb-run, or use --headless for the "
                   "JSON-lines monitor or --screenshot FILE for a picture.\n",
                   stderr);
        return 2;
    }
    QGuiApplication::setHighDpiScaleFactorRoundingPolicy(Qt::HighDpiScaleFactorRoundingPolicy::PassThrough);
    ocu::prepareSurfaceFormat();
    QApplication app(argc, argv);
    ocu::watchQuitSignals();
    QApplication::setOrganizationName(QStringLiteral("OCU"));
    QApplication::setApplicationName(QStringLiteral("ocu"));
    QApplication::setApplicationVersion(ocu::versionString());

    ocu::CommandLineOptions options;
    QString error, help;
    ocu::installTranslator(app, ocu::languageFromArgs(app.arguments()));
    if (!ocu::parseCommandLine(app.arguments(), options, error, help)) {
        if (error.isEmpty()) {
            std::fputs(qPrintable(help + QLatin1Char('\n')), stdout);
            return 0;
        }
        std::fprintf(stderr, "ocu: %s\n", qPrintable(error));
        return 2;
    }
    return ocu::runConsole(app, options);
}
