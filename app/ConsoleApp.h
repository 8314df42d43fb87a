#pragma once
#include "app/CommandLine.h"

#include <QString>
#include <QStringList>

class QApplication;

namespace ocu {

// The OpenGL 3.2 core default format the VTK view needs, set before QApplication (toolchain.md §4a).
void prepareSurfaceFormat();
// en | de | fr from --lang (scanned before the parser runs so --help is translated too), else "".
QString languageFromArgs(const QStringList& args);
// Loads the embedded German or French translation; lang empty = system locale. Returns the language used.
QString installTranslator(QApplication& app, const QString& lang);
// SIGINT, SIGTERM and SIGHUP become a normal QCoreApplication::quit(): the handler only writes the signal's
// number into a self-pipe (async-signal-safe) and a QSocketNotifier on the GUI thread quits, so the shutdown
// path (drive zeros, JAUS release, WebSocket close 1001, OSYRIS commit) runs as after closing the window. A
// second signal while shutting down gets the default action (ends the process at once). Install before
// QApplication (and before SDL starts, which then leaves our handlers alone); watch once it exists.
void installQuitSignalHandlers();
void watchQuitSignals();
// The signal that asked to quit (0 = none).
int quitSignal();
// QApplication::exec(), or 0 at once when a quit signal came before the loop could run (QCoreApplication::
// exit() before exec() is lost: exec() starts a fresh loop).
int execUnlessQuitting(QApplication& app);
// Runs the console (window, screenshot or headless) until it exits; returns the process exit code.
int runConsole(QApplication& app, const CommandLineOptions& options);

} // namespace ocu
