#pragma once
#include <QString>

namespace ocu {

class MainWindow;

// Grabs the whole window (view "all"), one panel by its key, or the whole window with one (tabbed) panel
// brought to the front ("all:<key>"), and writes a PNG. Returns an empty
// string on success, else the reason.
QString saveScreenshot(MainWindow& window, const QString& view, const QString& file);

} // namespace ocu
