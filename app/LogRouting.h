#pragma once
// Routes protocol-library log messages (ocu::logMessage, no Qt) into Qt logging categories
// (ocu.jaus, ocu.iso, ocu.osyris, ocu.sim, ocu.ui, ...), so --log and QT_LOGGING_RULES control them.
#include <QLoggingCategory>
#include <QString>

Q_DECLARE_LOGGING_CATEGORY(lcUi)
Q_DECLARE_LOGGING_CATEGORY(lcApp)

namespace ocu {

void installLogRouting();
// Enables debug output for a comma-separated list of category patterns (e.g. "ocu.jaus,ocu.iso").
void enableLogCategories(const QString& categories);

} // namespace ocu
