// Mission messages: ListManager, waypoint (list) drivers, PathReporter.
// Layouts: shared/research/jaus-autonomy.md §2.2, §3.1, §3.2, §4 and jaus-services-extra.md §3.2 (JSIDL).
#include "protocols/jaus/MessagesMission.h"

#include <array>
#include <numbers>

#include "protocols/jaus/MessageSupport.h"

namespace ocu::jaus {

using namespace codec;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSpeedMax = 327.67; // u16[0,327.67] m/s, LSB 0.005

// Optional fields of the waypoint records, PV u8 bits in table order (jaus-autonomy.md §3.2).
constexpr std::array<ScaledField<GlobalWaypoint>, 6> kGlobalWaypointFields{{
    {&GlobalWaypoint::alt, 4, -10000, 35000},
    {&GlobalWaypoint::roll, 2, -kPi, kPi},
    {&GlobalWaypoint::pitch, 2, -kPi, kPi},
    {&GlobalWaypoint::yaw, 2, -kPi, kPi},
    {&GlobalWaypoint::waypointTolerance, 2, 0, 100},
    {&GlobalWaypoint::pathTolerance, 4, 0, 100000},
}};
constexpr std::array<ScaledField<LocalWaypoint>, 6> kLocalWaypointFields{{
    {&LocalWaypoint::z, 4, -100000, 100000},
    {&LocalWaypoint::roll, 2, -kPi, kPi},
    {&LocalWaypoint::pitch, 2, -kPi, kPi},
    {&LocalWaypoint::yaw, 2, -kPi, kPi},
    {&LocalWaypoint::waypointTolerance, 2, 0, 100},
    {&LocalWaypoint::pathTolerance, 4, 0, 100000},
}};
// Path poses, PV u16 bits 0-7 (bit 8 = the raw timestamp), jaus-services-extra.md §3.2.
constexpr std::array<ScaledField<PathPoint>, 8> kGlobalPathFields{{
    {&PathPoint::lat, 4, -90, 90},
    {&PathPoint::lon, 4, -180, 180},
    {&PathPoint::alt, 4, -10000, 35000},
    {&PathPoint::positionRms, 4, 0, 100},
    {&PathPoint::roll, 2, -kPi, kPi},
    {&PathPoint::pitch, 2, -kPi, kPi},
    {&PathPoint::yaw, 2, -kPi, kPi},
    {&PathPoint::attitudeRms, 2, 0, kPi},
}};
constexpr std::array<ScaledField<PathPoint>, 8> kLocalPathFields{{
    {&PathPoint::x, 4, -100000, 100000},
    {&PathPoint::y, 4, -100000, 100000},
    {&PathPoint::z, 4, -100000, 100000},
    {&PathPoint::positionRms, 4, 0, 100},
    {&PathPoint::roll, 2, -kPi, kPi},
    {&PathPoint::pitch, 2, -kPi, kPi},
    {&PathPoint::yaw, 2, -kPi, kPi},
    {&PathPoint::attitudeRms, 2, 0, kPi},
}};
constexpr std::uint32_t kPathStampBit = 1u << 8;

void putElement(ByteWriter& w, const ListElement& e) {
    w.u16(e.uid);
    w.u16(e.previous);
    w.u16(e.next);
    w.u8(e.format);
    w.u16(std::uint16_t(e.data.size()));
    w.bytes(e.data);
}
ListElement getElement(ByteReader& r) {
    ListElement e;
    e.uid = r.u16();
    e.previous = r.u16();
    e.next = r.u16();
    e.format = r.u8();
    const std::uint16_t n = r.u16();
    auto b = r.bytes(n);
    e.data.assign(b.begin(), b.end());
    return e;
}

void putResolution(ByteWriter& w, const std::optional<double>& v) {
    if (v)
        w.u16(scaleToInt<std::uint16_t>(*v, 0, 10000));
}
std::optional<double> getResolution(ByteReader& r, std::uint32_t pv, int bit) {
    if (!(pv & (1u << bit)))
        return std::nullopt;
    return intToScale<std::uint16_t>(r.u16(), 0, 10000);
}
template <class U> void putRaw(ByteWriter& w, const std::optional<U>& v) {
    if (v)
        putUInt<U>(w, *v);
}
template <class U> std::optional<U> getRaw(ByteReader& r, std::uint32_t pv, int bit) {
    if (!(pv & (1u << bit)))
        return std::nullopt;
    return getUInt<U>(r);
}
template <class T> std::uint8_t bitIf(const std::optional<T>& v, int bit) {
    return v ? std::uint8_t(1u << bit) : std::uint8_t(0);
}

} // namespace

const char* missionMessageName(std::uint16_t id) {
    switch (id) {
    case msg::SetElement:
        return "SetElement";
    case msg::DeleteElement:
        return "DeleteElement";
    case msg::ConfirmElementRequest:
        return "ConfirmElementRequest";
    case msg::RejectElementRequest:
        return "RejectElementRequest";
    case msg::QueryElement:
        return "QueryElement";
    case msg::QueryElementList:
        return "QueryElementList";
    case msg::QueryElementCount:
        return "QueryElementCount";
    case msg::ReportElement:
        return "ReportElement";
    case msg::ReportElementList:
        return "ReportElementList";
    case msg::ReportElementCount:
        return "ReportElementCount";
    case msg::ExecuteList:
        return "ExecuteList";
    case msg::QueryActiveElement:
        return "QueryActiveElement";
    case msg::ReportActiveElement:
        return "ReportActiveElement";
    case msg::SetTravelSpeed:
        return "SetTravelSpeed";
    case msg::QueryTravelSpeed:
        return "QueryTravelSpeed";
    case msg::ReportTravelSpeed:
        return "ReportTravelSpeed";
    case msg::SetGlobalWaypoint:
        return "SetGlobalWaypoint";
    case msg::QueryGlobalWaypoint:
        return "QueryGlobalWaypoint";
    case msg::ReportGlobalWaypoint:
        return "ReportGlobalWaypoint";
    case msg::SetLocalWaypoint:
        return "SetLocalWaypoint";
    case msg::QueryLocalWaypoint:
        return "QueryLocalWaypoint";
    case msg::ReportLocalWaypoint:
        return "ReportLocalWaypoint";
    case msg::QueryPathReporterCapabilities:
        return "QueryPathReporterCapabilities";
    case msg::QueryPath:
        return "QueryPath";
    case msg::ReportPathReporterCapabilities:
        return "ReportPathReporterCapabilities";
    case msg::ReportPath:
        return "ReportPath";
    default:
        return nullptr;
    }
}

const char* nameFor(ElementRejection code) {
    switch (code) {
    case ElementRejection::InvalidElementId:
        return "invalid element ID";
    case ElementRejection::InvalidPrevious:
        return "invalid previous element";
    case ElementRejection::InvalidNext:
        return "invalid next element";
    case ElementRejection::UnsupportedType:
        return "unsupported element type";
    case ElementRejection::NotFound:
        return "element not found";
    case ElementRejection::OutOfMemory:
        return "out of memory";
    case ElementRejection::Unspecified:
        return "unspecified error";
    }
    return "unknown code";
}

// ---- ListManager ----------------------------------------------------------------------------------------
Bytes encode(const ListElement& m, std::uint16_t id) {
    Bytes out;
    auto w = start(out, id);
    putElement(w, m);
    return out;
}
Result<ListElement> decodeListElement(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    // With the format byte the length sits at body offset 7, without it (JAUS++) at 6; the one that matches
    // the bytes that follow wins, the JSIDL layout first.
    const ByteSpan body = p.subspan(2);
    auto lengthAt = [&](std::size_t at) {
        return body.size() >= at + 2 ? std::size_t(body[at] | (body[at + 1] << 8)) : std::size_t(~0u);
    };
    const bool jsidl = body.size() >= 9 && lengthAt(7) == body.size() - 9;
    if (!jsidl && body.size() >= 8 && lengthAt(6) == body.size() - 8) {
        ListElement e;
        e.uid = r->u16();
        e.previous = r->u16();
        e.next = r->u16();
        auto b = r->bytes(r->u16());
        e.data.assign(b.begin(), b.end());
        return finish(*r, e, id);
    }
    ListElement e = getElement(*r);
    return finish(*r, e, id);
}

Bytes encode(const SetElement& m) {
    Bytes out;
    auto w = start(out, msg::SetElement);
    w.u8(m.requestId);
    w.u8(std::uint8_t(m.elements.size()));
    for (const ListElement& e : m.elements)
        putElement(w, e);
    return out;
}
Result<SetElement> decodeSetElement(ByteSpan p) {
    auto r = open(p, msg::SetElement);
    if (!r)
        return makeError(r.error());
    SetElement m;
    m.requestId = r->u8();
    const std::uint8_t n = r->u8();
    for (int i = 0; i < n && r->ok(); ++i)
        m.elements.push_back(getElement(*r));
    return finish(*r, m, msg::SetElement);
}

Bytes encode(const DeleteElement& m) {
    Bytes out;
    auto w = start(out, msg::DeleteElement);
    w.u8(m.requestId);
    w.u8(std::uint8_t(m.uids.size()));
    for (std::uint16_t u : m.uids)
        w.u16(u);
    return out;
}
Result<DeleteElement> decodeDeleteElement(ByteSpan p) {
    auto r = open(p, msg::DeleteElement);
    if (!r)
        return makeError(r.error());
    DeleteElement m;
    m.requestId = r->u8();
    const std::uint8_t n = r->u8();
    for (int i = 0; i < n && r->ok(); ++i)
        m.uids.push_back(r->u16());
    return finish(*r, m, msg::DeleteElement);
}

Bytes encode(const RejectElementRequest& m) {
    Bytes out;
    auto w = start(out, msg::RejectElementRequest);
    w.u8(m.requestId);
    w.u8(m.code);
    return out;
}
Result<RejectElementRequest> decodeRejectElementRequest(ByteSpan p) {
    auto r = open(p, msg::RejectElementRequest);
    if (!r)
        return makeError(r.error());
    RejectElementRequest m;
    m.requestId = r->u8();
    m.code = r->u8();
    return finish(*r, m, msg::RejectElementRequest);
}

Bytes encode(const ReportElementList& m) {
    Bytes out;
    auto w = start(out, msg::ReportElementList);
    w.u16(std::uint16_t(m.uids.size()));
    for (std::uint16_t u : m.uids)
        w.u16(u);
    return out;
}
Result<ReportElementList> decodeReportElementList(ByteSpan p) {
    auto r = open(p, msg::ReportElementList);
    if (!r)
        return makeError(r.error());
    ReportElementList m;
    const std::uint16_t n = r->u16();
    if (std::size_t(n) * 2 > r->remaining())
        return makeError("truncated: ReportElementList lists more UIDs than it carries");
    for (int i = 0; i < n; ++i)
        m.uids.push_back(r->u16());
    return finish(*r, m, msg::ReportElementList);
}

// ---- Waypoint drivers -----------------------------------------------------------------------------------
Bytes encode(const ExecuteList& m) {
    Bytes out;
    auto w = start(out, msg::ExecuteList);
    w.u8(m.startUid ? 1 : 0);
    w.u16(scaleToInt<std::uint16_t>(m.speed, 0, kSpeedMax));
    if (m.startUid)
        w.u16(*m.startUid);
    return out;
}
Result<ExecuteList> decodeExecuteList(ByteSpan p) {
    auto r = open(p, msg::ExecuteList);
    if (!r)
        return makeError(r.error());
    ExecuteList m;
    const std::uint8_t pv = r->u8();
    m.speed = intToScale<std::uint16_t>(r->u16(), 0, kSpeedMax);
    if (pv & 1)
        m.startUid = r->u16();
    return finish(*r, m, msg::ExecuteList);
}

Bytes encodeTravelSpeed(std::uint16_t id, double speed) {
    return encodeU16(id, scaleToInt<std::uint16_t>(speed, 0, kSpeedMax));
}
Result<double> decodeTravelSpeed(ByteSpan p, std::uint16_t id) {
    auto v = decodeU16(p, id);
    if (!v)
        return makeError(v.error());
    return intToScale<std::uint16_t>(*v, 0, kSpeedMax);
}

Bytes encode(const GlobalWaypoint& m, std::uint16_t id) {
    Bytes out;
    auto w = start(out, id);
    w.u8(std::uint8_t(presenceOf<kGlobalWaypointFields>(m)));
    w.u32(scaleToInt<std::uint32_t>(m.lat, -90, 90));
    w.u32(scaleToInt<std::uint32_t>(m.lon, -180, 180));
    putFields<kGlobalWaypointFields>(w, m);
    return out;
}
Result<GlobalWaypoint> decodeGlobalWaypoint(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    GlobalWaypoint m;
    const std::uint32_t pv = r->u8();
    m.lat = intToScale<std::uint32_t>(r->u32(), -90, 90);
    m.lon = intToScale<std::uint32_t>(r->u32(), -180, 180);
    getFields<kGlobalWaypointFields>(*r, pv, 0, m);
    return finish(*r, m, id);
}
Bytes encode(const LocalWaypoint& m, std::uint16_t id) {
    Bytes out;
    auto w = start(out, id);
    w.u8(std::uint8_t(presenceOf<kLocalWaypointFields>(m)));
    w.u32(scaleToInt<std::uint32_t>(m.x, -100000, 100000));
    w.u32(scaleToInt<std::uint32_t>(m.y, -100000, 100000));
    putFields<kLocalWaypointFields>(w, m);
    return out;
}
Result<LocalWaypoint> decodeLocalWaypoint(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    LocalWaypoint m;
    const std::uint32_t pv = r->u8();
    m.x = intToScale<std::uint32_t>(r->u32(), -100000, 100000);
    m.y = intToScale<std::uint32_t>(r->u32(), -100000, 100000);
    getFields<kLocalWaypointFields>(*r, pv, 0, m);
    return finish(*r, m, id);
}

// ---- PathReporter ---------------------------------------------------------------------------------------
Bytes encode(const QueryPath& m) {
    Bytes out;
    auto w = start(out, msg::QueryPath);
    w.u8(std::uint8_t(bitIf(m.targetResolution, 0) | bitIf(m.maximumPoints, 1) | bitIf(m.maximumDistance, 2) |
                      bitIf(m.maximumTime, 3)));
    w.u8(m.pathType);
    putResolution(w, m.targetResolution);
    putRaw(w, m.maximumPoints);
    putRaw(w, m.maximumDistance);
    putRaw(w, m.maximumTime);
    return out;
}
Result<QueryPath> decodeQueryPath(ByteSpan p) {
    auto r = open(p, msg::QueryPath);
    if (!r)
        return makeError(r.error());
    QueryPath m;
    const std::uint32_t pv = r->u8();
    m.pathType = r->u8();
    m.targetResolution = getResolution(*r, pv, 0);
    m.maximumPoints = getRaw<std::uint16_t>(*r, pv, 1);
    m.maximumDistance = getRaw<std::uint32_t>(*r, pv, 2);
    m.maximumTime = getRaw<std::uint32_t>(*r, pv, 3);
    return finish(*r, m, msg::QueryPath);
}

Bytes encode(const ReportPathReporterCapabilities& m) {
    Bytes out;
    auto w = start(out, msg::ReportPathReporterCapabilities);
    w.u8(std::uint8_t(m.paths.size()));
    for (const PathCapability& c : m.paths) {
        w.u8(std::uint8_t(bitIf(c.minResolution, 0) | bitIf(c.maxResolution, 1) | bitIf(c.maximumPoints, 2) |
                          bitIf(c.maximumDistance, 3) | bitIf(c.maximumTime, 4)));
        w.u8(c.pathType);
        putResolution(w, c.minResolution);
        putResolution(w, c.maxResolution);
        putRaw(w, c.maximumPoints);
        putRaw(w, c.maximumDistance);
        putRaw(w, c.maximumTime);
    }
    return out;
}
Result<ReportPathReporterCapabilities> decodeReportPathReporterCapabilities(ByteSpan p) {
    auto r = open(p, msg::ReportPathReporterCapabilities);
    if (!r)
        return makeError(r.error());
    ReportPathReporterCapabilities m;
    const std::uint8_t n = r->u8();
    for (int i = 0; i < n && r->ok(); ++i) {
        PathCapability c;
        const std::uint32_t pv = r->u8();
        c.pathType = r->u8();
        c.minResolution = getResolution(*r, pv, 0);
        c.maxResolution = getResolution(*r, pv, 1);
        c.maximumPoints = getRaw<std::uint16_t>(*r, pv, 2);
        c.maximumDistance = getRaw<std::uint32_t>(*r, pv, 3);
        c.maximumTime = getRaw<std::uint32_t>(*r, pv, 4);
        m.paths.push_back(c);
    }
    return finish(*r, m, msg::ReportPathReporterCapabilities);
}

Bytes encode(const ReportPath& m) {
    Bytes out;
    out.reserve(5 + m.points.size() * 16);
    auto w = start(out, msg::ReportPath);
    w.u8(m.pathType);
    w.u16(std::uint16_t(m.points.size()));
    const bool global = isGlobalPath(m.pathType);
    for (const PathPoint& pt : m.points) {
        const std::uint32_t pv =
            global ? presenceOf<kGlobalPathFields>(pt) : presenceOf<kLocalPathFields>(pt);
        w.u16(std::uint16_t(pv | (pt.timestamp ? kPathStampBit : 0u)));
        if (global)
            putFields<kGlobalPathFields>(w, pt);
        else
            putFields<kLocalPathFields>(w, pt);
        if (pt.timestamp)
            w.u32(*pt.timestamp);
    }
    return out;
}
Result<ReportPath> decodeReportPath(ByteSpan p) {
    auto r = open(p, msg::ReportPath);
    if (!r)
        return makeError(r.error());
    ReportPath m;
    m.pathType = r->u8();
    if (m.pathType > 3)
        return makeError("value: ReportPath path type " + std::to_string(m.pathType) + " is not 0-3");
    const std::uint16_t n = r->u16();
    const bool global = isGlobalPath(m.pathType);
    for (int i = 0; i < n && r->ok(); ++i) {
        PathPoint pt;
        const std::uint32_t pv = r->u16();
        if (global)
            getFields<kGlobalPathFields>(*r, pv, 0, pt);
        else
            getFields<kLocalPathFields>(*r, pv, 0, pt);
        if (pv & kPathStampBit)
            pt.timestamp = r->u32();
        m.points.push_back(pt);
    }
    return finish(*r, m, msg::ReportPath);
}

} // namespace ocu::jaus
