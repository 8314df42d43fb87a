// The pan-tilt demand stream: keys J/L/I/K, the on-screen stick's camera mode and a joystick
// hat give rate demands; a change goes out at once, is repeated while it lasts, and release, focus loss,
// unplugging or disabling send a zero at once, repeated a few periods.
#include "widgets/teleop/PanTiltController.h"

#include <QSignalSpy>
#include <QTest>

using namespace ocu;

class TestPanTilt : public QObject {
    Q_OBJECT
private slots:
    void keysStickHatAndZeroOnRelease() {
        PanTiltController c;
        QSignalSpy cmd(&c, &PanTiltController::command);
        QSignalSpy stopped(&c, &PanTiltController::stopped);
        // Disabled: nothing moves.
        QVERIFY(c.handleKey(Qt::Key_L, true));
        QVERIFY(cmd.isEmpty() || cmd.last().at(0).toDouble() == 0);
        c.handleKey(Qt::Key_L, false);
        c.setEnabled(true);
        cmd.clear();

        c.handleKey(Qt::Key_L, true);
        QCOMPARE(cmd.last().at(0).toDouble(), 0.5);
        c.handleKey(Qt::Key_I, true);
        QCOMPARE(cmd.last().at(1).toDouble(), 0.5);
        QVERIFY(!c.handleKey(Qt::Key_W, true)); // not a camera key
        // Repeated while held.
        const int n = cmd.size();
        QTRY_VERIFY(cmd.size() > n + 2);
        QCOMPARE(cmd.last().at(0).toDouble(), 0.5);
        c.handleKey(Qt::Key_I, false);
        c.handleKey(Qt::Key_L, false);
        QCOMPARE(cmd.last().at(0).toDouble(), 0.0);
        QCOMPARE(cmd.last().at(1).toDouble(), 0.0);
        QCOMPARE(stopped.size(), 1);

        // The stick in camera mode: turn pans, forward tilts, at its deflection.
        c.setStick({-0.8, 0.3});
        QCOMPARE(cmd.last().at(0).toDouble(), 0.3);
        QCOMPARE(cmd.last().at(1).toDouble(), -0.8);
        c.releaseAll(QStringLiteral("focus lost"));
        QCOMPARE(cmd.last().at(0).toDouble(), 0.0);
        QCOMPARE(stopped.last().at(0).toString(), QStringLiteral("focus lost"));
        // Zeros repeated a few periods, then silence.
        QTRY_VERIFY(cmd.size() >= 3);
        QTest::qWait(600);
        const int settled = cmd.size();
        QTest::qWait(400);
        QCOMPARE(cmd.size(), settled);

        // A joystick hat; unplugging sends zero at once.
        FakeInputDevice dev;
        c.setDevice(&dev);
        dev.setHat({-1, 1});
        QCOMPARE(cmd.last().at(0).toDouble(), -0.5);
        QCOMPARE(cmd.last().at(1).toDouble(), 0.5);
        dev.unplug();
        QCOMPARE(cmd.last().at(0).toDouble(), 0.0);
        QCOMPARE(cmd.last().at(1).toDouble(), 0.0);

        // Disabling (control lost) while moving: zero at once.
        dev.plug();
        dev.setHat({1, 0});
        QCOMPARE(cmd.last().at(0).toDouble(), 0.5);
        c.setEnabled(false);
        QCOMPARE(cmd.last().at(0).toDouble(), 0.0);
    }
};

QTEST_MAIN(TestPanTilt)
#include "test_pan_tilt.moc"
