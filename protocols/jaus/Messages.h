#pragma once
// JAUS message payloads (message ID + body) as value types, with pure encode/decode functions.
// Layouts follow the public JSIDL (jaus-wire.md §3): little-endian, presence vectors first, scaled integers.
// Decoders accept whatever presence vector arrives (peers ignore the query's PV, jaus-wire.md §6.3) and
// ignore trailing bytes; they fail only when a field that must be present is missing.
// Codecs by family: MessagesCore.cpp (names, management, access control), MessagesDiscovery.cpp,
// MessagesEvents.cpp, MessagesMobility.cpp (drive commands, pose, velocity state), MessagesPlatform.cpp
// (platform specifications, health summary); shared building blocks in MessageSupport.h.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "protocols/common/Bytes.h"
#include "protocols/common/Result.h"
#include "protocols/jaus/JudpCodec.h"

namespace ocu::jaus {

namespace msg {
// Core (AS5710A)
inline constexpr std::uint16_t SetAuthority = 0x0001, Shutdown = 0x0002, Standby = 0x0003, Resume = 0x0004,
                               Reset = 0x0005, SetEmergency = 0x0006, ClearEmergency = 0x0007,
                               RequestControl = 0x000D, ReleaseControl = 0x000E, ConfirmControl = 0x000F,
                               RejectControl = 0x0010, CreateEvent = 0x01F0, UpdateEvent = 0x01F1,
                               CancelEvent = 0x01F2, ConfirmEventRequest = 0x01F3,
                               RejectEventRequest = 0x01F4, RegisterServices = 0x0B00,
                               QueryAuthority = 0x2001, QueryStatus = 0x2002, QueryTimeout = 0x2003,
                               QueryControl = 0x200D, QueryEvents = 0x21F0, QueryHeartbeatPulse = 0x2202,
                               QueryIdentification = 0x2B00, QueryConfiguration = 0x2B01,
                               QuerySubsystemList = 0x2B02, QueryServices = 0x2B03, QueryServiceList = 0x2B04,
                               ReportAuthority = 0x4001, ReportStatus = 0x4002, ReportTimeout = 0x4003,
                               ReportControl = 0x400D, ReportEvents = 0x41F0, Event = 0x41F1,
                               ReportHeartbeatPulse = 0x4202, ReportIdentification = 0x4B00,
                               ReportConfiguration = 0x4B01, ReportSubsystemList = 0x4B02,
                               ReportServices = 0x4B03, ReportServiceList = 0x4B04;
// Mobility (AS6009) and UGV (AS6091)
inline constexpr std::uint16_t SetWrenchEffort = 0x0405, QueryWrenchEffort = 0x2405,
                               ReportWrenchEffort = 0x4405, SetVelocityCommand = 0x0415,
                               QueryVelocityCommand = 0x2415, ReportVelocityCommand = 0x4415,
                               QueryGlobalPose = 0x2402, ReportGlobalPose = 0x4402, QueryLocalPose = 0x2403,
                               ReportLocalPose = 0x4403, QueryVelocityState = 0x2404,
                               ReportVelocityState = 0x4404, QueryPlatformSpecifications = 0x2502,
                               ReportPlatformSpecifications = 0x4502;
// IOP custom Health Monitor (FKIE HealthClass.xml: UGVSummary == "HealthSummary" in AEP-4818)
inline constexpr std::uint16_t QueryHealthSummary = 0xED10, UpdateHealthSummary = 0xDD10,
                               ReportHealthSummary = 0xFD10;
} // namespace msg

const char* messageName(std::uint16_t id);
inline std::uint16_t peekMessageId(ByteSpan payload) {
    return payload.size() >= 2 ? std::uint16_t(payload[0] | (payload[1] << 8)) : 0;
}

// ---- Value types ----------------------------------------------------------------------------------------
enum class ManagementState : std::uint8_t {
    Init = 0,
    Ready = 1,
    Standby = 2,
    Shutdown = 3,
    Failure = 4,
    Emergency = 5
};
const char* nameFor(ManagementState s);
enum class EmergencyCode : std::uint16_t {
    Stop = 1,
    Safety = 2
}; // SAFETY=2 is the IOP addition (AEP-4818 §4.5)
enum class ConfirmControlCode : std::uint8_t { Accepted = 0, NotAvailable = 1, InsufficientAuthority = 2 };
enum class RejectControlCode : std::uint8_t { Released = 0, NotAvailable = 1 };
enum class IdQueryType : std::uint8_t { System = 1, Subsystem = 2, Node = 3, Component = 4 };
enum class IdType : std::uint16_t {
    Vehicle = 10001,
    Ocu = 20001,
    OtherSubsystem = 30001,
    Node = 40001,
    Payload = 50001,
    Component = 60001
};

// Messages whose body is empty or one integer share these.
struct Empty {};
struct U8Body {
    std::uint8_t value = 0;
};
struct U16Body {
    std::uint16_t value = 0;
};

struct ReportStatus {
    ManagementState status = ManagementState::Init;
    std::uint32_t reserved = 0;
};
struct ReportControl {
    JausId controller; // all zero when uncontrolled
    std::uint8_t authority = 0;
};
struct QueryIdentification {
    IdQueryType type = IdQueryType::Subsystem;
};
struct ReportIdentification {
    IdQueryType queryType = IdQueryType::Subsystem;
    IdType type = IdType::Vehicle;
    std::string identification;
};
struct ServiceRecord {
    std::string uri;
    std::uint8_t major = 1;
    std::uint8_t minor = 0;
};
struct RegisterServices {
    std::vector<ServiceRecord> services;
};
struct ComponentServices {
    std::uint8_t component = 0;
    std::uint8_t instance = 0;
    std::vector<ServiceRecord> services;
};
struct NodeServices {
    std::uint8_t node = 0;
    std::vector<ComponentServices> components;
};
struct QueryServices {
    struct Node {
        std::uint8_t node = 255;
        std::vector<std::uint8_t> components{255};
    };
    std::vector<Node> nodes{Node{}};
};
struct ReportServices {
    std::vector<NodeServices> nodes;
};
struct QueryServiceList {
    struct Comp {
        std::uint8_t component = 255;
        std::optional<std::string> searchFilter;
    };
    struct Node {
        std::uint8_t node = 255;
        std::vector<Comp> components{Comp{}};
    };
    struct Subsystem {
        std::uint16_t subsystem = 0xFFFF;
        std::vector<Node> nodes{Node{}};
    };
    std::vector<Subsystem> subsystems{Subsystem{}};
};
struct ReportServiceList {
    struct Subsystem {
        std::uint16_t subsystem = 0;
        std::vector<NodeServices> nodes;
    };
    std::vector<Subsystem> subsystems;
};
// Discovery's configuration (AS5710A): which nodes and components a subsystem has, without their services.
struct QueryConfiguration {
    IdQueryType type = IdQueryType::Subsystem;
};
struct ReportConfiguration {
    struct Component {
        std::uint8_t component = 0;
        std::uint8_t instance = 0;
    };
    struct Node {
        std::uint8_t node = 0;
        std::vector<Component> components;
    };
    std::vector<Node> nodes;
};
struct ReportSubsystemList {
    std::vector<JausId> subsystems;
};

// Events (AS5710A). Rates are Hz, scaled u16 [0,1092].
enum class EventType : std::uint8_t { Periodic = 0, EveryChange = 1 };
struct CreateEvent {
    std::uint8_t requestId = 0;
    EventType type = EventType::Periodic;
    double rateHz = 0;
    Bytes queryMessage; // a whole query message including its ID
};
struct UpdateEvent {
    std::uint8_t requestId = 0;
    EventType type = EventType::Periodic;
    double rateHz = 0;
    std::uint8_t eventId = 0;
    Bytes queryMessage;
};
struct CancelEvent {
    std::uint8_t requestId = 0;
    std::uint8_t eventId = 0;
};
struct ConfirmEventRequest {
    std::uint8_t requestId = 0;
    std::uint8_t eventId = 0;
    double rateHz = 0;
};
struct RejectEventRequest {
    std::uint8_t requestId = 0;
    std::optional<std::uint8_t> responseCode; // 1 periodic unsupported ... 5 message not supported
    std::optional<std::string> errorMessage;  // fixed 80 characters on the wire
};
struct EventMsg {
    std::uint8_t eventId = 0;
    std::uint8_t sequence = 0;
    Bytes reportMessage; // a whole report message including its ID
};
struct QueryEvents {
    std::uint8_t variant = 3; // 0 message code, 1 event type, 2 event ID, 3 all
    std::uint16_t value = 0;
};
struct ReportEvents {
    struct Entry {
        EventType type = EventType::Periodic;
        std::uint8_t eventId = 0;
        Bytes queryMessage;
    };
    std::vector<Entry> events;
};

// Mobility. Optional fields = presence-vector bits in declaration order.
struct WrenchEffort {                                                                 // percent
    std::optional<double> propLinX, propLinY, propLinZ, propRotX, propRotY, propRotZ; // [-100,100]
    std::optional<double> resLinX, resLinY, resLinZ, resRotX, resRotY, resRotZ;       // [0,100]
};
struct VelocityCommand {
    std::uint8_t commandType = 0;                       // 0 current, 1 max, 2 min, 3 default
    std::optional<double> vx, vy, vz;                   // m/s
    std::optional<double> rollRate, pitchRate, yawRate; // rad/s
};
struct PresenceQuery16 {
    std::uint16_t presence = 0xFFFF;
};
struct GlobalPose {
    std::optional<double> lat, lon, alt, positionRms, roll, pitch, yaw, attitudeRms;
    std::optional<std::uint32_t> timestamp;
};
struct LocalPose {
    std::optional<double> x, y, z, positionRms, roll, pitch, yaw, attitudeRms;
    std::optional<std::uint32_t> timestamp;
};
struct VelocityState {
    std::optional<double> vx, vy, vz, velocityRms, rollRate, pitchRate, yawRate, rateRms;
    std::optional<std::uint32_t> timestamp;
};
struct PlatformSpecifications {
    // Variant 0 skid steer, 1 Ackermann.
    std::uint8_t steeringType = 0;
    std::optional<double> trackSeparation, driveWheelRadius; // skid steer
    std::optional<double> steeringAngleRange, minTurnRadius, wheelSeparation,
        ackDriveWheelRadius; // Ackermann
    std::optional<double> maxForwardSpeed, maxReverseSpeed, maxRotationalSpeed;
    std::optional<double> maxForwardAccel, maxReverseAccel, maxForwardDecel, maxReverseDecel;
    std::string name;
    std::optional<double> front, back, right, left, bottom, top; // metres from the reference point
};
struct HealthSummary {
    std::uint8_t severity = 0;                                // 0 NONE 1 INFO 2 WARN 3 ERR 4 FAIL
    std::vector<std::pair<std::uint8_t, std::uint8_t>> nodes; // (node ID, severity)
};

// ---- Encoders (payload = ID + body) ---------------------------------------------------------------------
Bytes encodeEmpty(std::uint16_t id);
Bytes encodeU8(std::uint16_t id, std::uint8_t v);
Bytes encodeU16(std::uint16_t id, std::uint16_t v);
Bytes encode(const ReportStatus& m);
Bytes encode(const ReportControl& m);
Bytes encode(const QueryIdentification& m);
Bytes encode(const ReportIdentification& m);
Bytes encode(const RegisterServices& m);
Bytes encode(const QueryServices& m);
Bytes encode(const ReportServices& m);
Bytes encode(const QueryServiceList& m);
Bytes encode(const ReportServiceList& m);
Bytes encode(const QueryConfiguration& m);
Bytes encode(const ReportConfiguration& m);
Bytes encode(const ReportSubsystemList& m);
Bytes encode(const CreateEvent& m);
Bytes encode(const UpdateEvent& m);
Bytes encode(const CancelEvent& m);
Bytes encode(const ConfirmEventRequest& m);
Bytes encode(const RejectEventRequest& m);
Bytes encode(const EventMsg& m);
Bytes encode(const QueryEvents& m);
Bytes encode(const ReportEvents& m);
Bytes encodeWrench(std::uint16_t id, const WrenchEffort& m); // SetWrenchEffort or ReportWrenchEffort
Bytes encodeVelocityCommand(std::uint16_t id, const VelocityCommand& m);
Bytes encodeQueryPv16(std::uint16_t id, std::uint16_t presence);
Bytes encodeQueryVelocityCommand(std::uint8_t presence, std::uint8_t commandType);
Bytes encode(const GlobalPose& m, std::uint16_t id = msg::ReportGlobalPose);
Bytes encode(const LocalPose& m, std::uint16_t id = msg::ReportLocalPose);
Bytes encode(const VelocityState& m);
Bytes encode(const PlatformSpecifications& m);
Bytes encode(const HealthSummary& m);

// ---- Decoders (payload = ID + body; the ID must match) --------------------------------------------------
Result<std::uint8_t> decodeU8(ByteSpan payload, std::uint16_t id);
Result<std::uint16_t> decodeU16(ByteSpan payload, std::uint16_t id);
Result<ReportStatus> decodeReportStatus(ByteSpan payload);
Result<ReportControl> decodeReportControl(ByteSpan payload);
Result<QueryIdentification> decodeQueryIdentification(ByteSpan payload);
Result<ReportIdentification> decodeReportIdentification(ByteSpan payload);
Result<RegisterServices> decodeRegisterServices(ByteSpan payload);
Result<QueryServices> decodeQueryServices(ByteSpan payload);
Result<ReportServices> decodeReportServices(ByteSpan payload);
Result<QueryServiceList> decodeQueryServiceList(ByteSpan payload);
Result<ReportServiceList> decodeReportServiceList(ByteSpan payload);
Result<ReportConfiguration> decodeReportConfiguration(ByteSpan payload);
Result<ReportSubsystemList> decodeReportSubsystemList(ByteSpan payload);
Result<CreateEvent> decodeCreateEvent(ByteSpan payload);
Result<UpdateEvent> decodeUpdateEvent(ByteSpan payload);
Result<CancelEvent> decodeCancelEvent(ByteSpan payload);
Result<ConfirmEventRequest> decodeConfirmEventRequest(ByteSpan payload);
Result<RejectEventRequest> decodeRejectEventRequest(ByteSpan payload);
Result<EventMsg> decodeEvent(ByteSpan payload);
Result<QueryEvents> decodeQueryEvents(ByteSpan payload);
Result<ReportEvents> decodeReportEvents(ByteSpan payload);
Result<WrenchEffort> decodeWrench(ByteSpan payload, std::uint16_t id = msg::SetWrenchEffort);
Result<VelocityCommand> decodeVelocityCommand(ByteSpan payload, std::uint16_t id = msg::SetVelocityCommand);
Result<std::uint16_t> decodeQueryPv16(ByteSpan payload, std::uint16_t id);
Result<GlobalPose> decodeGlobalPose(ByteSpan payload, std::uint16_t id = msg::ReportGlobalPose);
Result<LocalPose> decodeLocalPose(ByteSpan payload, std::uint16_t id = msg::ReportLocalPose);
Result<VelocityState> decodeVelocityState(ByteSpan payload);
Result<PlatformSpecifications> decodePlatformSpecifications(ByteSpan payload);
Result<HealthSummary> decodeHealthSummary(ByteSpan payload);

// Scaled-value ranges used by both sides (JSIDL).
inline constexpr double kEventRateMax = 1092.0;

} // namespace ocu::jaus
