#include "protocols/iso23725/FmsCore.h"

#include "protocols/common/Log.h"
#include "protocols/iso23725/LogCategory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ocu::iso23725 {

// At most this many error entries wait for the next rate-limited diagnostic; the rest are only counted.
static constexpr std::size_t kMaxPendingErrors = 20;

const char* nameFor(LinkState s) {
    switch (s) {
    case LinkState::Up:
        return "UP";
    case LinkState::Down:
        return "DOWN";
    default:
        return "UNKNOWN";
    }
}

const char* nameFor(AllStopState s) {
    switch (s) {
    case AllStopState::On:
        return "On";
    case AllStopState::Off:
        return "Off";
    default:
        return "UNKNOWN";
    }
}

namespace {
// The member an error text is about: codec errors start with the member name ("MachinePositionV1.Heading
// ...").
std::optional<std::string> memberOf(const std::string& error) {
    auto end = error.find_first_of(".: [");
    if (end == 0 || end == std::string::npos)
        return std::nullopt;
    std::string name = error.substr(0, end);
    if (name == "message" || name == "header")
        return std::nullopt;
    return name;
}
} // namespace

FmsCore::FmsCore(const IsoConfig& config, IsoLinkConfig link, IsoListener& listener, Counters& counters,
                 const Clock& clock, FmsOutbound& out)
    : m_cfg(config), m_link(std::move(link)), m_listener(listener), m_counters(counters), m_clock(clock),
      m_out(out), m_mapService(m_link.name, !m_link.mapWs.url.empty(), m_cfg.rules.mapServiceMember, listener,
                               counters, clock,
                               {[this](const Body& body) { return sendMapBody(body); },
                                [this](IsoSeverity s, const std::string& text) { event(s, text); },
                                [this](const std::string& error, bool frameRejected) {
                                    if (frameRejected)
                                        ++m_framesRejected;
                                    reportError("MapRejected", error, std::nullopt, std::nullopt);
                                }}) {}

void FmsCore::event(IsoSeverity s, const std::string& text) {
    if (s == IsoSeverity::Info)
        logInfo(kLog, text);
    else
        logWarning(kLog, text);
    m_listener.onEvent(s, text);
}

bool FmsCore::socketRefused(const char* what) {
    // The link was up but its WebSocket did not take the frame (closing under us): not sent, and said so.
    m_counters.add("cmd.refused.socket");
    setRefusal(OutcomeReason::SendFailed,
               "the WebSocket of link " + m_link.name + " did not take the frame (closing)");
    event(IsoSeverity::Warning, std::string(what) + " not sent: " + m_lastRefusal);
    return false;
}

void FmsCore::binaryFrame(std::size_t bytes) {
    peerWarning("binary_frame", "binary WebSocket frame of " + std::to_string(bytes) + " bytes from " +
                                    m_link.name + " ignored (§2: messages are text frames)");
}

void FmsCore::peerWarning(const std::string& cause, const std::string& text) {
    PeerWarning& w = m_peerWarnings[cause];
    const TimePoint now = m_clock.now();
    if (w.any && now - w.last < kPeerWarningGap) {
        ++w.suppressed;
        return;
    }
    const std::uint64_t more = w.suppressed;
    w = PeerWarning{now, 0, true};
    event(IsoSeverity::Warning,
          text +
              (more ? " (" + std::to_string(more) + " more of this kind in the last minute, counted)" : "") +
              "; at most one such warning per minute");
}

void FmsCore::setRefusal(OutcomeReason cause, std::string reason) {
    m_lastRefusalCause = cause;
    m_lastRefusal = std::move(reason);
}

bool FmsCore::refuse(const std::string& what, const std::string& reason, OutcomeReason cause) {
    m_counters.add("cmd.refused");
    setRefusal(cause, reason);
    event(IsoSeverity::Warning, what + " refused: " + reason + " (nothing sent)");
    return false;
}

bool FmsCore::upOrRefuse(const char* what) {
    if (m_state != LinkState::Up) {
        // §2.1 rule 1: commands are never queued while the link is down.
        m_counters.add("cmd.refused.link_down");
        setRefusal(OutcomeReason::LinkDown, "link " + m_link.name + " is " + nameFor(m_state));
        event(IsoSeverity::Warning, std::string(what) + " refused: link '" + m_link.name + "' is " +
                                        nameFor(m_state) + " (commands are not queued)");
        return false;
    }
    return true;
}

// One container with our header (the configured Protocol value) and one member.
std::string FmsCore::frame(const Body& body, std::optional<Guid> eq) const {
    Envelope env;
    env.header.protocol = m_cfg.rules.protocol;
    env.header.timestamp = makeTimestamp(unixMillisNow());
    env.header.equipmentId = std::move(eq);
    env.members.push_back(Member{body, nlohmann::json::object()});
    return encodeMessage(env);
}

bool FmsCore::sendBody(const Body& body, std::optional<Guid> eq, bool urgent) {
    std::string text = frame(body, std::move(eq));
    if (!(urgent ? m_out.sendMainUrgent(std::move(text)) : m_out.sendMain(std::move(text))))
        return false;
    ++m_messagesSent;
    m_counters.add("tx.messages");
    return true;
}

bool FmsCore::sendMapBody(const Body& body) {
    if (!separateMapService())
        return sendBody(body);
    if (!m_out.sendMap(frame(body, std::nullopt)))
        return false;
    m_counters.add("tx.map_service");
    return true;
}

FleetDefinitionV2 FmsCore::ownFleet() const {
    FleetDefinitionV2 f;
    f.ahsId = m_cfg.fmsId;
    for (auto& e : m_cfg.fleet)
        if (!e.autonomous)
            f.equipment.push_back(e);
    return f;
}

IsoMachineSnapshot& FmsCore::machine(const Guid& id) {
    auto it = m_machines.find(id);
    if (it != m_machines.end())
        return it->second;
    auto& m = m_machines[id];
    m.link = m_link.name;
    m.equipmentId = id;
    return m;
}

std::string FmsCore::label(const IsoMachineSnapshot& m) {
    return m.hid.empty() ? m.equipmentId : m.hid;
}

// ---------------------------------------------------------------- main channel

void FmsCore::opened(const std::string& peer) {
    m_tapPeer = peer;
    m_state = LinkState::Up;
    m_gotFirstMessage = false;
    m_mapService.linkOpened();
    m_listener.onLinkState(m_link.name, LinkState::Up, "connected to " + peer);
    event(IsoSeverity::Info, "link " + m_link.name + " up (" + peer + ")");
    // [ISO-seed]: FleetDefinitionV2 is the first message sent by both actors upon connection.
    sendBody(ownFleet());
    m_nextPeriodicDiagnostic = m_clock.now() + m_cfg.interfaceDiagnosticPeriod;
}

void FmsCore::text(std::string_view frame) {
    handleFrame(frame, false);
}

void FmsCore::closed(const std::string& reason) {
    m_state = LinkState::Down;
    m_ackDeadline.at.reset();
    m_statusDeadline.at.reset();
    m_nextPeriodicDiagnostic.reset();
    m_pendingErrors.clear();
    m_mapService.linkClosed();
    // §2.1 rule 5 / §7.7: all-stop and machine state are UNKNOWN while disconnected.
    m_allStop.state = AllStopState::Unknown;
    m_allStop.activeId.reset();
    m_allStop.external = false;
    m_listener.onAllStopChanged(m_link.name, m_allStop);
    for (auto& [id, m] : m_machines) {
        m.stateKnown = false;
        m_listener.onMachineChanged(m);
    }
    m_positionBatch.clear(); // those snapshots just went out whole
    m_positionQueued.clear();
    // Reported last, so a listener that sees DOWN already sees UNKNOWN all-stop and machine state.
    m_listener.onLinkState(m_link.name, LinkState::Down, reason);
    event(IsoSeverity::Warning, "link " + m_link.name + " down: " + reason);
}

void FmsCore::connectFailed(const std::string& reason, std::chrono::milliseconds retryIn) {
    m_counters.add("link.connect_failed");
    if (m_state != LinkState::Down) {
        m_state = LinkState::Down;
        m_listener.onLinkState(m_link.name, LinkState::Down, reason);
    }
    logInfo(kLog,
            "link " + m_link.name + ": " + reason + "; retry in " + std::to_string(retryIn.count()) + " ms");
}

// ---------------------------------------------------------------- map service channel (Q10)

void FmsCore::mapOpened(const std::string& peer) {
    m_mapService.channelOpened(peer);
}

void FmsCore::mapText(std::string_view frame) {
    handleFrame(frame, true);
}

void FmsCore::mapClosed(const std::string& reason) {
    m_mapService.channelClosed(reason);
}

// ---------------------------------------------------------------- incoming frames

void FmsCore::handleFrame(std::string_view frame, bool mapChannel) {
    m_counters.add(mapChannel ? "rx.map_service.frames" : "rx.frames");
    ++m_framesReceived;
    if (m_tap && m_tap->wantsRaw())
        m_tap->onRaw({"iso23725", m_link.name, m_tapPeer, mapChannel ? "map" : "main", tapBytes(frame)});
    const std::string& from = mapChannel ? "map service of " + m_link.name : m_link.name;
    std::size_t i = frame.find_first_not_of(" \t\r\n");
    if (i != std::string_view::npos && frame[i] == '<') {
        if (m_tap)
            m_tap->onDecoded({"iso23725", m_link.name, m_tapPeer, "MapDocument", tapBytes(frame)});
        m_mapService.chunk(frame, mapChannel); // raw XML: a map document (§8)
        return;
    }
    auto env = decodeMessage(frame, m_cfg.rules);
    if (!env) {
        const bool json = env.error() == "message: invalid JSON";
        m_counters.add(json ? "rx.rejected.invalid_json" : "rx.rejected.header");
        ++m_framesRejected;
        event(IsoSeverity::Warning, "message from " + from + " rejected: " + env.error());
        reportError(json ? "InvalidJson" : "InvalidHeader", env.error(), std::nullopt, std::nullopt);
        return;
    }
    if (!env->errors.empty())
        ++m_framesRejected;
    if (m_tap && !env->members.empty()) {
        // The frame as received is what decodeMessage decodes again; its members name the type.
        std::string type(memberName(env->members.front().body));
        for (std::size_t k = 1; k < env->members.size(); ++k)
            type.append("+").append(memberName(env->members[k].body));
        m_tap->onDecoded({"iso23725", m_link.name, m_tapPeer, type, tapBytes(frame)});
    }
    for (auto& e : env->errors) {
        m_counters.add("rx.rejected.invalid_member");
        event(IsoSeverity::Warning, "message from " + from + " rejected: " + e);
        reportError("InvalidMember", e, memberOf(e), env->header.timestamp);
    }
    for (auto& w : env->warnings) {
        m_counters.add("rx.tolerated");
        logWarning(kLog, from + ": " + w);
        const bool unknown = w.rfind("unknown member", 0) == 0;
        peerWarning(unknown ? "unknown_member" : "tolerated",
                    "message from " + from + ": " + w +
                        (unknown ? " (not in ISO 23725; kept, not acted on)" : ""));
    }
    if (env->outOfStandard) {
        m_counters.add("rx.out_of_standard");
        peerWarning("out_of_standard",
                    "message from " + from +
                        " names a protocol other than ISO23725 (out of the standard; decoded "
                        "as far as its members are known)");
    }
    if (!mapChannel && !m_gotFirstMessage && !env->members.empty()) {
        m_gotFirstMessage = true;
        if (!env->find<FleetDefinitionV2>()) {
            m_counters.add("rx.first_not_fleet_definition");
            event(IsoSeverity::Warning, "first message from " + m_link.name + " was " +
                                            std::string(memberName(env->members.front().body)) +
                                            ", not FleetDefinitionV2");
        }
    }
    handle(*env, mapChannel);
}

void FmsCore::handle(const Envelope& env, bool mapChannel) {
    const auto& eq = env.header.equipmentId;
    const std::int64_t hdrMs = env.header.timestamp.unixMs.value_or(unixMillisNow());
    for (auto& mem : env.members) {
        const bool mapMember =
            std::holds_alternative<MapServiceV1>(mem.body) || std::holds_alternative<MapSummaryV1>(mem.body);
        if (mapChannel && !mapMember && !std::holds_alternative<InterfaceDiagnosticV1>(mem.body) &&
            !std::holds_alternative<UnknownMember>(mem.body)) {
            m_counters.add("rx.rejected.wrong_channel");
            event(IsoSeverity::Warning, std::string(memberName(mem.body)) + " on the map service socket of " +
                                            m_link.name + " ignored");
            continue;
        }
        std::visit(
            [&](auto&& b) {
                using T = std::decay_t<decltype(b)>;
                if constexpr (std::is_same_v<T, FleetDefinitionV2>) {
                    onFleet(b);
                } else if constexpr (std::is_same_v<T, MachineAllStopV1>) {
                    setAllStop(b);
                } else if constexpr (std::is_same_v<T, MachineAllStopResponseV1>) {
                    onAllStopResponse(b);
                } else if constexpr (std::is_same_v<T, MapServiceV1>) {
                    m_mapService.service(b, mapChannel);
                } else if constexpr (std::is_same_v<T, MapSummaryV1>) {
                    m_mapService.summary(b, mapChannel);
                } else if constexpr (std::is_same_v<T, MapConnectivityV1>) {
                    m_mapService.connectivity(b);
                    m_routes = RouteGraph(b);
                    m_listener.onConnectivity(m_link.name, b);
                } else if constexpr (std::is_same_v<T, InterfaceDiagnosticV1>) {
                    for (auto& m : b.message)
                        event(m.severity == "Error"     ? IsoSeverity::Error
                              : m.severity == "Warning" ? IsoSeverity::Warning
                                                        : IsoSeverity::Info,
                              "interface diagnostic from " + m_link.name + ": " + m.code +
                                  (m.detail ? " - " + *m.detail : std::string()));
                    m_counters.add("rx.interface_diagnostic");
                } else if constexpr (std::is_same_v<T, UnknownMember>) {
                    m_counters.add("rx.unknown_member");
                } else if constexpr (std::is_same_v<T, MachineAllStopRequestV1> ||
                                     std::is_same_v<T, MapCommandV1> ||
                                     std::is_same_v<T, HaulTruckAssignmentRequestV2> ||
                                     std::is_same_v<T, HaulTruckAssignmentResetV1>) {
                    m_counters.add("rx.rejected.wrong_direction");
                    const std::string name(memberName(Body(b)));
                    event(IsoSeverity::Warning,
                          name + " from " + m_link.name + " ignored: only the FMS sends it");
                    reportError("WrongDirection", name + " is sent by the FMS only", name,
                                env.header.timestamp);
                } else {
                    if (!eq)
                        return; // checked by the codec for per-machine members
                    if (!m_machines.count(*eq)) {
                        std::size_t outside = 0;
                        for (const auto& [id, known] : m_machines)
                            outside += known.inAhsFleet ? 0 : 1;
                        if (outside >= kMaxMachinesOutsideFleet) {
                            m_counters.add("rx.rejected.machine_cap");
                            peerWarning("machine_cap",
                                        std::string(memberName(Body(b))) + " from " + m_link.name +
                                            " for machine " + *eq + " ignored: already " +
                                            std::to_string(kMaxMachinesOutsideFleet) +
                                            " machines not in its fleet definition (counted in "
                                            "rx.rejected.machine_cap)");
                            return;
                        }
                    }
                    auto& m = machine(*eq);
                    if (!m.inAhsFleet && !m.stateKnown) {
                        m_counters.add("rx.unknown_machine");
                        event(IsoSeverity::Warning, std::string(memberName(Body(b))) + " from " +
                                                        m_link.name + " for machine " + *eq +
                                                        " not in its fleet definition");
                    }
                    if constexpr (std::is_same_v<T, MachinePositionV1>) {
                        // The hot member (every machine, 1-10 Hz): a machine whose state is known only moves,
                        // and its new position waits for the next batch (flushPositions).
                        const bool moved = applyPosition(m, b);
                        if (m.stateKnown) {
                            if (moved)
                                queuePosition(m);
                            return;
                        }
                    } else {
                        machineMember(m, mem.body, hdrMs);
                    }
                    m.stateKnown = true;
                    if constexpr (std::is_same_v<T, HaulTruckProductionStateV2> ||
                                  std::is_same_v<T, HaulTruckPayloadV1> ||
                                  std::is_same_v<T, HaulTruckDumpV1> ||
                                  std::is_same_v<T, HaulTruckProductionCycleV1>)
                        m_listener.onProductionReport(m, mem.body, hdrMs);
                    m_listener.onMachineChanged(m);
                }
            },
            mem.body);
    }
}

// ---------------------------------------------------------------- interface diagnostic (§5 #15 [I])

void FmsCore::reportError(const std::string& code, const std::string& detail,
                          std::optional<std::string> refMember, std::optional<Timestamp> refTimestamp) {
    if (m_state != LinkState::Up)
        return;
    if (m_pendingErrors.size() >= kMaxPendingErrors) {
        ++m_errorsDropped; // reported as a measurement in the next diagnostic
        return;
    }
    constexpr std::size_t kMaxDetail = 200; // the offending text may be megabytes; the AHS needs the gist
    m_pendingErrors.push_back(
        DiagMessage{"Error", code, detail.substr(0, kMaxDetail), std::move(refMember),
                    refTimestamp && refTimestamp->unixMs ? refTimestamp : std::nullopt});
    const auto now = m_clock.now();
    if (!m_lastErrorDiagnostic || now - *m_lastErrorDiagnostic >= m_cfg.errorDiagnosticInterval)
        flushErrorDiagnostics();
}

void FmsCore::flushErrorDiagnostics() {
    if (m_pendingErrors.empty())
        return;
    InterfaceDiagnosticV1 d;
    d.message = std::move(m_pendingErrors);
    m_pendingErrors.clear();
    if (m_errorsDropped)
        d.measurement.push_back(
            DiagMeasurement{"ErrorsNotDetailed", static_cast<double>(m_errorsDropped), "count"});
    m_errorsDropped = 0;
    m_lastErrorDiagnostic = m_clock.now();
    if (sendBody(d))
        m_counters.add("tx.interface_diagnostic.error");
}

void FmsCore::sendPeriodicDiagnostic() {
    InterfaceDiagnosticV1 d;
    d.measurement = {
        {"MessagesReceived", static_cast<double>(m_framesReceived), "count"},
        {"MessagesSent", static_cast<double>(m_messagesSent), "count"},
        {"MessagesRejected", static_cast<double>(m_framesRejected), "count"},
        {"MachinesKnown", static_cast<double>(m_machines.size()), "count"},
    };
    if (sendBody(d))
        m_counters.add("tx.interface_diagnostic.periodic");
}

// ---------------------------------------------------------------- timers

void FmsCore::poll() {
    const auto now = m_clock.now();
    for (Deadline* d : {&m_ackDeadline, &m_statusDeadline}) {
        if (d->at && now >= *d->at) {
            d->at.reset();
            m_counters.add("allstop.timeout");
            event(IsoSeverity::Error, d->alarm + " on " + m_link.name);
        }
    }
    m_mapService.poll();
    if (m_state != LinkState::Up)
        return;
    if (!m_pendingErrors.empty() && m_lastErrorDiagnostic &&
        now - *m_lastErrorDiagnostic >= m_cfg.errorDiagnosticInterval)
        flushErrorDiagnostics();
    if (m_nextPeriodicDiagnostic && now >= *m_nextPeriodicDiagnostic) {
        sendPeriodicDiagnostic();
        // Keeps its cadence from the connection time; a late poll does not send a burst.
        while (*m_nextPeriodicDiagnostic <= now)
            *m_nextPeriodicDiagnostic += m_cfg.interfaceDiagnosticPeriod;
    }
}

} // namespace ocu::iso23725
