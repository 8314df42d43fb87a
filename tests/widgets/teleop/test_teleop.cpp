#include "widgets/teleop/JoystickMappingDialog.h"
#include "widgets/teleop/TeleopController.h"
#include "widgets/teleop/VirtualStick.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QTimer>
#include <QtTest>

using namespace ocu;

class TestTeleop : public QObject {
    Q_OBJECT

    // The controller's stream timer: waits count its periods, not wall time, so a loaded machine that
    // delivers fewer ticks per second cannot make an assertion pass or fail by accident.
    static QTimer* streamTimer(TeleopController& t) { return t.findChild<QTimer*>(); }
    static bool waitPeriods(TeleopController& t, int periods) {
        QSignalSpy ticks(streamTimer(t), &QTimer::timeout);
        for (int guard = 0; ticks.count() < periods && guard < 100; ++guard)
            ticks.wait(200);
        return ticks.count() >= periods;
    }

    static DriveAxes axesAt(const QSignalSpy& spy, int i) { return spy.at(i).at(0).value<DriveAxes>(); }
    static int countZeros(const QSignalSpy& spy, int from = 0) {
        int n = 0;
        for (int i = from; i < spy.size(); ++i)
            n += axesAt(spy, i).isZero() ? 1 : 0;
        return n;
    }

private slots:
    void initTestCase() { qRegisterMetaType<DriveAxes>(); }

    void mappingAndDetection() {
        AxisMapping m;
        m.forwardAxis = 3;
        m.turnAxis = 0;
        m.invertForward = true;
        m.invertTurn = false;
        m.deadZone = 0.2;
        const DriveAxes a = mapAxes({0.6, 0, 0, -1.0}, m);
        QCOMPARE(a.forward, 1.0);
        QCOMPARE(a.turn, 0.5);                    // (0.6 - 0.2) / 0.8
        QCOMPARE(mapAxes({0.1}, m), DriveAxes{}); // missing axis reads 0; small drift is inside the dead zone
        // Detection: the axis that travelled most from rest, at least half its range, with its sign.
        QVERIFY(!detectAxis({0, 0, 0}, {0.3, -0.2, 0.4}));
        auto d = detectAxis({0, 0.1, -1.0}, {0.2, -0.8, -0.9});
        QVERIFY(d);
        QCOMPARE(d->index, 1);
        QVERIFY(d->negative);
        // A trigger resting at -1 that is pulled to +1 is detected by its travel, not its value.
        d = detectAxis({0, -1.0}, {0.1, 1.0});
        QCOMPARE(d->index, 1);
        QVERIFY(!d->negative);
    }

    void mappingDialogPreviewAndDefaults() {
        FakeInputDevice pad;
        AxisMapping m;
        m.forwardAxis = 2;
        m.invertForward = false;
        m.deadZone = 0.0;
        pad.setMapping(m);
        pad.setRaw({0, 0, 0.5, 0});
        JoystickMappingDialog dlg(&pad);
        QCOMPARE(dlg.mapping(), m);
        QCOMPARE(dlg.findChild<QComboBox*>(QStringLiteral("combo-forward-axis"))->count(), 4);
        QCOMPARE(dlg.findChild<QLabel*>(QStringLiteral("label-mapped-preview"))->text(),
                 QStringLiteral("Demand: forward 50 %, turn 0 %"));
        dlg.findChild<QSlider*>(QStringLiteral("slider-dead-zone"))->setValue(25);
        pad.setRaw({0, 0, 0.625, 0}); // live values update the preview: (0.625 - 0.25) / 0.75 = 50 %
        QCOMPARE(dlg.findChild<QLabel*>(QStringLiteral("label-mapped-preview"))->text(),
                 QStringLiteral("Demand: forward 50 %, turn 0 %"));
        QCOMPARE(dlg.mapping().deadZone, 0.25);
        // One axis for both is refused: OK is disabled and the dialog says why.
        auto* ok = dlg.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
        QVERIFY(ok->isEnabled());
        dlg.findChild<QComboBox*>(QStringLiteral("combo-turn-axis"))->setCurrentIndex(2);
        QVERIFY(!ok->isEnabled());
        QCOMPARE(dlg.findChild<QLabel*>(QStringLiteral("label-detect-status"))->text(),
                 QStringLiteral("Forward and turn need two different axes."));
        dlg.setMapping(AxisMapping{});
        QVERIFY(ok->isEnabled());
        QCOMPARE(dlg.mapping(), AxisMapping{});
        QCOMPARE(pad.mapping(), m); // the dialog edits a copy; the panel applies it on OK
    }

    void savedMappingRoundTrip() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().remove(QStringLiteral("teleop"));
        QVERIFY(!loadSavedJoystickMapping(QStringLiteral("Pad A")));
        AxisMapping m;
        m.forwardAxis = 4;
        m.turnAxis = 3;
        m.invertForward = false;
        m.invertTurn = true;
        m.deadZone = 0.3;
        saveJoystickMapping(QStringLiteral("Pad A"), m);
        QCOMPARE(*loadSavedJoystickMapping(QStringLiteral("Pad A")), m);
        QVERIFY(!loadSavedJoystickMapping(QStringLiteral("Pad B"))); // per device name
        QSettings().remove(QStringLiteral("teleop"));
    }

    void keysNeedTheDeadManKey() {
        TeleopController t;
        t.setEnabled(true);
        QSignalSpy spy(&t, &TeleopController::command);
        QVERIFY(t.handleKey(Qt::Key_W, true));
        QVERIFY(waitPeriods(t, 3));
        QCOMPARE(spy.count(), 0);
        QVERIFY(t.handleKey(Qt::Key_Shift, true));
        QCOMPARE(spy.count(), 1);                      // at once, not at the next period
        QCOMPARE(axesAt(spy, 0), (DriveAxes{0.5, 0})); // default limit 50 %
        QVERIFY(!t.handleKey(Qt::Key_Q, true));        // not a driving key
    }
    void streamsAtRateAndZeroesOnRelease() {
        TeleopController t;
        t.setRateHz(20);
        t.setSpeedLimit(1.0);
        t.setEnabled(true);
        QSignalSpy spy(&t, &TeleopController::command);
        QSignalSpy stopped(&t, &TeleopController::stopped);
        t.handleKey(Qt::Key_Shift, true);
        t.handleKey(Qt::Key_Up, true);
        t.handleKey(Qt::Key_Right, true); // +X forward, positive rotation = right turn
        QVERIFY(waitPeriods(t, 4));       // the demand is repeated every period
        QVERIFY2(spy.count() >= 4, qPrintable(QString::number(spy.count())));
        QCOMPARE(axesAt(spy, spy.count() - 1), (DriveAxes{1.0, 1.0}));
        QCOMPARE(countZeros(spy), 0);
        const int before = spy.count();
        t.handleKey(Qt::Key_Up, false);
        t.handleKey(Qt::Key_Right, false);
        QCOMPARE(axesAt(spy, spy.count() - 1), (DriveAxes{})); // zero sent on release at once
        QCOMPARE(stopped.count(), 1);
        QVERIFY(waitPeriods(t, 10)); // the zero is repeated, then the stream goes quiet
        const int zeros = countZeros(spy, before);
        QCOMPARE(zeros, 1 + TeleopController::kZeroRepeats);
        const int after = spy.count();
        QVERIFY(waitPeriods(t, 3));
        QCOMPARE(spy.count(), after);
    }
    void releasingDeadManStops() {
        TeleopController t;
        t.setEnabled(true);
        QSignalSpy spy(&t, &TeleopController::command);
        t.handleKey(Qt::Key_Shift, true);
        t.handleKey(Qt::Key_S, true);
        QCOMPARE(axesAt(spy, 0).forward, -0.5);
        t.handleKey(Qt::Key_Shift, false);
        QVERIFY(axesAt(spy, spy.count() - 1).isZero());
    }
    void focusLossSendsZero() {
        TeleopController t;
        t.setEnabled(true);
        QSignalSpy spy(&t, &TeleopController::command);
        QSignalSpy stopped(&t, &TeleopController::stopped);
        t.handleKey(Qt::Key_Shift, true);
        t.handleKey(Qt::Key_A, true);
        QCOMPARE(axesAt(spy, 0).turn, -0.5);
        t.releaseAll("focus lost");
        QVERIFY(axesAt(spy, spy.count() - 1).isZero());
        QCOMPARE(stopped.at(0).at(0).toString(), QString("focus lost"));
        // Keys held before the focus loss do not resume driving.
        QVERIFY(waitPeriods(t, 3));
        QVERIFY(axesAt(spy, spy.count() - 1).isZero());
        QVERIFY(!t.isDriving());
    }
    void joystickUnplugDuringMotion() {
        TeleopController t;
        t.setSpeedLimit(0.8);
        t.setEnabled(true);
        FakeInputDevice dev;
        t.setDevice(&dev);
        QSignalSpy spy(&t, &TeleopController::command);
        QSignalSpy stopped(&t, &TeleopController::stopped);
        dev.setAxes({1.0, -0.5});
        QCOMPARE(axesAt(spy, 0), (DriveAxes{0.8, -0.4}));
        QVERIFY(waitPeriods(t, 2));
        QVERIFY(t.isDriving());
        QCOMPARE(t.activeSource(), TeleopController::Source::Device);
        dev.unplug();
        QVERIFY(axesAt(spy, spy.count() - 1).isZero());
        QCOMPARE(stopped.count(), 1);
        QCOMPARE(stopped.at(0).at(0).toString(), QString("joystick unplugged"));
        QVERIFY(waitPeriods(t, 3));
        QVERIFY(axesAt(spy, spy.count() - 1).isZero());
    }
    void disablingStops() {
        TeleopController t;
        t.setEnabled(true);
        FakeInputDevice dev;
        t.setDevice(&dev);
        QSignalSpy spy(&t, &TeleopController::command);
        dev.setAxes({0.5, 0});
        t.setEnabled(false); // control lost
        QVERIFY(axesAt(spy, spy.count() - 1).isZero());
        dev.setAxes({1, 0});
        QVERIFY(axesAt(spy, spy.count() - 1).isZero());
    }
    void deadZone() {
        QCOMPARE(applyDeadZone(0.1, 0.12), 0.0);
        QCOMPARE(applyDeadZone(-0.1, 0.12), 0.0);
        QCOMPARE(applyDeadZone(1.0, 0.12), 1.0);
        QCOMPARE(applyDeadZone(-1.0, 0.12), -1.0);
        QVERIFY(std::abs(applyDeadZone(0.56, 0.12) - 0.5) < 1e-9);
    }
    void virtualStickWithMouse() {
        VirtualStick s;
        s.resize(200, 200);
        s.show();
        QVERIFY(QTest::qWaitForWindowExposed(&s));
        TeleopController t;
        t.setSpeedLimit(1.0);
        t.setEnabled(true);
        connect(&s, &VirtualStick::axesChanged, &t, &TeleopController::setStick);
        QSignalSpy spy(&t, &TeleopController::command);
        const QPoint top = s.pointFor({1.0, 0}).toPoint();
        QTest::mousePress(&s, Qt::LeftButton, {}, top);
        QVERIFY(s.axes().forward > 0.95);
        QVERIFY(std::abs(s.axes().turn) < 0.05);
        QVERIFY(axesAt(spy, spy.count() - 1).forward > 0.95);
        QTest::mouseMove(&s, s.pointFor({0, 1.0}).toPoint());
        QTest::mouseRelease(&s, Qt::LeftButton, {}, s.pointFor({0, 1.0}).toPoint());
        QVERIFY(s.axes().isZero());
        QVERIFY(axesAt(spy, spy.count() - 1).isZero());
    }
};

QTEST_MAIN(TestTeleop)
#include "test_teleop.moc"
