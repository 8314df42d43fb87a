// The console beside a JAUS node manager that holds the JAUS port without SO_REUSEADDR (public node managers
// bind it so): the group socket cannot be bound, and the stack goes on by unicast from its own port instead
// of failing. Against a simulated UGV reachable through a static endpoint, over loopback: discovery, control
// (RequestControl confirmed), STOP ALL (SetEmergency reaches the vehicle and the vehicle reports EMERGENCY);
// the missing group socket is said once (log warning, TransportError event) and the stack reports it. Every
// wait ends as soon as its condition holds.
#include <QtTest>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/multicast.hpp>
#include <boost/asio/ip/udp.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>

#include "protocols/common/Log.h"
#include "protocols/common/Udp.h"
#include "protocols/jaus/JausStack.h"
#include "protocols/jaus/JudpCodec.h"
#include "protocols/jaus/JudpTransport.h"
#include "protocols/jaus/Messages.h"
#include "sim/jaus/JausDemo.h"
#include "tests/support/JausLoopback.h"
#include "tests/support/StackWaits.h"

using namespace ocu;
using namespace ocu::jaus;
namespace asio = boost::asio;
using asio::ip::udp;
using stacktest::waitFor;

namespace {

constexpr std::uint16_t kVehicle = 126;
constexpr std::uint16_t kConsole = 200;

// A node manager's socket: the JAUS port bound to the wildcard address WITHOUT SO_REUSEADDR, in the JAUS
// group on loopback. The wildcard is deliberate (not 127.0.0.1): that is how node managers bind, and only a
// wildcard bind collides with the console's group-address bind. The port is the kernel's choice, so it is
// free and held from the same call (no window in which another test could take it).
struct NodeManagerSocket {
    NodeManagerSocket() : socket(io) {
        socket.open(udp::v4());
        socket.bind(udp::endpoint(asio::ip::address_v4::any(), 0));
        socket.set_option(asio::ip::multicast::join_group(asio::ip::make_address_v4("239.255.0.1"),
                                                          asio::ip::make_address_v4("127.0.0.1")));
        socket.non_blocking(true);
    }
    std::uint16_t port() const { return socket.local_endpoint().port(); }
    // QueryIdentification messages from `subsystem` that reached this socket so far (the group's traffic).
    int queryIdentificationsFrom(std::uint16_t subsystem) {
        std::array<std::uint8_t, 65536> buf{};
        boost::system::error_code ec;
        udp::endpoint from;
        for (;;) {
            const std::size_t n = socket.receive_from(asio::buffer(buf), from, 0, ec);
            if (ec)
                break;
            auto d = decodeDatagram(ByteSpan(buf.data(), n));
            if (!d)
                continue;
            for (const auto& m : d->messages)
                if (m.header.source.subsystem == subsystem &&
                    peekMessageId(m.payload) == msg::QueryIdentification)
                    ++queries;
        }
        return queries;
    }
    asio::io_context io;
    udp::socket socket;
    int queries = 0;
};

struct Recorder : JausListener {
    std::mutex mutex;
    std::vector<JausEvent> events;
    void onSubsystemChanged(const SubsystemSnapshot&) override {}
    void onEvent(const JausEvent& e) override {
        std::lock_guard lock(mutex);
        events.push_back(e);
    }
    int count(EventKind k, const std::string& containing = {}) {
        std::lock_guard lock(mutex);
        return int(std::count_if(events.begin(), events.end(), [&](const JausEvent& e) {
            return e.kind == k && e.text.find(containing) != std::string::npos;
        }));
    }
    std::vector<JausEvent> of(EventKind k) {
        std::lock_guard lock(mutex);
        std::vector<JausEvent> out;
        for (const auto& e : events)
            if (e.kind == k)
                out.push_back(e);
        return out;
    }
};

// Warnings logged by the stacks (the process-wide sink; restored by the destructor).
struct Warnings {
    Warnings() {
        setLogSink([this](LogLevel level, std::string_view category, std::string_view message) {
            if (level < LogLevel::Warning)
                return;
            std::lock_guard lock(mutex);
            lines.push_back(std::string(category) + ": " + std::string(message));
        });
    }
    ~Warnings() { setLogSink({}); }
    int count(const std::string& containing) {
        std::lock_guard lock(mutex);
        return int(std::count_if(lines.begin(), lines.end(), [&](const std::string& l) {
            return l.find(containing) != std::string::npos;
        }));
    }
    std::mutex mutex;
    std::vector<std::string> lines;
};

sim::JausDemoOptions oneUgv() {
    sim::JausDemoOptions o;
    o.count = 1;
    o.firstSubsystemId = kVehicle;
    o.alternateKinematics = false;
    return o;
}

// The console as configured by default for the JAUS port (unicast and group on the same port), on loopback,
// with the vehicle as a static endpoint. The vehicle keeps a group of its own: it stands for a machine on
// another host, which a node manager on the console's host does not concern.
JausConfig consoleBeside(const sim::JausDemo& demo, std::uint16_t heldPort) {
    JausConfig c;
    c.subsystemId = kConsole;
    c.callSign = "OCU-PORT-HELD";
    c.authority = 205;
    c.driveCommandTimeoutS = 0;
    demo.configure(c); // the static endpoint of the vehicle
    c.transport.port = heldPort;
    c.transport.multicastPort = heldPort;
    return c;
}

} // namespace

class TestJausPortHeld : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { setLogThreshold(LogLevel::Warning); }

    // The whole console path with the port held: discovery through the static endpoint (and the group
    // QueryIdentification still leaves, from the console's own port), control confirmed, STOP ALL reaches
    // the vehicle.
    void discoveryControlAndStopWorkWithoutTheGroupSocket() {
        NodeManagerSocket nm;
        sim::JausDemo demo(oneUgv());
        Recorder rec;
        JausStack stack(consoleBeside(demo, nm.port()), rec);
        try {
            stack.start();
        } catch (const std::exception& e) {
            QFAIL(e.what()); // the stack must never die of a held port
        }
        QVERIFY(stack.running());
        QVERIFY(stack.localPort() != 0);
        QVERIFY(stack.localPort() != nm.port());

        // Discovery: the vehicle answers the unicast QueryIdentification of its static endpoint.
        auto snap = [&] { return stack.snapshot(kVehicle); };
        QVERIFY(waitFor([&] {
            auto s = snap();
            return s && s->callSign == "UGV-126" && s->link == LinkState::Up &&
                   s->mobilityComponent.subsystem == kVehicle;
        }));
        // The broadcast QueryIdentification still goes to the group (the node manager, in the group on the
        // held port, receives it): sending to the group needs no group socket.
        QVERIFY(waitFor([&] { return nm.queryIdentificationsFrom(kConsole) >= 1; }));

        // Control: RequestControl confirmed by the vehicle.
        std::atomic<int> requested{0};
        std::mutex outcomeMutex;
        std::vector<TargetOutcome> outcomes;
        stack.requestControl(kVehicle, [&](std::vector<TargetOutcome> o) {
            std::lock_guard lock(outcomeMutex);
            outcomes = std::move(o);
            ++requested;
        });
        QVERIFY(waitFor([&] { return requested == 1; }));
        {
            std::lock_guard lock(outcomeMutex);
            QCOMPARE(outcomes.size(), std::size_t(1));
            QVERIFY2(outcomes[0].sent, outcomes[0].reason.c_str());
        }
        QVERIFY(waitFor([&] { return snap() && snap()->controlledByUs; }));
        QVERIFY(waitFor([&] { return rec.count(EventKind::ControlAccepted) >= 1; }));
        QVERIFY(waitFor([&] {
            const auto v = demo.find(kVehicle)->state();
            return v.controller.subsystem == kConsole;
        }));

        // Stop: STOP ALL's SetEmergency reaches the vehicle, which reports EMERGENCY.
        std::atomic<int> stopped{0};
        stack.setEmergencyAll(EmergencyCode::Safety, [&](std::vector<TargetOutcome> o) {
            std::lock_guard lock(outcomeMutex);
            outcomes = std::move(o);
            ++stopped;
        });
        QVERIFY(waitFor([&] { return stopped == 1; }));
        {
            std::lock_guard lock(outcomeMutex);
            QCOMPARE(outcomes.size(), std::size_t(1));
            QCOMPARE(outcomes[0].target, std::string("jaus:126"));
            QVERIFY2(outcomes[0].sent, outcomes[0].reason.c_str());
        }
        QVERIFY(
            waitFor([&] { return demo.find(kVehicle)->state().management == ManagementState::Emergency; }));
        QVERIFY(waitFor([&] { return snap() && snap()->emergency; }));
        stack.stop();
        demo.stop();
    }

    // Said once, with the reason: one log warning (which names the unicast fallback too, not a second one),
    // one TransportError event, a counter; and the stack's accessor says the group socket is missing and why.
    void missingGroupSocketIsSaidOnceAndReported() {
        Warnings warnings;
        NodeManagerSocket nm;
        sim::JausDemo demo(oneUgv());
        Recorder rec;
        JausStack stack(consoleBeside(demo, nm.port()), rec);
        stack.start();

        const auto problem = stack.groupSocketProblem();
        QVERIFY(problem.has_value());
        QVERIFY(problem->heldByOther);
        QCOMPARE(problem->port, nm.port());
        QCOMPARE(problem->group, "239.255.0.1:" + std::to_string(nm.port()));
        QCOMPARE(problem->unicastPort, stack.localPort());
        QCOMPARE(problem->unicastPortHeld, nm.port()); // the configured unicast port was the held one too
        QVERIFY2(problem->reason.find("in use") != std::string::npos, problem->reason.c_str());
        QCOMPARE(stack.counters().get("transport.group_socket_missing"), std::uint64_t(1));

        // The event arrives on the io thread after start().
        QVERIFY(waitFor([&] { return rec.count(EventKind::TransportError) >= 1; }));
        const auto events = rec.of(EventKind::TransportError);
        QCOMPARE(events.front().severity, Severity::Warning);
        QCOMPARE(events.front().subsystem, std::uint16_t(0));
        const std::string port = std::to_string(nm.port());
        QVERIFY2(events.front().text.find("no group socket") != std::string::npos,
                 events.front().text.c_str());
        QVERIFY2(events.front().text.find("UDP port " + port + " is held by another process") !=
                     std::string::npos,
                 events.front().text.c_str());
        QVERIFY2(events.front().text.find(std::to_string(stack.localPort())) != std::string::npos,
                 events.front().text.c_str());
        QCOMPARE(events.front().text, toText(*problem));

        // Later: the vehicle discovered and two more discovery rounds sent to the group (the group traffic
        // goes on) - and still one warning, one event.
        QVERIFY(waitFor(
            [&] { return stack.snapshot(kVehicle) && stack.snapshot(kVehicle)->link == LinkState::Up; }));
        QVERIFY(waitFor([&] { return nm.queryIdentificationsFrom(kConsole) >= 1; }));
        for (int round = 2; round <= 3; ++round) {
            stack.discoverNow();
            QVERIFY(waitFor([&] { return nm.queryIdentificationsFrom(kConsole) >= round; }));
        }
        QCOMPARE(rec.count(EventKind::TransportError), 1);
        QCOMPARE(warnings.count("no group socket"), 1);
        QCOMPARE(warnings.count("held by another process"), 1); // no separate unicast-port warning
        stack.stop();
        demo.stop();
    }

    // The port free: the group socket is there, nothing is said.
    void nothingIsSaidWhenThePortIsFree() {
        Warnings warnings;
        sim::JausDemo demo(oneUgv());
        Recorder rec;
        JausConfig c = consoleBeside(demo, findFreeUdpPort());
        c.transport.port = 0;
        JausStack stack(c, rec);
        stack.start();
        QVERIFY(!stack.groupSocketProblem().has_value());
        QVERIFY(waitFor(
            [&] { return stack.snapshot(kVehicle) && stack.snapshot(kVehicle)->link == LinkState::Up; }));
        QCOMPARE(rec.count(EventKind::TransportError), 0);
        QCOMPARE(warnings.count("no group socket"), 0);
        QCOMPARE(stack.counters().get("transport.group_socket_missing"), std::uint64_t(0));
        stack.stop();
        demo.stop();
    }

    // UDP broadcast mode receives broadcasts on the unicast socket: its port held, the transport opens on an
    // ephemeral port and reports the broadcast port as missing, instead of failing.
    void broadcastModeWithThePortHeldOpensOnAnEphemeralPort() {
        NodeManagerSocket nm;
        asio::io_context io;
        Counters counters;
        TransportSettings s = jaustest::loopback(nm.port());
        s.multicast = false;
        s.broadcastAddress = "127.255.255.255";
        s.port = nm.port();
        JudpTransport t(io, s, counters, SteadyClock::instance(), "test.jaus");
        try {
            t.open();
        } catch (const std::exception& e) {
            QFAIL(e.what());
        }
        QVERIFY(t.localPort() != 0);
        QVERIFY(t.localPort() != nm.port());
        QVERIFY(t.groupSocketProblem().has_value());
        QVERIFY(t.groupSocketProblem()->heldByOther);
        QCOMPARE(t.groupSocketProblem()->group, "broadcast port " + std::to_string(nm.port()));
        QCOMPARE(t.groupSocketProblem()->unicastPort, t.localPort());
        QCOMPARE(counters.get("transport.port_in_use"), std::uint64_t(1));
        t.close();
    }
};

QTEST_GUILESS_MAIN(TestJausPortHeld)
#include "test_jaus_port_held.moc"
