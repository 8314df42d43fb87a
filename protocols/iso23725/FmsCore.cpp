#include "protocols/iso23725/FmsCore.h"
#include "protocols/iso23725/FleetDiscrepancies.h"

#include "protocols/common/Log.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ocu::iso23725 {

static constexpr const char* kLog = "ocu.iso";
// At most this many error entries wait for the next rate-limited diagnostic; the rest are only counted.
static constexpr std::size_t kMaxPendingErrors = 20;

const char* toString(LinkState s) {
    switch (s) {
    case LinkState::Up:
        return "UP";
    case LinkState::Down:
        return "DOWN";
    default:
        return "UNKNOWN";
    }
}

const char* toString(AllStopState s) {
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
    m_lastRefusal = "the WebSocket of link " + m_link.name + " did not take the frame (closing)";
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

bool FmsCore::refuse(const std::string& what, const std::string& reason) {
    m_counters.add("cmd.refused");
    m_lastRefusal = reason;
    event(IsoSeverity::Warning, what + " refused: " + reason + " (nothing sent)");
    return false;
}

bool FmsCore::upOrRefuse(const char* what) {
    if (m_state != LinkState::Up) {
        // §2.1 rule 1: commands are never queued while the link is down.
        m_counters.add("cmd.refused.link_down");
        m_lastRefusal = "link " + m_link.name + " is " + toString(m_state);
        event(IsoSeverity::Warning, std::string(what) + " refused: link '" + m_link.name + "' is " +
                                        toString(m_state) + " (commands are not queued)");
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
                        machineMember(m, b, hdrMs);
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

// ---------------------------------------------------------------- positions (§7.4)

bool FmsCore::applyPosition(IsoMachineSnapshot& m, const MachinePositionV1& b) {
    if (!b.pose.latitude || !b.pose.longitude) {
        m_counters.add("rx.position_unavailable");
        return false;
    }
    if (m.position && m.position->measuredUnixMs && b.timestamp.unixMs &&
        *b.timestamp.unixMs < *m.position->measuredUnixMs) {
        m_counters.add("rx.late_position"); // latest state wins (§2.1 rule 2)
        return false;
    }
    IsoPosition p;
    p.latitude = *b.pose.latitude;
    p.longitude = *b.pose.longitude;
    p.elevation = b.pose.elevation;
    if (b.pose.heading)
        p.heading = static_cast<double>(*b.pose.heading);
    if (b.pose.speed)
        p.speedKmh = static_cast<double>(*b.pose.speed);
    if (b.pose.latitudeAccuracy && b.pose.longitudeAccuracy)
        p.horizontalAccuracy = std::max(*b.pose.latitudeAccuracy, *b.pose.longitudeAccuracy);
    p.measuredUnixMs = b.timestamp.unixMs;
    p.receivedUnixMs = unixMillisNow();
    m.position = p;
    m_counters.add("rx.positions");
    return true;
}

void FmsCore::queuePosition(const IsoMachineSnapshot& m) {
    if (m_positionQueued.insert(&m).second)
        m_positionBatch.push_back(&m);
}

void FmsCore::dropQueuedPosition(const IsoMachineSnapshot& m) {
    if (m_positionQueued.erase(&m))
        m_positionBatch.erase(std::find(m_positionBatch.begin(), m_positionBatch.end(), &m));
}

void FmsCore::flushPositions(std::size_t maxMachines) {
    if (m_positionBatch.empty() || maxMachines == 0)
        return;
    m_counters.add("rx.position_batches");
    if (maxMachines >= m_positionBatch.size()) {
        m_listener.onMachinePositions(m_link.name, m_positionBatch);
        m_positionBatch.clear();
        m_positionQueued.clear();
        return;
    }
    // The earliest arrivals go first; a machine handed over here that moves again joins the end of the batch.
    const auto end = m_positionBatch.begin() + static_cast<std::ptrdiff_t>(maxMachines);
    const std::vector<const IsoMachineSnapshot*> step(m_positionBatch.begin(), end);
    for (const IsoMachineSnapshot* m : step)
        m_positionQueued.erase(m);
    m_positionBatch.erase(m_positionBatch.begin(), end);
    m_listener.onMachinePositions(m_link.name, step);
}

template <class T> void FmsCore::machineMember(IsoMachineSnapshot& m, const T& b, std::int64_t hdrMs) {
    if constexpr (std::is_same_v<T, MachineAutonomyModeV1>) {
        m.autonomyMode = b.autonomyMode;
    } else if constexpr (std::is_same_v<T, MachineDispatchAvailabilityV1>) {
        if (m.dispatchingCustodian == "AHS" && b.dispatchingCustodian == "FMS") {
            m.needsAssignment = true;
            m_counters.add("assignment.needed");
            event(IsoSeverity::Warning,
                  "machine " + label(m) + " needs an assignment (custodian AHS -> FMS, §8.3.4)");
        } else if (b.dispatchingCustodian != "FMS") {
            m.needsAssignment = false;
        }
        m.dispatchingCustodian = b.dispatchingCustodian;
    } else if constexpr (std::is_same_v<T, MachineDiagnosticV2>) {
        m.diagnostics = b.entries; // full list each time; [] clears (§8.4)
    } else if constexpr (std::is_same_v<T, BasicMachineHealthV2>) {
        m.health = b;
    } else if constexpr (std::is_same_v<T, HaulTruckProductionStateV2>) {
        // §2.1 rule 4: a late event never overwrites newer state.
        if (hdrMs < m.productionUnixMs) {
            m_counters.add("rx.late_event");
            event(IsoSeverity::Info, "late production state " + b.productionState + " of " + label(m) +
                                         " at " + formatTimestamp(hdrMs) + " kept in history only");
            return;
        }
        m.production = b;
        m.productionUnixMs = hdrMs;
    } else if constexpr (std::is_same_v<T, HaulTruckPayloadV1>) {
        if (hdrMs < m.payloadUnixMs) {
            m_counters.add("rx.late_event");
            event(IsoSeverity::Info,
                  "late payload of " + label(m) + " at " + formatTimestamp(hdrMs) + " kept in history only");
            return;
        }
        m.payload = b;
        m.payloadUnixMs = hdrMs;
    } else if constexpr (std::is_same_v<T, HaulTruckProductionStateSensorV1>) {
        m.sensor = b;
        m_counters.add("rx.production_sensor");
    } else if constexpr (std::is_same_v<T, HaulTruckDumpV1>) {
        m.lastDump = b;
        m.dumpUnixMs = std::max(m.dumpUnixMs, hdrMs);
        event(IsoSeverity::Info,
              "dump by " + label(m) + " at way " + std::to_string(b.wayId) +
                  (b.dumpedWeight ? ", " + std::to_string(*b.dumpedWeight) + " t" : std::string()));
    } else if constexpr (std::is_same_v<T, HaulTruckProductionCycleV1>) {
        m.lastCycle = b;
        event(IsoSeverity::Info, "cycle " + b.cycleId + " completed by " + label(m));
    } else if constexpr (std::is_same_v<T, HaulTruckAssignmentV1>) {
        m.assignment = b;
        if (b.status == "Active" || b.status == "Pending")
            m.needsAssignment = false;
    } else if constexpr (std::is_same_v<T, HaulTruckAssignmentResponseV1>) {
        onAssignmentResponse(m, b);
    }
}

// ---------------------------------------------------------------- fleet definition

void FmsCore::onFleet(const FleetDefinitionV2& f) {
    m_ahsFleet = f;
    std::set<Guid> listed;
    for (auto& e : f.equipment) {
        listed.insert(e.equipmentId);
        auto& m = machine(e.equipmentId);
        m.hid = e.hid;
        m.type = e.type;
        m.oem = e.oem;
        m.model = e.model;
        m.autonomous = e.autonomous;
        m.length = e.length;
        m.width = e.width;
        m.inAhsFleet = true;
        m_listener.onMachineChanged(m);
    }
    // No delete command exists: absence from a re-sent list removes the machine [ISO-seed].
    for (auto it = m_machines.begin(); it != m_machines.end();) {
        if (!listed.count(it->first)) {
            dropQueuedPosition(it->second);
            m_listener.onMachineRemoved(m_link.name, it->first);
            it = m_machines.erase(it);
        } else {
            ++it;
        }
    }
    checkDiscrepancies();
}

void FmsCore::checkDiscrepancies() {
    const auto items = checkFleet(*m_ahsFleet, m_cfg.fleet, m_cfg.dimensionTolerance);
    m_counters.add("fleet.discrepancies", items.size());
    // Reported once, through onFleetDiscrepancies only: an onEvent per item as well made every discrepancy
    // appear twice in the console (once as "discrepancy", once as "info") and flooded it.
    m_listener.onFleetDiscrepancies(m_link.name, items);
}

// ---------------------------------------------------------------- all-stop (§7.6, §7.7)

void FmsCore::setAllStop(const MachineAllStopV1& s) {
    auto& a = m_allStop;
    a.state = s.modeAllStop == "On" ? AllStopState::On : AllStopState::Off;
    a.activeId = s.modeAllStopId;
    a.external = a.state == AllStopState::On && s.modeAllStopId && !m_issuedIds.count(*s.modeAllStopId);
    if (a.pendingId && s.modeAllStopId == a.pendingId) {
        // The status confirms our request: Apply is confirmed by On, Remove by Off with the same id.
        m_statusDeadline.at.reset();
        if (a.state == AllStopState::Off)
            a.pendingId.reset();
    }
    if (a.external)
        event(IsoSeverity::Warning,
              "all-stop active on " + m_link.name + " (external, id " + *a.activeId + ")");
    m_listener.onAllStopChanged(m_link.name, a);
}

void FmsCore::onAllStopResponse(const MachineAllStopResponseV1& b) {
    m_ackDeadline.at.reset();
    std::string d = b.detail ? " (" + *b.detail + ")" : std::string();
    if (b.response == "Accepted") {
        event(IsoSeverity::Info, "all-stop request " + b.modeAllStopId + " accepted by " + m_link.name + d);
        // The response is not the state: only MachineAllStopV1 is (§7.7); wait for it.
        if (m_allStop.state != AllStopState::On || m_allStop.activeId != b.modeAllStopId)
            m_statusDeadline = {m_clock.now() + m_cfg.allStopStatusTimeout,
                                "all-stop accepted but status not confirmed"};
    } else {
        if (b.detail && b.detail->find("not supported") != std::string::npos) {
            m_allStop.supported = false;
            m_listener.onAllStopChanged(m_link.name, m_allStop);
        }
        event(IsoSeverity::Error, "all-stop request " + b.modeAllStopId + " rejected by " + m_link.name + d);
    }
}

bool FmsCore::allStopApply() {
    if (!upOrRefuse("all-stop Apply"))
        return false;
    Guid id = newGuid();
    if (!sendBody(MachineAllStopRequestV1{"Apply", id}, std::nullopt, true)) // ahead of queued frames
        return socketRefused("all-stop Apply");
    m_issuedIds.insert(id);
    m_allStop.pendingId = id;
    m_counters.add("allstop.apply");
    event(IsoSeverity::Info, "all-stop Apply " + id + " sent to " + m_link.name);
    m_ackDeadline = {m_clock.now() + m_cfg.allStopAckTimeout, "all-stop not acknowledged"};
    m_listener.onAllStopChanged(m_link.name, m_allStop);
    return true;
}

bool FmsCore::allStopRemove() {
    if (!upOrRefuse("all-stop Remove"))
        return false;
    // "Same ID used in apply must be used when removing" [OA-iso].
    std::optional<Guid> id = m_allStop.activeId ? m_allStop.activeId : m_allStop.pendingId;
    if (!id) {
        m_lastRefusal = "no active all-stop id on link " + m_link.name;
        event(IsoSeverity::Warning, "all-stop Remove refused on " + m_link.name + ": no active all-stop id");
        return false;
    }
    if (!sendBody(MachineAllStopRequestV1{"Remove", *id}, std::nullopt, true))
        return socketRefused("all-stop Remove");
    m_allStop.pendingId = id;
    m_counters.add("allstop.remove");
    event(IsoSeverity::Info, "all-stop Remove " + *id + " sent to " + m_link.name);
    m_ackDeadline = {m_clock.now() + m_cfg.allStopAckTimeout, "all-stop Remove not acknowledged"};
    return true;
}

// ---------------------------------------------------------------- assignments (§13.3)

bool FmsCore::requestAssignment(const Guid& equipmentId, std::vector<AssignmentItem> items) {
    if (!upOrRefuse("assignment request"))
        return false;
    auto it = m_machines.find(equipmentId);
    if (it == m_machines.end())
        return refuse("assignment request", "machine " + equipmentId + " is unknown on link " + m_link.name);
    auto& m = it->second;
    // §8.3 [I]: only a truck the AHS handed to the FMS is dispatched by the FMS.
    if (m.dispatchingCustodian != "FMS")
        return refuse("assignment request",
                      label(m) + (m.dispatchingCustodian.empty()
                                      ? " has not reported its DispatchingCustodian yet"
                                      : " is dispatched by the " + m.dispatchingCustodian +
                                            " (DispatchingCustodian " + m.dispatchingCustodian + ")"));
    if (items.empty())
        return refuse("assignment request", "no task given");
    for (auto& a : items) {
        if (std::find(enums::haulTask.begin(), enums::haulTask.end(), a.task) == enums::haulTask.end())
            return refuse("assignment request",
                          "task '" + a.task + "' is not one of Load, Offload, Fuel, Park, Wait");
        if (a.destinationEquipmentId && a.destinationSpotId)
            return refuse("assignment request",
                          "DestinationEquipmentId and DestinationSpotId are mutually exclusive (§5 #21)");
        if (a.destinationEquipmentId && !isGuid(*a.destinationEquipmentId))
            return refuse("assignment request",
                          "DestinationEquipmentId '" + *a.destinationEquipmentId + "' is not a GUID");
        if (!a.assignmentId.empty() && !isGuid(a.assignmentId))
            return refuse("assignment request", "AssignmentId '" + a.assignmentId + "' is not a GUID");
    }
    if (std::string why = routeAssignment(m, items); !why.empty())
        return refuse("assignment request", why);
    for (auto& a : items) {
        if (a.assignmentId.empty())
            a.assignmentId = newGuid();
        if (a.route && !m_cfg.rules.emitNegativeWayIds)
            for (auto& w : *a.route)
                w.wayId = std::abs(w.wayId); // Q6: negative ids not emitted unless enabled
    }
    if (!sendBody(HaulTruckAssignmentRequestV2{items}, equipmentId))
        return socketRefused("assignment request");
    m.requestedAssignments = items;
    m.assignmentResponses.clear();
    m_counters.add("assignment.request");
    std::string what;
    for (auto& a : items)
        what += (what.empty() ? "" : ", ") + a.task + " at way " + std::to_string(a.destinationId);
    event(IsoSeverity::Info, "assignment request sent to " + label(m) + ": " + what);
    m_listener.onMachineChanged(m);
    return true;
}

std::string FmsCore::routeAssignment(const IsoMachineSnapshot& m, std::vector<AssignmentItem>& items) const {
    if (m_routes.empty())
        return {}; // no MapConnectivityV1 yet: the AHS alone judges reachability
    std::optional<std::int64_t> from;
    if (m.production && m.production->wayId && m_routes.contains(*m.production->wayId))
        from = m.production->wayId;
    for (auto& a : items) {
        if (!m_routes.contains(a.destinationId))
            return "destination way " + std::to_string(a.destinationId) +
                   " is not in the AHS's MapConnectivityV1";
        if (from) {
            if (a.route) {
                if (std::string why = checkRoute(m_routes, *from, *a.route, a.destinationId); !why.empty())
                    return "task " + a.task + " to way " + std::to_string(a.destinationId) + ": " + why;
            } else {
                RouteResult r = shortestRoute(m_routes, *from, a.destinationId);
                if (!r.ok)
                    return "task " + a.task + ": destination " + r.error;
                // RouteV1 is optional (row 21): a destination next to the truck's way has no way in between,
                // and an empty list would only say that; it is left out then.
                if (std::vector<WayRef> v = r.routeV1(); m_cfg.rules.sendRoutes && !v.empty())
                    a.route = std::move(v);
            }
        }
        from = a.destinationId; // a future task starts where the previous one ends
    }
    return {};
}

bool FmsCore::resetAssignment(const Guid& equipmentId) {
    if (!upOrRefuse("assignment reset"))
        return false;
    auto it = m_machines.find(equipmentId);
    if (it == m_machines.end())
        return refuse("assignment reset", "machine " + equipmentId + " is unknown on link " + m_link.name);
    if (!sendBody(HaulTruckAssignmentResetV1{newGuid()}, equipmentId))
        return socketRefused("assignment reset");
    m_counters.add("assignment.reset");
    event(IsoSeverity::Info, "assignment reset sent to " + label(it->second));
    return true;
}

void FmsCore::onAssignmentResponse(IsoMachineSnapshot& m, const HaulTruckAssignmentResponseV1& b) {
    for (auto& r : b.items) {
        auto known = std::find_if(m.assignmentResponses.begin(), m.assignmentResponses.end(),
                                  [&](auto& x) { return x.assignmentId == r.assignmentId; });
        // §5 #22 [I]: a Rejected for an assignment already Accepted is the AHS giving it up.
        const bool withdrawn =
            known != m.assignmentResponses.end() && known->response == "Accepted" && r.response == "Rejected";
        if (known != m.assignmentResponses.end())
            *known = r;
        else
            m.assignmentResponses.push_back(r);
        if (r.response == "Accepted")
            m.needsAssignment = false;
        const std::string detail = r.detail ? " (" + *r.detail + ")" : std::string();
        if (withdrawn) {
            m_counters.add("assignment.withdrawn");
            event(IsoSeverity::Warning, "assignment " + r.assignmentId + " of " + label(m) +
                                            " can no longer be done: Rejected by the AHS" + detail);
        } else {
            event(r.response == "Accepted" ? IsoSeverity::Info : IsoSeverity::Warning,
                  "assignment " + r.assignmentId + " for " + label(m) + " " + r.response + detail);
        }
    }
}

// ---------------------------------------------------------------- own machines' positions (§7.4)

void FmsCore::sendOwnPositions(const std::map<Guid, IsoPosition>& positions) {
    if (m_state != LinkState::Up)
        return;
    const auto now = unixMillisNow();
    for (auto& [id, p] : positions) {
        MachinePositionV1 m;
        m.timestamp = makeTimestamp(p.measuredUnixMs.value_or(now));
        m.pose.latitude = p.latitude;
        m.pose.longitude = p.longitude;
        m.pose.elevation = p.elevation;
        if (p.heading)
            m.pose.heading = static_cast<std::int64_t>(std::lround(*p.heading)) % 360;
        if (p.speedKmh)
            m.pose.speed = std::lround(*p.speedKmh);
        sendBody(m, id);
    }
}

// ---------------------------------------------------------------- map service (§10.6, MapServiceClient)

bool FmsCore::fetchMap() {
    if (!separateMapService() && !upOrRefuse("map fetch"))
        return false;
    if (m_mapService.fetch())
        return true;
    m_lastRefusal =
        separateMapService() && m_mapService.channelState() != LinkState::Up
            ? "the map service of link " + m_link.name + " is " + toString(m_mapService.channelState())
            : "the WebSocket of link " + m_link.name + " did not take the frame (closing)";
    return false;
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
