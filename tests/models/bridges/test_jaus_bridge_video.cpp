// Video at the bridge: a simulated UGV's cameras, discovered through the IOP services by the JAUS stack,
// reach the panels' view (JausVehicle::videoEndpoints: sensor ID, name, RTSP URL, pan-tilt flag), a stream
// configured for the vehicle is listed beside them, and JausVehicleBridge::panTilt follows the rules of
// driving (refused without control, with the reason; handed to the stack with control, and the UGV's pan-tilt
// unit moves).
#include "models/bridges/JausBridge.h"
#include "models/testing/CommandWait.h"
#include "sim/jaus/JausDemo.h"

#include <QSignalSpy>
#include <QtTest>

using namespace ocu;

namespace {

sim::JausDemoOptions videoUgv() {
    sim::JausDemoOptions o;
    o.count = 1;
    o.alternateKinematics = false;
    o.video = true;
    return o;
}

jaus::JausConfig consoleConfig(const sim::JausDemo& demo) {
    jaus::JausConfig c;
    c.subsystemId = 200;
    c.callSign = "OCU-TEST";
    demo.configure(c);
    jaus::VideoEndpoint mast;
    mast.url = "rtsp://127.0.0.1:1/mast";
    mast.name = "mast";
    mast.configured = true;
    c.configuredVideo[126] = {mast};
    return c;
}

} // namespace

class TestJausBridgeVideo : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        static QTemporaryDir dir; // GStreamer's registry never in the user's home
        qputenv("GST_REGISTRY", (dir.path() + QStringLiteral("/registry.bin")).toLocal8Bit());
    }

    void endpointsAndPanTilt() {
        sim::JausDemo demo(videoUgv());
        sim::SimulatedUgv* ugv = demo.find(126);
        QVERIFY(ugv);
        JausBridge bridge(consoleConfig(demo), GeoFrame(videoUgv().origin));
        QVERIFY(bridge.start().isEmpty());
        auto named = [&] {
            auto v = bridge.subsystem(126);
            if (!v || v->videoEndpoints.size() != 3)
                return false;
            for (const JausVideoEndpoint& e : v->videoEndpoints)
                if (e.name.isEmpty())
                    return false;
            return true;
        };
        QTRY_VERIFY_WITH_TIMEOUT(named(), 30000);
        const auto eps = bridge.subsystem(126)->videoEndpoints;
        QCOMPARE(eps[0].sensorId, quint16(1000));
        QCOMPARE(eps[0].name, QStringLiteral("front (pan-tilt)"));
        QCOMPARE(eps[0].url, QString::fromStdString(ugv->cameraUrl(1000)));
        QVERIFY(eps[0].panTilt && !eps[0].configured);
        QCOMPARE(eps[1].name, QStringLiteral("rear"));
        QVERIFY(!eps[1].panTilt);
        QCOMPARE(eps[2].url, QStringLiteral("rtsp://127.0.0.1:1/mast"));
        QVERIFY(eps[2].configured);

        // Without control: refused at once, nothing handed to the stack.
        const CommandResult refused = bridge.panTilt(126, 1000, 0.5, 0);
        QVERIFY(!refused.ok);
        QVERIFY2(refused.message.contains(QStringLiteral("does not control")), qPrintable(refused.message));

        // With control: the demands go out (refreshed like a held key) and the unit turns.
        const CommandResult rc = testing::bridgeResult(
            [&](OutcomeCallback d) { bridge.command(RequestControl{QStringLiteral("jaus:126")}, d); });
        QVERIFY2(rc.ok, qPrintable(rc.message));
        QTRY_VERIFY_WITH_TIMEOUT(bridge.subsystem(126) && bridge.subsystem(126)->controlledByUs, 20000);
        QTRY_VERIFY_WITH_TIMEOUT((bridge.panTilt(126, 1000, -0.6, 0.2).ok && ugv->panTilt().pan < -0.3),
                                 20000);
        QVERIFY(ugv->panTilt().tilt > 0.05);
        QVERIFY(bridge.panTilt(126, 1000, 0, 0).ok);
        bridge.stop();
    }
};

QTEST_MAIN(TestJausBridgeVideo)
#include "test_jaus_bridge_video.moc"
