// DriveClient on its own with a FakeClock: a session needs control and no emergency and sends Resume unless
// READY; the demand goes out at once and is streamed at drive_rate_hz; velocity demands are clamped to the
// platform specification and wrench demands to ±100 %; a demand not refreshed within
// drive_command_timeout_s streams zero with one warning; a stop sends stop_repeats zero commands at the drive
// rate, never a single message.
#include <QtTest>

#include <cmath>

#include "protocols/jaus/clients/DriveClient.h"
#include "tests/protocols/jaus/clients/ClientRig.h"

using namespace ocu;
using namespace ocu::jaus;
using namespace ocu::jaus::test;

namespace {

struct DriveRig : ClientRig {
    DriveClient drive{ctx};
    explicit DriveRig(JausConfig c = rigConfig()) : ClientRig(std::move(c)) { drive.registerMessages(table); }
    RemoteSubsystem& controlled(std::uint16_t ss = 126) {
        RemoteSubsystem& r = vehicle(ss);
        r.snap.controlledByUs = true;
        r.snap.management = ManagementState::Ready;
        return r;
    }
    void run(RemoteSubsystem& r, double seconds) {
        runFor(seconds, [&](TimePoint now) { drive.tick(r, now); });
    }
    std::vector<VelocityCommand> velocities() const {
        std::vector<VelocityCommand> v;
        for (auto& s : out.sent)
            if (s.id() == msg::SetVelocityCommand)
                v.push_back(*decodeVelocityCommand(s.payload));
        return v;
    }
};

DriveCommand forward(double v, double yawRate = 0) {
    DriveCommand c;
    c.linear = v;
    c.angular = yawRate;
    return c;
}

} // namespace

class TestDriveClient : public QObject {
    Q_OBJECT

private slots:
    void sessionNeedsControlAndNoEmergency() {
        DriveRig rig;
        RemoteSubsystem& r = rig.vehicle();
        QVERIFY(!rig.drive.startDriving(126));
        QVERIFY(!rig.drive.setDriveCommand(126, forward(1)));
        r.snap.controlledByUs = true;
        r.snap.emergency = true;
        QVERIFY(!rig.drive.startDriving(126));
        QCOMPARE(rig.rec.count(EventKind::CommandRefused), 3);
        QVERIFY(rig.out.sent.empty());
        r.snap.emergency = false;
        r.snap.management = ManagementState::Standby;
        QVERIFY(rig.drive.startDriving(126));
        // Drivers obey only in READY: Resume first; then the session's first (zero) demand, at once.
        QCOMPARE(rig.out.ids(),
                 (std::vector<std::uint16_t>{msg::Resume, msg::QueryStatus, msg::SetVelocityCommand}));
        QVERIFY(r.snap.driving);

        DriveRig monitor(rigConfig(0));
        monitor.controlled();
        QVERIFY(!monitor.drive.startDriving(126));
    }

    void demandSentAtOnceThenStreamed() {
        DriveRig rig; // 20 Hz
        RemoteSubsystem& r = rig.controlled();
        QVERIFY(rig.drive.startDriving(126));
        rig.run(r, 0.01);
        QCOMPARE(rig.out.count(msg::SetVelocityCommand), 1); // the stream starts with zero demand
        QVERIFY(rig.drive.setDriveCommand(126, forward(1.5, 0.3)));
        QCOMPARE(rig.out.count(msg::SetVelocityCommand), 2); // at once, not at the next period
        auto v = rig.velocities().back();
        QVERIFY(std::abs(*v.vx - 1.5) < 1e-3 && std::abs(*v.yawRate - 0.3) < 1e-3);
        QCOMPARE(rig.out.last(msg::SetVelocityCommand)->destination, ClientRig::mobility());
        QVERIFY(rig.drive.setDriveCommand(126, forward(1.5, 0.3))); // same demand: no extra message
        QCOMPARE(rig.out.count(msg::SetVelocityCommand), 2);
        for (int i = 0; i < 10; ++i) { // refreshed every 0.1 s, streamed every 0.05 s
            rig.run(r, 0.1);
            QVERIFY(rig.drive.setDriveCommand(126, forward(1.5, 0.3)));
        }
        QCOMPARE(rig.out.count(msg::SetVelocityCommand), 22);
        QCOMPARE(rig.counters.get("tx.drive"), std::uint64_t(22));
    }

    // What the drive commands return says whether the socket took the message; a stream
    // that stops reaching the socket is one error event per failing streak (not one per 20 Hz message) and
    // one when it goes out again.
    void driveCommandsSayWhatWentOnTheWire() {
        DriveRig rig;
        RemoteSubsystem& r = rig.controlled();
        rig.out.failWith = "the JAUS transport is closed";
        QVERIFY(!rig.drive.startDriving(126));
        QVERIFY(
            QString::fromStdString(rig.ctx.lastRefusal()).contains("not sent: the JAUS transport is closed"));
        QCOMPARE(rig.rec.count(EventKind::DriveNotSent), 1);
        rig.out.failWith.clear();
        QVERIFY(rig.drive.startDriving(126));
        QVERIFY(rig.drive.setDriveCommand(126, forward(1)));
        rig.out.failWith = "No buffer space available";
        QVERIFY(!rig.drive.setDriveCommand(126, forward(1.2)));
        QVERIFY(QString::fromStdString(rig.ctx.lastRefusal()).contains("No buffer space available"));
        QCOMPARE(rig.rec.count(EventKind::DriveNotSent), 2);
        for (int i = 0; i < 5; ++i) { // the stream keeps failing at 20 Hz: still one event
            rig.run(r, 0.1);
            QVERIFY(!rig.drive.setDriveCommand(126, forward(1.2)));
        }
        QCOMPARE(rig.rec.count(EventKind::DriveNotSent), 2);
        QVERIFY(rig.counters.get("tx.drive.failed") >= 10);
        rig.out.failWith.clear();
        rig.run(r, 0.1);
        QCOMPARE(rig.rec.count(EventKind::DriveNotSent), 3); // "going out again"
        QVERIFY(rig.drive.setDriveCommand(126, forward(1.2)));
        rig.out.failWith = "Network is unreachable";
        QVERIFY(!rig.drive.stopDriving(126)); // the first zero was not taken
        rig.out.failWith.clear();
        r.snap.controlledByUs = false;
        QVERIFY(!rig.drive.stopDriving(126)); // not controlled: no zeros go out, and the result says so
        QVERIFY(QString::fromStdString(rig.ctx.lastRefusal()).contains("does not control"));
    }

    void clampedToPlatformAndPercent() {
        DriveRig rig;
        RemoteSubsystem& r = rig.controlled();
        PlatformSpecifications spec;
        spec.maxForwardSpeed = 2;
        spec.maxReverseSpeed = 0.5;
        spec.maxRotationalSpeed = 1;
        r.snap.platform = spec;
        QVERIFY(rig.drive.startDriving(126));
        QVERIFY(rig.drive.setDriveCommand(126, forward(50, -9)));
        auto v = rig.velocities().back();
        QVERIFY(std::abs(*v.vx - 2) < 1e-3 && std::abs(*v.yawRate + 1) < 1e-3);
        QVERIFY(rig.drive.setDriveCommand(126, forward(-3, 9)));
        v = rig.velocities().back();
        QVERIFY(std::abs(*v.vx + 0.5) < 1e-3 && std::abs(*v.yawRate - 1) < 1e-3);

        JausConfig c = rigConfig();
        c.velocityDrive = false;
        DriveRig wrench(c);
        wrench.controlled();
        QVERIFY(wrench.drive.startDriving(126));
        DriveCommand w;
        w.mode = DriveCommand::Mode::Wrench;
        w.linear = 150;
        w.angular = -150;
        w.brake = -5;
        QVERIFY(wrench.drive.setDriveCommand(126, w));
        auto we = decodeWrench(wrench.out.last(msg::SetWrenchEffort)->payload);
        QVERIFY(we && std::abs(*we->propLinX - 100) < 1e-2 && std::abs(*we->propRotZ + 100) < 1e-2 &&
                std::abs(*we->resLinX) < 1e-9);
    }

    void staleDemandStreamsZero() {
        DriveRig rig; // watchdog 0.5 s
        RemoteSubsystem& r = rig.controlled();
        QVERIFY(rig.drive.startDriving(126));
        QVERIFY(rig.drive.setDriveCommand(126, forward(1)));
        rig.run(r, 0.5);
        QVERIFY(*rig.velocities().back().vx > 0.9);
        rig.run(r, 0.1);
        QVERIFY(std::abs(*rig.velocities().back().vx) < 1e-6);
        QCOMPARE(rig.rec.count(EventKind::CommandRefused), 1);
        rig.run(r, 2);
        QCOMPARE(rig.rec.count(EventKind::CommandRefused), 1); // warned once
        QVERIFY(r.snap.driving);                               // still open, streaming zero
        QVERIFY(rig.drive.setDriveCommand(126, forward(1)));   // a fresh demand drives again
        QVERIFY(*rig.velocities().back().vx > 0.9);
    }

    void stopSendsSeveralZeros() {
        JausConfig c = rigConfig();
        c.stopRepeats = 4;
        DriveRig rig(c);
        RemoteSubsystem& r = rig.controlled();
        QVERIFY(rig.drive.startDriving(126));
        QVERIFY(rig.drive.setDriveCommand(126, forward(1)));
        rig.out.sent.clear();
        QVERIFY(rig.drive.stopDriving(126));
        QCOMPARE(rig.out.count(msg::SetVelocityCommand), 1); // the first zero at once
        QVERIFY(r.snap.driving);                             // until the last zero is out
        QVERIFY(rig.drive.anyActive());
        QVERIFY(!rig.drive.setDriveCommand(126, forward(1))); // the session is closed
        rig.run(r, 1);
        QCOMPARE(rig.out.count(msg::SetVelocityCommand), 4);
        for (auto& v : rig.velocities())
            QVERIFY(std::abs(*v.vx) < 1e-6 && std::abs(*v.yawRate) < 1e-6);
        QVERIFY(!r.snap.driving);
        QVERIFY(!rig.drive.anyActive());
    }

    void endSessionKeepsOrDropsTheZeroTail() {
        DriveRig rig;
        RemoteSubsystem& r = rig.controlled();
        QVERIFY(rig.drive.startDriving(126));
        QVERIFY(rig.drive.stopDriving(126));
        rig.drive.endSession(r, false);
        QVERIFY(rig.drive.anyActive()); // the zeros of the stop still go out
        rig.drive.endSession(r, true);
        QVERIFY(!rig.drive.anyActive());
        QVERIFY(!r.snap.driving);
    }
};

QTEST_GUILESS_MAIN(TestDriveClient)
#include "test_drive_client.moc"
