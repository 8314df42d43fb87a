// End to end over loopback against the foreign JAUS vehicle in the discovery dialects of public stacks: the
// wildcard QueryServices (node 255, component 255) answered with a ReportServices of 0 components, and the
// services pushed as RegisterServices by each component (or told only to a query naming the component, or
// never told). The vehicle has three components like such stacks do: 126.1.1 the platform manager
// (Discovery, Liveness), 126.1.2 a PrimitiveDriver (Management and AccessControl by inheritance, efforts
// only, no VelocityStateDriver), 126.1.3 the pose sensors. It listens on unicast only (static endpoint).
#include <QtTest>

#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>

#include "protocols/common/Log.h"
#include "protocols/common/Udp.h"
#include "protocols/jaus/JausStack.h"
#include "protocols/jaus/Messages.h"
#include "tests/protocols/jaus/foreign/ForeignJausVehicle.h"
#include "tests/support/JausLoopback.h"
#include "tests/support/StackWaits.h"

using namespace ocu;
using namespace ocu::jaus;
using foreign::ExtraComponent;
using foreign::ForeignJausVehicle;
using foreign::ServicesDialect;
using foreign::VehicleOptions;
using stacktest::Outcomes;
using stacktest::waitFor;

namespace {

using Quiet = jaustest::QuietListener;

VehicleOptions publicStack(ServicesDialect dialect) {
    VehicleOptions o;
    o.callSign = "PUBLIC-126";
    o.services = {"urn:jaus:jss:core:Discovery", "urn:jaus:jss:core:Liveness"};
    o.management = false;
    o.accessControl = false;
    o.servicesDialect = dialect;
    o.everyComponentIdentifies = true;
    ExtraComponent driver;
    driver.component = 2;
    driver.services = {"urn:jaus:jss:mobility:PrimitiveDriver"};
    driver.management = driver.accessControl = true;
    ExtraComponent pose;
    pose.component = 3;
    pose.services = {"urn:jaus:jss:mobility:GlobalPoseSensor", "urn:jaus:jss:mobility:LocalPoseSensor",
                     "urn:jaus:jss:mobility:VelocityStateSensor"};
    pose.accessControl = true; // the sensors derive from AccessControl (AS6009)
    pose.pose = true;
    o.extraComponents = {driver, pose};
    return o;
}

JausConfig console(Role role, std::uint8_t authority, std::uint16_t vehiclePort) {
    static const std::uint16_t group = findFreeUdpPort();
    JausConfig c;
    c.subsystemId = 200;
    c.callSign = "OCU-200";
    c.role = role;
    c.authority = authority;
    c.statusPollHz = 2;
    c.linkLostS = 3;
    c.eventConfirmTimeoutS = 1; // the vehicle serves no events: polls start after this
    c.transport = jaustest::loopback(group);
    c.transport.staticEndpoints.push_back(
        StaticEndpoint{JausId{126, 0xFF, 0xFF}, "127.0.0.1", vehiclePort, false});
    return c;
}

struct Console {
    Console(Role role, std::uint8_t authority, std::uint16_t vehiclePort)
        : stack(console(role, authority, vehiclePort), quiet) {
        stack.start();
    }
    ~Console() { stack.stop(); }
    std::optional<SubsystemSnapshot> snap() { return stack.snapshot(126); }
    bool identified() {
        auto s = snap();
        return s && s->callSign == "PUBLIC-126";
    }
    std::uint32_t id() const { return stack.config().ownId().value(); }
    Quiet quiet;
    JausStack stack;
};

// Discovery, pose, control, drive, stop, clear and STOP ALL against a vehicle that describes itself in
// the given dialect (its services learnt through registrations or named queries).
void exerciseEverything(ForeignJausVehicle& v, Console& ocu) {
    QVERIFY(waitFor([&] { return ocu.identified(); }));
    QVERIFY2(waitFor([&] {
                 auto s = ocu.snap();
                 return s && s->mobilityComponent == JausId{126, 1, 2};
             }),
             "the driver component was never learnt");
    // Pose and velocity from the pose component (no events: polled after the CreateEvent timed out).
    QVERIFY(waitFor([&] {
        auto s = ocu.snap();
        return s && s->globalPose && s->globalPose->lat && s->localPose && s->localPose->x;
    }));
    QVERIFY(std::abs(*ocu.snap()->globalPose->lat - 48.1) < 1e-5);
    QVERIFY(std::abs(*ocu.snap()->globalPose->lon - 11.5) < 1e-5);
    QVERIFY(std::abs(*ocu.snap()->localPose->x - 12.5) < 1e-3);
    QVERIFY(std::abs(*ocu.snap()->localPose->y + 3.25) < 1e-3);

    Outcomes req;
    ocu.stack.requestControl(126, req.callback());
    auto r = req.get();
    QVERIFY(r && r->size() == 1);
    QVERIFY2(r->front().sent, r->front().reason.c_str());
    QVERIFY(waitFor([&] { return ocu.snap()->controlledByUs; }));
    QCOMPARE(v.controller(), ocu.id());
    QVERIFY(v.receivedBy(msg::RequestControl, 2) > 0);

    // Drive: efforts only (the vehicle lists PrimitiveDriver and no VelocityStateDriver).
    Outcomes start;
    ocu.stack.startDriving(126, start.callback());
    QVERIFY2(start.get() && start.get()->front().sent, start.get()->front().reason.c_str());
    Outcomes velocity;
    ocu.stack.setDriveCommand(126, DriveCommand{DriveCommand::Mode::Velocity, 1.0, 0.0, 0.0},
                              velocity.callback());
    auto vo = velocity.get();
    QVERIFY(vo && !vo->front().sent);
    QVERIFY2(vo->front().reason.find("VelocityStateDriver") != std::string::npos, vo->front().reason.c_str());
    Outcomes effort;
    ocu.stack.setDriveCommand(126, DriveCommand{DriveCommand::Mode::Wrench, 30.0, 5.0, 0.0},
                              effort.callback());
    QVERIFY2(effort.get() && effort.get()->front().sent, effort.get()->front().reason.c_str());
    Outcomes stopDrive;
    ocu.stack.stopDriving(126, stopDrive.callback());
    QVERIFY(stopDrive.get() && stopDrive.get()->front().sent);
    QVERIFY(waitFor([&] { return v.receivedBy(msg::SetWrenchEffort, 2) >= 3; }));
    QCOMPARE(v.received(msg::SetVelocityCommand), 0);

    Outcomes stop;
    ocu.stack.setEmergency(126, EmergencyCode::Stop, stop.callback());
    QVERIFY(stop.get() && stop.get()->front().sent);
    QVERIFY(waitFor([&] { return v.status() == 5; }));
    QVERIFY(v.receivedBy(msg::SetEmergency, 2) > 0);
    QVERIFY(waitFor([&] { return ocu.snap()->emergency; })); // from its ReportStatus

    Outcomes clear;
    ocu.stack.clearEmergency(126, clear.callback());
    QVERIFY(clear.get() && clear.get()->front().sent);
    QVERIFY(waitFor([&] { return v.status() != 5; }));
    QVERIFY(waitFor([&] { return !ocu.snap()->emergency; }));

    Outcomes all;
    ocu.stack.setEmergencyAll(EmergencyCode::Stop, all.callback());
    auto a = all.get();
    QVERIFY(a && a->size() == 1);
    QCOMPARE(a->front().target, std::string("jaus:126"));
    QVERIFY2(a->front().sent, a->front().reason.c_str());
    QVERIFY(waitFor([&] { return v.status() == 5; }));
    QVERIFY(waitFor([&] { return ocu.snap()->emergency; }));
    QCOMPARE(v.malformed(), 0);
}

} // namespace

class TestJausForeignDialect : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { setLogThreshold(LogLevel::Error); }

    // Empty wildcard answer, RegisterServices pushed by every component.
    void emptyWildcardAnswerAndRegisterServices() {
        ForeignJausVehicle v(publicStack(ServicesDialect::EmptyWildcardRegister));
        Console ocu(Role::PrimaryOperator, 205, v.port());
        exerciseEverything(v, ocu);
        QVERIFY(v.received(msg::QueryServices) > 0);
        QCOMPARE(ocu.stack.counters().get("rx.unhandled"), std::uint64_t(0)); // RegisterServices is read
    }

    // Empty wildcard answer, no registrations: the components heard from are asked by name.
    void emptyWildcardAnswerAndNamedQueries() {
        VehicleOptions o = publicStack(ServicesDialect::EmptyWildcardRegister);
        o.pushRegistrations = false;
        ForeignJausVehicle v(o);
        Console ocu(Role::PrimaryOperator, 205, v.port());
        exerciseEverything(v, ocu);
        QVERIFY(v.received(msg::QueryConfiguration) > 0);
        QVERIFY(v.receivedBy(msg::QueryServices, 2) > 0); // a query naming the driver reached it
    }

    // Services never told: the vehicle is listed (identified, link up) and STOP ALL, like a single stop,
    // still puts SetEmergency on the wire for it, to every component (126.255.255), and says so.
    void servicesNeverLearntStillStopped() {
        ForeignJausVehicle v(publicStack(ServicesDialect::Silent));
        Console ocu(Role::Monitor, 0, v.port());
        QVERIFY(waitFor([&] { return ocu.identified(); }));
        QVERIFY(waitFor([&] { return v.received(msg::QueryConfiguration) > 0; })); // the empty answer came
        QVERIFY(ocu.snap()->services.empty());
        Outcomes all;
        ocu.stack.setEmergencyAll(EmergencyCode::Stop, all.callback());
        auto a = all.get();
        QVERIFY(a && a->size() == 1);
        QVERIFY2(a->front().sent, a->front().reason.c_str());
        QVERIFY2(a->front().note.find("services are not known") != std::string::npos,
                 a->front().note.c_str());
        QVERIFY2(a->front().note.find("126.255.255") != std::string::npos, a->front().note.c_str());
        QVERIFY(waitFor([&] { return v.receivedBy(msg::SetEmergency, 2) > 0; }));
        QVERIFY(waitFor([&] { return v.status() == 5; }));
        // The emergency shows from the vehicle's own report (QueryStatus went to every component too).
        QVERIFY(waitFor([&] { return ocu.snap()->emergency; }));
    }

    // A single stop for such a vehicle goes the same way.
    void singleStopWithServicesNeverLearnt() {
        ForeignJausVehicle v(publicStack(ServicesDialect::Silent));
        Console ocu(Role::PrimaryOperator, 205, v.port());
        QVERIFY(waitFor([&] { return ocu.identified(); }));
        QVERIFY(waitFor([&] { return v.received(msg::QueryConfiguration) > 0; }));
        Outcomes one;
        ocu.stack.setEmergency(126, EmergencyCode::Stop, one.callback());
        auto o = one.get();
        QVERIFY(o && o->size() == 1);
        QVERIFY2(o->front().sent, o->front().reason.c_str());
        QVERIFY(!o->front().note.empty());
        QVERIFY(waitFor([&] { return v.status() == 5; }));
        QVERIFY(waitFor([&] { return ocu.snap()->emergency; }));
    }
};

QTEST_GUILESS_MAIN(TestJausForeignDialect)
#include "test_jaus_foreign_dialect.moc"
