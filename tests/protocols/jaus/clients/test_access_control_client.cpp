// AccessControlClient on its own with a FakeClock, the vehicle played by hand: request with our authority
// and QueryTimeout once, re-requests at 40 % of the reported timeout while confirmations flow, control lost
// when they stop, refusal without retry, pre-emption told from a timeout by the next ReportControl (or its
// absence), release answered by RejectControl with zero drive commands first, a late accept handed back, the
// monitor role never requesting.
#include <QtTest>

#include <cmath>

#include "protocols/jaus/clients/AccessControlClient.h"
#include "protocols/jaus/clients/DriveClient.h"
#include "tests/protocols/jaus/clients/ClientRig.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::jaus::test;

namespace {

struct AccessRig : ClientRig {
    DriveClient drive{ctx};
    AccessControlClient access{ctx, drive};
    explicit AccessRig(JausConfig c = rigConfig()) : ClientRig(std::move(c)) {
        access.registerMessages(table);
        drive.registerMessages(table);
    }
    // 10 ms steps; the vehicle confirms every RequestControl when confirming is true.
    void run(RemoteSubsystem& r, double seconds, bool confirming = false) {
        runFor(seconds, [&](TimePoint now) {
            const std::size_t before = out.sent.size();
            access.tick(r, now);
            drive.tick(r, now);
            for (std::size_t k = before; confirming && k < out.sent.size(); ++k)
                if (out.sent[k].id() == msg::RequestControl)
                    deliver(r, encodeU8(msg::ConfirmControl, 0));
        });
    }
    // Request and get accepted.
    void takeControl(RemoteSubsystem& r) {
        QVERIFY(access.requestControl(r.id()));
        QVERIFY(deliver(r, encodeU8(msg::ConfirmControl, 0)));
        QVERIFY(r.snap.controlledByUs);
    }
};

ReportControl controlledBy(JausId controller, std::uint8_t authority) {
    ReportControl rc;
    rc.controller = controller;
    rc.authority = authority;
    return rc;
}

} // namespace

class TestAccessControlClient : public QObject {
    Q_OBJECT

private slots:
    void requestNeedsMobilityComponentAndAuthority() {
        AccessRig rig;
        RemoteSubsystem& bare = rig.ctx.remote(126); // heard, services unknown
        QVERIFY(!rig.access.requestControl(126));
        QVERIFY(!rig.access.requestControl(77)); // never heard of
        QCOMPARE(rig.rec.count(EventKind::CommandRefused), 2);
        QCOMPARE(rig.out.count(msg::RequestControl), 0);
        QCOMPARE(bare.snap.access, AccessState::Monitoring);

        AccessRig monitor(rigConfig(0));
        RemoteSubsystem& r = monitor.vehicle();
        QVERIFY(!monitor.access.requestControl(126));
        monitor.run(r, 3);
        QCOMPARE(monitor.out.count(msg::RequestControl), 0);
        QCOMPARE(monitor.counters.get("cmd.refused"), std::uint64_t(1));
    }

    void acceptedAndKeptWhileConfirmationsFlow() {
        AccessRig rig;
        RemoteSubsystem& r = rig.vehicle();
        QVERIFY(rig.access.requestControl(126));
        QCOMPARE(rig.out.ids(), (std::vector<std::uint16_t>{msg::RequestControl, msg::QueryTimeout}));
        QCOMPARE(rig.out.sent[0].destination, AccessRig::mobility());
        QCOMPARE(*decodeU8(rig.out.sent[0].payload, msg::RequestControl), std::uint8_t(205));
        QVERIFY(!r.snap.controlledByUs); // nothing shown before the vehicle says so

        QVERIFY(rig.deliver(r, encodeU8(msg::ConfirmControl, 0)));
        QVERIFY(r.snap.controlledByUs);
        QCOMPARE(r.snap.access, AccessState::ControlAccepted);
        QCOMPARE(r.snap.controller, (JausId{200, 1, 1}));
        QCOMPARE(rig.rec.count(EventKind::ControlAccepted), 1);
        QVERIFY(rig.deliver(r, encodeU8(msg::ReportTimeout, 10)));
        QCOMPARE(r.snap.accessTimeoutS, std::uint8_t(10));

        // 40 % of the 10 s timeout: a re-request every 4 s; QueryControl at the 1 Hz status rate.
        const int requests = rig.out.count(msg::RequestControl);
        rig.run(r, 40.0, true);
        QCOMPARE(rig.out.count(msg::RequestControl) - requests, 10);
        QVERIFY(rig.out.count(msg::QueryControl) >= 39);
        QCOMPARE(rig.out.count(msg::QueryTimeout), 1); // asked once
        QVERIFY(r.snap.controlledByUs);
        QCOMPARE(rig.rec.count(EventKind::ControlLost), 0);
        QCOMPARE(rig.rec.count(EventKind::ControlAccepted), 1); // confirmations of re-requests are quiet
    }

    void lostWhenConfirmationsStop() {
        AccessRig rig;
        RemoteSubsystem& r = rig.vehicle();
        rig.takeControl(r);
        QVERIFY(rig.drive.startDriving(126));
        QVERIFY(r.snap.driving);
        rig.run(r, 4.9); // the 5 s default timeout (no ReportTimeout) has not passed
        QVERIFY(r.snap.controlledByUs);
        rig.run(r, 0.2);
        QVERIFY(!r.snap.controlledByUs);
        QCOMPARE(r.snap.access, AccessState::Timeout);
        QCOMPARE(rig.rec.count(EventKind::ControlLost), 1);
        QVERIFY(!r.snap.driving); // the drive session ends with control
        QVERIFY(!rig.drive.anyActive());
        // No more re-requests after the loss.
        const int n = rig.out.count(msg::RequestControl);
        rig.run(r, 5);
        QCOMPARE(rig.out.count(msg::RequestControl), n);
    }

    void refusedWithoutRetry() {
        AccessRig rig;
        RemoteSubsystem& r = rig.vehicle();
        QVERIFY(rig.access.requestControl(126));
        QVERIFY(rig.deliver(r, encodeU8(msg::ConfirmControl, 2)));
        QCOMPARE(r.snap.access, AccessState::InsufficientAuthority);
        QCOMPARE(rig.rec.count(EventKind::ControlRejected), 1);
        QCOMPARE(rig.out.sent.back().id(), msg::QueryControl); // who holds it, then
        const int n = rig.out.count(msg::RequestControl);
        rig.run(r, 5);
        QCOMPARE(rig.out.count(msg::RequestControl), n);

        QVERIFY(rig.access.requestControl(126));
        QVERIFY(rig.deliver(r, encodeU8(msg::ConfirmControl, 1)));
        QCOMPARE(r.snap.access, AccessState::NotAvailable);
    }

    void reRequestRefusedWhileInControlIsPreemption() {
        AccessRig rig;
        RemoteSubsystem& r = rig.vehicle();
        rig.takeControl(r);
        QVERIFY(rig.deliver(r, encodeU8(msg::ConfirmControl, 2)));
        QVERIFY(!r.snap.controlledByUs);
        QCOMPARE(r.snap.access, AccessState::Preempted);
        QCOMPARE(rig.rec.count(EventKind::ControlPreempted), 1);
        QCOMPARE(rig.rec.count(EventKind::ControlRejected), 0);
    }

    void rejectThenReportControlTellsPreemptionFromTimeout() {
        AccessRig rig;
        RemoteSubsystem& r = rig.vehicle();
        rig.takeControl(r);
        QVERIFY(rig.deliver(r, encodeU8(msg::RejectControl, 1)));
        QVERIFY(!r.snap.controlledByUs);
        QCOMPARE(r.snap.access, AccessState::ControlReleased); // undecided until ReportControl
        QCOMPARE(rig.out.sent.back().id(), msg::QueryControl);
        QVERIFY(rig.deliver(r, encode(controlledBy({201, 1, 1}, 230))));
        QCOMPARE(r.snap.access, AccessState::Preempted);
        QCOMPARE(r.snap.controller, (JausId{201, 1, 1}));
        QCOMPARE(rig.rec.count(EventKind::ControlPreempted), 1);

        // A controller of lower or equal authority (or none) means our control timed out.
        AccessRig low;
        RemoteSubsystem& r2 = low.vehicle();
        low.takeControl(r2);
        QVERIFY(low.deliver(r2, encodeU8(msg::RejectControl, 0)));
        QVERIFY(low.deliver(r2, encode(controlledBy({201, 1, 1}, 205))));
        QCOMPARE(r2.snap.access, AccessState::Timeout);
        QCOMPARE(low.rec.count(EventKind::ControlLost), 1);

        // No ReportControl at all: decided as a timeout one second later.
        AccessRig silent;
        RemoteSubsystem& r3 = silent.vehicle();
        silent.takeControl(r3);
        QVERIFY(silent.deliver(r3, encodeU8(msg::RejectControl, 1)));
        silent.run(r3, 0.9);
        QCOMPARE(r3.snap.access, AccessState::ControlReleased);
        silent.run(r3, 0.2);
        QCOMPARE(r3.snap.access, AccessState::Timeout);
        QCOMPARE(silent.rec.count(EventKind::ControlLost), 1);
    }

    void missedRejectNoticedFromReportControl() {
        AccessRig rig;
        RemoteSubsystem& r = rig.vehicle();
        rig.takeControl(r);
        // Within 500 ms of a confirmation a ReportControl naming someone else is stale: ignored.
        rig.run(r, 0.45);
        QVERIFY(rig.deliver(r, encode(controlledBy({201, 1, 1}, 230))));
        QVERIFY(r.snap.controlledByUs);
        rig.run(r, 0.1);
        QVERIFY(rig.deliver(r, encode(controlledBy({201, 1, 1}, 230))));
        QVERIFY(!r.snap.controlledByUs);
        QCOMPARE(r.snap.access, AccessState::Preempted);
    }

    void releaseSendsZeroDriveFirstAndEndsOnReject() {
        AccessRig rig;
        RemoteSubsystem& r = rig.vehicle();
        rig.takeControl(r);
        QVERIFY(rig.drive.startDriving(126));
        rig.out.sent.clear();
        QVERIFY(rig.access.releaseControl(126));
        auto ids = rig.out.ids();
        QVERIFY(ids.size() >= 2);
        QCOMPARE(ids.back(), msg::ReleaseControl);
        for (std::size_t i = 0; i + 1 < ids.size(); ++i) {
            QCOMPARE(ids[i], msg::SetVelocityCommand);
            QVERIFY(std::abs(*decodeVelocityCommand(rig.out.sent[i].payload)->vx) < 1e-6);
        }
        QVERIFY(r.snap.controlledByUs); // until the vehicle answers
        QVERIFY(rig.deliver(r, encodeU8(msg::RejectControl, 0)));
        QVERIFY(!r.snap.controlledByUs);
        QCOMPARE(r.snap.access, AccessState::ControlReleased);
        QCOMPARE(rig.rec.count(EventKind::ControlReleased), 1);
        QCOMPARE(rig.rec.count(EventKind::ControlLost), 0);
        const int n = rig.out.count(msg::RequestControl);
        rig.run(r, 5);
        QCOMPARE(rig.out.count(msg::RequestControl), n);
        QVERIFY(!rig.drive.anyActive());
    }

    void lateAcceptHandedBack() {
        AccessRig rig;
        RemoteSubsystem& r = rig.vehicle();
        QVERIFY(rig.access.requestControl(126));
        QVERIFY(rig.access.releaseControl(126)); // gave up before the answer
        rig.out.sent.clear();
        QVERIFY(rig.deliver(r, encodeU8(msg::ConfirmControl, 0)));
        QVERIFY(!r.snap.controlledByUs);
        QCOMPARE(rig.out.ids(), std::vector<std::uint16_t>{msg::ReleaseControl});
    }

    void releaseAllReleasesWhatWeHoldOrAsked() {
        AccessRig rig;
        RemoteSubsystem& a = rig.vehicle(126);
        rig.vehicle(127);
        rig.vehicle(128); // never asked
        rig.takeControl(a);
        QVERIFY(rig.access.requestControl(127)); // asked, not yet confirmed
        QVERIFY(rig.access.wantsControl(127));
        rig.out.sent.clear();
        rig.access.releaseAll();
        std::vector<JausId> released;
        for (auto& s : rig.out.sent)
            if (s.id() == msg::ReleaseControl)
                released.push_back(s.destination);
        QCOMPARE(released, (std::vector<JausId>{AccessRig::mobility(126), AccessRig::mobility(127)}));
        QVERIFY(!rig.access.wantsControl(127));
    }

    void reportControlShowsWhoControlsWhileMonitoring() {
        AccessRig rig;
        RemoteSubsystem& r = rig.vehicle();
        QVERIFY(rig.deliver(r, encode(controlledBy({}, 0))));
        QCOMPARE(r.snap.access, AccessState::NotControlled);
        QVERIFY(rig.deliver(r, encode(controlledBy({201, 1, 1}, 230))));
        QCOMPARE(r.snap.access, AccessState::Monitoring);
        QCOMPARE(r.snap.controllerAuthority, std::uint8_t(230));
        QVERIFY(rig.deliver(r, encodeEmpty(msg::ReportAuthority))); // known, ignored
        QVERIFY(!rig.deliver(r, encodeEmpty(msg::ReportStatus)));   // not this client's
        // Bad bodies are counted, never applied.
        QVERIFY(rig.deliver(r, encodeEmpty(msg::ReportControl))); // the ID without its body
        QCOMPARE(rig.counters.get("rx.rejected.truncated"), std::uint64_t(1));
        QCOMPARE(r.snap.access, AccessState::Monitoring);
    }
};

QTEST_GUILESS_MAIN(TestAccessControlClient)
#include "test_access_control_client.moc"
