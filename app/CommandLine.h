#pragma once
// The console's command line (QCommandLineParser); parsing is separate from main() so it can be tested.
#include <QSize>
#include <QString>
#include <QStringList>

namespace ocu {

struct CommandLineOptions {
    QString configFile;     // empty = built-in simulated site
    bool noSim = false;     // do not start the built-in simulators even if the config enables them
    QString screenshotFile; // write a PNG and exit
    QString view = QStringLiteral("all");
    QSize size{1600, 1000};
    double settleSeconds = 3.0;
    QString language;           // de | fr | en; empty = system locale
    QString logCategories;      // comma-separated Qt logging categories to enable at debug level
    bool headless = false;      // JSON-lines monitor on stdout, commands on stdin, no window
    double durationSeconds = 0; // headless: stop after this long (0 = until stdin closes or SIGINT)
    bool resetLayout = false;
    // Issue 15 §4: with --headless, the shift report written when the run ends (PDF and/or CSV).
    QString shiftReportPdf;
    QString shiftReportCsv;
};

// Parses args (args[0] is the program name). On failure returns false and fills error; with --help or
// --version fills helpText and returns false with an empty error.
bool parseCommandLine(const QStringList& args, CommandLineOptions& options, QString& error,
                      QString& helpText);

// The view names --view accepts (besides "all").
QStringList screenshotViewNames();

} // namespace ocu
