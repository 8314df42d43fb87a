// Teleoperation with video end to end on loopback: a simulated UGV driven through the
// teleop panel (JausBridge, real JAUS on loopback) while the panel plays the vehicle's configured cameras
// from a loopback RTSP server. Receive frames, switch cameras, stop the server -> the video watchdog zeroes
// the drive stream at once (seen by the controller and at the vehicle: it stops on zeros, not by its drive
// timeout), video back -> driving still held until the operator's Resume, then it drives again.
#include "models/FleetContext.h"
#include "models/bridges/JausBridge.h"
#include "models/testing/CommandWait.h"
#include "models/video/VideoPlayer.h"
#include "protocols/jaus/JausStack.h"
#include "sim/jaus/JausDemo.h"
#include "tests/video/TestRtspServer.h"
#include "widgets/jaus/TeleopPanel.h"
#include "widgets/jaus/TeleopVideoPane.h"
#include "widgets/teleop/PanTiltController.h"
#include "widgets/teleop/TeleopController.h"
#include "widgets/teleop/VirtualStick.h"
#include "widgets/video/VideoView.h"

#include <QComboBox>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QVBoxLayout>
#include <QtTest>

#include <cmath>

using namespace ocu;
using namespace ocu::jaus;
using ocu::testing::TestRtspServer;

namespace {

int backgroundGrey(const QImage& img) {
    return img.isNull() ? -1 : qGreen(img.pixel(4, img.height() / 4));
}

struct Site {
    Site() : demo(options()) {
        JausConfig c;
        c.subsystemId = 200;
        c.callSign = "OCU-VIDEO";
        c.role = Role::PrimaryOperator;
        c.authority = 205;
        demo.configure(c);
        bridge = std::make_unique<JausBridge>(c, GeoFrame(options().origin));
        ctx.addBridge(bridge.get());
        const QString e = bridge->start();
        if (!e.isEmpty())
            qFatal("%s", qPrintable(e));
    }
    static sim::JausDemoOptions options() {
        sim::JausDemoOptions o;
        o.count = 1;
        o.alternateKinematics = false;
        return o;
    }
    sim::JausDemo demo;
    FleetContext ctx;
    std::unique_ptr<JausBridge> bridge;
};

} // namespace

class TestTeleopVideo : public QObject {
    Q_OBJECT
private slots:
    void watchdogZeroesTheDriveAndResumeIsDeliberate() {
        TestRtspServer server({{"/front", 60}, {"/rear", 200}}, 640, 360, 30);
        QVERIFY(server.start());
        Site s;
        QTRY_VERIFY_WITH_TIMEOUT(!s.bridge->subsystems().isEmpty(), 20000);
        const quint16 id = s.bridge->subsystems().first();
        sim::SimulatedUgv& ugv = *s.demo.find(id);
        const QString machine = JausVehicleBridge::machineId(id);
        // Control can be requested once the vehicle reported its services.
        QTRY_VERIFY_WITH_TIMEOUT(s.bridge->subsystem(id) && !s.bridge->subsystem(id)->services.isEmpty(),
                                 20000);
        const CommandResult rc = ocu::testing::gateResult([&](CommandGate::ResultHandler h) {
            s.ctx.gate()->command(RequestControl{machine}, QStringLiteral("test"), h);
        });
        QVERIFY2(rc.ok, qPrintable(rc.message));

        TeleopPanel panel(s.bridge.get(), s.ctx.gate(), s.ctx.selection(), nullptr);
        panel.resize(1000, 900);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        JausVideoEndpoint front{1, 1, QString::fromStdString(server.url("/front")), QStringLiteral("front"),
                                true};
        JausVideoEndpoint rear{2, 2, QString::fromStdString(server.url("/rear")), QStringLiteral("rear"),
                               false};
        panel.setConfiguredCameras(id, {front, rear});
        panel.setVehicle(id);
        TeleopVideoPane* video = panel.video();
        QCOMPARE(video->cameraBox()->count(), 2);
        // No video yet: driving waits for it (no latch, no resume needed).
        QTRY_VERIFY_WITH_TIMEOUT(video->player()->state() == VideoState::Playing, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(panel.controller()->isEnabled(), 30000);
        QVERIFY(panel.videoHold().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(video->view()->paintedFrame() > 0, 30000);
        QVERIFY(backgroundGrey(video->player()->currentFrame().image) < 100);
        QVERIFY(video->view()->streamText().contains(QStringLiteral("640×360")));

        // Drive.
        panel.setFocus();
        QSignalSpy commands(panel.controller(), &TeleopController::command);
        QTest::keyPress(&panel, Qt::Key_Shift);
        QTest::keyPress(&panel, Qt::Key_W, Qt::ShiftModifier);
        QTRY_VERIFY_WITH_TIMEOUT(ugv.state().v > 0.3, 20000);
        QTest::keyRelease(&panel, Qt::Key_W, Qt::ShiftModifier);
        QTest::keyRelease(&panel, Qt::Key_Shift);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(ugv.state().v) < 1e-3, 20000);

        // Pan-tilt of the front camera (it has pan-tilt): J pans left, release sends zero.
        QSignalSpy panTilt(&panel, &TeleopPanel::panTiltCommand);
        QTest::keyPress(&panel, Qt::Key_J);
        QVERIFY(!panTilt.isEmpty());
        QCOMPARE(panTilt.last().at(0).value<quint16>(), id);
        QCOMPARE(panTilt.last().at(1).value<quint16>(), quint16(1));
        QVERIFY(panTilt.last().at(2).toDouble() < 0);
        QTest::keyRelease(&panel, Qt::Key_J);
        QCOMPARE(panTilt.last().at(2).toDouble(), 0.0);
        QCOMPARE(panTilt.last().at(3).toDouble(), 0.0);

        // The on-screen stick's camera mode pans instead of driving; leaving the mode sends zero.
        const int drives = commands.size();
        panel.stickCameraButton()->setChecked(true);
        emit panel.stick()->axesChanged(DriveAxes{0.0, 0.7});
        QVERIFY(panTilt.last().at(2).toDouble() > 0);
        QTest::qWait(200);
        QVERIFY(std::abs(ugv.state().v) < 1e-3);
        for (int i = drives; i < commands.size(); ++i)
            QVERIFY(commands.at(i).at(0).value<DriveAxes>().isZero());
        panel.stickCameraButton()->setChecked(false);
        QCOMPARE(panTilt.last().at(2).toDouble(), 0.0);

        // Switch cameras: the rear camera's (bright) picture.
        video->selectCamera(1);
        QTRY_VERIFY_WITH_TIMEOUT(video->player()->state() == VideoState::Playing &&
                                     backgroundGrey(video->player()->currentFrame().image) > 150,
                                 30000);
        QTRY_VERIFY_WITH_TIMEOUT(panel.controller()->isEnabled(), 30000);
        // The rear camera has no pan-tilt: J sends nothing.
        panTilt.clear();
        QTest::keyPress(&panel, Qt::Key_J);
        QTest::keyRelease(&panel, Qt::Key_J);
        QVERIFY(panTilt.isEmpty());

        // Drive, then the camera server dies: the watchdog zeroes the drive at once.
        QTest::keyPress(&panel, Qt::Key_Shift);
        QTest::keyPress(&panel, Qt::Key_W, Qt::ShiftModifier);
        QTRY_VERIFY_WITH_TIMEOUT(ugv.state().v > 0.3, 20000);
        commands.clear();
        server.stop();
        QTRY_VERIFY_WITH_TIMEOUT(!panel.videoHold().isEmpty(), 20000);
        QVERIFY(video->watchdog().tripped());
        QVERIFY2(panel.videoHold().contains(QLatin1String("WATCHDOG")), qPrintable(panel.videoHold()));
        QVERIFY(!commands.isEmpty());
        QVERIFY(commands.last().at(0).value<DriveAxes>().isZero());
        QVERIFY(!panel.controller()->isEnabled());
        QVERIFY(video->view()->alert().contains(QLatin1String("WATCHDOG")));
        // The vehicle stops on the zeros (not by its own drive timeout).
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(ugv.state().v) < 1e-3, 20000);
        QVERIFY(!ugv.state().driveTimedOut);
        // Keys still held or pressed again drive nothing.
        QTest::keyRelease(&panel, Qt::Key_W, Qt::ShiftModifier);
        QTest::keyPress(&panel, Qt::Key_W, Qt::ShiftModifier);
        QTest::qWait(300);
        QVERIFY(std::abs(ugv.state().v) < 1e-3);
        QVERIFY(!video->resumeButton()->isEnabled()); // video still gone
        QTest::keyRelease(&panel, Qt::Key_W, Qt::ShiftModifier);
        QTest::keyRelease(&panel, Qt::Key_Shift);
        // Another camera while tripped: the trip stays (only Resume clears it), also once that camera plays.
        video->selectCamera(0);
        QCOMPARE(video->player()->url(), video->cameras()[0].url);
        QVERIFY(video->watchdog().tripped());
        QVERIFY(!panel.controller()->isEnabled());

        // Video back: still held until the operator resumes.
        QVERIFY(server.start());
        QTRY_VERIFY_WITH_TIMEOUT(video->player()->state() == VideoState::Playing, 60000);
        QTRY_VERIFY_WITH_TIMEOUT(video->resumeButton()->isEnabled(), 30000);
        QVERIFY(video->watchdog().tripped());
        QVERIFY(!panel.controller()->isEnabled());
        QTest::mouseClick(video->resumeButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(panel.controller()->isEnabled(), 20000);
        QVERIFY(panel.videoHold().isEmpty());
        panel.setFocus();
        QTest::keyPress(&panel, Qt::Key_Shift);
        QTest::keyPress(&panel, Qt::Key_W, Qt::ShiftModifier);
        QTRY_VERIFY_WITH_TIMEOUT(ugv.state().v > 0.3, 20000);
        QTest::keyRelease(&panel, Qt::Key_W, Qt::ShiftModifier);
        QTest::keyRelease(&panel, Qt::Key_Shift);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(ugv.state().v) < 1e-3, 20000);
    }

    // A 1366-px laptop's side column (~290 px, the main window's scroll area): the panel fits its width (no
    // horizontal scrolling), the stick stacks above its settings, the picture keeps 16:9 of the width; in a
    // wide dock the stick and its settings are side by side again.
    void narrowDockFits() {
        Site s;
        auto* panel = new TeleopPanel(s.bridge.get(), s.ctx.gate(), s.ctx.selection(), nullptr);
        QScrollArea scroll;
        scroll.setFrameShape(QFrame::NoFrame);
        scroll.setWidgetResizable(true);
        scroll.setWidget(panel);
        scroll.resize(300, 400);
        scroll.show();
        QVERIFY(QTest::qWaitForWindowExposed(&scroll));
        QTRY_VERIFY(panel->width() <= scroll.viewport()->width());
        QVERIFY(!scroll.horizontalScrollBar()->isVisible());
        QVERIFY(panel->stickCameraButton()->y() >= panel->stick()->geometry().bottom());
        VideoView* view = panel->video()->view();
        QVERIFY2(view->height() >= view->width() * 9 / 16 - 1,
                 qPrintable(QStringLiteral("%1x%2").arg(view->width()).arg(view->height())));
        scroll.resize(1000, 900);
        QTRY_VERIFY(panel->stickCameraButton()->x() >= panel->stick()->geometry().right());
        QTRY_COMPARE(panel->width(), scroll.viewport()->width());
    }

    // A pane that is not shown receives and decodes nothing (a teleop panel in a hidden tab costs nothing);
    // shown again, it plays again; the full-screen window keeps it playing while the pane is hidden.
    void hiddenPaneDecodesNothing() {
        TestRtspServer server({{"/front", 60}}, 640, 360, 30);
        QVERIFY(server.start());
        QWidget host;
        auto* pane = new TeleopVideoPane(&host);
        auto* l = new QVBoxLayout(&host);
        l->addWidget(pane);
        host.resize(640, 400);
        // Cameras known before the pane is ever shown: nothing is played.
        pane->setCameras(
            {JausVideoEndpoint{1, 1, QString::fromStdString(server.url("/front")), {}, false, true}});
        QCOMPARE(pane->player()->state(), VideoState::Idle);
        host.show();
        QVERIFY(QTest::qWaitForWindowExposed(&host));
        QTRY_VERIFY_WITH_TIMEOUT(pane->player()->state() == VideoState::Playing, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(pane->watchdog().allowsDriving(), 30000);

        pane->hide();
        QCOMPARE(pane->player()->state(), VideoState::Idle);
        const quint64 frames = pane->player()->status().frames;
        QTest::qWait(500);
        QCOMPARE(pane->player()->status().frames, frames); // nothing decoded meanwhile
        QVERIFY(!pane->watchdog().tripped());              // hiding is not a video loss
        QVERIFY(!pane->watchdog().allowsDriving());        // but nothing is driven without the picture

        pane->show();
        QTRY_VERIFY_WITH_TIMEOUT(pane->player()->state() == VideoState::Playing, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(pane->watchdog().allowsDriving(), 30000);
        QVERIFY(!pane->watchdog().tripped());

        // Full screen, then the pane's tab goes away: the window keeps the stream; closing it stops it.
        pane->openFullScreen();
        QVERIFY(pane->fullScreenWindow());
        pane->hide();
        QVERIFY(pane->player()->isActive());
        pane->closeFullScreen();
        QTRY_VERIFY(!pane->fullScreenWindow());
        QCOMPARE(pane->player()->state(), VideoState::Idle);
    }

    // The detached full-screen window shows the same stream; Esc returns.
    void fullScreenWindowAndEsc() {
        TestRtspServer server({{"/front", 60}}, 640, 360, 30);
        QVERIFY(server.start());
        TeleopVideoPane pane;
        pane.resize(640, 400);
        pane.show();
        pane.setCameras(
            {JausVideoEndpoint{1, 1, QString::fromStdString(server.url("/front")), {}, false, true}});
        QTRY_VERIFY_WITH_TIMEOUT(pane.player()->state() == VideoState::Playing, 30000);
        QTest::mouseClick(pane.fullScreenButton(), Qt::LeftButton);
        QVERIFY(pane.fullScreenWindow());
        QVERIFY(pane.fullScreenWindow()->isWindow());
        auto* view = pane.fullScreenWindow()->findChild<VideoView*>();
        QVERIFY(view);
        QTRY_VERIFY_WITH_TIMEOUT(view->paintedFrame() > 0, 30000);
        QPointer<QWidget> w = pane.fullScreenWindow();
        QTest::keyClick(w, Qt::Key_Escape);
        QTRY_VERIFY(!w);
        QVERIFY(!pane.fullScreenWindow());
    }
};

QTEST_MAIN(TestTeleopVideo)
#include "test_teleop_video.moc"
