// The ISO 23725 bridge between the FMS stack's io thread and the GUI thread, against the simulated AHS on
// loopback (no trucks of its own: the test sends the positions): queued delivery (signals emitted on the
// bridge's thread; a receiver on another thread runs on its own), coalescing (a burst of positions for one
// machine while the GUI thread is busy becomes one signal carrying the latest position), and commands while
// the link is down (refused with the reason; nothing reaches the AHS, then or when the link is back).
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/bridges/IsoBridge.h"
#include "models/testing/CommandWait.h"
#include "sim/iso23725/SimulatedAhs.h"
#include "tests/models/bridges/BridgeThreadSupport.h"
#include "tests/support/IsoSimConsole.h"

#include <QDateTime>
#include <QSignalSpy>
#include <QtTest>

using namespace ocu;
using bridgetest::waitBusy;

namespace {

const std::string kMachineA = "0b3c1d2e-4f50-4a61-8b72-9c83d4e5f601";
const std::string kMachineB = "0b3c1d2e-4f50-4a61-8b72-9c83d4e5f602";

sim::SimulatedAhsConfig quietAhs() {
    sim::SimulatedAhsConfig c;
    c.truckCount = 0; // the only machine data are the test's
    c.healthEvents = false;
    return c;
}

iso23725::IsoConfig consoleConfig(const std::string& url) {
    return isosim::consoleConfig(url);
}

// MachinePositionV1 from the AHS (catalogue example shape); `seq` orders the timestamps.
std::string position(const std::string& equipment, double lat, double lon, int seq) {
    static const QDateTime t0 = QDateTime::currentDateTimeUtc();
    const std::string ts = t0.addMSecs(seq).toString(Qt::ISODateWithMs).toStdString();
    char body[512];
    std::snprintf(
        body, sizeof body,
        R"({"Protocol":"ISO23725","Version":1,"Timestamp":"%s","EquipmentId":"%s",)"
        R"("MachinePositionV1":{"Timestamp":"%s","Heading":87,"Latitude":%.7f,"Longitude":%.7f,)"
        R"("Elevation":500.0,"LatitudeAccuracy":0.05,"LongitudeAccuracy":0.06,"ElevationAccuracy":0.11,)"
        R"("HeadingAccuracy":0.8,"Speed":20}})",
        ts.c_str(), equipment.c_str(), ts.c_str(), lat, lon);
    return body;
}

QString idOf(const std::string& equipment) {
    return QStringLiteral("iso23725:") + QString::fromStdString(equipment);
}

bool linkIs(const IsoBridge& b, LinkState s) {
    const auto l = b.linkStatus(QStringLiteral("iso23725:ahs"));
    return l && l->state == s;
}

} // namespace

class TestIsoBridgeThreads : public QObject {
    Q_OBJECT
private slots:
    void queuedDeliveryAndCoalescing() {
        sim::SimulatedAhs ahs(quietAhs());
        QVERIFY(ahs.start());
        const GeoPoint origin = quietAhs().origin;
        IsoBridge bridge(consoleConfig(ahs.url()), GeoFrame(origin));
        bridgetest::Deliveries seen(&bridge);
        bridgetest::ProbeThread worker(&bridge);
        QVERIFY(bridge.start().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(linkIs(bridge, LinkState::Up), 20000);
        int seq = 0;
        ahs.sendRaw(position(kMachineA, origin.lat, origin.lon, ++seq));
        QTRY_VERIFY_WITH_TIMEOUT(seen.latest(idOf(kMachineA)).has_value(), 20000);
        // Machine B is known before the burst: the first thing heard of a machine is a whole change, which
        // FmsCore delivers at once, while a known machine's positions wait for the next position batch
        // (kPositionBatchInterval). With B unknown, B's first position could overtake A's last positions
        // still waiting for their batch, so "B pending" would not mean "every position of A handed over"
        // (seen under ThreadSanitizer, where a batch is flushed in the middle of the burst).
        ahs.sendRaw(position(kMachineB, origin.lat, origin.lon + 1e-4, ++seq));
        QTRY_VERIFY_WITH_TIMEOUT(seen.latest(idOf(kMachineB)).has_value(), 20000);

        // Queued delivery: the positions arrive on the stack's io thread, the signals are emitted on the
        // bridge's (this GUI) thread, and a receiver living on another thread is called on that thread.
        QCOMPARE(bridge.thread(), QThread::currentThread());
        QVERIFY(seen.allOn(bridge.thread()));
        QTRY_VERIFY_WITH_TIMEOUT(worker.probe().calls > 0, 20000);
        QCOMPARE(worker.probe().ranOn.load(), worker.thread());

        // Coalescing: while the GUI thread is busy, 50 positions of machine A arrive, then one of machine B.
        // They come in order on one WebSocket and both machines are known, so their positions leave FmsCore
        // in arrival order (position batches): when B is pending every position of A has been handed over.
        // The burst is sent in two halves with a position batch of A handed over in between, so a batch
        // flushed in the middle of the burst (the case that made this test flaky) is always exercised.
        QTest::qWait(200);
        QCoreApplication::processEvents();
        seen.clear();
        const auto before = bridge.machineStats();
        const int n = 50;
        double lastLat = 0;
        for (int i = 1; i <= n; ++i) {
            lastLat = origin.lat + i * 1e-5;
            ahs.sendRaw(position(kMachineA, lastLat, origin.lon, ++seq));
            if (i == n / 2)
                QVERIFY(waitBusy([&] { return bridge.pendingMachineUpdates() == 1; }));
        }
        ahs.sendRaw(position(kMachineB, origin.lat + 1e-5, origin.lon + 1e-4, ++seq));
        QVERIFY(waitBusy([&] { return bridge.pendingMachineUpdates() == 2; }));
        const auto burst = bridge.machineStats();
        QCOMPARE(burst.drains, before.drains); // nothing was delivered while the GUI thread was busy
        QCOMPARE(seen.count(), 0);
        // FmsCore already merges the positions that arrive within one flush window (latest wins), so the
        // coalescer sees between one push per machine and one per position, never more.
        const quint64 pushed = burst.pushed - before.pushed;
        QVERIFY2(pushed >= 2 && pushed <= quint64(n + 1), qPrintable(QString::number(pushed)));

        QCoreApplication::processEvents();
        QCOMPARE(seen.count(), 1); // one signal for the whole burst
        QCOMPARE(seen.batches[0].size(), 2);
        const auto a = seen.latest(idOf(kMachineA));
        QVERIFY(a.has_value());
        QVERIFY2(std::abs(a->lat - lastLat) < 1e-9,
                 qPrintable(QString::number(a->lat, 'f', 7) +
                            QStringLiteral(" rejected %1 pushed %2")
                                .arg(bridge.linkCounters().value(0).rejectedTotal())
                                .arg(pushed))); // latest wins
        QVERIFY(seen.latest(idOf(kMachineB)).has_value());
        QCOMPARE(bridge.machineStats().drains, before.drains + 1);
        QVERIFY(seen.allOn(bridge.thread()));
        bridge.stop();
        ahs.stop();
    }

    void implausiblePositionsKeepTheLastGoodOne() {
        // Positions beyond the site extent, too fast or jumping are not drawn: the machine keeps
        // its last good position and is marked implausible; each cause is counted on the link and warned
        // once per machine; a good position afterwards is drawn again.
        sim::SimulatedAhs ahs(quietAhs());
        QVERIFY(ahs.start());
        const GeoPoint origin = quietAhs().origin;
        IsoBridge bridge(consoleConfig(ahs.url()), GeoFrame(origin));
        QList<FleetEvent> events;
        connect(&bridge, &FleetBridge::eventRaised, this, [&](const FleetEvent& e) {
            if (e.text.contains(QStringLiteral("position ignored")))
                events << e;
        });
        bridgetest::Deliveries seen(&bridge);
        QVERIFY(bridge.start().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(linkIs(bridge, LinkState::Up), 20000);
        const QString id = idOf(kMachineA);
        int seq = 0;
        ahs.sendRaw(position(kMachineA, origin.lat + 0.001, origin.lon, ++seq)); // 111 m north
        QTRY_VERIFY_WITH_TIMEOUT(seen.latest(id) && seen.latest(id)->hasPosition, 20000);
        const MachineState good = *seen.latest(id);
        QVERIFY(std::abs(good.n - 111.2) < 1);
        auto counted = [&](const char* cause) {
            const auto c = bridge.linkCounters();
            return c.isEmpty() ? quint64(0) : c[0].rejected.value(QStringLiteral("implausible.") + cause);
        };
        auto sameAsGood = [&] {
            const auto m = seen.latest(id);
            return m && m->hasPosition && std::abs(m->n - good.n) < 0.01 && std::abs(m->e - good.e) < 0.01;
        };
        // 1 degree north: 111 km from the origin (twice, in two batches: counted twice, warned once).
        ahs.sendRaw(position(kMachineA, origin.lat + 1.0, origin.lon, ++seq));
        QTRY_COMPARE_WITH_TIMEOUT(counted("outside_extent"), quint64(1), 20000);
        ahs.sendRaw(position(kMachineA, origin.lat + 1.0, origin.lon, ++seq));
        QTRY_COMPARE_WITH_TIMEOUT(counted("outside_extent"), quint64(2), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(seen.latest(id)->healthText.contains(QStringLiteral("implausible")), 20000);
        QVERIFY(sameAsGood());
        QCOMPARE(seen.latest(id)->health, HealthLevel::Warning);
        // 250 km/h.
        std::string fast = position(kMachineA, origin.lat + 0.001, origin.lon, ++seq);
        fast.replace(fast.find("\"Speed\":20"), 10, "\"Speed\":250");
        ahs.sendRaw(fast);
        QTRY_COMPARE_WITH_TIMEOUT(counted("speed"), quint64(1), 20000);
        // 5 km away a moment later: a jump.
        ahs.sendRaw(position(kMachineA, origin.lat + 0.046, origin.lon, ++seq));
        QTRY_COMPARE_WITH_TIMEOUT(counted("jump"), quint64(1), 20000);
        QCoreApplication::processEvents();
        QVERIFY(sameAsGood());
        QTRY_COMPARE_WITH_TIMEOUT(events.size(), 3, 20000); // one per cause
        QVERIFY(std::all_of(events.begin(), events.end(), [&](const FleetEvent& e) {
            return e.severity == EventSeverity::Warning && e.machineId == id;
        }));
        // A good position next to the last good one is drawn, and the mark is gone.
        ahs.sendRaw(position(kMachineA, origin.lat + 0.0011, origin.lon, ++seq));
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(seen.latest(id)->n - 122.3) < 1, 20000);
        QVERIFY2(!seen.latest(id)->healthText.contains(QStringLiteral("implausible")),
                 qPrintable(seen.latest(id)->healthText));
        QCOMPARE(events.size(), 3);
        bridge.stop();
    }

    void rejectedInputIsCountedPerLink() {
        // What the AHS sent and the console rejected, per link and reason (link details,
        // headless counters); the stack's totals count it as well.
        sim::SimulatedAhs ahs(quietAhs());
        QVERIFY(ahs.start());
        IsoBridge bridge(consoleConfig(ahs.url()), GeoFrame(quietAhs().origin));
        QVERIFY(bridge.start().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(linkIs(bridge, LinkState::Up), 20000);
        auto rejected = [&] {
            const QVector<LinkCounters> c = bridge.linkCounters();
            return c.size() == 1 && c[0].link == QStringLiteral("iso23725:ahs") ? c[0].rejectedTotal()
                                                                                : quint64(0);
        };
        QCOMPARE(rejected(), quint64(0));
        ahs.sendRaw("{\"this is\": not JSON");
        ahs.sendRaw("{\"this is\": not JSON");
        QTRY_COMPARE_WITH_TIMEOUT(rejected(), quint64(2), 20000);
        const LinkCounters c = bridge.linkCounters()[0];
        QCOMPARE(c.rejected.value(QStringLiteral("rejected.invalid_json")), quint64(2));
        QVERIFY(c.all.value(QStringLiteral("rx.frames")) >= 2);
        bridge.stop();
    }

    void stalledIoThreadRaisesAnAlarmAndDegradesTheLink() {
        // The io thread blocked on purpose (a handler waiting on a latch) for more than 1 s.
        sim::SimulatedAhs ahs(quietAhs());
        QVERIFY(ahs.start());
        IsoBridge bridge(consoleConfig(ahs.url()), GeoFrame(quietAhs().origin));
        QVERIFY(bridge.start().isEmpty());
        bridgetest::expectWatchdog(bridge, QStringLiteral("iso23725:ahs"),
                                   [&](std::function<void()> f) { bridge.postToIo(std::move(f)); });
        bridge.stop();
    }

    void commandsWhileTheLinkIsDownAreRefused() {
        auto first = std::make_unique<sim::SimulatedAhs>(quietAhs());
        QVERIFY(first->start());
        const std::uint16_t port = first->port();
        const GeoPoint origin = quietAhs().origin;
        IsoBridge bridge(consoleConfig(first->url()), GeoFrame(origin));
        bridgetest::Deliveries seen(&bridge);
        QVERIFY(bridge.start().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(linkIs(bridge, LinkState::Up), 20000);
        first->sendRaw(position(kMachineA, origin.lat, origin.lon, 1));
        QTRY_VERIFY_WITH_TIMEOUT(seen.latest(idOf(kMachineA)).has_value(), 20000);

        // The AHS goes away: the link is down.
        first->stop();
        first.reset();
        QTRY_VERIFY_WITH_TIMEOUT(linkIs(bridge, LinkState::Down), 20000);
        const QList<CommandResult> refused{
            ocu::testing::bridgeResult([&](auto d) { bridge.stopAll(d); }),
            ocu::testing::bridgeResult([&](auto d) { bridge.stopMachine(idOf(kMachineA), d); }),
            ocu::testing::bridgeResult([&](auto d) { bridge.clearStop(idOf(kMachineA), d); }),
            ocu::testing::bridgeResult([&](auto d) {
                bridge.command(AllStopApply{QStringLiteral("ahs"), {}}, d);
            }),
            ocu::testing::bridgeResult([&](auto d) {
                bridge.command(FetchMap{QStringLiteral("ahs"), {}}, d);
            })};
        for (const CommandResult& r : refused) {
            QVERIFY2(!r.ok, qPrintable(r.message));
            QVERIFY2(r.message.contains(QStringLiteral("ISO 23725 link ahs is down")) &&
                         r.message.contains(QStringLiteral("nothing sent")),
                     qPrintable(r.message));
        }

        // The AHS is back on the same port: the link comes up again and nothing refused reaches it.
        auto cfg = quietAhs();
        cfg.port = port;
        sim::SimulatedAhs second(cfg);
        QVERIFY(second.start());
        QTRY_VERIFY_WITH_TIMEOUT(linkIs(bridge, LinkState::Up), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(second.stats().sessions == 1, 20000);
        QTest::qWait(1000);
        QVERIFY(!second.stats().allStopOn);

        // With the link up the same stop goes out.
        const CommandResult stop = ocu::testing::bridgeResult([&](auto d) { bridge.stopAll(d); });
        QVERIFY2(stop.ok, qPrintable(stop.message));
        QTRY_VERIFY_WITH_TIMEOUT(second.stats().allStopOn, 10000);
        bridge.stop();
        second.stop();
    }

    // Confirmation beyond stops: the all-stop release (clear_stop through the gate) is confirmed by the AHS's
    // own report (all-stop inactive), logged with its latency.
    void clearStopConfirmedByTheAhs() {
        sim::SimulatedAhs ahs(quietAhs());
        QVERIFY(ahs.start());
        const GeoPoint origin = quietAhs().origin;
        AlarmModel alarms;
        CommandGate gate(&alarms);
        IsoBridge bridge(consoleConfig(ahs.url()), GeoFrame(origin));
        bridgetest::Deliveries seen(&bridge);
        gate.addBridge(&bridge);
        QVERIFY(bridge.start().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(linkIs(bridge, LinkState::Up), 20000);
        ahs.sendRaw(position(kMachineA, origin.lat, origin.lon, 1));
        QTRY_VERIFY_WITH_TIMEOUT(seen.latest(idOf(kMachineA)).has_value(), 20000);
        QSignalSpy stopped(&gate, &CommandGate::stopConfirmed);
        QSignalSpy confirmed(&gate, &CommandGate::commandConfirmed);
        QSignalSpy unconfirmed(&gate, &CommandGate::commandUnconfirmed);
        QVERIFY(ocu::testing::gateResult([&](auto h) { gate.stopAll(QStringLiteral("test"), h); }).ok);
        QTRY_COMPARE_WITH_TIMEOUT(stopped.count(), 1, 20000);
        const QString id = idOf(kMachineA);
        QVERIFY(ocu::testing::gateResult([&](auto h) {
                    gate.clearStop(id, gate.requestClearToken(id), QStringLiteral("test"), h);
                }).ok);
        QTRY_COMPARE_WITH_TIMEOUT(confirmed.count(), 1, 20000);
        QCOMPARE(confirmed.first().at(0).toString(), QStringLiteral("clear_stop"));
        QCOMPARE(confirmed.first().at(1).toString(), QStringLiteral("iso23725 link ahs"));
        QVERIFY2(confirmed.first().at(2).toString().contains(QStringLiteral("all-stop inactive")),
                 qPrintable(confirmed.first().at(2).toString()));
        QVERIFY(!ahs.stats().allStopOn);
        QCOMPARE(unconfirmed.count(), 0);
        bridge.stop();
        ahs.stop();
    }
};

QTEST_GUILESS_MAIN(TestIsoBridgeThreads)
#include "test_iso_bridge_threads.moc"
