// JausCore whole (every client composed) on a FakeClock, with the vehicle played message by message:
// the JSS inheritance table, the stop rule for the monitor, targets found by inheritance, status polling
// without events, Reject-then-Confirm and the controller field, static endpoints and the link-down probe.
#include <QtTest>

#include <algorithm>

#include "protocols/jaus/JausCore.h"
#include "protocols/jaus/ServiceInheritance.h"

using namespace ocu;
using namespace ocu::jaus;

namespace {

constexpr std::string_view LWLD = "urn:jaus:jss:mobility:LocalWaypointListDriver";

// The table is constexpr: the chains are checked at compile time too.
static_assert(inheritsFrom(LWLD, service::ListManager));
static_assert(inheritsFrom(LWLD, service::Management));
static_assert(inheritsFrom(LWLD, service::AccessControl));
static_assert(inheritsFrom(LWLD, service::Transport));
static_assert(inheritsFrom(service::LocalPoseSensor, service::AccessControl));
static_assert(!inheritsFrom(service::LocalPoseSensor, service::Management));
static_assert(!inheritsFrom(service::VelocityStateSensor, service::AccessControl));

struct Sent {
    JausId destination;
    Bytes payload;
    SendOptions options;
    TimePoint at;
    std::uint16_t id() const { return peekMessageId(payload); }
};

struct Capture : JausOutput {
    const Clock* clock = nullptr;
    std::vector<Sent> sent;
    void send(const JausId& d, const Bytes& p, SendOptions o) override {
        sent.push_back({d, p, o, clock->now()});
    }
    std::string sendOrWhy(const JausId& d, const Bytes& p, SendOptions o) override {
        send(d, p, o); // the captured "socket" takes everything
        return {};
    }
    int count(std::uint16_t id, JausId to = {}) const {
        return int(std::count_if(sent.begin(), sent.end(), [&](const Sent& s) {
            return s.id() == id && (to.subsystem == 0 || s.destination == to);
        }));
    }
    std::vector<TimePoint> times(std::uint16_t id) const {
        std::vector<TimePoint> out;
        for (auto& s : sent)
            if (s.id() == id)
                out.push_back(s.at);
        return out;
    }
};

struct Listener : JausListener {
    JausId self;
    bool sawSelfAsOther = false; // our ID as controller while not controlled by us
    std::vector<JausEvent> events;
    void onSubsystemChanged(const SubsystemSnapshot& s) override {
        if (!s.controlledByUs && s.controller == self)
            sawSelfAsOther = true;
    }
    void onEvent(const JausEvent& e) override { events.push_back(e); }
    int count(EventKind k) const {
        return int(
            std::count_if(events.begin(), events.end(), [&](const JausEvent& e) { return e.kind == k; }));
    }
};

JausConfig config(Role role = Role::PrimaryOperator, std::uint8_t authority = 205) {
    JausConfig c;
    c.subsystemId = 200;
    c.role = role;
    c.authority = authority;
    c.statusPollHz = 1;
    c.accessTimeoutS = 5;
    c.linkLostS = 3;
    c.discoveryIntervalS = 30;
    return c;
}

const JausId kVehicle{126, 1, 1};

struct Rig {
    FakeClock clock;
    Counters counters;
    Capture out;
    Listener listener;
    JausCore core;
    explicit Rig(JausConfig c = config()) : core(c, listener, out, clock, counters) {
        out.clock = &clock;
        listener.self = c.ownId();
    }
    void fromVehicle(const Bytes& payload, JausId from = kVehicle) {
        core.handle(from, core.config().ownId(), payload);
    }
    void run(double seconds) {
        for (int i = 0; i < int(seconds * 100 + 0.5); ++i) {
            clock.advance(std::chrono::milliseconds(10));
            core.tick();
        }
    }
    // A vehicle (one component 126.1.1) that identifies itself and lists exactly `services`.
    void discover(std::vector<std::string> services) {
        core.tick();
        fromVehicle(encode(ReportIdentification{IdQueryType::Subsystem, IdType::Vehicle, "FOREIGN-126"}));
        ComponentServices c{1, 0, {}};
        for (auto& s : services)
            c.services.push_back(ServiceRecord{s, 1, 1});
        fromVehicle(encode(ReportServices{{NodeServices{1, {c}}}}));
    }
};

} // namespace

class TestJausCoreRules : public QObject {
    Q_OBJECT

private slots:
    void inheritanceTable() {
        QVERIFY(offers({{std::string(LWLD), 1, 1}}, service::Management));
        QVERIFY(offers({{std::string(service::LocalPoseSensor), 1, 1}}, service::AccessControl));
        QVERIFY(!offers({{std::string(service::LocalPoseSensor), 1, 1},
                         {std::string(service::VelocityStateSensor), 1, 1}},
                        service::Management));
        QVERIFY(offers({{"urn:jaus:jss:mobility:ListManager", 1, 0}}, service::Management)); // 1.0 namespace
        QVERIFY(
            offers({{"urn:jaus:jss:environmentSensing:H264VideoEncoding", 2, 0}}, service::AccessControl));
        QVERIFY(!offers({{"urn:jaus:jss:iop:PathReporter", 1, 1}}, service::AccessControl));
        QVERIFY(!offers({{"urn:example:Unknown", 1, 0}}, service::Events)); // unknown: only itself
        QVERIFY(offers({{"urn:example:Unknown", 1, 0}}, "urn:example:Unknown"));
        // Every parent named in the table is itself in the table (no broken chain).
        for (const ServiceParent& p : kServiceParents)
            if (!p.parent.empty())
                QVERIFY2(std::any_of(kServiceParents.begin(), kServiceParents.end(),
                                     [&](const ServiceParent& q) { return q.uri == p.parent; }),
                         std::string(p.parent).c_str());
    }

    // §2: the monitor puts SetEmergency on the wire for a vehicle it does not control, to the component that
    // offers Management by inheritance, at safety priority; its ClearEmergency is refused with a reason.
    void monitorStopsAVehicleItDoesNotControl() {
        Rig rig(config(Role::Monitor, 0));
        rig.discover({std::string(service::LocalPoseSensor), std::string(LWLD)});
        QVERIFY(!rig.core.snapshot(126)->controlledByUs);
        const auto outcomes = rig.core.setEmergencyAll(EmergencyCode::Stop);
        QCOMPARE(outcomes.size(), std::size_t(1));
        QCOMPARE(outcomes[0].target, std::string("jaus:126"));
        QVERIFY(outcomes[0].sent);
        QCOMPARE(rig.out.count(msg::SetEmergency, kVehicle), 1);
        auto se = std::find_if(rig.out.sent.begin(), rig.out.sent.end(),
                               [](auto& s) { return s.id() == msg::SetEmergency; });
        QCOMPARE(se->options.priority, Priority::Safety);
        QCOMPARE(*decodeU16(se->payload, msg::SetEmergency), std::uint16_t(EmergencyCode::Stop));
        rig.fromVehicle(encode(ReportStatus{ManagementState::Emergency, 0}));
        QVERIFY(rig.core.snapshot(126)->emergency);

        const bool cleared = rig.core.clearEmergency(126);
        const TargetOutcome o = rig.core.outcome(126, cleared);
        QVERIFY(!o.sent);
        QVERIFY2(o.reason.find("may stop but not clear") != std::string::npos, o.reason.c_str());
        QCOMPARE(rig.out.count(msg::ClearEmergency), 0);
        QVERIFY(rig.core.config().mayStop());
        QVERIFY(!rig.core.config().mayClearStop());
    }

    // §3: a vehicle listing only derived services: control, emergency and status polling go to its component;
    // a sensors-only one takes control but the stop is refused with a reason naming the missing service.
    void targetsFoundByInheritance() {
        Rig rig;
        rig.discover({std::string(service::LocalPoseSensor), std::string(LWLD)});
        QVERIFY(rig.core.requestControl(126));
        QCOMPARE(rig.out.count(msg::RequestControl, kVehicle), 1);
        QVERIFY(rig.core.setEmergency(126));
        QCOMPARE(rig.out.count(msg::SetEmergency, kVehicle), 1);
        rig.out.sent.clear();
        rig.run(3.0);
        QVERIFY(rig.out.count(msg::QueryStatus, kVehicle) >= 3);

        Rig sensors;
        sensors.discover({std::string(service::LocalPoseSensor), std::string(service::VelocityStateSensor)});
        QVERIFY(sensors.core.requestControl(126));
        QCOMPARE(sensors.out.count(msg::RequestControl, kVehicle), 1);
        const TargetOutcome o = sensors.core.outcome(126, sensors.core.setEmergency(126));
        QVERIFY(!o.sent);
        QCOMPARE(o.reason,
                 std::string("no component of subsystem 126 offers Management (directly or by inheritance)"));
        QCOMPARE(sensors.out.count(msg::SetEmergency), 0);

        Rig unknown;
        const TargetOutcome u = unknown.core.outcome(127, unknown.core.requestControl(127));
        QVERIFY(!u.sent);
        QVERIFY2(u.reason.find("has not been discovered") != std::string::npos, u.reason.c_str());
    }

    // §4: without events the status is polled at status_poll_hz, so an emergency set by anyone shows within
    // one poll period plus the round trip.
    void statusPolledWithinOnePeriodWithoutEvents() {
        JausConfig c = config();
        c.linkLostS = 20; // a quiet vehicle stays up for the whole run
        Rig rig(c);
        rig.discover({std::string(LWLD)});
        rig.run(6);
        const auto t = rig.out.times(msg::QueryStatus);
        QVERIFY(t.size() >= 5);
        for (std::size_t i = 1; i < t.size(); ++i)
            QVERIFY(t[i] - t[i - 1] <= std::chrono::milliseconds(1010));
        QVERIFY(rig.out.count(msg::QueryControl, kVehicle) >= 5);
    }

    // §4: RejectControl then ConfirmControl(accepted) to the same request is accepted and kept; a
    // RejectControl alone counts after the grace; our own ID is never shown as another controller.
    void rejectThenConfirmAccepted() {
        Rig rig;
        rig.discover({std::string(LWLD)});
        QVERIFY(rig.core.requestControl(126));
        rig.fromVehicle(encodeU8(msg::RejectControl, 0));
        rig.fromVehicle(encodeU8(msg::ConfirmControl, 0));
        QVERIFY(rig.core.snapshot(126)->controlledByUs);
        rig.run(4);
        QVERIFY(rig.core.snapshot(126)->controlledByUs);
        QCOMPARE(rig.out.count(msg::ReleaseControl), 0);
        QCOMPARE(rig.listener.count(EventKind::ControlRejected), 0);

        Rig alone;
        alone.discover({std::string(LWLD)});
        QVERIFY(alone.core.requestControl(126));
        alone.fromVehicle(encodeU8(msg::RejectControl, 1));
        QCOMPARE(alone.listener.count(EventKind::ControlRejected), 0); // not yet: a Confirm may follow
        alone.run(2);
        QCOMPARE(alone.listener.count(EventKind::ControlRejected), 1);
        QCOMPARE(alone.core.snapshot(126)->access, AccessState::NotAvailable);
    }

    void ownIdNeverShownAsOtherController() {
        Rig rig;
        rig.discover({std::string(LWLD)});
        QVERIFY(rig.core.requestControl(126));
        rig.fromVehicle(encodeU8(msg::ConfirmControl, 0));
        QVERIFY(rig.core.snapshot(126)->controlledByUs);
        QVERIFY(rig.core.releaseControl(126));
        rig.fromVehicle(encodeU8(msg::RejectControl, 0)); // CONTROL_RELEASED
        QVERIFY(!rig.core.snapshot(126)->controlledByUs);
        QVERIFY(!(rig.core.snapshot(126)->controller == rig.core.config().ownId()));
        // A ReportControl naming us that left the vehicle before our release arrived: stale, not "in
        // control".
        rig.fromVehicle(encode(ReportControl{rig.core.config().ownId(), 205}));
        QVERIFY(!rig.core.snapshot(126)->controlledByUs);
        QCOMPARE(rig.out.count(msg::ReleaseControl), 1);
        // A peer that answers a release with nothing: released when its access timeout has passed.
        QVERIFY(rig.core.requestControl(126));
        rig.fromVehicle(encodeU8(msg::ConfirmControl, 0));
        QVERIFY(rig.core.releaseControl(126));
        rig.run(6);
        QVERIFY(!rig.core.snapshot(126)->controlledByUs);
        QVERIFY(!rig.listener.sawSelfAsOther);
    }

    // §4: a peer that never tells the old controller: the re-request (every 40 % of the access timeout) is
    // answered INSUFFICIENT_AUTHORITY and the console shows pre-emption within the access timeout.
    void preemptionLearntFromReRequest() {
        Rig rig;
        rig.discover({std::string(LWLD)});
        QVERIFY(rig.core.requestControl(126));
        rig.fromVehicle(encodeU8(msg::ConfirmControl, 0));
        const int before = rig.out.count(msg::RequestControl);
        rig.run(rig.core.config().accessTimeoutS * 0.5);
        QVERIFY(rig.out.count(msg::RequestControl) > before); // re-requested inside the timeout
        rig.fromVehicle(encodeU8(msg::ConfirmControl, 2));
        QVERIFY(!rig.core.snapshot(126)->controlledByUs);
        QCOMPARE(rig.core.snapshot(126)->access, AccessState::Preempted);
        QVERIFY(!rig.listener.sawSelfAsOther);
    }

    // §5: static endpoints get a unicast QueryIdentification at start and every discovery interval.
    void staticEndpointsQueriedEveryInterval() {
        JausConfig c = config();
        c.transport.staticEndpoints.push_back(
            StaticEndpoint{JausId{130, 0xFF, 0xFF}, "192.0.2.30", 3794, false});
        Rig rig(c);
        rig.core.tick();
        QCOMPARE(rig.out.count(msg::QueryIdentification, JausId{130, 0xFF, 0xFF}), 1);
        rig.run(c.discoveryIntervalS + 0.1);
        QCOMPARE(rig.out.count(msg::QueryIdentification, JausId{130, 0xFF, 0xFF}), 2);
    }

    // §5: a subsystem whose link is down is probed at 1 Hz at its platform manager (its last address).
    void linkDownProbedAtOneHertz() {
        Rig rig;
        rig.discover({std::string(LWLD)});
        rig.run(rig.core.config().linkLostS + 0.1);
        QCOMPARE(rig.core.snapshot(126)->link, LinkState::Down);
        rig.out.sent.clear();
        rig.run(5);
        const int probes = rig.out.count(msg::QueryIdentification, kVehicle);
        QVERIFY2(probes >= 4 && probes <= 6, std::to_string(probes).c_str());
        rig.fromVehicle(encode(ReportIdentification{IdQueryType::Subsystem, IdType::Vehicle, "FOREIGN-126"}));
        QCOMPARE(rig.core.snapshot(126)->link, LinkState::Up);
        QCOMPARE(rig.listener.count(EventKind::LinkRestored), 1);
    }
};

QTEST_GUILESS_MAIN(TestJausCoreRules)
#include "test_jaus_core_rules.moc"
