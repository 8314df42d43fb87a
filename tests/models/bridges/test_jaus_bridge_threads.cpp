// The JAUS bridge between the stack's io thread and the GUI thread, against a simulated UGV on loopback:
// queued delivery (signals emitted on the bridge's thread; a receiver on another thread runs on its own),
// coalescing (a burst of reports for one vehicle while the GUI thread is busy becomes one signal carrying the
// latest state), and commands while the vehicle's link is down (refused with the reason; nothing reaches the
// vehicle, then or when it is heard again).
#include "models/bridges/JausBridge.h"
#include "models/testing/CommandWait.h"
#include "protocols/jaus/Messages.h"
#include "sim/jaus/JausDemo.h"
#include "tests/models/bridges/BridgeThreadSupport.h"

#include <QSignalSpy>
#include <QtTest>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>

#include <mutex>

using namespace ocu;
using bridgetest::waitBusy;

namespace {

const QString kVehicle = QStringLiteral("jaus:126");

sim::JausDemoOptions oneUgv() {
    sim::JausDemoOptions o;
    o.count = 1;
    o.alternateKinematics = false;
    return o;
}

jaus::JausConfig consoleConfig(const sim::JausDemo& demo, double linkLostS) {
    jaus::JausConfig c;
    c.subsystemId = 200;
    c.callSign = "OCU-TEST";
    c.role = jaus::Role::PrimaryOperator;
    c.authority = 205;
    c.linkLostS = linkLostS;
    demo.configure(c);
    return c;
}

// Message IDs the simulated UGV receives (its io thread).
struct Received {
    std::mutex mutex;
    QVector<quint16> ids;
    void tap(sim::SimulatedUgv& ugv) {
        ugv.setMessageTap([this](ByteSpan p) {
            if (p.size() < 2)
                return;
            std::lock_guard lock(mutex);
            ids.push_back(static_cast<quint16>(p[0] | (p[1] << 8)));
        });
    }
    int count(quint16 id) {
        std::lock_guard lock(mutex);
        return int(ids.count(id));
    }
};

} // namespace

class TestJausBridgeThreads : public QObject {
    Q_OBJECT
private slots:
    void queuedDeliveryAndCoalescing() {
        sim::JausDemo demo(oneUgv());
        jaus::JausConfig config = consoleConfig(demo, 60);
        config.heartbeatRateHz = 2; // configurable: the link is degraded 1.25 s into a silence
        JausBridge bridge(config, GeoFrame(oneUgv().origin));
        bridgetest::Deliveries seen(&bridge);
        bridgetest::ProbeThread worker(&bridge);
        QSignalSpy views(&bridge, &JausVehicleBridge::subsystemUpdated);
        QVERIFY(bridge.start().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(seen.latest(kVehicle) && seen.latest(kVehicle)->link == LinkState::Up,
                                 20000);
        QTRY_VERIFY_WITH_TIMEOUT(bridge.linkStatus(QStringLiteral("jaus")) &&
                                     bridge.linkStatus(QStringLiteral("jaus"))->state == LinkState::Up,
                                 20000);

        // Queued delivery: the reports arrive on the stack's io thread, the signals are emitted on the
        // bridge's (this GUI) thread, and a receiver living on another thread is called on that thread.
        QCOMPARE(bridge.thread(), QThread::currentThread());
        QVERIFY(seen.allOn(bridge.thread()));
        QTRY_VERIFY_WITH_TIMEOUT(worker.probe().calls > 0, 20000);
        QCOMPARE(worker.probe().ranOn.load(), worker.thread());

        // Coalescing: the GUI thread is busy while the vehicle keeps reporting (pose, velocity, heartbeats).
        QCoreApplication::processEvents();
        seen.clear();
        views.clear();
        const auto before = bridge.machineStats();
        QVERIFY(waitBusy([&] { return bridge.machineStats().pushed >= before.pushed + 20; }));
        // Then the vehicle falls silent (it still hears us). After 2.5 missed heartbeats the stack reports
        // its link degraded; the bridge publishes the JAUS link as no longer up right after that last change
        // of the vehicle, and nothing changes after it (the link is declared lost only after 60 s).
        demo.ugvs().front()->setPacketLoss(1.0);
        QVERIFY(waitBusy([&] { return bridge.pendingLinkUpdates() > 0; }));
        const auto burst = bridge.machineStats();
        QCOMPARE(burst.drains, before.drains); // nothing was delivered while the GUI thread was busy
        QCOMPARE(seen.count(), 0);
        QCOMPARE(bridge.pendingMachineUpdates(), size_t(1)); // one vehicle: one pending value
        qInfo("%llu updates of %s while the GUI thread was busy", qulonglong(burst.pushed - before.pushed),
              qPrintable(kVehicle));

        QCoreApplication::processEvents();
        QCOMPARE(seen.count(), 1); // one signal for the whole burst
        QCOMPARE(seen.batches[0].size(), 1);
        QCOMPARE(seen.batches[0][0].id, kVehicle);
        QCOMPARE(seen.batches[0][0].link,
                 LinkState::Degraded); // the latest state, not the first of the burst
        QCOMPARE(bridge.machineStats().drains, before.drains + 1);
        QVERIFY(seen.allOn(bridge.thread()));
        // The panels' vehicle view is coalesced the same way.
        QCOMPARE(views.count(), 1);
        QCOMPARE(views[0][0].value<JausVehicle>().link, JausLink::Degraded);
        QCOMPARE(bridge.subsystem(126)->link, JausLink::Degraded);
        bridge.stop();
    }

    void implausiblePoseIsNotDrawnButCountedAndWarnedOnce() {
        // A UGV whose poses are 220 km from the site origin (beyond the default 50 km extent) is
        // marked implausible and not drawn; the cause is counted on the link, one warning is raised.
        sim::JausDemo demo(oneUgv());
        GeoPoint elsewhere = oneUgv().origin;
        elsewhere.lat += 2.0;
        JausBridge bridge(consoleConfig(demo, 60), GeoFrame(elsewhere));
        QList<FleetEvent> events;
        connect(&bridge, &FleetBridge::eventRaised, this, [&](const FleetEvent& e) {
            if (e.text.contains(QStringLiteral("pose ignored")))
                events << e;
        });
        bridgetest::Deliveries seen(&bridge);
        QVERIFY(bridge.start().isEmpty());
        auto implausible = [&] {
            const auto c = bridge.linkCounters();
            return c.isEmpty() ? quint64(0)
                               : c[0].rejected.value(QStringLiteral("implausible.outside_extent"));
        };
        // Counted once per distinct pose (a standing UGV repeats its pose in every report), one warning.
        QTRY_VERIFY_WITH_TIMEOUT(implausible() >= 1, 30000);
        // The counter moves on the io thread; the state carrying the verdict reaches the GUI thread later.
        QTRY_VERIFY_WITH_TIMEOUT(seen.latest(kVehicle).has_value() &&
                                     seen.latest(kVehicle)->health == HealthLevel::Warning,
                                 20000);
        const MachineState m = *seen.latest(kVehicle);
        QVERIFY2(!m.hasPosition, qPrintable(QStringLiteral("%1 %2").arg(m.e).arg(m.n)));
        QCOMPARE(m.health, HealthLevel::Warning);
        QVERIFY2(m.healthText.contains(QStringLiteral("implausible pose ignored")), qPrintable(m.healthText));
        QVERIFY(!bridge.subsystem(126) || !bridge.subsystem(126)->globalPose);
        QTRY_COMPARE_WITH_TIMEOUT(events.size(), 1, 10000);
        QCOMPARE(events[0].severity, EventSeverity::Warning);
        QCOMPARE(events[0].machineId, kVehicle);
        QVERIFY2(events[0].text.contains(QStringLiteral("outside_extent")), qPrintable(events[0].text));
        QCoreApplication::processEvents();
        QCOMPARE(events.size(), 1);
        bridge.stop();
    }

    void heldGroupPortIsAStatusNoteNotAFailure() {
        // Beside a node manager that holds the JAUS port without SO_REUSEADDR (bound to the wildcard, as node
        // managers do): the bridge starts, the vehicle comes up through its static endpoint, the status bar
        // note names the port, and the operator gets one warning event.
        namespace asio = boost::asio;
        asio::io_context io;
        asio::ip::udp::socket nodeManager(io);
        nodeManager.open(asio::ip::udp::v4());
        nodeManager.bind(asio::ip::udp::endpoint(asio::ip::address_v4::any(), 0));
        const quint16 held = nodeManager.local_endpoint().port();
        sim::JausDemo demo(oneUgv());
        jaus::JausConfig c = consoleConfig(demo, 60);
        c.transport.port = held;
        c.transport.multicastPort = held;
        JausBridge bridge(c, GeoFrame(oneUgv().origin));
        QList<FleetEvent> events;
        connect(&bridge, &FleetBridge::eventRaised, this, [&](const FleetEvent& e) {
            if (e.text.contains(QStringLiteral("no group socket")))
                events << e;
        });
        QCOMPARE(bridge.statusNote(), QString()); // not started: nothing to say
        QCOMPARE(bridge.start(), QString());
        QCOMPARE(bridge.statusNote(),
                 QStringLiteral("JAUS: no group socket (%1 held by another process)").arg(held));
        QTRY_VERIFY_WITH_TIMEOUT(bridge.linkStatus(QStringLiteral("jaus")) &&
                                     bridge.linkStatus(QStringLiteral("jaus"))->state == LinkState::Up,
                                 20000);
        QTRY_COMPARE_WITH_TIMEOUT(events.size(), 1, 10000);
        QCOMPARE(events[0].severity, EventSeverity::Warning);
        QVERIFY(events[0].requiresAck);
        QVERIFY2(events[0].text.contains(QString::number(held)), qPrintable(events[0].text));
        bridge.stop();
        QCOMPARE(bridge.statusNote(), QString()); // a stopped stack has no group socket to miss
        QCOMPARE(events.size(), 1);
    }

    void stalledIoThreadRaisesAnAlarmAndDegradesTheLink() {
        // The io thread blocked on purpose (a handler waiting on a latch) for more than 1 s.
        sim::JausDemo demo(oneUgv());
        JausBridge bridge(consoleConfig(demo, 60), GeoFrame(oneUgv().origin));
        QVERIFY(bridge.start().isEmpty());
        bridgetest::expectWatchdog(bridge, QStringLiteral("jaus"),
                                   [&](std::function<void()> f) { bridge.postToIo(std::move(f)); });
        bridge.stop();
    }

    void commandsWhileTheLinkIsDownAreRefused() {
        Received received;
        sim::JausDemo demo(oneUgv());
        auto& ugv = *demo.ugvs().front();
        received.tap(ugv);
        JausBridge bridge(consoleConfig(demo, 1), GeoFrame(oneUgv().origin)); // link lost after 1 s
        QVERIFY(bridge.start().isEmpty());
        auto vehicle = [&] { return bridge.subsystem(126).value_or(JausVehicle{}); };
        QTRY_VERIFY_WITH_TIMEOUT(vehicle().link == JausLink::Up && vehicle().mobilityComponent.subsystem != 0,
                                 20000);
        // Control first, so that the refusals below are about the link and not about access.
        QVERIFY(ocu::testing::bridgeResult([&](auto d) { bridge.command(RequestControl{kVehicle}, d); }).ok);
        QTRY_VERIFY_WITH_TIMEOUT(vehicle().controlledByUs, 10000);

        // The vehicle falls silent (it still hears us): after 1 s its link is down.
        ugv.setPacketLoss(1.0);
        QTRY_COMPARE_WITH_TIMEOUT(vehicle().link, JausLink::Down, 20000);
        const QList<CommandResult> refused{
            ocu::testing::bridgeResult([&](auto d) { bridge.stopMachine(kVehicle, d); }),
            ocu::testing::bridgeResult([&](auto d) { bridge.clearStop(kVehicle, d); }),
            ocu::testing::bridgeResult([&](auto d) { bridge.command(RequestControl{kVehicle}, d); }),
            ocu::testing::bridgeResult([&](auto d) {
                bridge.command(Management{kVehicle, ManagementAction::Resume}, d);
            }),
            ocu::testing::bridgeResult([&](auto d) {
                TimedDrive drive;
                drive.id = kVehicle;
                drive.linear = 0.5;
                bridge.command(drive, d);
            }),
            bridge.drive(126, JausDrive{JausDrive::Mode::Velocity, 0.5, 0, 0})};
        for (const CommandResult& r : refused) {
            QVERIFY2(!r.ok, qPrintable(r.message));
            QVERIFY2(r.message.contains(QStringLiteral("the link to jaus:126 is down; nothing sent")),
                     qPrintable(r.message));
        }
        // Nothing went out: not while the link was down, and not when the vehicle is heard again.
        QTest::qWait(1000);
        ugv.setPacketLoss(0);
        QTRY_COMPARE_WITH_TIMEOUT(vehicle().link, JausLink::Up, 20000);
        QTest::qWait(1000);
        for (quint16 id : {jaus::msg::SetEmergency, jaus::msg::ClearEmergency, jaus::msg::Resume,
                           jaus::msg::SetVelocityCommand, jaus::msg::SetWrenchEffort})
            QVERIFY2(received.count(id) == 0,
                     qPrintable(QStringLiteral("message 0x%1 reached the vehicle").arg(id, 4, 16)));
        QVERIFY(ugv.state().management != jaus::ManagementState::Emergency);

        // With the link up the same stop goes out.
        const CommandResult stop =
            ocu::testing::bridgeResult([&](auto d) { bridge.stopMachine(kVehicle, d); });
        QVERIFY2(stop.ok, qPrintable(stop.message));
        QTRY_VERIFY_WITH_TIMEOUT(received.count(jaus::msg::SetEmergency) > 0, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(ugv.state().management, jaus::ManagementState::Emergency, 10000);

        // STOP ALL addresses every discovered vehicle, even one whose link is down (it may still hear us):
        // the result says it went on the wire, per vehicle.
        ugv.setPacketLoss(1.0);
        QTRY_COMPARE_WITH_TIMEOUT(vehicle().link, JausLink::Down, 20000);
        const int before = received.count(jaus::msg::SetEmergency);
        const CommandResult all = ocu::testing::bridgeResult([&](auto d) { bridge.stopAll(d); });
        QCOMPARE(all.targets.size(), 1);
        QCOMPARE(targetId(all.targets[0]), QStringLiteral("jaus:126"));
        QVERIFY2(all.targets[0].sent, qPrintable(all.message));
        QTRY_VERIFY_WITH_TIMEOUT(received.count(jaus::msg::SetEmergency) > before, 10000);
        bridge.stop();
        ugv.setMessageTap({});
    }
};

QTEST_GUILESS_MAIN(TestJausBridgeThreads)
#include "test_jaus_bridge_threads.moc"
