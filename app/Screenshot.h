#pragma once
#include <QString>

namespace ocu {

class MainWindow;

// Grabs the whole window (view "all") or one panel by its key and writes a PNG. Returns an empty
// string on success, else the reason.
QString saveScreenshot(MainWindow& window, const QString& view, const QString& file);

} // namespace ocu
