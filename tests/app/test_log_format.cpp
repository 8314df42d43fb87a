// The console's log lines on stderr: the journal's priority prefix when stderr is the journal's stream, no
// colour codes when it is not a terminal, one line per message; and the real `ocu` writing them so.
#include "app/LogFormat.h"

#include <QProcess>
#include <QtTest>

#include <sys/stat.h>
#include <unistd.h>

using namespace ocu;

class TestLogFormat : public QObject {
    Q_OBJECT

    static QByteArray devIno(int fd) {
        struct stat st {};
        if (::fstat(fd, &st) != 0)
            return {};
        return QByteArray::number(static_cast<qulonglong>(st.st_dev)) + ':' +
               QByteArray::number(static_cast<qulonglong>(st.st_ino));
    }

private slots:
    void styleFollowsWhereStderrGoes() {
        int fds[2];
        QCOMPARE(::pipe(fds), 0);
        // JOURNAL_STREAM naming this very pipe: the journal; naming another file, or unset: plain (a pipe is
        // no terminal).
        QCOMPARE(logStyleFor(fds[1], devIno(fds[1]).constData()), LogStyle::Journal);
        int other[2];
        QCOMPARE(::pipe(other), 0);
        QCOMPARE(logStyleFor(fds[1], devIno(other[1]).constData()), LogStyle::Plain);
        QCOMPARE(logStyleFor(fds[1], nullptr), LogStyle::Plain);
        QCOMPARE(logStyleFor(fds[1], "garbage"), LogStyle::Plain);
        for (int fd : {fds[0], fds[1], other[0], other[1]})
            ::close(fd);
    }
    void journalLinesCarryThePriority() {
        QCOMPARE(formatLogLine(LogStyle::Journal, QtDebugMsg, "ocu.jaus: d"), QByteArray("<7>ocu.jaus: d\n"));
        QCOMPARE(formatLogLine(LogStyle::Journal, QtInfoMsg, "ocu.iso: link up"),
                 QByteArray("<6>ocu.iso: link up\n"));
        QCOMPARE(formatLogLine(LogStyle::Journal, QtWarningMsg, "ocu.iso: w"), QByteArray("<4>ocu.iso: w\n"));
        QCOMPARE(formatLogLine(LogStyle::Journal, QtCriticalMsg, "ocu.app: c"),
                 QByteArray("<3>ocu.app: c\n"));
        QCOMPARE(journalPriority(QtFatalMsg), 2);
    }
    void oneLinePerMessage() {
        for (LogStyle s : {LogStyle::Journal, LogStyle::Plain, LogStyle::Terminal}) {
            const QByteArray line = formatLogLine(s, QtWarningMsg, "first\nsecond\n");
            QCOMPARE(line.count('\n'), 1);
            QVERIFY(line.endsWith("first second\n"));
        }
    }
    void colourOnlyOnATerminal() {
        for (QtMsgType t : {QtDebugMsg, QtInfoMsg, QtWarningMsg, QtCriticalMsg}) {
            QVERIFY(!formatLogLine(LogStyle::Plain, t, "x").contains('\x1b'));
            QVERIFY(!formatLogLine(LogStyle::Journal, t, "x").contains('\x1b'));
        }
        QCOMPARE(formatLogLine(LogStyle::Plain, QtWarningMsg, "ocu.iso: w"),
                 QByteArray("warning: ocu.iso: w\n"));
        QVERIFY(formatLogLine(LogStyle::Terminal, QtCriticalMsg, "e").contains("\x1b[1;31merror\x1b[0m"));
    }
    // The real console under a JOURNAL_STREAM naming its stderr: every log line has a priority prefix and no
    // colour code.
    void consoleWritesJournalLines() {
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        env.insert("QT_QPA_PLATFORM", "offscreen");
        env.insert("OCU_THREAD_PRIORITY", "nice"); // its one log line about the stop-path priority
        p.setProcessEnvironment(env);
        // The shell learns stderr's device:inode (the pipe to this test) and hands it on, as systemd does.
        p.start("/bin/sh", {"-c",
                            "JOURNAL_STREAM=$(stat -L -c %d:%i /proc/self/fd/2) exec \"$0\" --headless "
                            "--duration 1 --no-record --log 'ocu.*' </dev/null",
                            OCU_BINARY});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        const QList<QByteArray> lines = p.readAllStandardError().split('\n');
        int prefixed = 0;
        for (const QByteArray& l : lines) {
            QVERIFY2(!l.contains('\x1b'), l.constData());
            static const QRegularExpression prio("^<[0-7]>\\S");
            if (prio.match(QString::fromUtf8(l)).hasMatch())
                ++prefixed;
        }
        QVERIFY2(prefixed >= 3, qPrintable(QString::number(prefixed)));
    }
};

QTEST_GUILESS_MAIN(TestLogFormat)
#include "test_log_format.moc"
