#include "app/LogFormat.h"

#include <cstdio>
#include <cstdlib>

#include <sys/stat.h>
#include <unistd.h>

namespace ocu {

namespace {

LogStyle g_style = LogStyle::Plain;

const char* levelWord(QtMsgType type) {
    switch (type) {
    case QtDebugMsg:
        return "debug";
    case QtInfoMsg:
        return "info";
    case QtWarningMsg:
        return "warning";
    case QtCriticalMsg:
        return "error";
    case QtFatalMsg:
        return "fatal";
    }
    return "info";
}

// SGR colours of the level word on a terminal: errors red, warnings yellow, debug dim.
const char* levelColour(QtMsgType type) {
    switch (type) {
    case QtDebugMsg:
        return "\x1b[2m";
    case QtInfoMsg:
        return "";
    case QtWarningMsg:
        return "\x1b[33m";
    case QtCriticalMsg:
    case QtFatalMsg:
        return "\x1b[1;31m";
    }
    return "";
}

void writeMessage(QtMsgType type, const QMessageLogContext& context, const QString& message) {
    const QByteArray line = formatLogLine(g_style, type, qFormatLogMessage(type, context, message));
    // One write(2) per line: lines of different threads do not interleave.
    [[maybe_unused]] const ssize_t n =
        ::write(STDERR_FILENO, line.constData(), static_cast<size_t>(line.size()));
}

} // namespace

LogStyle logStyleFor(int fd, const char* journalStream) {
    struct stat st {};
    if (journalStream && *journalStream && ::fstat(fd, &st) == 0) {
        // "device:inode" in decimal, as systemd writes it (systemd.exec(5), $JOURNAL_STREAM).
        unsigned long long dev = 0, ino = 0;
        if (std::sscanf(journalStream, "%llu:%llu", &dev, &ino) == 2 && dev == st.st_dev && ino == st.st_ino)
            return LogStyle::Journal;
    }
    return ::isatty(fd) ? LogStyle::Terminal : LogStyle::Plain;
}

int journalPriority(QtMsgType type) {
    switch (type) {
    case QtDebugMsg:
        return 7; // LOG_DEBUG
    case QtInfoMsg:
        return 6; // LOG_INFO
    case QtWarningMsg:
        return 4; // LOG_WARNING
    case QtCriticalMsg:
        return 3; // LOG_ERR
    case QtFatalMsg:
        return 2; // LOG_CRIT
    }
    return 6;
}

QByteArray formatLogLine(LogStyle style, QtMsgType type, const QString& text) {
    QByteArray body = text.toUtf8();
    while (body.endsWith('\n'))
        body.chop(1);
    body.replace('\n', ' ');
    QByteArray line;
    switch (style) {
    case LogStyle::Journal:
        // The priority carries the level; the journal adds time, unit and process.
        line = '<' + QByteArray::number(journalPriority(type)) + '>' + body;
        break;
    case LogStyle::Terminal:
    case LogStyle::Plain:
        if (type != QtInfoMsg) {
            const bool colour = style == LogStyle::Terminal && *levelColour(type);
            line = (colour ? QByteArray(levelColour(type)) : QByteArray()) + levelWord(type) +
                   (colour ? "\x1b[0m" : "") + ": ";
        }
        line += body;
        break;
    }
    return line + '\n';
}

void installConsoleLogFormat() {
    g_style = logStyleFor(STDERR_FILENO, std::getenv("JOURNAL_STREAM"));
    qInstallMessageHandler(writeMessage);
}

} // namespace ocu
