// Platform mode and state, lights and odometry end to end over loopback: the console's JausStack against the
// simulated UGV (mode and state read and set, lights switched and the vehicle's report changing, the
// odometer advancing while it drives and its trip reset, the emergency platform state refusing a drive and
// a mission command), and against the foreign vehicle with Platform State and Illumination on a component
// of its own (plus a comms-lost policy service it only lists) and without any of them.
#include <QtTest>

#include "protocols/common/Log.h"
#include "protocols/common/Udp.h"
#include "protocols/jaus/JausStack.h"
#include "protocols/jaus/MessagesPlatformServices.h"
#include "sim/jaus/JausDemo.h"
#include "tests/protocols/jaus/foreign/ForeignJausVehicle.h"
#include "tests/support/JausLoopback.h"
#include "tests/support/StackWaits.h"

using namespace ocu;
using namespace ocu::jaus;
using stacktest::Outcomes;
using stacktest::waitFor;

namespace {

struct Console {
    explicit Console(JausConfig c) : stack(std::move(c), listener) { stack.start(); }
    ~Console() { stack.stop(); }
    PlatformServicesStatus platform(std::uint16_t ss = 126) {
        auto s = stack.snapshot(ss);
        return s ? s->platformServices : PlatformServicesStatus{};
    }
    bool known(std::uint16_t ss = 126) {
        return waitFor([&] {
            auto s = stack.snapshot(ss);
            return s && !s->services.empty() && s->mobilityComponent.subsystem;
        });
    }
    bool control(std::uint16_t ss = 126) {
        stack.requestControl(ss, {});
        return waitFor([&] {
            auto s = stack.snapshot(ss);
            return s && s->controlledByUs;
        });
    }
    template <class Command> TargetOutcome outcome(Command command) {
        Outcomes o;
        command(o.callback());
        auto v = o.get();
        return v && v->size() == 1 ? v->front() : TargetOutcome{};
    }
    jaustest::QuietListener listener;
    JausStack stack;
};

JausConfig consoleConfig() {
    JausConfig c;
    c.subsystemId = 200;
    c.callSign = "OCU-200";
    c.authority = 205;
    c.driveCommandTimeoutS = 0;
    c.statusPollHz = 5;
    c.eventConfirmTimeoutS = 0.3; // the foreign vehicle serves no events: polls start after this
    return c;
}

JausConfig foreignConsole(std::uint16_t vehiclePort) {
    static const std::uint16_t group = findFreeUdpPort();
    JausConfig c = consoleConfig();
    c.transport = jaustest::loopback(group);
    c.transport.staticEndpoints.push_back(
        StaticEndpoint{JausId{126, 0xFF, 0xFF}, "127.0.0.1", vehiclePort, false});
    return c;
}

// The foreign vehicle's one component with a primitive driver, so the console has something to drive.
foreign::VehicleOptions driveVehicle() {
    foreign::VehicleOptions o;
    o.services.push_back("urn:jaus:jss:mobility:PrimitiveDriver");
    return o;
}

} // namespace

class TestJausPlatform : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { setLogThreshold(LogLevel::Warning); }

    void simulatedUgvModeStateLightsOdometry() {
        sim::JausDemoOptions o;
        o.count = 1;
        sim::JausDemo demo(o);
        JausConfig cfg = consoleConfig();
        demo.configure(cfg);
        Console c(cfg);
        QVERIFY(c.known());
        QVERIFY(waitFor([&] {
            const auto p = c.platform();
            return p.state && p.mode && p.lights && p.odometerM && p.tripM && !p.supportedModes.empty();
        }));
        PlatformServicesStatus p = c.platform();
        QCOMPARE(*p.state, std::uint8_t(PlatformState::Operational));
        QCOMPARE(*p.mode, std::uint8_t(PlatformMode::StandardOperating));
        QCOMPARE(p.stateService.uri, std::string("urn:jaus:jss:iop:PlatformState"));
        QVERIFY(!p.commsLostService.offered);      // the simulated UGV has no comms-lost policy service
        QCOMPARE(*p.lights, light::RunningLights); // the simulated UGV starts with its running lights on
        QVERIFY(c.control());

        // Lights: the vehicle's report changes; its visible-light source is never asked for.
        const std::uint32_t on = light::Headlights | light::RunningLights | light::LeftTurnSignal;
        QVERIFY(c.outcome([&](auto cb) { c.stack.setLights(126, on, on, cb); }).sent);
        QVERIFY(waitFor([&] { return c.platform().lights == on; }));
        QVERIFY(c.outcome([&](auto cb) { c.stack.setLights(126, light::LeftTurnSignal, 0, cb); }).sent);
        QVERIFY(waitFor([&] { return c.platform().lights == (light::Headlights | light::RunningLights); }));
        const TargetOutcome visible = c.outcome([&](auto cb) {
            c.stack.setLights(126, light::VisibleLightSource, light::VisibleLightSource, cb);
        });
        QVERIFY(!visible.sent);
        QCOMPARE(visible.cause, OutcomeReason::InvalidArgument);

        // Mode: training, as the vehicle then reports it.
        QVERIFY(c.outcome([&](auto cb) { c.stack.setPlatformMode(126, 1, cb); }).sent);
        QVERIFY(waitFor([&] { return c.platform().mode == std::uint8_t(1); }));

        // Odometer: advances while the kinematics drive, the trip resets, the platform total does not.
        c.stack.resume(126, {});
        QVERIFY(c.outcome([&](auto cb) { c.stack.startDriving(126, cb); }).sent);
        DriveCommand forward;
        forward.linear = 2.0;
        const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(2500);
        while (std::chrono::steady_clock::now() < until) {
            c.stack.setDriveCommand(126, forward, {});
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        c.stack.stopDriving(126, {});
        QVERIFY2(waitFor([&] { return c.platform().tripM.value_or(0) >= 2; }),
                 qPrintable(QString::number(c.platform().tripM.value_or(0))));
        const std::uint32_t total = *c.platform().odometerM;
        QVERIFY(total >= 2);
        QVERIFY(waitFor([&] { return demo.find(126)->state().v == 0; }));
        QVERIFY(c.outcome([&](auto cb) { c.stack.resetTripOdometer(126, cb); }).sent);
        QVERIFY(waitFor([&] { return c.platform().tripM == 0u; }));
        QVERIFY(c.platform().odometerM.value_or(0) >= total);

        // Shutdown is not a state this vehicle may be put in: its refusal reaches the operator.
        QVERIFY(c.outcome([&](auto cb) { c.stack.setPlatformState(126, 2, cb); }).sent);
        QVERIFY(waitFor([&] { return !c.platform().stateRefusal.empty(); }));
        QCOMPARE(*c.platform().state, std::uint8_t(PlatformState::Operational));

        // Emergency: reported, then drive and mission commands are refused with the reason.
        QVERIFY(c.outcome([&](auto cb) { c.stack.setPlatformState(126, 4, cb); }).sent);
        QVERIFY(waitFor([&] { return c.platform().state == std::uint8_t(PlatformState::Emergency); }));
        const TargetOutcome drive = c.outcome([&](auto cb) { c.stack.startDriving(126, cb); });
        QVERIFY(!drive.sent);
        QCOMPARE(drive.cause, OutcomeReason::Refused);
        QVERIFY2(QString::fromStdString(drive.reason).contains("emergency platform state"),
                 drive.reason.c_str());
        const TargetOutcome mission = c.outcome([&](auto cb) { c.stack.missionStart(126, 0, cb); });
        QVERIFY(!mission.sent);
        QVERIFY(QString::fromStdString(mission.reason).contains("emergency platform state"));
        // Back to Operational: driving is accepted again.
        QVERIFY(c.outcome([&](auto cb) { c.stack.setPlatformState(126, 1, cb); }).sent);
        QVERIFY(waitFor([&] { return c.platform().state == std::uint8_t(PlatformState::Operational); }));
        // The emergency ends on the vehicle's management report too (polled, it may come a second later).
        QVERIFY(waitFor([&] {
            auto s = c.stack.snapshot(126);
            return s && !s->emergency;
        }));
        const TargetOutcome again = c.outcome([&](auto cb) { c.stack.startDriving(126, cb); });
        QVERIFY2(again.sent, again.reason.c_str());
        c.stack.stopDriving(126, {});
    }

    void foreignVehicleWithPlatformStateAndLights() {
        foreign::VehicleOptions o = driveVehicle();
        o.services.push_back("urn:jaus:jss:iop:CommsLostPolicyManager");
        foreign::ExtraComponent platform;
        platform.component = 5;
        platform.services = {"urn:jaus:jss:iop:PlatformState", "urn:jaus:jss:ugv:IlluminationService"};
        platform.accessControl = true;
        o.extraComponents = {platform};
        o.platformServicesComponent = 5;
        foreign::ForeignJausVehicle vehicle(o);
        Console c(foreignConsole(vehicle.port()));
        QVERIFY(c.known());
        QVERIFY(waitFor(
            [&] { return c.platform().state && c.platform().lights && c.platform().lightsSupported; }));
        PlatformServicesStatus p = c.platform();
        QVERIFY(p.stateService.offered && p.illuminationService.offered);
        QVERIFY(!p.modeService.offered && !p.odometryService.offered);
        QVERIFY(p.commsLostService.offered);
        QCOMPARE(p.commsLostService.uri, std::string("urn:jaus:jss:iop:CommsLostPolicyManager"));
        QCOMPARE(p.commsLostService.major, 1);
        QCOMPARE(p.commsLostService.minor, 1);
        QCOMPARE(*p.lightsSupported, light::Headlights | light::IrLightSource);

        // Lights on a component of its own: its own control is taken for the command.
        QVERIFY(c.outcome([&](auto cb) {
                     c.stack.setLights(126, light::IrLightSource, light::IrLightSource, cb);
                 }).sent);
        QVERIFY(waitFor([&] { return vehicle.lights() == light::IrLightSource; }));
        QVERIFY(waitFor([&] { return c.platform().lights == light::IrLightSource; }));
        // A light it lacks is refused before the wire.
        const TargetOutcome brake =
            c.outcome([&](auto cb) { c.stack.setLights(126, light::BrakeLights, light::BrakeLights, cb); });
        QVERIFY(!brake.sent);
        QCOMPARE(brake.cause, OutcomeReason::NotSupported);
        // Its own control is let go after the last command (ReleaseControl 0x000E).
        QVERIFY2(waitFor([&] { return vehicle.controller() == 0 && vehicle.received(0x000E) >= 1; }),
                 qPrintable(QStringLiteral("controller %1, RequestControl %2, ReleaseControl %3")
                                .arg(vehicle.controller(), 0, 16)
                                .arg(vehicle.received(0x000D))
                                .arg(vehicle.received(0x000E))));

        // Emergency platform state: its Management follows, the console refuses a drive command.
        QVERIFY(c.outcome([&](auto cb) { c.stack.setPlatformState(126, 4, cb); }).sent);
        QVERIFY(waitFor([&] { return vehicle.status() == 5; }));
        QVERIFY(waitFor([&] { return c.platform().emergencyState(); }));
        const TargetOutcome drive = c.outcome([&](auto cb) { c.stack.startDriving(126, cb); });
        QVERIFY(!drive.sent);
        QVERIFY(QString::fromStdString(drive.reason).contains("emergency platform state"));
        QVERIFY(c.outcome([&](auto cb) { c.stack.setPlatformState(126, 1, cb); }).sent);
        QVERIFY(waitFor([&] { return c.platform().state == std::uint8_t(PlatformState::Operational); }));
        QCOMPARE(vehicle.malformed(), 0);
    }

    void foreignVehicleWithoutThem() {
        foreign::ForeignJausVehicle vehicle(driveVehicle());
        Console c(foreignConsole(vehicle.port()));
        QVERIFY(c.known());
        const PlatformServicesStatus p = c.platform();
        QVERIFY(!p.stateService.offered && !p.illuminationService.offered && !p.modeService.offered &&
                !p.odometryService.offered && !p.commsLostService.offered);
        QVERIFY(!p.state && !p.lights && !p.odometerM);
        for (auto command : std::vector<std::function<void(OutcomeCallback)>>{
                 [&](OutcomeCallback cb) {
                     c.stack.setLights(126, light::Headlights, light::Headlights, cb);
                 },
                 [&](OutcomeCallback cb) { c.stack.setPlatformState(126, 4, cb); },
                 [&](OutcomeCallback cb) { c.stack.setPlatformMode(126, 1, cb); },
                 [&](OutcomeCallback cb) { c.stack.resetTripOdometer(126, cb); }}) {
            const TargetOutcome o = c.outcome(command);
            QVERIFY(!o.sent);
            QCOMPARE(o.cause, OutcomeReason::NotSupported);
        }
        // Driving is not refused for a platform state the vehicle never reported.
        QVERIFY(c.control());
        QVERIFY(c.outcome([&](auto cb) { c.stack.startDriving(126, cb); }).sent);
        c.stack.stopDriving(126, {});
        QCOMPARE(vehicle.malformed(), 0);
    }
};

QTEST_GUILESS_MAIN(TestJausPlatform)
#include "test_jaus_platform.moc"
