#include "protocols/jaus/Messages.h"

#include <numbers>

namespace ocu::jaus {

namespace {

constexpr double kPi = std::numbers::pi;

ByteWriter start(Bytes& out, std::uint16_t id) {
    out.reserve(48); // most messages fit: one allocation instead of several regrowths
    ByteWriter w(out);
    w.u16(id);
    return w;
}

// Opens a reader positioned after the message ID; fails when the ID differs.
Result<ByteReader> open(ByteSpan payload, std::uint16_t id) {
    if (payload.size() < 2)
        return makeError("short: payload has no message ID");
    const std::uint16_t got = peekMessageId(payload);
    if (got != id)
        return makeError("message_id: expected " + std::string(messageName(id)) + ", got 0x" +
                         std::to_string(got));
    ByteReader r(payload);
    r.u16();
    return r;
}

template <class T> Result<T> finish(const ByteReader& r, T value, std::uint16_t id) {
    if (!r.ok())
        return makeError(std::string("truncated: ") + messageName(id) + " body is too short");
    return value;
}

void putString8(ByteWriter& w, const std::string& s) {
    const std::size_t n = std::min<std::size_t>(s.size(), 255);
    w.u8(std::uint8_t(n));
    w.bytes(ByteSpan(reinterpret_cast<const std::uint8_t*>(s.data()), n));
}
std::string getString8(ByteReader& r) {
    auto n = r.u8();
    auto b = r.bytes(n);
    return std::string(b.begin(), b.end());
}
void putBlob32(ByteWriter& w, const Bytes& b) {
    w.u32(std::uint32_t(b.size()));
    w.bytes(b);
}
Bytes getBlob32(ByteReader& r) {
    auto n = r.u32();
    if (n > r.remaining()) {
        r.fail();
        return {};
    }
    auto b = r.bytes(n);
    return Bytes(b.begin(), b.end());
}

// Presence-vector helpers: each optional field is one bit, in declaration order.
struct PvWriter {
    std::uint32_t pv = 0;
    int bit = 0;
    template <class T> void mark(const std::optional<T>& v) {
        if (v)
            pv |= 1u << bit;
        ++bit;
    }
};

void putU32s(ByteWriter& w, const std::optional<double>& v, double lo, double hi) {
    if (v)
        w.u32(scaleToInt<std::uint32_t>(*v, lo, hi));
}
void putU16s(ByteWriter& w, const std::optional<double>& v, double lo, double hi) {
    if (v)
        w.u16(scaleToInt<std::uint16_t>(*v, lo, hi));
}
void putU8s(ByteWriter& w, const std::optional<double>& v, double lo, double hi) {
    if (v)
        w.u8(scaleToInt<std::uint8_t>(*v, lo, hi));
}
void getU32s(ByteReader& r, std::uint32_t pv, int bit, std::optional<double>& v, double lo, double hi) {
    if (pv & (1u << bit))
        v = intToScale<std::uint32_t>(r.u32(), lo, hi);
}
void getU16s(ByteReader& r, std::uint32_t pv, int bit, std::optional<double>& v, double lo, double hi) {
    if (pv & (1u << bit))
        v = intToScale<std::uint16_t>(r.u16(), lo, hi);
}
void getU8s(ByteReader& r, std::uint32_t pv, int bit, std::optional<double>& v, double lo, double hi) {
    if (pv & (1u << bit))
        v = intToScale<std::uint8_t>(r.u8(), lo, hi);
}

void putServices(ByteWriter& w, const std::vector<ServiceRecord>& s) {
    w.u8(std::uint8_t(std::min<std::size_t>(s.size(), 255)));
    for (std::size_t i = 0; i < s.size() && i < 255; ++i) {
        putString8(w, s[i].uri);
        w.u8(s[i].major);
        w.u8(s[i].minor);
    }
}
std::vector<ServiceRecord> getServices(ByteReader& r) {
    std::vector<ServiceRecord> out;
    auto n = r.u8();
    for (int i = 0; i < n && r.ok(); ++i) {
        ServiceRecord s;
        s.uri = getString8(r);
        s.major = r.u8();
        s.minor = r.u8();
        out.push_back(std::move(s));
    }
    return out;
}
void putNodes(ByteWriter& w, const std::vector<NodeServices>& nodes) {
    w.u8(std::uint8_t(std::min<std::size_t>(nodes.size(), 255)));
    for (auto& n : nodes) {
        w.u8(n.node);
        w.u8(std::uint8_t(std::min<std::size_t>(n.components.size(), 255)));
        for (auto& c : n.components) {
            w.u8(c.component);
            w.u8(c.instance);
            putServices(w, c.services);
        }
    }
}
std::vector<NodeServices> getNodes(ByteReader& r) {
    std::vector<NodeServices> out;
    auto nn = r.u8();
    for (int i = 0; i < nn && r.ok(); ++i) {
        NodeServices n;
        n.node = r.u8();
        auto nc = r.u8();
        for (int j = 0; j < nc && r.ok(); ++j) {
            ComponentServices c;
            c.component = r.u8();
            c.instance = r.u8();
            c.services = getServices(r);
            n.components.push_back(std::move(c));
        }
        out.push_back(std::move(n));
    }
    return out;
}

} // namespace

const char* messageName(std::uint16_t id) {
    switch (id) {
    case msg::SetAuthority:
        return "SetAuthority";
    case msg::Shutdown:
        return "Shutdown";
    case msg::Standby:
        return "Standby";
    case msg::Resume:
        return "Resume";
    case msg::Reset:
        return "Reset";
    case msg::SetEmergency:
        return "SetEmergency";
    case msg::ClearEmergency:
        return "ClearEmergency";
    case msg::RequestControl:
        return "RequestControl";
    case msg::ReleaseControl:
        return "ReleaseControl";
    case msg::ConfirmControl:
        return "ConfirmControl";
    case msg::RejectControl:
        return "RejectControl";
    case msg::CreateEvent:
        return "CreateEvent";
    case msg::UpdateEvent:
        return "UpdateEvent";
    case msg::CancelEvent:
        return "CancelEvent";
    case msg::ConfirmEventRequest:
        return "ConfirmEventRequest";
    case msg::RejectEventRequest:
        return "RejectEventRequest";
    case msg::RegisterServices:
        return "RegisterServices";
    case msg::QueryAuthority:
        return "QueryAuthority";
    case msg::QueryStatus:
        return "QueryStatus";
    case msg::QueryTimeout:
        return "QueryTimeout";
    case msg::QueryControl:
        return "QueryControl";
    case msg::QueryEvents:
        return "QueryEvents";
    case msg::QueryHeartbeatPulse:
        return "QueryHeartbeatPulse";
    case msg::QueryIdentification:
        return "QueryIdentification";
    case msg::QueryConfiguration:
        return "QueryConfiguration";
    case msg::QuerySubsystemList:
        return "QuerySubsystemList";
    case msg::QueryServices:
        return "QueryServices";
    case msg::QueryServiceList:
        return "QueryServiceList";
    case msg::ReportAuthority:
        return "ReportAuthority";
    case msg::ReportStatus:
        return "ReportStatus";
    case msg::ReportTimeout:
        return "ReportTimeout";
    case msg::ReportControl:
        return "ReportControl";
    case msg::ReportEvents:
        return "ReportEvents";
    case msg::Event:
        return "Event";
    case msg::ReportHeartbeatPulse:
        return "ReportHeartbeatPulse";
    case msg::ReportIdentification:
        return "ReportIdentification";
    case msg::ReportConfiguration:
        return "ReportConfiguration";
    case msg::ReportSubsystemList:
        return "ReportSubsystemList";
    case msg::ReportServices:
        return "ReportServices";
    case msg::ReportServiceList:
        return "ReportServiceList";
    case msg::SetWrenchEffort:
        return "SetWrenchEffort";
    case msg::QueryWrenchEffort:
        return "QueryWrenchEffort";
    case msg::ReportWrenchEffort:
        return "ReportWrenchEffort";
    case msg::SetVelocityCommand:
        return "SetVelocityCommand";
    case msg::QueryVelocityCommand:
        return "QueryVelocityCommand";
    case msg::ReportVelocityCommand:
        return "ReportVelocityCommand";
    case msg::QueryGlobalPose:
        return "QueryGlobalPose";
    case msg::ReportGlobalPose:
        return "ReportGlobalPose";
    case msg::QueryLocalPose:
        return "QueryLocalPose";
    case msg::ReportLocalPose:
        return "ReportLocalPose";
    case msg::QueryVelocityState:
        return "QueryVelocityState";
    case msg::ReportVelocityState:
        return "ReportVelocityState";
    case msg::QueryPlatformSpecifications:
        return "QueryPlatformSpecifications";
    case msg::ReportPlatformSpecifications:
        return "ReportPlatformSpecifications";
    case msg::QueryHealthSummary:
        return "QueryHealthSummary";
    case msg::UpdateHealthSummary:
        return "UpdateHealthSummary";
    case msg::ReportHealthSummary:
        return "ReportHealthSummary";
    default:
        return "unknown";
    }
}

const char* toString(ManagementState s) {
    switch (s) {
    case ManagementState::Init:
        return "INIT";
    case ManagementState::Ready:
        return "READY";
    case ManagementState::Standby:
        return "STANDBY";
    case ManagementState::Shutdown:
        return "SHUTDOWN";
    case ManagementState::Failure:
        return "FAILURE";
    case ManagementState::Emergency:
        return "EMERGENCY";
    }
    return "UNKNOWN";
}

// ---- simple bodies ----
Bytes encodeEmpty(std::uint16_t id) {
    Bytes out;
    start(out, id);
    return out;
}
Bytes encodeU8(std::uint16_t id, std::uint8_t v) {
    Bytes out;
    start(out, id).u8(v);
    return out;
}
Bytes encodeU16(std::uint16_t id, std::uint16_t v) {
    Bytes out;
    start(out, id).u16(v);
    return out;
}
Result<std::uint8_t> decodeU8(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    std::uint8_t v = r->u8();
    return finish(*r, v, id);
}
Result<std::uint16_t> decodeU16(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    std::uint16_t v = r->u16();
    return finish(*r, v, id);
}

Bytes encode(const ReportStatus& m) {
    Bytes out;
    auto w = start(out, msg::ReportStatus);
    w.u8(std::uint8_t(m.status));
    w.u32(m.reserved);
    return out;
}
Result<ReportStatus> decodeReportStatus(ByteSpan p) {
    auto r = open(p, msg::ReportStatus);
    if (!r)
        return makeError(r.error());
    ReportStatus m;
    auto s = r->u8();
    if (s > 5)
        return makeError("value: ReportStatus status " + std::to_string(s) + " out of range");
    m.status = ManagementState(s);
    // Reserved u32: tolerated when missing (some peers send only the status byte).
    if (r->remaining() >= 4)
        m.reserved = r->u32();
    return finish(*r, m, msg::ReportStatus);
}

Bytes encode(const ReportControl& m) {
    Bytes out;
    auto w = start(out, msg::ReportControl);
    w.u16(m.controller.subsystem);
    w.u8(m.controller.node);
    w.u8(m.controller.component);
    w.u8(m.authority);
    return out;
}
Result<ReportControl> decodeReportControl(ByteSpan p) {
    auto r = open(p, msg::ReportControl);
    if (!r)
        return makeError(r.error());
    ReportControl m;
    m.controller.subsystem = r->u16();
    m.controller.node = r->u8();
    m.controller.component = r->u8();
    m.authority = r->u8();
    return finish(*r, m, msg::ReportControl);
}

Bytes encode(const QueryIdentification& m) {
    return encodeU8(msg::QueryIdentification, std::uint8_t(m.type));
}
Result<QueryIdentification> decodeQueryIdentification(ByteSpan p) {
    auto v = decodeU8(p, msg::QueryIdentification);
    if (!v)
        return makeError(v.error());
    if (*v < 1 || *v > 4)
        return makeError("value: QueryIdentification type " + std::to_string(*v) + " out of range");
    return QueryIdentification{IdQueryType(*v)};
}
Bytes encode(const ReportIdentification& m) {
    Bytes out;
    auto w = start(out, msg::ReportIdentification);
    w.u8(std::uint8_t(m.queryType));
    w.u16(std::uint16_t(m.type));
    putString8(w, m.identification);
    return out;
}
Result<ReportIdentification> decodeReportIdentification(ByteSpan p) {
    auto r = open(p, msg::ReportIdentification);
    if (!r)
        return makeError(r.error());
    ReportIdentification m;
    m.queryType = IdQueryType(r->u8());
    m.type = IdType(r->u16());
    m.identification = getString8(*r);
    return finish(*r, m, msg::ReportIdentification);
}

Bytes encode(const RegisterServices& m) {
    Bytes out;
    auto w = start(out, msg::RegisterServices);
    putServices(w, m.services);
    return out;
}
Result<RegisterServices> decodeRegisterServices(ByteSpan p) {
    auto r = open(p, msg::RegisterServices);
    if (!r)
        return makeError(r.error());
    RegisterServices m;
    m.services = getServices(*r);
    return finish(*r, m, msg::RegisterServices);
}

Bytes encode(const QueryServices& m) {
    Bytes out;
    auto w = start(out, msg::QueryServices);
    w.u8(std::uint8_t(m.nodes.size()));
    for (auto& n : m.nodes) {
        w.u8(n.node);
        w.u8(std::uint8_t(n.components.size()));
        for (auto c : n.components)
            w.u8(c);
    }
    return out;
}
Result<QueryServices> decodeQueryServices(ByteSpan p) {
    auto r = open(p, msg::QueryServices);
    if (!r)
        return makeError(r.error());
    QueryServices m;
    m.nodes.clear();
    auto nn = r->u8();
    for (int i = 0; i < nn && r->ok(); ++i) {
        QueryServices::Node n;
        n.node = r->u8();
        n.components.clear();
        auto nc = r->u8();
        for (int j = 0; j < nc && r->ok(); ++j)
            n.components.push_back(r->u8());
        m.nodes.push_back(std::move(n));
    }
    return finish(*r, m, msg::QueryServices);
}

Bytes encode(const ReportServices& m) {
    Bytes out;
    auto w = start(out, msg::ReportServices);
    putNodes(w, m.nodes);
    return out;
}
Result<ReportServices> decodeReportServices(ByteSpan p) {
    auto r = open(p, msg::ReportServices);
    if (!r)
        return makeError(r.error());
    ReportServices m;
    m.nodes = getNodes(*r);
    return finish(*r, m, msg::ReportServices);
}

Bytes encode(const QueryServiceList& m) {
    Bytes out;
    auto w = start(out, msg::QueryServiceList);
    w.u16(std::uint16_t(m.subsystems.size()));
    for (auto& s : m.subsystems) {
        w.u16(s.subsystem);
        w.u8(std::uint8_t(s.nodes.size()));
        for (auto& n : s.nodes) {
            w.u8(n.node);
            w.u8(std::uint8_t(n.components.size()));
            for (auto& c : n.components) {
                w.u8(c.searchFilter ? 1 : 0);
                w.u8(c.component);
                if (c.searchFilter)
                    putString8(w, *c.searchFilter);
            }
        }
    }
    return out;
}
Result<QueryServiceList> decodeQueryServiceList(ByteSpan p) {
    auto r = open(p, msg::QueryServiceList);
    if (!r)
        return makeError(r.error());
    QueryServiceList m;
    m.subsystems.clear();
    auto ns = r->u16();
    for (int i = 0; i < ns && r->ok(); ++i) {
        QueryServiceList::Subsystem s;
        s.subsystem = r->u16();
        s.nodes.clear();
        auto nn = r->u8();
        for (int j = 0; j < nn && r->ok(); ++j) {
            QueryServiceList::Node n;
            n.node = r->u8();
            n.components.clear();
            auto nc = r->u8();
            for (int k = 0; k < nc && r->ok(); ++k) {
                QueryServiceList::Comp c;
                auto pv = r->u8();
                c.component = r->u8();
                if (pv & 1)
                    c.searchFilter = getString8(*r);
                n.components.push_back(std::move(c));
            }
            s.nodes.push_back(std::move(n));
        }
        m.subsystems.push_back(std::move(s));
    }
    return finish(*r, m, msg::QueryServiceList);
}

Bytes encode(const ReportServiceList& m) {
    Bytes out;
    auto w = start(out, msg::ReportServiceList);
    w.u16(std::uint16_t(m.subsystems.size()));
    for (auto& s : m.subsystems) {
        w.u16(s.subsystem);
        putNodes(w, s.nodes);
    }
    return out;
}
Result<ReportServiceList> decodeReportServiceList(ByteSpan p) {
    auto r = open(p, msg::ReportServiceList);
    if (!r)
        return makeError(r.error());
    ReportServiceList m;
    auto ns = r->u16();
    for (int i = 0; i < ns && r->ok(); ++i) {
        ReportServiceList::Subsystem s;
        s.subsystem = r->u16();
        s.nodes = getNodes(*r);
        m.subsystems.push_back(std::move(s));
    }
    return finish(*r, m, msg::ReportServiceList);
}

Bytes encode(const ReportSubsystemList& m) {
    Bytes out;
    auto w = start(out, msg::ReportSubsystemList);
    w.u8(std::uint8_t(std::min<std::size_t>(m.subsystems.size(), 255)));
    for (std::size_t i = 0; i < m.subsystems.size() && i < 255; ++i) {
        w.u16(m.subsystems[i].subsystem);
        w.u8(m.subsystems[i].node);
        w.u8(m.subsystems[i].component);
    }
    return out;
}
Result<ReportSubsystemList> decodeReportSubsystemList(ByteSpan p) {
    auto r = open(p, msg::ReportSubsystemList);
    if (!r)
        return makeError(r.error());
    ReportSubsystemList m;
    auto n = r->u8();
    for (int i = 0; i < n && r->ok(); ++i) {
        JausId id;
        id.subsystem = r->u16();
        id.node = r->u8();
        id.component = r->u8();
        m.subsystems.push_back(id);
    }
    return finish(*r, m, msg::ReportSubsystemList);
}

// ---- events ----
Bytes encode(const CreateEvent& m) {
    Bytes out;
    auto w = start(out, msg::CreateEvent);
    w.u8(m.requestId);
    w.u8(std::uint8_t(m.type));
    w.u16(scaleToInt<std::uint16_t>(m.rateHz, 0, kEventRateMax));
    putBlob32(w, m.queryMessage);
    return out;
}
Result<CreateEvent> decodeCreateEvent(ByteSpan p) {
    auto r = open(p, msg::CreateEvent);
    if (!r)
        return makeError(r.error());
    CreateEvent m;
    m.requestId = r->u8();
    m.type = EventType(r->u8() & 1);
    m.rateHz = intToScale<std::uint16_t>(r->u16(), 0, kEventRateMax);
    m.queryMessage = getBlob32(*r);
    return finish(*r, m, msg::CreateEvent);
}
Bytes encode(const UpdateEvent& m) {
    Bytes out;
    auto w = start(out, msg::UpdateEvent);
    w.u8(m.requestId);
    w.u8(std::uint8_t(m.type));
    w.u16(scaleToInt<std::uint16_t>(m.rateHz, 0, kEventRateMax));
    w.u8(m.eventId);
    putBlob32(w, m.queryMessage);
    return out;
}
Result<UpdateEvent> decodeUpdateEvent(ByteSpan p) {
    auto r = open(p, msg::UpdateEvent);
    if (!r)
        return makeError(r.error());
    UpdateEvent m;
    m.requestId = r->u8();
    m.type = EventType(r->u8() & 1);
    m.rateHz = intToScale<std::uint16_t>(r->u16(), 0, kEventRateMax);
    m.eventId = r->u8();
    m.queryMessage = getBlob32(*r);
    return finish(*r, m, msg::UpdateEvent);
}
Bytes encode(const CancelEvent& m) {
    Bytes out;
    auto w = start(out, msg::CancelEvent);
    w.u8(m.requestId);
    w.u8(m.eventId);
    return out;
}
Result<CancelEvent> decodeCancelEvent(ByteSpan p) {
    auto r = open(p, msg::CancelEvent);
    if (!r)
        return makeError(r.error());
    CancelEvent m;
    m.requestId = r->u8();
    m.eventId = r->u8();
    return finish(*r, m, msg::CancelEvent);
}
Bytes encode(const ConfirmEventRequest& m) {
    Bytes out;
    auto w = start(out, msg::ConfirmEventRequest);
    w.u8(m.requestId);
    w.u8(m.eventId);
    w.u16(scaleToInt<std::uint16_t>(m.rateHz, 0, kEventRateMax));
    return out;
}
Result<ConfirmEventRequest> decodeConfirmEventRequest(ByteSpan p) {
    auto r = open(p, msg::ConfirmEventRequest);
    if (!r)
        return makeError(r.error());
    ConfirmEventRequest m;
    m.requestId = r->u8();
    m.eventId = r->u8();
    m.rateHz = intToScale<std::uint16_t>(r->u16(), 0, kEventRateMax);
    return finish(*r, m, msg::ConfirmEventRequest);
}
Bytes encode(const RejectEventRequest& m) {
    Bytes out;
    auto w = start(out, msg::RejectEventRequest);
    w.u8(std::uint8_t((m.responseCode ? 1 : 0) | (m.errorMessage ? 2 : 0)));
    w.u8(m.requestId);
    if (m.responseCode)
        w.u8(*m.responseCode);
    if (m.errorMessage)
        w.fixedString(*m.errorMessage, 80);
    return out;
}
Result<RejectEventRequest> decodeRejectEventRequest(ByteSpan p) {
    auto r = open(p, msg::RejectEventRequest);
    if (!r)
        return makeError(r.error());
    RejectEventRequest m;
    auto pv = r->u8();
    m.requestId = r->u8();
    if (pv & 1)
        m.responseCode = r->u8();
    if (pv & 2)
        m.errorMessage = r->fixedString(80);
    return finish(*r, m, msg::RejectEventRequest);
}
Bytes encode(const EventMsg& m) {
    Bytes out;
    auto w = start(out, msg::Event);
    w.u8(m.eventId);
    w.u8(m.sequence);
    putBlob32(w, m.reportMessage);
    return out;
}
Result<EventMsg> decodeEvent(ByteSpan p) {
    auto r = open(p, msg::Event);
    if (!r)
        return makeError(r.error());
    EventMsg m;
    m.eventId = r->u8();
    m.sequence = r->u8();
    m.reportMessage = getBlob32(*r);
    if (r->ok() && m.reportMessage.size() < 2)
        return makeError("value: Event wraps no report message");
    return finish(*r, m, msg::Event);
}
Bytes encode(const QueryEvents& m) {
    Bytes out;
    auto w = start(out, msg::QueryEvents);
    w.u8(m.variant);
    if (m.variant == 0)
        w.u16(m.value);
    else
        w.u8(std::uint8_t(m.value));
    return out;
}
Result<QueryEvents> decodeQueryEvents(ByteSpan p) {
    auto r = open(p, msg::QueryEvents);
    if (!r)
        return makeError(r.error());
    QueryEvents m;
    m.variant = r->u8();
    if (m.variant > 3)
        return makeError("value: QueryEvents variant " + std::to_string(m.variant));
    m.value = m.variant == 0 ? r->u16() : r->u8();
    return finish(*r, m, msg::QueryEvents);
}
Bytes encode(const ReportEvents& m) {
    Bytes out;
    auto w = start(out, msg::ReportEvents);
    w.u8(std::uint8_t(std::min<std::size_t>(m.events.size(), 255)));
    for (std::size_t i = 0; i < m.events.size() && i < 255; ++i) {
        w.u8(std::uint8_t(m.events[i].type));
        w.u8(m.events[i].eventId);
        putBlob32(w, m.events[i].queryMessage);
    }
    return out;
}
Result<ReportEvents> decodeReportEvents(ByteSpan p) {
    auto r = open(p, msg::ReportEvents);
    if (!r)
        return makeError(r.error());
    ReportEvents m;
    auto n = r->u8();
    for (int i = 0; i < n && r->ok(); ++i) {
        ReportEvents::Entry e;
        e.type = EventType(r->u8() & 1);
        e.eventId = r->u8();
        e.queryMessage = getBlob32(*r);
        m.events.push_back(std::move(e));
    }
    return finish(*r, m, msg::ReportEvents);
}

// ---- mobility ----
Bytes encodeWrench(std::uint16_t id, const WrenchEffort& m) {
    PvWriter pv;
    const std::optional<double>* prop[] = {&m.propLinX, &m.propLinY, &m.propLinZ,
                                           &m.propRotX, &m.propRotY, &m.propRotZ};
    const std::optional<double>* res[] = {&m.resLinX, &m.resLinY, &m.resLinZ,
                                          &m.resRotX, &m.resRotY, &m.resRotZ};
    for (auto* f : prop)
        pv.mark(*f);
    for (auto* f : res)
        pv.mark(*f);
    Bytes out;
    auto w = start(out, id);
    w.u16(std::uint16_t(pv.pv));
    for (auto* f : prop)
        putU16s(w, *f, -100, 100);
    for (auto* f : res)
        putU8s(w, *f, 0, 100);
    return out;
}
Result<WrenchEffort> decodeWrench(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    WrenchEffort m;
    std::optional<double>* prop[] = {&m.propLinX, &m.propLinY, &m.propLinZ,
                                     &m.propRotX, &m.propRotY, &m.propRotZ};
    std::optional<double>* res[] = {&m.resLinX, &m.resLinY, &m.resLinZ, &m.resRotX, &m.resRotY, &m.resRotZ};
    const std::uint32_t pv = r->u16();
    for (int i = 0; i < 6; ++i)
        getU16s(*r, pv, i, *prop[i], -100, 100);
    for (int i = 0; i < 6; ++i)
        getU8s(*r, pv, 6 + i, *res[i], 0, 100);
    return finish(*r, m, id);
}

Bytes encodeVelocityCommand(std::uint16_t id, const VelocityCommand& m) {
    PvWriter pv;
    pv.mark(m.vx);
    pv.mark(m.vy);
    pv.mark(m.vz);
    pv.mark(m.rollRate);
    pv.mark(m.pitchRate);
    pv.mark(m.yawRate);
    Bytes out;
    auto w = start(out, id);
    w.u8(std::uint8_t(pv.pv));
    w.u8(m.commandType);
    putU32s(w, m.vx, -327.68, 327.67);
    putU32s(w, m.vy, -327.68, 327.67);
    putU32s(w, m.vz, -327.68, 327.67);
    putU16s(w, m.rollRate, -32.768, 32.767);
    putU16s(w, m.pitchRate, -32.768, 32.767);
    putU16s(w, m.yawRate, -32.768, 32.767);
    return out;
}
Result<VelocityCommand> decodeVelocityCommand(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    VelocityCommand m;
    const std::uint32_t pv = r->u8();
    m.commandType = r->u8();
    getU32s(*r, pv, 0, m.vx, -327.68, 327.67);
    getU32s(*r, pv, 1, m.vy, -327.68, 327.67);
    getU32s(*r, pv, 2, m.vz, -327.68, 327.67);
    getU16s(*r, pv, 3, m.rollRate, -32.768, 32.767);
    getU16s(*r, pv, 4, m.pitchRate, -32.768, 32.767);
    getU16s(*r, pv, 5, m.yawRate, -32.768, 32.767);
    return finish(*r, m, id);
}
Bytes encodeQueryPv16(std::uint16_t id, std::uint16_t presence) {
    return encodeU16(id, presence);
}
Result<std::uint16_t> decodeQueryPv16(ByteSpan p, std::uint16_t id) {
    return decodeU16(p, id);
}
Bytes encodeQueryVelocityCommand(std::uint8_t presence, std::uint8_t commandType) {
    Bytes out;
    auto w = start(out, msg::QueryVelocityCommand);
    w.u8(presence);
    w.u8(commandType);
    return out;
}

Bytes encode(const GlobalPose& m, std::uint16_t id) {
    PvWriter pv;
    pv.mark(m.lat);
    pv.mark(m.lon);
    pv.mark(m.alt);
    pv.mark(m.positionRms);
    pv.mark(m.roll);
    pv.mark(m.pitch);
    pv.mark(m.yaw);
    pv.mark(m.attitudeRms);
    pv.mark(m.timestamp);
    Bytes out;
    auto w = start(out, id);
    w.u16(std::uint16_t(pv.pv));
    putU32s(w, m.lat, -90, 90);
    putU32s(w, m.lon, -180, 180);
    putU32s(w, m.alt, -10000, 35000);
    putU32s(w, m.positionRms, 0, 100);
    putU16s(w, m.roll, -kPi, kPi);
    putU16s(w, m.pitch, -kPi, kPi);
    putU16s(w, m.yaw, -kPi, kPi);
    putU16s(w, m.attitudeRms, 0, kPi);
    if (m.timestamp)
        w.u32(*m.timestamp);
    return out;
}
Result<GlobalPose> decodeGlobalPose(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    GlobalPose m;
    const std::uint32_t pv = r->u16();
    getU32s(*r, pv, 0, m.lat, -90, 90);
    getU32s(*r, pv, 1, m.lon, -180, 180);
    getU32s(*r, pv, 2, m.alt, -10000, 35000);
    getU32s(*r, pv, 3, m.positionRms, 0, 100);
    getU16s(*r, pv, 4, m.roll, -kPi, kPi);
    getU16s(*r, pv, 5, m.pitch, -kPi, kPi);
    getU16s(*r, pv, 6, m.yaw, -kPi, kPi);
    getU16s(*r, pv, 7, m.attitudeRms, 0, kPi);
    if (pv & (1u << 8))
        m.timestamp = r->u32();
    return finish(*r, m, id);
}
Bytes encode(const LocalPose& m, std::uint16_t id) {
    PvWriter pv;
    pv.mark(m.x);
    pv.mark(m.y);
    pv.mark(m.z);
    pv.mark(m.positionRms);
    pv.mark(m.roll);
    pv.mark(m.pitch);
    pv.mark(m.yaw);
    pv.mark(m.attitudeRms);
    pv.mark(m.timestamp);
    Bytes out;
    auto w = start(out, id);
    w.u16(std::uint16_t(pv.pv));
    putU32s(w, m.x, -100000, 100000);
    putU32s(w, m.y, -100000, 100000);
    putU32s(w, m.z, -100000, 100000);
    putU32s(w, m.positionRms, 0, 100);
    putU16s(w, m.roll, -kPi, kPi);
    putU16s(w, m.pitch, -kPi, kPi);
    putU16s(w, m.yaw, -kPi, kPi);
    putU16s(w, m.attitudeRms, 0, kPi);
    if (m.timestamp)
        w.u32(*m.timestamp);
    return out;
}
Result<LocalPose> decodeLocalPose(ByteSpan p, std::uint16_t id) {
    auto r = open(p, id);
    if (!r)
        return makeError(r.error());
    LocalPose m;
    const std::uint32_t pv = r->u16();
    getU32s(*r, pv, 0, m.x, -100000, 100000);
    getU32s(*r, pv, 1, m.y, -100000, 100000);
    getU32s(*r, pv, 2, m.z, -100000, 100000);
    getU32s(*r, pv, 3, m.positionRms, 0, 100);
    getU16s(*r, pv, 4, m.roll, -kPi, kPi);
    getU16s(*r, pv, 5, m.pitch, -kPi, kPi);
    getU16s(*r, pv, 6, m.yaw, -kPi, kPi);
    getU16s(*r, pv, 7, m.attitudeRms, 0, kPi);
    if (pv & (1u << 8))
        m.timestamp = r->u32();
    return finish(*r, m, id);
}
Bytes encode(const VelocityState& m) {
    PvWriter pv;
    pv.mark(m.vx);
    pv.mark(m.vy);
    pv.mark(m.vz);
    pv.mark(m.velocityRms);
    pv.mark(m.rollRate);
    pv.mark(m.pitchRate);
    pv.mark(m.yawRate);
    pv.mark(m.rateRms);
    pv.mark(m.timestamp);
    Bytes out;
    auto w = start(out, msg::ReportVelocityState);
    w.u16(std::uint16_t(pv.pv));
    putU32s(w, m.vx, -327.68, 327.67);
    putU32s(w, m.vy, -327.68, 327.67);
    putU32s(w, m.vz, -327.68, 327.67);
    putU32s(w, m.velocityRms, 0, 100);
    putU16s(w, m.rollRate, -32.768, 32.767);
    putU16s(w, m.pitchRate, -32.768, 32.767);
    putU16s(w, m.yawRate, -32.768, 32.767);
    putU16s(w, m.rateRms, 0, kPi);
    if (m.timestamp)
        w.u32(*m.timestamp);
    return out;
}
Result<VelocityState> decodeVelocityState(ByteSpan p) {
    auto r = open(p, msg::ReportVelocityState);
    if (!r)
        return makeError(r.error());
    VelocityState m;
    const std::uint32_t pv = r->u16();
    getU32s(*r, pv, 0, m.vx, -327.68, 327.67);
    getU32s(*r, pv, 1, m.vy, -327.68, 327.67);
    getU32s(*r, pv, 2, m.vz, -327.68, 327.67);
    getU32s(*r, pv, 3, m.velocityRms, 0, 100);
    getU16s(*r, pv, 4, m.rollRate, -32.768, 32.767);
    getU16s(*r, pv, 5, m.pitchRate, -32.768, 32.767);
    getU16s(*r, pv, 6, m.yawRate, -32.768, 32.767);
    getU16s(*r, pv, 7, m.rateRms, 0, kPi);
    if (pv & (1u << 8))
        m.timestamp = r->u32();
    return finish(*r, m, msg::ReportVelocityState);
}

Bytes encode(const PlatformSpecifications& m) {
    Bytes out;
    auto w = start(out, msg::ReportPlatformSpecifications);
    w.u8(m.steeringType);
    if (m.steeringType == 0) {
        PvWriter pv;
        pv.mark(m.trackSeparation);
        pv.mark(m.driveWheelRadius);
        w.u8(std::uint8_t(pv.pv));
        putU16s(w, m.trackSeparation, 0, 30);
        putU16s(w, m.driveWheelRadius, 0, 10);
    } else {
        PvWriter pv;
        pv.mark(m.steeringAngleRange);
        pv.mark(m.minTurnRadius);
        pv.mark(m.wheelSeparation);
        pv.mark(m.ackDriveWheelRadius);
        w.u8(std::uint8_t(pv.pv));
        putU16s(w, m.steeringAngleRange, -kPi / 2, kPi / 2);
        putU16s(w, m.minTurnRadius, 0, 25);
        putU16s(w, m.wheelSeparation, 0, 30);
        putU16s(w, m.ackDriveWheelRadius, 0, 10);
    }
    PvWriter iv;
    iv.mark(m.maxForwardSpeed);
    iv.mark(m.maxReverseSpeed);
    iv.mark(m.maxRotationalSpeed);
    iv.mark(m.maxForwardAccel);
    iv.mark(m.maxReverseAccel);
    iv.mark(m.maxForwardDecel);
    iv.mark(m.maxReverseDecel);
    w.u8(std::uint8_t(iv.pv));
    putU16s(w, m.maxForwardSpeed, 0, 90);
    putU16s(w, m.maxReverseSpeed, 0, 90);
    putU16s(w, m.maxRotationalSpeed, 0, 6.28);
    putU8s(w, m.maxForwardAccel, 0, 40);
    putU8s(w, m.maxReverseAccel, 0, 40);
    putU8s(w, m.maxForwardDecel, 0, 40);
    putU8s(w, m.maxReverseDecel, 0, 40);
    PvWriter sv;
    for (auto* f : {&m.front, &m.back, &m.right, &m.left, &m.bottom, &m.top})
        sv.mark(*f);
    w.u16(std::uint16_t(sv.pv));
    putString8(w, m.name);
    for (auto* f : {&m.front, &m.back, &m.right, &m.left, &m.bottom, &m.top})
        putU16s(w, *f, 0, 30);
    return out;
}
Result<PlatformSpecifications> decodePlatformSpecifications(ByteSpan p) {
    auto r = open(p, msg::ReportPlatformSpecifications);
    if (!r)
        return makeError(r.error());
    PlatformSpecifications m;
    m.steeringType = r->u8();
    if (m.steeringType == 0) {
        const std::uint32_t pv = r->u8();
        getU16s(*r, pv, 0, m.trackSeparation, 0, 30);
        getU16s(*r, pv, 1, m.driveWheelRadius, 0, 10);
    } else if (m.steeringType == 1) {
        const std::uint32_t pv = r->u8();
        getU16s(*r, pv, 0, m.steeringAngleRange, -kPi / 2, kPi / 2);
        getU16s(*r, pv, 1, m.minTurnRadius, 0, 25);
        getU16s(*r, pv, 2, m.wheelSeparation, 0, 30);
        getU16s(*r, pv, 3, m.ackDriveWheelRadius, 0, 10);
    } else {
        return makeError("value: ReportPlatformSpecifications variant " + std::to_string(m.steeringType));
    }
    const std::uint32_t iv = r->u8();
    getU16s(*r, iv, 0, m.maxForwardSpeed, 0, 90);
    getU16s(*r, iv, 1, m.maxReverseSpeed, 0, 90);
    getU16s(*r, iv, 2, m.maxRotationalSpeed, 0, 6.28);
    getU8s(*r, iv, 3, m.maxForwardAccel, 0, 40);
    getU8s(*r, iv, 4, m.maxReverseAccel, 0, 40);
    getU8s(*r, iv, 5, m.maxForwardDecel, 0, 40);
    getU8s(*r, iv, 6, m.maxReverseDecel, 0, 40);
    const std::uint32_t sv = r->u16();
    m.name = getString8(*r);
    std::optional<double>* dims[] = {&m.front, &m.back, &m.right, &m.left, &m.bottom, &m.top};
    for (int i = 0; i < 6; ++i)
        getU16s(*r, sv, i, *dims[i], 0, 30);
    // Remaining spec fields (centre of gravity, weight, angles) are not used by the console: skipped.
    return finish(*r, m, msg::ReportPlatformSpecifications);
}

Bytes encode(const HealthSummary& m) {
    Bytes out;
    auto w = start(out, msg::ReportHealthSummary);
    w.u8(m.severity);
    w.u8(std::uint8_t(std::min<std::size_t>(m.nodes.size(), 255)));
    for (std::size_t i = 0; i < m.nodes.size() && i < 255; ++i) {
        w.u8(m.nodes[i].first);
        w.u8(m.nodes[i].second);
    }
    return out;
}
Result<HealthSummary> decodeHealthSummary(ByteSpan p) {
    auto r = open(p, msg::ReportHealthSummary);
    if (!r)
        return makeError(r.error());
    HealthSummary m;
    m.severity = r->u8();
    auto n = r->u8();
    for (int i = 0; i < n && r->ok(); ++i) {
        auto node = r->u8();
        auto sev = r->u8();
        m.nodes.emplace_back(node, sev);
    }
    return finish(*r, m, msg::ReportHealthSummary);
}

} // namespace ocu::jaus
