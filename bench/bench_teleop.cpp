// Teleop latency: a joystick axis change -> SetWrenchEffort bytes arriving at the simulated UGV
// over loopback, while 1,000 other machines update the fleet model at 10 Hz and the fleet list and the 2D
// map are on screen. A small harness (not Google Benchmark): it prints percentiles of N samples.
//
//   QT_QPA_PLATFORM=offscreen build/bench/bench_teleop [samples]
#include "models/FleetContext.h"
#include "models/FleetModel.h"
#include "models/FleetSelection.h"
#include "models/bridges/JausBridge.h"
#include "models/testing/FakeFleetBridge.h"
#include "protocols/jaus/JausStack.h"
#include "sim/jaus/JausDemo.h"
#include "widgets/FleetListWidget.h"
#include "widgets/SiteMapView.h"
#include "widgets/jaus/TeleopPanel.h"
#include "widgets/teleop/TeleopController.h"

#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QHBoxLayout>
#include <QTimer>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>

using namespace ocu;
using WallClock = std::chrono::steady_clock;

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const int samples = argc > 1 ? std::max(10, std::atoi(argv[1])) : 300;

    sim::JausDemoOptions o;
    o.count = 1;
    sim::JausDemo demo(o);
    jaus::JausConfig cfg;
    cfg.subsystemId = 200;
    demo.configure(cfg);
    FleetContext ctx;
    JausBridge jaus(cfg, GeoFrame(o.origin));
    ctx.addBridge(&jaus);
    if (!jaus.start().isEmpty())
        return 1;

    // 1,000 other machines at 10 Hz from a worker thread.
    FakeFleetBridge others(Protocol::Other);
    ctx.addBridge(&others);
    std::atomic<bool> run{true};
    std::thread load([&] {
        int tick = 0;
        while (run) {
            for (int i = 0; i < 1000; ++i) {
                MachineState m;
                m.id = QStringLiteral("other:%1").arg(i);
                m.protocol = Protocol::Other;
                m.name = m.id;
                m.type = QStringLiteral("haul truck");
                m.link = LinkState::Up;
                m.hasPosition = true;
                m.e = (i % 40) * 25.0 + std::sin(tick * 0.1 + i) * 5;
                m.n = (i / 40) * 25.0 + std::cos(tick * 0.1 + i) * 5;
                m.headingDeg = (tick * 3 + i) % 360;
                m.length = 12;
                m.width = 7;
                others.setMachine(m);
            }
            ++tick;
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    });

    QWidget window;
    auto* list = new FleetListWidget(ctx.fleet(), ctx.selection());
    auto* map = new SiteMapView;
    map->setFleet(ctx.fleet(), ctx.selection());
    FakeInputDevice joystick;
    auto* teleop = new TeleopPanel(&jaus, ctx.gate(), ctx.selection(), &joystick);
    teleop->findChild<QComboBox*>(QStringLiteral("combo-drive-mode"))->setCurrentIndex(1); // wrench effort
    auto* lay = new QHBoxLayout(&window);
    lay->addWidget(list);
    lay->addWidget(map, 2);
    lay->addWidget(teleop);
    window.resize(1920, 1080);
    window.show();

    // Wire-side timestamps: every SetWrenchEffort the UGV receives.
    std::mutex mutex;
    std::vector<std::pair<WallClock::time_point, double>> wire;
    demo.ugvs().front()->setMessageTap([&](ByteSpan p) {
        if (jaus::peekMessageId(p) != jaus::msg::SetWrenchEffort)
            return;
        auto w = jaus::decodeWrench(p);
        if (!w || !w->propLinX)
            return;
        std::lock_guard lock(mutex);
        wire.emplace_back(WallClock::now(), *w->propLinX);
    });

    auto waitUntil = [&](auto pred, int ms) {
        QElapsedTimer t;
        t.start();
        while (!pred() && t.elapsed() < ms)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        return pred();
    };
    const std::uint16_t ugv = demo.ugvs().front()->config().subsystemId;
    if (!waitUntil([&] { return jaus.subsystem(ugv) && jaus.subsystem(ugv)->mobilityComponent.subsystem; },
                   10000))
        return 2;
    jaus.command(RequestControl{JausBridge::machineId(ugv)}, [](std::vector<TargetOutcome>) {});
    if (!waitUntil([&] { return jaus.subsystem(ugv)->controlledByUs; }, 5000))
        return 3;
    ctx.selection()->setCurrent(JausBridge::machineId(ugv));
    if (!waitUntil([&] { return teleop->controller()->isEnabled(); }, 5000))
        return 4;

    std::vector<double> latencyMs;
    for (int i = 0; i < samples; ++i) {
        const double axis = (i % 2) ? 0.7 : 0.3;
        const double expected = axis * 100.0 * teleop->controller()->speedLimit();
        const auto t0 = WallClock::now();
        joystick.setAxes({axis, 0});
        WallClock::time_point seen{};
        waitUntil(
            [&] {
                std::lock_guard lock(mutex);
                for (auto& [t, v] : wire)
                    if (t >= t0 && std::abs(v - expected) < 0.5) {
                        seen = t;
                        return true;
                    }
                return false;
            },
            1000);
        if (seen != WallClock::time_point{})
            latencyMs.push_back(std::chrono::duration<double, std::milli>(seen - t0).count());
        // Let the GUI work through a few model updates between samples.
        QElapsedTimer gap;
        gap.start();
        while (gap.elapsed() < 40)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    joystick.setAxes({0, 0});
    run = false;
    load.join();
    std::sort(latencyMs.begin(), latencyMs.end());
    auto pct = [&](double p) {
        return latencyMs.empty()
                   ? -1.0
                   : latencyMs[std::min(latencyMs.size() - 1, std::size_t(p * latencyMs.size()))];
    };
    std::printf(
        "teleop axis event -> SetWrenchEffort at the UGV (loopback), 1,000 machines at 10 Hz in the model\n");
    std::printf("samples %zu of %d  p50 %.3f ms  p90 %.3f ms  p99 %.3f ms  max %.3f ms  (model rows %d)\n",
                latencyMs.size(), samples, pct(0.50), pct(0.90), pct(0.99),
                latencyMs.empty() ? -1.0 : latencyMs.back(), ctx.fleet()->rowCount());
    jaus.stop();
    return latencyMs.size() == std::size_t(samples) ? 0 : 5;
}
