// Flight recorder and replay benchmarks (docs/performance.md "Flight recorder and replay"): prints figures,
// asserts nothing.
//   1. Recording cost: N machines x H Hz (default 1,000 x 10) plus other traffic (an event and a link change
//      per second, a command every 10 s) for S seconds of recording time, pushed as the console does; CPU
//      time of the whole process (producer + writer thread) per second of traffic = share of one core; file
//      size per hour.
//   2. Seek: random positions in the recording; wall time per seek (picture rebuilt: keyframe + records after
//      it, pushed into a FleetModel).
//   3. Replay at 16x: advancing through the recording in 40 ms ticks of 16x (640 ms of recording per tick)
//   into a
//      FleetModel; keeps up when a tick's work takes less than its 40 ms.
//   Every machine update also arrives as one decoded inbound message through the stacks' tap (MessageTap), a
//   third each JAUS ReportGlobalPose (34 bytes), ISO 23725 PositionV1 (JSON, ~330 bytes) and OSYRIS CmPos (73
//   bytes), as the io threads hand them over (--no-messages leaves them out).
// Usage: bench_recording [--machines N] [--hz H] [--seconds S] [--seeks K] [--keep FILE] [--no-messages]
#include "models/FleetBridge.h"
#include "models/FleetModel.h"
#include "models/recording/Recorder.h"
#include "models/recording/Recording.h"
#include "models/recording/ReplayController.h"
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
#include <random>

#include <sys/resource.h>

using namespace ocu;
using namespace ocu::recording;

static double processCpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    int machines = 1000, hz = 10, seconds = 60, seeks = 50;
    QString keep;
    const QStringList args = app.arguments();
    const bool withMessages = !args.contains(QStringLiteral("--no-messages"));
    for (int i = 1; i + 1 < args.size(); ++i) {
        if (args[i] == QLatin1String("--machines"))
            machines = args[++i].toInt();
        else if (args[i] == QLatin1String("--hz"))
            hz = args[++i].toInt();
        else if (args[i] == QLatin1String("--seconds"))
            seconds = args[++i].toInt();
        else if (args[i] == QLatin1String("--seeks"))
            seeks = args[++i].toInt();
        else if (args[i] == QLatin1String("--keep"))
            keep = args[++i];
    }
    QTemporaryDir dir;
    const QString file = keep.isEmpty() ? dir.filePath(QStringLiteral("bench.sqlite")) : keep;
    const qint64 t0 = 1'700'000'000'000;
    qint64 clock = t0;

    // ---- 1. recording ----
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
        m.lat = 48.2;
        m.lon = 11.4;
    }
    double cpuRecording = 0;
    quint64 records = 0;
    {
        Recorder rec;
        RecorderOptions o;
        o.path = file;
        o.clock = [&clock] { return clock; };
        o.flushIntervalMs = 200;
        // The console's default: one run's file limited to record.max_total_mb (2048 MB; its trim check and
        // incremental vacuum run with every commit).
        o.maxFileBytes = effectiveMaxFileBytes(0, 2048);
        if (const QString err = rec.start(o); !err.isEmpty()) {
            std::fprintf(stderr, "bench_recording: %s\n", qPrintable(err));
            return 1;
        }
        const int stepMs = 1000 / hz;
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
                w = {"jaus", "jaus", std::to_string(100 + i) + ".1.1", "4402",
                     std::vector<std::uint8_t>(34, 7)};
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
        const double cpu0 = processCpuSeconds();
        QVector<MachineState> batch;
        batch.reserve(machines);
        for (qint64 ms = 0; ms < qint64(seconds) * 1000; ms += stepMs) {
            clock = t0 + ms;
            batch.clear();
            for (int i = 0; i < machines; ++i) {
                MachineState& m = fleet[size_t(i)];
                const double a = double(ms) / 1000.0 * 0.01 + i;
                m.e = 1000 * std::cos(a) + i;
                m.n = 1000 * std::sin(a);
                m.u = 10 + std::sin(a * 3);
                // lat/lon follow e/n (a recorded Position carries both, the doubles exactly).
                m.lat = 48.2 + m.n / 111320.0;
                m.lon = 11.4 + m.e / (111320.0 * 0.6665);
                m.headingDeg = std::fmod(a * 57.3, 360);
                m.speed = 8 + std::sin(a);
                m.lastDataMs = clock - 3;
                m.lastMessageMs = clock - 20;
                if (ms % 30000 == 0 && i % 10 == 0) // a status change now and then (Full records)
                    m.healthText = m.healthText.isEmpty() ? QStringLiteral("tyre pressure") : QString();
                batch.push_back(m);
                if (withMessages) {
                    Wire& w = wire[size_t(i)];
                    // What changes between messages: the position's digits or bytes.
                    const auto v = std::uint64_t(std::llround(std::fabs(m.e * 1e4) + std::fabs(m.n * 1e4)));
                    if (w.bytes.size() > 200) { // the JSON's latitude, longitude and heading digits
                        for (const char* key : {"Latitude\":48.", "Longitude\":11.", "Heading\":"}) {
                            const std::size_t kl = std::strlen(key);
                            auto p = std::search(w.bytes.begin(), w.bytes.end(), key, key + kl);
                            std::uint64_t x = v ^ kl;
                            if (p != w.bytes.end())
                                for (p += std::ptrdiff_t(kl); p < w.bytes.end() && std::isdigit(*p);
                                     ++p, x /= 7)
                                    *p = std::uint8_t('0' + x % 10);
                        }
                    } else {
                        for (std::size_t k = 4; k < 28 && k < w.bytes.size(); ++k)
                            w.bytes[k] = std::uint8_t(v >> (8 * (k % 8)));
                    }
                    tap->onDecoded({w.protocol, w.link, w.peer, w.type, w.bytes});
                }
            }
            rec.recordStates(batch); // what FleetModel::machinesChanged hands over per delivered batch
            records += quint64(machines);
            if (ms % 1000 == 0) {
                rec.recordEvent(makeEvent(EventSeverity::Warning, EventKind::Diagnostic, fleet[0].id,
                                          QStringLiteral("diagnostic %1").arg(ms)));
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
        }
        rec.stop();
        cpuRecording = processCpuSeconds() - cpu0;
        const auto s = rec.stats();
        const double bytes = double(QFileInfo(file).size());
        std::printf(
            "recording: %d machines x %d Hz + events/links/commands, %d s of traffic, %llu state records\n",
            machines, hz, seconds, static_cast<unsigned long long>(records));
        std::printf("  cpu (producer + writer): %.3f s = %.2f %% of one core (writer thread alone %.3f s)\n",
                    cpuRecording, 100.0 * cpuRecording / seconds, double(s.writerCpuNs) / 1e9);
        std::printf("  dropped %llu, commits %llu\n", static_cast<unsigned long long>(s.dropped),
                    static_cast<unsigned long long>(s.commits));
        std::printf("  inbound messages recorded %llu (%.1f MB of message chunks = %.0f MB per hour)\n",
                    static_cast<unsigned long long>(s.messages), double(s.messageBytes) / 1e6,
                    double(s.messageBytes) / 1e6 * 3600.0 / seconds);
        std::printf("  file %.1f MB = %.0f MB per hour (%.1f bytes per machine update)\n", bytes / 1e6,
                    bytes / 1e6 * 3600.0 / seconds, bytes / double(records));
    }

    // ---- 2. seek ----
    auto rec = Recording::open(file);
    if (!rec) {
        std::fprintf(stderr, "bench_recording: cannot open the recording\n");
        return 1;
    }
    {
        FleetModel model;
        ReplayController c(rec.get(), &model);
        std::mt19937_64 rng(16);
        std::uniform_int_distribution<qint64> pos(rec->startMs(), rec->endMs());
        std::vector<double> ms;
        for (int i = 0; i < seeks; ++i) {
            c.seek(pos(rng));
            ms.push_back(c.lastSeekMs());
        }
        std::sort(ms.begin(), ms.end());
        double sum = 0;
        for (double v : ms)
            sum += v;
        std::printf("seek: %d random seeks in %d s of recording, %d machines: mean %.1f ms, p50 %.1f ms, max "
                    "%.1f ms\n",
                    seeks, seconds, int(model.rowCount()), sum / double(ms.size()), ms[ms.size() / 2],
                    ms.back());
    }

    // ---- 3. replay at 16x ----
    {
        FleetModel model;
        ReplayController c(rec.get(), &model);
        c.seek(rec->startMs());
        const qint64 tick = 640; // 40 ms of wall time at 16x
        QElapsedTimer wall;
        wall.start();
        double worst = 0;
        int ticks = 0;
        for (qint64 t = rec->startMs(); t < rec->endMs();) {
            QElapsedTimer one;
            one.start();
            t = std::min(rec->endMs(), t + tick);
            c.moveTo(t);
            worst = std::max(worst, double(one.nsecsElapsed()) / 1e6);
            ++ticks;
        }
        const double total = double(wall.nsecsElapsed()) / 1e6;
        std::printf(
            "replay 16x: %d ticks of 640 ms recording: mean %.1f ms per tick (budget 40 ms), worst %.1f ms; "
            "%.1fx real time possible\n",
            ticks, total / ticks, worst, double(rec->endMs() - rec->startMs()) / total);
    }
    return 0;
}
