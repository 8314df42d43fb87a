#pragma once
// Logging from protocol code without Qt: stacks call a LogSink; the app routes it to Qt logging
// categories (ocu.jaus, ocu.iso, ocu.osyris), tests may capture it, and the default writes to stderr.
#include <functional>
#include <string>
#include <string_view>

namespace ocu {

enum class LogLevel { Debug, Info, Warning, Error };

using LogSink = std::function<void(LogLevel, std::string_view category, std::string_view message)>;

// Process-wide default sink; replaceable (the app installs a Qt-backed one at start-up).
void setLogSink(LogSink sink);
void logMessage(LogLevel level, std::string_view category, std::string_view message);
// Messages below this level are dropped cheaply (default Info).
void setLogThreshold(LogLevel level);
bool logEnabled(LogLevel level);

inline void logDebug(std::string_view cat, std::string_view msg) {
    if (logEnabled(LogLevel::Debug))
        logMessage(LogLevel::Debug, cat, msg);
}
inline void logInfo(std::string_view cat, std::string_view msg) {
    logMessage(LogLevel::Info, cat, msg);
}
inline void logWarning(std::string_view cat, std::string_view msg) {
    logMessage(LogLevel::Warning, cat, msg);
}
inline void logError(std::string_view cat, std::string_view msg) {
    logMessage(LogLevel::Error, cat, msg);
}

const char* nameFor(LogLevel level);

} // namespace ocu
