// The OSYRIS bridge between the station's io thread and the GUI thread, against a simulated roller's station
// on loopback multicast (paused: the test publishes its positions): queued delivery (signals emitted on the
// bridge's thread; a receiver on another thread runs on its own), coalescing (a burst of positions for one
// machine while the GUI thread is busy becomes one signal carrying the latest position), and commands while
// no station is heard (refused with the reason; nothing reaches a station that joins later).
#include "models/bridges/OsyrisBridge.h"
#include "models/testing/CommandWait.h"
#include "protocols/common/Udp.h"
#include "protocols/osyris/OsyrisCodec.h"
#include "sim/osyris/OsyrisDemo.h"
#include "tests/models/bridges/BridgeThreadSupport.h"

#include <QtTest>

#include <mutex>

using namespace ocu;
using bridgetest::waitBusy;

namespace {

const GeoPoint kOrigin{48.137154, 11.576124, 520};

sim::osyris::OsyrisDemoOptions oneRoller() {
    sim::osyris::OsyrisDemoOptions o;
    o.rollers = 1;
    o.paver = false;
    o.relay = false;
    return o;
}

osyris::OsyrisConfig consoleConfig(osyris::OsyrisConfig c) {
    c.originLat = kOrigin.lat;
    c.originLon = kOrigin.lon;
    c.originAlt = kOrigin.alt;
    return c;
}

osyris::CmPos at(double x, double y) {
    osyris::CmPos p;
    p.x = static_cast<float>(x);
    p.y = static_cast<float>(y);
    p.dx = 2.0f;
    p.flags = osyris::kPosValid | osyris::kPosAccuracyHigh;
    return p;
}

// Texts a station receives (its io thread).
struct Texts : osyris::OsyrisListener {
    std::mutex mutex;
    std::vector<std::string> texts;
    std::atomic<bool> heardOcu{false};
    void onText(std::uint8_t, const std::string& t) override {
        std::lock_guard lock(mutex);
        texts.push_back(t);
    }
    void onStationAlive(std::uint8_t idx, std::optional<osyris::SlotRange>) override {
        if (idx == 200)
            heardOcu = true;
    }
    int count() {
        std::lock_guard lock(mutex);
        return int(texts.size());
    }
};

} // namespace

class TestOsyrisBridgeThreads : public QObject {
    Q_OBJECT
private slots:
    void queuedDeliveryAndCoalescing() {
        sim::osyris::OsyrisDemo demo(oneRoller());
        std::string err;
        QVERIFY2(demo.start(&err), err.c_str());
        demo.setPaused(true); // the roller publishes only what the test gives it
        auto& roller = demo.station(0);
        const QString id = QStringLiteral("osyris:%1").arg(roller.config().stationIndex);
        OsyrisBridge bridge(consoleConfig(demo.ocuConfig()), GeoFrame(kOrigin));
        bridgetest::Deliveries seen(&bridge);
        bridgetest::ProbeThread worker(&bridge);
        QVERIFY(bridge.start().isEmpty());
        roller.publishOwnPosition(at(0, 0));
        QTRY_VERIFY_WITH_TIMEOUT(seen.latest(id).has_value(), 20000);

        // Queued delivery: the positions arrive on the station's io thread, the signals are emitted on the
        // bridge's (this GUI) thread, and a receiver living on another thread is called on that thread.
        QCOMPARE(bridge.thread(), QThread::currentThread());
        QVERIFY(seen.allOn(bridge.thread()));
        QTRY_VERIFY_WITH_TIMEOUT(worker.probe().calls > 0, 20000);
        QCOMPARE(worker.probe().ranOn.load(), worker.thread());

        // Coalescing: while the GUI thread is busy, 40 positions of the roller arrive (in slot order, each
        // one reported by the station).
        QTest::qWait(300);
        QCoreApplication::processEvents();
        seen.clear();
        const auto before = bridge.machineStats();
        const int n = 40;
        for (int i = 1; i <= n; ++i)
            roller.publishOwnPosition(at(0.5 * i, 3.0));
        QVERIFY(waitBusy([&] { return bridge.machineStats().pushed >= before.pushed + n; }));
        const auto burst = bridge.machineStats();
        QCOMPARE(burst.drains, before.drains); // nothing was delivered while the GUI thread was busy
        QCOMPARE(seen.count(), 0);
        QCOMPARE(bridge.pendingMachineUpdates(), size_t(1));

        QCoreApplication::processEvents();
        QCOMPARE(seen.count(), 1); // one signal for the whole burst
        QCOMPARE(seen.batches[0].size(), 1);
        const MachineState m = seen.batches[0][0];
        QCOMPARE(m.id, id);
        // The latest position (0.5 * n m east, 3 m north of the worksite origin = the site origin here).
        QVERIFY2(std::abs(m.e - 0.5 * n) < 0.01 && std::abs(m.n - 3.0) < 0.01,
                 qPrintable(QStringLiteral("%1 %2").arg(m.e).arg(m.n)));
        QCOMPARE(bridge.machineStats().drains, before.drains + 1);
        bridge.stop();
        demo.stop();
    }

    void stalledIoThreadRaisesAnAlarmAndDegradesTheLink() {
        // The io thread blocked on purpose (a handler waiting on a latch) for more than 1 s.
        sim::osyris::OsyrisDemo demo(oneRoller());
        std::string err;
        QVERIFY2(demo.start(&err), err.c_str());
        const osyris::OsyrisConfig cfg = consoleConfig(demo.ocuConfig());
        OsyrisBridge bridge(cfg, GeoFrame(kOrigin));
        QVERIFY(bridge.start().isEmpty());
        bridgetest::expectWatchdog(
            bridge, QStringLiteral("osyris:%1:%2").arg(QString::fromStdString(cfg.group)).arg(cfg.port),
            [&](std::function<void()> f) { bridge.postToIo(std::move(f)); });
        bridge.stop();
        demo.stop();
    }

    void silentStationsDegradeTheLinkAndHeardAgainUp() {
        // A partitioned radio: the link shown degraded after 2.5 SendPeriods without a station, up when one
        // is heard again (stations restarted on the same group and port).
        auto opts = oneRoller();
        auto demo = std::make_unique<sim::osyris::OsyrisDemo>(opts);
        std::string err;
        QVERIFY2(demo->start(&err), err.c_str());
        osyris::OsyrisConfig cfg = consoleConfig(demo->ocuConfig());
        cfg.sendPeriodMs = 400; // silent for 1 s: degraded
        OsyrisBridge bridge(cfg, GeoFrame(kOrigin));
        QVector<LinkStatus> seen;
        connect(&bridge, &FleetBridge::linkChanged, this, [&](const LinkStatus& s) { seen.push_back(s); });
        QVERIFY(bridge.start().isEmpty());
        auto last = [&] { return seen.isEmpty() ? LinkState::Unknown : seen.last().state; };
        QTRY_COMPARE_WITH_TIMEOUT(last(), LinkState::Up, 10000);
        demo->stop();
        QElapsedTimer silent;
        silent.start();
        QTRY_COMPARE_WITH_TIMEOUT(last(), LinkState::Degraded, 5000);
        QVERIFY2(silent.elapsed() >= 900, qPrintable(QString::number(silent.elapsed())));
        QVERIFY(seen.last().detail.startsWith(QStringLiteral("no station heard")));
        opts.port = cfg.port;
        demo = std::make_unique<sim::osyris::OsyrisDemo>(opts);
        QVERIFY2(demo->start(&err), err.c_str());
        QTRY_COMPARE_WITH_TIMEOUT(last(), LinkState::Up, 10000);
        bridge.stop();
        demo->stop();
    }

    void commandsWhileNoStationIsHeardAreRefused() {
        osyris::OsyrisConfig cfg = sim::osyris::OsyrisDemo(oneRoller()).ocuConfig();
        cfg.port = findFreeUdpPort();
        OsyrisBridge bridge(consoleConfig(cfg), GeoFrame(kOrigin));
        QVERIFY(bridge.start().isEmpty());
        // Joined, nobody heard: a message now would wait in the station's store for whoever joins later.
        const QList<CommandResult> refused{
            ocu::testing::bridgeResult([&](auto d) { bridge.stopAll(d); }),
            ocu::testing::bridgeResult([&](auto d) { bridge.stopMachine(QStringLiteral("osyris:1"), d); }),
            ocu::testing::bridgeResult([&](auto d) {
                bridge.command(SendText{{}, QStringLiteral("hello")}, d);
            }),
            ocu::testing::bridgeResult([&](auto d) { bridge.command(PingStation{1}, d); })};
        for (const CommandResult& r : refused) {
            QVERIFY2(!r.ok, qPrintable(r.message));
            QVERIFY2(r.message.contains(QStringLiteral("no OSYRIS station heard")) &&
                         r.message.contains(QStringLiteral("nothing sent")),
                     qPrintable(r.message));
        }

        // A machine's station joins: both hear each other, and none of the refused messages reaches it.
        Texts texts;
        osyris::OsyrisConfig machine = cfg;
        machine.stationIndex = 1;
        machine.active = 15; // sends positions and shows messages
        osyris::OsyrisStack station(machine, texts);
        std::string err;
        QVERIFY2(station.start(&err), err.c_str());
        const QString link =
            QStringLiteral("osyris:%1:%2").arg(QString::fromStdString(cfg.group)).arg(cfg.port);
        QTRY_VERIFY_WITH_TIMEOUT(bridge.linkStatus(link) && bridge.linkStatus(link)->state == LinkState::Up,
                                 20000);
        QTRY_VERIFY_WITH_TIMEOUT(texts.heardOcu.load(), 20000);
        QTest::qWait(1500);
        QCOMPARE(texts.count(), 0);

        // With a station heard the same stop goes out.
        const CommandResult stop = ocu::testing::bridgeResult([&](auto d) { bridge.stopAll(d); });
        QVERIFY2(stop.ok, qPrintable(stop.message));
        QCOMPARE(stop.targets.size(), 1);
        QCOMPARE(targetId(stop.targets[0]),
                 QStringLiteral("osyris group %1:%2").arg(QString::fromStdString(cfg.group)).arg(cfg.port));
        QTRY_COMPARE_WITH_TIMEOUT(texts.count(), 1, 10000);
        bridge.stop();
        station.stop();
    }

    void implausiblePositionKeepsTheLastGoodOneAndWarns() {
        // One CmPos with a drum of 10^6 m must neither move the machine nor hang the io thread.
        sim::osyris::OsyrisDemo demo(oneRoller());
        std::string err;
        QVERIFY2(demo.start(&err), err.c_str());
        demo.setPaused(true);
        auto& roller = demo.station(0);
        const QString id = QStringLiteral("osyris:%1").arg(roller.config().stationIndex);
        OsyrisBridge bridge(consoleConfig(demo.ocuConfig()), GeoFrame(kOrigin));
        QList<FleetEvent> events;
        connect(&bridge, &FleetBridge::eventRaised, this, [&](const FleetEvent& e) { events << e; });
        bridgetest::Deliveries seen(&bridge);
        QVERIFY(bridge.start().isEmpty());
        roller.publishOwnPosition(at(4, 5));
        QTRY_VERIFY_WITH_TIMEOUT(seen.latest(id).has_value() && seen.latest(id)->hasPosition, 20000);
        osyris::CmPos huge = at(6, 5);
        huge.dx = 1e6f;
        roller.publishOwnPosition(huge);
        QTRY_VERIFY_WITH_TIMEOUT(seen.latest(id)->healthText.contains(QStringLiteral("implausible")), 20000);
        const MachineState m = *seen.latest(id);
        QCOMPARE(m.health, HealthLevel::Warning);
        QVERIFY2(std::abs(m.e - 4) < 0.01 && std::abs(m.n - 5) < 0.01, qPrintable(QString::number(m.e)));
        QTRY_VERIFY_WITH_TIMEOUT(
            std::any_of(events.begin(), events.end(),
                        [](const FleetEvent& e) { return e.text.contains(QStringLiteral("drum width")); }),
            20000);
        // Counted per link and cause (link details, headless counters).
        QTRY_VERIFY_WITH_TIMEOUT(
            !bridge.linkCounters().isEmpty() &&
                bridge.linkCounters()[0].rejected.value(QStringLiteral("implausible.drum_width")) >= 1,
            20000);
        // The station still turns: a good position after it is shown.
        roller.publishOwnPosition(at(7, 5));
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(seen.latest(id)->e - 7) < 0.01, 20000);
        QCOMPARE(seen.latest(id)->health, HealthLevel::Ok);
        bridge.stop();
        demo.stop();
    }
};

QTEST_GUILESS_MAIN(TestOsyrisBridgeThreads)
#include "test_osyris_bridge_threads.moc"
