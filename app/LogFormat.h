#pragma once
// How the console's log lines look on stderr, by where stderr goes:
//   Journal  — stderr is the systemd journal's stream (JOURNAL_STREAM names its device:inode,
//   systemd.exec(5)):
//              each line starts with the sd-daemon priority "<N>" (sd-daemon(3)), no colour.
//   Terminal — a TTY: the level word coloured (ANSI SGR).
//   Plain    — a file or a pipe: no colour codes.
// Always one line per message (line breaks inside a message become spaces), so a journal entry, a grep
// match or a log collector's record is one whole event.
#include <QByteArray>
#include <QString>
#include <QtGlobal>

namespace ocu {

enum class LogStyle { Journal, Terminal, Plain };

// The style for output on file descriptor fd, with journalStream the value of JOURNAL_STREAM (may be null).
LogStyle logStyleFor(int fd, const char* journalStream);
// The sd-daemon priority of a Qt message type: debug 7, info 6, warning 4, critical 3, fatal 2.
int journalPriority(QtMsgType type);
// One log line, '\n' included; `text` is the message already formatted (qFormatLogMessage: category and
// text).
QByteArray formatLogLine(LogStyle style, QtMsgType type, const QString& text);

// Qt's message handler for the console process: every qDebug/qInfo/qWarning/qCritical (and the protocol
// libraries' messages, routed there by LogRouting) written to stderr as above. Called once from main(); tests
// keep Qt Test's own handler.
void installConsoleLogFormat();

} // namespace ocu
