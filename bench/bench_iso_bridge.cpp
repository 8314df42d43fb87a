// bench_iso_bridge: the ISO 23725 positions path end to end on the console's side:
// 1,000 simulated trucks at 10 Hz over loopback ws:// -> IsoStack io thread (decode, FmsCore) -> IsoBridge
// -> the bridge's coalescer -> FleetModel on the GUI thread. Reports, per position received:
//  * io_cpu_us_per_pos: CPU time of the stack's io thread ("iso23725"), all of it (WebSocket, decode, core,
//    bridge) divided by the positions the simulator sent in the window;
//  * gui_cpu_us_per_pos / gui_busy_pct: the GUI thread's share (coalescer drains, FleetModel upserts);
//  * values_pushed_per_pos: machine values handed to the coalescer per position;
//  * locks_per_pos: the coalescer's hand-overs (one lock each) per position;
//  * latency_mean_ms / latency_max_ms: from the position's arrival in FmsCore (MachineState::lastDataMs) to
//    its delivery on the GUI thread (machinesUpdated).
#include "models/FleetModel.h"
#include "models/bridges/IsoBridge.h"
#include "sim/iso23725/IsoDemo.h"

#include "protocols/common/Log.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QTimer>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <sys/types.h>

using namespace ocu;

namespace {

double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

// The id of this process's thread named `name` (IoThread names its thread), or 0.
pid_t threadNamed(const QString& name) {
    const auto tasks = QDir(QStringLiteral("/proc/self/task")).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    for (const QString& tid : tasks) {
        QFile f(QStringLiteral("/proc/self/task/%1/comm").arg(tid));
        if (f.open(QIODevice::ReadOnly) && QString::fromUtf8(f.readAll()).trimmed() == name)
            return pid_t(tid.toInt());
    }
    return 0;
}

// CPU time of another thread of this process, through its per-thread CPU clock (the clock id Linux derives
// from a thread id, as glibc's pthread_getcpuclockid does: ~tid << 3 | CPUCLOCK_SCHED | CPUCLOCK_PERTHREAD).
double threadCpuSeconds(pid_t tid) {
    const clockid_t clock = clockid_t((~unsigned(tid) << 3) | 6u);
    timespec ts{};
    if (clock_gettime(clock, &ts) != 0)
        return 0;
    return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

void runEventLoopFor(int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

} // namespace

static void BM_IsoPositionsIntoFleetModel(benchmark::State& state) {
    setLogThreshold(LogLevel::Error);
    const int trucks = int(state.range(0));
    const int seconds = 5;
    for (auto _ : state) {
        sim::SimulatedAhsConfig sc;
        sc.truckCount = trucks;
        sc.positionRateHz = 10;
        sc.healthEvents = true; // health and diagnostics in every snapshot, as on a real site
        auto demo = sim::startIsoDemo(sc);
        if (!demo.ahs) {
            state.SkipWithError("simulator did not start");
            return;
        }
        IsoBridge bridge(demo.config, GeoFrame(sc.origin));
        FleetModel model;
        model.setRefreshIntervalMs(500);
        model.addBridge(&bridge);
        double latencySum = 0, latencyMax = 0;
        quint64 latencyCount = 0;
        QObject::connect(&bridge, &FleetBridge::machinesUpdated, [&](const QVector<MachineState>& batch) {
            const qint64 now = QDateTime::currentMSecsSinceEpoch();
            for (const MachineState& m : batch)
                if (m.hasPosition && m.lastDataMs > 0) {
                    const double d = double(now - m.lastDataMs);
                    latencySum += d;
                    latencyMax = std::max(latencyMax, d);
                    ++latencyCount;
                }
        });
        if (!bridge.start().isEmpty()) {
            state.SkipWithError("bridge did not start");
            return;
        }
        // Warm up: every truck in the model, then one more second.
        QElapsedTimer warm;
        warm.start();
        while (model.rowCount() < trucks && warm.elapsed() < 30000)
            runEventLoopFor(50);
        runEventLoopFor(1000);
        const pid_t io = threadNamed(QStringLiteral("iso23725"));
        if (model.rowCount() < trucks || io == 0) {
            state.SkipWithError("trucks did not all arrive, or no io thread found");
            return;
        }

        latencySum = latencyMax = 0;
        latencyCount = 0;
        const auto st0 = bridge.machineStats();
        const auto sent0 = demo.ahs->stats().positionsSent;
        const double io0 = threadCpuSeconds(io), gui0 = threadCpuSeconds();
        QElapsedTimer wall;
        wall.start();
        runEventLoopFor(seconds * 1000);
        const double elapsed = double(wall.nsecsElapsed()) * 1e-9;
        const double ioCpu = threadCpuSeconds(io) - io0, guiCpu = threadCpuSeconds() - gui0;
        const double positions = double(demo.ahs->stats().positionsSent - sent0);
        const auto st1 = bridge.machineStats();

        state.counters["positions_per_s"] = positions / elapsed;
        state.counters["io_cpu_us_per_pos"] = 1e6 * ioCpu / positions;
        state.counters["io_busy_pct"] = 100.0 * ioCpu / elapsed;
        state.counters["gui_cpu_us_per_pos"] = 1e6 * guiCpu / positions;
        state.counters["gui_busy_pct"] = 100.0 * guiCpu / elapsed;
        state.counters["values_pushed_per_pos"] = double(st1.pushed - st0.pushed) / positions;
        state.counters["locks_per_pos"] = double(st1.handovers - st0.handovers) / positions;
        state.counters["drains_per_s"] = double(st1.drains - st0.drains) / elapsed;
        state.counters["latency_mean_ms"] = latencyCount ? latencySum / double(latencyCount) : -1;
        state.counters["latency_max_ms"] = latencyMax;
        state.counters["rows"] = model.rowCount();
        state.SetIterationTime(elapsed);
        bridge.stop();
        demo.ahs->stop();
    }
}
BENCHMARK(BM_IsoPositionsIntoFleetModel)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond)->UseManualTime();

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
