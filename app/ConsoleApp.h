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
// Runs the console (window, screenshot or headless) until it exits; returns the process exit code.
int runConsole(QApplication& app, const CommandLineOptions& options);

} // namespace ocu
