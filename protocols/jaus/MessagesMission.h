#pragma once
// JAUS mission messages (AS6009 mobility, AS5710A core ListManager, IOP PathReporter): the ListManager
// (core 1.1 and mobility 1.0 share IDs and layouts), the Local/Global Waypoint List Drivers, the single
// Local/Global Waypoint Drivers and the PathReporter. Layouts and IDs from
// shared/research/jaus-autonomy.md §1-§4 and jaus-services-extra.md §3 (JSIDL). Same rules as Messages.h:
// little-endian, presence vectors first, scaled integers; decoders accept any presence vector and ignore
// trailing bytes, they fail only when a field that must be present is missing. Codecs in MessagesMission.cpp.
#include <cstdint>
#include <optional>
#include <vector>

#include "protocols/common/Bytes.h"
#include "protocols/common/Result.h"

namespace ocu::jaus {

namespace msg {
// ListManager (core 1.1 / mobility 1.0)
inline constexpr std::uint16_t SetElement = 0x041A, DeleteElement = 0x041B, ConfirmElementRequest = 0x041C,
                               RejectElementRequest = 0x041D, QueryElement = 0x241A,
                               QueryElementList = 0x241B, QueryElementCount = 0x241C, ReportElement = 0x441A,
                               ReportElementList = 0x441B, ReportElementCount = 0x441C;
// Waypoint (list) drivers (mobility 1.0 / 1.1 classic messages)
inline constexpr std::uint16_t ExecuteList = 0x041E, QueryActiveElement = 0x241E,
                               ReportActiveElement = 0x441E, SetTravelSpeed = 0x040A,
                               QueryTravelSpeed = 0x240A, ReportTravelSpeed = 0x440A,
                               SetGlobalWaypoint = 0x040C, QueryGlobalWaypoint = 0x240C,
                               ReportGlobalWaypoint = 0x440C, SetLocalWaypoint = 0x040D,
                               QueryLocalWaypoint = 0x240D, ReportLocalWaypoint = 0x440D;
// IOP PathReporter 1.1
inline constexpr std::uint16_t QueryPathReporterCapabilities = 0xDEF0, QueryPath = 0xDEF1,
                               ReportPathReporterCapabilities = 0xDEF2, ReportPath = 0xDEF3;
} // namespace msg

// Names of the IDs above (nullptr for others); messageName() falls back to it.
const char* missionMessageName(std::uint16_t id);

// ---- ListManager ----------------------------------------------------------------------------------------
// UID 0 = head in QueryElement/ExecuteList, 65535 = all in DeleteElement (jaus-autonomy.md §2.3).
inline constexpr std::uint16_t kHeadUid = 0, kAllUids = 0xFFFF;

// ElementRec: the element data of the waypoint drivers is a whole message including its ID (format 0).
struct ListElement {
    std::uint16_t uid = 0, previous = 0, next = 0;
    std::uint8_t format = 0; // 0 JAUS message, 1 user defined
    Bytes data;
    bool operator==(const ListElement&) const = default;
};
struct SetElement {
    std::uint8_t requestId = 0;
    std::vector<ListElement> elements; // count u8: at most 255 per message
};
struct DeleteElement {
    std::uint8_t requestId = 0;
    std::vector<std::uint16_t> uids; // count u8
};
enum class ElementRejection : std::uint8_t {
    InvalidElementId = 1,
    InvalidPrevious = 2,
    InvalidNext = 3,
    UnsupportedType = 4,
    NotFound = 5,
    OutOfMemory = 6,
    Unspecified = 7
};
const char* nameFor(ElementRejection code); // words for the operator; "code N" for others
struct RejectElementRequest {
    std::uint8_t requestId = 0;
    std::uint8_t code = 7;
};
struct ReportElementList {
    std::vector<std::uint16_t> uids; // count u16, in the server's order
};

// ---- Waypoint drivers -----------------------------------------------------------------------------------
// ExecuteList: speed u16[0,327.67] m/s; PV b0 = start UID (0 = head).
struct ExecuteList {
    double speed = 0;
    std::optional<std::uint16_t> startUid;
};
// Set/Report{Global,Local}Waypoint (0x040C/0x440C, 0x040D/0x440D): mandatory position, optional
// b0 altitude or z, b1-b3 attitude at the waypoint, b4 waypoint tolerance u16[0,100] m, b5 path tolerance
// u32[0,100000] m (0 = infinite).
struct GlobalWaypoint {
    double lat = 0, lon = 0; // degrees WGS84
    std::optional<double> alt, roll, pitch, yaw, waypointTolerance, pathTolerance;
};
struct LocalWaypoint {
    double x = 0, y = 0; // metres in the vehicle's local frame
    std::optional<double> z, roll, pitch, yaw, waypointTolerance, pathTolerance;
};

// ---- PathReporter ---------------------------------------------------------------------------------------
enum class PathType : std::uint8_t {
    HistoricalGlobal = 0,
    HistoricalLocal = 1,
    PlannedGlobal = 2,
    PlannedLocal = 3
};
inline bool isGlobalPath(std::uint8_t type) {
    return type == 0 || type == 2;
}
struct QueryPath {
    std::uint8_t pathType = 1;
    std::optional<double> targetResolution;                    // b0 u16[0,10000] m
    std::optional<std::uint16_t> maximumPoints;                // b1
    std::optional<std::uint32_t> maximumDistance, maximumTime; // b2 m, b3 s, not scaled
};
struct PathCapability {
    std::uint8_t pathType = 1;
    std::optional<double> minResolution, maxResolution;        // b0, b1 u16[0,10000] m
    std::optional<std::uint16_t> maximumPoints;                // b2
    std::optional<std::uint32_t> maximumDistance, maximumTime; // b3 m, b4 s
};
struct ReportPathReporterCapabilities {
    std::vector<PathCapability> paths; // count u8
};
// One pose of a path, PV u16: a global path fills lat/lon/alt, a local one x/y/z (same scalings as
// ReportGlobalPose / ReportLocalPose).
struct PathPoint {
    std::optional<double> lat, lon, alt, x, y, z, positionRms, roll, pitch, yaw, attitudeRms;
    std::optional<std::uint32_t> timestamp;
};
struct ReportPath {
    std::uint8_t pathType = 1;     // the variant tag
    std::vector<PathPoint> points; // count u16
};

// ---- Encoders (payload = ID + body) ---------------------------------------------------------------------
Bytes encode(const ListElement& m, std::uint16_t id = msg::ReportElement); // ReportElement
Bytes encode(const SetElement& m);
Bytes encode(const DeleteElement& m);
Bytes encode(const RejectElementRequest& m);
Bytes encode(const ReportElementList& m);
Bytes encode(const ExecuteList& m);
Bytes encodeTravelSpeed(std::uint16_t id, double speed); // SetTravelSpeed or ReportTravelSpeed
Bytes encode(const GlobalWaypoint& m, std::uint16_t id = msg::SetGlobalWaypoint);
Bytes encode(const LocalWaypoint& m, std::uint16_t id = msg::SetLocalWaypoint);
Bytes encode(const QueryPath& m);
Bytes encode(const ReportPathReporterCapabilities& m);
Bytes encode(const ReportPath& m);
// ConfirmElementRequest (RequestID), QueryElement (UID), ReportElementCount, ReportActiveElement, the empty
// queries and Query{Global,Local}Waypoint (PV u8): encodeU8 / encodeU16 / encodeEmpty of Messages.h.

// ---- Decoders (payload = ID + body; the ID must match) --------------------------------------------------
// ReportElement also without the format byte (JAUS++ leaves it out, jaus-autonomy.md §2.4).
Result<ListElement> decodeListElement(ByteSpan payload, std::uint16_t id = msg::ReportElement);
Result<SetElement> decodeSetElement(ByteSpan payload);
Result<DeleteElement> decodeDeleteElement(ByteSpan payload);
Result<RejectElementRequest> decodeRejectElementRequest(ByteSpan payload);
Result<ReportElementList> decodeReportElementList(ByteSpan payload);
Result<ExecuteList> decodeExecuteList(ByteSpan payload);
Result<double> decodeTravelSpeed(ByteSpan payload, std::uint16_t id);
Result<GlobalWaypoint> decodeGlobalWaypoint(ByteSpan payload, std::uint16_t id = msg::SetGlobalWaypoint);
Result<LocalWaypoint> decodeLocalWaypoint(ByteSpan payload, std::uint16_t id = msg::SetLocalWaypoint);
Result<QueryPath> decodeQueryPath(ByteSpan payload);
Result<ReportPathReporterCapabilities> decodeReportPathReporterCapabilities(ByteSpan payload);
Result<ReportPath> decodeReportPath(ByteSpan payload);

} // namespace ocu::jaus
