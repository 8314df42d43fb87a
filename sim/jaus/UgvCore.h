#pragma once
// The simulated UGV's JAUS services as a socket-free state machine (AEP-4818 §10 items 1-18, 24):
// platform manager 1.1 (Discovery, Liveness, HealthMonitor, UnsolicitedHeartbeat), Core Mobility
// Component 3.1 (AccessControl, Management, PrimitiveDriver, VelocityStateDriver, PlatformSpecifications),
// pose/velocity sensor component 3.2 (GlobalPoseSensor, LocalPoseSensor, VelocityStateSensor), events on
// every component, and a kinematic model. Driven by handle()/tick() with an ocu::Clock, so tests can use a
// FakeClock. Messages reach the services through a table keyed by message ID (UgvMessageTable); each service
// registers its messages from its own file: UgvDiscovery.cpp, UgvEvents.cpp, UgvAccessControl.cpp,
// UgvManagement.cpp, UgvDrive.cpp, UgvPoseSensors.cpp, UgvWaypoints.cpp (ListManager, the Local/Global
// Waypoint (List) Drivers on 3.1, PathReporter on 3.2), UgvPlatform.cpp (Platform Mode/State, Illumination,
// Odometry on 3.1),
// UgvHandoff.cpp (Enhanced Access Control on 3.1).
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "protocols/common/Clock.h"
#include "protocols/common/Counters.h"
#include "protocols/common/GeoFrame.h"
#include "protocols/jaus/JausConfig.h"
#include "protocols/jaus/JausOutput.h"
#include "protocols/jaus/Messages.h"
#include "protocols/jaus/MessagesHandoff.h"
#include "protocols/jaus/MessagesMission.h"
#include "sim/jaus/UgvMessageTable.h"
#include "sim/jaus/UgvVideo.h"

namespace ocu::sim {

enum class Kinematics { SkidSteer, Ackermann };

struct UgvFaults {
    bool dropHeartbeat = false; // no unsolicited heartbeat
    double heartbeatRateHz = 1; // unsolicited heartbeat rate (slow it to test liveness)
    bool rejectControl = false; // answer every RequestControl with NOT_AVAILABLE
    bool rejectEvents = false;  // answer CreateEvent with RejectEventRequest
    double eventRateScale = 1;  // confirm periodic events at this fraction of the requested rate
    bool loseDiscovery = false; // ignore QueryServices / QueryIdentification
    double packetLoss = 0;      // outgoing datagrams dropped (transport fault)
    int delayMs = 0;            // outgoing latency (transport fault)
    bool reorder = false;       // outgoing reordering (transport fault)
};

struct SimulatedUgvConfig {
    std::uint16_t subsystemId = 126;
    std::string callSign = "UGV-126";
    Kinematics kinematics = Kinematics::SkidSteer;
    double startX = 0, startY = 0,
           startYaw = 0; // local frame: x north, y east, yaw clockwise from north (rad)
    GeoPoint origin{48.137154, 11.576124, 520}; // local (0,0) on the globe
    jaus::TransportSettings network;

    std::uint8_t defaultAuthority = 125; // Mobility-node components ≥ 125 (AEP-4818 §4.3.2)
    double accessTimeoutS = 5;
    double driveTimeoutS = 1; // 0 disables (AEP-4818 §7.1.1)
    double driveRecoveryS = 1;
    double minDriveRateHz = 5;                                         // "Drive Frequency" for recovery
    double maxForwardSpeed = 2, maxReverseSpeed = 1, maxYawRate = 1.0; // m/s, rad/s
    double maxAccel = 2, maxYawAccel = 4;                              // m/s², rad/s²
    double trackWidth = 0.6, wheelRadius = 0.15, minTurnRadius = 2.0, wheelBase = 1.2;
    double length = 1.2, width = 0.8, height = 0.9;
    double physicsRateHz = 50;
    double headingGain = 2; // waypoint following: yaw rate (rad/s) per radian of heading error
    UgvFaults faults;
    // IlluminationState at start (UgvPlatform.cpp): the running lights (b3), safety lights a UGV on a site
    // keeps on.
    std::uint32_t lights = 1u << 3;
    // Enhanced Access Control 1.1 on the Core Mobility Component (UgvHandoff.cpp, AEP-4818 §6.3.2.2): the
    // Handoff Decision Timeout (the controller's answer) and the Handoff Request Timeout (the requester's
    // re-assertion), whole seconds on the wire, 0 = off.
    bool enhancedAccessControl = true;
    double handoffDecisionTimeoutS = 60, handoffRequestTimeoutS = 5;
    // Cameras served over RTSP by SimulatedUgv and announced through Digital Resource Discovery
    // (UgvVideo); empty = no video services.
    std::vector<SimCameraConfig> cameras;
};

// The waypoint services' state (UgvWaypoints.cpp): one ListManager list shared by the Local and Global
// Waypoint List Drivers (each element says which kind it is), the single waypoint drivers' waypoint, the
// travel speed, and the historical path the PathReporter reports.
struct UgvRoute {
    std::map<std::uint16_t, jaus::ListElement> list;
    std::uint16_t active = 0;                // 0 = no list executing
    double speed = 0;                        // m/s; reset to 0 when the driver leaves Ready
    std::optional<jaus::ListElement> single; // a SetLocalWaypoint / SetGlobalWaypoint of the single drivers
    bool singleArrived = false;
    std::vector<std::pair<double, double>> path; // (x, y) every 0.25 m, at most 1000 points
    std::uint16_t captured = 0;                  // elements reached (tests)
};

// The platform services' state (UgvPlatform.cpp): mode, lights, where the trip odometers started, and who
// set the platform's emergency (only that client may ask for Operational without control).
struct UgvPlatformServices {
    std::uint8_t mode = 0;
    std::uint32_t lights = 0;
    double tripStart[3] = {0, 0, 0}; // TRIP_A-C, odometer metres at their reset
    jaus::JausId emergencyBy;
};
// Enhanced Access Control's queue (UgvHandoff.cpp): the hand-off requests forwarded to the controller.
struct UgvHandoffRequest {
    std::uint8_t id = 0;
    jaus::JausId requester;
    std::uint8_t authority = 0;
    std::string explanation;
    TimePoint lastAsserted{}, forwarded{};
};
struct UgvHandoffQueue {
    std::vector<UgvHandoffRequest> requests;
    jaus::JausId forwardedTo; // the controller the queue was last sent to
    std::uint8_t nextId = 1;
};

struct UgvState {
    double x = 0, y = 0, yaw = 0, v = 0, w = 0;
    jaus::ManagementState management = jaus::ManagementState::Standby;
    jaus::JausId controller;
    std::uint8_t controllerAuthority = 0;
    bool driveTimedOut = false;
    double odometer = 0; // metres travelled
};

class UgvCore {
public:
    UgvCore(SimulatedUgvConfig config, jaus::JausOutput& output, const Clock& clock, Counters& counters);

    void handle(const jaus::JausId& src, const jaus::JausId& dst, ByteSpan payload);
    void tick();

    // Fault injection and inspection (owner's thread).
    UgvFaults& faults() { return m_cfg.faults; }
    void preemptControl(std::uint8_t authority = 255); // an internal SAFETY_CRITICAL client takes control
    void forceDriveTimeout();
    void enterEmergency();
    void enterFailure();
    void clearFailure();
    const UgvState& state() const { return m_s; }
    const UgvRoute& route() const { return m_route; }
    const UgvPlatformServices& platformServices() const { return m_platform; }
    std::uint8_t platformState() const;               // as ReportPlatformState says it (UgvPlatform.cpp)
    std::uint32_t odometerM(std::uint8_t type) const; // as ReportOdometry says it
    const SimulatedUgvConfig& config() const { return m_cfg; }
    bool isLocal(const jaus::JausId& id) const;
    jaus::GlobalPose globalPose() const;
    UgvVideo& video() { return m_video; }
    const UgvVideo& video() const { return m_video; }

    jaus::JausId platformManager() const { return {m_cfg.subsystemId, 1, 1}; }
    jaus::JausId mobility() const { return {m_cfg.subsystemId, 3, 1}; }
    jaus::JausId sensors() const { return {m_cfg.subsystemId, 3, 2}; }
    // The on-board SAFETY_CRITICAL client used by the pre-emption fault.
    jaus::JausId internalClient() const { return {m_cfg.subsystemId, 3, 200}; }

private:
    struct EventSub {
        std::uint8_t eventId = 0;
        std::uint8_t requestId = 0;
        jaus::JausId requester;
        jaus::JausId component;
        jaus::EventType type = jaus::EventType::Periodic;
        double rateHz = 0;
        Bytes query;
        TimePoint lastSent{};
        Bytes lastReport;
        std::uint8_t sequence = 0;
    };

    void send(const jaus::JausId& from, const jaus::JausId& to, const Bytes& payload,
              jaus::Priority prio = jaus::Priority::Standard);
    // A malformed message: counted by reason and logged.
    void rejectMalformed(const std::string& error);
    bool serves(const jaus::JausId& comp, std::uint16_t id) const { return m_table.serves(comp, id); }
    std::optional<Bytes> report(const jaus::JausId& comp, ByteSpan query) {
        return m_table.report(comp, query);
    }

    // The services: each registers its messages in m_table.
    void registerDiscovery();     // Discovery, Liveness, HealthMonitor (platform manager)
    void registerEvents();        // Events (every component)
    void registerAccessControl(); // AccessControl (Core Mobility Component)
    void registerManagement();    // Management (Core Mobility Component)
    void registerDriving();       // PrimitiveDriver, VelocityStateDriver (Core Mobility Component)
    void registerPoseSensors();   // pose and velocity sensors, PlatformSpecifications
    void registerWaypoints();     // ListManager, waypoint (list) drivers (3.1), PathReporter (3.2)
    void registerPlatform();      // Platform Mode/State, Illumination, Odometry (3.1)
    void registerHandoff();       // Enhanced Access Control (3.1)

    // Discovery
    std::vector<jaus::ServiceRecord> servicesOf(const jaus::JausId& comp) const;
    void answerIdentification(const jaus::JausId& comp, const jaus::JausId& src, ByteSpan p);
    void answerServices(const jaus::JausId& comp, const jaus::JausId& src, std::uint16_t id);
    // Events
    void createEvent(const jaus::JausId& comp, const jaus::JausId& src, const jaus::CreateEvent& ce);
    void updateEvent(const jaus::JausId& comp, const jaus::JausId& src, ByteSpan p);
    void cancelEvent(const jaus::JausId& comp, const jaus::JausId& src, ByteSpan p);
    void tickEvents(TimePoint now);
    // Access control and management
    void accessRequest(const jaus::JausId& src, std::uint8_t authority);
    void releaseController(jaus::RejectControlCode code);
    bool isController(const jaus::JausId& src) const { return m_s.controller == src && src.subsystem != 0; }
    void tickAccessTimeout(TimePoint now);
    void managementCommand(const jaus::JausId& src, std::uint16_t id);
    // Driving
    void setWrenchEffort(const jaus::JausId& src, ByteSpan p);
    void setVelocityCommand(const jaus::JausId& src, ByteSpan p);
    void driveMessage(TimePoint now);
    void physics(TimePoint now);
    // Pose sensors and platform specifications
    Bytes reportGlobalPose(ByteSpan query) const;
    Bytes reportLocalPose(ByteSpan query) const;
    Bytes reportVelocityState(ByteSpan query) const;
    Bytes reportPlatformSpecifications() const;
    // Waypoints
    void setElement(const jaus::JausId& src, ByteSpan p);
    void deleteElement(const jaus::JausId& src, ByteSpan p);
    void executeList(const jaus::JausId& src, ByteSpan p);
    void setSingleWaypoint(const jaus::JausId& src, ByteSpan p);
    void setTravelSpeed(const jaus::JausId& src, ByteSpan p);
    std::optional<std::pair<double, double>> targetOf(const jaus::ListElement& e, double* tolerance) const;
    std::optional<Bytes> reportWaypoint(std::uint16_t reportId) const;
    Bytes reportPath(ByteSpan query) const;
    void followRoute(TimePoint now); // sets the drive demand while a route runs (physics)
    void recordPath();
    // Enhanced Access Control
    void requestHandoff(const jaus::JausId& src, const jaus::RequestHandoff& request);
    void confirmRelease(const jaus::JausId& src, ByteSpan p);
    void answerHandoff(const jaus::JausId& to, std::uint8_t id, jaus::HandoffCode code);
    void forwardHandoffQueue();
    void tickHandoff(TimePoint now);

    SimulatedUgvConfig m_cfg;
    jaus::JausOutput& m_out;
    const Clock& m_clock;
    Counters& m_counters;
    GeoFrame m_geo;
    UgvState m_s;
    jaus::ManagementState m_beforeEmergency = jaus::ManagementState::Standby;
    TimePoint m_lastRequest{}, m_lastDrive{}, m_lastPrevDrive{}, m_recoveryStart{}, m_lastPhysics{},
        m_lastHeartbeat{};
    bool m_haveDrive = false;
    bool m_started = false;
    // Last accepted command
    bool m_velocityMode = true;
    double m_cmdV = 0, m_cmdW = 0, m_brake = 0;
    jaus::WrenchEffort m_wrench;
    jaus::VelocityCommand m_velCmd;
    std::map<std::uint8_t, EventSub> m_events;
    std::uint8_t m_nextEventId = 1;
    UgvVideo m_video;
    UgvRoute m_route;
    UgvPlatformServices m_platform;
    jaus::ManagementState m_routeManagement = jaus::ManagementState::Standby;
    UgvHandoffQueue m_handoff;
    UgvMessageTable m_table;
};

} // namespace ocu::sim
