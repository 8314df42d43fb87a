// Teleop video on loopback, against the simulated UGV's own cameras (sim/jaus): the console
// discovers the cameras through the IOP services (Digital Resource Discovery, Visual Sensor), plays the front
// one in the teleop panel, pans it from the keyboard (the unit's joint moves), switches to the rear camera,
// drives; the UGV's RTSP server stops -> the watchdog zeroes the drive (the UGV stops on zeros, not by its
// drive timeout); the server is back -> frames again, driving only after the operator's Resume.
#include "models/FleetContext.h"
#include "models/bridges/JausBridge.h"
#include "models/testing/CommandWait.h"
#include "models/video/VideoPlayer.h"
#include "protocols/jaus/JausStack.h"
#include "sim/jaus/JausDemo.h"
#include "widgets/jaus/TeleopPanel.h"
#include "widgets/jaus/TeleopVideoPane.h"
#include "widgets/teleop/TeleopController.h"
#include "widgets/video/VideoView.h"

#include <QComboBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QtTest>

#include <cmath>

using namespace ocu;
using namespace ocu::jaus;

class TestTeleopVideoSim : public QObject {
    Q_OBJECT
private slots:
    void discoverPlaySwitchLoseAndResume() {
        sim::JausDemoOptions o;
        o.count = 1;
        o.alternateKinematics = false;
        o.video = true;
        sim::JausDemo demo(o);
        JausConfig c;
        c.subsystemId = 200;
        c.callSign = "OCU-VIDEO";
        c.role = Role::PrimaryOperator;
        c.authority = 205;
        demo.configure(c);
        FleetContext ctx;
        JausBridge bridge(c, GeoFrame(o.origin));
        ctx.addBridge(&bridge);
        QCOMPARE(bridge.start(), QString());
        sim::SimulatedUgv& ugv = *demo.ugvs().front();

        TeleopPanel panel(&bridge, ctx.gate(), ctx.selection(), nullptr);
        panel.resize(1000, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QTRY_VERIFY_WITH_TIMEOUT(!bridge.subsystems().isEmpty(), 20000);
        const quint16 id = bridge.subsystems().first();
        panel.setVehicle(id);
        TeleopVideoPane* video = panel.video();

        // Discovered through the IOP services: two announced cameras, the front one on the pan-tilt.
        // (the endpoints come from Digital Resource Discovery first, the names and the pan-tilt mount from
        // the Visual Sensor and Pan Tilt services a little later)
        QTRY_VERIFY_WITH_TIMEOUT(video->cameras().size() == 2 && video->cameras()[0].panTilt, 30000);
        QVERIFY(!video->cameras()[0].configured);
        QVERIFY(!video->cameras()[1].panTilt);
        QCOMPARE(video->cameras()[0].url,
                 QString::fromStdString(ugv.cameraUrl(video->cameras()[0].sensorId)));
        QTRY_VERIFY_WITH_TIMEOUT(video->player()->state() == VideoState::Playing, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(video->view()->paintedFrame() > 0, 30000);
        QVERIFY(video->player()->status().ageFromTimeCode);

        QTRY_VERIFY_WITH_TIMEOUT(bridge.subsystem(id) && !bridge.subsystem(id)->services.isEmpty(), 20000);
        const CommandResult rc = ocu::testing::gateResult([&](CommandGate::ResultHandler h) {
            ctx.gate()->command(RequestControl{JausVehicleBridge::machineId(id)}, QStringLiteral("test"), h);
        });
        QVERIFY2(rc.ok, qPrintable(rc.message));
        QTRY_VERIFY_WITH_TIMEOUT(panel.controller()->isEnabled(), 30000);

        // Pan the front camera right with L: the unit's joint moves; release stops it.
        panel.setFocus();
        const double pan0 = ugv.panTilt().pan;
        QTest::keyPress(&panel, Qt::Key_L);
        QTRY_VERIFY_WITH_TIMEOUT(ugv.panTilt().pan > pan0 + 0.2, 30000);
        QTest::keyRelease(&panel, Qt::Key_L);

        // Switch to the rear camera.
        const quint64 framesFront = video->player()->status().frames;
        video->selectCamera(1);
        QCOMPARE(video->player()->url(), video->cameras()[1].url);
        QTRY_VERIFY_WITH_TIMEOUT(
            video->player()->state() == VideoState::Playing && video->player()->status().frames > 3, 30000);
        Q_UNUSED(framesFront);
        QTRY_VERIFY_WITH_TIMEOUT(panel.controller()->isEnabled(), 30000);

        // Drive; the cameras' server dies: the watchdog zeroes the drive stream at once.
        QSignalSpy commands(panel.controller(), &TeleopController::command);
        QTest::keyPress(&panel, Qt::Key_Shift);
        QTest::keyPress(&panel, Qt::Key_W, Qt::ShiftModifier);
        QTRY_VERIFY_WITH_TIMEOUT(ugv.state().v > 0.3, 20000);
        ugv.stopCameras();
        QTRY_VERIFY_WITH_TIMEOUT(video->watchdog().tripped(), 20000);
        QVERIFY(panel.videoHold().contains(QLatin1String("WATCHDOG")));
        QVERIFY(commands.last().at(0).value<DriveAxes>().isZero());
        QVERIFY(!panel.controller()->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(ugv.state().v) < 1e-3, 20000);
        QVERIFY(!ugv.state().driveTimedOut);
        QTest::keyRelease(&panel, Qt::Key_W, Qt::ShiftModifier);
        QTest::keyRelease(&panel, Qt::Key_Shift);

        // Back: frames again; driving only after Resume.
        QCOMPARE(ugv.startCameras(), std::string());
        QTRY_VERIFY_WITH_TIMEOUT(video->player()->state() == VideoState::Playing, 60000);
        QTRY_VERIFY_WITH_TIMEOUT(video->resumeButton()->isEnabled(), 30000);
        QVERIFY(!panel.controller()->isEnabled());
        QTest::mouseClick(video->resumeButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(panel.controller()->isEnabled(), 20000);
        panel.setFocus();
        QTest::keyPress(&panel, Qt::Key_Shift);
        QTest::keyPress(&panel, Qt::Key_W, Qt::ShiftModifier);
        QTRY_VERIFY_WITH_TIMEOUT(ugv.state().v > 0.3, 20000);
        QTest::keyRelease(&panel, Qt::Key_W, Qt::ShiftModifier);
        QTest::keyRelease(&panel, Qt::Key_Shift);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(ugv.state().v) < 1e-3, 20000);
        bridge.stop();
    }
};

QTEST_MAIN(TestTeleopVideoSim)
#include "test_teleop_video_sim.moc"
