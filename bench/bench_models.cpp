// bench_models: the telemetry path (stack -> coalescer -> models) under the full fleet's load.
//  * BM_FleetAt10Hz: a worker thread publishes 1,000 machines every 100 ms (10,000 positions/s) through a
//    FleetBridge (coalescer) for 5 s while the GUI thread runs the event loop with FleetModel, a sorted
//    FleetFilterProxy and FleetModel::refresh at 2 Hz. Reports the GUI thread's CPU busy fraction, the
//    drains, the largest backlog seen by the producer and whether the backlog grew.
//  * BM_CoalescerPush: cost of one push from the io thread.
//  * BM_ModelUpsert1000: one 1,000-machine batch into FleetModel + sorted proxy.
#include "models/FleetFilterProxy.h"
#include "models/FleetModel.h"
#include "models/testing/FakeFleetBridge.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTimer>
#include <atomic>
#include <benchmark/benchmark.h>
#include <chrono>
#include <cmath>
#include <ctime>
#include <thread>

using namespace ocu;

namespace {
double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

MachineState machine(int i, int tick) {
    MachineState m;
    m.id = QStringLiteral("iso23725:T%1").arg(i);
    m.protocol = Protocol::Iso23725;
    m.name = QStringLiteral("T%1").arg(i);
    m.type = QStringLiteral("haul truck");
    m.link = LinkState::Up;
    m.hasPosition = true;
    const double a = (i * 0.37 + tick * 0.01);
    m.e = 500 * std::cos(a) + i % 50;
    m.n = 500 * std::sin(a) + i / 50;
    m.headingDeg = std::fmod(a * 57.3 + 90, 360);
    m.speed = 8 + (i % 5);
    m.length = 12;
    m.width = 7;
    m.stop = StopState::None;
    m.mode = ModeCategory::Autonomous;
    m.health = HealthLevel::Ok;
    return m;
}
} // namespace

static void BM_FleetAt10Hz(benchmark::State& state) {
    const int machines = int(state.range(0));
    const int seconds = 5;
    for (auto _ : state) {
        FakeFleetBridge bridge(Protocol::Iso23725);
        FleetModel model;
        model.setRefreshIntervalMs(500);
        model.addBridge(&bridge);
        FleetFilterProxy proxy;
        proxy.setSourceModel(&model);
        proxy.sort(FleetModel::ColEast);
        quint64 batches = 0;
        QObject::connect(&model, &FleetModel::machinesChanged, [&](const QStringList&) { ++batches; });

        std::atomic<bool> stop{false};
        std::atomic<size_t> maxPending{0};
        std::vector<size_t> pendingAtTick;
        std::thread producer([&] {
            // Pre-build the states (the protocol decode is measured elsewhere).
            auto next = std::chrono::steady_clock::now();
            for (int tick = 0; !stop.load(); ++tick) {
                const size_t pending = bridge.pendingMachineUpdates();
                pendingAtTick.push_back(pending);
                maxPending = std::max(maxPending.load(), pending);
                for (int i = 0; i < machines; ++i)
                    bridge.publishMachine(machine(i, tick));
                next += std::chrono::milliseconds(100);
                std::this_thread::sleep_until(next);
            }
        });
        const double cpu0 = threadCpuSeconds();
        QElapsedTimer wall;
        wall.start();
        QTimer::singleShot(seconds * 1000, [&] { QCoreApplication::quit(); });
        QCoreApplication::exec();
        const double cpu = threadCpuSeconds() - cpu0;
        const double elapsed = double(wall.nsecsElapsed()) * 1e-9;
        stop = true;
        producer.join();
        QCoreApplication::processEvents();

        // "No growing queue": the backlog the producer sees in the last second is no larger than in the
        // first.
        size_t firstMax = 0, lastMax = 0;
        const size_t n = pendingAtTick.size();
        for (size_t i = 0; i < n; ++i) {
            if (i < 10)
                firstMax = std::max(firstMax, pendingAtTick[i]);
            if (i + 10 >= n)
                lastMax = std::max(lastMax, pendingAtTick[i]);
        }
        const auto st = bridge.machineStats();
        state.counters["gui_busy_pct"] = 100.0 * cpu / elapsed;
        state.counters["positions_per_s"] = double(st.pushed) / elapsed;
        state.counters["drains"] = double(st.drains);
        state.counters["model_batches"] = double(batches);
        state.counters["rows"] = model.rowCount();
        state.counters["max_backlog"] = double(maxPending.load());
        state.counters["backlog_first_s"] = double(firstMax);
        state.counters["backlog_last_s"] = double(lastMax);
        state.counters["overwritten"] = double(st.pushed - st.delivered);
        state.SetIterationTime(elapsed);
    }
}
BENCHMARK(BM_FleetAt10Hz)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond)->UseManualTime();

static void BM_CoalescerPush(benchmark::State& state) {
    QObject ctx;
    size_t delivered = 0;
    TelemetryCoalescer<int, MachineState> c(&ctx, [&](auto&& b) { delivered += b.size(); });
    const MachineState m = machine(1, 1);
    int k = 0;
    for (auto _ : state) {
        c.push(k, m);
        k = (k + 1) % 1000;
    }
    c.drainNow();
    benchmark::DoNotOptimize(delivered);
}
BENCHMARK(BM_CoalescerPush);

static void BM_ModelUpsert1000(benchmark::State& state) {
    FleetModel model;
    model.setRefreshIntervalMs(0);
    FleetFilterProxy proxy;
    proxy.setSourceModel(&model);
    proxy.sort(FleetModel::ColEast);
    QVector<MachineState> batch;
    for (int i = 0; i < 1000; ++i)
        batch.push_back(machine(i, 0));
    model.upsert(batch);
    int tick = 0;
    for (auto _ : state) {
        state.PauseTiming();
        ++tick;
        for (int i = 0; i < 1000; ++i)
            batch[i] = machine(i, tick);
        state.ResumeTiming();
        model.upsert(batch);
    }
}
BENCHMARK(BM_ModelUpsert1000)->Unit(benchmark::kMicrosecond);

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
