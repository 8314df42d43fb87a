// LivenessClient on its own with a FakeClock: up while messages arrive, degraded after 2.5 heartbeat periods
// (at most half of link_lost_s), down after link_lost_s with one LinkLost, LinkRestored only when a link
// that was down comes back (not on first contact, not after a degraded spell), the heartbeat event asked
// from the platform manager at the configured rate, and QueryHeartbeatPulse answered.
#include <QtTest>

#include <cmath>

#include "protocols/jaus/clients/EventsClient.h"
#include "protocols/jaus/clients/LivenessClient.h"
#include "tests/protocols/jaus/clients/ClientRig.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::jaus::test;

namespace {

struct LivenessRig : ClientRig {
    EventsClient events{ctx};
    LivenessClient liveness{ctx, events};
    explicit LivenessRig(JausConfig c = rigConfig()) : ClientRig(std::move(c)) {
        events.registerMessages(table);
        liveness.registerMessages(table);
    }
    // First contact, as JausCore makes it.
    RemoteSubsystem& contact(std::uint16_t ss = 126) {
        RemoteSubsystem& r = vehicle(ss);
        const bool restored = liveness.heard(r, true);
        if (restored)
            qFatal("first contact reported as a restored link");
        return r;
    }
    void run(RemoteSubsystem& r, double seconds) {
        runFor(seconds, [&](TimePoint now) { liveness.tick(r, now); });
    }
};

} // namespace

class TestLivenessClient : public QObject {
    Q_OBJECT

private slots:
    void degradedThenDownOnSilence() {
        LivenessRig rig; // heartbeat 1 Hz, link lost after 5 s
        RemoteSubsystem& r = rig.contact();
        QCOMPARE(r.snap.link, LinkState::Up);
        QCOMPARE(r.snap.lastMessage, rig.clock.now());
        QVERIFY(r.snap.lastMessageUnixMs > 0);
        rig.run(r, 2.5);
        QCOMPARE(r.snap.link, LinkState::Up);
        rig.run(r, 0.1);
        QCOMPARE(r.snap.link, LinkState::Degraded);
        QCOMPARE(rig.rec.count(EventKind::LinkLost), 0);
        QCOMPARE(rig.rec.snapshots.size(), std::size_t(1)); // the change was handed to the listener
        rig.run(r, 2.3);
        QCOMPARE(r.snap.link, LinkState::Degraded);
        rig.run(r, 0.2);
        QCOMPARE(r.snap.link, LinkState::Down);
        QCOMPARE(rig.rec.count(EventKind::LinkLost), 1);
        QCOMPARE(rig.rec.events.back().severity, Severity::Error);
        rig.run(r, 10);
        QCOMPARE(rig.rec.count(EventKind::LinkLost), 1); // once per outage
    }

    void anyMessageKeepsTheLinkUp() {
        LivenessRig rig;
        RemoteSubsystem& r = rig.contact();
        for (int i = 0; i < 20; ++i) {
            rig.run(r, 2.0);
            QVERIFY(!rig.liveness.heard(r, false));
        }
        QCOMPARE(r.snap.link, LinkState::Up);
        QVERIFY(rig.rec.events.empty());
    }

    void restoredOnlyAfterDown() {
        LivenessRig rig;
        RemoteSubsystem& r = rig.contact();
        rig.run(r, 3);
        QCOMPARE(r.snap.link, LinkState::Degraded);
        QVERIFY(!rig.liveness.heard(r, false)); // degraded -> up is not a restoration
        QCOMPARE(r.snap.link, LinkState::Up);
        rig.run(r, 6);
        QCOMPARE(r.snap.link, LinkState::Down);
        QVERIFY(rig.liveness.heard(r, false));
        QCOMPARE(r.snap.link, LinkState::Up);
        QCOMPARE(rig.rec.count(EventKind::LinkRestored), 1);
        QVERIFY(!rig.liveness.heard(r, false));
        QCOMPARE(rig.rec.count(EventKind::LinkRestored), 1);
    }

    void degradedAfterTwoAndAHalfHeartbeatsAtMostHalfTheLossTime() {
        JausConfig c = rigConfig();
        c.linkLostS = 2;
        LivenessRig rig(c); // 2.5 heartbeat periods would be 2.5 s: capped at 1 s
        RemoteSubsystem& r = rig.contact();
        rig.run(r, 0.95);
        QCOMPARE(r.snap.link, LinkState::Up);
        rig.run(r, 0.1);
        QCOMPARE(r.snap.link, LinkState::Degraded);
        rig.run(r, 1.0);
        QCOMPARE(r.snap.link, LinkState::Down);

        c = rigConfig();
        c.heartbeatRateHz = 4; // 2.5 periods = 0.625 s, well inside half of the 5 s loss time
        LivenessRig fast(c);
        RemoteSubsystem& f = fast.contact();
        fast.run(f, 0.6);
        QCOMPARE(f.snap.link, LinkState::Up);
        fast.run(f, 0.05);
        QCOMPARE(f.snap.link, LinkState::Degraded);
        fast.run(f, 4.3);
        QCOMPARE(f.snap.link, LinkState::Degraded);
        fast.run(f, 0.1);
        QCOMPARE(f.snap.link, LinkState::Down);
    }

    void heartbeatEventFromThePlatformManager() {
        JausConfig c = rigConfig();
        c.heartbeatRateHz = 2;
        LivenessRig rig(c);
        RemoteSubsystem& r = rig.contact();
        r.components.platformManager = JausId{126, 1, 1};
        rig.liveness.onServicesKnown(r);
        rig.events.tick(r, rig.clock.now());
        const Sent* ce = rig.out.last(msg::CreateEvent);
        QVERIFY(ce);
        QCOMPARE(ce->destination, (JausId{126, 1, 1}));
        auto m = decodeCreateEvent(ce->payload);
        QVERIFY(m.ok());
        QCOMPARE(m->type, EventType::Periodic);
        QVERIFY(std::abs(m->rateHz - 2.0) < 0.02);
        QCOMPARE(peekMessageId(m->queryMessage), msg::QueryHeartbeatPulse);
    }

    void answersQueryHeartbeatPulse() {
        LivenessRig rig;
        const JausId asker{77, 1, 1};
        QVERIFY(rig.table.answer(msg::QueryHeartbeatPulse, asker, encodeEmpty(msg::QueryHeartbeatPulse)));
        QCOMPARE(rig.out.sent.size(), std::size_t(1));
        QCOMPARE(rig.out.sent[0].destination, asker);
        QCOMPARE(rig.out.sent[0].id(), msg::ReportHeartbeatPulse);
    }
};

QTEST_GUILESS_MAIN(TestLivenessClient)
#include "test_liveness_client.moc"
