// Teleop video against foreign vehicles (tests/protocols/jaus/foreign: an independent JAUS peer sharing no
// code with sim/ or protocols/jaus), end to end through JausBridge into the teleop panel, with the pictures
// from the loopback test RTSP server (tests/video):
//  * a vehicle whose Digital Resource Discovery behaves like other vendors' (silent for its first seconds,
//    every answer late, no optional fields, an HTTP snapshot URL beside the RTSP stream, no Visual Sensor
//    service): its RTSP stream is found and played; the HTTP one is not offered;
//  * a vehicle that announces no video, with an RTSP URL configured for it in the site configuration
//    (static_endpoints[].video -> JausConfig::configuredVideo): that stream is played, marked configured;
//  * a vehicle with no video at all: no camera, nothing played, driving not held by the video watchdog.
#include "models/FleetContext.h"
#include "models/bridges/JausBridge.h"
#include "models/video/VideoPlayer.h"
#include "protocols/common/Udp.h"
#include "tests/protocols/jaus/foreign/ForeignJausVehicle.h"
#include "tests/support/JausLoopback.h"
#include "tests/video/TestRtspServer.h"
#include "widgets/jaus/TeleopPanel.h"
#include "widgets/jaus/TeleopVideoPane.h"
#include "widgets/video/VideoView.h"

#include <QComboBox>
#include <QtTest>

using namespace ocu;
using namespace ocu::jaus;
using foreign::AnnouncedStream;
using foreign::ForeignJausVehicle;
using foreign::VehicleOptions;
using ocu::testing::TestRtspServer;

namespace {

int backgroundGrey(const QImage& img) {
    return img.isNull() ? -1 : qGreen(img.pixel(4, img.height() / 4));
}

VehicleOptions vehicle(std::uint16_t subsystem, const std::string& callSign) {
    VehicleOptions o;
    o.subsystem = subsystem;
    o.callSign = callSign;
    o.services = {"urn:jaus:jss:mobility:LocalPoseSensor"};
    return o;
}

} // namespace

class TestTeleopVideoForeign : public QObject {
    Q_OBJECT
private slots:
    void oddAnnouncedConfiguredAndNone() {
        TestRtspServer server({{"/drive", 60}, {"/mast", 200}}, 640, 360, 30);
        QVERIFY(server.start());

        VehicleOptions odd = vehicle(126, "FOREIGN-126");
        odd.services.push_back("urn:jaus:jss:iop:DigitalResourceDiscovery");
        odd.streams = {
            {"http://127.0.0.1:8080/snapshot.jpg", true, true, 7, 5}, // HTTP: not a pull stream
            {server.url("/drive"), false, false, 0, 0},               // no optional field at all
        };
        odd.drdSilentFirstMs = 2000;
        odd.replyDelayMs = 200;
        ForeignJausVehicle oddVehicle(odd);
        ForeignJausVehicle quietVehicle(vehicle(127, "FOREIGN-127")); // announces no video
        ForeignJausVehicle blindVehicle(vehicle(128, "FOREIGN-128")); // no video at all

        JausConfig c;
        c.subsystemId = 200;
        c.callSign = "OCU-200";
        c.role = Role::PrimaryOperator;
        c.authority = 205;
        c.transport = jaustest::loopback(findFreeUdpPort());
        auto& t = c.transport;
        t.staticEndpoints.push_back(
            StaticEndpoint{JausId{126, 0xFF, 0xFF}, "127.0.0.1", oddVehicle.port(), false});
        t.staticEndpoints.push_back(
            StaticEndpoint{JausId{127, 0xFF, 0xFF}, "127.0.0.1", quietVehicle.port(), false});
        t.staticEndpoints.push_back(
            StaticEndpoint{JausId{128, 0xFF, 0xFF}, "127.0.0.1", blindVehicle.port(), false});
        VideoEndpoint mast;
        mast.url = server.url("/mast");
        mast.name = "mast";
        mast.configured = true;
        c.configuredVideo[127] = {mast};

        FleetContext ctx;
        JausBridge bridge(c, GeoFrame(GeoPoint{48.137154, 11.576124, 520}));
        ctx.addBridge(&bridge);
        QCOMPARE(bridge.start(), QString());
        TeleopPanel panel(&bridge, ctx.gate(), ctx.selection(), nullptr);
        panel.resize(1000, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        TeleopVideoPane* video = panel.video();
        QTRY_VERIFY_WITH_TIMEOUT(bridge.subsystems().size() == 3, 30000);

        // The odd announcer: its RTSP stream only, unnamed (no Visual Sensor), played.
        panel.setVehicle(126);
        QTRY_VERIFY_WITH_TIMEOUT(video->cameras().size() == 1, 30000);
        QCOMPARE(video->cameras()[0].url, QString::fromStdString(server.url("/drive")));
        QVERIFY(!video->cameras()[0].configured);
        QVERIFY(!video->cameras()[0].panTilt);
        QVERIFY(!video->cameraBox()->currentText().isEmpty()); // a name of our own ("camera 0")
        QTRY_VERIFY_WITH_TIMEOUT(video->player()->state() == VideoState::Playing, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(video->view()->paintedFrame() > 0, 30000);
        QVERIFY(backgroundGrey(video->player()->currentFrame().image) < 100);
        QTRY_VERIFY_WITH_TIMEOUT(video->watchdog().allowsDriving(), 30000);
        QVERIFY(oddVehicle.received(0xE702) >= 2); // asked again through its silent start-up
        QCOMPARE(oddVehicle.malformed(), 0);

        // The vehicle that announces nothing: the configured stream, marked so, played.
        panel.setVehicle(127);
        QTRY_VERIFY_WITH_TIMEOUT(video->cameras().size() == 1, 30000);
        QCOMPARE(video->cameras()[0].url, QString::fromStdString(server.url("/mast")));
        QVERIFY(video->cameras()[0].configured);
        QVERIFY(video->cameraBox()->currentText().contains(QLatin1String("configured")));
        QTRY_VERIFY_WITH_TIMEOUT(video->player()->state() == VideoState::Playing &&
                                     backgroundGrey(video->player()->currentFrame().image) > 150,
                                 30000);
        QCOMPARE(quietVehicle.received(0xE702), 0); // it offers no DRD: not asked

        // No video at all: no camera, nothing played, the watchdog does not hold driving.
        panel.setVehicle(128);
        QTRY_VERIFY_WITH_TIMEOUT(panel.video()->cameras().isEmpty(), 10000);
        QCOMPARE(video->player()->state(), VideoState::Idle);
        QVERIFY(!video->watchdog().required());
        QVERIFY(video->watchdog().allowsDriving());
        QVERIFY(panel.videoHold().isEmpty());
        bridge.stop();
    }
};

QTEST_MAIN(TestTeleopVideoForeign)
#include "test_teleop_video_foreign.moc"
