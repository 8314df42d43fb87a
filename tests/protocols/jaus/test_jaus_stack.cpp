// End to end over real loopback sockets (127.0.0.1, free ports, multicast TTL 0): the OCU JausStack against
// two SimulatedUgvs started by JausDemo. Every wait here is generous and ends as
// soon as its condition holds; the time bounds themselves (discovery within 3 s, drive timeout, access
// timeout, 5 m at 1 m/s) are proven on a FakeClock in tests/sim/jaus/test_jaus_services.cpp, because on a
// loaded machine a wall clock measures the scheduler, not the protocol.
#include <QtTest>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <random>
#include <thread>

#include "protocols/common/GeoFrame.h"
#include "protocols/common/Log.h"
#include "protocols/common/MessageTap.h"
#include "protocols/common/Udp.h"
#include "protocols/jaus/JausStack.h"
#include "protocols/jaus/Messages.h"
#include "sim/jaus/JausDemo.h"
#include "tests/support/StackWaits.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::sim;
using Clk = std::chrono::steady_clock;

namespace {

struct Recorder : JausListener {
    std::mutex mutex;
    std::vector<JausEvent> events;
    void onSubsystemChanged(const SubsystemSnapshot&) override {}
    void onEvent(const JausEvent& e) override {
        std::lock_guard lock(mutex);
        events.push_back(e);
    }
    int count(EventKind k, std::uint16_t ss) {
        std::lock_guard lock(mutex);
        return int(std::count_if(events.begin(), events.end(),
                                 [&](const JausEvent& e) { return e.kind == k && e.subsystem == ss; }));
    }
};

using stacktest::waitFor;

JausConfig ocuConfig(const JausDemo& demo, std::uint16_t ss = 200, std::uint8_t authority = 205) {
    JausConfig c;
    c.subsystemId = ss;
    c.callSign = "OCU-" + std::to_string(ss);
    c.authority = authority;
    c.driveCommandTimeoutS =
        0; // these tests set a demand once and let the stack stream it (watchdog: services test)
    demo.configure(c);
    return c;
}

struct Fixture {
    explicit Fixture(JausDemoOptions o = {}) : demo(o), stack(ocuConfig(demo), rec) { stack.start(); }
    ~Fixture() {
        stack.stop();
        demo.stop();
    }
    std::optional<SubsystemSnapshot> snap(std::uint16_t ss) { return stack.snapshot(ss); }
    bool ready(std::uint16_t ss) {
        auto s = snap(ss);
        return s && s->platform && s->mobilityComponent.subsystem != 0;
    }
    bool takeControl(std::uint16_t ss) {
        if (!waitFor([&] { return ready(ss); }))
            return false;
        stack.requestControl(ss, {});
        return waitFor([&] { return snap(ss) && snap(ss)->controlledByUs; });
    }
    void drive(std::uint16_t ss, double v) {
        stack.startDriving(ss, {});
        DriveCommand c;
        c.linear = v;
        stack.setDriveCommand(ss, c, {});
    }
    JausDemo demo;
    Recorder rec;
    JausStack stack;
};

// Steady-clock time at which a UGV last received a message of one type (its io thread, before handling).
struct LastReceived {
    std::atomic<Clk::rep> at{0};
    void watch(SimulatedUgv& ugv, std::uint16_t messageId) {
        ugv.setMessageTap([this, messageId](ByteSpan p) {
            if (peekMessageId(p) == messageId)
                at = Clk::now().time_since_epoch().count();
        });
    }
    double secondsSince() const {
        return std::chrono::duration<double>(Clk::now() - Clk::time_point(Clk::duration(at.load()))).count();
    }
};

} // namespace

class TestJausLoopback : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { setLogThreshold(LogLevel::Warning); }

    // Within 3 s of protocol time: test_jaus_services discoveryFindsCallSignAndServices (FakeClock).
    void discoversTwoUgvsWithCallSigns() {
        const auto t0 = Clk::now();
        Fixture f;
        QVERIFY(waitFor([&] {
            auto a = f.snap(126), b = f.snap(127);
            return a && b && a->callSign == "UGV-126" && b->callSign == "UGV-127";
        }));
        qInfo("both UGVs discovered with their call signs after %.0f ms (wall clock)",
              std::chrono::duration<double, std::milli>(Clk::now() - t0).count());
        QCOMPARE(f.rec.count(EventKind::Discovered, 126), 1);
        QCOMPARE(f.rec.count(EventKind::Discovered, 127), 1);
        QVERIFY(waitFor([&] { return f.ready(126) && f.ready(127); }));
        QCOMPARE(f.snap(127)->platform->steeringType, std::uint8_t(1)); // the second one is Ackermann
        QVERIFY(!f.snap(126)->endpoint.empty());
        QVERIFY(waitFor([&] { return f.snap(126)->globalPose.has_value(); }));
        QCOMPARE(f.stack.counters().sumPrefix("rx.rejected."), std::uint64_t(0));
    }

    // Driven over the wire until the UGV has gone 5 m, stopped, and the console's poses agree with the
    // vehicle's truth. (Distance per time at 1 m/s: test_jaus_services driveForwardFiveMetres, FakeClock.)
    void takeControlAndDriveFiveMetres() {
        Fixture f;
        QVERIFY(f.takeControl(126));
        f.drive(126, 2.0); // the platform's top speed: 5 m in about 3 s
        QVERIFY(waitFor([&] { return f.snap(126)->management == ManagementState::Ready; }));
        QVERIFY(waitFor([&] { return f.demo.find(126)->state().x >= 5.0; }));
        f.stack.stopDriving(126, {});
        QVERIFY(waitFor([&] { return std::abs(f.demo.find(126)->state().v) < 1e-6; }));
        const auto truth = f.demo.find(126)->state();
        QVERIFY2(truth.x >= 5.0 && std::abs(truth.y) < 0.05, qPrintable(QString::number(truth.x)));
        // Pose reports after the stop: local and global pose match the truth.
        GeoFrame frame(JausDemoOptions{}.origin);
        auto agrees = [&] {
            auto s = f.snap(126);
            if (!s || !s->localPose || !s->localPose->x || !s->globalPose || !s->globalPose->lat ||
                !s->globalPose->lon)
                return false;
            const auto enu = frame.toLocal(GeoPoint{*s->globalPose->lat, *s->globalPose->lon, 0});
            return std::abs(*s->localPose->x - truth.x) < 0.05 && std::abs(enu.n - truth.x) < 0.05 &&
                   std::abs(enu.e - truth.y) < 0.05;
        };
        QVERIFY2(waitFor(agrees), qPrintable(QString("truth %1 m, local %2 m")
                                                 .arg(truth.x)
                                                 .arg(f.snap(126)->localPose && f.snap(126)->localPose->x
                                                          ? *f.snap(126)->localPose->x
                                                          : -1.0)));
        // The other UGV did not move.
        QCOMPARE(f.demo.find(127)->state().x, 0.0);
    }

    void emergencyStopsUntilCleared() {
        Fixture f;
        QVERIFY(f.takeControl(126));
        f.drive(126, 1.0);
        QVERIFY(waitFor([&] { return f.demo.find(126)->state().v > 0.9; }));
        f.stack.setEmergency(126, EmergencyCode::Safety, {});
        QVERIFY(waitFor([&] { return f.demo.find(126)->state().management == ManagementState::Emergency; }));
        QCOMPARE(f.demo.find(126)->state().v, 0.0);
        QVERIFY(waitFor([&] { return f.snap(126)->emergency; }));
        QCOMPARE(f.rec.count(EventKind::Emergency, 126), 1);
        const double x = f.demo.find(126)->state().x;
        f.drive(126, 1.0); // refused while in emergency
        QVERIFY(waitFor([&] { return f.rec.count(EventKind::CommandRefused, 126) >= 1; }));
        std::this_thread::sleep_for(std::chrono::milliseconds(500)); // ten drive periods: nothing moves
        QCOMPARE(f.demo.find(126)->state().x, x);
        f.stack.clearEmergency(126, {});
        QVERIFY(waitFor([&] { return !f.snap(126)->emergency; }));
        QCOMPARE(f.rec.count(EventKind::EmergencyCleared, 126), 1);
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
        QCOMPARE(f.demo.find(126)->state().x, x); // still stopped: nothing drives it
    }

    // STOP ALL leaves from the caller's thread: once the io thread planned both vehicles'
    // SetEmergency, setEmergencyAll sends them before it returns, and the core still learns them: both
    // targets reported sent, the driving vehicle stops, its drive session ends, both report EMERGENCY.
    void stopAllFromTheCallersThreadIsLearntByTheCore() {
        Fixture f;
        QVERIFY(f.takeControl(126));
        QVERIFY(waitFor([&] { return f.ready(127); }));
        f.drive(126, 1.0);
        QVERIFY(waitFor([&] { return f.demo.find(126)->state().v > 0.9; }));
        QVERIFY(waitFor([&] { return f.stack.plannedStopCount() == 2; }));
        const auto plannedBefore = f.stack.counters().get("tx.planned");
        std::mutex m;
        std::vector<TargetOutcome> out;
        f.stack.setEmergencyAll(EmergencyCode::Safety, [&](std::vector<TargetOutcome> o) {
            std::lock_guard lock(m);
            out = std::move(o);
        });
        // Both planned datagrams were taken by the socket before setEmergencyAll returned.
        QCOMPARE(f.stack.counters().get("tx.planned"), plannedBefore + 2);
        QVERIFY(waitFor([&] {
            std::lock_guard lock(m);
            return out.size() == 2;
        }));
        for (const auto& o : out)
            QVERIFY2(o.sent, o.reason.c_str());
        for (std::uint16_t ss : {126, 127})
            QVERIFY(
                waitFor([&] { return f.demo.find(ss)->state().management == ManagementState::Emergency; }));
        QCOMPARE(f.demo.find(126)->state().v, 0.0);
        QVERIFY(waitFor([&] { return f.snap(126)->emergency && f.snap(127)->emergency; }));
        QVERIFY(!f.snap(126)->driving); // the core ended the drive session as for its own SetEmergency
    }

    // The UGV's own watchdog on its real clock. Its 1 s window (not before 0.9 s, by 1.2 s) is proven on a
    // FakeClock by test_jaus_services driveTimeoutStopsAndRecovers; here it never fires early. The timeout
    // is configurable: half a second is still ten periods of the 20 Hz drive stream.
    void ugvStopsAfterDriveTimeoutWhenStreamingStops() {
        JausDemoOptions o;
        o.driveTimeoutS = 0.5;
        LastReceived lastDrive;
        Fixture f(o);
        lastDrive.watch(*f.demo.find(126), msg::SetVelocityCommand);
        QVERIFY(f.takeControl(126));
        f.drive(126, 1.0);
        QVERIFY(waitFor([&] { return f.demo.find(126)->state().v > 0.9; }));
        QCOMPARE(f.demo.find(126)->counters().get("drive.timeouts"), std::uint64_t(0)); // streamed in time
        f.stack.setTransmitFaults(1.0); // the OCU stops streaming (and everything else)
        QVERIFY(waitFor([&] { return f.demo.find(126)->state().driveTimedOut; }));
        const double quiet = lastDrive.secondsSince();
        QVERIFY2(quiet >= o.driveTimeoutS, qPrintable(QString::number(quiet))); // not before the timeout
        QCOMPARE(f.demo.find(126)->counters().get("drive.timeouts"), std::uint64_t(1));
        QVERIFY(waitFor([&] { return f.demo.find(126)->state().v == 0.0; }));
        f.demo.find(126)->setMessageTap({});
    }

    // The UGV's access timeout on its real clock: never before the timeout after the last RequestControl.
    // Kept while re-requests flow and lost within the window: test_jaus_services (FakeClock).
    void silentOcuLosesControlAfterAccessTimeout() {
        JausDemoOptions o;
        o.accessTimeoutS = 1; // fast timer: the UGV's timeout is configurable (whole seconds on the wire)
        LastReceived lastRequest;
        Fixture f(o);
        lastRequest.watch(*f.demo.find(126), msg::RequestControl);
        QVERIFY(f.takeControl(126));
        QVERIFY(waitFor([&] { return f.snap(126)->accessTimeoutS == 1; }));
        f.stack.setTransmitFaults(1.0);
        QVERIFY(waitFor([&] { return f.demo.find(126)->state().controller.subsystem == 0; }));
        const double quiet = lastRequest.secondsSince();
        QVERIFY2(quiet >= o.accessTimeoutS, qPrintable(QString::number(quiet)));
        // The OCU notices it too (it still hears the UGV).
        QVERIFY(waitFor([&] { return !f.snap(126)->controlledByUs; }));
        f.demo.find(126)->setMessageTap({});
    }

    void higherAuthorityOcuPreempts() {
        Fixture f;
        QVERIFY(f.takeControl(126));
        QVERIFY(f.takeControl(127));
        Recorder rec2;
        JausStack second(ocuConfig(f.demo, 201, 230), rec2);
        second.start();
        QVERIFY(waitFor([&] {
            auto s = second.snapshot(126);
            return s && s->mobilityComponent.subsystem != 0;
        }));
        second.requestControl(126, {});
        QVERIFY(waitFor([&] { return second.snapshot(126)->controlledByUs; }));
        QVERIFY(waitFor([&] { return f.rec.count(EventKind::ControlPreempted, 126) == 1; }));
        QCOMPARE(f.snap(126)->access, AccessState::Preempted);
        QCOMPARE(f.snap(126)->controller, (JausId{201, 1, 1}));
        // The other vehicle stays ours.
        QVERIFY(f.snap(127)->controlledByUs);
        QCOMPARE(f.demo.find(127)->state().controller, (JausId{200, 1, 1}));
        second.stop(); // releases 126
        QVERIFY(waitFor([&] { return f.demo.find(126)->state().controller.subsystem == 0; }));
    }

    void stopReleasesAllControl() {
        Fixture f;
        QVERIFY(f.takeControl(126));
        QVERIFY(f.takeControl(127));
        f.stack.stop();
        QVERIFY(waitFor([&] {
            return f.demo.find(126)->state().controller.subsystem == 0 &&
                   f.demo.find(127)->state().controller.subsystem == 0;
        }));
    }

    void injectedFaultsLoseAndRestoreTheLink() {
        JausDemoOptions o;
        o.count = 1;
        JausDemo demo(o);
        Recorder rec;
        JausConfig c = ocuConfig(demo);
        c.linkLostS = 1; // fast timer (configurable)
        JausStack stack(c, rec);
        stack.start();
        QVERIFY(waitFor([&] {
            auto s = stack.snapshot(126);
            return s && s->platform.has_value();
        }));
        // 30 % loss, 20 ms delay and reordering: the vehicle stays usable.
        auto* ugv = demo.find(126);
        ugv->setPacketLoss(0.3);
        ugv->setPacketDelay(20);
        ugv->setReorder(true);
        std::this_thread::sleep_for(std::chrono::duration<double>(c.linkLostS)); // one link_lost_s
        QCOMPARE(stack.snapshot(126)->link, LinkState::Up);
        QCOMPARE(rec.count(EventKind::LinkLost, 126), 0);
        // Total silence: link lost after link_lost_s.
        ugv->setPacketLoss(1.0);
        QVERIFY(waitFor([&] { return stack.snapshot(126)->link == LinkState::Down; }));
        QCOMPARE(rec.count(EventKind::LinkLost, 126), 1);
        ugv->setPacketLoss(0);
        ugv->setPacketDelay(0);
        ugv->setReorder(false);
        QVERIFY(waitFor([&] { return stack.snapshot(126)->link == LinkState::Up; }));
        QCOMPARE(rec.count(EventKind::LinkRestored, 126), 1);
        // Other switches: failure shows in management and health; rejected control is reported.
        ugv->enterFailure();
        QVERIFY(waitFor([&] { return stack.snapshot(126)->management == ManagementState::Failure; }));
        ugv->clearFailure();
        ugv->setRejectControl(true);
        stack.requestControl(126, {});
        QVERIFY(waitFor([&] { return stack.snapshot(126)->access == AccessState::NotAvailable; }));
        QCOMPARE(rec.count(EventKind::ControlRejected, 126), 1);
        stack.stop();
    }

    void preemptionByOnBoardClientIsReported() {
        Fixture f;
        QVERIFY(f.takeControl(126));
        f.demo.find(126)->preemptControl(255);
        QVERIFY(waitFor([&] { return f.snap(126)->access == AccessState::Preempted; }));
        QCOMPARE(f.rec.count(EventKind::ControlPreempted, 126), 1);
        QCOMPARE(f.snap(126)->controllerAuthority, std::uint8_t(255));
    }

    void jtcpPeer() {
        // A UGV reachable over JTCP (static table entry with "tcp"); broadcasts stay on JUDP.
        const std::uint16_t mc = findFreeUdpPort();
        SimulatedUgvConfig uc;
        uc.subsystemId = 140;
        uc.callSign = "TCP-UGV";
        uc.network = JausDemo::loopbackTransport(mc);
        uc.network.jtcpServer = true;
        uc.network.jtcpPort = 0;
        SimulatedUgv ugv(uc);
        ugv.start();
        const std::uint16_t tcpPort = ugv.localTcpPort();
        QVERIFY(tcpPort != 0);
        JausConfig c;
        c.transport = JausDemo::loopbackTransport(mc);
        c.transport.staticEndpoints.push_back({JausId{140, 255, 255}, "127.0.0.1", tcpPort, true});
        Recorder rec;
        JausStack stack(c, rec);
        stack.start();
        QVERIFY(waitFor([&] {
            auto s = stack.snapshot(140);
            return s && s->platform.has_value();
        }));
        QCOMPARE(stack.snapshot(140)->callSign, std::string("TCP-UGV"));
        QVERIFY(stack.counters().get("tx.jtcp.messages") > 0);
        QVERIFY(stack.counters().get("rx.jtcp.messages") > 0);
        stack.requestControl(140, {});
        QVERIFY(waitFor([&] { return stack.snapshot(140)->controlledByUs; }));
        stack.stop();
        QVERIFY(waitFor([&] { return ugv.state().controller.subsystem == 0; }));
        ugv.stop();
    }

    // The flight recorder's tap sees every delivered message with its type (the message code) and
    // sender, and, when it wants raw frames, every datagram as received - undecodable ones included.
    void tapSeesDecodedMessagesAndRawDatagrams() {
        struct CollectTap : MessageTap {
            std::mutex m;
            std::vector<std::tuple<std::string, std::string, Bytes>> decoded; // peer, type, bytes
            std::vector<Bytes> raws;
            void onDecoded(const TappedMessage& t) override {
                QCOMPARE(t.protocol, std::string_view("jaus"));
                std::lock_guard l(m);
                decoded.emplace_back(std::string(t.peer), std::string(t.type),
                                     Bytes(t.bytes.begin(), t.bytes.end()));
            }
            void onRaw(const TappedMessage& t) override {
                std::lock_guard l(m);
                raws.emplace_back(t.bytes.begin(), t.bytes.end());
            }
            bool wantsRaw() const override { return true; }
        } tap;
        JausDemo demo;
        Recorder rec;
        JausStack stack(ocuConfig(demo), rec);
        stack.setMessageTap(&tap);
        stack.start();
        QVERIFY(waitFor([&] {
            std::lock_guard l(tap.m);
            return std::any_of(tap.decoded.begin(), tap.decoded.end(),
                               [](const auto& d) { return std::get<0>(d).rfind("126.", 0) == 0; });
        }));
        boost::asio::io_context io;
        boost::asio::ip::udp::socket s(
            io, boost::asio::ip::udp::endpoint(boost::asio::ip::address_v4::loopback(), 0));
        const Bytes junk{0xEE, 0x01, 0x02, 0x03, 0x04};
        s.send_to(boost::asio::buffer(junk),
                  boost::asio::ip::udp::endpoint(boost::asio::ip::address_v4::loopback(), stack.localPort()));
        QVERIFY(waitFor([&] {
            std::lock_guard l(tap.m);
            return std::find(tap.raws.begin(), tap.raws.end(), junk) != tap.raws.end();
        }));
        stack.stop();
        demo.stop();
        std::lock_guard l(tap.m);
        QVERIFY(tap.raws.size() >= tap.decoded.size() / 2); // datagrams may carry several messages
        for (const auto& [peer, type, bytes] : tap.decoded) {
            QVERIFY(bytes.size() >= 2);
            QVERIFY(bytes != junk);
            char hex[5];
            std::snprintf(hex, sizeof hex, "%04X", unsigned(bytes[0] | bytes[1] << 8));
            QCOMPARE(type, std::string(hex));
        }
    }

    void garbageIsCountedNotFatal() {
        Fixture f;
        QVERIFY(waitFor([&] { return f.ready(126); }));
        // Random bytes and legacy headers to the OCU's port.
        boost::asio::io_context io;
        boost::asio::ip::udp::socket s(
            io, boost::asio::ip::udp::endpoint(boost::asio::ip::address_v4::loopback(), 0));
        boost::asio::ip::udp::endpoint to(boost::asio::ip::address_v4::loopback(), f.stack.localPort());
        std::mt19937 rng(7);
        for (int i = 0; i < 50; ++i) {
            Bytes d(std::size_t(1 + rng() % 1400));
            for (auto& b : d)
                b = std::uint8_t(rng());
            s.send_to(boost::asio::buffer(d), to);
        }
        const std::string legacy = "JAUS01.0xxxxxxxxxxxxxxxx";
        s.send_to(boost::asio::buffer(legacy), to);
        QVERIFY(waitFor([&] { return f.stack.counters().get("rx.rejected.legacy_opc") == 1; }));
        QVERIFY(f.stack.counters().sumPrefix("rx.rejected.") >= 45);
        QVERIFY(f.rec.count(EventKind::DecodeError, 0) >= 1);
        // Still working.
        QVERIFY(f.takeControl(126));
    }
};

QTEST_GUILESS_MAIN(TestJausLoopback)
#include "test_jaus_stack.moc"
