#pragma once
// ISO 23725 message value types and their JSON codec (shared/research/iso23725.md §3-§6).
// Enumerations are kept as validated strings so unknown-but-tolerated values survive a round trip.
// Numbers that may be null are std::optional: nullopt means "unavailable" (ISO §4.2.3), never a default.
#include "protocols/common/Result.h"
#include "protocols/iso23725/InferredRules.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace ocu::iso23725 {

using Guid = std::string; // canonical lower-case 8-4-4-4-12

// A timestamp as received: the raw text plus milliseconds since the Unix epoch when it could be read.
struct Timestamp {
    std::string text;
    std::optional<std::int64_t> unixMs;
    bool operator==(const Timestamp&) const = default;
};

struct Header {
    std::string protocol = "ISO23725";
    std::optional<std::int64_t> version = 1;
    Timestamp timestamp;
    std::optional<Guid> equipmentId;
    bool operator==(const Header&) const = default;
};

// ---- enumeration value sets (§4.3) ----
namespace enums {
extern const std::vector<std::string_view> equipmentType;  // 22 values, §6.2.3
extern const std::vector<std::string_view> actor;          // AHS, FMS
extern const std::vector<std::string_view> actionRequest;  // Apply, Remove
extern const std::vector<std::string_view> actionResponse; // Accepted, Rejected
extern const std::vector<std::string_view> actionStatus;   // On, Off
extern const std::vector<std::string_view> autonomyMode;   // 7 values
extern const std::vector<std::string_view> haulTask;       // Load, Offload, Fuel, Park, Wait
extern const std::vector<std::string_view> productionState;
extern const std::vector<std::string_view> wayType;     // Road, Area
extern const std::vector<std::string_view> defaultTask; // Load, Offload, Supply, Park, Wait, Drive, Fuel
extern const std::vector<std::string_view> severity;    // Info, Warning, Error
extern const std::vector<std::string_view> assignmentStatus;
} // namespace enums

// ---- 1 FleetDefinitionV2 (§6.2) ----
struct Equipment {
    Guid equipmentId;
    std::string hid;
    std::string type;
    std::string oem;
    std::string model;
    bool autonomous = false;
    std::optional<double> length;
    std::optional<double> width;
    bool operator==(const Equipment&) const = default;
};
struct FleetDefinitionV2 {
    Guid ahsId;
    std::vector<Equipment> equipment;
    bool operator==(const FleetDefinitionV2&) const = default;
};

// ---- 2-4 all-stop (§6.3) ----
struct MachineAllStopRequestV1 {
    std::string modeAllStop; // Apply | Remove
    Guid modeAllStopId;
    bool operator==(const MachineAllStopRequestV1&) const = default;
};
struct MachineAllStopResponseV1 {
    std::string response; // Accepted | Rejected
    Guid modeAllStopId;
    std::optional<std::string> detail;
    bool operator==(const MachineAllStopResponseV1&) const = default;
};
struct MachineAllStopV1 {
    std::string modeAllStop; // On | Off
    std::optional<Guid> modeAllStopId;
    bool operator==(const MachineAllStopV1&) const = default;
};

// ---- 5 MachinePositionV1 (§7.4) ----
struct PoseFields {
    std::optional<std::int64_t> heading; // degrees 0-359, compass
    std::optional<double> latitude;
    std::optional<double> longitude;
    std::optional<double> elevation;
    std::optional<double> latitudeAccuracy;
    std::optional<double> longitudeAccuracy;
    std::optional<double> elevationAccuracy;
    std::optional<double> headingAccuracy;
    std::optional<std::int64_t> speed; // km/h
    bool operator==(const PoseFields&) const = default;
};
struct AttachmentPose {
    Guid equipmentId;
    PoseFields pose;
    bool operator==(const AttachmentPose&) const = default;
};
struct MachinePositionV1 {
    Timestamp timestamp; // measurement time
    PoseFields pose;
    std::optional<std::vector<AttachmentPose>> attachment;
    bool operator==(const MachinePositionV1&) const = default;
};

// ---- 6 BasicMachineHealthV2 (§7.5) ----
struct Tire {
    std::string tirePosition;
    std::optional<std::int64_t> tirePressure;    // kPa
    std::optional<std::int64_t> tireTemperature; // degC
    bool operator==(const Tire&) const = default;
};
struct BasicMachineHealthV2 {
    std::optional<std::int64_t> fuelLevel;
    std::optional<double> totalMachineHour;
    std::optional<double> totalEngineHour;
    std::optional<std::vector<Tire>> tire;
    std::optional<std::int64_t> primeMoverTemp; // may-level, example only [I]
    bool operator==(const BasicMachineHealthV2&) const = default;
};

// ---- 7-9 (§8) ----
struct MachineAutonomyModeV1 {
    std::string autonomyMode;
    bool operator==(const MachineAutonomyModeV1&) const = default;
};
struct MachineDispatchAvailabilityV1 {
    std::string dispatchingCustodian;
    std::optional<std::string> impendingCustodian;
    std::optional<Timestamp> impendingTime;
    bool operator==(const MachineDispatchAvailabilityV1&) const = default;
};
struct DiagnosticEntry {
    std::int64_t componentId = 0;
    std::int64_t faultCode = 0;
    bool operator==(const DiagnosticEntry&) const = default;
};
struct MachineDiagnosticV2 {
    std::vector<DiagnosticEntry> entries; // full list; [] = all cleared
    bool operator==(const MachineDiagnosticV2&) const = default;
};

// ---- 10 MapConnectivityV1 (§9.1) ----
struct WayRef {
    std::int64_t wayId = 0;
    bool operator==(const WayRef&) const = default;
};
struct ConnectivityItem {
    std::int64_t wayId = 0;
    std::string wayType; // Road | Area
    std::optional<double> roadLength;
    std::optional<std::string> roadName;
    std::optional<std::string> areaDefaultTask;
    std::optional<std::string> areaName;
    std::vector<WayRef> connection;
    bool operator==(const ConnectivityItem&) const = default;
};
struct MapConnectivityV1 {
    std::vector<ConnectivityItem> items;
    bool operator==(const MapConnectivityV1&) const = default;
};

// ---- 11-13 map service (§10.6) ----
struct MapServiceV1 {
    std::int64_t api = 1;
    bool operator==(const MapServiceV1&) const = default;
};
struct MapSummaryV1 {
    Timestamp timestamp;
    std::int64_t changeSetMap = 0;
    std::int64_t changeSetWay = 0;
    std::optional<std::int64_t> uid;
    std::int64_t nodeCount = 0;
    std::int64_t wayCount = 0;
    std::int64_t documentCount = 0;
    bool operator==(const MapSummaryV1&) const = default;
};
struct MapCommandV1 {
    std::string method = "GET";
    std::string scope = "/summary";
    bool operator==(const MapCommandV1&) const = default;
};

// ---- 15 InterfaceDiagnosticV1 (§11) [I] ----
struct DiagMeasurement {
    std::string name;
    std::optional<double> value;
    std::string unit;
    bool operator==(const DiagMeasurement&) const = default;
};
struct DiagMessage {
    std::string severity;
    std::string code;
    std::optional<std::string> detail;
    std::optional<std::string> refMember;
    std::optional<Timestamp> refTimestamp;
    bool operator==(const DiagMessage&) const = default;
};
struct InterfaceDiagnosticV1 {
    std::vector<DiagMeasurement> measurement;
    std::vector<DiagMessage> message;
    bool operator==(const InterfaceDiagnosticV1&) const = default;
};

// ---- 16-20 production (§12) ----
struct StateTime {
    std::string productionState;
    Timestamp start;
    std::optional<double> duration;
    bool operator==(const StateTime&) const = default;
};
struct HaulTruckProductionCycleV1 {
    Guid cycleId;
    std::optional<Guid> assignmentId;
    std::int64_t loadWayId = 0;
    std::int64_t dumpWayId = 0;
    std::optional<Guid> loaderEquipmentId;
    std::optional<std::int64_t> payloadWeight;
    std::vector<StateTime> stateTimes;
    bool operator==(const HaulTruckProductionCycleV1&) const = default;
};
struct HaulTruckProductionStateV2 {
    std::optional<Guid> assignmentId; // null when none
    std::optional<std::int64_t> wayId;
    std::string autonomyMode;
    std::string productionState;
    bool operator==(const HaulTruckProductionStateV2&) const = default;
};
struct HaulTruckProductionStateSensorV1 {
    std::optional<bool> loaded;
    std::optional<bool> bodyRaised;
    std::optional<bool> parkBrake;
    std::optional<std::int64_t> payloadWeight;
    std::optional<bool> inLoadArea;
    std::optional<bool> inDumpArea;
    bool operator==(const HaulTruckProductionStateSensorV1&) const = default;
};
struct HaulTruckPayloadV1 {
    std::optional<std::int64_t> payloadWeight; // t
    std::optional<double> accuracy;
    std::optional<nlohmann::json>
        payloadSourceId; // GUID string, number or null (§9 tolerance); absent = nullopt
    bool operator==(const HaulTruckPayloadV1&) const = default;
};
struct HaulTruckDumpV1 {
    std::optional<Guid> assignmentId;
    std::int64_t wayId = 0;
    std::optional<std::int64_t> dumpedWeight;
    std::optional<std::int64_t> destinationSpotId;
    std::optional<Guid> dumpEquipmentId;
    bool operator==(const HaulTruckDumpV1&) const = default;
};

// ---- 21-24 assignment (§13.3) ----
struct AssignmentItem {
    Guid assignmentId;
    std::string task;
    std::int64_t destinationId = 0;
    std::optional<Guid> destinationEquipmentId;
    std::optional<std::int64_t> destinationSpotId;
    std::optional<std::vector<WayRef>> route;
    bool operator==(const AssignmentItem&) const = default;
};
struct HaulTruckAssignmentRequestV2 {
    std::vector<AssignmentItem> items; // first = current, then future [I]
    bool operator==(const HaulTruckAssignmentRequestV2&) const = default;
};
struct AssignmentResponseItem {
    Guid assignmentId;
    std::string response;
    std::optional<std::string> detail;
    bool operator==(const AssignmentResponseItem&) const = default;
};
struct HaulTruckAssignmentResponseV1 {
    std::vector<AssignmentResponseItem> items;
    bool operator==(const HaulTruckAssignmentResponseV1&) const = default;
};
struct HaulTruckAssignmentResetV1 {
    Guid resetId;
    bool operator==(const HaulTruckAssignmentResetV1&) const = default;
};
struct HaulTruckAssignmentV1 {
    std::optional<Guid> assignmentId; // null when idle
    std::string status;
    std::optional<std::string> task;
    std::optional<std::int64_t> destinationId;
    bool operator==(const HaulTruckAssignmentV1&) const = default;
};

// A member this codec does not know (other protocol, vendor extension): kept verbatim (§4.2).
struct UnknownMember {
    std::string name;
    nlohmann::json value;
    bool operator==(const UnknownMember&) const = default;
};

using Body = std::variant<FleetDefinitionV2, MachineAllStopRequestV1, MachineAllStopResponseV1,
                          MachineAllStopV1, MachinePositionV1, BasicMachineHealthV2, MachineAutonomyModeV1,
                          MachineDispatchAvailabilityV1, MachineDiagnosticV2, MapConnectivityV1, MapServiceV1,
                          MapSummaryV1, MapCommandV1, InterfaceDiagnosticV1, HaulTruckProductionCycleV1,
                          HaulTruckProductionStateV2, HaulTruckProductionStateSensorV1, HaulTruckPayloadV1,
                          HaulTruckDumpV1, HaulTruckAssignmentRequestV2, HaulTruckAssignmentResponseV1,
                          HaulTruckAssignmentResetV1, HaulTruckAssignmentV1, UnknownMember>;

// The member name a body is keyed by in the container ("FleetDefinitionV2", ...).
std::string_view memberName(const Body& body);

// One decoded message member plus the unknown fields found inside it (kept for a faithful round trip).
struct Member {
    Body body;
    nlohmann::json extra; // null, or an object of unknown members
};

// One JSON container (§4.2.1): header plus one or more members.
struct Envelope {
    Header header;
    std::vector<Member> members;
    std::vector<std::string> errors;   // members rejected (each names member and message)
    std::vector<std::string> warnings; // tolerated deviations (unknown members, repaired timestamps, aliases)
    bool outOfStandard = false;        // Protocol other than ISO23725

    template <class T> const T* find() const {
        for (auto& m : members)
            if (auto* p = std::get_if<T>(&m.body))
                return p;
        return nullptr;
    }
};

// Decodes one text frame. Fails (with a message) only when the frame is not a JSON object or its header is
// invalid; a member that fails validation is listed in errors and dropped while the good members are kept.
Result<Envelope> decodeMessage(std::string_view text, const InferredRules& rules = defaultInferredRules());
Result<Envelope> decodeJson(const nlohmann::json& doc, const InferredRules& rules = defaultInferredRules());

nlohmann::json toJson(const Envelope& env);
std::string encodeMessage(const Envelope& env);
// Convenience: header for "now" plus one body (EquipmentId when given).
std::string encodeMessage(const Body& body, std::optional<Guid> equipmentId = std::nullopt,
                          std::int64_t unixMs = -1);

// ---- helpers (exposed for tests and for the stack) ----
std::optional<std::int64_t> parseTimestamp(std::string_view text, bool repair, bool* repaired = nullptr);
std::string formatTimestamp(std::int64_t unixMs); // yyyy-MM-ddTHH:mm:ss.zzzZ
Timestamp makeTimestamp(std::int64_t unixMs);
bool isGuid(std::string_view s);
Guid newGuid(); // random v4

} // namespace ocu::iso23725
