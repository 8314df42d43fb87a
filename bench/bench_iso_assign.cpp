// bench_iso_assign: the assignment round trip on loopback under a full fleet. The
// console (IsoBridge, its stack's io thread, this GUI thread) sends HaulTruckAssignmentRequestV2 to one truck
// at a time while 1,000 simulated trucks report positions at 10 Hz over the same ws:// link (the simulated
// AHS in this process, its own io thread); the round trip runs from IsoBridge::command(Assign) on the GUI
// thread to the truck's HaulTruckAssignmentResponseV1 being visible in the bridge's dispatch view on the GUI
// thread (dispatchChanged). One request outstanding at a time. Prints p50, p99 and max in ms, the requests,
// the positions per second received meanwhile, and the CPU time of the GUI thread per request.
//   bench_iso_assign [--trucks 1000] [--rate 10] [--requests 500]
#include "models/bridges/IsoBridge.h"
#include "sim/iso23725/IsoDemo.h"

#include "protocols/common/Log.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <QUuid>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <vector>

using namespace ocu;

namespace {

double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

void runEventLoopFor(int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

double percentile(std::vector<double> v, double p) {
    if (v.empty())
        return -1;
    std::sort(v.begin(), v.end());
    const auto i = std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5));
    return v[i];
}

int argInt(const QStringList& args, const QString& name, int def) {
    const int i = args.indexOf(name);
    return i >= 0 && i + 1 < args.size() ? args[i + 1].toInt() : def;
}

} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    setLogThreshold(LogLevel::Error);
    const QStringList args = app.arguments();
    const int trucks = argInt(args, QStringLiteral("--trucks"), 1000);
    const int rate = argInt(args, QStringLiteral("--rate"), 10);
    const int requests = argInt(args, QStringLiteral("--requests"), 500);
    const int gapMs = argInt(args, QStringLiteral("--gap-ms"), 23);

    sim::SimulatedAhsConfig sc;
    sc.truckCount = trucks;
    sc.positionRateHz = rate;
    sc.healthEvents = true;
    auto demo = sim::startIsoDemo(sc);
    if (!demo.ahs) {
        std::fprintf(stderr, "simulator did not start: %s\n", demo.error.c_str());
        return 1;
    }
    const auto view = demo.ahs->dispatchView();
    IsoBridge bridge(demo.config, GeoFrame(sc.origin));
    if (!bridge.start().isEmpty()) {
        std::fprintf(stderr, "bridge did not start\n");
        return 1;
    }
    // Warm up: every truck's dispatch view with its custodian, the destinations, then two more seconds.
    QElapsedTimer warm;
    warm.start();
    auto ready = [&] {
        if (bridge.destinations().isEmpty())
            return 0;
        int n = 0;
        for (const auto& d : bridge.dispatchStates())
            n += d.custodian.isEmpty() ? 0 : 1;
        return n;
    };
    while (ready() < trucks && warm.elapsed() < 60000)
        runEventLoopFor(100);
    if (ready() < trucks) {
        std::fprintf(stderr, "only %d of %d trucks arrived\n", ready(), trucks);
        return 1;
    }
    runEventLoopFor(2000);

    std::vector<double> rtt;
    int refused = 0, timeouts = 0, notSent = 0;
    const auto sent0 = demo.ahs->stats().positionsSent;
    const double gui0 = threadCpuSeconds();
    QElapsedTimer wall;
    wall.start();
    for (int i = 0; i < requests; ++i) {
        if (i > 0 && gapMs > 0)
            runEventLoopFor(gapMs);
        const auto& truck = view.trucks[std::size_t((i * 37) % trucks)];
        const QString id = QStringLiteral("iso23725:") + QString::fromStdString(truck.id);
        if (!bridge.assignRefusal(id).isEmpty()) {
            ++refused;
            continue;
        }
        IsoTask task;
        task.assignmentId = QUuid::createUuid().toString(QUuid::WithoutBraces);
        task.task = QStringLiteral("Load");
        task.destinationId = view.loadAreas[std::size_t(i) % view.loadAreas.size()];
        const QString aid = task.assignmentId;
        QEventLoop loop;
        bool answered = false, wasSent = true;
        auto check = [&] {
            const auto d = bridge.dispatchState(id);
            if (d && d->response(aid)) {
                answered = true;
                loop.quit();
            }
        };
        const auto conn =
            QObject::connect(&bridge, &IsoBridge::dispatchChanged, &loop, [&](const QStringList& ids) {
                if (ids.contains(id))
                    check();
            });
        QTimer::singleShot(10000, &loop, &QEventLoop::quit);
        QElapsedTimer t;
        t.start();
        bridge.command(IsoBridge::assignCommand(id, {task}),
                       [&wasSent](std::vector<TargetOutcome> o) { wasSent = allSent(o); });
        check();
        if (!answered)
            loop.exec();
        const double ms = double(t.nsecsElapsed()) * 1e-6;
        QObject::disconnect(conn);
        if (!wasSent)
            ++notSent;
        else if (!answered)
            ++timeouts;
        else
            rtt.push_back(ms);
    }
    const double elapsed = double(wall.nsecsElapsed()) * 1e-9;
    const double guiCpu = threadCpuSeconds() - gui0;
    const double positions = double(demo.ahs->stats().positionsSent - sent0);
    std::printf(
        "bench_iso_assign: %d trucks at %d Hz, %zu round trips (%d refused before sending, %d not sent, "
        "%d unanswered in 10 s)\n",
        trucks, rate, rtt.size(), refused, notSent, timeouts);
    std::printf("  assign -> response round trip: p50 %.2f ms  p99 %.2f ms  max %.2f ms\n",
                percentile(rtt, 0.5), percentile(rtt, 0.99),
                rtt.empty() ? -1.0 : *std::max_element(rtt.begin(), rtt.end()));
    std::printf("  over %.1f s: positions sent %.0f /s; GUI thread %.0f %% busy (positions, dispatch views, "
                "requests)\n",
                elapsed, positions / elapsed, 100 * guiCpu / elapsed);
    bridge.stop();
    demo.ahs->stop();
    return rtt.empty() ? 1 : 0;
}
