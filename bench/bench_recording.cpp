// Flight recorder benchmarks (docs/performance.md "Flight recorder and replay"): prints figures, asserts
// nothing.
//   1. Recording cost: N machines x H Hz (default 1,000 x 10) plus other traffic (an event and a link change
//      per second, a command every 10 s) for S seconds of recording time, pushed as the console does; CPU
//      time of the recorder (its writer thread and the producers' record calls) per second of traffic =
//      share of one core; bytes per machine update and MB per machine-hour, twice: "before" (schema 3 as the
//      console wrote it until schema 4: exact Delta records, zlib, every inbound message) and "after" (the
//      default recording: schema 4 Move records, zstd, no message log). Positions carry GNSS-like noise
//      (--noise-cm, default +-1 cm; heading +-0.05 deg, speed +-0.02 m/s) and lat/lon follow e/n/u through
//      the site frame, as the bridges derive one from the other. Then the "after" state chunks compressed
//      again with zlib and zstd at several levels (size and time).
//   2. Seek: random positions in the recording; wall time per seek (picture rebuilt: keyframe + records after
//      it, pushed into a FleetModel; the alarm list: the rows alive at T, at most the list's cap), and the
//      walk over the events that opening the replay costs once.
//   3. Replay at 16x: advancing through the recording in 40 ms ticks of 16x (640 ms of recording per tick)
//   into a
//      FleetModel; keeps up when a tick's work takes less than its 40 ms.
//   Every machine update also arrives as one decoded inbound message through the stacks' tap (MessageTap), a
//   third each JAUS ReportGlobalPose (34 bytes), ISO 23725 PositionV1 (JSON, ~330 bytes) and OSYRIS CmPos (73
//   bytes), as the io threads hand them over (--no-messages leaves them out).
// Usage: bench_recording [--machines N] [--hz H] [--seconds S] [--seeks K] [--keep FILE] [--no-messages]
//                        [--only before|after] [--noise-cm C] [--seek-only FILE] [--after-messages]
//                        [--ack-after S]
//   --no-messages: the "before" run without the message log; --seek-only: seeks (and 16x) in an existing
//   recording (e.g. a 12-hour one kept with --keep) without recording anything; --after-messages: one more
//   schema 4 run with record.messages on (what the message log costs now); --ack-after: every event (an
//   alarm: a warning) acknowledged S seconds after it, as an operator would (default: never, so that the
//   alarm list holds every event of the file).
#include "models/AlarmModel.h"
#include "models/FleetBridge.h"
#include "models/FleetModel.h"
#include "models/recording/AlarmHistory.h"
#include "models/recording/BlobCodec.h"
#include "models/recording/Recorder.h"
#include "models/recording/Recording.h"
#include "models/recording/ReplayController.h"
#include "protocols/common/GeoFrame.h"
#include "protocols/common/MessageTap.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTemporaryDir>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <limits>
#include <random>

#include <sqlite3.h>
#include <sys/resource.h>
#include <time.h>

using namespace ocu;
using namespace ocu::recording;

static double processCpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

static double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + double(ts.tv_nsec) / 1e9;
}

struct Setup {
    int machines = 1000, hz = 10, seconds = 60;
    double noiseCm = 1;
    bool messages = true;   // the "before" run's message log
    qint64 ackAfterMs = -1; // --ack-after: each event's alarm acknowledged this long after it (-1: never)
};

struct RunFigures {
    quint64 updates = 0;
    double fileBytes = 0;
    double recorderCpu = 0; // writer thread + the producer's record calls
    double processCpu = 0;
    Recorder::Stats stats;
};

static const GeoPoint kOrigin{48.2, 11.4, 480};

// Records `setup` into `file`: legacy = the format before schema 4; messages = the message log on.
static bool record(const Setup& setup, const QString& file, bool legacy, bool messages, RunFigures& fig) {
    const int machines = setup.machines;
    const qint64 t0 = 1'700'000'000'000;
    auto clock = std::make_shared<ManualModelClock>(t0);
    const GeoFrame frame(kOrigin);
    std::vector<MachineState> fleet;
    fleet.resize(size_t(machines));
    for (int i = 0; i < machines; ++i) {
        MachineState& m = fleet[size_t(i)];
        m.id = QStringLiteral("iso23725:truck-%1").arg(i);
        m.protocol = Protocol::Iso23725;
        m.name = QStringLiteral("HT%1").arg(i);
        m.type = QStringLiteral("haul truck");
        m.link = LinkState::Up;
        m.hasPosition = true;
        m.modeText = QStringLiteral("Autonomous");
        m.mode = ModeCategory::Autonomous;
        m.stop = StopState::None;
        m.health = HealthLevel::Ok;
    }
    Recorder rec;
    RecorderOptions o;
    o.path = file;
    o.clock = clock;
    o.flushIntervalMs = 200;
    o.legacySchema3 = legacy;
    o.messages = messages;
    o.originLat = kOrigin.lat;
    o.originLon = kOrigin.lon;
    o.originAlt = kOrigin.alt;
    // The console's default: one run's file limited to record.max_total_mb (2048 MB; its trim check and
    // incremental vacuum run with every commit).
    o.maxFileBytes = effectiveMaxFileBytes(0, 2048);
    if (const QString err = rec.start(o); !err.isEmpty()) {
        std::fprintf(stderr, "bench_recording: %s\n", qPrintable(err));
        return false;
    }
    const int stepMs = 1000 / setup.hz;
    // The inbound messages: one per machine update, bytes prepared once (the peers encode them).
    struct Wire {
        const char* protocol;
        std::string link, peer;
        const char* type;
        std::vector<std::uint8_t> bytes;
    };
    std::vector<Wire> wire{size_t(machines)};
    for (int i = 0; i < machines; ++i) {
        Wire& w = wire[size_t(i)];
        if (i % 3 == 0) {
            w = {"jaus", "jaus", std::to_string(100 + i) + ".1.1", "4402", std::vector<std::uint8_t>(34, 7)};
            w.bytes[0] = 0x02, w.bytes[1] = 0x44;
        } else if (i % 3 == 1) {
            const std::string json =
                R"({"Header":{"Protocol":"ISO23725","Version":"1.0","EquipmentId":"6f1c2d3e-0000-4000-8000-)" +
                std::to_string(100000000000 + i) +
                R"(","Timestamp":"2026-11-24T02:00:00.000Z"},"PositionV1":{"Latitude":48.2085123,"Longitude":11.4702456,"Altitude":480.25,"Heading":123.4,"Speed":8.25,"Accuracy":0.05,"Source":"GNSS","Time":"2026-11-24T02:00:00.000Z"}})";
            w = {"iso23725", "ahs", "127.0.0.1:40000", "PositionV1", {json.begin(), json.end()}};
        } else {
            w = {"osyris", "osyris:233.1.1.1:50010", std::to_string(i % 250), "CmPos",
                 std::vector<std::uint8_t>(73, 3)};
        }
    }
    MessageTap* tap = rec.messageTap();
    std::mt19937_64 rng(27);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double noise = setup.noiseCm / 100.0;
    const double cpu0 = processCpuSeconds();
    double producerCpu = 0;
    QVector<MachineState> batch;
    batch.reserve(machines);
    const qint64 ackAfterMs = setup.ackAfterMs;
    std::deque<std::pair<qint64, QString>> pendingAcks; // (when, the alarm's key)
    for (qint64 ms = 0; ms < qint64(setup.seconds) * 1000; ms += stepMs) {
        clock->set(t0 + ms);
        while (!pendingAcks.empty() && pendingAcks.front().first <= ms) {
            rec.recordAck(pendingAcks.front().second, QStringLiteral("op"), clock->nowMs());
            pendingAcks.pop_front();
        }
        batch.clear();
        for (int i = 0; i < machines; ++i) {
            MachineState& m = fleet[size_t(i)];
            const double a = double(ms) / 1000.0 * 0.01 + i;
            // A truck on a 1-km circle at ~10 m/s, with GNSS-like noise on every coordinate.
            m.e = 1000 * std::cos(a) + i + noise * unit(rng);
            m.n = 1000 * std::sin(a) + noise * unit(rng);
            m.u = 10 + std::sin(a * 3) + noise * unit(rng);
            m.headingDeg = std::fmod(a * 57.3, 360) + 0.05 * unit(rng);
            m.speed = 8 + std::sin(a) + 0.02 * unit(rng);
            // lat/lon and e/n/u agree through the site frame, as a bridge makes them.
            const GeoPoint g = frame.toGeodetic({m.e, m.n, m.u});
            m.lat = g.lat;
            m.lon = g.lon;
            m.lastDataMs = clock->nowMs() - 3;
            m.lastMessageMs = clock->nowMs() - 20;
            if (ms % 30000 == 0 && i % 10 == 0) // a status change now and then (Full records)
                m.healthText = m.healthText.isEmpty() ? QStringLiteral("tyre pressure") : QString();
            batch.push_back(m);
            if (o.messages) {
                Wire& w = wire[size_t(i)];
                // What changes between messages: the position's digits or bytes.
                const auto v = std::uint64_t(std::llround(std::fabs(m.e * 1e4) + std::fabs(m.n * 1e4)));
                if (w.bytes.size() > 200) { // the JSON's latitude, longitude and heading digits
                    for (const char* key : {"Latitude\":48.", "Longitude\":11.", "Heading\":"}) {
                        const std::size_t kl = std::strlen(key);
                        auto p = std::search(w.bytes.begin(), w.bytes.end(), key, key + kl);
                        std::uint64_t x = v ^ kl;
                        if (p != w.bytes.end())
                            for (p += std::ptrdiff_t(kl); p < w.bytes.end() && std::isdigit(*p); ++p, x /= 7)
                                *p = std::uint8_t('0' + x % 10);
                    }
                } else {
                    for (std::size_t k = 4; k < 28 && k < w.bytes.size(); ++k)
                        w.bytes[k] = std::uint8_t(v >> (8 * (k % 8)));
                }
                const double p0 = threadCpuSeconds();
                tap->onDecoded({w.protocol, w.link, w.peer, w.type, w.bytes});
                producerCpu += threadCpuSeconds() - p0;
            }
        }
        const double c1 = threadCpuSeconds();
        rec.recordStates(batch); // what FleetModel::machinesChanged hands over per delivered batch
        producerCpu += threadCpuSeconds() - c1;
        fig.updates += quint64(machines);
        if (ms % 1000 == 0) {
            FleetEvent ev = makeEvent(EventSeverity::Warning, EventKind::Diagnostic, fleet[0].id,
                                      QStringLiteral("diagnostic %1").arg(ms));
            ev.timeMs =
                clock->nowMs(); // the recording's time: an acknowledgement covers what was raised before it
            rec.recordEvent(ev);
            if (ackAfterMs >= 0)
                pendingAcks.push_back({ms + ackAfterMs, alarmKey(ev)});
            LinkStatus l;
            l.link = QStringLiteral("iso23725:ahs");
            l.state = LinkState::Up;
            l.dataAgeMs = 40;
            rec.recordLink(QStringLiteral("iso23725"), l);
        }
        if (ms % 10000 == 0)
            rec.recordCommand(QStringLiteral(
                R"({"origin":"gui","action":"stop","target":"iso23725:truck-1","ok":true,"targets":[{"id":"iso23725:truck-1","sent":true}]})"));
        // The writer commits every 200 ms of recording time (as with the wall clock).
        if (ms % 200 == 0)
            rec.flush();
        if (ms % 3'600'000 == 0 && ms > 0)
            std::fprintf(stderr, "  ... %lld h recorded\n", static_cast<long long>(ms / 3'600'000));
    }
    rec.stop();
    fig.processCpu = processCpuSeconds() - cpu0;
    fig.stats = rec.stats();
    fig.recorderCpu = producerCpu + double(fig.stats.writerCpuNs) / 1e9;
    fig.fileBytes = double(QFileInfo(file).size());
    return true;
}

static void printRun(const char* label, const Setup& setup, const RunFigures& f) {
    const double hours = setup.seconds / 3600.0;
    const double machineHours = hours * setup.machines;
    std::printf("%s: %d machines x %d Hz + events/links/commands, %d s of traffic, %llu state records\n",
                label, setup.machines, setup.hz, setup.seconds, static_cast<unsigned long long>(f.updates));
    std::printf(
        "  cpu: recorder (writer thread + record calls) %.3f s = %.2f %% of one core; writer alone %.3f "
        "s; whole process incl. the bench's own traffic generation %.3f s\n",
        f.recorderCpu, 100.0 * f.recorderCpu / setup.seconds, double(f.stats.writerCpuNs) / 1e9,
        f.processCpu);
    std::printf("  dropped %llu, commits %llu, inbound messages recorded %llu (%.1f MB of message chunks)\n",
                static_cast<unsigned long long>(f.stats.dropped),
                static_cast<unsigned long long>(f.stats.commits),
                static_cast<unsigned long long>(f.stats.messages), double(f.stats.messageBytes) / 1e6);
    std::printf(
        "  state chunks %.2f MB (%.2f MB before compression, %.2f bytes per update), keyframes %.2f MB\n",
        double(f.stats.stateBytes) / 1e6, double(f.stats.stateRawBytes) / 1e6,
        double(f.stats.stateRawBytes) / double(f.updates), double(f.stats.keyframeBytes) / 1e6);
    std::printf(
        "  file %.2f MB = %.1f MB per hour = %.3f MB per machine-hour (%.2f bytes per machine update)\n",
        f.fileBytes / 1e6, f.fileBytes / 1e6 / hours, f.fileBytes / 1e6 / machineHours,
        f.fileBytes / double(f.updates));
}

// The state chunks of `file` decompressed and compressed again with each codec and level.
static void compareCodecs(const QString& file) {
    sqlite3* db = nullptr;
    if (sqlite3_open_v2(file.toUtf8().constData(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK)
        return;
    std::vector<QByteArray> chunks;
    sqlite3_stmt* q = nullptr;
    sqlite3_prepare_v2(db, "SELECT data FROM states ORDER BY id", -1, &q, nullptr);
    while (sqlite3_step(q) == SQLITE_ROW)
        chunks.push_back(uncompressBlob(
            QByteArray(static_cast<const char*>(sqlite3_column_blob(q, 0)), sqlite3_column_bytes(q, 0)),
            BlobCodec::Zstd));
    sqlite3_finalize(q);
    sqlite3_close(db);
    double raw = 0;
    for (const QByteArray& c : chunks)
        raw += double(c.size());
    std::printf("codecs on the \"after\" state chunks (%zu chunks, %.2f MB uncompressed):\n", chunks.size(),
                raw / 1e6);
    const std::pair<BlobCodec, int> codecs[] = {
        {BlobCodec::Zlib, 1}, {BlobCodec::Zlib, 6}, {BlobCodec::Zlib, 9}, {BlobCodec::Zstd, 1},
        {BlobCodec::Zstd, 3}, {BlobCodec::Zstd, 6}, {BlobCodec::Zstd, 9}, {BlobCodec::Zstd, 19}};
    for (const auto& [codec, level] : codecs) {
        double packed = 0, cNs = 0, dNs = 0;
        for (const QByteArray& c : chunks) {
            QElapsedTimer t;
            t.start();
            const QByteArray p = compressBlob(c, codec, level);
            cNs += double(t.nsecsElapsed());
            t.restart();
            const QByteArray back = uncompressBlob(p, codec);
            dNs += double(t.nsecsElapsed());
            packed += double(p.size());
            if (back != c)
                std::printf("  %s %d: round trip FAILED\n", blobCodecName(codec), level);
        }
        std::printf("  %s level %2d: %.2f MB (%.1f x), compress %.0f MB/s, decompress %.0f MB/s\n",
                    blobCodecName(codec), level, packed / 1e6, raw / packed, raw / (cNs / 1e9) / 1e6,
                    raw / (dNs / 1e9) / 1e6);
    }
}

static void seekAndReplay(const QString& file, int seeks, const char* label) {
    auto rec = Recording::open(file);
    if (!rec) {
        std::fprintf(stderr, "bench_recording: cannot open %s\n", qPrintable(file));
        return;
    }
    const double hours = double(rec->endMs() - rec->startMs()) / 3.6e6;
    {
        FleetModel model;
        QElapsedTimer opening;
        opening.start();
        ReplayController c(rec.get(), &model); // walks the events once (AlarmHistory)
        const double openMs = double(opening.nsecsElapsed()) / 1e6;
        const AlarmHistory history(rec.get(), c.maxAlarmEntries());
        AlarmModel restored;
        std::mt19937_64 rng(16);
        std::uniform_int_distribution<qint64> pos(rec->startMs(), rec->endMs());
        std::vector<double> ms, picture, alarmList, linksRead;
        int alarmRows = 0;
        for (int i = 0; i < seeks; ++i) {
            const qint64 t = pos(rng);
            c.seek(t);
            ms.push_back(c.lastSeekMs());
            QElapsedTimer p;
            p.start();
            (void)rec->statesAtIdx(t); // the machine picture alone (keyframe + chunks)
            picture.push_back(double(p.nsecsElapsed()) / 1e6);
            p.restart();
            restored.restore(history.rowsAt(t)); // the alarm list at T: the rows alive then, read by id
            alarmList.push_back(double(p.nsecsElapsed()) / 1e6);
            alarmRows = std::max(alarmRows, restored.rowCount());
            p.restart();
            (void)rec->linksAt(t);
            linksRead.push_back(double(p.nsecsElapsed()) / 1e6);
        }
        std::sort(ms.begin(), ms.end());
        std::sort(picture.begin(), picture.end());
        double sum = 0, pictureSum = 0;
        for (double v : ms)
            sum += v;
        for (double v : picture)
            pictureSum += v;
        std::printf(
            "seek (%s): %d random seeks in %.2f h of recording (%.0f MB), %d machines: mean %.1f ms, p50 "
            "%.1f ms, max %.1f ms\n",
            label, seeks, hours, double(QFileInfo(file).size()) / 1e6, int(model.rowCount()),
            sum / double(ms.size()), ms[ms.size() / 2], ms.back());
        std::printf("  of which the machine picture alone (keyframe + chunks): mean %.1f ms, max %.1f ms\n",
                    pictureSum / double(picture.size()), picture.back());
        auto mean = [](const std::vector<double>& v) {
            double sum = 0;
            for (double x : v)
                sum += x;
            return v.empty() ? 0.0 : sum / double(v.size());
        };
        std::sort(alarmList.begin(), alarmList.end());
        std::printf(
            "  the alarm list at T (up to %d rows, cap %d): mean %.1f ms, max %.1f ms; the links at T: mean "
            "%.1f ms\n",
            alarmRows, c.maxAlarmEntries(), mean(alarmList), alarmList.back(), mean(linksRead));
        std::printf(
            "  opening the replay (one walk over %lld events and %lld acknowledgements): %.1f ms\n",
            static_cast<long long>(
                rec->events(std::numeric_limits<qint64>::min(), std::numeric_limits<qint64>::max()).size()),
            static_cast<long long>(
                rec->acks(std::numeric_limits<qint64>::min(), std::numeric_limits<qint64>::max()).size()),
            openMs);
    }
    {
        FleetModel model;
        ReplayController c(rec.get(), &model);
        // At most 10 minutes of 16x play: its per-tick cost does not depend on the file's length.
        const qint64 from = rec->startMs(), to = std::min(rec->endMs(), from + 600'000);
        c.seek(from);
        const qint64 tick = 640; // 40 ms of wall time at 16x
        QElapsedTimer wall;
        wall.start();
        double worst = 0;
        int ticks = 0;
        for (qint64 t = from; t < to;) {
            QElapsedTimer one;
            one.start();
            t = std::min(to, t + tick);
            c.moveTo(t);
            worst = std::max(worst, double(one.nsecsElapsed()) / 1e6);
            ++ticks;
        }
        const double total = double(wall.nsecsElapsed()) / 1e6;
        std::printf(
            "replay 16x (%s): %d ticks of 640 ms recording: mean %.1f ms per tick (budget 40 ms), worst "
            "%.1f ms; %.1fx real time possible\n",
            label, ticks, total / ticks, worst, double(to - from) / total);
    }
}

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    Setup setup;
    int seeks = 50;
    QString keep, only, seekOnly;
    const QStringList args = app.arguments();
    setup.messages = !args.contains(QStringLiteral("--no-messages"));
    for (int i = 1; i + 1 < args.size(); ++i) {
        if (args[i] == QLatin1String("--machines"))
            setup.machines = args[++i].toInt();
        else if (args[i] == QLatin1String("--hz"))
            setup.hz = args[++i].toInt();
        else if (args[i] == QLatin1String("--seconds"))
            setup.seconds = args[++i].toInt();
        else if (args[i] == QLatin1String("--seeks"))
            seeks = args[++i].toInt();
        else if (args[i] == QLatin1String("--keep"))
            keep = args[++i];
        else if (args[i] == QLatin1String("--only"))
            only = args[++i];
        else if (args[i] == QLatin1String("--ack-after"))
            setup.ackAfterMs = qint64(args[++i].toDouble() * 1000);
        else if (args[i] == QLatin1String("--noise-cm"))
            setup.noiseCm = args[++i].toDouble();
        else if (args[i] == QLatin1String("--seek-only"))
            seekOnly = args[++i];
    }
    if (!seekOnly.isEmpty()) {
        seekAndReplay(seekOnly, seeks, "existing file");
        return 0;
    }
    QTemporaryDir dir;
    const QString before = dir.filePath(QStringLiteral("before.sqlite"));
    const QString after = keep.isEmpty() ? dir.filePath(QStringLiteral("after.sqlite")) : keep;
    RunFigures fb, fa;
    const bool doBefore = only != QLatin1String("after"), doAfter = only != QLatin1String("before");
    if (doBefore) {
        if (!record(setup, before, true, setup.messages, fb))
            return 1;
        printRun("before (schema 3, every inbound message)", setup, fb);
    }
    if (doAfter) {
        if (!record(setup, after, false, false, fa))
            return 1;
        printRun("after (schema 4, the default recording)", setup, fa);
    }
    if (args.contains(QStringLiteral("--after-messages"))) {
        RunFigures fm;
        if (!record(setup, dir.filePath(QStringLiteral("after-messages.sqlite")), false, true, fm))
            return 1;
        printRun("after with record.messages (schema 4 + every inbound message)", setup, fm);
    }
    const double mh = setup.seconds / 3600.0 * setup.machines;
    if (doBefore && doAfter)
        std::printf(
            "before -> after: %.2f -> %.2f bytes per machine update, %.3f -> %.3f MB per machine-hour "
            "(target <= 0.25); the default folder (2,048 MB) holds %.1f h -> %.1f h of these %d "
            "machines\n",
            fb.fileBytes / double(fb.updates), fa.fileBytes / double(fa.updates), fb.fileBytes / 1e6 / mh,
            fa.fileBytes / 1e6 / mh, 2048e6 * 1.048576 / (fb.fileBytes / (setup.seconds / 3600.0)),
            2048e6 * 1.048576 / (fa.fileBytes / (setup.seconds / 3600.0)), setup.machines);
    if (doAfter)
        compareCodecs(after);
    if (doBefore)
        seekAndReplay(before, seeks, "before");
    if (doAfter)
        seekAndReplay(after, seeks, "after");
    return 0;
}
