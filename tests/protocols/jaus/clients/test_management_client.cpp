// ManagementClient on its own with a FakeClock: SetEmergency at safety priority repeated every 200 ms (five
// times at most) until ReportStatus shows EMERGENCY, allowed for the monitor and for a vehicle whose
// mobility component is unknown (sent to ss.255.255), ending the drive session; ClearEmergency with the
// same code, refused for the monitor; Resume/Standby/Shutdown/Reset only with control; the on-change status
// event and the status poll; management events from ReportStatus.
#include <QtTest>

#include "protocols/jaus/clients/DriveClient.h"
#include "protocols/jaus/clients/EventsClient.h"
#include "protocols/jaus/clients/ManagementClient.h"
#include "tests/protocols/jaus/clients/ClientRig.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::jaus::test;

namespace {

struct ManagementRig : ClientRig {
    EventsClient events{ctx};
    DriveClient drive{ctx};
    ManagementClient management{ctx, events, drive};
    explicit ManagementRig(JausConfig c = rigConfig()) : ClientRig(std::move(c)) {
        events.registerMessages(table);
        drive.registerMessages(table);
        management.registerMessages(table);
    }
    void run(RemoteSubsystem& r, double seconds) {
        runFor(seconds, [&](TimePoint now) { management.tick(r, now); });
    }
    static Bytes status(ManagementState s) { return encode(ReportStatus{s, 0}); }
};

} // namespace

class TestManagementClient : public QObject {
    Q_OBJECT

private slots:
    void emergencyRepeatedUntilReported() {
        ManagementRig rig;
        RemoteSubsystem& r = rig.vehicle();
        QVERIFY(rig.management.setEmergency(126));
        QCOMPARE(rig.out.ids(), (std::vector<std::uint16_t>{msg::SetEmergency, msg::QueryStatus}));
        const Sent& se = rig.out.sent[0];
        QCOMPARE(se.destination, ClientRig::mobility());
        QCOMPARE(se.options.priority, Priority::Safety);
        QCOMPARE(*decodeU16(se.payload, msg::SetEmergency), std::uint16_t(EmergencyCode::Safety));
        rig.run(r, 0.45);
        QCOMPARE(rig.out.count(msg::SetEmergency), 3); // at 0, 200 and 400 ms
        QVERIFY(rig.deliver(r, ManagementRig::status(ManagementState::Emergency)));
        QVERIFY(r.snap.emergency);
        QCOMPARE(r.snap.management, std::optional<ManagementState>(ManagementState::Emergency));
        QCOMPARE(rig.rec.count(EventKind::Emergency), 1);
        QCOMPARE(rig.rec.count(EventKind::ManagementChanged), 1);
        rig.run(r, 2);
        QCOMPARE(rig.out.count(msg::SetEmergency), 3); // confirmed: no more repeats
    }

    void emergencyRepeatsAreBounded() {
        ManagementRig rig;
        RemoteSubsystem& r = rig.vehicle();
        QVERIFY(rig.management.setEmergency(126, EmergencyCode::Stop));
        rig.run(r, 5);
        QCOMPARE(rig.out.count(msg::SetEmergency), 6); // the first and five repeats
        for (auto& s : rig.out.sent)
            if (s.id() == msg::SetEmergency)
                QCOMPARE(*decodeU16(s.payload, msg::SetEmergency), std::uint16_t(EmergencyCode::Stop));
    }

    void monitorStopsButDoesNotClear() {
        ManagementRig rig(rigConfig(0));
        RemoteSubsystem& r = rig.vehicle();
        QVERIFY(rig.management.setEmergency(126));
        QVERIFY(rig.deliver(r, ManagementRig::status(ManagementState::Emergency)));
        QVERIFY(!rig.management.clearEmergency(126));
        QCOMPARE(rig.out.count(msg::ClearEmergency), 0);
        QCOMPARE(rig.rec.count(EventKind::CommandRefused), 1);
        QVERIFY(!rig.management.setEmergency(99)); // unknown subsystem
    }

    void emergencyWithoutMobilityComponentGoesToAll() {
        ManagementRig rig;
        rig.ctx.remote(126); // heard, services unknown
        QVERIFY(rig.management.setEmergency(126));
        QCOMPARE(rig.out.sent[0].destination, (JausId{126, 0xFF, 0xFF}));
        QVERIFY(!rig.management.clearEmergency(126)); // clearing needs the component
    }

    void clearUsesTheSameCode() {
        ManagementRig rig;
        RemoteSubsystem& r = rig.vehicle();
        QVERIFY(rig.management.setEmergency(126, EmergencyCode::Stop));
        QVERIFY(rig.deliver(r, ManagementRig::status(ManagementState::Emergency)));
        QVERIFY(rig.management.clearEmergency(126));
        const Sent* ce = rig.out.last(msg::ClearEmergency);
        QVERIFY(ce);
        QCOMPARE(*decodeU16(ce->payload, msg::ClearEmergency), std::uint16_t(EmergencyCode::Stop));
        QCOMPARE(ce->options.priority, Priority::Safety);
        QVERIFY(rig.deliver(r, ManagementRig::status(ManagementState::Standby)));
        QVERIFY(!r.snap.emergency);
        QCOMPARE(rig.rec.count(EventKind::EmergencyCleared), 1);
    }

    void emergencyEndsTheDriveSession() {
        ManagementRig rig;
        RemoteSubsystem& r = rig.vehicle();
        r.snap.controlledByUs = true; // as the access-control client leaves it
        QVERIFY(rig.drive.startDriving(126));
        QVERIFY(rig.drive.anyActive());
        QVERIFY(rig.management.setEmergency(126));
        QVERIFY(!rig.drive.anyActive());
        QVERIFY(!r.snap.driving);
    }

    void commandsNeedControl() {
        ManagementRig rig;
        RemoteSubsystem& r = rig.vehicle();
        QVERIFY(!rig.management.command(126, msg::Resume, "resume"));
        QCOMPARE(rig.out.count(msg::Resume), 0);
        r.snap.controlledByUs = true;
        QVERIFY(rig.management.command(126, msg::Resume, "resume"));
        QCOMPARE(rig.out.ids(), (std::vector<std::uint16_t>{msg::Resume, msg::QueryStatus}));
        ManagementRig monitor(rigConfig(0));
        RemoteSubsystem& m = monitor.vehicle();
        m.snap.controlledByUs = true;
        QVERIFY(!monitor.management.command(126, msg::Shutdown, "shutdown"));
        QCOMPARE(monitor.rec.events.back().text, std::string("the monitor role may not shutdown"));
    }

    void statusOnChangeEventAndPoll() {
        ManagementRig rig; // status_poll_hz 1
        RemoteSubsystem& r = rig.vehicle();
        rig.management.onServicesKnown(r);
        QCOMPARE(rig.events.state(126, msg::QueryStatus),
                 std::optional<EventsClient::SubscriptionState>(EventsClient::SubscriptionState::None));
        rig.events.tick(r, rig.clock.now());
        auto ce = decodeCreateEvent(rig.out.last(msg::CreateEvent)->payload);
        QVERIFY(ce && ce->type == EventType::EveryChange);
        QCOMPARE(rig.out.last(msg::CreateEvent)->destination, ClientRig::mobility());
        const int before = rig.out.count(msg::QueryStatus);
        rig.run(r, 3);
        QCOMPARE(rig.out.count(msg::QueryStatus) - before, 3);
        r.snap.link = LinkState::Down; // not polled while down
        rig.run(r, 3);
        QCOMPARE(rig.out.count(msg::QueryStatus) - before, 3);
    }

    void managementChangesAreEvents() {
        ManagementRig rig;
        RemoteSubsystem& r = rig.vehicle();
        QVERIFY(rig.deliver(r, ManagementRig::status(ManagementState::Standby)));
        QVERIFY(rig.deliver(r, ManagementRig::status(ManagementState::Standby)));
        QCOMPARE(rig.rec.count(EventKind::ManagementChanged), 1);
        QVERIFY(rig.deliver(r, ManagementRig::status(ManagementState::Failure)));
        QCOMPARE(rig.rec.events.back().severity, Severity::Error);
        QVERIFY(rig.deliver(r, Bytes{0x02, 0x40, 0x09})); // ReportStatus with status 9
        QCOMPARE(rig.counters.get("rx.rejected.value"), std::uint64_t(1));
        QCOMPARE(r.snap.management, std::optional<ManagementState>(ManagementState::Failure));
    }
};

QTEST_GUILESS_MAIN(TestManagementClient)
#include "test_management_client.moc"
