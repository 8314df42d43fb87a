// Video discovery over loopback: the OCU's JausStack discovers the video streams of ForeignJausVehicle, an
// independent peer (its own encoder, nothing from protocols/jaus or sim/jaus) whose Digital Resource
// Discovery behaves like other vendors' (FKIE's server ignores queries for its first seconds, answers late,
// leaves out the optional JAUS_ID / ResourceID fields, and the vehicle offers no Visual Sensor service). And
// a vehicle that announces nothing gets the stream configured for it in the site configuration.
#include <QtTest>

#include <chrono>
#include <thread>

#include "protocols/common/Udp.h"
#include "protocols/jaus/JausStack.h"
#include "protocols/jaus/MessagesVideo.h"
#include "tests/protocols/jaus/foreign/ForeignJausVehicle.h"
#include "tests/support/JausLoopback.h"

using namespace ocu;
using namespace ocu::jaus;
using foreign::ForeignJausVehicle;
using foreign::VehicleOptions;
using Clk = std::chrono::steady_clock;

namespace {

template <class Pred> bool waitFor(Pred p, double seconds = 20) {
    const auto end =
        Clk::now() + std::chrono::duration_cast<Clk::duration>(std::chrono::duration<double>(seconds));
    while (Clk::now() < end) {
        if (p())
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return p();
}

struct Quiet : JausListener {
    void onSubsystemChanged(const SubsystemSnapshot&) override {}
    void onEvent(const JausEvent&) override {}
};

JausConfig console(std::uint16_t vehiclePort) {
    JausConfig c;
    c.subsystemId = 200;
    c.callSign = "OCU-200";
    c.transport = jaustest::loopback(findFreeUdpPort());
    auto& t = c.transport;
    t.staticEndpoints.push_back(StaticEndpoint{JausId{126, 0xFF, 0xFF}, "127.0.0.1", vehiclePort, false});
    return c;
}

std::vector<VideoEndpoint> endpoints(JausStack& stack) {
    auto s = stack.snapshot(126);
    return s ? s->videoEndpoints : std::vector<VideoEndpoint>{};
}

} // namespace

class TestJausForeignVideo : public QObject {
    Q_OBJECT
private slots:
    void oddDigitalResourceDiscovery() {
        VehicleOptions o;
        o.services = {"urn:jaus:jss:iop:DigitalResourceDiscovery", "urn:jaus:jss:mobility:LocalPoseSensor"};
        o.streams = {
            {"rtsp://127.0.0.1:8554/bare", false, false, 0, 0},       // no optional field at all
            {"rtsp://127.0.0.1:8554/drive", false, true, 1003, 0},    // ResourceID only
            {"http://127.0.0.1:8080/snapshot.jpg", true, true, 7, 5}, // HTTP: not a pull stream
        };
        o.drdSilentFirstMs = 2500; // like FKIE's 5 s start-up silence, shorter for the test
        o.replyDelayMs = 300;      // and every answer late
        ForeignJausVehicle vehicle(o);
        Quiet quiet;
        JausStack stack(console(vehicle.port()), quiet);
        stack.start();

        QVERIFY2(waitFor([&] { return endpoints(stack).size() == 2; }),
                 "the streams announced through Digital Resource Discovery never showed");
        const auto eps = endpoints(stack);
        QCOMPARE(QString::fromStdString(eps[0].url), QStringLiteral("rtsp://127.0.0.1:8554/bare"));
        QCOMPARE(eps[0].sensorId, 0);
        QVERIFY(eps[0].name.empty()); // no Visual Sensor service: no name, still a stream
        QVERIFY(!eps[0].configured);
        QVERIFY(!eps[0].panTilt);
        QCOMPARE(QString::fromStdString(eps[1].url), QStringLiteral("rtsp://127.0.0.1:8554/drive"));
        QCOMPARE(eps[1].sensorId, 1003);
        QCOMPARE(eps[1].resourceId, 1003);
        // The console retried through the silent start-up, once a second; asked no Visual Sensor questions
        // of a vehicle that offers none; and stopped retrying once answered (a slow refresh follows).
        QVERIFY(vehicle.received(msg::QueryDigitalResourceEndpoint) >= 2);
        QCOMPARE(vehicle.received(msg::QueryVisualSensorCapabilities), 0);
        QCOMPARE(vehicle.received(msg::QuerySensorGeometricProperties), 0);
        const int asked = vehicle.received(msg::QueryDigitalResourceEndpoint);
        std::this_thread::sleep_for(std::chrono::milliseconds(2500));
        QVERIFY2(vehicle.received(msg::QueryDigitalResourceEndpoint) <= asked + 1,
                 "still querying every second after the report arrived");
        QCOMPARE(vehicle.malformed(), 0);
        stack.stop();
    }

    // A vehicle that announces nothing: the site configuration's stream for it is published, marked
    // configured.
    void configuredStream() {
        VehicleOptions o;
        o.services = {"urn:jaus:jss:mobility:LocalPoseSensor"};
        ForeignJausVehicle vehicle(o);
        JausConfig c = console(vehicle.port());
        VideoEndpoint ve;
        ve.url = "rtsp://127.0.0.1:8554/mast";
        ve.name = "mast";
        ve.configured = true;
        c.configuredVideo[126] = {ve};
        Quiet quiet;
        JausStack stack(c, quiet);
        stack.start();
        QVERIFY(waitFor([&] { return endpoints(stack).size() == 1; }));
        const auto eps = endpoints(stack);
        QCOMPARE(QString::fromStdString(eps[0].url), QStringLiteral("rtsp://127.0.0.1:8554/mast"));
        QCOMPARE(QString::fromStdString(eps[0].name), QStringLiteral("mast"));
        QVERIFY(eps[0].configured);
        QCOMPARE(vehicle.received(msg::QueryDigitalResourceEndpoint), 0); // it offers no DRD: not asked
        stack.stop();
    }
};

QTEST_GUILESS_MAIN(TestJausForeignVideo)
#include "test_jaus_foreign_video.moc"
