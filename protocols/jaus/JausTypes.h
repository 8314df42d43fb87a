#pragma once
// Values the JAUS stack hands to the console: subsystem snapshots, events, drive commands, the listener.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "protocols/common/Clock.h"
#include "protocols/jaus/HandoffTypes.h"
#include "protocols/jaus/JudpCodec.h"
#include "protocols/jaus/Messages.h"
#include "protocols/jaus/MissionTypes.h"
#include "protocols/jaus/PlatformTypes.h"
#include "protocols/jaus/VideoTypes.h"

namespace ocu::jaus {

enum class LinkState { Up, Degraded, Down };
enum class AccessState {
    NotAvailable,
    NotControlled,
    Monitoring, // we only watch (MONITOR role or no control requested)
    ControlAccepted,
    ControlReleased,
    Timeout,
    InsufficientAuthority,
    Preempted
};
const char* nameFor(LinkState s);
const char* nameFor(AccessState s);

struct ComponentInfo {
    std::uint8_t component = 0;
    std::vector<ServiceRecord> services;
};
struct NodeInfo {
    std::uint8_t node = 0;
    std::vector<ComponentInfo> components;
};

// A pan-tilt unit of a vehicle (AS6057A, AEP-4818 §9.3.3) as its position sensor reports it.
struct PanTiltState {
    JausId component;
    bool controlledByUs = false;     // its own access control confirmed our RequestControl
    std::optional<double> pan, tilt; // rad, from ReportPanTiltJointPositions; empty until reported
    bool operator==(const PanTiltState&) const = default;
};

struct SubsystemSnapshot {
    std::uint16_t subsystem = 0;
    std::string callSign;
    std::string endpoint; // "ip:port" of the platform manager, empty when unknown
    LinkState link = LinkState::Down;
    TimePoint lastMessage{};
    std::int64_t lastMessageUnixMs = 0;

    AccessState access = AccessState::Monitoring;
    JausId controller; // all zero when uncontrolled
    std::uint8_t controllerAuthority = 0;
    bool controlledByUs = false;
    std::uint8_t accessTimeoutS = 0; // from ReportTimeout (0 = unknown or disabled)

    std::optional<ManagementState> management;
    bool emergency = false;
    bool driving = false; // a drive session of ours is open

    std::optional<GlobalPose> globalPose;
    std::optional<LocalPose> localPose;
    std::optional<VelocityState> velocity;
    std::optional<PlatformSpecifications> platform;
    std::optional<HealthSummary> health;

    JausId mobilityComponent; // zero until discovered
    std::vector<NodeInfo> services;

    // The vehicle's video streams (Digital Resource Discovery + Visual Sensor names, or configured
    // per vehicle) and its pan-tilt units.
    std::vector<VideoEndpoint> videoEndpoints;
    std::vector<PanTiltState> panTilts;

    // The waypoint mission this console uploaded (MissionClient), phase None when there is none.
    MissionStatus mission;
    // Platform mode and state, lights, odometer, comms-lost service (PlatformClient), from its reports.
    PlatformServicesStatus platformServices;
    // Hand-off between consoles (HandoffClient): our request, and the requests forwarded to us.
    HandoffStatus handoff;
};

enum class Severity { Info, Warning, Error };
enum class EventKind {
    Discovered,
    LinkLost,
    LinkRestored,
    ControlAccepted,
    ControlRejected,
    ControlReleased,
    ControlLost,
    ControlPreempted,
    Emergency,
    EmergencyCleared,
    ManagementChanged,
    HealthFault,
    DecodeError,
    CommandRefused,
    TransportError,
    DriveNotSent,   // a drive stream message was not taken by the socket, or the stream recovered
    MissionChanged, // the phase of a waypoint mission changed (text names the new one)
    HandoffChanged, // a hand-off request: ours answered, or another console's forwarded to us (text says)
};
const char* nameFor(EventKind k);

struct JausEvent {
    Severity severity = Severity::Info;
    EventKind kind = EventKind::Discovered;
    std::uint16_t subsystem = 0; // 0 when not about one subsystem
    std::string text;
};

struct DriveCommand {
    enum class Mode { Wrench, Velocity };
    Mode mode = Mode::Velocity;
    double linear = 0; // Wrench: propulsive linear X % [-100,100]; Velocity: m/s (+ forward)
    double angular =
        0; // Wrench: propulsive rotational Z %; Velocity: yaw rate rad/s (+ = right, AEP-4818 §7.7)
    double brake = 0; // Wrench only: resistive linear X % [0,100]
};

// The transport runs without its group socket (JudpTransport::open): the group's port is held by another
// process that bound it without SO_REUSEADDR (public JAUS node managers do), or the group cannot be joined.
// Only what others send to the group (or, in broadcast mode, to the broadcast port) is not received; the
// console still sends to the group and works by unicast from its own port, where replies come back (peers
// answer the source port, AEP-4818 §4.7.2).
struct GroupSocketProblem {
    std::string group;                 // "239.255.0.1:3794", or "broadcast port 3794"
    std::uint16_t port = 0;            // the group's port (multicast_port)
    bool heldByOther = false;          // the bind failed with EADDRINUSE
    std::string reason;                // what failed, e.g. "bind: Address already in use"
    std::uint16_t unicastPort = 0;     // the port the console sends from and receives replies on
    std::uint16_t unicastPortHeld = 0; // the configured unicast port when it was held too (else 0)
    bool operator==(const GroupSocketProblem&) const = default;
};
// The warning in English (log line and JAUS event): what is missing, why, and how the console goes on.
std::string toText(const GroupSocketProblem& p);

// Called on the stack's io thread; implementations must not block.
struct JausListener {
    virtual ~JausListener() = default;
    virtual void onSubsystemChanged(const SubsystemSnapshot& snapshot) = 0;
    virtual void onEvent(const JausEvent& event) = 0;
};

} // namespace ocu::jaus
