#include "app/CommandLine.h"
#include "app/ProtocolModule.h"
#include "app/SiteRuntime.h"
#include "app/WorkspaceLayout.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QRegularExpression>

namespace ocu {

QStringList screenshotViewNames() {
    // The panels of the console's window: the main ones, those of the protocol modules of this build and the
    // control room (a site with the shared history).
    QList<PanelSpec> modulePanels;
    for (const auto& m : makeProtocolModules())
        modulePanels += m->panels();
    modulePanels << SiteRuntime::controlRoomPanel();
    return MainWindow::panelKeysWith(modulePanels);
}

namespace {

// --config … --reset-layout: the site, the window and its screenshot, language, logging, headless.
QList<QCommandLineOption> consoleOptions() {
    QCommandLineOption config({QStringLiteral("c"), QStringLiteral("config")},
                              QCoreApplication::translate("CommandLine", "Site configuration (JSON, see "
                                                                         "docs/site-config.md). Default: the "
                                                                         "built-in simulated site."),
                              QStringLiteral("FILE"));
    QCommandLineOption checkConfig(QStringLiteral("check-config"),
                                   QCoreApplication::translate("CommandLine",
                                                               "Check the site configuration FILE, print "
                                                               "each problem as file:line, start nothing; "
                                                               "exit 0 when valid, 1 when not."),
                                   QStringLiteral("FILE"));
    QCommandLineOption noSim(QStringLiteral("no-sim"),
                             QCoreApplication::translate("CommandLine",
                                                         "Do not start the built-in simulators, "
                                                         "even if the configuration enables them."));
    QCommandLineOption shot(QStringLiteral("screenshot"),
                            QCoreApplication::translate("CommandLine", "Write a PNG screenshot to FILE after "
                                                                       "--settle seconds, then exit 0."),
                            QStringLiteral("FILE"));
    QCommandLineOption view(QStringLiteral("view"),
                            QCoreApplication::translate("CommandLine", "What --screenshot captures: all (the "
                                                                       "whole window) or one panel: %1.")
                                    .arg(screenshotViewNames().join(QStringLiteral(", "))) +
                                QLatin1Char(' ') +
                                QCoreApplication::translate("CommandLine",
                                                            "all:PANEL: the whole window with that panel in "
                                                            "front."),
                            QStringLiteral("NAME"), QStringLiteral("all"));
    QCommandLineOption size(QStringLiteral("size"),
                            QCoreApplication::translate("CommandLine", "Window size for the screenshot, e.g. "
                                                                       "1600x1000."),
                            QStringLiteral("WxH"), QStringLiteral("1600x1000"));
    QCommandLineOption settle(QStringLiteral("settle"),
                              QCoreApplication::translate("CommandLine",
                                                          "Seconds to let live data arrive before "
                                                          "the screenshot (default 3)."),
                              QStringLiteral("SECONDS"), QStringLiteral("3"));
    QCommandLineOption lang(QStringLiteral("lang"),
                            QCoreApplication::translate("CommandLine",
                                                        "User interface language: en, de or fr "
                                                        "(default: the system locale)."),
                            QStringLiteral("LANG"));
    QCommandLineOption log(QStringLiteral("log"),
                           QCoreApplication::translate("CommandLine",
                                                       "Enable debug output for these logging "
                                                       "categories, comma-separated: ocu.jaus, "
                                                       "ocu.iso, ocu.osyris, ocu.ui, ocu.sim, ocu.* "
                                                       "(Qt wildcard rules)."),
                           QStringLiteral("CATEGORIES"));
    QCommandLineOption headless(QStringLiteral("headless"),
                                QCoreApplication::translate("CommandLine",
                                                            "No window: print one JSON line per "
                                                            "machine change and per event on "
                                                            "stdout, read JSON-line commands on "
                                                            "stdin (see README)."));
    QCommandLineOption duration(QStringLiteral("duration"),
                                QCoreApplication::translate("CommandLine",
                                                            "With --headless: stop after SECONDS "
                                                            "(default: run until stdin closes)."),
                                QStringLiteral("SECONDS"), QStringLiteral("0"));
    QCommandLineOption socket(QStringLiteral("command-socket"),
                              QCoreApplication::translate("CommandLine",
                                                          "With --headless: also take JSON-line commands on "
                                                          "a local socket at PATH (mode 0660: owner and "
                                                          "group); the run then ends on SIGTERM or "
                                                          "--duration, not at the end of stdin."),
                              QStringLiteral("PATH"));
    QCommandLineOption reset(QStringLiteral("reset-layout"),
                             QCoreApplication::translate("CommandLine", "Start with the default panel layout "
                                                                        "instead of the saved one."));
    return {config, checkConfig, noSim,    shot,     view,   size, settle,
            lang,   log,         headless, duration, socket, reset};
}

// The shift report, the flight recorder, the replay and its exports, the night palette.
QList<QCommandLineOption> runOptions() {
    // The shift report at the end of a headless run.
    QCommandLineOption shiftPdf(QStringLiteral("shift-report"),
                                QCoreApplication::translate("CommandLine",
                                                            "With --headless: write the shift "
                                                            "report as PDF to FILE when the run ends."),
                                QStringLiteral("FILE"));
    QCommandLineOption shiftCsv(QStringLiteral("shift-csv"),
                                QCoreApplication::translate("CommandLine",
                                                            "With --headless: write the shift "
                                                            "report as CSV to FILE when the run ends."),
                                QStringLiteral("FILE"));
    const auto tr = [](const char* text) { return QCoreApplication::translate("CommandLine", text); };
    QCommandLineOption record(QStringLiteral("record"),
                              tr("Folder for this run's flight recording (default: record.dir of the site "
                                 "configuration, else the user's data folder)."),
                              QStringLiteral("DIR"));
    QCommandLineOption noRecord(QStringLiteral("no-record"), tr("Do not record this run."));
    QCommandLineOption replay(QStringLiteral("replay"),
                              tr("Replay a flight recording (no protocol stacks, commands disabled)."),
                              QStringLiteral("FILE"));
    QCommandLineOption at(
        QStringLiteral("at"),
        tr("With --replay: start at T (seconds after the start, HH:MM:SS UTC or ISO 8601)."),
        QStringLiteral("T"));
    QCommandLineOption speed(QStringLiteral("speed"),
                             tr("With --replay: playing speed 0.1 to 16 (--headless: default as fast as "
                                "possible)."),
                             QStringLiteral("X"));
    QCommandLineOption exJsonl(QStringLiteral("export-jsonl"),
                               tr("With --replay: write the window --from/--to as JSON lines and exit."),
                               QStringLiteral("FILE"));
    QCommandLineOption exCsv(QStringLiteral("export-csv"),
                             tr("With --replay: write machine states of the window as CSV and exit."),
                             QStringLiteral("FILE"));
    QCommandLineOption exSlice(QStringLiteral("export-slice"),
                               tr("With --replay: write the window as a new recording and exit."),
                               QStringLiteral("FILE"));
    QCommandLineOption from(QStringLiteral("from"), tr("Start of the export window (as --at)."),
                            QStringLiteral("T"));
    QCommandLineOption to(QStringLiteral("to"), tr("End of the export window (as --at)."),
                          QStringLiteral("T"));
    // The night palette from the start (screenshots of it; the View menu toggles it too).
    QCommandLineOption night(QStringLiteral("night"),
                             QCoreApplication::translate("CommandLine", "Start with the night palette."));
    QCommandLineOption workspace(QStringLiteral("workspace"),
                                 tr("Start in this workspace: dispatch, compaction, ugv, monitor or all "
                                    "(default: the one last used, else the operator's role's)."),
                                 QStringLiteral("NAME"));
    return {shiftPdf, shiftCsv, record,  noRecord, replay, at,    speed,
            exJsonl,  exCsv,    exSlice, from,     to,     night, workspace};
}

QString name(const char* option) {
    return QString::fromLatin1(option);
}

// --view, --size, --settle, --lang.
bool readWindowOptions(const QCommandLineParser& p, CommandLineOptions& o, QString& error) {
    o.configFile = p.value(name("config"));
    o.checkConfigFile = p.value(name("check-config"));
    o.noSim = p.isSet(name("no-sim"));
    o.screenshotFile = p.value(name("screenshot"));
    o.view = p.value(name("view")).toLower();
    // "all:<panel>": the whole window with that tabbed panel in front.
    const QString viewPanel = o.view.startsWith(QLatin1String("all:")) ? o.view.mid(4) : o.view;
    if (o.view != QLatin1String("all") && !screenshotViewNames().contains(viewPanel)) {
        error = QCoreApplication::translate("CommandLine", "--view: unknown view \"%1\"; use all, %2")
                    .arg(o.view, screenshotViewNames().join(QStringLiteral(", ")));
        return false;
    }
    const QString size = p.value(name("size"));
    static const QRegularExpression sizeRe(QStringLiteral("^(\\d{2,5})x(\\d{2,5})$"));
    auto m = sizeRe.match(size);
    if (!m.hasMatch()) {
        error =
            QCoreApplication::translate("CommandLine", "--size: expected WxH such as 1600x1000, got \"%1\"")
                .arg(size);
        return false;
    }
    o.size = QSize(m.captured(1).toInt(), m.captured(2).toInt());
    if (o.size.width() < 320 || o.size.height() < 240 || o.size.width() > 8192 || o.size.height() > 8192) {
        error = QCoreApplication::translate("CommandLine", "--size: %1 is outside 320x240 .. 8192x8192")
                    .arg(size);
        return false;
    }
    bool ok = false;
    o.settleSeconds = p.value(name("settle")).toDouble(&ok);
    if (!ok || o.settleSeconds < 0 || o.settleSeconds > 3600) {
        error =
            QCoreApplication::translate("CommandLine", "--settle: expected seconds between 0 and 3600, got "
                                                       "\"%1\"")
                .arg(p.value(name("settle")));
        return false;
    }
    o.language = p.value(name("lang")).toLower();
    if (!o.language.isEmpty() && o.language != QLatin1String("en") && o.language != QLatin1String("de") &&
        o.language != QLatin1String("fr")) {
        error = QCoreApplication::translate("CommandLine", "--lang: \"%1\" is not one of en, de, fr")
                    .arg(o.language);
        return false;
    }
    o.resetLayout = p.isSet(name("reset-layout"));
    o.night = p.isSet(name("night"));
    o.workspace = p.value(name("workspace")).toLower();
    if (Workspace w; !o.workspace.isEmpty() && !workspaceFromKey(o.workspace, &w)) {
        error = QCoreApplication::translate("CommandLine",
                                            "--workspace: \"%1\" is not one of dispatch, compaction, ugv, "
                                            "monitor, all")
                    .arg(o.workspace);
        return false;
    }
    return true;
}

// --log, --headless, --duration and the shift report.
bool readRunOptions(const QCommandLineParser& p, CommandLineOptions& o, QString& error) {
    o.logCategories = p.value(name("log"));
    o.headless = p.isSet(name("headless"));
    bool ok = false;
    o.durationSeconds = p.value(name("duration")).toDouble(&ok);
    if (!ok || o.durationSeconds < 0) {
        error = QCoreApplication::translate("CommandLine", "--duration: expected seconds >= 0, got \"%1\"")
                    .arg(p.value(name("duration")));
        return false;
    }
    o.commandSocket = p.value(name("command-socket"));
    if (!o.commandSocket.isEmpty() && !o.headless) {
        error = QCoreApplication::translate("CommandLine", "--command-socket needs --headless");
        return false;
    }
    if (o.headless && !o.screenshotFile.isEmpty()) {
        error = QCoreApplication::translate("CommandLine", "--headless and --screenshot cannot be combined");
        return false;
    }
    o.shiftReportPdf = p.value(name("shift-report"));
    o.shiftReportCsv = p.value(name("shift-csv"));
    if ((!o.shiftReportPdf.isEmpty() || !o.shiftReportCsv.isEmpty()) && !o.headless) {
        error = QCoreApplication::translate(
            "CommandLine", "--shift-report/--shift-csv need --headless (in the window: Production "
                           "panel, Shift report)");
        return false;
    }
    return true;
}

// The recorder, --replay and its exports.
bool readReplayOptions(const QCommandLineParser& p, CommandLineOptions& o, QString& error) {
    const auto tr = [](const char* text) { return QCoreApplication::translate("CommandLine", text); };
    o.recordDir = p.value(name("record"));
    o.noRecord = p.isSet(name("no-record"));
    o.replayFile = p.value(name("replay"));
    o.replayAt = p.value(name("at"));
    o.exportJsonl = p.value(name("export-jsonl"));
    o.exportCsv = p.value(name("export-csv"));
    o.exportSlice = p.value(name("export-slice"));
    o.exportFrom = p.value(name("from"));
    o.exportTo = p.value(name("to"));
    const bool speedSet = p.isSet(name("speed"));
    if (speedSet) {
        bool ok = false;
        o.replaySpeed = p.value(name("speed")).toDouble(&ok);
        if (!ok || o.replaySpeed < 0 || o.replaySpeed > 16) {
            error = tr("--speed: expected 0.1 to 16, got \"%1\"").arg(p.value(name("speed")));
            return false;
        }
        o.replaySpeedSet = true;
    }
    const bool replayOnly = !o.replayAt.isEmpty() || speedSet || !o.exportJsonl.isEmpty() ||
                            !o.exportCsv.isEmpty() || !o.exportSlice.isEmpty() || !o.exportFrom.isEmpty() ||
                            !o.exportTo.isEmpty();
    if (replayOnly && o.replayFile.isEmpty()) {
        error = tr("--at, --speed, --export-* and --from/--to need --replay FILE");
        return false;
    }
    return true;
}

} // namespace

bool parseCommandLine(const QStringList& args, CommandLineOptions& o, QString& error, QString& helpText) {
    QCommandLineParser p;
    p.setApplicationDescription(QCoreApplication::translate(
        "CommandLine",
        "Mixed-fleet Operator Control Unit: JAUS ground vehicles, ISO 23725 autonomous haulage "
        "and OSYRIS rollers and pavers on one console.\nWithout --config it starts on the built-in "
        "simulated site."));
    auto help = p.addHelpOption();
    auto version = p.addVersionOption();
    p.addOptions(consoleOptions());
    p.addOptions(runOptions());
    if (!p.parse(args)) {
        error = p.errorText();
        return false;
    }
    if (p.isSet(help)) {
        helpText = p.helpText();
        error.clear();
        return false;
    }
    if (p.isSet(version)) {
        helpText =
            QCoreApplication::applicationName() + QLatin1Char(' ') + QCoreApplication::applicationVersion();
        error.clear();
        return false;
    }
    if (!p.positionalArguments().isEmpty()) {
        error = QCoreApplication::translate("CommandLine", "Unexpected argument: %1")
                    .arg(p.positionalArguments().first());
        return false;
    }
    return readWindowOptions(p, o, error) && readRunOptions(p, o, error) && readReplayOptions(p, o, error);
}

} // namespace ocu
