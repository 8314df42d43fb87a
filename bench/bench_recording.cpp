// Issue 16 benchmarks (docs/performance.md "Flight recorder and replay"): prints figures, asserts nothing.
//   1. Recording cost: N machines x H Hz (default 1,000 x 10) plus other traffic (an event and a link change
//      per second, a command every 10 s) for S seconds of recording time, pushed as the console does; CPU
//      time of the whole process (producer + writer thread) per second of traffic = share of one core; file
//      size per hour.
//   2. Seek: random positions in the recording; wall time per seek (picture rebuilt: keyframe + records after
//      it, pushed into a FleetModel).
//   3. Replay at 16x: advancing through the recording in 40 ms ticks of 16x (640 ms of recording per tick)
//   into a
//      FleetModel; keeps up when a tick's work takes less than its 40 ms.
// Usage: bench_recording [--machines N] [--hz H] [--seconds S] [--seeks K] [--keep FILE]
#include "models/FleetBridge.h"
#include "models/FleetModel.h"
#include "models/recording/Recorder.h"
#include "models/recording/Recording.h"
#include "models/recording/ReplayController.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
#include <cstdio>
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
        if (const QString err = rec.start(o); !err.isEmpty()) {
            std::fprintf(stderr, "bench_recording: %s\n", qPrintable(err));
            return 1;
        }
        const int stepMs = 1000 / hz;
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
                m.headingDeg = std::fmod(a * 57.3, 360);
                m.speed = 8 + std::sin(a);
                m.lastDataMs = clock - 3;
                m.lastMessageMs = clock - 20;
                if (ms % 30000 == 0 && i % 10 == 0) // a status change now and then (Full records)
                    m.healthText = m.healthText.isEmpty() ? QStringLiteral("tyre pressure") : QString();
                batch.push_back(m);
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
