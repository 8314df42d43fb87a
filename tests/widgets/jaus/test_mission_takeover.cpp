// Taking the stick over a running mission in the teleop panel (offscreen, a fake JAUS vehicle): the first
// stick demand asks the operator instead of opening a drive session; "Pause and drive" sends mission_pause
// through the command gate, and the drive session opens only once the gate confirms the pause from the
// vehicle's report; "Keep the mission", a refused pause or an unconfirmed one never drive; without a
// running mission the stick drives at once.
#include "models/CommandGate.h"
#include "models/FleetContext.h"
#include "models/jaus/JausVehicleBridge.h"
#include "widgets/jaus/MissionTakeover.h"
#include "widgets/jaus/TeleopPanel.h"
#include "widgets/teleop/InputDevice.h"

#include <QLabel>
#include <QMap>
#include <QMessageBox>
#include <QPushButton>
#include <QtTest>

using namespace ocu;

namespace {

// A vehicle we control, running a five-waypoint mission; what the gate hands over is kept, and the pause
// is answered as the test says (the vehicle's report, a refusal, or silence).
class FakeJausBridge final : public JausVehicleBridge {
public:
    enum class PauseAnswer { Reports, Refuses, Silent };
    PauseAnswer pauseAnswer = PauseAnswer::Reports;
    JausVehicle vehicle;
    QVector<OperatorCommand> commands;
    int drives = 0;

    FakeJausBridge() {
        vehicle.subsystem = 126;
        vehicle.callSign = QStringLiteral("UGV-126");
        vehicle.link = JausLink::Up;
        vehicle.access = JausAccess::ControlAccepted;
        vehicle.controlledByUs = true;
        vehicle.management = JausManagement::Ready;
        vehicle.mission.state = MissionState::Running;
        vehicle.mission.waypoints.resize(5);
        vehicle.mission.activeIndex = 2;
    }
    JausConsoleIdentity identity() const override {
        return {QStringLiteral("OCU"), 200, 205, true, true, true, 20, {}};
    }
    QList<quint16> subsystems() const override { return {126}; }
    std::optional<JausVehicle> subsystem(quint16 id) const override {
        return id == 126 ? std::optional<JausVehicle>(vehicle) : std::nullopt;
    }
    CommandResult drive(quint16, const JausDrive&) override {
        ++drives;
        return CommandResult::success();
    }
    CommandResult stopDriving(quint16) override { return CommandResult::success(); }
    void stopAll(OutcomeCallback done) override { done({}); }
    void stopMachine(const QString&, OutcomeCallback done) override { done({}); }
    void clearStop(const QString&, OutcomeCallback done) override { done({}); }
    bool confirmsCommand(const QString& action) const override { return action == "mission_pause"; }
    bool reportsConfirmed(const QString& action, const QString&) const override {
        return action == "mission_pause" && vehicle.mission.state != MissionState::Running;
    }
    void report() { emit subsystemUpdated(vehicle); }
    void command(const OperatorCommand& c, OutcomeCallback done) override {
        commands << c;
        const std::string target = commandTarget(c).toStdString();
        if (std::holds_alternative<MissionPause>(c) && pauseAnswer == PauseAnswer::Refuses) {
            done({refusal(QString::fromStdString(target), OutcomeReason::NotControlled,
                          "the list driver is controlled by another console")});
            return;
        }
        done({TargetOutcome::sentTo(target)});
        if (std::holds_alternative<MissionPause>(c) && pauseAnswer == PauseAnswer::Reports)
            QTimer::singleShot(50, this, [this] { // the vehicle's report comes later, as on the wire
                vehicle.mission.state = MissionState::Paused;
                report();
                emit commandReported("mission_pause", machineId(126), "UGV-126 reports the mission paused");
            });
    }
    QStringList names() const {
        QStringList out;
        for (const OperatorCommand& c : commands)
            out << commandName(c);
        return out;
    }
};

struct Rig {
    FakeJausBridge bridge;
    FleetContext ctx;
    FakeInputDevice pad;
    TeleopPanel* panel;
    Rig() {
        ctx.addBridge(&bridge);
        ctx.gate()->setConfirmTimeoutMs(400);
        panel = new TeleopPanel(&bridge, ctx.gate(), ctx.selection(), &pad);
        panel->setVehicle(126);
        panel->resize(700, 800);
        panel->show();
    }
    ~Rig() { delete panel; }
    QMessageBox* question() const { return panel->missionTakeover()->question(); }
    void answer(bool drive) {
        QMessageBox* box = question();
        QVERIFY(box);
        for (QAbstractButton* b : box->buttons())
            if (box->buttonRole(b) == (drive ? QMessageBox::AcceptRole : QMessageBox::RejectRole)) {
                b->click();
                return;
            }
        QFAIL("no such button");
    }
};

} // namespace

class TestMissionTakeover : public QObject {
    Q_OBJECT
private slots:
    void confirmedTakeoverPausesThenDrives() {
        Rig r;
        QVERIFY(QTest::qWaitForWindowExposed(r.panel));
        r.pad.setAxes({0.5, 0});
        QTRY_VERIFY(r.question());
        QVERIFY(r.question()->text().contains("UGV-126 is running a mission (waypoint 3 of 5)"));
        QVERIFY(r.bridge.commands.isEmpty()); // nothing before the operator answers
        QVERIFY(!r.panel->sessionOpen());
        r.answer(true);
        QTRY_COMPARE(r.bridge.names(), (QStringList{"mission_pause", "drive_start"}));
        QCOMPARE(std::get<MissionPause>(r.bridge.commands[0]).id, QStringLiteral("jaus:126"));
        QCOMPARE(r.bridge.vehicle.mission.state, MissionState::Paused); // drive_start came after the report
        QTRY_VERIFY(r.panel->sessionOpen());
        QTRY_VERIFY(r.bridge.drives > 0);
        QVERIFY(!r.panel->missionTakeover()->pending());
    }

    void keepingTheMissionNeverDrives() {
        Rig r;
        QVERIFY(QTest::qWaitForWindowExposed(r.panel));
        r.pad.setAxes({0.5, 0});
        QTRY_VERIFY(r.question());
        r.answer(false);
        QTest::qWait(100);
        QVERIFY(r.bridge.commands.isEmpty());
        QCOMPARE(r.bridge.drives, 0);
        QVERIFY2(r.panel->driveProblem().contains("kept the mission"), qPrintable(r.panel->driveProblem()));
        // Still held: no new question per demand; released and pushed again: asked again.
        r.pad.setAxes({0.6, 0});
        QTest::qWait(50);
        QVERIFY(!r.question());
        r.pad.setAxes({0, 0});
        r.pad.setAxes({0.5, 0});
        QTRY_VERIFY(r.question());
    }

    void refusedOrUnconfirmedPauseNeverDrives() {
        for (auto answer : {FakeJausBridge::PauseAnswer::Refuses, FakeJausBridge::PauseAnswer::Silent}) {
            Rig r;
            r.bridge.pauseAnswer = answer;
            QVERIFY(QTest::qWaitForWindowExposed(r.panel));
            r.pad.setAxes({0.5, 0});
            QTRY_VERIFY(r.question());
            r.answer(true);
            QTRY_VERIFY(
                r.panel->driveProblem().startsWith("Drive session NOT started: the mission was not paused"));
            QTest::qWait(100);
            QCOMPARE(r.bridge.names(), QStringList{"mission_pause"});
            QCOMPARE(r.bridge.drives, 0);
            QVERIFY(!r.panel->sessionOpen());
        }
    }

    void withoutARunningMissionTheStickDrivesAtOnce() {
        Rig r;
        r.bridge.vehicle.mission.state = MissionState::Paused;
        r.bridge.report();
        QVERIFY(QTest::qWaitForWindowExposed(r.panel));
        r.pad.setAxes({0.5, 0});
        QTRY_COMPARE(r.bridge.names(), QStringList{"drive_start"});
        QVERIFY(!r.question());
        QTRY_VERIFY(r.panel->sessionOpen());
    }
};

QTEST_MAIN(TestMissionTakeover)
#include "test_mission_takeover.moc"
