// Flight recorder and recording reader: what is recorded reads back as it was at any time
// (keyframe seek and forward play agree, both directions), alarms and acknowledgements as of the replay time,
// the bounded queue drops and counts instead of growing, exports (JSON lines, CSV, slice), hostile blobs.
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/FleetBridge.h"
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/recording/RecordCodec.h"
#include "models/recording/RecordSchema.h"
#include "models/recording/Recorder.h"
#include "models/recording/Recording.h"
#include "models/recording/ReplayController.h"
#include "protocols/common/GeoFrame.h"
#include "protocols/common/MessageTap.h"

#include <QBuffer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <sqlite3.h>

#include <cmath>
#include <random>

using namespace ocu;
using namespace ocu::recording;

namespace {

MachineState machine(const QString& id, double e, double n) {
    MachineState m;
    m.id = id;
    m.protocol = Protocol::Iso23725;
    m.name = id.toUpper();
    m.type = QStringLiteral("haul truck");
    m.link = LinkState::Up;
    m.hasPosition = true;
    m.e = e;
    m.n = n;
    m.u = 1.5;
    m.lat = 48.2 + n * 1e-5;
    m.lon = 11.4 + e * 1e-5;
    m.headingDeg = 90;
    m.speed = 8.25;
    m.modeText = QStringLiteral("Autonomous");
    m.mode = ModeCategory::Autonomous;
    m.stop = StopState::None;
    m.health = HealthLevel::Ok;
    return m;
}

// The test's own picture: what the fleet was after every record up to t.
struct Truth {
    QMap<qint64, QHash<QString, MachineState>> at; // t -> picture after the records at t
    QHash<QString, MachineState> now;
    void set(qint64 t, const MachineState& m) {
        now.insert(m.id, m);
        at[t] = now;
    }
    void remove(qint64 t, const QString& id) {
        now.remove(id);
        at[t] = now;
    }
    QHash<QString, MachineState> pictureAt(qint64 t) const {
        auto it = at.upperBound(t);
        if (it == at.begin())
            return {};
        return *std::prev(it);
    }
};

bool samePicture(const QHash<QString, MachineState>& a, const QHash<QString, MachineState>& b, QString* why) {
    if (a.size() != b.size()) {
        *why = QStringLiteral("%1 machines vs %2").arg(a.size()).arg(b.size());
        return false;
    }
    for (auto it = a.cbegin(); it != a.cend(); ++it) {
        auto o = b.constFind(it.key());
        if (o == b.cend()) {
            *why = it.key() + QStringLiteral(" missing");
            return false;
        }
        if (!sameStatus(*it, *o)) {
            *why = it.key() + QStringLiteral(" status differs");
            return false;
        }
        if (std::hypot(it->e - o->e, it->n - o->n) > 0.01 || std::abs(it->u - o->u) > 0.01 ||
            std::abs(it->speed - o->speed) > 1e-3 || it->lastDataMs != o->lastDataMs) {
            *why = QStringLiteral("%1 at %2,%3 vs %4,%5")
                       .arg(it.key())
                       .arg(it->e)
                       .arg(it->n)
                       .arg(o->e)
                       .arg(o->n);
            return false;
        }
    }
    return true;
}

// Schema 4's resolution (RecordCodec.h): e/n/u 1 cm, heading 0.01 deg, speed 0.01 m/s (each rounded: half of
// it), lat/lon 1e-7 deg; times and everything else exact.
bool withinResolution(const QHash<QString, MachineState>& got, const QHash<QString, MachineState>& want,
                      QString* why) {
    if (got.size() != want.size()) {
        *why = QStringLiteral("%1 machines vs %2").arg(got.size()).arg(want.size());
        return false;
    }
    constexpr double slack = 1e-9;
    for (auto w = want.cbegin(); w != want.cend(); ++w) {
        auto g = got.constFind(w.key());
        if (g == got.cend()) {
            *why = w.key() + QStringLiteral(" missing");
            return false;
        }
        if (!sameStatus(*g, *w)) {
            *why = w.key() + QStringLiteral(" status differs");
            return false;
        }
        const struct {
            const char* what;
            double a, b, tolerance;
        } fields[] = {{"e", g->e, w->e, 0.005},
                      {"n", g->n, w->n, 0.005},
                      {"u", g->u, w->u, 0.005},
                      {"heading", g->headingDeg, w->headingDeg, 0.005},
                      {"speed", g->speed, w->speed, 0.005},
                      {"lat", g->lat, w->lat, 1e-7},
                      {"lon", g->lon, w->lon, 1e-7}};
        for (const auto& f : fields)
            if (!(std::abs(f.a - f.b) <= f.tolerance + slack)) {
                *why = QStringLiteral("%1 %2: %3 vs %4")
                           .arg(w.key(), QLatin1String(f.what))
                           .arg(f.a, 0, 'g', 12)
                           .arg(f.b, 0, 'g', 12);
                return false;
            }
        if (g->lastDataMs != w->lastDataMs || g->lastMessageMs != w->lastMessageMs) {
            *why = w.key() + QStringLiteral(" times differ");
            return false;
        }
    }
    return true;
}

QHash<QString, MachineState> pictureOf(const FleetModel& fleet) {
    QHash<QString, MachineState> out;
    for (const MachineState& m : fleet.machinesSnapshot())
        out.insert(m.id, m);
    return out;
}

} // namespace

class TestRecorder : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    std::shared_ptr<ManualModelClock> m_clock = std::make_shared<ManualModelClock>();
    Truth m_truth;
    QString m_file;
    qint64 m_t0 = 0;
    qint64 m_alarmT = 0, m_ackT = 0;

    // 3 machines at 10 Hz for 60 s of recording time (fake clock), a status change now and then, one machine
    // leaving and coming back, events, an acknowledgement, a command, a link change.
    // legacy: written as schema 3 (the format before schema 4), whose positions are exact to the millimetre.
    void recordScenario(const QString& path, bool legacy = false) {
        Recorder rec;
        RecorderOptions o;
        o.path = path;
        o.legacySchema3 = legacy;
        o.keyframeIntervalMs = 5000;
        o.flushIntervalMs = 5;
        o.clock = m_clock;
        m_t0 = 1'700'000'000'000;
        m_clock->set(m_t0);
        QVERIFY(rec.start(o).isEmpty());
        LinkStatus up;
        up.link = QStringLiteral("iso23725:ahs");
        up.state = LinkState::Up;
        rec.recordLink(QStringLiteral("iso23725"), up);
        for (int step = 0; step <= 600; ++step) {
            m_clock->set(m_t0 + step * 100);
            for (int k = 0; k < 3; ++k) {
                const QString id = QStringLiteral("iso23725:t%1").arg(k);
                if (k == 2 && step >= 200 && step < 300) {
                    if (step == 200) {
                        rec.recordRemoval(id);
                        m_truth.remove(m_clock->nowMs(), id);
                    }
                    continue;
                }
                MachineState m = machine(id, 100.0 * k + step * 0.8333, -50.0 + step * 0.01234);
                m.lastDataMs = m_clock->nowMs() - 7;
                m.lastMessageMs = k == 1 ? 0 : m_clock->nowMs() - 20;
                if (k == 1 && step >= 150)
                    m.stop = StopState::Stopped, m.stopText = QStringLiteral("all-stop");
                if (k == 0 && (step / 50) % 2 == 1)
                    m.health = HealthLevel::Warning, m.healthText = QStringLiteral("tyre pressure");
                rec.recordStates({m});
                MachineState expected = m;
                applyPosition(expected, m, m_clock->nowMs()); // the file keeps millimetres
                if (!m_truth.now.contains(id) || !sameStatus(m_truth.now.value(id), m))
                    expected = m; // a Full record: exact
                m_truth.set(m_clock->nowMs(), expected);
            }
            if (step == 150) {
                FleetEvent ev =
                    makeEvent(EventSeverity::Alarm, EventKind::HealthFault, QStringLiteral("iso23725:t1"),
                              QStringLiteral("stopped"), QStringLiteral("iso23725"));
                ev.timeMs = m_clock->nowMs();
                rec.recordEvent(ev);
                m_alarmT = m_clock->nowMs();
                rec.recordCommand(
                    QStringLiteral(R"({"origin":"gui","action":"stop_all","ok":false,"targets":[]})"));
            }
            if (step == 400) {
                FleetEvent ev =
                    makeEvent(EventSeverity::Alarm, EventKind::HealthFault, QStringLiteral("iso23725:t1"),
                              QStringLiteral("stopped"), QStringLiteral("iso23725"));
                ev.timeMs = m_alarmT;
                rec.recordAck(alarmKey(ev), QStringLiteral("op"), m_clock->nowMs());
                m_ackT = m_clock->nowMs();
                up.state = LinkState::Down;
                rec.recordLink(QStringLiteral("iso23725"), up);
            }
            if (step % 20 == 0)
                rec.flush(); // several commits and keyframes
        }
        rec.stop();
        QCOMPARE(rec.stats().dropped, 0u);
    }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_file = m_dir.filePath(QStringLiteral("run.sqlite"));
        recordScenario(m_file);
    }

    void readsBackThePictureAtAnyTime() {
        auto rec = Recording::open(m_file);
        QVERIFY(rec);
        QCOMPARE(rec->startMs(), m_t0);
        QCOMPARE(rec->endMs(), m_t0 + 60000);
        for (qint64 t : {m_t0 - 1, m_t0, m_t0 + 50, m_t0 + 4999, m_t0 + 5000, m_t0 + 15'050, m_t0 + 20'000,
                         m_t0 + 25'000, m_t0 + 30'000, m_t0 + 44'444, m_t0 + 60'000}) {
            QString why;
            QVERIFY2(samePicture(rec->statesAt(t), m_truth.pictureAt(t), &why),
                     qPrintable(QStringLiteral("t+%1: %2").arg(t - m_t0).arg(why)));
        }
        // Keyframes were written (seek does not decode the whole file).
        QVERIFY(rec->meta(QStringLiteral("keyframe_interval_ms")).toInt() == 5000);
    }

    void seekAndPlayLandOnTheSamePicture() {
        auto rec = Recording::open(m_file);
        QVERIFY(rec);
        FleetModel played, sought;
        ReplayController a(rec.get(), &played), b(rec.get(), &sought);
        a.seek(a.startMs());
        // Forward in uneven steps (the play path), then compare with a seek (the keyframe path) at each stop.
        QString why;
        for (qint64 t = a.startMs(); t <= a.endMs(); t += 1'337) {
            a.moveTo(t);
            b.seek(t);
            QVERIFY2(samePicture(pictureOf(played), pictureOf(sought), &why), qPrintable(why));
            QVERIFY2(samePicture(pictureOf(played), m_truth.pictureAt(t), &why), qPrintable(why));
        }
        // Backwards, and forwards again, to the same picture.
        b.seek(m_t0 + 30'000);
        const auto at30 = pictureOf(sought);
        b.seek(m_t0 + 55'000);
        b.seek(m_t0 + 30'000);
        QVERIFY2(samePicture(pictureOf(sought), at30, &why), qPrintable(why));
        b.seek(m_t0 + 2'000);
        b.moveTo(m_t0 + 30'000);
        QVERIFY2(samePicture(pictureOf(sought), at30, &why), qPrintable(why));
        // The machine that left is gone in between and back afterwards.
        b.seek(m_t0 + 25'000);
        QVERIFY(!sought.machine(QStringLiteral("iso23725:t2")));
        b.seek(m_t0 + 35'000);
        QVERIFY(sought.machine(QStringLiteral("iso23725:t2")));
        QVERIFY(b.lastSeekMs() >= 0);
    }

    void alarmsAndAcknowledgementsAsOfTheReplayTime() {
        auto rec = Recording::open(m_file);
        QVERIFY(rec);
        FleetModel fleet;
        ReplayController c(rec.get(), &fleet);
        c.seek(m_alarmT - 1);
        QCOMPARE(c.alarms()->rowCount(), 0);
        c.moveTo(m_alarmT);
        QCOMPARE(c.alarms()->rowCount(), 1);
        QCOMPARE(c.alarms()->unacknowledgedCount(), 1);
        c.moveTo(m_ackT);
        QCOMPARE(c.alarms()->unacknowledgedCount(), 0);
        // Back before the acknowledgement: unacknowledged again (a fresh model).
        QSignalSpy replaced(&c, &ReplayController::alarmsReplaced);
        c.seek(m_ackT - 100);
        QCOMPARE(replaced.count(), 1);
        QCOMPARE(c.alarms()->rowCount(), 1);
        QCOMPARE(c.alarms()->unacknowledgedCount(), 1);
        // Links as they were; markers for the alarm and the command (not reaching every target: bad).
        QCOMPARE(rec->linksAt(m_ackT - 1).value(0).state, LinkState::Up);
        QCOMPARE(rec->linksAt(m_ackT).value(0).state, LinkState::Down);
        const auto markers = rec->markers();
        QCOMPARE(markers.size(), 2);
        QCOMPARE(markers[0].t, m_alarmT);
        QVERIFY(markers[1].kind == Marker::Kind::Command && markers[1].bad);
    }

    void repeatedAlarmIsOneRowUntilAcknowledged() {
        auto clock = std::make_shared<ManualModelClock>(1'000'000);
        Recorder rec;
        RecorderOptions o;
        o.path = m_dir.filePath(QStringLiteral("twins.sqlite"));
        o.clock = clock;
        QVERIFY(rec.start(o).isEmpty());
        FleetEvent ev = makeEvent(EventSeverity::Alarm, EventKind::LinkLoss, {}, QStringLiteral("link lost"));
        ev.timeMs = 1'000'100;
        clock->set(1'000'100);
        rec.recordEvent(ev);
        rec.recordEvent(ev); // a repeat of an open alarm: one key, one row (AlarmModel groups, EEMUA 191)
        clock->set(1'000'200);
        rec.recordAck(alarmKey(ev), QStringLiteral("op"), clock->nowMs());
        clock->set(1'000'300);
        rec.recordAck(alarmKey(ev), QStringLiteral("op"), clock->nowMs());
        rec.stop();
        auto r = Recording::open(o.path);
        QVERIFY(r);
        FleetModel fleet;
        ReplayController c(r.get(), &fleet);
        c.seek(1'000'150);
        QCOMPARE(c.alarms()->rowCount(), 1);
        QCOMPARE(c.alarms()->unacknowledgedCount(), 1);
        c.moveTo(1'000'200); // the recorded acknowledgement closes it (by the shared key)
        QCOMPARE(c.alarms()->rowCount(), 1);
        QCOMPARE(c.alarms()->unacknowledgedCount(), 0);
        c.seek(1'000'150); // and seeking back before it opens it again
        QCOMPARE(c.alarms()->unacknowledgedCount(), 1);
    }

    // The replayed alarm list at any instant is the live one of that instant, whether the replay seeks there
    // (the rows alive then, AlarmHistory) or plays forward from the start (every event added in turn): a live
    // AlarmModel recorded as the console records it (eventAdded, alarmAcknowledged) for 20 minutes, alarms of
    // a few keys raised again while open and after their acknowledgement, entries without acknowledgement,
    // acknowledgements by key and by row, one of them before an alarm whose own clock is well ahead (not
    // covered: AlarmModel's skew), and a cap small enough that the live list dropped rows many times.
    void alarmListAtSeekEqualsPlayingForward_data() {
        QTest::addColumn<int>("cap");
        QTest::newRow("cap 40 (rows dropped)") << 40;
        QTest::newRow("the console's cap") << AlarmModel::kDefaultMaxEntries;
    }
    void alarmListAtSeekEqualsPlayingForward() {
        QFETCH(int, cap);
        struct Seen {
            FleetEvent event;
            QString key, ackedBy;
            bool acked = false;
            qint64 ackedMs = 0;
            int occurrences = 0;
        };
        auto picture = [](const AlarmModel& m) {
            QVector<Seen> rows;
            for (int i = 0; i < m.rowCount(); ++i)
                rows.push_back({m.eventAt(i), m.keyAt(i), m.acknowledgedByAt(i), m.isAcknowledged(i),
                                m.acknowledgedAtMs(i), m.occurrencesAt(i)});
            return rows;
        };
        auto same = [](const QVector<Seen>& a, const QVector<Seen>& b, const QString& where) {
            if (a.size() != b.size())
                return QStringLiteral("%1: %2 rows, live %3").arg(where).arg(a.size()).arg(b.size());
            for (qsizetype i = 0; i < a.size(); ++i) {
                const Seen &x = a[i], &y = b[i];
                if (x.key != y.key || x.event.timeMs != y.event.timeMs ||
                    x.event.severity != y.event.severity || x.event.kind != y.event.kind ||
                    x.event.machineId != y.event.machineId || x.event.source != y.event.source ||
                    x.event.text != y.event.text || x.event.requiresAck != y.event.requiresAck ||
                    x.acked != y.acked || x.ackedMs != y.ackedMs || x.ackedBy != y.ackedBy ||
                    x.occurrences != y.occurrences)
                    return QStringLiteral("%1: row %2 (%3) differs from the live one (%4)")
                        .arg(where)
                        .arg(i)
                        .arg(x.key + QLatin1Char('/') + QString::number(x.occurrences) +
                                 (x.acked ? QStringLiteral(" acked") : QString()),
                             y.key + QLatin1Char('/') + QString::number(y.occurrences) +
                                 (y.acked ? QStringLiteral(" acked") : QString()));
            }
            return QString();
        };

        auto clock = std::make_shared<ManualModelClock>(1'700'000'000'000);
        const qint64 start = clock->nowMs();
        Recorder rec;
        RecorderOptions o;
        o.path = m_dir.filePath(QStringLiteral("alarms-%1.sqlite").arg(cap));
        o.flushIntervalMs = 5;
        o.clock = clock;
        QVERIFY(rec.start(o).isEmpty());
        AlarmModel live;
        live.setClock(clock);
        live.setOperatorName(QStringLiteral("op"));
        live.setMaxEntries(cap);
        connect(&live, &AlarmModel::eventAdded, &rec, &Recorder::recordEvent);
        connect(&live, &AlarmModel::alarmAcknowledged, &rec, &Recorder::recordAck);

        std::mt19937_64 rng(27);
        auto pick = [&rng](int n) { return int(std::uniform_int_distribution<int>(0, n - 1)(rng)); };
        QMap<qint64, QVector<Seen>> truth; // instant -> the live list after everything recorded up to it
        for (int step = 0; step < 2400; ++step) { // 20 minutes, a step every 500 ms
            clock->set(start + step * 500);
            const int what = pick(11);
            if (what < 5) {
                // An alarm of one of a few keys (a repeat while open, a new row once acknowledged).
                const QString machineId = QStringLiteral("iso23725:t%1").arg(pick(4));
                FleetEvent ev = makeEvent(EventSeverity(1 + pick(3)),
                                          pick(2) ? EventKind::Timeout : EventKind::HealthFault, machineId,
                                          QStringLiteral("fault %1").arg(step), QStringLiteral("iso23725"));
                ev.timeMs = clock->nowMs();
                live.add(ev);
            } else if (what == 5) {
                // A machine whose own clock is a minute ahead: the acknowledgements by key in the next minute
                // do not cover it (AlarmModel::kAckSkewMs).
                FleetEvent ev =
                    makeEvent(EventSeverity::Alarm, EventKind::Timeout, QStringLiteral("iso23725:t4"),
                              QStringLiteral("ahead"), QStringLiteral("iso23725"));
                ev.timeMs = clock->nowMs() + 60'000;
                live.add(ev);
            } else if (what < 8) {
                // An entry that needs no acknowledgement.
                FleetEvent ev = makeEvent(EventSeverity::Info, EventKind::Info, {},
                                          QStringLiteral("note %1").arg(pick(50)), QStringLiteral("gui"));
                ev.timeMs = clock->nowMs();
                live.add(ev);
            } else if (what == 8 && live.rowCount() > 0) {
                // The operator acknowledges a row (perhaps one acknowledged already). Not the machine whose
                // clock is ahead: the file keeps the acknowledgement by key, which the replay applies as
                // acknowledgeKey does, with the skew.
                const int row = pick(live.rowCount());
                if (live.eventAt(row).machineId != QLatin1String("iso23725:t4"))
                    live.acknowledge(row);
            } else {
                // An acknowledgement by key (another console's), perhaps of a key not open.
                const QString machineId = QStringLiteral("iso23725:t%1").arg(pick(5));
                FleetEvent ev =
                    makeEvent(EventSeverity::Alarm, pick(2) ? EventKind::Timeout : EventKind::HealthFault,
                              machineId, {}, QStringLiteral("iso23725"));
                live.acknowledgeKey(alarmKey(ev), QStringLiteral("console-2"), clock->nowMs());
            }
            truth.insert(clock->nowMs(), picture(live));
            if (pick(4) == 0) {
                // Two things in one millisecond: an event, then its acknowledgement (the file keeps no order
                // across events and acknowledgements within a millisecond; the replay takes the events
                // first).
                clock->advance(1);
                FleetEvent ev =
                    makeEvent(EventSeverity::Warning, EventKind::Timeout, QStringLiteral("iso23725:t9"),
                              QStringLiteral("late"), QStringLiteral("iso23725"));
                ev.timeMs = clock->nowMs();
                live.add(ev);
                live.acknowledgeKey(alarmKey(ev), QStringLiteral("op"), clock->nowMs());
                truth.insert(clock->nowMs(), picture(live));
            }
            if (step % 50 == 0)
                rec.flush();
        }
        rec.stop();
        QCOMPARE(rec.stats().dropped, 0u);
        if (cap < 1000)
            QVERIFY2(live.rowCount() <= cap + 8, "the live list was capped"); // (its open alarms stay)

        auto r = Recording::open(o.path);
        QVERIFY(r);
        // 200 random instants of the recording (and the ends), in a random order.
        QVector<qint64> instants{start - 1, start, clock->nowMs()};
        for (int i = 0; i < 200; ++i)
            instants.push_back(start + std::uniform_int_distribution<qint64>(0, clock->nowMs() - start)(rng));
        // The replay's times are the file's (up to its last commit).
        auto liveAt = [&truth, &r](qint64 t) {
            const auto it = truth.upperBound(std::clamp(t, r->startMs(), r->endMs()));
            return it == truth.begin() ? QVector<Seen>() : std::prev(it).value();
        };

        FleetModel seekFleet;
        ReplayController seeking(r.get(), &seekFleet);
        seeking.setMaxAlarmEntries(cap);
        QCOMPARE(seeking.maxAlarmEntries(), cap);
        for (qint64 t : std::as_const(instants)) {
            seeking.seek(t);
            const QString diff =
                same(picture(*seeking.alarms()), liveAt(t), QStringLiteral("seek to +%1 ms").arg(t - start));
            QVERIFY2(diff.isEmpty(), qPrintable(diff));
            QCOMPARE(seeking.alarms()->unacknowledgedCount(),
                     int(std::count_if(liveAt(t).cbegin(), liveAt(t).cend(),
                                       [](const Seen& s) { return !s.acked; })));
        }

        // Playing forward from the start, in steps short enough to add the events one after the other.
        std::sort(instants.begin(), instants.end());
        FleetModel playFleet;
        ReplayController playing(r.get(), &playFleet);
        playing.setMaxAlarmEntries(cap);
        playing.seek(start);
        for (qint64 t : std::as_const(instants)) {
            while (playing.position() < std::min(t, r->endMs()))
                playing.moveTo(std::min(t, playing.position() + 3000));
            const QString diff =
                same(picture(*playing.alarms()), liveAt(t), QStringLiteral("play to +%1 ms").arg(t - start));
            QVERIFY2(diff.isEmpty(), qPrintable(diff));
        }
    }

    void playsAtTheChosenSpeedInBothDirections() {
        auto rec = Recording::open(m_file);
        QVERIFY(rec);
        FleetModel fleet;
        ReplayController c(rec.get(), &fleet);
        c.seek(m_t0 + 10'000);
        c.setSpeed(16);
        c.setTickIntervalMs(10);
        QElapsedTimer wall;
        wall.start();
        c.play();
        QTRY_VERIFY_WITH_TIMEOUT(c.position() >= m_t0 + 20'000, 20000);
        // 10 s of recording at 16x: no sooner than 10/16 s of wall time.
        QVERIFY(wall.elapsed() >= 600);
        c.pause();
        c.setReverse(true);
        const qint64 from = c.position();
        c.play();
        QTRY_VERIFY_WITH_TIMEOUT(c.position() <= from - 5'000, 20000);
        c.pause();
        QString why;
        QVERIFY2(samePicture(pictureOf(fleet), m_truth.pictureAt(c.position()), &why), qPrintable(why));
        c.setSpeed(100);
        QCOMPARE(c.speed(), 16.0);
        c.setSpeed(0.01);
        QCOMPARE(c.speed(), 0.1);
        c.faster();
        QCOMPARE(c.speed(), 0.25);
    }

    void exportsJsonLinesCsvAndSlices() {
        auto rec = Recording::open(m_file);
        QVERIFY(rec);
        const qint64 from = m_t0 + 10'000, to = m_t0 + 12'000;
        QBuffer csv;
        csv.open(QIODevice::WriteOnly);
        QVERIFY(rec->exportCsv(&csv, from, to));
        const QList<QByteArray> lines = csv.data().split('\n');
        QVERIFY(lines[0].startsWith("time,t_ms,id,name,protocol,e,n,u"));
        // 21 steps (both ends included) x 3 machines, a header and the empty tail after the last CRLF.
        QCOMPARE(lines.size(), 21 * 3 + 2);
        QBuffer jsonl;
        jsonl.open(QIODevice::WriteOnly);
        QVERIFY(rec->exportJsonLines(&jsonl, m_t0 + 14'900, m_t0 + 15'000));
        int machines = 0, events = 0, commands = 0;
        for (const QByteArray& l : jsonl.data().split('\n')) {
            if (l.isEmpty())
                continue;
            const QJsonObject o = QJsonDocument::fromJson(l).object();
            QVERIFY(o.contains(QStringLiteral("t")));
            const QString type = o.value(QStringLiteral("type")).toString();
            machines += type == QLatin1String("machine");
            events += type == QLatin1String("event");
            commands += type == QLatin1String("command");
        }
        QCOMPARE(machines, 6);
        QCOMPARE(events, 1);
        QCOMPARE(commands, 1);

        const QString slice = m_dir.filePath(QStringLiteral("slice.sqlite"));
        QVERIFY(rec->exportSlice(slice, m_t0 + 14'000, m_t0 + 33'000));
        QString err;
        QVERIFY(!rec->exportSlice(slice, m_t0, m_t0 + 1, &err)); // never overwrites
        auto part = Recording::open(slice);
        QVERIFY(part);
        QCOMPARE(part->startMs(), m_t0 + 14'000);
        QString why;
        for (qint64 t : {m_t0 + 14'000, m_t0 + 21'000, m_t0 + 29'999, m_t0 + 33'000})
            QVERIFY2(samePicture(part->statesAt(t), rec->statesAt(t), &why), qPrintable(why));
        QCOMPARE(part->events(0, std::numeric_limits<qint64>::max()).size(), 1);
    }

    void fullQueueDropsAndCounts() {
        Recorder rec;
        RecorderOptions o;
        o.path = m_dir.filePath(QStringLiteral("drops.sqlite"));
        o.queueCapacity = 10;
        o.flushIntervalMs = 60000; // the writer sleeps: the queue fills
        QVERIFY(rec.start(o).isEmpty());
        QTest::qWait(50); // the writer is waiting
        for (int i = 0; i < 100; ++i)
            rec.recordStates({machine(QStringLiteral("jaus:%1").arg(i), i, i)});
        const auto s = rec.stats();
        QCOMPARE(s.queued, 10u);
        QCOMPARE(s.dropped, 90u);
        rec.flush();
        QCOMPARE(rec.stats().written, 10u);
        rec.stop();
        auto r = Recording::open(o.path);
        QVERIFY(r);
        QCOMPARE(r->statesAt(r->endMs()).size(), 10);
    }

    // What the stacks hand to the tap is in the file - protocol, link, peer, type, receive time
    // and the bytes - readable by time window, exported as JSON lines (ISO 23725 decoded), copied by a slice.
    // record.raw off: raw frames are not kept; on: they are, flagged raw, undecodable ones included.
    void tappedMessagesAreRecorded() {
        for (const bool raw : {false, true}) {
            Recorder rec;
            RecorderOptions o;
            o.path = m_dir.filePath(raw ? QStringLiteral("msgs-raw.sqlite") : QStringLiteral("msgs.sqlite"));
            o.flushIntervalMs = 5;
            o.messages = true;
            o.raw = raw;
            auto clock = std::make_shared<ManualModelClock>(1'700'000'000'000);
            o.clock = clock;
            QVERIFY(rec.start(o).isEmpty());
            MessageTap* tap = rec.messageTap();
            QVERIFY(tap);
            QCOMPARE(tap->wantsRaw(), raw);
            const std::uint8_t jaus[] = {0x02, 0x44, 1, 2, 3, 4};
            const std::string iso = R"({"Header":{"Protocol":"ISO23725"},"PositionV1":{"X":1}})";
            const std::uint8_t osy[] = {9, 8, 7, 6, 5, 4, 3, 2, 1};
            const std::uint8_t junk[] = {0xFF, 0x00, 0xEE};
            clock->advance(100);
            tap->onDecoded({"jaus", "jaus", "42.1.1", "4402", jaus});
            clock->advance(1500); // a new chunk
            tap->onDecoded({"iso23725", "ahs", "127.0.0.1:5000", "PositionV1", tapBytes(iso)});
            clock->advance(10);
            tap->onDecoded({"osyris", "osyris:239.1.1.1:7000", "3", "CmPos", osy});
            if (tap->wantsRaw())
                tap->onRaw({"jaus", "jaus", "127.0.0.1:9", {}, junk});
            clock->advance(10);
            tap->onDecoded({"osyris", "osyris:239.1.1.1:7000", "3", "CmPos", osy});
            rec.flush();
            QCOMPARE(rec.stats().messages, raw ? 5u : 4u);
            rec.stop();
            auto r = Recording::open(o.path);
            QVERIFY(r);
            const auto channels = r->messageChannels();
            QVector<RecordedMessage> all;
            r->messages(0, std::numeric_limits<qint64>::max(), [&](const RecordedMessage& m) {
                all.push_back(m);
                return true;
            });
            QCOMPARE(all.size(), raw ? 5 : 4);
            const qint64 t0 = 1'700'000'000'000;
            auto check = [&](int i, qint64 t, const char* protocol, const char* type, const QByteArray& bytes,
                             bool isRaw) {
                const MessageChannel c = channels.value(all[i].channel);
                QCOMPARE(all[i].t, t);
                QCOMPARE(c.protocol, QString::fromLatin1(protocol));
                QCOMPARE(c.type, QString::fromLatin1(type));
                QCOMPARE(all[i].bytes, bytes);
                QCOMPARE(all[i].raw, isRaw);
            };
            auto bytesOf = [](const auto& a) {
                return QByteArray(reinterpret_cast<const char*>(std::data(a)), qsizetype(std::size(a)));
            };
            check(0, t0 + 100, "jaus", "4402", bytesOf(jaus), false);
            QCOMPARE(channels.value(all[0].channel).peer, QStringLiteral("42.1.1"));
            check(1, t0 + 1600, "iso23725", "PositionV1", QByteArray::fromStdString(iso), false);
            QCOMPARE(channels.value(all[1].channel).link, QStringLiteral("ahs"));
            check(2, t0 + 1610, "osyris", "CmPos", bytesOf(osy), false);
            int k = 3;
            if (raw)
                check(k++, t0 + 1610, "jaus", "", bytesOf(junk), true);
            check(k, t0 + 1620, "osyris", "CmPos", bytesOf(osy), false);
            QCOMPARE(all[2].channel, all[k].channel); // one channel per (protocol, link, peer, type)
            // A window: only what was received in it.
            int inWindow = 0;
            r->messages(t0 + 1600, t0 + 1610, [&](const RecordedMessage&) { return ++inWindow, true; });
            QCOMPARE(inWindow, raw ? 3 : 2);
            // The export shows them, ISO 23725 decoded.
            QBuffer buf;
            buf.open(QIODevice::WriteOnly);
            QVERIFY(r->exportJsonLines(&buf, t0, t0 + 5000));
            bool sawIso = false;
            int lines = 0;
            for (const QByteArray& line : buf.data().split('\n')) {
                const QJsonObject obj = QJsonDocument::fromJson(line).object();
                if (obj.value(QStringLiteral("type")).toString() == QLatin1String("message") ||
                    obj.value(QStringLiteral("type")).toString() == QLatin1String("raw"))
                    ++lines;
                if (obj.value(QStringLiteral("msg_type")).toString() == QLatin1String("PositionV1")) {
                    sawIso = true;
                    QCOMPARE(obj.value(QStringLiteral("t")).toDouble(), double(t0 + 1600));
                    QCOMPARE(obj.value(QStringLiteral("json"))
                                 .toObject()
                                 .value(QStringLiteral("PositionV1"))
                                 .toObject()
                                 .value(QStringLiteral("X"))
                                 .toInt(),
                             1);
                }
            }
            QVERIFY(sawIso);
            QCOMPARE(lines, raw ? 5 : 4);
            // A slice keeps the messages of its window.
            const QString slice = o.path + QStringLiteral(".slice.sqlite");
            QVERIFY(r->exportSlice(slice, t0 + 1000, t0 + 5000));
            auto s = Recording::open(slice);
            QVERIFY(s);
            QVector<RecordedMessage> inSlice;
            s->messages(t0 + 1000, t0 + 5000, [&](const RecordedMessage& m) {
                inSlice.push_back(m);
                return true;
            });
            for (const RecordedMessage& m : inSlice)
                QCOMPARE(s->messageChannels().value(m.channel).type, channels.value(m.channel).type);
            QCOMPARE(inSlice.size(), raw ? 4 : 3);
        }
    }

    // Hostile message chunks end the walk, never read past the blob.
    void malformedMessageChunk() {
        QByteArray chunk;
        appendMessage(chunk, 1, 5, false, "abcdef", 6);
        appendMessage(chunk, 2, 7, true, "xyz", 3);
        int n = 0;
        QVERIFY(decodeMessageChunk(chunk, 1000, 0, 10000, [&](const RecordedMessage&) { return ++n, true; }));
        QCOMPARE(n, 2);
        for (int cut = 0; cut < chunk.size(); ++cut) {
            n = 0;
            decodeMessageChunk(chunk.left(cut), 1000, 0, 10000,
                               [&](const RecordedMessage& m) { return ++n, m.bytes.size() <= 6; });
            QVERIFY(n <= 1 || cut == chunk.size());
        }
        QByteArray huge;
        appendMessage(huge, 1, 5, false, "ab", 2);
        huge[3] = char(0x7F); // the length now claims more than the blob holds
        QVERIFY(!decodeMessageChunk(huge, 0, 0, 10000, [](const RecordedMessage&) { return true; }));
    }

    // attach(): what the console's models and its gate see is what the file holds - machine states and
    // removals, events, acknowledgements (the shared key, who), and every gate command with its result and
    // per-target outcome (the audit line).
    void attachRecordsTheModelsAndTheGate() {
        FleetContext ctx;
        Recorder rec;
        RecorderOptions o;
        o.path = m_dir.filePath(QStringLiteral("attached.sqlite"));
        QVERIFY(rec.start(o).isEmpty());
        rec.attach(&ctx);
        MachineState m = machine(QStringLiteral("iso23725:t1"), 12, 34);
        m.lastDataMs = QDateTime::currentMSecsSinceEpoch();
        ctx.fleet()->upsert({m});
        ctx.fleet()->upsert({machine(QStringLiteral("iso23725:t2"), 1, 2)});
        ctx.fleet()->remove({QStringLiteral("iso23725:t2")});
        FleetEvent alarm =
            makeEvent(EventSeverity::Alarm, EventKind::HealthFault, m.id, QStringLiteral("fault"));
        ctx.alarms()->add(alarm);
        // Who is at the console: in the acknowledgement and the audit line.
        const OperatorIdentity who{QStringLiteral("alice"), OperatorRole::Supervisor,
                                   QStringLiteral("ocu-2")};
        ctx.gate()->setOperator(who);
        ctx.alarms()->setOperatorName(who.byText());
        ctx.alarms()->acknowledge(0);
        const QString key = ctx.alarms()->keyAt(0);
        ctx.gate()->stopMachine(QStringLiteral("no-such-machine"), QStringLiteral("test"));
        QTRY_VERIFY_WITH_TIMEOUT(rec.stats().queued >= 6, 10000);
        rec.flush();
        rec.stop();

        auto r = Recording::open(o.path);
        QVERIFY(r);
        const auto end = r->statesAt(r->endMs());
        QCOMPARE(end.size(), 1);
        QCOMPARE(end.value(m.id).e, 12.0);
        QCOMPARE(end.value(m.id).name, m.name);
        bool sawFault = false;
        for (const RecordedEvent& e : r->events(r->startMs() - 1, r->endMs()))
            sawFault |= e.event.text == QLatin1String("fault") && e.key == key && e.event.requiresAck;
        QVERIFY(sawFault);
        const auto acks = r->acks(r->startMs() - 1, r->endMs());
        QCOMPARE(acks.size(), 1);
        QCOMPARE(acks.first().key, key);
        QCOMPARE(acks.first().by, QStringLiteral("alice (supervisor) @ ocu-2"));
        const auto cmds = r->commands(r->startMs() - 1, r->endMs());
        QCOMPARE(cmds.size(), 1);
        QCOMPARE(cmds.first().origin, QStringLiteral("test"));
        QCOMPARE(cmds.first().target, QStringLiteral("no-such-machine"));
        QVERIFY(!cmds.first().ok);
        const QJsonObject audit = QJsonDocument::fromJson(cmds.first().audit.toUtf8()).object();
        QCOMPARE(audit.value(QStringLiteral("target")).toString(), QStringLiteral("no-such-machine"));
        QVERIFY(audit.contains(QStringLiteral("targets")));
        QCOMPARE(audit.value(QStringLiteral("operator")).toString(), QStringLiteral("alice"));
        QCOMPARE(audit.value(QStringLiteral("role")).toString(), QStringLiteral("supervisor"));
        QCOMPARE(audit.value(QStringLiteral("console")).toString(), QStringLiteral("ocu-2"));
    }

    // The writer behind: dropped records reach the operator as a warning with the count.
    void dropsAreReportedToTheOperator() {
        FleetContext ctx;
        Recorder rec;
        RecorderOptions o;
        o.path = m_dir.filePath(QStringLiteral("dropreport.sqlite"));
        o.queueCapacity = 5;
        o.flushIntervalMs = 60000;
        o.messages = true;
        o.dropReportIntervalMs = 200; // the report itself is what is checked, not its 5 s pace
        QVERIFY(rec.start(o).isEmpty());
        QString warning;
        connect(ctx.alarms(), &AlarmModel::eventAdded, this, [&](const FleetEvent& e) {
            if (e.source == QLatin1String("recorder") && e.severity == EventSeverity::Warning)
                warning = e.text;
        });
        rec.attach(&ctx);
        QTest::qWait(50);
        const std::uint8_t b[] = {1, 2};
        for (int i = 0; i < 50; ++i)
            rec.messageTap()->onDecoded({"jaus", "jaus", "1.1.1", "4402", b});
        QVERIFY(rec.stats().dropped >= 40u);
        QTRY_VERIFY_WITH_TIMEOUT(!warning.isEmpty(), 20000);
        QVERIFY2(warning.contains(QStringLiteral("dropped")), qPrintable(warning));
        rec.stop();
    }

    void refusesWhatIsNotARecording() {
        QString err;
        QVERIFY(!Recording::open(m_dir.filePath(QStringLiteral("nothing.sqlite")), &err));
        QVERIFY(err.contains(QStringLiteral("no such file")));
        QFile junk(m_dir.filePath(QStringLiteral("junk.sqlite")));
        QVERIFY(junk.open(QIODevice::WriteOnly));
        junk.write(QByteArray(4096, 'x'));
        junk.close();
        QVERIFY(!Recording::open(junk.fileName(), &err));
        QVERIFY(err.contains(QStringLiteral("not an OCU recording")));
        // An existing file is never overwritten by a recorder.
        Recorder rec;
        RecorderOptions o;
        o.path = m_file;
        QVERIFY(!rec.start(o).isEmpty());
    }

    void hostileChunksEndCleanly() {
        QByteArray good;
        appendFull(good, 1, 0, machine(QStringLiteral("jaus:1"), 1, 2));
        appendPosition(good, 1, 5, 1005, machine(QStringLiteral("jaus:1"), 3, 4));
        for (int cut = 0; cut < good.size(); ++cut) {
            QHash<std::uint32_t, MachineState> s;
            const bool ok = decodeChunk(good.left(cut), 1000, s, std::numeric_limits<qint64>::min(),
                                        std::numeric_limits<qint64>::max());
            QVERIFY(cut == 0 || !ok || s.size() <= 1);
        }
        // Delta records (schema 3): exact against applyPosition, every cut ends cleanly.
        {
            const MachineState base = machine(QStringLiteral("jaus:1"), 1, 2);
            MachineState next = machine(QStringLiteral("jaus:1"), 3.2346, -4.5);
            next.lat += 1.234567e-6;
            next.headingDeg = 271.3;
            next.speed = 0.5;
            next.lastDataMs = 1003;
            next.lastMessageMs = 990;
            QByteArray delta;
            appendFull(delta, 1, 0, base);
            appendDelta(delta, 1, 5, 1005, base, next);
            MachineState want = base;
            applyPosition(want, next, 1005);
            QHash<std::uint32_t, MachineState> s;
            QVERIFY(decodeChunk(delta, 1000, s, std::numeric_limits<qint64>::min(),
                                std::numeric_limits<qint64>::max()));
            const MachineState& got = s[1];
            QCOMPARE(got.e, want.e);
            QCOMPARE(got.n, want.n);
            QCOMPARE(got.u, want.u);
            QCOMPARE(got.lat, next.lat);
            QCOMPARE(got.lon, next.lon);
            QCOMPARE(got.headingDeg, want.headingDeg);
            QCOMPARE(got.speed, want.speed);
            QCOMPARE(got.lastDataMs, qint64(1003));
            QCOMPARE(got.lastMessageMs, qint64(990));
            QCOMPARE(got.e, 3.235); // mm
            for (int cut = 0; cut < delta.size(); ++cut) {
                QHash<std::uint32_t, MachineState> c;
                const bool ok = decodeChunk(delta.left(cut), 1000, c, std::numeric_limits<qint64>::min(),
                                            std::numeric_limits<qint64>::max());
                QVERIFY(cut == 0 || !ok || c.size() <= 1);
            }
            QByteArray junk = delta.left(int(delta.size()) - 20);
            junk.append(QByteArray(12, '\xff')); // a varint longer than 10 bytes
            QHash<std::uint32_t, MachineState> c;
            QVERIFY(!decodeChunk(junk, 1000, c, std::numeric_limits<qint64>::min(),
                                 std::numeric_limits<qint64>::max()));
        }
        // Schema 4 chunks (columns, Move records): a chunk decodes to what the encoder's base says, every cut
        // and every flipped byte ends cleanly, a wrong column count is refused.
        {
            const GeoFrame frame(GeoPoint{48.2, 11.4, 0});
            ChunkEncoder enc(&frame);
            enc.begin(1000);
            MachineState base = machine(QStringLiteral("jaus:1"), 1, 2);
            enc.full(1, 1000, base);
            MachineState moved = base;
            for (int i = 1; i <= 4; ++i) {
                MachineState next = machine(QStringLiteral("jaus:1"), 1 + i * 0.73, 2 - i * 0.41);
                if (i % 2 == 0) { // derived from e/n/u through the frame
                    const GeoPoint g = frame.toGeodetic({next.e, next.n, next.u});
                    next.lat = g.lat;
                    next.lon = g.lon;
                }
                next.lastDataMs = 1000 + i * 100 - 3;
                next.lastMessageMs = i == 3 ? 0 : next.lastDataMs - 9;
                QVERIFY(enc.move(1, 1000 + i * 100, moved, next));
            }
            enc.removed(2, 1450);
            const QByteArray chunk = enc.data();
            QHash<std::uint32_t, MachineState> s;
            DecodeOptions opt;
            opt.format = ChunkFormat::Compact;
            opt.frame = &frame;
            QVERIFY(decodeChunk(chunk, 1000, s, std::numeric_limits<qint64>::min(),
                                std::numeric_limits<qint64>::max(), {}, opt));
            QCOMPARE(s[1].e, moved.e);
            QCOMPARE(s[1].n, moved.n);
            QCOMPARE(s[1].lat, moved.lat);
            QCOMPARE(s[1].lon, moved.lon);
            QCOMPARE(s[1].lastDataMs, moved.lastDataMs);
            QCOMPARE(s[1].lastMessageMs, moved.lastMessageMs);
            for (int cut = 0; cut < chunk.size(); ++cut) {
                QHash<std::uint32_t, MachineState> c;
                const bool ok = decodeChunk(chunk.left(cut), 1000, c, std::numeric_limits<qint64>::min(),
                                            std::numeric_limits<qint64>::max(), {}, opt);
                QVERIFY(cut == 0 || !ok);
            }
            for (int at = 0; at < chunk.size(); ++at) {
                QByteArray flipped = chunk;
                flipped[at] = char(flipped[at] ^ 0xa5);
                QHash<std::uint32_t, MachineState> c;
                decodeChunk(flipped, 1000, c, std::numeric_limits<qint64>::min(),
                            std::numeric_limits<qint64>::max(), {}, opt); // ends, with or without an error
            }
            QByteArray wrong = chunk;
            wrong[0] = char(3);
            QHash<std::uint32_t, MachineState> c;
            QVERIFY(!decodeChunk(wrong, 1000, c, std::numeric_limits<qint64>::min(),
                                 std::numeric_limits<qint64>::max(), {}, opt));
        }
        QByteArray bad = good;
        bad[0] = char(99); // unknown record type
        QHash<std::uint32_t, MachineState> s;
        QVERIFY(
            !decodeChunk(bad, 0, s, std::numeric_limits<qint64>::min(), std::numeric_limits<qint64>::max()));
        QByteArray huge;
        huge.append(char(1));
        huge.append(QByteArray(8, '\0'));
        huge.append(QByteArray(7 + 80 + 16, '\0'));
        huge.append(QByteArray("\xff\xff\xff\x7f", 4)); // a string "2 GB long"
        QVERIFY(
            !decodeChunk(huge, 0, s, std::numeric_limits<qint64>::min(), std::numeric_limits<qint64>::max()));
    }

    // A file of an earlier build (schema 2: plain state chunks of Full and Position records) still reads.
    void readsSchemaTwoFiles() {
        const QString path = m_dir.filePath(QStringLiteral("schema2.sqlite"));
        sqlite3* db = nullptr;
        QCOMPARE(sqlite3_open(path.toUtf8().constData(), &db), SQLITE_OK);
        QCOMPARE(sqlite3_exec(db, kSchemaSql, nullptr, nullptr, nullptr), SQLITE_OK);
        QByteArray chunk;
        MachineState a = machine(QStringLiteral("jaus:1"), 10, 20);
        a.lastDataMs = 1'000'000;
        appendFull(chunk, 1, 0, a);
        MachineState b = machine(QStringLiteral("jaus:1"), 11.5, 21.25);
        b.lastDataMs = 1'000'100;
        appendPosition(chunk, 1, 100, 1'000'100, b);
        sqlite3_stmt* st = nullptr;
        QCOMPARE(sqlite3_prepare_v2(db, "INSERT INTO states(t0, t1, n, data) VALUES(1000000, 1000100, 2, ?)",
                                    -1, &st, nullptr),
                 SQLITE_OK);
        sqlite3_bind_blob(st, 1, chunk.constData(), int(chunk.size()), SQLITE_TRANSIENT);
        QCOMPARE(sqlite3_step(st), SQLITE_DONE);
        sqlite3_finalize(st);
        QCOMPARE(sqlite3_exec(
                     db,
                     "INSERT INTO meta VALUES('schema','2'); INSERT INTO meta VALUES('start_ms','1000000');"
                     "INSERT INTO meta VALUES('end_ms','1000100'); INSERT INTO machines VALUES(1,'jaus:1');",
                     nullptr, nullptr, nullptr),
                 SQLITE_OK);
        sqlite3_close(db);
        QString err;
        auto r = Recording::open(path, &err);
        QVERIFY2(r, qPrintable(err));
        QCOMPARE(r->statesAt(1'000'050).value(QStringLiteral("jaus:1")).e, 10.0);
        QCOMPARE(r->statesAt(1'000'100).value(QStringLiteral("jaus:1")).e, 11.5);
        QCOMPARE(r->statesAt(1'000'100).value(QStringLiteral("jaus:1")).lat, b.lat);
    }

    // Schema 4 (Move records in fixed point, zstd): a live fleet model recorded as the console records it,
    // then the picture at 50 random instants - read back, seeked to and played to - equals the live one
    // within the recording's resolution (withinResolution: 1 cm, 0.01 deg, 0.01 m/s, 1e-7 deg; times exact).
    // The fleet mixes what the encoder must tell apart: lat/lon that follow e/n/u through the site frame
    // (derived), lat/lon of another frame (carried), no message time, reversing, GNSS-like noise, jumps of
    // kilometres, positions beyond a Move's range (Full records), status changes, a machine leaving and
    // coming back.
    void replaysMoveRecordsAtFiftyInstants() {
        const GeoPoint origin{48.2, 11.4, 480};
        const GeoFrame site(origin), other(GeoPoint{48.21, 11.39, 300});
        FleetContext ctx;
        FleetModel* live = ctx.fleet();
        const qint64 t0 = 1'700'000'000'000;
        auto clock = std::make_shared<ManualModelClock>(t0);
        Recorder rec;
        RecorderOptions o;
        o.path = m_dir.filePath(QStringLiteral("schema4.sqlite"));
        o.clock = clock;
        o.flushIntervalMs = 5;
        o.originLat = origin.lat;
        o.originLon = origin.lon;
        o.originAlt = origin.alt;
        QVERIFY(rec.start(o).isEmpty());
        rec.attach(&ctx);
        Truth truth;
        std::mt19937_64 rng(27);
        std::uniform_real_distribution<double> noise(-0.02, 0.02);
        const int machines = 24, steps = 3000; // 5 minutes at 10 Hz
        for (int step = 0; step < steps; ++step) {
            clock->set(t0 + step * 100);
            QVector<MachineState> batch;
            for (int k = 0; k < machines; ++k) {
                const QString id = QStringLiteral("m%1").arg(k);
                if (k == 5 && step >= 1200 && step < 1500) {
                    if (step == 1200)
                        live->remove({id});
                    continue;
                }
                const double a = step * 0.004 + k;
                MachineState m = machine(id, 800 * std::cos(a) + noise(rng), 800 * std::sin(a) + noise(rng));
                m.u = 20 * std::sin(a) + noise(rng);
                m.headingDeg = std::fmod(a * 57.29578 + 90, 360) + 10 * noise(rng);
                m.speed = 3.2 + std::sin(a) + noise(rng);
                m.lastDataMs = clock->nowMs() - 3 - step % 7;
                m.lastMessageMs = m.lastDataMs - 15;
                switch (k % 4) {
                case 0: // lat/lon and e/n/u agree through the site frame, as a bridge makes them
                    break;
                case 1: { // lat/lon in another frame than e/n/u
                    const GeoPoint g = other.toGeodetic({m.e, m.n, m.u});
                    m.lat = g.lat;
                    m.lon = g.lon;
                    break;
                }
                case 2: // no message time, heading in -180..180, reversing
                    m.lastMessageMs = 0;
                    m.headingDeg -= 180;
                    m.speed = -m.speed;
                    break;
                case 3: // jumps, positions a Move cannot carry, status changes
                    if ((step / 100) % 5 == 4)
                        m.e += 5000;
                    if (step % 250 == 17)
                        m.n = 3.0e6;
                    if ((step / 70) % 2 == 1)
                        m.health = HealthLevel::Warning, m.healthText = QStringLiteral("coolant");
                    break;
                }
                if (k % 4 != 1) {
                    const GeoPoint g = site.toGeodetic({m.e, m.n, m.u});
                    m.lat = g.lat;
                    m.lon = g.lon;
                }
                batch.push_back(m);
            }
            live->upsert(batch); // the recorder hears machinesChanged, as in the console
            QHash<QString, MachineState> now;
            for (const MachineState& m : live->machinesSnapshot())
                now.insert(m.id, m);
            truth.now = now;
            truth.at[clock->nowMs()] = now;
            if (step % 2 == 0)
                rec.flush();
        }
        rec.stop();
        QCOMPARE(rec.stats().dropped, 0u);

        auto r = Recording::open(o.path);
        QVERIFY(r);
        QCOMPARE(r->meta(QStringLiteral("schema")), QString::number(kSchemaVersion));
        QCOMPARE(r->meta(QStringLiteral("states_codec")), QStringLiteral("zstd"));
        std::uniform_int_distribution<qint64> when(r->startMs(), r->endMs());
        QVector<qint64> instants;
        for (int i = 0; i < 50; ++i)
            instants << when(rng);
        FleetModel seeked, played;
        ReplayController seekC(r.get(), &seeked), playC(r.get(), &played);
        QVector<qint64> sorted = instants;
        std::sort(sorted.begin(), sorted.end());
        playC.seek(r->startMs());
        QString why;
        for (int i = 0; i < instants.size(); ++i) {
            const qint64 t = instants[i];
            const auto want = truth.pictureAt(t);
            QVERIFY2(withinResolution(r->statesAt(t), want, &why),
                     qPrintable(QStringLiteral("read at +%1 ms: %2").arg(t - t0).arg(why)));
            seekC.seek(t);
            QVERIFY2(withinResolution(pictureOf(seeked), want, &why),
                     qPrintable(QStringLiteral("seek to +%1 ms: %2").arg(t - t0).arg(why)));
            playC.moveTo(sorted[i]); // forward from the previous instant: continues, no new seek
            QVERIFY2(withinResolution(pictureOf(played), truth.pictureAt(sorted[i]), &why),
                     qPrintable(QStringLiteral("play to +%1 ms: %2").arg(sorted[i] - t0).arg(why)));
        }
        // A slice of a schema 4 recording is one too, and replays the same.
        const QString slice = m_dir.filePath(QStringLiteral("schema4-slice.sqlite"));
        QVERIFY(r->exportSlice(slice, t0 + 61'000, t0 + 185'000));
        auto s = Recording::open(slice);
        QVERIFY(s);
        for (qint64 t : {t0 + 61'000, t0 + 61'050, t0 + 120'000, t0 + 150'000, t0 + 185'000})
            QVERIFY2(withinResolution(s->statesAt(t), truth.pictureAt(t), &why), qPrintable(why));
    }

    // A recording of the format before schema 4 (written by the recorder's legacySchema3 path: fixed-width
    // records, exact Delta records, zlib) still opens and replays exactly as it was recorded, and a slice of
    // it becomes a schema 4 recording (the way to migrate one).
    void opensAndReplaysSchemaThreeRecordings() {
        const QString path = m_dir.filePath(QStringLiteral("schema3.sqlite"));
        recordScenario(path, true);
        QString err;
        auto r = Recording::open(path, &err);
        QVERIFY2(r, qPrintable(err));
        QCOMPARE(r->meta(QStringLiteral("schema")), QStringLiteral("3"));
        QCOMPARE(r->meta(QStringLiteral("states_codec")), QStringLiteral("zlib"));
        QString why;
        FleetModel fleet;
        ReplayController c(r.get(), &fleet);
        for (qint64 t : {m_t0, m_t0 + 4999, m_t0 + 15'050, m_t0 + 20'000, m_t0 + 29'999, m_t0 + 45'100,
                         m_t0 + 60'000, m_t0 + 10'000}) {
            const auto want = m_truth.pictureAt(t);
            const auto got = r->statesAt(t);
            QVERIFY2(samePicture(got, want, &why), qPrintable(why));
            for (auto it = want.cbegin(); it != want.cend(); ++it) { // schema 3: mm and exact lat/lon
                QVERIFY(std::abs(got[it.key()].e - it->e) < 1e-9 && std::abs(got[it.key()].n - it->n) < 1e-9);
                QCOMPARE(got[it.key()].lat, it->lat);
                QCOMPARE(got[it.key()].lon, it->lon);
            }
            c.seek(t);
            QVERIFY2(samePicture(pictureOf(fleet), want, &why), qPrintable(why));
        }
        c.seek(m_t0);
        c.moveTo(m_t0 + 33'333);
        QVERIFY2(samePicture(pictureOf(fleet), m_truth.pictureAt(m_t0 + 33'333), &why), qPrintable(why));
        QCOMPARE(r->events(m_t0 - 1, m_t0 + 60'000).size(), 1);
        const QString migrated = m_dir.filePath(QStringLiteral("schema3-to-4.sqlite"));
        QVERIFY(r->exportSlice(migrated, r->startMs(), r->endMs()));
        auto m = Recording::open(migrated);
        QVERIFY(m);
        QCOMPARE(m->meta(QStringLiteral("schema")), QString::number(kSchemaVersion));
        for (qint64 t : {m_t0 + 4999, m_t0 + 20'000, m_t0 + 45'100, m_t0 + 60'000})
            QVERIFY2(withinResolution(m->statesAt(t), r->statesAt(t), &why), qPrintable(why));
    }

    void parsesReplayTimes() {
        const qint64 start = QDateTime(QDate(2026, 11, 23), QTime(21, 0, 0), Qt::UTC).toMSecsSinceEpoch();
        QCOMPARE(parseReplayTime(QStringLiteral("30"), start), start + 30000);
        QCOMPARE(parseReplayTime(QStringLiteral("1.5s"), start), start + 1500);
        QCOMPARE(parseReplayTime(QStringLiteral("21:00:05.250"), start), start + 5250);
        QCOMPARE(parseReplayTime(QStringLiteral("2026-11-23T21:01:00Z"), start), start + 60000);
        QCOMPARE(parseReplayTime(QStringLiteral("soon"), start), qint64(-1));
        QCOMPARE(parseReplayTime(QStringLiteral("25:00:00"), start), qint64(-1));
    }

    void retentionDeletesOldAndExcess() {
        QTemporaryDir d;
        auto make = [&](const QString& name, int kb, int ageDays) {
            QFile f(d.filePath(name));
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray(kb * 1024, 'r'));
            f.flush(); // before the time is set: a write left in the buffer would stamp the file again
            f.setFileTime(QDateTime::currentDateTimeUtc().addDays(-ageDays),
                          QFileDevice::FileModificationTime);
            f.close();
        };
        make(QStringLiteral("ocu-a.sqlite"), 100, 40);
        make(QStringLiteral("ocu-b.sqlite"), 100, 3);
        make(QStringLiteral("ocu-c.sqlite"), 100, 2);
        make(QStringLiteral("ocu-d.sqlite"), 100, 0);  // being written (fresh): kept
        make(QStringLiteral("other.sqlite"), 100, 90); // not ours: kept
        // A creation cut off by a kill: never a recording, deleted once no console can still be creating it.
        make(QStringLiteral("ocu-e.sqlite.part"), 8, 1);
        make(QStringLiteral("ocu-f.sqlite.part"), 8, 0);
        const QStringList gone = applyRetention(d.path(), 250 * 1024, 30);
        QCOMPARE(gone, (QStringList{QStringLiteral("ocu-e.sqlite.part"), QStringLiteral("ocu-a.sqlite"),
                                    QStringLiteral("ocu-b.sqlite")}));
        QVERIFY(QFile::exists(d.filePath(QStringLiteral("ocu-c.sqlite"))));
        QVERIFY(QFile::exists(d.filePath(QStringLiteral("other.sqlite"))));
        QVERIFY(QFile::exists(d.filePath(QStringLiteral("ocu-f.sqlite.part"))));
    }

    // The default retention keeps a long run from filling the disk: the run's own file stays within its limit
    // (its oldest machine data go, the picture from then on and the events stay), and the folder's older runs
    // give way while it records. Fake clock: 20 minutes of 250 machines at 10 Hz with ±1 cm of GNSS-like
    // noise (schema 4 keeps a smooth drive in so few bytes that it takes that many to outgrow the limit three
    // times).
    void longRunStaysWithinItsLimits() {
        QTemporaryDir d;
        QVERIFY(d.isValid());
        QCOMPARE(effectiveMaxFileBytes(0, 2048), qint64(2048) * 1024 * 1024); // unset: the folder's budget
        QCOMPARE(effectiveMaxFileBytes(100, 2048), qint64(100) * 1024 * 1024);
        QCOMPARE(effectiveMaxFileBytes(0, 0), qint64(0));
        {
            QFile old(d.filePath(QStringLiteral("ocu-20260101-000000-1.sqlite"))); // an older run, 600 KB
            QVERIFY(old.open(QIODevice::WriteOnly));
            old.write(QByteArray(600 * 1024, 'r'));
            old.flush();
            old.setFileTime(QDateTime::currentDateTimeUtc().addDays(-1), QFileDevice::FileModificationTime);
        }
        const qint64 limit = 1024 * 1024;
        const QString file = d.filePath(QStringLiteral("ocu-20260102-000000-2.sqlite"));
        const qint64 t0 = 1'700'000'000'000;
        auto clock = std::make_shared<ManualModelClock>(t0);
        Recorder rec;
        RecorderOptions o;
        o.path = file;
        o.clock = clock;
        o.maxFileBytes = effectiveMaxFileBytes(0, 1.0);
        o.retentionDir = d.path();
        o.maxTotalBytes = limit;
        o.maxAgeDays = 30;
        QVERIFY(rec.start(o).isEmpty());
        const int machines = 250, seconds = 1200;
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> noise(-0.01, 0.01);
        qint64 biggest = 0;
        QHash<QString, MachineState> last;
        for (qint64 ms = 0; ms <= seconds * 1000; ms += 100) {
            clock->set(t0 + ms);
            QVector<MachineState> batch;
            for (int i = 0; i < machines; ++i) {
                const double a = double(ms) / 1000.0 * 0.05 + i;
                MachineState m = machine(QStringLiteral("iso23725:t%1").arg(i),
                                         500 * std::cos(a) + i + noise(rng), 500 * std::sin(a) + noise(rng));
                m.headingDeg = std::fmod(a * 57.3, 360);
                m.lastDataMs = clock->nowMs();
                batch.push_back(m);
                last.insert(m.id, m);
            }
            rec.recordStates(batch);
            if (ms % 60000 == 0)
                rec.recordEvent(makeEvent(EventSeverity::Warning, EventKind::Diagnostic, {},
                                          QStringLiteral("minute %1").arg(ms / 60000)));
            if (ms % 200 == 0)
                rec.flush();
            if (ms % 10000 == 0)
                biggest = std::max(biggest, QFileInfo(file).size());
        }
        rec.stop();
        const quint64 written = rec.stats().stateBytes;
        QVERIFY2(written > quint64(3 * limit), qPrintable(QString::number(written))); // it had to trim
        QVERIFY2(biggest <= limit + limit / 2,
                 qPrintable(QStringLiteral("file reached %1 bytes").arg(biggest)));
        QVERIFY(QFileInfo(file).size() <= limit + limit / 2);
        QCOMPARE(rec.deletedByRetention(), QStringList{QStringLiteral("ocu-20260101-000000-1.sqlite")});
        QVERIFY(!QFile::exists(d.filePath(QStringLiteral("ocu-20260101-000000-1.sqlite"))));

        auto r = Recording::open(file);
        QVERIFY(r);
        const qint64 trimmed = r->meta(QStringLiteral("trimmed_before_ms")).toLongLong();
        QVERIFY(trimmed > t0 && trimmed < t0 + seconds * 1000);
        // The end is complete and within the recording's resolution (1 cm, 1e-7 deg), the picture from the
        // trim on too, and every event stayed.
        const auto end = r->statesAt(r->endMs());
        QCOMPARE(end.size(), machines);
        for (const MachineState& m : last) {
            QVERIFY(end.contains(m.id));
            QVERIFY(std::abs(end[m.id].e - m.e) <= 0.005 && std::abs(end[m.id].n - m.n) <= 0.005);
            QVERIFY(std::abs(end[m.id].lat - m.lat) <= 0.5e-7 && std::abs(end[m.id].lon - m.lon) <= 0.5e-7);
        }
        QCOMPARE(r->statesAt(trimmed + 1).size(), machines);
        QCOMPARE(r->events(r->startMs() - 1, r->endMs()).size(), seconds / 60 + 1);
    }
};

QTEST_MAIN(TestRecorder)
#include "test_recorder.moc"
