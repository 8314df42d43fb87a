// The OCU client services (JausCore) against the simulated UGV's services (UgvCore), connected by an
// in-memory bus and driven by a FakeClock: access control (kept while re-requests flow, lost after the
// timeout, pre-empted by a higher authority, refused below the default authority, never requested with
// authority 0), discovery, events with polling fallback, management/emergency, driving, drive timeout.
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <deque>

#include "protocols/jaus/JausCore.h"
#include "sim/jaus/UgvCore.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::sim;

namespace {

struct Packet {
    JausId src, dst;
    Bytes payload;
};

// Every party sees every packet (like one multicast LAN); each filters by destination.
struct Bus {
    std::deque<Packet> queue;
    std::vector<std::function<void(const Packet&)>> parties;
    bool dropAll = false;
    std::function<bool(const Packet&)> filter; // true = drop
    void pump() {
        for (int guard = 0; !queue.empty() && guard < 100000; ++guard) {
            Packet p = std::move(queue.front());
            queue.pop_front();
            if (dropAll || (filter && filter(p)))
                continue;
            for (auto& f : parties)
                f(p);
        }
    }
};

struct Port : JausOutput {
    Bus& bus;
    JausId self;
    std::vector<Packet>* log = nullptr;
    Port(Bus& b, JausId s) : bus(b), self(s) {}
    void send(const JausId& dst, const Bytes& payload, SendOptions) override {
        sendFrom(self, dst, payload, {});
    }
    std::string sendOrWhy(const JausId& dst, const Bytes& payload, SendOptions) override {
        sendFrom(self, dst, payload, {}); // the in-memory bus takes everything
        return {};
    }
    void sendFrom(const JausId& src, const JausId& dst, const Bytes& payload, SendOptions) override {
        Packet p{src, dst, payload};
        if (log)
            log->push_back(p);
        bus.queue.push_back(std::move(p));
    }
};

struct Recorder : JausListener {
    std::vector<JausEvent> events;
    int changes = 0;
    void onSubsystemChanged(const SubsystemSnapshot&) override { ++changes; }
    void onEvent(const JausEvent& e) override { events.push_back(e); }
    int count(EventKind k) const {
        return int(
            std::count_if(events.begin(), events.end(), [&](const JausEvent& e) { return e.kind == k; }));
    }
};

JausConfig ocuConfig(std::uint16_t ss, std::uint8_t authority) {
    JausConfig c;
    c.subsystemId = ss;
    c.callSign = "OCU-" + std::to_string(ss);
    c.authority = authority;
    c.role = authority == 0 ? Role::Monitor : Role::PrimaryOperator;
    return c;
}

// One OCU (or two) and one UGV on a bus, stepped in 10 ms increments of a FakeClock.
struct World {
    FakeClock clock;
    Bus bus;
    Counters ocuCounters, ocu2Counters, ugvCounters;
    Recorder rec, rec2;
    std::vector<Packet> ocuSent;
    std::unique_ptr<Port> ocuPort, ocu2Port, ugvPort;
    std::unique_ptr<JausCore> ocu, ocu2;
    std::unique_ptr<UgvCore> ugv;
    bool ocuSilent = false;

    // The drive-command watchdog is off unless a test asks for it: most tests set a demand once and let it
    // stream.
    explicit World(std::uint8_t authority = 205, SimulatedUgvConfig ucfg = {}, double driveWatchdogS = 0) {
        auto cfg = ocuConfig(200, authority);
        cfg.driveCommandTimeoutS = driveWatchdogS;
        ocuPort = std::make_unique<Port>(bus, cfg.ownId());
        ocuPort->log = &ocuSent;
        ocu = std::make_unique<JausCore>(cfg, rec, *ocuPort, clock, ocuCounters);
        ugvPort = std::make_unique<Port>(bus, JausId{ucfg.subsystemId, 1, 1});
        ugv = std::make_unique<UgvCore>(ucfg, *ugvPort, clock, ugvCounters);
        bus.parties.push_back([this](const Packet& p) {
            if (!ocuSilent)
                ocu->handle(p.src, p.dst, p.payload);
        });
        bus.parties.push_back([this](const Packet& p) { ugv->handle(p.src, p.dst, p.payload); });
    }
    void addSecondOcu(std::uint8_t authority) {
        auto cfg = ocuConfig(201, authority);
        ocu2Port = std::make_unique<Port>(bus, cfg.ownId());
        ocu2 = std::make_unique<JausCore>(cfg, rec2, *ocu2Port, clock, ocu2Counters);
        bus.parties.push_back([this](const Packet& p) { ocu2->handle(p.src, p.dst, p.payload); });
    }
    void step(Duration d = std::chrono::milliseconds(10)) {
        clock.advance(d);
        if (!ocuSilent)
            ocu->tick();
        if (ocu2)
            ocu2->tick();
        ugv->tick();
        bus.pump();
    }
    void run(double seconds) {
        const int n = int(std::lround(seconds * 100));
        for (int i = 0; i < n; ++i)
            step();
    }
    template <class Pred> bool runUntil(Pred p, double maxSeconds) {
        for (int i = 0; i < int(maxSeconds * 100); ++i) {
            if (p())
                return true;
            step();
        }
        return p();
    }
    SubsystemSnapshot snap(std::uint16_t ss = 126) const {
        return ocu->snapshot(ss).value_or(SubsystemSnapshot{});
    }
    int sentCount(std::uint16_t id) const {
        return int(std::count_if(ocuSent.begin(), ocuSent.end(),
                                 [&](const Packet& p) { return peekMessageId(p.payload) == id; }));
    }
};

} // namespace

class TestJausServices : public QObject {
    Q_OBJECT

private slots:
    void discoveryFindsCallSignAndServices() {
        World w;
        QVERIFY(w.runUntil([&] { return w.snap().callSign == "UGV-126"; }, 3));
        QVERIFY(w.runUntil([&] { return w.snap().mobilityComponent == (JausId{126, 3, 1}); }, 3));
        QCOMPARE(w.rec.count(EventKind::Discovered), 1);
        auto s = w.snap();
        QCOMPARE(s.services.size(), std::size_t(2));
        QVERIFY(w.runUntil([&] { return w.snap().platform.has_value(); }, 3));
        QCOMPARE(w.snap().platform->name, std::string("OCU-SIM SkidSteer"));
        // Events confirmed: pose arrives without polling.
        QVERIFY(
            w.runUntil([&] { return w.snap().globalPose.has_value() && w.snap().localPose.has_value(); }, 3));
        QCOMPARE(w.ocuCounters.get("events.fallback.timeout"), std::uint64_t(0));
        QCOMPARE(w.ocuCounters.get("events.fallback.rejected"), std::uint64_t(0));
        QVERIFY(std::abs(*w.snap().globalPose->lat - 48.137154) < 1e-5);
        QCOMPARE(w.snap().link, LinkState::Up);
        QCOMPARE(w.snap().management, std::optional<ManagementState>(ManagementState::Standby));
        // Management state arrives by an on-change event: an emergency shows within one tick, not a 1 s poll.
        w.run(0.5);
        w.ugv->enterEmergency();
        w.step();
        w.step();
        QVERIFY(w.snap().emergency);
    }

    void controlKeptWhileReRequestsFlow() {
        World w;
        QVERIFY(w.runUntil([&] { return w.snap().mobilityComponent.subsystem != 0; }, 3));
        QVERIFY(w.ocu->requestControl(126));
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        QCOMPARE(w.snap().access, AccessState::ControlAccepted);
        QCOMPARE(w.snap().accessTimeoutS, std::uint8_t(5)); // read with QueryTimeout
        QCOMPARE(w.rec.count(EventKind::ControlAccepted), 1);
        const int before = w.sentCount(msg::RequestControl);
        w.run(20); // four times the access-control timeout
        QVERIFY(w.snap().controlledByUs);
        QCOMPARE(w.ugv->state().controller, (JausId{200, 1, 1}));
        // Re-requests at ≤ half the timeout: 20 s / 2 s = 10 at least.
        QVERIFY(w.sentCount(msg::RequestControl) - before >= 10);
        QCOMPARE(w.rec.count(EventKind::ControlLost), 0);
    }

    void controlLostAfterTimeoutWhenReRequestsStop() {
        World w;
        QVERIFY(w.runUntil([&] { return w.snap().mobilityComponent.subsystem != 0; }, 3));
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        w.ocuSilent = true; // the OCU stops talking (and listening)
        w.run(4.5);
        QCOMPARE(w.ugv->state().controller, (JausId{200, 1, 1})); // still inside the 5 s timeout
        w.run(1.0);
        QCOMPARE(w.ugv->state().controller, JausId{}); // released by the UGV
        // Back online, the OCU learns it lost control (RejectControl was missed: QueryControl / no confirm).
        w.ocuSilent = false;
        QVERIFY(w.runUntil([&] { return !w.snap().controlledByUs; }, 6));
        QVERIFY(w.snap().access == AccessState::Timeout || w.snap().access == AccessState::ControlAccepted ||
                w.snap().access == AccessState::ControlReleased);
    }

    void clientNoticesMissingConfirmations() {
        World w;
        QVERIFY(w.runUntil([&] { return w.snap().mobilityComponent.subsystem != 0; }, 3));
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        // The UGV stops answering: after the access-control timeout the OCU reports control lost.
        w.bus.filter = [](const Packet& p) { return p.src.subsystem == 126; };
        w.run(4);
        QVERIFY(w.snap().controlledByUs);
        w.run(1.5);
        QVERIFY(!w.snap().controlledByUs);
        QCOMPARE(w.snap().access, AccessState::Timeout);
        QCOMPARE(w.rec.count(EventKind::ControlLost), 1);
        QCOMPARE(w.snap().link, LinkState::Down);
        QVERIFY(w.rec.count(EventKind::LinkLost) == 1);
        w.bus.filter = nullptr;
        QVERIFY(w.runUntil([&] { return w.snap().link == LinkState::Up; }, 3));
        QCOMPARE(w.rec.count(EventKind::LinkRestored), 1);
    }

    void preemptedByHigherAuthority() {
        World w;
        w.addSecondOcu(230);
        QVERIFY(w.runUntil([&] { return w.snap().mobilityComponent.subsystem != 0; }, 3));
        QVERIFY(w.runUntil(
            [&] {
                return w.ocu2->snapshot(126).has_value() &&
                       w.ocu2->snapshot(126)->mobilityComponent.subsystem != 0;
            },
            3));
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        w.ocu2->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.ocu2->snapshot(126)->controlledByUs; }, 1));
        QVERIFY(w.runUntil([&] { return w.snap().access == AccessState::Preempted; }, 2));
        QVERIFY(!w.snap().controlledByUs);
        QCOMPARE(w.rec.count(EventKind::ControlPreempted), 1);
        QCOMPARE(w.snap().controller, (JausId{201, 1, 1}));
        QCOMPARE(w.ugv->state().controllerAuthority, std::uint8_t(230));
        // The other console answered our discovery as an OCU: it is not listed as a vehicle.
        QCOMPARE(w.ocu->subsystems(), std::vector<std::uint16_t>{126});
        QCOMPARE(w.ocu2->subsystems(), std::vector<std::uint16_t>{126});
        // The lower authority cannot take it back.
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().access == AccessState::InsufficientAuthority; }, 2));
        QVERIFY(w.ocu2->snapshot(126)->controlledByUs);
    }

    void equalAuthorityDoesNotPreempt() {
        World w;
        w.addSecondOcu(205);
        QVERIFY(w.runUntil(
            [&] {
                return w.snap().mobilityComponent.subsystem != 0 && w.ocu2->snapshot(126) &&
                       w.ocu2->snapshot(126)->mobilityComponent.subsystem != 0;
            },
            3));
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        w.ocu2->requestControl(126);
        QVERIFY(w.runUntil(
            [&] { return w.ocu2->snapshot(126)->access == AccessState::InsufficientAuthority; }, 2));
        QVERIFY(w.snap().controlledByUs);
        QCOMPARE(w.rec2.count(EventKind::ControlRejected), 1);
    }

    void refusedBelowDefaultAuthority() {
        World w(100); // below the Mobility-node default of 125
        QVERIFY(w.runUntil([&] { return w.snap().mobilityComponent.subsystem != 0; }, 3));
        QVERIFY(w.ocu->requestControl(126));
        QVERIFY(w.runUntil([&] { return w.snap().access == AccessState::InsufficientAuthority; }, 1));
        QVERIFY(!w.snap().controlledByUs);
        QCOMPARE(w.ugv->state().controller, JausId{});
        QCOMPARE(w.rec.count(EventKind::ControlRejected), 1);
        // No endless retry after a refusal.
        const int n = w.sentCount(msg::RequestControl);
        w.run(5);
        QCOMPARE(w.sentCount(msg::RequestControl), n);
    }

    void neverRequestedWithAuthorityZero() {
        World w(0); // MONITOR role
        QVERIFY(w.runUntil([&] { return w.snap().mobilityComponent.subsystem != 0; }, 3));
        QVERIFY(!w.ocu->requestControl(126));
        QVERIFY(!w.ocu->startDriving(126));
        QVERIFY(!w.ocu->resume(126));
        QVERIFY(!w.ocu->clearEmergency(126));
        w.run(3);
        QCOMPARE(w.sentCount(msg::RequestControl), 0);
        QCOMPARE(w.sentCount(msg::SetVelocityCommand), 0);
        QCOMPARE(w.sentCount(msg::Resume), 0);
        QCOMPARE(w.rec.count(EventKind::CommandRefused), 4);
        QCOMPARE(w.snap().access, AccessState::NotControlled); // ReportControl shows nobody
        // The monitor may still stop the vehicle.
        QVERIFY(w.ocu->setEmergency(126));
        QVERIFY(w.runUntil([&] { return w.snap().emergency; }, 1));
    }

    void releaseControlAndReleaseAll() {
        World w;
        QVERIFY(w.runUntil([&] { return w.snap().mobilityComponent.subsystem != 0; }, 3));
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        w.ocu->releaseAll();
        QVERIFY(w.runUntil([&] { return w.snap().access == AccessState::ControlReleased; }, 1));
        QCOMPARE(w.ugv->state().controller, JausId{});
        QCOMPARE(w.rec.count(EventKind::ControlReleased), 1);
        QCOMPARE(w.rec.count(EventKind::ControlLost), 0);
        const int n = w.sentCount(msg::RequestControl);
        w.run(5);
        QCOMPARE(w.sentCount(msg::RequestControl), n);
    }

    void driveForwardFiveMetres() {
        World w;
        QVERIFY(w.runUntil([&] { return w.snap().platform.has_value(); }, 3));
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        QVERIFY(w.ocu->startDriving(126)); // sends Resume
        QVERIFY(w.runUntil([&] { return w.snap().management == ManagementState::Ready; }, 1));
        DriveCommand c;
        c.linear = 1.0;
        // A console refreshes its demand continuously (teleop at the drive rate).
        for (int i = 0; i < 50; ++i) {
            QVERIFY(w.ocu->setDriveCommand(126, c));
            w.run(0.1);
        }
        QVERIFY(w.ocu->stopDriving(126));
        w.run(1.5);
        const double x = w.ugv->state().x;
        QVERIFY2(std::abs(x - 5.0) < 0.5, qPrintable(QString::number(x)));
        QVERIFY(std::abs(w.ugv->state().v) < 1e-9);
        // The reported local pose follows.
        QVERIFY(w.snap().localPose && std::abs(*w.snap().localPose->x - x) < 0.05);
        // Stop was several zero messages.
        int zeros = 0;
        for (auto& p : w.ocuSent)
            if (peekMessageId(p.payload) == msg::SetVelocityCommand) {
                auto v = decodeVelocityCommand(p.payload);
                if (v && std::abs(*v->vx) < 1e-6)
                    ++zeros;
            }
        QVERIFY(zeros >= 5);
        // Drive rate 20 Hz while streaming: about 100 commands in 5 s.
        QVERIFY(w.sentCount(msg::SetVelocityCommand) >= 95);
    }

    void staleDemandStreamsZero() {
        // A frozen console (demand set once, never refreshed) must not keep the vehicle moving.
        World w(205, {}, 0.5);
        QVERIFY(w.runUntil([&] { return w.snap().platform.has_value(); }, 3));
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        QVERIFY(w.ocu->startDriving(126));
        QVERIFY(w.runUntil([&] { return w.snap().management == ManagementState::Ready; }, 1));
        DriveCommand c;
        c.linear = 1.0;
        QVERIFY(w.ocu->setDriveCommand(126, c));
        w.run(0.4); // within the 0.5 s watchdog: the demand is streamed
        QVERIFY(w.ugv->state().v > 0.3);
        w.run(1.0);
        QCOMPARE(w.ugv->state().v, 0.0); // zero streamed after 0.5 s, not the 1 s drive timeout
        QVERIFY(!w.ugv->state().driveTimedOut);
        QVERIFY(w.snap().driving); // the session stays open, streaming zero
        bool warned = false;
        for (auto& e : w.rec.events)
            warned = warned || (e.kind == EventKind::CommandRefused &&
                                e.text.find("not refreshed") != std::string::npos);
        QVERIFY(warned);
        // A fresh demand drives again.
        QVERIFY(w.ocu->setDriveCommand(126, c));
        w.run(0.3);
        QVERIFY(w.ugv->state().v > 0.3);
    }

    void clampedToPlatformSpecification() {
        World w;
        QVERIFY(w.runUntil([&] { return w.snap().platform.has_value(); }, 3));
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        w.ocu->startDriving(126);
        DriveCommand c;
        c.linear = 50;  // far above max forward 2 m/s
        c.angular = -9; // above max yaw rate 1 rad/s
        w.ocu->setDriveCommand(126, c);
        w.run(0.2);
        auto last = std::find_if(w.ocuSent.rbegin(), w.ocuSent.rend(), [](const Packet& p) {
            return peekMessageId(p.payload) == msg::SetVelocityCommand;
        });
        QVERIFY(last != w.ocuSent.rend());
        auto v = decodeVelocityCommand(last->payload);
        QVERIFY(v && std::abs(*v->vx - 2.0) < 0.01 && std::abs(*v->yawRate + 1.0) < 0.01);
    }

    void wrenchEffortSkidSteerTurnsRight() {
        World w;
        QVERIFY(w.runUntil([&] { return w.snap().platform.has_value(); }, 3));
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        w.ocu->startDriving(126);
        DriveCommand c;
        c.mode = DriveCommand::Mode::Wrench;
        c.linear = 0;
        c.angular = 50; // + = right = clockwise: yaw increases
        w.ocu->setDriveCommand(126, c);
        w.run(1.0);
        QVERIFY(w.ugv->state().yaw > 0.2);
        QVERIFY2(std::abs(w.ugv->state().x) < 1e-6, qPrintable(QString::number(w.ugv->state().x))); // pivot
    }

    void ackermannCannotPivot() {
        SimulatedUgvConfig cfg;
        cfg.kinematics = Kinematics::Ackermann;
        World w(205, cfg);
        QVERIFY(w.runUntil([&] { return w.snap().platform.has_value(); }, 3));
        QCOMPARE(w.snap().platform->steeringType, std::uint8_t(1));
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        w.ocu->startDriving(126);
        DriveCommand c;
        c.angular = 1.0;
        w.ocu->setDriveCommand(126, c);
        w.run(1.0);
        QVERIFY(std::abs(w.ugv->state().yaw) < 1e-9);
        c.linear = 1.0;
        w.ocu->setDriveCommand(126, c);
        w.run(2.0);
        QVERIFY(w.ugv->state().yaw > 0.3);
        QVERIFY(std::abs(w.ugv->state().w) <= 1.0 / cfg.minTurnRadius + 1e-6);
    }

    void driveTimeoutStopsAndRecovers() {
        World w;
        QVERIFY(w.runUntil([&] { return w.snap().platform.has_value(); }, 3));
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        w.ocu->startDriving(126);
        DriveCommand c;
        c.linear = 1.0;
        w.ocu->setDriveCommand(126, c);
        w.run(2.0);
        QVERIFY(w.ugv->state().v > 0.9);
        // Drive commands stop reaching the UGV (everything else flows).
        w.bus.filter = [](const Packet& p) { return peekMessageId(p.payload) == msg::SetVelocityCommand; };
        w.run(0.9);
        QVERIFY(!w.ugv->state().driveTimedOut);
        w.run(0.3);
        QVERIFY(w.ugv->state().driveTimedOut);
        w.run(1.0);
        QVERIFY(std::abs(w.ugv->state().v) < 1e-9);
        // Commands again: still stopped during the 1 s recovery, moving after it.
        w.bus.filter = nullptr;
        w.run(0.5);
        QVERIFY(w.ugv->state().driveTimedOut);
        QVERIFY(std::abs(w.ugv->state().v) < 1e-9);
        w.run(1.0);
        QVERIFY(!w.ugv->state().driveTimedOut);
        w.run(1.0);
        QVERIFY(w.ugv->state().v > 0.9);
    }

    void emergencyStopsUntilCleared() {
        World w;
        QVERIFY(w.runUntil([&] { return w.snap().platform.has_value(); }, 3));
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        w.ocu->startDriving(126);
        DriveCommand c;
        c.linear = 1.0;
        w.ocu->setDriveCommand(126, c);
        w.run(2.0);
        QVERIFY(w.ugv->state().v > 0.9);
        QVERIFY(w.ocu->setEmergency(126)); // SAFETY = 2 by default
        auto setEm = std::find_if(w.ocuSent.rbegin(), w.ocuSent.rend(), [](const Packet& p) {
            return peekMessageId(p.payload) == msg::SetEmergency;
        });
        QCOMPARE(*decodeU16(setEm->payload, msg::SetEmergency), std::uint16_t(2));
        w.step();
        QCOMPARE(w.ugv->state().v, 0.0);
        QCOMPARE(w.ugv->state().management, ManagementState::Emergency);
        QVERIFY(w.runUntil([&] { return w.snap().emergency; }, 1));
        QCOMPARE(w.rec.count(EventKind::Emergency), 1);
        // Drive commands are refused by the console and would be ignored by the UGV.
        QVERIFY(!w.ocu->startDriving(126));
        const double x = w.ugv->state().x;
        w.run(3.0);
        QCOMPARE(w.ugv->state().x, x);
        QVERIFY(w.snap().controlledByUs); // an emergency does not cost the controller its control
        QVERIFY(w.ocu->clearEmergency(126));
        QVERIFY(w.runUntil([&] { return !w.snap().emergency; }, 2));
        QCOMPARE(w.rec.count(EventKind::EmergencyCleared), 1);
        QCOMPARE(w.ugv->state().management, ManagementState::Ready);
        QCOMPARE(w.ugv->state().x, x); // nothing moves until driving restarts
        // Health summary shows ERR while in emergency (polled every 5 s).
        w.ocu->setEmergency(126, EmergencyCode::Stop);
        QVERIFY(w.runUntil([&] { return w.snap().health && w.snap().health->severity == 3; }, 6));
        QVERIFY(w.rec.count(EventKind::HealthFault) >= 1);
    }

    void managementCommandsNeedControl() {
        World w;
        QVERIFY(w.runUntil([&] { return w.snap().mobilityComponent.subsystem != 0; }, 3));
        QVERIFY(!w.ocu->resume(126)); // refused by the console without control
        w.ocu->requestControl(126);
        QVERIFY(w.runUntil([&] { return w.snap().controlledByUs; }, 1));
        QVERIFY(w.ocu->resume(126));
        QVERIFY(w.runUntil([&] { return w.snap().management == ManagementState::Ready; }, 1));
        QVERIFY(w.ocu->standby(126));
        QVERIFY(w.runUntil([&] { return w.snap().management == ManagementState::Standby; }, 1));
        QVERIFY(w.ocu->shutdown(126));
        QVERIFY(w.runUntil([&] { return w.snap().management == ManagementState::Shutdown; }, 1));
        QVERIFY(w.ocu->reset(126));
        QVERIFY(w.runUntil([&] { return w.snap().management == ManagementState::Standby; }, 1));
    }

    void eventsRejectedFallBackToPolling() {
        SimulatedUgvConfig cfg;
        cfg.faults.rejectEvents = true;
        World w(205, cfg);
        QVERIFY(w.runUntil([&] { return w.snap().mobilityComponent.subsystem != 0; }, 3));
        QVERIFY(w.runUntil([&] { return w.ocuCounters.get("events.fallback.rejected") >= 4; }, 2));
        QVERIFY(w.runUntil([&] { return w.snap().globalPose.has_value(); }, 2));
        const int polls = w.sentCount(msg::QueryGlobalPose);
        w.run(2.0);
        QVERIFY(w.sentCount(msg::QueryGlobalPose) - polls >= 15); // 10 Hz polling
    }

    void eventsAtLowerRateFallBackToPolling() {
        SimulatedUgvConfig cfg;
        cfg.faults.eventRateScale = 0.2;
        World w(205, cfg);
        QVERIFY(w.runUntil([&] { return w.ocuCounters.get("events.fallback.rate") >= 3; }, 4));
        QVERIFY(w.runUntil([&] { return w.snap().velocity.has_value(); }, 2));
    }

    void heartbeatDropDegradesLink() {
        SimulatedUgvConfig cfg;
        World w(205, cfg);
        QVERIFY(w.runUntil([&] { return w.snap().mobilityComponent.subsystem != 0; }, 3));
        // Silence: the whole UGV disappears.
        w.bus.filter = [](const Packet& p) { return p.src.subsystem == 126; };
        w.run(3);
        QCOMPARE(w.snap().link, LinkState::Degraded);
        w.run(2.5);
        QCOMPARE(w.snap().link, LinkState::Down);
        QCOMPARE(w.rec.count(EventKind::LinkLost), 1);
    }

    void ocuAnswersAsSubsystem() {
        World w;
        Bus& bus = w.bus;
        std::vector<Packet> got;
        bus.parties.push_back([&](const Packet& p) {
            if (p.dst == (JausId{77, 1, 1}))
                got.push_back(p);
        });
        const JausId asker{77, 1, 1};
        bus.queue.push_back({asker, JausId{200, 1, 1}, encode(QueryIdentification{IdQueryType::Subsystem})});
        bus.queue.push_back({asker, JausId{200, 1, 1}, encode(QueryServices{})});
        bus.queue.push_back({asker, JausId{200, 1, 1}, encodeEmpty(msg::QueryHeartbeatPulse)});
        bus.pump();
        QCOMPARE(got.size(), std::size_t(3));
        auto ri = decodeReportIdentification(got[0].payload);
        QVERIFY(ri && ri->identification == "OCU-200" && ri->type == IdType::Ocu);
        auto rs = decodeReportServices(got[1].payload);
        QVERIFY(rs && rs->nodes.size() == 1 && rs->nodes[0].components[0].services.size() >= 3);
        QCOMPARE(peekMessageId(got[2].payload), msg::ReportHeartbeatPulse);
    }
    // The UGV's message table routes each message to the component whose service handles it: every other
    // (component, message) pair is ignored, as the services listed in ReportServices say.
    void messagesReachOnlyTheComponentsServingThem() {
        World w;
        const JausId pm{126, 1, 1}, mob{126, 3, 1}, sen{126, 3, 2};
        const std::vector<std::uint16_t> everywhere{msg::QueryHeartbeatPulse, msg::CreateEvent,
                                                    msg::UpdateEvent, msg::CancelEvent, msg::QueryEvents};
        const std::vector<std::uint16_t> atPm{msg::QueryIdentification, msg::QueryServices,
                                              msg::QueryServiceList,    msg::QuerySubsystemList,
                                              msg::RegisterServices,    msg::QueryHealthSummary,
                                              msg::UpdateHealthSummary};
        const std::vector<std::uint16_t> atMobility{msg::RequestControl,
                                                    msg::ReleaseControl,
                                                    msg::QueryControl,
                                                    msg::QueryAuthority,
                                                    msg::SetAuthority,
                                                    msg::QueryTimeout,
                                                    msg::QueryStatus,
                                                    msg::Shutdown,
                                                    msg::Standby,
                                                    msg::Resume,
                                                    msg::Reset,
                                                    msg::SetEmergency,
                                                    msg::ClearEmergency,
                                                    msg::SetWrenchEffort,
                                                    msg::QueryWrenchEffort,
                                                    msg::SetVelocityCommand,
                                                    msg::QueryVelocityCommand,
                                                    msg::QueryPlatformSpecifications};
        const std::vector<std::uint16_t> atSensors{msg::QueryGlobalPose, msg::QueryLocalPose,
                                                   msg::QueryVelocityState};
        const std::vector<std::uint16_t> nowhere{msg::ReportStatus, msg::ReportControl, msg::ConfirmControl,
                                                 msg::ReportGlobalPose};
        auto served = [&](const JausId& c, std::uint16_t id) {
            auto in = [id](const std::vector<std::uint16_t>& v) {
                return std::find(v.begin(), v.end(), id) != v.end();
            };
            return in(everywhere) || (c == pm && in(atPm)) || (c == mob && in(atMobility)) ||
                   (c == sen && in(atSensors));
        };
        const JausId asker{300, 1, 1};
        for (const auto* list : {&everywhere, &atPm, &atMobility, &atSensors, &nowhere})
            for (std::uint16_t id : *list)
                for (const JausId& c : {pm, mob, sen}) {
                    const std::uint64_t before = w.ugvCounters.get("rx.ignored");
                    w.ugv->handle(asker, c, encodeEmpty(id));
                    const bool ignored = w.ugvCounters.get("rx.ignored") != before;
                    if (ignored == served(c, id))
                        QFAIL(qPrintable(QString("%1 at %2: %3")
                                             .arg(messageName(id))
                                             .arg(QString::fromStdString(c.toString()))
                                             .arg(ignored ? "ignored" : "handled")));
                }
    }
};

QTEST_GUILESS_MAIN(TestJausServices)
#include "test_jaus_services.moc"
