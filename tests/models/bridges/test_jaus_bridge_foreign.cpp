// JausBridge + CommandGate against the foreign JAUS vehicle (tests/protocols/jaus/foreign), end to end over
// loopback:
// - confirmation beyond stops: request_control, clear_stop and release_control are confirmed by the
//   vehicle's own reports (an event with the latency), and a command the vehicle never answers raises a
//   Timeout alarm after the confirmation time;
// - targets per machine: with the stack stopped, stop_all names every vehicle the console knows (heard
//   earlier, or a configured static endpoint), each with its reason, and the JAUS link shows stopped.
#include "models/AlarmModel.h"
#include "models/CommandGate.h"
#include "models/bridges/JausBridge.h"
#include "models/testing/CommandWait.h"
#include "protocols/common/GeoFrame.h"
#include "protocols/common/Udp.h"
#include "tests/protocols/jaus/foreign/ForeignJausVehicle.h"
#include "tests/support/JausLoopback.h"

#include <QJsonObject>
#include <QSignalSpy>
#include <QtTest>

using namespace ocu;
using namespace ocu::jaus;
using ocu::testing::gateResult;

namespace {

JausConfig consoleConfig(std::uint16_t vehiclePort, std::uint16_t neverHeardPort) {
    JausConfig c;
    c.subsystemId = 151;
    c.callSign = "OCU-151";
    c.role = Role::PrimaryOperator;
    c.authority = 205;
    c.statusPollHz = 2;
    c.linkLostS = 1.5;
    c.accessTimeoutS = 3;
    c.transport = jaustest::loopback(findFreeUdpPort());
    auto& t = c.transport;
    t.staticEndpoints.push_back(StaticEndpoint{JausId{126, 0xFF, 0xFF}, "127.0.0.1", vehiclePort, false});
    // A configured vehicle that never answers (nobody listens there).
    t.staticEndpoints.push_back(StaticEndpoint{JausId{127, 0xFF, 0xFF}, "127.0.0.1", neverHeardPort, false});
    return c;
}

bool hasTimeoutAlarm(const AlarmModel& alarms, const QString& machine) {
    for (int i = 0; i < alarms.rowCount(); ++i)
        if (alarms.eventAt(i).kind == ocu::EventKind::Timeout && alarms.eventAt(i).machineId == machine &&
            alarms.eventAt(i).severity == EventSeverity::Alarm)
            return true;
    return false;
}

} // namespace

class TestJausBridgeForeign : public QObject {
    Q_OBJECT
private slots:
    void controlAndClearAreConfirmedByTheVehicle() {
        foreign::ForeignJausVehicle vehicle(foreign::VehicleOptions{});
        AlarmModel alarms;
        CommandGate gate(&alarms);
        gate.setConfirmTimeoutMs(3000);
        JausBridge bridge(consoleConfig(vehicle.port(), findFreeUdpPort()),
                          GeoFrame(GeoPoint{-23.36, 119.73, 550}));
        gate.addBridge(&bridge);
        QVERIFY(bridge.start().isEmpty());
        const QString id = QStringLiteral("jaus:126");
        QTRY_VERIFY_WITH_TIMEOUT(bridge.subsystem(126) && bridge.subsystem(126)->link == JausLink::Up &&
                                     !bridge.subsystem(126)->services.isEmpty(),
                                 20000);
        QSignalSpy confirmed(&gate, &CommandGate::commandConfirmed);
        QSignalSpy unconfirmed(&gate, &CommandGate::commandUnconfirmed);
        auto confirmedText = [&](const char* action) {
            for (const auto& c : confirmed)
                if (c.at(0).toString() == QLatin1String(action) && c.at(1).toString() == id)
                    return c.at(2).toString();
            return QString();
        };

        // request_control: confirmed by the vehicle's ConfirmControl (it answers no QueryControl).
        QVERIFY(gateResult([&](auto h) { gate.command(RequestControl{id}, QStringLiteral("test"), h); }).ok);
        QTRY_VERIFY_WITH_TIMEOUT(!confirmedText("request_control").isEmpty(), 10000);
        QVERIFY2(confirmedText("request_control").contains(QLatin1String("confirms control")) &&
                     confirmedText("request_control").contains(QLatin1String("ms after the command")),
                 qPrintable(confirmedText("request_control")));
        QCOMPARE(vehicle.controller(), foreign::ForeignJausVehicle::id(151, 1, 1));

        // stop, then clear_stop: confirmed when the vehicle reports it is no longer in EMERGENCY.
        QVERIFY(gateResult([&](auto h) { gate.stopMachine(id, QStringLiteral("test"), h); }).ok);
        QTRY_VERIFY_WITH_TIMEOUT(bridge.subsystem(126)->emergency, 10000);
        QVERIFY(gateResult([&](auto h) {
                    gate.clearStop(id, gate.requestClearToken(id), QStringLiteral("test"), h);
                }).ok);
        QTRY_VERIFY_WITH_TIMEOUT(!confirmedText("clear_stop").isEmpty(), 10000);
        QVERIFY2(confirmedText("clear_stop").contains(QLatin1String("emergency cleared")),
                 qPrintable(confirmedText("clear_stop")));
        QVERIFY(vehicle.status() != 5); // out of EMERGENCY (STANDBY after ClearEmergency, JSS Management)

        // release_control: confirmed by the vehicle's answer.
        QVERIFY(gateResult([&](auto h) { gate.command(ReleaseControl{id}, QStringLiteral("test"), h); }).ok);
        QTRY_VERIFY_WITH_TIMEOUT(!confirmedText("release_control").isEmpty(), 10000);
        QCOMPARE(unconfirmed.count(), 0);
        QVERIFY(gate.awaitingCommandConfirmation().isEmpty());

        // A vehicle that hears nothing any more: the request leaves (sent), no answer comes, and the
        // confirmation time raises a Timeout alarm naming it.
        vehicle.setOffline(true);
        const CommandResult r =
            gateResult([&](auto h) { gate.command(RequestControl{id}, QStringLiteral("test"), h); });
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(gate.awaitingCommandConfirmation(), QStringList{QStringLiteral("request_control jaus:126")});
        QTRY_COMPARE_WITH_TIMEOUT(unconfirmed.count(), 1, 20000);
        QCOMPARE(unconfirmed.first().at(0).toString(), QStringLiteral("request_control"));
        QVERIFY(hasTimeoutAlarm(alarms, id));
        bridge.stop();
    }

    // A command the operator's role may not issue is refused at the gate and never reaches the wire (the
    // vehicle receives no RequestControl); STOP ALL from a monitor at a locked console does (SetEmergency).
    void refusedByRoleSendsNothing() {
        foreign::ForeignJausVehicle vehicle(foreign::VehicleOptions{});
        AlarmModel alarms;
        CommandGate gate(&alarms);
        JausBridge bridge(consoleConfig(vehicle.port(), findFreeUdpPort()),
                          GeoFrame(GeoPoint{-23.36, 119.73, 550}));
        gate.addBridge(&bridge);
        gate.permissions().allow(QStringLiteral("request_control"),
                                 {OperatorRole::UgvOperator, OperatorRole::Supervisor, OperatorRole::Admin});
        QVERIFY(bridge.start().isEmpty());
        const QString id = QStringLiteral("jaus:126");
        QTRY_VERIFY_WITH_TIMEOUT(bridge.subsystem(126) && bridge.subsystem(126)->link == JausLink::Up &&
                                     !bridge.subsystem(126)->services.isEmpty(),
                                 20000);
        gate.setOperator({QStringLiteral("mon"), OperatorRole::Monitor, QStringLiteral("ocu-151")});
        const CommandResult r =
            gateResult([&](auto h) { gate.command(RequestControl{id}, QStringLiteral("test"), h); });
        QVERIFY(!r.ok);
        QCOMPARE(r.targets.first().cause, OutcomeReason::NotPermitted);
        QTest::qWait(500);
        QCOMPARE(vehicle.received(msg::RequestControl), 0);
        QCOMPARE(vehicle.controller(), 0u);

        gate.setLocked(true);
        QVERIFY(gateResult([&](auto h) { gate.stopAll(QStringLiteral("test"), h); }).ok);
        QTRY_VERIFY_WITH_TIMEOUT(vehicle.received(msg::SetEmergency) > 0, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(vehicle.status(), std::uint8_t(5), 10000);
        QCOMPARE(vehicle.received(msg::RequestControl), 0);
        bridge.stop();
    }

    // The drive commands' results say what went on the wire: refused without control; the
    // session start and the demand sent when the socket took them (the vehicle receives them); the session
    // end noted with its reason; with the stack stopped, nothing is sent and the result says why.
    void driveReportsWhatWentOnTheWire() {
        foreign::VehicleOptions o;
        o.services.push_back("urn:jaus:jss:mobility:VelocityStateDriver");
        foreign::ForeignJausVehicle vehicle(o);
        AlarmModel alarms;
        CommandGate gate(&alarms);
        JausBridge bridge(consoleConfig(vehicle.port(), findFreeUdpPort()),
                          GeoFrame(GeoPoint{-23.36, 119.73, 550}));
        gate.addBridge(&bridge);
        QVERIFY(bridge.start().isEmpty());
        const QString id = QStringLiteral("jaus:126");
        QTRY_VERIFY_WITH_TIMEOUT(bridge.subsystem(126) && bridge.subsystem(126)->link == JausLink::Up &&
                                     !bridge.subsystem(126)->services.isEmpty(),
                                 20000);
        auto cmd = [&](const char* name, QJsonObject args) {
            args.insert(QStringLiteral("id"), id);
            const ParsedCommand parsed = parseOperatorCommand(QString::fromLatin1(name), args);
            if (!parsed.command)
                return CommandResult::failure(parsed.error);
            return gateResult([&](auto h) { gate.command(*parsed.command, QStringLiteral("test"), h); });
        };
        CommandResult r = cmd("drive", {{"linear", 0.5}, {"duration", 1.0}});
        QVERIFY(!r.ok);
        QVERIFY2(reasonText(r.targets.value(0)).contains(QLatin1String("does not control")),
                 qPrintable(r.message));
        QCOMPARE(vehicle.received(0x0415), 0); // SetVelocityCommand: nothing went out

        QVERIFY(cmd("request_control", {}).ok);
        QTRY_VERIFY_WITH_TIMEOUT(bridge.subsystem(126)->controlledByUs, 10000);
        r = cmd("drive_start", {{"reason", "test"}});
        QVERIFY2(r.ok, qPrintable(r.message));
        QTRY_VERIFY_WITH_TIMEOUT(vehicle.received(0x0415) >= 1, 10000); // the session's first (zero) demand
        r = cmd("drive", {{"linear", 0.5}, {"duration", 1.0}});
        QVERIFY2(r.ok, qPrintable(r.message));
        QTRY_VERIFY_WITH_TIMEOUT(vehicle.received(0x0415) >= 5, 10000); // streamed at the drive rate
        r = cmd("drive_stop", {{"reason", "operator released the stick"}});
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(noteText(r.targets.value(0)), QStringLiteral("session ended: operator released the stick"));

        bridge.stop();
        for (const char* name : {"drive_start", "drive", "drive_stop"}) {
            r = cmd(name, {{"linear", 0.1}});
            QVERIFY(!r.ok);
            QVERIFY2(reasonText(r.targets.value(0)).contains(QLatin1String("not running")),
                     qPrintable(r.message));
        }
    }

    void stoppedStackNamesEveryKnownVehicle() {
        foreign::ForeignJausVehicle vehicle(foreign::VehicleOptions{});
        AlarmModel alarms;
        CommandGate gate(&alarms);
        JausBridge bridge(consoleConfig(vehicle.port(), findFreeUdpPort()),
                          GeoFrame(GeoPoint{-23.36, 119.73, 550}));
        gate.addBridge(&bridge);
        QVERIFY(bridge.start().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(bridge.subsystem(126) && bridge.subsystem(126)->link == JausLink::Up, 20000);
        QTRY_COMPARE_WITH_TIMEOUT(bridge.linkStatus(QStringLiteral("jaus"))->state, ocu::LinkState::Up,
                                  10000);

        // Running: the vehicle heard and the static endpoint never heard both get SetEmergency.
        CommandResult r = gateResult([&](auto h) { gate.stopAll(QStringLiteral("test"), h); });
        QCOMPARE(r.targets.size(), 2);
        QVERIFY2(r.ok, qPrintable(r.message));
        QCOMPARE(targetId(r.targets[1]), QStringLiteral("jaus:127"));
        QVERIFY2(noteText(r.targets[1]).contains(QLatin1String("never heard")),
                 qPrintable(noteText(r.targets[1])));
        QTRY_VERIFY_WITH_TIMEOUT(vehicle.status() == 5, 10000); // EMERGENCY

        // Stopped: nothing can go out, and the result names each vehicle with the reason.
        bridge.stop();
        QCOMPARE(bridge.linkStatus(QStringLiteral("jaus"))->state, ocu::LinkState::Down);
        QVERIFY(bridge.linkStatus(QStringLiteral("jaus"))->detail.contains(QLatin1String("stopped")));
        r = gateResult([&](auto h) { gate.stopAll(QStringLiteral("test"), h); });
        QVERIFY(!r.ok);
        QCOMPARE(r.targets.size(), 2);
        QCOMPARE(targetId(r.targets[0]), QStringLiteral("jaus:126"));
        QCOMPARE(targetId(r.targets[1]), QStringLiteral("jaus:127"));
        for (const TargetOutcome& t : r.targets) {
            QVERIFY(!t.sent);
            QVERIFY2(reasonText(t).contains(QLatin1String("not running")), qPrintable(reasonText(t)));
        }
    }
};

QTEST_GUILESS_MAIN(TestJausBridgeForeign)
#include "test_jaus_bridge_foreign.moc"
