#pragma once
// The console's command line (QCommandLineParser); parsing is separate from main() so it can be tested.
#include <QSize>
#include <QString>
#include <QStringList>

namespace ocu {

struct CommandLineOptions {
    QString configFile;      // empty = built-in simulated site
    QString checkConfigFile; // --check-config FILE: validate it, print its errors, start nothing
    bool noSim = false;      // do not start the built-in simulators even if the config enables them
    QString screenshotFile;  // write a PNG and exit
    QString view = QStringLiteral("all");
    QSize size{1600, 1000};
    double settleSeconds = 3.0;
    QString language;           // de | fr | en; empty = system locale
    QString logCategories;      // comma-separated Qt logging categories to enable at debug level
    bool headless = false;      // JSON-lines monitor on stdout, commands on stdin, no window
    double durationSeconds = 0; // headless: stop after this long (0 = until stdin closes or SIGINT)
    QString commandSocket;      // headless: also read commands from this local socket (app/HeadlessSocket.h)
    bool resetLayout = false;
    bool night = false; // --night: start with the night palette
    QString workspace;  // --workspace: dispatch | compaction | ugv | monitor | all; empty = the role's
    // With --headless, the shift report written when the run ends (PDF and/or CSV).
    QString shiftReportPdf;
    QString shiftReportCsv;
    // Flight recorder and replay (docs/recording.md).
    QString recordDir;      // --record DIR: this run's recording goes there (overrides record.dir)
    bool noRecord = false;  // --no-record
    QString replayFile;     // --replay FILE: replay a recording instead of connecting to a site
    QString replayAt;       // --at T: start the replay at T (seconds after the start, HH:MM:SS or ISO 8601)
    double replaySpeed = 1; // --speed X (0.1..16; headless: 0 = as fast as possible, the default)
    bool replaySpeedSet = false;
    QString exportJsonl, exportCsv, exportSlice; // --export-jsonl/--export-csv/--export-slice FILE
    QString exportFrom, exportTo;                // --from T --to T (default: the whole recording)
};

// Parses args (args[0] is the program name). On failure returns false and fills error; with --help or
// --version fills helpText and returns false with an empty error.
bool parseCommandLine(const QStringList& args, CommandLineOptions& options, QString& error,
                      QString& helpText);

// The view names --view accepts (besides "all").
QStringList screenshotViewNames();

} // namespace ocu
