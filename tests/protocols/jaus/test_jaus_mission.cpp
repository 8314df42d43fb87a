// Waypoint missions end to end over loopback: the console's JausStack against the simulated UGV (its
// ListManager with both list drivers) and against the foreign vehicle in the public stacks' dialect (a
// LocalWaypointListDriver of its own component over mobility:ListManager 1.0, no events, no PathReporter;
// also with the empty wildcard QueryServices answer + RegisterServices). Five-waypoint local and global
// missions are uploaded, verified by read-back and run: the active element advances to the end and the
// vehicle passes within tolerance of every waypoint. Pause, resume, abort; STOP ALL during a mission shows
// "stopped by emergency" and nothing restarts after the clear; a refused element or ExecuteList shows the
// reason. Also the GeoJSON route file (saved, reopened: the same SetElement bytes).
// Built twice, so that CTest runs the halves side by side: the simulated UGV's part and the GeoJSON file
// (test_jaus_mission), the foreign vehicle's part (test_jaus_mission_foreign, OCU_MISSION_FOREIGN_PEER=1).
#include <QtTest>

#include <QTemporaryDir>

#include <atomic>
#include <cmath>
#include <mutex>
#include <set>
#include <thread>

#include "models/jaus/MissionGeoJson.h"
#include "protocols/common/GeoFrame.h"
#include "protocols/common/Log.h"
#include "protocols/common/Udp.h"
#include "protocols/jaus/JausStack.h"
#include "sim/jaus/JausDemo.h"
#include "tests/protocols/jaus/foreign/ForeignJausVehicle.h"
#include "tests/support/JausLoopback.h"
#include "tests/support/StackWaits.h"

using namespace ocu;
using namespace ocu::jaus;
using stacktest::waitFor;

namespace {

constexpr double kMissionWaitS = 60;
// Fast vehicles (the test's own settings): the same route logic, missions over in a few seconds. The
// foreign vehicle moves every 50 ms; the console polls its active element at kPollHz, several polls per leg.
constexpr double kSimSpeed = 4, kForeignSpeed = 3, kPollHz = 20;

struct Listener : JausListener {
    std::mutex mutex;
    std::vector<std::string> missionEvents;
    void onSubsystemChanged(const SubsystemSnapshot&) override {}
    void onEvent(const JausEvent& e) override {
        if (e.kind != EventKind::MissionChanged)
            return;
        std::lock_guard lock(mutex);
        missionEvents.push_back(e.text);
    }
};

// Local offsets (north, east) of a five-waypoint route from the vehicle's start: legs of 1.4-1.6 m, each
// longer than twice the 0.5 m capture radius, so every waypoint must be reached on its own.
const std::vector<std::pair<double, double>> kRoute{{1.5, 0}, {2.5, 1}, {2.5, 2.5}, {1, 3}, {0, 2}};

// Samples where the vehicle is (local x north, y east) while a mission runs; the closest approach to each
// target and the active indices the console saw.
struct Watch {
    std::vector<std::pair<double, double>> targets;
    std::vector<double> closest;
    std::set<int> activeSeen;
    std::atomic<bool> stop{false};
    std::thread thread;
    template <class Where, class Active> void start(Where where, Active active) {
        closest.assign(targets.size(), 1e9);
        thread = std::thread([this, where, active] {
            while (!stop) {
                const auto [x, y] = where();
                for (std::size_t i = 0; i < targets.size(); ++i)
                    closest[i] =
                        std::min(closest[i], std::hypot(targets[i].first - x, targets[i].second - y));
                activeSeen.insert(active());
                // Faster than the simulated UGV's 50 Hz physics: every pose it takes is seen.
                std::this_thread::sleep_for(std::chrono::milliseconds(5));
            }
        });
    }
    void finish() {
        stop = true;
        if (thread.joinable())
            thread.join();
    }
    ~Watch() { finish(); }
};

struct Console {
    explicit Console(JausConfig c) : stack(std::move(c), listener) { stack.start(); }
    ~Console() { stack.stop(); }
    MissionStatus mission(std::uint16_t ss) {
        auto s = stack.snapshot(ss);
        return s ? s->mission : MissionStatus{};
    }
    bool phase(std::uint16_t ss, MissionPhase p, double seconds = stacktest::kWaitS) {
        return waitFor([&] { return mission(ss).phase == p; }, seconds);
    }
    bool posed(std::uint16_t ss) {
        return waitFor([&] {
            auto s = stack.snapshot(ss);
            return s && s->globalPose && s->localPose && s->mobilityComponent.subsystem;
        });
    }
    bool control(std::uint16_t ss) {
        stack.requestControl(ss, {});
        return waitFor([&] {
            auto s = stack.snapshot(ss);
            return s && s->controlledByUs;
        });
    }
    Listener listener;
    JausStack stack;
};

#if !OCU_MISSION_FOREIGN_PEER
JausConfig simConsole(const sim::JausDemo& demo) {
    JausConfig c;
    c.subsystemId = 200;
    c.callSign = "OCU-200";
    c.authority = 205;
    c.driveCommandTimeoutS = 0;
    demo.configure(c);
    return c;
}

#else
JausConfig foreignConsole(std::uint16_t vehiclePort) {
    static const std::uint16_t group = findFreeUdpPort();
    JausConfig c;
    c.subsystemId = 200;
    c.callSign = "OCU-200";
    c.authority = 205;
    c.statusPollHz = kPollHz;
    c.eventConfirmTimeoutS = 0.3; // the vehicle serves no events: polls start after this
    c.transport = jaustest::loopback(group);
    c.transport.staticEndpoints.push_back(
        StaticEndpoint{JausId{126, 0xFF, 0xFF}, "127.0.0.1", vehiclePort, false});
    return c;
}

// The public stacks' vehicle: drive component 2, pose sensors 3, the list driver on component 4 of its own.
foreign::VehicleOptions
publicListDriver(foreign::ServicesDialect dialect = foreign::ServicesDialect::Report) {
    foreign::VehicleOptions o;
    o.callSign = "PUBLIC-126";
    o.services = {"urn:jaus:jss:core:Discovery", "urn:jaus:jss:core:Liveness"};
    o.management = o.accessControl = false;
    o.servicesDialect = dialect;
    o.everyComponentIdentifies = true;
    foreign::ExtraComponent drive;
    drive.component = 2;
    drive.services = {"urn:jaus:jss:mobility:PrimitiveDriver"};
    drive.management = drive.accessControl = true;
    foreign::ExtraComponent pose;
    pose.component = 3;
    pose.services = {"urn:jaus:jss:mobility:GlobalPoseSensor", "urn:jaus:jss:mobility:LocalPoseSensor"};
    pose.accessControl = pose.pose = true;
    foreign::ExtraComponent list;
    list.component = 4;
    list.services = {"urn:jaus:jss:mobility:ListManager", "urn:jaus:jss:mobility:LocalWaypointListDriver"};
    list.management = list.accessControl = true;
    o.extraComponents = {drive, pose, list};
    o.listDriverComponent = 4;
    o.listDriver.maxSpeed = kForeignSpeed;
    return o;
}

#endif

// The route's waypoints in WGS84 from a local start (x north, y east) through the frame at `origin`.
std::vector<MissionPoint> routeFrom(const GeoFrame& frame, double x0, double y0, double originX,
                                    double originY, double tolerance, double speed) {
    std::vector<MissionPoint> pts;
    for (auto [dn, de] : kRoute) {
        const GeoPoint g = frame.toGeodetic(EnuPoint{y0 - originY + de, x0 - originX + dn, 0});
        pts.push_back(MissionPoint{g.lat, g.lon, speed, tolerance});
    }
    return pts;
}

std::vector<std::pair<double, double>> localTargets(double x0, double y0) {
    std::vector<std::pair<double, double>> t;
    for (auto [dn, de] : kRoute)
        t.emplace_back(x0 + dn, y0 + de);
    return t;
}

} // namespace

class TestJausMission : public QObject {
    Q_OBJECT

#if !OCU_MISSION_FOREIGN_PEER
    struct SimRig {
        SimRig() : demo(options()), console(simConsole(demo)) {}
        static sim::JausDemoOptions options() {
            sim::JausDemoOptions o;
            o.count = 1;
            o.adjustUgv = [](sim::SimulatedUgvConfig& c) {
                c.maxForwardSpeed = kSimSpeed;
                c.maxYawRate = 4;   // rad/s
                c.maxAccel = 16;    // m/s²
                c.maxYawAccel = 16; // rad/s²
                c.headingGain = 6;  // turns in a fraction of a second at this yaw rate
            };
            return o;
        }
        sim::SimulatedUgv& ugv() { return *demo.find(126); }
        // The simulated UGV's local (0, 0) is the site origin (x north, y east).
        std::vector<MissionPoint> route(double tolerance = 0.5, double speed = kSimSpeed) {
            const auto s = ugv().state();
            return routeFrom(GeoFrame(origin()), s.x, s.y, 0, 0, tolerance, speed);
        }
        GeoPoint origin() const { return sim::JausDemoOptions{}.origin; }
        sim::JausDemo demo;
        Console console;
    };

#endif

    // Runs an uploaded mission to its end and checks the active element and the pose.
    void runToTheEnd(Console& c, std::function<std::pair<double, double>()> where,
                     std::vector<std::pair<double, double>> targets, double tolerance) {
        Watch w;
        w.targets = std::move(targets);
        w.start(where, [&c] { return c.mission(126).activeIndex; });
        c.stack.missionStart(126, 0, {});
        QVERIFY(c.phase(126, MissionPhase::Running));
        QVERIFY2(c.phase(126, MissionPhase::Completed, kMissionWaitS), nameFor(c.mission(126).phase));
        w.finish();
        for (int i = 0; i < 5; ++i)
            QVERIFY2(w.activeSeen.count(i),
                     qPrintable(QStringLiteral("waypoint %1 never active").arg(i + 1)));
        for (std::size_t i = 0; i < w.closest.size(); ++i)
            QVERIFY2(w.closest[i] <= tolerance + 0.02,
                     qPrintable(QStringLiteral("waypoint %1: closest %2 m").arg(i + 1).arg(w.closest[i])));
    }

private slots:
    void initTestCase() {
        setLogThreshold(LogLevel::Warning);
    }

#if !OCU_MISSION_FOREIGN_PEER
    void simulatedUgvLocalAndGlobalMissions() {
        SimRig rig;
        Console& c = rig.console;
        QVERIFY(c.posed(126));
        QVERIFY(c.control(126));
        for (bool global : {false, true}) {
            const auto s = rig.ugv().state();
            c.stack.missionUpload(126, rig.route(), global, {});
            QVERIFY2(c.phase(126, MissionPhase::Uploaded), c.mission(126).reason.c_str());
            QCOMPARE(c.mission(126).global, global);
            QCOMPARE(rig.ugv().route().list.size(), std::size_t(5));
            runToTheEnd(
                c,
                [&rig] {
                    const auto st = rig.ugv().state();
                    return std::pair{st.x, st.y};
                },
                localTargets(s.x, s.y), 0.5);
            QCOMPARE(rig.ugv().route().active, std::uint16_t(0));
            // The driven path: the simulated UGV offers a PathReporter.
            QCOMPARE(c.mission(126).pathSource, std::string("path reporter"));
            QVERIFY(c.mission(126).drivenPath.size() > 10);
        }
    }

    void simulatedUgvPauseResumeAbort() {
        SimRig rig;
        Console& c = rig.console;
        QVERIFY(c.posed(126));
        QVERIFY(c.control(126));
        c.stack.missionUpload(126, rig.route(0.5, 2.0), false, {});
        QVERIFY(c.phase(126, MissionPhase::Uploaded));
        c.stack.missionStart(126, 0, {});
        QVERIFY(waitFor([&] { return c.mission(126).activeIndex >= 1; }, kMissionWaitS));
        c.stack.missionPause(126, {});
        QVERIFY(c.phase(126, MissionPhase::Paused));
        QVERIFY(waitFor([&] { return std::abs(rig.ugv().state().v) < 0.01; }));
        const auto held = rig.ugv().state();
        std::this_thread::sleep_for(std::chrono::milliseconds(600));
        QVERIFY(std::hypot(rig.ugv().state().x - held.x, rig.ugv().state().y - held.y) < 0.05);
        c.stack.missionResume(126, {});
        QVERIFY(c.phase(126, MissionPhase::Running));
        QVERIFY(waitFor([&] { return std::abs(rig.ugv().state().v) > 0.2; }));
        c.stack.missionAbort(126, {});
        QVERIFY(c.phase(126, MissionPhase::Aborted));
        QVERIFY(waitFor([&] { return std::abs(rig.ugv().state().v) < 0.01; }));
        QCOMPARE(rig.ugv().route().list.size(), std::size_t(0)); // DeleteElement(65535)
    }

    void stopAllDuringAMissionNeverRestarts() {
        SimRig rig;
        Console& c = rig.console;
        QVERIFY(c.posed(126));
        QVERIFY(c.control(126));
        c.stack.missionUpload(126, rig.route(0.5, 2.0), false, {});
        QVERIFY(c.phase(126, MissionPhase::Uploaded));
        c.stack.missionStart(126, 0, {});
        QVERIFY(waitFor([&] { return c.mission(126).activeIndex >= 1; }, kMissionWaitS));
        c.stack.setEmergencyAll(EmergencyCode::Safety, {});
        QVERIFY(c.phase(126, MissionPhase::StoppedByEmergency));
        QVERIFY(waitFor([&] { return std::abs(rig.ugv().state().v) < 0.01; }));
        c.stack.clearEmergency(126, {});
        QVERIFY(waitFor([&] { return rig.ugv().state().management != ManagementState::Emergency; }));
        const auto after = rig.ugv().state();
        std::this_thread::sleep_for(std::chrono::milliseconds(1500));
        const auto later = rig.ugv().state();
        QVERIFY2(std::hypot(later.x - after.x, later.y - after.y) < 0.05,
                 qPrintable(QStringLiteral("moved from %1,%2 to %3,%4 v %5 mgmt %6 active %7 speed %8")
                                .arg(after.x)
                                .arg(after.y)
                                .arg(later.x)
                                .arg(later.y)
                                .arg(later.v)
                                .arg(int(later.management))
                                .arg(rig.ugv().route().active)
                                .arg(rig.ugv().route().speed)));
        QCOMPARE(c.mission(126).phase, MissionPhase::StoppedByEmergency);
        QCOMPARE(rig.ugv().route().speed, 0.0);
    }

#else  // the foreign vehicle's list driver
    // The public stacks' dialect, and the vehicle that answers the wildcard QueryServices with nothing.
    void foreignLocalListDriverOfItsOwn_data() {
        QTest::addColumn<int>("dialect");
        QTest::newRow("report") << int(foreign::ServicesDialect::Report);
        QTest::newRow("empty wildcard + RegisterServices")
            << int(foreign::ServicesDialect::EmptyWildcardRegister);
    }
    void foreignLocalListDriverOfItsOwn() {
        QFETCH(int, dialect);
        foreign::ForeignJausVehicle v(publicListDriver(foreign::ServicesDialect(dialect)));
        Console c(foreignConsole(v.port()));
        QVERIFY(c.posed(126));
        QVERIFY(c.control(126)); // the drive component: let go once the mission starts
        const auto [x0, y0] = v.localPosition();
        const GeoFrame frame(GeoPoint{48.1, 11.5, 0});
        for (bool global : {false, true}) {
            const auto [x, y] = v.localPosition();
            // A global mission goes to the only list driver there is: the local one, through the frame.
            c.stack.missionUpload(126, routeFrom(frame, x, y, x0, y0, 0.5, kForeignSpeed),
                                  global ? std::nullopt : std::optional(false), {});
            QVERIFY2(c.phase(126, MissionPhase::Uploaded), c.mission(126).reason.c_str());
            QVERIFY(!c.mission(126).global);
            runToTheEnd(
                c, [&v] { return v.localPosition(); }, localTargets(x, y), 0.5);
            QCOMPARE(v.activeElement(), std::uint16_t(0));
            QCOMPARE(c.mission(126).pathSource, std::string("pose trail"));
            QVERIFY(c.mission(126).drivenPath.size() > 5);
        }
        // It ran on polls (no events), on its own control, with the drive component let go.
        QVERIFY(v.receivedBy(0x241E, 4) > 3);  // QueryActiveElement
        QVERIFY(v.receivedBy(0x000E, 2) >= 1); // ReleaseControl of the drive component
        QCOMPARE(v.malformed(), 0);
    }

    // The JTS examples' layout: one component hosts everything, the list driver beside the pose sensors and
    // the primitive driver. The console controls that one component, runs the mission on it and keeps it
    // (nothing to let go: the driver drives for the component's controller).
    void foreignListDriverOnThePoseComponent() {
        foreign::VehicleOptions o;
        o.callSign = "JTS-126";
        o.services = {"urn:jaus:jss:core:Discovery",
                      "urn:jaus:jss:core:Liveness",
                      "urn:jaus:jss:core:AccessControl",
                      "urn:jaus:jss:core:Management",
                      "urn:jaus:jss:mobility:PrimitiveDriver",
                      "urn:jaus:jss:mobility:GlobalPoseSensor",
                      "urn:jaus:jss:mobility:LocalPoseSensor",
                      "urn:jaus:jss:mobility:ListManager",
                      "urn:jaus:jss:mobility:LocalWaypointListDriver"};
        o.pose = true;
        o.listDriverComponent = o.component;
        o.listDriver.maxSpeed = kForeignSpeed;
        foreign::ForeignJausVehicle v(o);
        Console c(foreignConsole(v.port()));
        QVERIFY(c.posed(126));
        QCOMPARE(c.stack.snapshot(126)->mobilityComponent.component, std::uint8_t(1));
        const auto [x0, y0] = v.localPosition();
        c.stack.missionUpload(
            126, routeFrom(GeoFrame(GeoPoint{48.1, 11.5, 0}), x0, y0, x0, y0, 0.5, kForeignSpeed), false, {});
        QVERIFY2(c.phase(126, MissionPhase::Uploaded), c.mission(126).reason.c_str());
        QCOMPARE(v.controller(), (std::uint32_t(200) << 16) | (1u << 8) | 1u); // control of that component
        runToTheEnd(
            c, [&v] { return v.localPosition(); }, localTargets(x0, y0), 0.5);
        QCOMPARE(v.activeElement(), std::uint16_t(0));
        QCOMPARE(c.mission(126).pathSource, std::string("pose trail"));
        QVERIFY(c.mission(126).drivenPath.size() > 5);
        QCOMPARE(v.receivedBy(0x000E, 1), 0); // never let go of the one component: it is the driver's
        QVERIFY(c.stack.snapshot(126)->controlledByUs);
        QVERIFY(v.receivedBy(0x241E, 1) > 3); // QueryActiveElement, polled
        QCOMPARE(v.malformed(), 0);
    }

    void foreignPauseResumeAndStopAll() {
        foreign::ForeignJausVehicle v(publicListDriver());
        Console c(foreignConsole(v.port()));
        QVERIFY(c.posed(126));
        const auto [x0, y0] = v.localPosition();
        c.stack.missionUpload(
            126, routeFrom(GeoFrame(GeoPoint{48.1, 11.5, 0}), x0, y0, x0, y0, 0.5, kForeignSpeed), false, {});
        QVERIFY2(c.phase(126, MissionPhase::Uploaded), c.mission(126).reason.c_str());
        c.stack.missionStart(126, 0, {});
        QVERIFY(waitFor([&] { return c.mission(126).activeIndex >= 1; }, kMissionWaitS));
        c.stack.missionPause(126, {});
        QVERIFY(c.phase(126, MissionPhase::Paused));
        const auto held = v.localPosition();
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
        QCOMPARE(v.localPosition(), held);
        c.stack.missionResume(126, {});
        QVERIFY(c.phase(126, MissionPhase::Running));
        QVERIFY(waitFor([&] { return v.localPosition() != held; }));
        c.stack.setEmergencyAll(EmergencyCode::Safety, {});
        QVERIFY(c.phase(126, MissionPhase::StoppedByEmergency));
        QCOMPARE(v.status(), std::uint8_t(5));
        c.control(126);
        c.stack.clearEmergency(126, {});
        QVERIFY(waitFor([&] { return v.status() != 5; }));
        const auto stopped = v.localPosition();
        std::this_thread::sleep_for(std::chrono::milliseconds(1500));
        QCOMPARE(v.localPosition(), stopped);
        QCOMPARE(c.mission(126).phase, MissionPhase::StoppedByEmergency);
        c.stack.missionAbort(126, {});
        QVERIFY(c.phase(126, MissionPhase::Aborted));
    }

    void refusedElementAndExecuteListShowTheReason() {
        auto o = publicListDriver();
        o.listDriver.rejectSetElementCode = 3;
        foreign::ForeignJausVehicle v(o);
        Console c(foreignConsole(v.port()));
        QVERIFY(c.posed(126));
        const auto [x0, y0] = v.localPosition();
        const auto route = routeFrom(GeoFrame(GeoPoint{48.1, 11.5, 0}), x0, y0, x0, y0, 0.5, 1.0);
        c.stack.missionUpload(126, route, false, {});
        QVERIFY(c.phase(126, MissionPhase::Rejected));
        QVERIFY2(c.mission(126).reason.find("invalid next element (code 3)") != std::string::npos,
                 c.mission(126).reason.c_str());

        auto o2 = publicListDriver();
        o2.listDriver.ignoreExecuteList = true;
        foreign::ForeignJausVehicle v2(o2);
        Console c2(foreignConsole(v2.port()));
        QVERIFY(c2.posed(126));
        c2.stack.missionUpload(126, route, false, {});
        QVERIFY(c2.phase(126, MissionPhase::Uploaded));
        c2.stack.missionStart(126, 0, {});
        QVERIFY(c2.phase(126, MissionPhase::Rejected));
        QVERIFY(c2.mission(126).reason.find("ExecuteList") != std::string::npos);
        QVERIFY(c2.mission(126).activeIndex < 0);
        std::lock_guard lock(c2.listener.mutex);
        QVERIFY(std::none_of(c2.listener.missionEvents.begin(), c2.listener.missionEvents.end(),
                             [](const std::string& t) { return t.find("running") != std::string::npos; }));
    }
#endif // OCU_MISSION_FOREIGN_PEER

#if !OCU_MISSION_FOREIGN_PEER
    // A route saved as GeoJSON and opened again gives the same waypoints, so the same SetElement bytes.
    void geoJsonRouteRoundTrip() {
        QVector<MissionWaypoint> route;
        for (int i = 0; i < 5; ++i)
            route << MissionWaypoint{48.1371543 + i * 1.234567e-5, 11.5761241 - i * 2.2e-5, 1.5, 0.75};
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("mission.geojson"));
        QString why;
        QVERIFY2(writeMissionGeoJsonFile(path, route, &why), qPrintable(why));
        const auto back = readMissionGeoJsonFile(path, &why);
        QVERIFY2(back, qPrintable(why));
        QCOMPARE(*back, route); // exact: the same SetGlobalWaypoint / SetLocalWaypoint bytes follow
        QVERIFY(!readMissionGeoJson(R"({"type":"FeatureCollection","features":[]})", &why));
        QVERIFY(why.contains(QStringLiteral("LineString")));
        QVERIFY(!readMissionGeoJson(
            R"({"type":"Feature","geometry":{"type":"LineString","coordinates":[[11,95]]}})", &why));
    }
#endif
};

QTEST_GUILESS_MAIN(TestJausMission)
#include "test_jaus_mission.moc"
