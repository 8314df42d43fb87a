// End to end over loopback (127.0.0.1, free ports, multicast outbound interface 127.0.0.1): the OCU's
// JausStack against ForeignJausVehicle, an independent JAUS peer that does less than our simulator (only
// derived services listed, no events, no heartbeat, no QueryControl / QueryTimeout answers, Reject-then-
// Confirm on pre-emption) and listens on unicast only, so consoles reach it through static endpoints.
// Waits are generous and end as soon as their condition holds; time bounds themselves (poll
// period, 1 Hz probe, reject grace) are proven on a FakeClock in test_jaus_core_rules.
#include <QtTest>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>

#include <chrono>
#include <mutex>
#include <thread>

#include "protocols/common/Log.h"
#include "protocols/common/Udp.h"
#include "protocols/jaus/JausStack.h"
#include "protocols/jaus/Messages.h"
#include "tests/protocols/jaus/foreign/ForeignJausVehicle.h"
#include "tests/support/JausLoopback.h"
#include "tests/support/StackWaits.h"

using namespace ocu;
using namespace ocu::jaus;
using foreign::ForeignJausVehicle;
using foreign::VehicleOptions;
using stacktest::Outcomes;
using stacktest::waitFor;

namespace {

using Quiet = jaustest::QuietListener;

std::uint16_t groupPort() {
    static const std::uint16_t port = findFreeUdpPort(); // one group per test process
    return port;
}

JausConfig console(std::uint16_t ss, Role role, std::uint8_t authority, std::uint16_t vehiclePort) {
    JausConfig c;
    c.subsystemId = ss;
    c.callSign = "OCU-" + std::to_string(ss);
    c.role = role;
    c.authority = authority;
    c.statusPollHz = 2;
    c.linkLostS = 1.5;
    c.discoveryIntervalS = 30; // recovery must not wait for it
    c.accessTimeoutS = 3;
    c.transport = jaustest::loopback(groupPort());
    auto& t = c.transport;
    t.staticEndpoints.push_back(StaticEndpoint{JausId{126, 0xFF, 0xFF}, "127.0.0.1", vehiclePort, false});
    return c;
}

struct Console {
    Console(std::uint16_t ss, Role role, std::uint8_t authority, std::uint16_t vehiclePort)
        : Console(console(ss, role, authority, vehiclePort)) {}
    explicit Console(const JausConfig& c) : stack(c, quiet) { stack.start(); }
    ~Console() { stack.stop(); }
    std::optional<SubsystemSnapshot> snap() { return stack.snapshot(126); }
    bool discovered() {
        auto s = snap();
        return s && s->callSign == "FOREIGN-126" && !s->services.empty();
    }
    std::uint32_t id() const { return stack.config().ownId().value(); }
    Quiet quiet;
    JausStack stack;
};

} // namespace

class TestJausForeign : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { setLogThreshold(LogLevel::Error); }

    // §3 + §5 + §7: a vehicle listing only LocalPoseSensor and LocalWaypointListDriver, reachable only by its
    // static endpoint: discovered, controlled, stopped, cleared, released. (Main: never discovered, since
    // static endpoints got no unicast QueryIdentification; and no mobility component for such a vehicle.)
    void derivedServicesOnlyVehicleWorksEndToEnd() {
        ForeignJausVehicle v(VehicleOptions{});
        Console ocu(200, Role::PrimaryOperator, 205, v.port());
        QVERIFY(waitFor([&] { return ocu.discovered(); }));
        Outcomes req;
        ocu.stack.requestControl(126, req.callback());
        auto r = req.get();
        QVERIFY(r && r->size() == 1);
        QVERIFY2(r->front().sent, r->front().reason.c_str());
        QVERIFY(waitFor([&] { return ocu.snap()->controlledByUs; }));
        QCOMPARE(v.controller(), ocu.id());

        Outcomes stop;
        ocu.stack.setEmergency(126, EmergencyCode::Stop, stop.callback());
        QVERIFY(stop.get() && stop.get()->front().sent);
        QVERIFY(waitFor([&] { return v.status() == 5; }));
        QVERIFY(waitFor([&] { return ocu.snap()->emergency; })); // from its ReportStatus (polled, no events)

        Outcomes clear;
        ocu.stack.clearEmergency(126, clear.callback());
        QVERIFY(clear.get() && clear.get()->front().sent);
        QVERIFY(waitFor([&] { return v.status() != 5; }));
        QVERIFY(waitFor([&] { return !ocu.snap()->emergency; }));

        Outcomes rel;
        ocu.stack.releaseControl(126, rel.callback());
        QVERIFY(rel.get() && rel.get()->front().sent);
        QVERIFY(waitFor([&] { return v.controller() == 0 && !ocu.snap()->controlledByUs; }));
        // §4: after the release our own ID is never shown as the (other) controller.
        QVERIFY(!(ocu.snap()->controller == ocu.stack.config().ownId()));
        QCOMPARE(v.malformed(), 0);
    }

    // §3: a component with sensors only inherits AccessControl (LocalPoseSensor) but not Management: control
    // is requested and accepted, an emergency is refused with a reason naming the missing service.
    void sensorOnlyComponentAcceptsControlButNotEmergency() {
        VehicleOptions o;
        o.services = {"urn:jaus:jss:mobility:LocalPoseSensor", "urn:jaus:jss:mobility:VelocityStateSensor"};
        o.management = false;
        ForeignJausVehicle v(o);
        Console ocu(200, Role::PrimaryOperator, 205, v.port());
        QVERIFY(waitFor([&] { return ocu.discovered(); }));
        Outcomes req;
        ocu.stack.requestControl(126, req.callback());
        QVERIFY(req.get() && req.get()->front().sent);
        QVERIFY(waitFor([&] { return v.controller() == ocu.id(); }));
        Outcomes stop;
        ocu.stack.setEmergency(126, EmergencyCode::Stop, stop.callback());
        auto s = stop.get();
        QVERIFY(s && s->size() == 1);
        QVERIFY(!s->front().sent);
        QVERIFY2(s->front().reason.find("offers Management") != std::string::npos, s->front().reason.c_str());
        QCOMPARE(v.received(msg::SetEmergency), 0);
    }

    // §1: management commands report what went on the wire: Resume without control is refused with the
    // reason (nothing sent), with control it is sent and the vehicle's status shows it.
    void managementCommandsReportTheirOutcome() {
        ForeignJausVehicle v(VehicleOptions{});
        Console ocu(200, Role::PrimaryOperator, 205, v.port());
        QVERIFY(waitFor([&] { return ocu.discovered(); }));
        Outcomes early;
        ocu.stack.resume(126, early.callback());
        auto e = early.get();
        QVERIFY(e && e->size() == 1);
        QCOMPARE(e->front().target, std::string("jaus:126"));
        QVERIFY(!e->front().sent);
        QVERIFY2(e->front().reason.find("needs control") != std::string::npos, e->front().reason.c_str());
        QCOMPARE(v.received(msg::Resume), 0);
        Outcomes req;
        ocu.stack.requestControl(126, req.callback());
        QVERIFY(req.get() && req.get()->front().sent);
        QVERIFY(waitFor([&] { return v.controller() == ocu.id(); }));
        Outcomes standby;
        ocu.stack.standby(126, standby.callback());
        auto s = standby.get();
        QVERIFY(s && s->size() == 1 && s->front().sent);
        QVERIFY(waitFor([&] { return v.received(msg::Standby) >= 1; }));
    }

    // §2: the monitor role stops a vehicle it does not control (SetEmergency on the wire, through STOP ALL)
    // and its ClearEmergency is refused with a reason, nothing sent.
    void monitorStopsAndCannotClear() {
        ForeignJausVehicle v(VehicleOptions{});
        Console monitor(201, Role::Monitor, 0, v.port());
        QVERIFY(waitFor([&] { return monitor.discovered(); }));
        Outcomes all;
        monitor.stack.setEmergencyAll(EmergencyCode::Stop, all.callback());
        auto a = all.get();
        QVERIFY(a && a->size() == 1);
        QCOMPARE(a->front().target, std::string("jaus:126"));
        QVERIFY(a->front().sent);
        QVERIFY(waitFor([&] { return v.status() == 5; }));
        QVERIFY(v.receivedFrom(msg::SetEmergency, monitor.id()) >= 1);
        Outcomes clear;
        monitor.stack.clearEmergency(126, clear.callback());
        auto c = clear.get();
        QVERIFY(c && !c->front().sent && !c->front().reason.empty());
        QTest::qWait(300);
        QCOMPARE(v.received(msg::ClearEmergency), 0);
        QCOMPARE(v.status(), std::uint8_t(5));
    }

    // §4: no events: an emergency set and cleared by another console shows on this one through the status
    // poll.
    void emergencyByAnotherConsoleShows() {
        ForeignJausVehicle v(VehicleOptions{});
        Console watcher(201, Role::Monitor, 0, v.port());
        Console other(202, Role::PrimaryOperator, 210, v.port());
        QVERIFY(waitFor([&] { return watcher.discovered() && other.discovered(); }));
        QVERIFY(waitFor([&] { return watcher.snap()->management.has_value(); }));
        QVERIFY(!watcher.snap()->emergency);
        other.stack.setEmergency(126, EmergencyCode::Safety, {});
        QVERIFY(waitFor([&] { return watcher.snap()->emergency; }));
        other.stack.clearEmergency(126, {});
        QVERIFY(waitFor([&] { return !watcher.snap()->emergency; }));
        QCOMPARE(v.received(msg::CreateEvent) > 0, true); // it asked for events; none came
    }

    // §4: pre-emption answered with RejectControl then ConfirmControl(accepted): accepted and kept; the old
    // controller, never told, learns it from its next re-request's answer within the access timeout; neither
    // console shows itself as the other controller.
    void rejectThenConfirmIsAcceptedAndOldControllerLearns() {
        ForeignJausVehicle v(VehicleOptions{});
        Console low(202, Role::PrimaryOperator, 205, v.port());
        Console high(203, Role::SafetyCritical, 240, v.port());
        QVERIFY(waitFor([&] { return low.discovered() && high.discovered(); }));
        low.stack.requestControl(126, {});
        QVERIFY(waitFor([&] { return low.snap()->controlledByUs && v.controller() == low.id(); }));
        high.stack.requestControl(126, {});
        QVERIFY(waitFor([&] { return high.snap()->controlledByUs && v.controller() == high.id(); }));
        // Beyond the reject grace and a re-request: still ours, never handed back.
        QVERIFY(waitFor([&] { return v.receivedFrom(msg::RequestControl, high.id()) >= 3; }));
        QVERIFY(high.snap()->controlledByUs);
        QCOMPARE(v.controller(), high.id());
        QCOMPARE(v.receivedFrom(msg::ReleaseControl, high.id()), 0);
        // The old controller: its re-request is answered INSUFFICIENT_AUTHORITY.
        QVERIFY(waitFor([&] { return !low.snap()->controlledByUs; }));
        QCOMPARE(low.snap()->access, AccessState::Preempted);
        QVERIFY(!(low.snap()->controller == low.stack.config().ownId()));
    }

    // §7: a vehicle answering late (every reply 600 ms after the request): discovered, controlled and stopped
    // all the same, and control holds through re-requests answered late. Access timeout 2 s on both sides
    // (configurable): re-requests every 0.8 s, each answered 0.6 s later.
    void lateAnswersStillWork() {
        VehicleOptions o;
        o.replyDelayMs = 600;
        o.accessTimeoutS = 2;
        ForeignJausVehicle v(o);
        JausConfig c = console(200, Role::PrimaryOperator, 205, v.port());
        c.accessTimeoutS = o.accessTimeoutS;
        Console ocu(c);
        QVERIFY(waitFor([&] { return ocu.discovered(); }));
        ocu.stack.requestControl(126, {});
        QVERIFY(waitFor([&] { return ocu.snap()->controlledByUs; }));
        ocu.stack.setEmergency(126, EmergencyCode::Safety, {});
        QVERIFY(waitFor([&] { return ocu.snap()->emergency; }));
        QVERIFY(waitFor([&] { return v.receivedFrom(msg::RequestControl, ocu.id()) >= 3; }));
        QVERIFY(ocu.snap()->controlledByUs);
        QCOMPARE(v.controller(), ocu.id());
        QCOMPARE(v.malformed(), 0);
    }

    // §5: a link lost while the vehicle was away is restored by the 1 Hz unicast probe, not by the 30 s
    // discovery broadcast (main: polling stopped while down, the vehicle was never asked again).
    void linkRestoredByProbeAfterOutage() {
        ForeignJausVehicle v(VehicleOptions{});
        JausConfig c = console(200, Role::PrimaryOperator, 205, v.port());
        c.statusPollHz = 5; // fast timers (configurable): the outage is noticed after 1 s
        c.linkLostS = 1;
        Console ocu(c);
        QVERIFY(waitFor([&] { return ocu.discovered(); }));
        v.setOffline(true);
        QVERIFY(waitFor([&] { return ocu.snap()->link == LinkState::Down; }));
        const int before = v.received(msg::QueryIdentification);
        v.setOffline(false);
        QVERIFY(waitFor([&] { return ocu.snap()->link == LinkState::Up; }, 10)); // < the 30 s interval
        QVERIFY(v.received(msg::QueryIdentification) > before);
    }

    // §6: two consoles on one host configured with the same unicast port (the group's port): the second
    // falls back to an ephemeral unicast port instead of stealing the first one's replies; both keep links.
    void twoConsolesOnOneHostKeepTheirLinks() {
        ForeignJausVehicle v(VehicleOptions{});
        JausConfig a = console(204, Role::Monitor, 0, v.port());
        JausConfig b = console(205, Role::Monitor, 0, v.port());
        a.transport.port = b.transport.port = groupPort();
        // Fast timers (configurable): polled at 5 Hz, a link is down after 1 s without a reply.
        a.statusPollHz = b.statusPollHz = 5;
        a.linkLostS = b.linkLostS = 1;
        Quiet q;
        JausStack sa(a, q), sb(b, q);
        sa.start();
        sb.start();
        QVERIFY(sa.localPort() == groupPort());
        QVERIFY(sb.localPort() != groupPort());
        auto up = [](JausStack& s) {
            auto x = s.snapshot(126);
            return x && !x->services.empty() && x->link == LinkState::Up;
        };
        QVERIFY(waitFor([&] { return up(sa) && up(sb); }));
        QTest::qWait(int(1200 * a.linkLostS)); // longer than link_lost_s: both still hear their own replies
        QVERIFY(up(sa));
        QVERIFY(up(sb));
        sb.stop();
        sa.stop();
    }

    // §6: beside a JAUS node manager holding the port (SO_REUSEADDR, like JTS): the console with port 0
    // starts, never binds that port for unicast, and unicast datagrams for the node manager reach it only.
    void besideANodeManagerHoldingThePort() {
        namespace asio = boost::asio;
        asio::io_context io;
        asio::ip::udp::socket nm(io);
        nm.open(asio::ip::udp::v4());
        nm.set_option(asio::socket_base::reuse_address(true));
        nm.bind(asio::ip::udp::endpoint(asio::ip::address_v4::any(), groupPort()));
        ForeignJausVehicle v(VehicleOptions{});
        Console ocu(200, Role::Monitor, 0, v.port());
        QVERIFY(ocu.stack.localPort() != groupPort());
        QVERIFY(waitFor([&] { return ocu.discovered(); }));
        // A datagram for the node manager (a JAUS message to it, as a peer would send).
        asio::ip::udp::socket peer(io, asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), 0));
        // QueryIdentification(subsystem) from 100.1.1 to 126.1.1: [02][00][size 17][props 01][dst][src]
        // [00 2B 02][seq 0].
        const std::uint8_t bytes[] = {0x02, 0x00, 0x11, 0x00, 0x01, 0x01, 0x01, 0x7e, 0x00,
                                      0x01, 0x01, 0x64, 0x00, 0x00, 0x2b, 0x02, 0x00, 0x00};
        for (int i = 0; i < 3; ++i)
            peer.send_to(asio::buffer(bytes),
                         asio::ip::udp::endpoint(asio::ip::address_v4::loopback(), groupPort()));
        std::array<std::uint8_t, 64> buf{};
        nm.non_blocking(true);
        int got = 0;
        const auto peerPort = peer.local_endpoint().port();
        waitFor([&] {
            boost::system::error_code ec;
            asio::ip::udp::endpoint from;
            // The node manager also gets the group's traffic (the console's discovery): count the peer's
            // only.
            while (nm.receive_from(asio::buffer(buf), from, 0, ec) > 0 && !ec)
                got += from.port() == peerPort ? 1 : 0;
            return got == 3;
        });
        QCOMPARE(got, 3);
        QTest::qWait(200);
        // What the console received meanwhile came from the vehicle (its polls), never these datagrams.
        QCOMPARE(ocu.stack.counters().get("rx.ignored.not_for_us"), std::uint64_t(0));
    }
};

QTEST_GUILESS_MAIN(TestJausForeign)
#include "test_jaus_foreign.moc"
