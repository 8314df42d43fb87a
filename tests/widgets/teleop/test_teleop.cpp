#include "widgets/teleop/TeleopController.h"
#include "widgets/teleop/VirtualStick.h"

#include <QSignalSpy>
#include <QtTest>

using namespace ocu;

class TestTeleop : public QObject {
    Q_OBJECT

    static DriveAxes axesAt(const QSignalSpy& spy, int i) { return spy.at(i).at(0).value<DriveAxes>(); }
    static int countZeros(const QSignalSpy& spy, int from = 0) {
        int n = 0;
        for (int i = from; i < spy.size(); ++i)
            n += axesAt(spy, i).isZero() ? 1 : 0;
        return n;
    }

private slots:
    void initTestCase() { qRegisterMetaType<DriveAxes>(); }

    void keysNeedTheDeadManKey() {
        TeleopController t;
        t.setEnabled(true);
        QSignalSpy spy(&t, &TeleopController::command);
        QVERIFY(t.handleKey(Qt::Key_W, true));
        QTest::qWait(150);
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
        QTest::qWait(300);
        QVERIFY2(spy.count() >= 4, qPrintable(QString::number(spy.count())));
        QCOMPARE(axesAt(spy, spy.count() - 1), (DriveAxes{1.0, 1.0}));
        QCOMPARE(countZeros(spy), 0);
        const int before = spy.count();
        t.handleKey(Qt::Key_Up, false);
        t.handleKey(Qt::Key_Right, false);
        QCOMPARE(axesAt(spy, spy.count() - 1), (DriveAxes{})); // zero sent on release at once
        QCOMPARE(stopped.count(), 1);
        QTest::qWait(500); // 10 periods: the zero is repeated, then the stream goes quiet
        const int zeros = countZeros(spy, before);
        QCOMPARE(zeros, 1 + TeleopController::kZeroRepeats);
        const int after = spy.count();
        QTest::qWait(150);
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
        QTest::qWait(120);
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
        QTest::qWait(120);
        QVERIFY(t.isDriving());
        QCOMPARE(t.activeSource(), TeleopController::Source::Device);
        dev.unplug();
        QVERIFY(axesAt(spy, spy.count() - 1).isZero());
        QCOMPARE(stopped.count(), 1);
        QCOMPARE(stopped.at(0).at(0).toString(), QString("joystick unplugged"));
        QTest::qWait(120);
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
