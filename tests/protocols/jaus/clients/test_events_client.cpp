// EventsClient on its own with a FakeClock: CreateEvent per subscription once the vehicle is reachable,
// confirmed events not polled, polling at the requested rate when the request is rejected, unconfirmed
// within event_confirm_timeout_s, or confirmed below half the rate (then cancelled), events re-created when
// the link returns, the report inside an Event handed to the client that handles it (nested or unknown
// reports counted), and a CreateEvent sent to the console rejected.
#include <QtTest>

#include <cmath>
#include <set>
#include <stdexcept>

#include "protocols/jaus/clients/EventsClient.h"
#include "tests/protocols/jaus/clients/ClientRig.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::jaus::test;

namespace {

using SubState = EventsClient::SubscriptionState;

struct EventsRig : ClientRig {
    EventsClient events{ctx};
    std::vector<GlobalPose> poses; // what a pose client would have received
    EventsRig() {
        events.registerMessages(table);
        table.onVehicleMessage(msg::ReportGlobalPose, [this](RemoteSubsystem&, const JausId&, ByteSpan p) {
            poses.push_back(*decodeGlobalPose(p));
        });
    }
    void run(RemoteSubsystem& r, double seconds) {
        runFor(seconds, [&](TimePoint now) { events.tick(r, now); });
    }
    CreateEvent lastCreate() const { return *decodeCreateEvent(out.last(msg::CreateEvent)->payload); }
};

const JausId kSensor{126, 3, 2};
Bytes poseQuery() {
    return encodeQueryPv16(msg::QueryGlobalPose, 0x01FF);
}

} // namespace

class TestEventsClient : public QObject {
    Q_OBJECT

private slots:
    void confirmedEventIsNotPolled() {
        EventsRig rig;
        RemoteSubsystem& r = rig.vehicle();
        rig.events.subscribe(r, kSensor, poseQuery(), 10);
        QCOMPARE(rig.events.state(126, msg::QueryGlobalPose), std::optional<SubState>(SubState::None));
        rig.run(r, 0.01);
        QCOMPARE(rig.out.count(msg::CreateEvent), 1);
        const CreateEvent ce = rig.lastCreate();
        QCOMPARE(rig.out.last(msg::CreateEvent)->destination, kSensor);
        QCOMPARE(ce.type, EventType::Periodic);
        QVERIFY(std::abs(ce.rateHz - 10) < 0.02);
        QCOMPARE(ce.queryMessage, poseQuery());
        QCOMPARE(rig.events.state(126, msg::QueryGlobalPose), std::optional<SubState>(SubState::Pending));
        QVERIFY(rig.deliver(r, encode(ConfirmEventRequest{ce.requestId, 7, 10.0}), kSensor));
        QCOMPARE(rig.events.state(126, msg::QueryGlobalPose), std::optional<SubState>(SubState::Active));
        rig.run(r, 5);
        QCOMPARE(rig.out.count(msg::QueryGlobalPose), 0);
        QCOMPARE(rig.out.count(msg::CreateEvent), 1);
        // A confirmation for another request changes nothing.
        QVERIFY(rig.deliver(r, encode(ConfirmEventRequest{std::uint8_t(ce.requestId + 1), 8, 1.0}), kSensor));
        QCOMPARE(rig.events.state(126, msg::QueryGlobalPose), std::optional<SubState>(SubState::Active));
    }

    void unconfirmedFallsBackToPolling() {
        EventsRig rig; // event_confirm_timeout_s 2
        RemoteSubsystem& r = rig.vehicle();
        rig.events.subscribe(r, kSensor, poseQuery(), 10);
        rig.run(r, 2.0);
        QCOMPARE(rig.events.state(126, msg::QueryGlobalPose), std::optional<SubState>(SubState::Pending));
        rig.run(r, 0.05);
        QCOMPARE(rig.events.state(126, msg::QueryGlobalPose), std::optional<SubState>(SubState::Polling));
        QCOMPARE(rig.counters.get("events.fallback.timeout"), std::uint64_t(1));
        const int before = rig.out.count(msg::QueryGlobalPose);
        rig.run(r, 2.0);
        QCOMPARE(rig.out.count(msg::QueryGlobalPose) - before, 20); // 10 Hz
        QCOMPARE(rig.out.last(msg::QueryGlobalPose)->payload, poseQuery());
    }

    void rejectedFallsBackToPolling() {
        EventsRig rig;
        RemoteSubsystem& r = rig.vehicle();
        rig.events.subscribe(r, kSensor, poseQuery(), 5);
        rig.run(r, 0.01);
        RejectEventRequest rej;
        rej.requestId = rig.lastCreate().requestId;
        rej.responseCode = 1;
        QVERIFY(rig.deliver(r, encode(rej), kSensor));
        QCOMPARE(rig.events.state(126, msg::QueryGlobalPose), std::optional<SubState>(SubState::Polling));
        QCOMPARE(rig.counters.get("events.fallback.rejected"), std::uint64_t(1));
        rig.run(r, 2.0);
        QCOMPARE(rig.out.count(msg::QueryGlobalPose), 10); // 5 Hz
    }

    void confirmedTooSlowIsCancelledAndPolled() {
        EventsRig rig;
        RemoteSubsystem& r = rig.vehicle();
        rig.events.subscribe(r, kSensor, poseQuery(), 10);
        rig.run(r, 0.01);
        const std::uint8_t req = rig.lastCreate().requestId;
        QVERIFY(rig.deliver(r, encode(ConfirmEventRequest{req, 9, 2.0}), kSensor));
        QCOMPARE(rig.events.state(126, msg::QueryGlobalPose), std::optional<SubState>(SubState::Polling));
        QCOMPARE(rig.counters.get("events.fallback.rate"), std::uint64_t(1));
        auto cancel = decodeCancelEvent(rig.out.last(msg::CancelEvent)->payload);
        QVERIFY(cancel && cancel->requestId == req && cancel->eventId == 9);
        // Above half the rate is accepted.
        EventsRig half;
        RemoteSubsystem& h = half.vehicle();
        half.events.subscribe(h, kSensor, poseQuery(), 10);
        half.run(h, 0.01);
        QVERIFY(half.deliver(h, encode(ConfirmEventRequest{half.lastCreate().requestId, 1, 6.0}), kSensor));
        QCOMPARE(half.events.state(126, msg::QueryGlobalPose), std::optional<SubState>(SubState::Active));
    }

    void onChangeEventsAskForRateZero() {
        EventsRig rig;
        RemoteSubsystem& r = rig.vehicle();
        rig.events.subscribe(r, ClientRig::mobility(), encodeEmpty(msg::QueryStatus), 1,
                             EventType::EveryChange);
        rig.run(r, 0.01);
        const CreateEvent ce = rig.lastCreate();
        QCOMPARE(ce.type, EventType::EveryChange);
        QCOMPARE(ce.rateHz, 0.0);
        // A slow confirmation does not matter for an on-change event.
        QVERIFY(rig.deliver(r, encode(ConfirmEventRequest{ce.requestId, 3, 0.0})));
        QCOMPARE(rig.events.state(126, msg::QueryStatus), std::optional<SubState>(SubState::Active));
    }

    void recreatedWhenTheLinkReturnsAndSilentWhileDown() {
        EventsRig rig;
        RemoteSubsystem& r = rig.vehicle();
        rig.events.subscribe(r, kSensor, poseQuery(), 10);
        rig.run(r, 0.01);
        const std::uint8_t first = rig.lastCreate().requestId;
        QVERIFY(rig.deliver(r, encode(ConfirmEventRequest{first, 1, 10.0}), kSensor));
        r.snap.link = LinkState::Down;
        rig.events.onLinkRestored(r);
        rig.run(r, 3);
        QCOMPARE(rig.out.count(msg::CreateEvent), 1); // nothing goes to a vehicle that is down
        r.snap.link = LinkState::Up;
        rig.run(r, 0.01);
        QCOMPARE(rig.out.count(msg::CreateEvent), 2);
        QVERIFY(rig.lastCreate().requestId != first); // a fresh request ID
    }

    void eventsCarryReportsToTheirClient() {
        EventsRig rig;
        RemoteSubsystem& r = rig.vehicle();
        GlobalPose g;
        g.lat = 48.1;
        g.lon = 11.5;
        QVERIFY(rig.deliver(r, encode(EventMsg{1, 0, encode(g)}), kSensor));
        QCOMPARE(rig.poses.size(), std::size_t(1));
        QVERIFY(std::abs(*rig.poses[0].lat - 48.1) < 1e-6);
        QVERIFY(rig.deliver(r, encode(EventMsg{1, 1, encodeEmpty(msg::ReportWrenchEffort)}), kSensor));
        QCOMPARE(rig.counters.get("rx.unhandled"), std::uint64_t(1));
        QVERIFY(rig.deliver(r, encode(EventMsg{1, 2, encode(EventMsg{1, 0, encode(g)})}), kSensor));
        QCOMPARE(rig.counters.get("rx.rejected.nested"), std::uint64_t(1));
        QCOMPARE(rig.poses.size(), std::size_t(1));
    }

    void createEventToTheConsoleIsRejected() {
        EventsRig rig;
        const JausId asker{77, 1, 1};
        const Bytes ce =
            encode(CreateEvent{42, EventType::Periodic, 1.0, encodeEmpty(msg::QueryHeartbeatPulse)});
        // Answered, but not "only a question": from a vehicle it still counts as a sign of life.
        QVERIFY(!rig.table.answer(msg::CreateEvent, asker, ce));
        QCOMPARE(rig.out.sent.size(), std::size_t(1));
        QCOMPARE(rig.out.sent[0].destination, asker);
        auto rej = decodeRejectEventRequest(rig.out.sent[0].payload);
        QVERIFY(rej && rej->requestId == 42 && rej->responseCode == std::optional<std::uint8_t>(5));
    }

    void oneClientPerMessage() {
        // The dispatch table refuses a second handler for an ID: a report inside an Event has one owner.
        EventsRig rig;
        QVERIFY_THROWS_EXCEPTION(
            std::logic_error,
            rig.table.onVehicleMessage(msg::Event, [](RemoteSubsystem&, const JausId&, ByteSpan) {}));
        QVERIFY_THROWS_EXCEPTION(
            std::logic_error,
            rig.table.onRequest(msg::CreateEvent, [](const JausId&, ByteSpan) { return true; }));
        QVERIFY(!rig.table.answer(msg::QueryIdentification, JausId{77, 1, 1}, encode(QueryIdentification{})));
        QVERIFY(rig.out.sent.empty());
    }

    // Services learnt in parts call subscribe again with the same subscription: it is kept (one CreateEvent,
    // its state untouched); a changed one replaces it.
    void sameSubscriptionIsKept() {
        EventsRig rig;
        RemoteSubsystem& r = rig.vehicle();
        rig.events.subscribe(r, kSensor, poseQuery(), 10);
        rig.run(r, 0.01);
        QCOMPARE(rig.out.count(msg::CreateEvent), 1);
        rig.events.subscribe(r, kSensor, poseQuery(), 10);
        rig.run(r, 0.5);
        QCOMPARE(rig.out.count(msg::CreateEvent), 1);
        rig.events.subscribe(r, kSensor, poseQuery(), 5);
        rig.run(r, 0.01);
        QCOMPARE(rig.out.count(msg::CreateEvent), 2);
    }

    void requestIdsNeverZero() {
        EventsRig rig;
        RemoteSubsystem& r = rig.vehicle();
        std::set<int> seen;
        for (int i = 0; i < 300; ++i) {
            // A changed rate each time: a new subscription, so a new CreateEvent with the next request ID.
            rig.events.subscribe(r, kSensor, poseQuery(), 10 + i % 2);
            rig.run(r, 0.01);
            seen.insert(rig.lastCreate().requestId);
        }
        QVERIFY(!seen.count(0));
        QCOMPARE(seen.size(), std::size_t(255));
    }
};

QTEST_GUILESS_MAIN(TestEventsClient)
#include "test_events_client.moc"
