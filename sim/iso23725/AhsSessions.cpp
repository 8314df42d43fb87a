#include "sim/iso23725/AhsSessions.h"

#include "protocols/common/Log.h"

#include <cctype>

namespace ocu::sim {

using namespace ocu::iso23725;

namespace {

constexpr const char* kLog = "ocu.sim.iso";

// The member name a codec error message starts with ("MachineAutonomyModeV1.AutonomyMode: ..."), if any.
std::optional<std::string> memberOfError(const std::string& error) {
    std::size_t n = 0;
    while (n < error.size() && std::isalnum(static_cast<unsigned char>(error[n])))
        ++n;
    if (n == 0 || error.compare(0, n, "message") == 0 || error.compare(0, n, "header") == 0)
        return std::nullopt;
    return error.substr(0, n);
}

// Members only the AHS (or its map service) sends (§5 "Dir"): the FMS sending one is an interface error.
bool onlyAhsSends(const Body& b) {
    return std::visit(
        [](auto&& m) {
            using T = std::decay_t<decltype(m)>;
            return !(std::is_same_v<T, FleetDefinitionV2> || std::is_same_v<T, MachineAllStopRequestV1> ||
                     std::is_same_v<T, MachinePositionV1> || std::is_same_v<T, MapCommandV1> ||
                     std::is_same_v<T, InterfaceDiagnosticV1> ||
                     std::is_same_v<T, HaulTruckAssignmentRequestV2> ||
                     std::is_same_v<T, HaulTruckAssignmentResetV1> || std::is_same_v<T, UnknownMember>);
        },
        b);
}

std::string encode(const Body& b, std::optional<Guid> eq) {
    Envelope env;
    env.header.timestamp = makeTimestamp(unixMillisNow());
    env.header.equipmentId = std::move(eq);
    env.members.push_back(Member{b, nlohmann::json::object()});
    return encodeMessage(env);
}

std::string wsUrl(const SimulatedAhsConfig& c, std::uint16_t port, const std::string& path) {
    return std::string(c.tls ? "wss://" : "ws://") + c.bindAddress + ":" + std::to_string(port) + path;
}

} // namespace

AhsSessions::AhsSessions(boost::asio::io_context& io, const SimulatedAhsConfig& config, PitMap& map,
                         HaulFleet& fleet, Counters& counters)
    : m_io(io), m_cfg(config), m_map(map), m_fleet(fleet), m_counters(counters) {}

AhsSessions::~AhsSessions() = default;

Result<bool> AhsSessions::start() {
    WsOptions o;
    o.pingInterval = m_cfg.pingInterval;
    o.deadAfter = m_cfg.deadAfter;
    o.backoffMin = std::chrono::milliseconds(200);
    o.backoffMax = std::chrono::milliseconds(2000);
    if (!m_cfg.connectUrl.empty()) {
        o.role = WsRole::Client;
        o.url = m_cfg.connectUrl;
        o.tls.caFile = m_cfg.caFile;
        o.tls.certFile = m_cfg.certFile;
        o.tls.keyFile = m_cfg.keyFile;
    } else {
        o.role = WsRole::Service;
        o.url = wsUrl(m_cfg, m_cfg.port, m_cfg.path);
        o.tls.certFile = m_cfg.certFile;
        o.tls.keyFile = m_cfg.keyFile;
        o.tls.caFile = m_cfg.clientCaFile;
    }
    // Q10: the map service as its own WebSocket service, with the main service's TLS settings.
    WsOptions mo = o;
    mo.role = WsRole::Service;
    mo.url = wsUrl(m_cfg, m_cfg.mapPort, m_cfg.mapPath);
    mo.tls = WsTlsOptions{};
    mo.tls.certFile = m_cfg.certFile;
    mo.tls.keyFile = m_cfg.keyFile;
    mo.tls.caFile = m_cfg.clientCaFile;

    m_main = std::make_unique<WsEndpoint>(m_io, o, *this, m_counters);
    auto s = m_main->start();
    if (s && m_cfg.separateMapService) {
        m_mapService = std::make_unique<WsEndpoint>(m_io, mo, m_mapSide, m_counters);
        s = m_mapService->start();
        if (!s) {
            s = makeError("map service: " + s.error());
            m_main->stop();
        }
    }
    return s;
}

void AhsSessions::stop() {
    if (m_main)
        m_main->stop();
    if (m_mapService)
        m_mapService->stop();
    m_sessions.clear(); // with their diagnostic timers
    m_mapSessions.clear();
}

void AhsSessions::release() {
    m_mapService.reset();
    m_main.reset();
}

std::uint16_t AhsSessions::port() const {
    return m_main ? m_main->localPort() : m_cfg.port;
}

std::uint16_t AhsSessions::mapPort() const {
    return m_mapService ? m_mapService->localPort() : m_cfg.mapPort;
}

std::string AhsSessions::mapUrl() const {
    return wsUrl(m_cfg, mapPort(), m_cfg.mapPath);
}

std::size_t AhsSessions::queuedBytes() const {
    return m_main ? m_main->queuedBytes() : 0;
}

// ---------------------------------------------------------------- sending

// Every frame to an FMS goes through here so the session's sent count stays right.
void AhsSessions::sendText(Sock k, SessionId s, std::string text, bool binary) {
    auto& t = table(k);
    auto it = t.find(s);
    auto& e = k == Sock::Main ? m_main : m_mapService;
    if (it == t.end() || !e)
        return;
    if (binary ? e->sendBinary(s, std::move(text)) : e->send(s, std::move(text)))
        ++it->second.sent;
}

void AhsSessions::sendTo(SessionId s, const Body& b, std::optional<Guid> eq) {
    sendText(Sock::Main, s, encode(b, std::move(eq)));
}

void AhsSessions::sendOn(Sock k, SessionId s, const Body& b) {
    sendText(k, s, encode(b, std::nullopt));
}

void AhsSessions::broadcast(const Body& b, std::optional<Guid> eq) {
    std::string text = encode(b, std::move(eq));
    for (auto& [s, st] : m_sessions)
        sendText(Sock::Main, s, text);
}

void AhsSessions::broadcastRaw(const std::string& data, bool binary) {
    for (auto& [s, st] : m_sessions)
        sendText(Sock::Main, s, data, binary);
}

// At the configured rate (§7.4: 1-10 Hz).
void AhsSessions::sendPositions() {
    if (m_sessions.empty())
        return;
    for (auto& t : m_fleet.trucks()) {
        broadcast(m_fleet.position(t), t.id);
        ++m_positionsSent;
    }
}

void AhsSessions::announceMapChange() {
    if (!m_cfg.separateMapService) {
        broadcast(m_map.summary(m_cfg.mapChunkElements));
        return;
    }
    for (auto& [s, st] : m_mapSessions)
        sendOn(Sock::Map, s, m_map.summary(m_cfg.mapChunkElements));
}

void AhsSessions::snapshotTo(SessionId s) {
    // [ISO-seed] FleetDefinitionV2 first, then the "At Connection" snapshot (research note §10).
    sendTo(s, FleetDefinitionV2{m_cfg.ahsId, m_fleet.equipment()});
    sendTo(s, MachineAllStopV1{m_fleet.allStopOn() ? "On" : "Off", m_allStopId});
    for (auto& t : m_fleet.trucks()) {
        Envelope env;
        env.header.timestamp = makeTimestamp(unixMillisNow());
        env.header.equipmentId = t.id;
        env.members.push_back(
            Member{MachineAutonomyModeV1{m_fleet.autonomyMode(t)}, nlohmann::json::object()});
        env.members.push_back(Member{m_fleet.position(t), nlohmann::json::object()}); // piggy-backed (§3)
        sendText(Sock::Main, s, encodeMessage(env));
        sendTo(s, MachineDispatchAvailabilityV1{t.custodian, std::nullopt, std::nullopt}, t.id);
        sendTo(s, MachineDiagnosticV2{t.faults}, t.id);
        sendTo(s, m_fleet.productionState(t), t.id);
        sendTo(s, t.sensorSent, t.id); // §5 row 18 [I]: current sensor inputs next to the state
    }
    sendTo(s, m_fleet.connectivity()); // §9 connectivity is not part of the map service: always here
    if (!m_cfg.separateMapService) {
        sendTo(s, MapServiceV1{1});
        sendTo(s, m_map.summary(m_cfg.mapChunkElements));
    }
}

// ---------------------------------------------------------------- sessions

void AhsSessions::onOpen(SessionId id, const std::string& peer) {
    m_sessions[id];
    logInfo(kLog, "FMS connected from " + peer);
    snapshotTo(id);
    scheduleDiagnostic(id);
}

void AhsSessions::onClose(SessionId id, const std::string& reason) {
    m_sessions.erase(id); // destroys its diagnostic timer: the pending wait ends with operation_aborted
    logInfo(kLog, "FMS disconnected: " + reason);
}

void AhsSessions::onText(SessionId id, std::string text) {
    onFrame(Sock::Main, id, text);
}

// The separate map service (Q10) is a service-identification protocol: the service speaks first
// (MapServiceV1, then the At-Connection MapSummaryV1; §2 "Connection start", §10.6.1) and expects no
// FleetDefinitionV2 from the client.
void AhsSessions::onMapOpen(SessionId id, const std::string& peer) {
    m_mapSessions[id];
    logInfo(kLog, "map service client connected from " + peer);
    sendOn(Sock::Map, id, MapServiceV1{1});
    sendOn(Sock::Map, id, m_map.summary(m_cfg.mapChunkElements));
    m_counters.add("sim.map.sessions");
}

void AhsSessions::onMapClose(SessionId id, const std::string& reason) {
    m_mapSessions.erase(id);
    logInfo(kLog, "map service client disconnected: " + reason);
}

// §5 row 15 [I]: periodic InterfaceDiagnosticV1 with the session's frame counts (main socket only: the map
// service has its own, identification-first protocol). Period 0 turns it off.
void AhsSessions::scheduleDiagnostic(SessionId id) {
    auto it = m_sessions.find(id);
    if (it == m_sessions.end() || m_cfg.interfaceDiagnosticPeriod.count() <= 0)
        return;
    auto& tm = it->second.diagTimer;
    if (!tm)
        tm = std::make_unique<boost::asio::steady_timer>(m_io);
    tm->expires_after(m_cfg.interfaceDiagnosticPeriod);
    tm->async_wait([this, id](boost::system::error_code ec) {
        if (ec)
            return;
        auto it = m_sessions.find(id);
        if (it == m_sessions.end())
            return;
        const auto& st = it->second;
        InterfaceDiagnosticV1 d;
        d.measurement.push_back(
            DiagMeasurement{"MessagesReceived", static_cast<double>(st.received), "count"});
        d.measurement.push_back(DiagMeasurement{"MessagesSent", static_cast<double>(st.sent), "count"});
        d.measurement.push_back(
            DiagMeasurement{"MessagesRejected", static_cast<double>(st.rejected), "count"});
        m_counters.add("sim.tx.interface_diagnostic");
        sendOn(Sock::Main, id, d);
        scheduleDiagnostic(id);
    });
}

// ---------------------------------------------------------------- requests from the FMS

// One text frame from an FMS on either socket. Rejections (invalid JSON or header, a member failing
// validation, a member only the AHS sends) are answered with one InterfaceDiagnosticV1 of Error messages
// (§5 row 15 [I]: "on error"), RefMember/RefTimestamp where known.
void AhsSessions::onFrame(Sock k, SessionId id, const std::string& text) {
    auto& tab = table(k);
    auto sit = tab.find(id);
    if (sit == tab.end())
        return;
    auto& st = sit->second;
    ++m_framesReceived;
    ++st.received;
    std::vector<DiagMessage> errors;
    auto reject = [&](const char* code, const char* counter, std::string detail,
                      std::optional<std::string> member, std::optional<Timestamp> ts) {
        m_counters.add("sim.rx.rejected");
        m_counters.add(std::string("sim.rx.rejected.") + counter);
        logWarning(kLog, "message from FMS rejected: " + detail);
        errors.push_back(DiagMessage{"Error", code, std::move(detail), std::move(member), std::move(ts)});
    };
    auto env = decodeMessage(text);
    if (!env) {
        // Nothing of the frame is used; its Timestamp is quoted when the JSON at least parses.
        auto doc = nlohmann::json::parse(text, nullptr, false);
        std::optional<Timestamp> ts;
        if (doc.is_object())
            if (auto t = doc.find("Timestamp"); t != doc.end() && t->is_string())
                ts = Timestamp{t->get<std::string>(), parseTimestamp(t->get<std::string>(), true)};
        if (doc.is_discarded())
            reject("InvalidJson", "invalid_json", env.error(), std::nullopt, std::nullopt);
        else
            reject("InvalidHeader", "invalid_header", env.error(), std::nullopt, ts);
    } else {
        const Timestamp& ts = env->header.timestamp;
        for (auto& e : env->errors)
            reject("InvalidMember", "invalid_member", e, memberOfError(e), ts);
        if (k == Sock::Main && !st.gotFirst && !env->members.empty()) {
            st.gotFirst = true;
            m_fmsFirst.push_back(std::string(memberName(env->members.front().body)));
            // Said per session so a run over a faulty network can check every reconnect began with it.
            logInfo(kLog, "FMS session's first message: " + m_fmsFirst.back());
        }
        for (auto& m : env->members) {
            if (onlyAhsSends(m.body)) {
                std::string name(memberName(m.body));
                reject("WrongDirection", "wrong_direction", name + " is sent by the AHS, not by the FMS",
                       name, ts);
                continue;
            }
            if (std::get_if<UnknownMember>(&m.body))
                m_counters.add("sim.rx.unknown_member"); // tolerated, never an error (§4.2)
            else if (std::get_if<InterfaceDiagnosticV1>(&m.body))
                m_counters.add("sim.rx.interface_diagnostic");
            else if (k == Sock::Map)
                onMapServiceMember(id, m.body, ts);
            else
                onMember(id, *env, m.body, ts);
        }
    }
    if (errors.empty())
        return;
    st.rejected += errors.size();
    InterfaceDiagnosticV1 d;
    d.message = std::move(errors);
    m_counters.add("sim.tx.interface_diagnostic.error"); // counted before it can be seen
    sendOn(k, id, d);
}

void AhsSessions::onMember(SessionId id, const Envelope& env, const Body& b, const Timestamp& ts) {
    if (auto* r = std::get_if<MachineAllStopRequestV1>(&b))
        onAllStop(*r);
    else if (auto* c = std::get_if<MapCommandV1>(&b))
        onMapCommand(Sock::Main, id, *c, ts);
    else if (auto* a = std::get_if<HaulTruckAssignmentRequestV2>(&b))
        m_fleet.assign(env.header.equipmentId.value_or(""), *a);
    else if (std::get_if<HaulTruckAssignmentResetV1>(&b))
        m_fleet.resetAssignments(env.header.equipmentId.value_or(""));
    else if (std::get_if<MachinePositionV1>(&b))
        m_counters.add("sim.rx.fms_positions");
    else if (std::get_if<FleetDefinitionV2>(&b))
        m_counters.add("sim.rx.fms_fleet");
}

// On the separate map service only MapCommandV1 means something; a FleetDefinitionV2 is not expected but
// harmless, anything else belongs on the main socket and is not acted on here.
void AhsSessions::onMapServiceMember(SessionId id, const Body& b, const Timestamp& ts) {
    if (auto* c = std::get_if<MapCommandV1>(&b)) {
        onMapCommand(Sock::Map, id, *c, ts);
    } else if (std::get_if<FleetDefinitionV2>(&b)) {
        m_counters.add("sim.map.rx.fleet");
    } else {
        std::string name(memberName(b));
        InterfaceDiagnosticV1 d;
        d.message.push_back(DiagMessage{"Warning", "NotMapService",
                                        name + " ignored: the map service only serves MapCommandV1", name,
                                        ts});
        m_counters.add("sim.map.rx.ignored");
        sendOn(Sock::Map, id, d);
    }
}

// All-stop (§7.6, §7.7): one active stop at a time, removed only with the id that applied it.
void AhsSessions::onAllStop(const MachineAllStopRequestV1& r) {
    const bool on = m_fleet.allStopOn();
    if (r.modeAllStop == "Apply") {
        if (on && m_allStopId != r.modeAllStopId) {
            broadcast(MachineAllStopResponseV1{"Rejected", r.modeAllStopId,
                                               std::string("an all-stop is already active with id ") +
                                                   *m_allStopId});
            return;
        }
        broadcast(MachineAllStopResponseV1{"Accepted", r.modeAllStopId,
                                           "Stop commanded to " + std::to_string(m_fleet.trucks().size()) +
                                               " machines"});
        m_allStopId = r.modeAllStopId;
    } else {
        if (!on || m_allStopId != r.modeAllStopId) {
            broadcast(
                MachineAllStopResponseV1{"Rejected", r.modeAllStopId, std::string("unknown ModeAllStopId")});
            return;
        }
        broadcast(MachineAllStopResponseV1{"Accepted", r.modeAllStopId, std::nullopt});
    }
    const bool apply = r.modeAllStop == "Apply";
    broadcast(MachineAllStopV1{apply ? "On" : "Off", m_allStopId});
    m_fleet.setAllStop(apply); // the trucks' new autonomy modes follow the status
    m_counters.add(apply ? "sim.allstop.on" : "sim.allstop.off");
}

void AhsSessions::onMapCommand(Sock k, SessionId s, const MapCommandV1& c, const Timestamp& ts) {
    if (k == Sock::Main && m_cfg.separateMapService) {
        // Q10: the map is served elsewhere; say where instead of silently ignoring the request.
        InterfaceDiagnosticV1 d;
        d.message.push_back(DiagMessage{"Warning", "MapServiceElsewhere",
                                        "the map service is a separate WebSocket service at " + mapUrl(),
                                        std::string("MapCommandV1"), ts});
        m_counters.add("sim.map.elsewhere");
        sendOn(k, s, d);
    } else if (c.scope == "/summary") {
        sendOn(k, s, m_map.summary(m_cfg.mapChunkElements));
    } else if (c.scope == "/") {
        auto chunks = m_map.osmChunks(m_cfg.mapChunkElements);
        sendOn(k, s, m_map.summary(m_cfg.mapChunkElements));
        for (auto& ch : chunks)
            sendText(k, s, ch); // raw XML, not wrapped in JSON (§8)
        m_counters.add("sim.map.sent");
    } else {
        InterfaceDiagnosticV1 d;
        d.message.push_back(DiagMessage{"Warning", "UnknownScope",
                                        "MapCommandV1 scope '" + c.scope + "' unknown",
                                        std::string("MapCommandV1"), std::nullopt});
        sendOn(k, s, d);
    }
}

} // namespace ocu::sim
