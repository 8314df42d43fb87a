#include "protocols/common/Log.h"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace ocu {
namespace {
std::mutex g_mutex;
LogSink g_sink;
std::atomic<int> g_threshold{static_cast<int>(LogLevel::Info)};
} // namespace

const char* nameFor(LogLevel level) {
    switch (level) {
    case LogLevel::Debug:
        return "debug";
    case LogLevel::Info:
        return "info";
    case LogLevel::Warning:
        return "warning";
    case LogLevel::Error:
        return "error";
    }
    return "?";
}

void setLogSink(LogSink sink) {
    std::lock_guard lock(g_mutex);
    g_sink = std::move(sink);
}

void setLogThreshold(LogLevel level) {
    g_threshold = static_cast<int>(level);
}

bool logEnabled(LogLevel level) {
    return static_cast<int>(level) >= g_threshold.load();
}

void logMessage(LogLevel level, std::string_view category, std::string_view message) {
    if (!logEnabled(level))
        return;
    LogSink sink;
    {
        std::lock_guard lock(g_mutex);
        sink = g_sink;
    }
    if (sink) {
        sink(level, category, message);
        return;
    }
    std::fprintf(stderr, "[%s] %.*s: %.*s\n", nameFor(level), static_cast<int>(category.size()),
                 category.data(), static_cast<int>(message.size()), message.data());
}

} // namespace ocu
