// The built-in simulated site is recorded while it runs (the console's own recorder,
// in-process), then replayed: the fleet model at T (half-way) equals the live one at T (positions within 1
// cm, same states, same staleness, same alarms and acknowledgements); seeking backwards and forwards lands on
// the same picture. And the real `ocu` killed with SIGKILL while recording: the file opens cleanly and at
// most 1 s before the kill is missing.
//
// Duration: OCU_RECORD_TEST_SECONDS (default 60: the minute, compared at T = 30 s; a shorter run for
// quick iterations is e.g. `OCU_RECORD_TEST_SECONDS=10 ctest -R test_record_replay`).
#include "app/SiteLoader.h"
#include "app/SiteRuntime.h"
#include "models/AlarmModel.h"
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/ModelClock.h"
#include "models/recording/RecordCodec.h"
#include "models/recording/Recorder.h"
#include "models/recording/Recording.h"
#include "models/recording/ReplayController.h"
#include "tests/support/BuiltProtocols.h"
#include "tests/support/RecordedUgvs.h"

#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

#include <algorithm>

#include <cmath>
#include <csignal>

#include <sqlite3.h>

using namespace ocu;
using namespace ocu::recording;

namespace {

// The time the console's models and its recorder stamp with (models/ModelClock.h): the run's instants are
// taken on it, so "the picture at T" and the records' times compare like with like.
qint64 modelNow() {
    return systemModelClock()->nowMs();
}

// Machines the checks expect at least: 8 of the built-in site's, or fewer where this build leaves a protocol
// out (each brings at least: JAUS 2 UGVs, ISO 23725 6 trucks, OSYRIS 2 rollers).
constexpr int kSiteMachines = std::min(8, (ocutest::kWithJaus ? 2 : 0) + (ocutest::kWithIso23725 ? 6 : 0) +
                                              (ocutest::kWithOsyris ? 2 : 0));

struct Picture {
    QHash<QString, MachineState> machines;
    QHash<QString, bool> stale;
    // Machines whose data age at the picture's time is within 1 s of their staleness threshold: the live
    // model evaluated staleness at its refresh, the replay at the recorded time; on a loaded machine the two
    // instants can straddle the threshold, so staleness is not compared for these.
    QSet<QString> nearStaleBoundary;
    int alarms = 0, unacked = 0;
};

// What a recording made with record.messages and record.raw holds (recordsEveryProtocolsMessages).
struct RecordedMessages {
    bool opened = false;
    QString bad; // a message out of order, outside the run or not matching its channel
    int n = 0;
    QHash<QString, QSet<QString>> types, rawOf; // per protocol: message types, raw links
    bool hasPassCounts = false, replayHasPassCounts = false;
    qint64 coveredCells = 0; // in the replay's pass counts at the end
    bool complete() const {
        // Each protocol of this build (tests/support/BuiltProtocols.h).
        return opened && bad.isEmpty() && n > 100 &&
               (!ocutest::kWithOsyris ||
                (types.value(QStringLiteral("osyris")).contains(QStringLiteral("CmPos")) &&
                 !rawOf.value(QStringLiteral("osyris")).isEmpty() && hasPassCounts && replayHasPassCounts &&
                 coveredCells > 0)) &&
               (!ocutest::kWithIso23725 ||
                (types.value(QStringLiteral("iso23725")).contains(QStringLiteral("FleetDefinitionV2")) &&
                 !rawOf.value(QStringLiteral("iso23725")).isEmpty())) &&
               (!ocutest::kWithJaus || (types.value(QStringLiteral("jaus")).size() >= 3 &&
                                        !rawOf.value(QStringLiteral("jaus")).isEmpty()));
    }
};

// Reads the messages of the recording in `file` (messages received between tStart and tEnd) and replays
// its end for the pass counts.
RecordedMessages inspectMessages(const QString& file, qint64 tStart, qint64 tEnd) {
    RecordedMessages out;
    auto rec = Recording::open(file);
    if (!rec)
        return out;
    out.opened = true;
    const auto channels = rec->messageChannels();
    qint64 last = 0;
    rec->messages(0, std::numeric_limits<qint64>::max(), [&](const RecordedMessage& m) {
        const MessageChannel c = channels.value(m.channel);
        ++out.n;
        if (m.t < last || m.t < tStart || m.t > tEnd)
            out.bad = QStringLiteral("time %1 out of order or outside the run").arg(m.t);
        last = m.t;
        if (m.raw) {
            out.rawOf[c.protocol].insert(c.link);
            return true;
        }
        out.types[c.protocol].insert(c.type);
        if (c.protocol == QLatin1String("jaus") &&
            (m.bytes.size() < 2 ||
             c.type != QStringLiteral("%1")
                           .arg(quint8(m.bytes[0]) | quint8(m.bytes[1]) << 8, 4, 16, QLatin1Char('0'))
                           .toUpper()))
            out.bad = QStringLiteral("JAUS type %1 does not match its message code").arg(c.type);
        if (c.protocol == QLatin1String("iso23725") && c.type != QLatin1String("MapDocument") &&
            !m.bytes.contains(c.type.section(QLatin1Char('+'), 0, 0).toUtf8()))
            out.bad = QStringLiteral("ISO 23725 type %1 not in its frame").arg(c.type);
        if (c.protocol == QLatin1String("osyris") && c.type == QLatin1String("CmPos") && m.bytes.size() != 73)
            out.bad = QStringLiteral("CmPos of %1 bytes").arg(m.bytes.size());
        if (c.peer.isEmpty() && c.protocol != QLatin1String("iso23725"))
            out.bad = QStringLiteral("%1 message without a peer").arg(c.protocol);
        return out.bad.isEmpty();
    });
    out.hasPassCounts = rec->hasPassCounts();
    if (out.hasPassCounts) {
        FleetModel fleet;
        ReplayController replay(rec.get(), &fleet);
        replay.seek(rec->endMs());
        out.replayHasPassCounts = replay.passCounts() != nullptr;
        if (out.replayHasPassCounts)
            out.coveredCells = qint64(summarize(*replay.passCounts(), PassTarget{}).coveredCells);
    }
    return out;
}

Picture pictureOf(const FleetModel& fleet, const AlarmModel& alarms) {
    Picture p;
    for (const MachineState& m : fleet.machinesSnapshot()) {
        p.machines.insert(m.id, m);
        p.stale.insert(m.id, fleet.isStale(m.id));
        if (std::abs(fleet.nowMs() - m.lastDataMs - fleet.staleAfterMs(m.protocol)) < 1000)
            p.nearStaleBoundary.insert(m.id);
    }
    p.alarms = alarms.rowCount();
    p.unacked = alarms.unacknowledgedCount();
    return p;
}

QString compare(const Picture& live, const Picture& replay) {
    if (live.machines.size() != replay.machines.size())
        return QStringLiteral("%1 machines live, %2 replayed")
            .arg(live.machines.size())
            .arg(replay.machines.size());
    for (auto it = live.machines.cbegin(); it != live.machines.cend(); ++it) {
        const MachineState& a = *it;
        if (!replay.machines.contains(a.id))
            return a.id + QStringLiteral(" not replayed");
        const MachineState& b = replay.machines[a.id];
        if (!sameStatus(a, b))
            return a.id + QStringLiteral(": state differs (%1/%2 vs %3/%4)")
                              .arg(a.modeText, toText(a.stop), b.modeText, toText(b.stop));
        const double d = std::hypot(a.e - b.e, a.n - b.n, a.u - b.u);
        if (d > 0.01)
            return a.id + QStringLiteral(": %1 m apart").arg(d);
        if (live.stale.value(a.id) != replay.stale.value(a.id) && !live.nearStaleBoundary.contains(a.id))
            return a.id + QStringLiteral(": staleness differs");
    }
    if (live.alarms != replay.alarms || live.unacked != replay.unacked)
        return QStringLiteral("alarms %1 (%2 unacknowledged) live, %3 (%4) replayed")
            .arg(live.alarms)
            .arg(live.unacked)
            .arg(replay.alarms)
            .arg(replay.unacked);
    return {};
}

} // namespace

class TestRecordReplay : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void replayEqualsLive() {
        const int seconds = qEnvironmentVariableIsSet("OCU_RECORD_TEST_SECONDS")
                                ? std::max(4, qEnvironmentVariableIntValue("OCU_RECORD_TEST_SECONDS"))
                                : 60;
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        auto site = loadSite({});
        QVERIFY(site.ok());
        SiteConfig cfg = std::move(site.value());
        cfg.record.dir = dir.path().toStdString();
        QString file;
        Picture live;
        qint64 tLive = 0, tStart = 0;
        {
            SiteRuntime runtime(cfg);
            runtime.start();
            QVERIFY(runtime.recorder());
            file = runtime.recorder()->path();
            auto* ctx = runtime.findChild<FleetContext*>();
            QVERIFY(ctx);
            tStart = modelNow();
            QTest::qWait(seconds * 500);
            // An operator acknowledges what is there, so acknowledgements are part of the picture.
            ctx->alarms()->acknowledgeAll();
            QTest::qWait(300);
            // The live picture at T: staleness evaluated now; records made after this instant carry a later
            // time (the 2 ms pause), records before it an earlier or equal one.
            ctx->fleet()->refresh();
            tLive = modelNow();
            live = pictureOf(*ctx->fleet(), *ctx->alarms());
            QThread::msleep(2);
            QVERIFY2(int(live.machines.size()) >= kSiteMachines, "the simulated site's machines");
            QTest::qWait(seconds * 500);
            runtime.stop();
            QCOMPARE(runtime.recorder()->stats().dropped, 0u);
        }
        auto rec = Recording::open(file);
        QVERIFY(rec);
        QVERIFY(rec->startMs() <= tStart);
        QVERIFY(rec->endMs() >= tLive + seconds * 400);

        FleetModel fleet;
        ReplayController replay(rec.get(), &fleet);
        replay.seek(tLive);
        QString diff = compare(live, pictureOf(fleet, *replay.alarms()));
        QVERIFY2(diff.isEmpty(), qPrintable(diff));
        QVERIFY(live.alarms > 0);
        // The comparison sees a difference of 2 s (the trucks moved): it is not vacuous.
        replay.seek(tLive - 2000);
        QVERIFY(!compare(live, pictureOf(fleet, *replay.alarms())).isEmpty());

        // Backwards and forwards again: the same picture.
        replay.seek(rec->endMs());
        replay.seek(rec->startMs() + 500);
        replay.seek(tLive);
        diff = compare(live, pictureOf(fleet, *replay.alarms()));
        QVERIFY2(diff.isEmpty(), qPrintable("after seeking back: " + diff));
        // Playing forward from before T (no seek) lands on it too.
        replay.seek(tLive - 7000);
        for (qint64 t = tLive - 7000; t < tLive;) {
            t = std::min(tLive, t + 333);
            replay.moveTo(t);
        }
        diff = compare(live, pictureOf(fleet, *replay.alarms()));
        QVERIFY2(diff.isEmpty(), qPrintable("after playing forward: " + diff));
    }

    // The simulated site's inbound messages of every protocol are in the file with their type,
    // peer and receive time when record.messages is on (off by default); with record.raw the raw frames too.
    void recordsEveryProtocolsMessages() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        auto site = loadSite({});
        QVERIFY(site.ok());
        SiteConfig cfg = std::move(site.value());
        cfg.record.dir = dir.path().toStdString();
        cfg.record.raw = true;
        cfg.record.messages = true;
        QString file;
        qint64 tStart = 0, tEnd = 0;
        {
            SiteRuntime runtime(cfg);
            tStart = modelNow();
            runtime.start();
            QVERIFY(runtime.recorder());
            file = runtime.recorder()->path();
            // Recording until the file holds everything asserted below (read while it is written, as a
            // replay of a running console does), at most a minute.
            QElapsedTimer waited;
            waited.start();
            for (;;) {
                const RecordedMessages now = inspectMessages(file, tStart, modelNow());
                if (now.complete() || !now.bad.isEmpty() || waited.elapsed() > 60000)
                    break;
                QTest::qWait(250);
            }
            runtime.stop();
            tEnd = modelNow();
            QCOMPARE(runtime.recorder()->stats().dropped, 0u);
        }
        // The whole file once the recorder closed it.
        const RecordedMessages m = inspectMessages(file, tStart, tEnd);
        QVERIFY(m.opened);
        QVERIFY2(m.bad.isEmpty(), qPrintable(m.bad));
        QVERIFY(m.n > 100);
        if (ocutest::kWithOsyris) {
            QVERIFY2(m.types.value(QStringLiteral("osyris")).contains(QStringLiteral("CmPos")),
                     qPrintable(QStringList(m.types.value(QStringLiteral("osyris")).values()).join(',')));
            QVERIFY(!m.rawOf.value(QStringLiteral("osyris")).isEmpty());
            // The rollers' pass counts are recorded, and the replay at the end shows covered cells.
            QVERIFY(m.hasPassCounts);
            QVERIFY(m.replayHasPassCounts);
            QVERIFY(m.coveredCells > 0);
        }
        if (ocutest::kWithIso23725) {
            QVERIFY2(m.types.value(QStringLiteral("iso23725")).contains(QStringLiteral("FleetDefinitionV2")),
                     qPrintable(QStringList(m.types.value(QStringLiteral("iso23725")).values()).join(',')));
            QVERIFY(!m.rawOf.value(QStringLiteral("iso23725")).isEmpty());
        }
        if (ocutest::kWithJaus) {
            QVERIFY(m.types.value(QStringLiteral("jaus")).size() >= 3);
            QVERIFY(!m.rawOf.value(QStringLiteral("jaus")).isEmpty());
        }
    }

    // Without record.dir the run records into OCU_RECORD_DIR (tests: a temporary folder, never the
    // user's home), and retention by age and size is enforced there at start.
    void recordsIntoOcuRecordDirWithRetention() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QByteArray saved = qgetenv("OCU_RECORD_DIR");
        qputenv("OCU_RECORD_DIR", dir.path().toUtf8());
        auto make = [&](const QString& name, int kb, int ageDays) {
            QFile f(dir.filePath(name));
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray(kb * 1024, 'r'));
            f.flush(); // before the time is set: a later write would make the file fresh
            f.setFileTime(QDateTime::currentDateTimeUtc().addDays(-ageDays),
                          QFileDevice::FileModificationTime);
        };
        make(QStringLiteral("ocu-20260101-000000-1.sqlite"), 10, 40); // older than max_age_days
        make(QStringLiteral("ocu-20261101-000000-2.sqlite"), 900, 3); // the oldest beyond max_total_mb
        make(QStringLiteral("ocu-20261120-000000-3.sqlite"), 300, 2); // fits
        auto site = loadSite({});
        QVERIFY(site.ok());
        SiteConfig cfg = std::move(site.value());
        cfg.simulation.enabled = false;
        cfg.record.dir.clear();
        cfg.record.maxAgeDays = 30;
        cfg.record.maxTotalMb = 1;
        {
            SiteRuntime runtime(cfg);
            runtime.start();
            QVERIFY(runtime.recorder());
            QCOMPARE(QFileInfo(runtime.recorder()->path()).absolutePath(),
                     QFileInfo(dir.path()).absoluteFilePath());
            runtime.stop();
        }
        if (saved.isNull())
            qunsetenv("OCU_RECORD_DIR");
        else
            qputenv("OCU_RECORD_DIR", saved);
        const QStringList left =
            QDir(dir.path()).entryList({QStringLiteral("ocu-*.sqlite")}, QDir::Files, QDir::Name);
        QVERIFY2(left.size() == 2, qPrintable(left.join(QLatin1Char(' '))));
        QCOMPARE(left.first(), QStringLiteral("ocu-20261120-000000-3.sqlite"));
    }

    // kill -9 during recording: the file opens, at most 1 s is missing.
    void killNineLosesAtMostOneSecond() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QProcess ocu;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        ocu.setProcessEnvironment(env);
        ocu.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        ocu.start(QStringLiteral(OCU_BINARY),
                  {QStringLiteral("--headless"), QStringLiteral("--duration"), QStringLiteral("120"),
                   QStringLiteral("--record"), dir.path()});
        QVERIFY(ocu.waitForStarted(10000));
        // Recording and machines moving: wait for the file to hold machine data for a while.
        QString file;
        QTRY_VERIFY_WITH_TIMEOUT(
            !(file = QDir(dir.path()).entryList({QStringLiteral("ocu-*.sqlite")}).value(0)).isEmpty(), 30000);
        file = dir.filePath(file);
        qint64 firstData = 0;
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                auto r = Recording::open(file);
                if (!r || int(r->statesAt(r->endMs()).size()) < kSiteMachines)
                    return false;
                if (firstData == 0)
                    firstData = r->endMs();
                return r->endMs() - firstData >= 3000;
            }(),
            60000);
        const qint64 killedAt = modelNow();
        ::kill(pid_t(ocu.processId()), SIGKILL);
        QVERIFY(ocu.waitForFinished(10000));
        QCOMPARE(ocu.exitStatus(), QProcess::CrashExit);
        QString err;
        auto rec = Recording::open(file, &err);
        QVERIFY2(rec, qPrintable(err));
        QVERIFY(rec->meta(QStringLiteral("closed")).isEmpty()); // it really was cut off
        QVERIFY2(killedAt - rec->endMs() <= 1000,
                 qPrintable(QStringLiteral("%1 ms missing").arg(killedAt - rec->endMs())));
        QVERIFY(int(rec->statesAt(rec->endMs()).size()) >= kSiteMachines);
        // The whole file is intact.
        sqlite3* db = nullptr;
        QCOMPARE(sqlite3_open_v2(file.toUtf8().constData(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
        sqlite3_stmt* st = nullptr;
        QCOMPARE(sqlite3_prepare_v2(db, "PRAGMA integrity_check", -1, &st, nullptr), SQLITE_OK);
        QCOMPARE(sqlite3_step(st), SQLITE_ROW);
        const QByteArray verdict(reinterpret_cast<const char*>(sqlite3_column_text(st, 0)));
        sqlite3_finalize(st);
        sqlite3_close(db);
        QCOMPARE(verdict, QByteArray("ok"));
    }

    // Replay and export on the real binary: `ocu --replay FILE --at T --screenshot out.png` (the window with
    // its REPLAY banner at the size asked for), `ocu --replay FILE --headless` (the JSON lines of the run,
    // ending on the recorded end) and the exports (JSON lines, CSV per machine, a slice that replays).
    void replayAndExportFromTheCommandLine() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString file = dir.filePath(QStringLiteral("cli.sqlite"));
        const qint64 t0 = 1'700'000'000'000;
        {
            // 20 s of two machines at 10 Hz, an alarm at +5 s.
            auto clock = std::make_shared<ManualModelClock>(t0);
            Recorder rec;
            RecorderOptions o;
            o.path = file;
            o.clock = clock;
            QVERIFY(rec.start(o).isEmpty());
            recordtest::recordTwoUgvs(rec, *clock, t0, 200, [&](int step) {
                if (step == 50)
                    rec.recordEvent(recordtest::controlLostAlarm(clock->nowMs()));
            });
            rec.stop();
        }
        auto run = [&](const QStringList& args, QByteArray* out = nullptr) {
            QProcess p;
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
            env.remove(QStringLiteral("DISPLAY"));
            env.insert(QStringLiteral("OCU_RECORD_DIR"), dir.filePath(QStringLiteral("rec")));
            p.setProcessEnvironment(env);
            p.setProcessChannelMode(QProcess::SeparateChannels);
            p.start(QStringLiteral(OCU_BINARY), args);
            if (!p.waitForFinished(120000)) {
                p.kill();
                p.waitForFinished();
                return -1;
            }
            if (out)
                *out = p.readAllStandardOutput();
            const QByteArray err = p.readAllStandardError();
            if (p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0)
                qWarning("ocu %s: %s", qPrintable(args.join(QLatin1Char(' '))), err.constData());
            return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
        };

        // The window at +10 s, 1366x768: the purple REPLAY banner across the top.
        const QString png = dir.filePath(QStringLiteral("replay.png"));
        QCOMPARE(run({QStringLiteral("--replay"), file, QStringLiteral("--at"), QStringLiteral("10"),
                      QStringLiteral("--screenshot"), png, QStringLiteral("--size"),
                      QStringLiteral("1366x768"), QStringLiteral("--settle"), QStringLiteral("1")}),
                 0);
        QImage img(png);
        QVERIFY(!img.isNull());
        QCOMPARE(img.size(), QSize(1366, 768));
        int purple = 0;
        for (int y = 0; y < 120; ++y)
            for (int x = 0; x < img.width(); x += 4)
                if (img.pixelColor(x, y) == QColor(0x7b, 0x1f, 0xa2))
                    ++purple;
        QVERIFY2(purple > 200, qPrintable(QStringLiteral("%1 banner pixels").arg(purple)));
        // A time that is no time is refused.
        QVERIFY(run({QStringLiteral("--replay"), file, QStringLiteral("--at"), QStringLiteral("soon"),
                     QStringLiteral("--headless")}) != 0);

        // Headless: machine lines for both machines, the alarm, replay stamps in time order up to the end;
        // the last machine line of jaus:100 is its last recorded position.
        QByteArray out;
        QCOMPARE(run({QStringLiteral("--replay"), file, QStringLiteral("--headless")}, &out), 0);
        QSet<QString> ids;
        qint64 lastStamp = 0;
        int stamps = 0, alarms = 0;
        double lastE = -1;
        for (const QByteArray& line : out.split('\n')) {
            if (line.isEmpty())
                continue;
            QJsonParseError pe;
            const QJsonObject o = QJsonDocument::fromJson(line, &pe).object();
            QVERIFY2(pe.error == QJsonParseError::NoError, line.constData());
            const QString type = o.value(QStringLiteral("type")).toString();
            if (type == QLatin1String("replay")) {
                const qint64 t =
                    QDateTime::fromString(o.value(QStringLiteral("time")).toString(), Qt::ISODateWithMs)
                        .toMSecsSinceEpoch();
                QVERIFY(t >= lastStamp);
                lastStamp = t;
                ++stamps;
            } else if (type == QLatin1String("machine")) {
                ids.insert(o.value(QStringLiteral("id")).toString());
                if (o.value(QStringLiteral("id")).toString() == QLatin1String("jaus:100"))
                    lastE = o.value(QStringLiteral("e")).toDouble();
            } else if (type == QLatin1String("event") &&
                       o.value(QStringLiteral("text")).toString().contains(QLatin1String("control lost"))) {
                ++alarms;
            }
        }
        QCOMPARE(ids, (QSet<QString>{QStringLiteral("jaus:100"), QStringLiteral("jaus:101")}));
        QCOMPARE(alarms, 1);
        QVERIFY(stamps >= 100); // 20 s in steps of 100 ms
        QCOMPARE(lastStamp, t0 + 20'000);
        QCOMPARE(lastE, 100.0);

        // Exports of +5 s .. +15 s.
        const QString jsonl = dir.filePath(QStringLiteral("w.jsonl")),
                      csv = dir.filePath(QStringLiteral("w.csv")),
                      slice = dir.filePath(QStringLiteral("slice.sqlite"));
        QCOMPARE(run({QStringLiteral("--replay"), file, QStringLiteral("--export-jsonl"), jsonl,
                      QStringLiteral("--export-csv"), csv, QStringLiteral("--export-slice"), slice,
                      QStringLiteral("--from"), QStringLiteral("5"), QStringLiteral("--to"),
                      QStringLiteral("15")}),
                 0);
        QFile j(jsonl), c(csv);
        QVERIFY(j.open(QIODevice::ReadOnly) && c.open(QIODevice::ReadOnly));
        int machineLines = 0, eventLines = 0;
        for (const QByteArray& line : j.readAll().split('\n')) {
            const QJsonObject o = QJsonDocument::fromJson(line).object();
            const qint64 t = qint64(o.value(QStringLiteral("t")).toDouble());
            if (o.isEmpty())
                continue;
            QVERIFY2(t >= t0 + 5000 && t <= t0 + 15'000, line.constData());
            machineLines += o.value(QStringLiteral("type")).toString() == QLatin1String("machine");
            eventLines += o.value(QStringLiteral("type")).toString() == QLatin1String("event");
        }
        QVERIFY2(machineLines >= 190 && machineLines <= 204, qPrintable(QString::number(machineLines)));
        QCOMPARE(eventLines, 1);
        const QList<QByteArray> rows = c.readAll().trimmed().split('\n');
        QVERIFY(rows.first().startsWith("time,t_ms,id,name,protocol,e,n"));
        int rows100 = 0;
        for (const QByteArray& row : rows.mid(1))
            rows100 += row.split(',').value(2) == "jaus:100";
        QVERIFY2(rows100 >= 95 && rows100 <= 102, qPrintable(QString::number(rows100)));
        auto part = Recording::open(slice);
        QVERIFY(part);
        QCOMPARE(part->startMs(), t0 + 5000);
        QCOMPARE(part->statesAt(t0 + 12'000).value(QStringLiteral("jaus:100")).e, 60.0);
        // A slice is never written over.
        QVERIFY(run({QStringLiteral("--replay"), file, QStringLiteral("--export-slice"), slice}) != 0);
    }
};

QTEST_MAIN(TestRecordReplay)
#include "test_record_replay.moc"
