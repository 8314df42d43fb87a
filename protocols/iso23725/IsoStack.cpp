#include "IsoStack.h"

#include "WsTransport.h"

#include "common/IoThread.h"
#include "common/Log.h"

#include <boost/asio/steady_timer.hpp>

#include <cmath>
#include <set>

namespace ocu::iso23725 {

static constexpr const char* kLog = "ocu.iso";

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
std::int64_t nowMs() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}
} // namespace

namespace {

struct Link : WsHandler {
    IsoStack::Impl* stack = nullptr;
    IsoLinkConfig cfg;
    std::unique_ptr<WsEndpoint> ep;
    std::optional<SessionId> session;
    LinkState state = LinkState::Unknown;
    bool gotFirstMessage = false;
    std::optional<FleetDefinitionV2> ahsFleet;
    std::map<Guid, IsoMachineSnapshot> machines;
    AllStopStatus allStop;
    std::set<Guid> issuedIds;
    std::unique_ptr<boost::asio::steady_timer> ackTimer, statusTimer;
    MapAssembler assembler;
    bool fetchPending = false;
    std::optional<MapSummaryV1> fetchingSummary;
    std::shared_ptr<MapModel> map;
    std::optional<MapConnectivityV1> connectivity;

    void onOpen(SessionId id, const std::string& peer) override;
    void onText(SessionId id, std::string text) override;
    void onClose(SessionId id, const std::string& reason) override;
    void onConnectFailed(const std::string& reason, std::chrono::milliseconds retryIn) override;
};

} // namespace

struct IsoStack::Impl {
    Impl(IsoConfig c, IsoListener& l, Counters& counters)
        : cfg(std::move(c)), listener(l), counters(counters), io("iso23725"), positionTimer(io.context()) {}

    IsoConfig cfg;
    IsoListener& listener;
    Counters& counters;
    IoThread io;
    std::map<std::string, std::unique_ptr<Link>> links;
    std::map<Guid, IsoPosition> ownPositions;
    boost::asio::steady_timer positionTimer;

    void event(IsoSeverity s, const std::string& text) {
        if (s == IsoSeverity::Info)
            logInfo(kLog, text);
        else
            logWarning(kLog, text);
        listener.onEvent(s, text);
    }

    Link* upLink(const std::string& name, const char* what) {
        auto it = links.find(name);
        if (it == links.end()) {
            event(IsoSeverity::Warning,
                  std::string(what) + " refused: no ISO 23725 link named '" + name + "'");
            return nullptr;
        }
        Link& l = *it->second;
        if (l.state != LinkState::Up || !l.session) {
            // §2.1 rule 1: commands are never queued while the link is down.
            counters.add("cmd.refused.link_down");
            event(IsoSeverity::Warning, std::string(what) + " refused: link '" + name + "' is " +
                                            toString(l.state) + " (commands are not queued)");
            return nullptr;
        }
        return &l;
    }

    void send(Link& l, const Body& body, std::optional<Guid> eq = std::nullopt) {
        if (!l.session)
            return;
        Envelope env;
        env.header.protocol = cfg.rules.protocol;
        env.header.timestamp = makeTimestamp(nowMs());
        env.header.equipmentId = std::move(eq);
        env.members.push_back(Member{body, nlohmann::json::object()});
        l.ep->send(*l.session, encodeMessage(env));
        counters.add("tx.messages");
    }

    FleetDefinitionV2 ownFleet() const {
        FleetDefinitionV2 f;
        f.ahsId = cfg.fmsId;
        for (auto& e : cfg.fleet)
            if (!e.autonomous)
                f.equipment.push_back(e);
        return f;
    }

    IsoMachineSnapshot& machine(Link& l, const Guid& id) {
        auto it = l.machines.find(id);
        if (it != l.machines.end())
            return it->second;
        auto& m = l.machines[id];
        m.link = l.cfg.name;
        m.equipmentId = id;
        return m;
    }

    void checkDiscrepancies(Link& l) {
        std::vector<std::string> items;
        const auto& ahs = *l.ahsFleet;
        std::map<Guid, const Equipment*> ahsById;
        for (auto& e : ahs.equipment)
            ahsById[e.equipmentId] = &e;
        auto dimDiff = [&](const std::optional<double>& a, const std::optional<double>& b) {
            return a.has_value() != b.has_value() || (a && std::fabs(*a - *b) > cfg.dimensionTolerance);
        };
        auto fmt = [](const std::optional<double>& v) {
            if (!v)
                return std::string("null");
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.2f", *v);
            return std::string(buf);
        };
        for (auto& mine : cfg.fleet) {
            auto it = ahsById.find(mine.equipmentId);
            if (it == ahsById.end()) {
                if (mine.autonomous)
                    items.push_back("machine " + mine.hid + " (" + mine.equipmentId +
                                    ") is missing from the AHS fleet definition");
                continue;
            }
            const Equipment& a = *it->second;
            const std::string who = "machine " + mine.equipmentId + ": ";
            if (!mine.autonomous)
                items.push_back(who + "listed by both the FMS (manned) and the AHS");
            if (a.hid != mine.hid)
                items.push_back(who + "HID '" + a.hid + "' at the AHS, '" + mine.hid + "' at the FMS");
            if (a.type != mine.type)
                items.push_back(who + "type " + a.type + " at the AHS, " + mine.type + " at the FMS");
            if (dimDiff(a.length, mine.length) || dimDiff(a.width, mine.width))
                items.push_back(who + "dimensions " + fmt(a.length) + " x " + fmt(a.width) +
                                " m at the AHS, " + fmt(mine.length) + " x " + fmt(mine.width) +
                                " m at the FMS");
        }
        std::set<Guid> mineIds;
        for (auto& e : cfg.fleet)
            mineIds.insert(e.equipmentId);
        for (auto& a : ahs.equipment)
            if (!mineIds.count(a.equipmentId))
                items.push_back("machine " + a.hid + " (" + a.equipmentId + ", " + a.type +
                                ") of the AHS is not in the FMS fleet");
        counters.add("fleet.discrepancies", items.size());
        listener.onFleetDiscrepancies(l.cfg.name, items);
        for (auto& i : items)
            event(IsoSeverity::Warning, "fleet discrepancy on " + l.cfg.name + ": " + i);
    }

    void onFleet(Link& l, const FleetDefinitionV2& f) {
        l.ahsFleet = f;
        std::set<Guid> listed;
        for (auto& e : f.equipment) {
            listed.insert(e.equipmentId);
            auto& m = machine(l, e.equipmentId);
            m.hid = e.hid;
            m.type = e.type;
            m.oem = e.oem;
            m.model = e.model;
            m.autonomous = e.autonomous;
            m.length = e.length;
            m.width = e.width;
            m.inAhsFleet = true;
            listener.onMachineChanged(m);
        }
        // No delete command exists: absence from a re-sent list removes the machine [ISO-seed].
        for (auto it = l.machines.begin(); it != l.machines.end();) {
            if (!listed.count(it->first)) {
                listener.onMachineRemoved(l.cfg.name, it->first);
                it = l.machines.erase(it);
            } else {
                ++it;
            }
        }
        checkDiscrepancies(l);
    }

    void setAllStop(Link& l, const MachineAllStopV1& s) {
        auto& a = l.allStop;
        a.state = s.modeAllStop == "On" ? AllStopState::On : AllStopState::Off;
        a.activeId = s.modeAllStopId;
        a.external = a.state == AllStopState::On && s.modeAllStopId && !l.issuedIds.count(*s.modeAllStopId);
        if (a.pendingId && s.modeAllStopId == a.pendingId) {
            if (l.statusTimer)
                l.statusTimer->cancel();
            if (a.state == AllStopState::Off)
                a.pendingId.reset();
        }
        if (a.external)
            event(IsoSeverity::Warning,
                  "all-stop active on " + l.cfg.name + " (external, id " + *a.activeId + ")");
        listener.onAllStopChanged(l.cfg.name, a);
    }

    void startTimer(Link& l, std::unique_ptr<boost::asio::steady_timer>& t, std::chrono::milliseconds d,
                    std::string alarm) {
        if (!t)
            t = std::make_unique<boost::asio::steady_timer>(io.context());
        t->expires_after(d);
        t->async_wait([this, alarm = std::move(alarm), &l](boost::system::error_code ec) {
            if (ec)
                return;
            counters.add("allstop.timeout");
            event(IsoSeverity::Error, alarm + " on " + l.cfg.name);
        });
    }

    void handle(Link& l, const Envelope& env) {
        const auto& eq = env.header.equipmentId;
        const std::int64_t hdrMs = env.header.timestamp.unixMs.value_or(nowMs());
        for (auto& mem : env.members) {
            std::visit(
                [&](auto&& b) {
                    using T = std::decay_t<decltype(b)>;
                    if constexpr (std::is_same_v<T, FleetDefinitionV2>) {
                        onFleet(l, b);
                    } else if constexpr (std::is_same_v<T, MachineAllStopV1>) {
                        setAllStop(l, b);
                    } else if constexpr (std::is_same_v<T, MachineAllStopResponseV1>) {
                        if (l.ackTimer)
                            l.ackTimer->cancel();
                        std::string d = b.detail ? " (" + *b.detail + ")" : std::string();
                        if (b.response == "Accepted") {
                            event(IsoSeverity::Info,
                                  "all-stop request " + b.modeAllStopId + " accepted by " + l.cfg.name + d);
                            if (l.allStop.state != AllStopState::On || l.allStop.activeId != b.modeAllStopId)
                                startTimer(l, l.statusTimer, cfg.allStopStatusTimeout,
                                           "all-stop accepted but status not confirmed");
                        } else {
                            if (b.detail && b.detail->find("not supported") != std::string::npos) {
                                l.allStop.supported = false;
                                listener.onAllStopChanged(l.cfg.name, l.allStop);
                            }
                            event(IsoSeverity::Error,
                                  "all-stop request " + b.modeAllStopId + " rejected by " + l.cfg.name + d);
                        }
                    } else if constexpr (std::is_same_v<T, MapServiceV1>) {
                        counters.add("rx.map_service");
                    } else if constexpr (std::is_same_v<T, MapSummaryV1>) {
                        onSummary(l, b);
                    } else if constexpr (std::is_same_v<T, MapConnectivityV1>) {
                        l.connectivity = b;
                        if (l.map) {
                            auto m = std::make_shared<MapModel>(*l.map);
                            m->connectivity.assign(b);
                            l.map = m;
                            listener.onMapChanged(l.cfg.name, *m);
                        }
                    } else if constexpr (std::is_same_v<T, InterfaceDiagnosticV1>) {
                        for (auto& m : b.message)
                            event(m.severity == "Error"     ? IsoSeverity::Error
                                  : m.severity == "Warning" ? IsoSeverity::Warning
                                                            : IsoSeverity::Info,
                                  "interface diagnostic from " + l.cfg.name + ": " + m.code +
                                      (m.detail ? " - " + *m.detail : std::string()));
                        counters.add("rx.interface_diagnostic");
                    } else if constexpr (std::is_same_v<T, UnknownMember>) {
                        counters.add("rx.unknown_member");
                    } else if constexpr (std::is_same_v<T, MachineAllStopRequestV1> ||
                                         std::is_same_v<T, MapCommandV1> ||
                                         std::is_same_v<T, HaulTruckAssignmentRequestV2> ||
                                         std::is_same_v<T, HaulTruckAssignmentResetV1>) {
                        counters.add("rx.rejected.wrong_direction");
                        event(IsoSeverity::Warning, std::string(memberName(Body(b))) + " from " + l.cfg.name +
                                                        " ignored: only the FMS sends it");
                    } else {
                        if (!eq)
                            return; // checked by the codec for per-machine members
                        auto& m = machine(l, *eq);
                        if (!m.inAhsFleet && !m.stateKnown) {
                            counters.add("rx.unknown_machine");
                            event(IsoSeverity::Warning, std::string(memberName(Body(b))) + " from " +
                                                            l.cfg.name + " for machine " + *eq +
                                                            " not in its fleet definition");
                        }
                        machineMember(l, m, b, hdrMs);
                        m.stateKnown = true;
                        listener.onMachineChanged(m);
                    }
                },
                mem.body);
        }
    }

    template <class T> void machineMember(Link& l, IsoMachineSnapshot& m, const T& b, std::int64_t hdrMs) {
        if constexpr (std::is_same_v<T, MachinePositionV1>) {
            if (!b.pose.latitude || !b.pose.longitude) {
                counters.add("rx.position_unavailable");
                return;
            }
            if (m.position && m.position->measuredUnixMs && b.timestamp.unixMs &&
                *b.timestamp.unixMs < *m.position->measuredUnixMs) {
                counters.add("rx.late_position"); // latest state wins (§2.1 rule 2)
                return;
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
            p.receivedUnixMs = nowMs();
            m.position = p;
            counters.add("rx.positions");
        } else if constexpr (std::is_same_v<T, MachineAutonomyModeV1>) {
            m.autonomyMode = b.autonomyMode;
        } else if constexpr (std::is_same_v<T, MachineDispatchAvailabilityV1>) {
            if (m.dispatchingCustodian == "AHS" && b.dispatchingCustodian == "FMS")
                event(IsoSeverity::Info,
                      "machine " + label(m) + " needs an assignment (custodian AHS -> FMS, §8.3.4)");
            m.dispatchingCustodian = b.dispatchingCustodian;
        } else if constexpr (std::is_same_v<T, MachineDiagnosticV2>) {
            m.diagnostics = b.entries; // full list each time; [] clears (§8.4)
        } else if constexpr (std::is_same_v<T, BasicMachineHealthV2>) {
            m.health = b;
        } else if constexpr (std::is_same_v<T, HaulTruckProductionStateV2>) {
            // §2.1 rule 4: a late event never overwrites newer state.
            if (hdrMs < m.productionUnixMs) {
                counters.add("rx.late_event");
                event(IsoSeverity::Info, "late production state " + b.productionState + " of " + label(m) +
                                             " at " + formatTimestamp(hdrMs) + " kept in history only");
                return;
            }
            m.production = b;
            m.productionUnixMs = hdrMs;
        } else if constexpr (std::is_same_v<T, HaulTruckPayloadV1>) {
            if (hdrMs < m.payloadUnixMs) {
                counters.add("rx.late_event");
                event(IsoSeverity::Info, "late payload of " + label(m) + " at " + formatTimestamp(hdrMs) +
                                             " kept in history only");
                return;
            }
            m.payload = b;
            m.payloadUnixMs = hdrMs;
        } else if constexpr (std::is_same_v<T, HaulTruckProductionStateSensorV1>) {
            m.sensor = b;
        } else if constexpr (std::is_same_v<T, HaulTruckDumpV1>) {
            m.lastDump = b;
            event(IsoSeverity::Info,
                  "dump by " + label(m) + " at way " + std::to_string(b.wayId) +
                      (b.dumpedWeight ? ", " + std::to_string(*b.dumpedWeight) + " t" : std::string()));
        } else if constexpr (std::is_same_v<T, HaulTruckProductionCycleV1>) {
            m.lastCycle = b;
            event(IsoSeverity::Info, "cycle " + b.cycleId + " completed by " + label(m));
        } else if constexpr (std::is_same_v<T, HaulTruckAssignmentV1>) {
            m.assignment = b;
        } else if constexpr (std::is_same_v<T, HaulTruckAssignmentResponseV1>) {
            m.assignmentResponses = b.items;
            for (auto& r : b.items)
                event(r.response == "Accepted" ? IsoSeverity::Info : IsoSeverity::Warning,
                      "assignment " + r.assignmentId + " for " + label(m) + " " + r.response +
                          (r.detail ? " (" + *r.detail + ")" : std::string()));
        }
        (void)l;
    }

    static std::string label(const IsoMachineSnapshot& m) { return m.hid.empty() ? m.equipmentId : m.hid; }

    void requestMap(Link& l) {
        l.fetchPending = true;
        send(l, MapCommandV1{"GET", "/"});
        counters.add("map.fetch");
    }

    void onSummary(Link& l, const MapSummaryV1& s) {
        if (l.assembler.active()) {
            if (l.fetchingSummary && l.fetchingSummary->changeSetMap == s.changeSetMap &&
                l.fetchingSummary->changeSetWay == s.changeSetWay)
                return; // the same map being transferred
            event(IsoSeverity::Warning, "map changed during transfer on " + l.cfg.name + ": fetching again");
            l.assembler.reset();
            if (!l.fetchPending) {
                requestMap(l);
                return;
            }
        }
        if (l.fetchPending) {
            l.fetchPending = false;
            l.fetchingSummary = s;
            l.assembler.begin(s);
            listener.onMapProgress(l.cfg.name, l.assembler.progress());
            if (s.documentCount == 0)
                finishMap(l);
            return;
        }
        // Re-fetch when the change sets moved (§8 exchange).
        if (!l.map || l.map->summary.changeSetMap != s.changeSetMap ||
            l.map->summary.changeSetWay != s.changeSetWay)
            requestMap(l);
    }

    void onChunk(Link& l, std::string_view xml) {
        if (!l.assembler.active()) {
            counters.add("rx.rejected.unexpected_map_chunk");
            event(IsoSeverity::Warning,
                  "map chunk from " + l.cfg.name + " without a pending map request ignored");
            return;
        }
        auto p = l.assembler.addChunk(xml);
        if (!p) {
            counters.add("rx.rejected.map");
            event(IsoSeverity::Error, "map from " + l.cfg.name + " rejected: " + p.error() +
                                          (l.map ? " (previous map kept)" : std::string()));
            return;
        }
        listener.onMapProgress(l.cfg.name, *p);
        if (p->complete())
            finishMap(l);
    }

    void finishMap(Link& l) {
        auto m = l.assembler.finish();
        if (!m) {
            counters.add("rx.rejected.map");
            event(IsoSeverity::Error, "map from " + l.cfg.name + " rejected: " + m.error());
            return;
        }
        auto model = std::make_shared<MapModel>(std::move(*m));
        if (l.connectivity)
            model->connectivity.assign(*l.connectivity);
        for (auto& w : model->warnings)
            event(IsoSeverity::Warning, "map from " + l.cfg.name + ": " + w);
        l.map = model;
        counters.add("map.complete");
        event(IsoSeverity::Info, "map from " + l.cfg.name +
                                     " complete: " + std::to_string(model->nodes.size()) + " nodes, " +
                                     std::to_string(model->ways.size()) + " ways");
        listener.onMapChanged(l.cfg.name, *model);
    }

    void sendOwnPositions() {
        if (!cfg.sendPositions)
            return;
        const auto now = nowMs();
        for (auto& [name, l] : links) {
            if (l->state != LinkState::Up)
                continue;
            for (auto& [id, p] : ownPositions) {
                MachinePositionV1 m;
                m.timestamp = makeTimestamp(p.measuredUnixMs.value_or(now));
                m.pose.latitude = p.latitude;
                m.pose.longitude = p.longitude;
                m.pose.elevation = p.elevation;
                if (p.heading)
                    m.pose.heading = static_cast<std::int64_t>(std::lround(*p.heading)) % 360;
                if (p.speedKmh)
                    m.pose.speed = std::lround(*p.speedKmh);
                send(*l, m, id);
            }
        }
    }

    void positionTick() {
        auto period =
            std::chrono::milliseconds(static_cast<int>(1000.0 / std::clamp(cfg.positionRateHz, 1.0, 10.0)));
        positionTimer.expires_after(period);
        positionTimer.async_wait([this](boost::system::error_code ec) {
            if (ec)
                return;
            sendOwnPositions();
            positionTick();
        });
    }
};

// ---------------------------------------------------------------- link callbacks (io thread)

void Link::onOpen(SessionId id, const std::string& peer) {
    auto& s = *stack;
    if (session) { // service role: a second AHS connection replaces the first
        s.event(IsoSeverity::Warning,
                "link " + cfg.name + ": new connection from " + peer + " replaces the old one");
        ep->close(*session, "replaced");
    }
    session = id;
    state = LinkState::Up;
    gotFirstMessage = false;
    fetchPending = false;
    assembler.reset();
    s.listener.onLinkState(cfg.name, LinkState::Up, "connected to " + peer);
    s.event(IsoSeverity::Info, "link " + cfg.name + " up (" + peer + ")");
    // [ISO-seed]: FleetDefinitionV2 is the first message sent by both actors upon connection.
    s.send(*this, s.ownFleet());
    s.sendOwnPositions();
}

void Link::onText(SessionId id, std::string text) {
    auto& s = *stack;
    if (session != id)
        return;
    s.counters.add("rx.frames");
    std::size_t i = text.find_first_not_of(" \t\r\n");
    if (i != std::string::npos && text[i] == '<') {
        s.onChunk(*this, text);
        return;
    }
    auto env = decodeMessage(text, s.cfg.rules);
    if (!env) {
        s.counters.add(env.error() == "message: invalid JSON" ? "rx.rejected.invalid_json"
                                                              : "rx.rejected.header");
        s.event(IsoSeverity::Warning, "message from " + cfg.name + " rejected: " + env.error());
        return;
    }
    for (auto& e : env->errors) {
        s.counters.add("rx.rejected.invalid_member");
        s.event(IsoSeverity::Warning, "message from " + cfg.name + " rejected: " + e);
    }
    for (auto& w : env->warnings) {
        s.counters.add("rx.tolerated");
        logWarning(kLog, cfg.name + ": " + w);
    }
    if (env->outOfStandard)
        s.counters.add("rx.out_of_standard");
    if (!gotFirstMessage && !env->members.empty()) {
        gotFirstMessage = true;
        if (!env->find<FleetDefinitionV2>()) {
            s.counters.add("rx.first_not_fleet_definition");
            s.event(IsoSeverity::Warning, "first message from " + cfg.name + " was " +
                                              std::string(memberName(env->members.front().body)) +
                                              ", not FleetDefinitionV2");
        }
    }
    s.handle(*this, *env);
}

void Link::onClose(SessionId id, const std::string& reason) {
    auto& s = *stack;
    if (session != id)
        return;
    session.reset();
    state = LinkState::Down;
    if (ackTimer)
        ackTimer->cancel();
    if (statusTimer)
        statusTimer->cancel();
    if (assembler.active()) {
        assembler.reset();
        s.event(IsoSeverity::Warning, "map transfer from " + cfg.name + " interrupted" +
                                          (map ? " (previous map kept)" : std::string()));
    }
    fetchPending = false;
    // §2.1 rule 5 / §7.7: all-stop and machine state are UNKNOWN while disconnected.
    allStop.state = AllStopState::Unknown;
    allStop.activeId.reset();
    allStop.external = false;
    s.listener.onAllStopChanged(cfg.name, allStop);
    for (auto& [mid, m] : machines) {
        m.stateKnown = false;
        s.listener.onMachineChanged(m);
    }
    // Reported last, so a listener that sees DOWN already sees UNKNOWN all-stop and machine state.
    s.listener.onLinkState(cfg.name, LinkState::Down, reason);
    s.event(IsoSeverity::Warning, "link " + cfg.name + " down: " + reason);
}

void Link::onConnectFailed(const std::string& reason, std::chrono::milliseconds retryIn) {
    auto& s = *stack;
    s.counters.add("link.connect_failed");
    if (state != LinkState::Down) {
        state = LinkState::Down;
        s.listener.onLinkState(cfg.name, LinkState::Down, reason);
    }
    logInfo(kLog,
            "link " + cfg.name + ": " + reason + "; retry in " + std::to_string(retryIn.count()) + " ms");
}

// ---------------------------------------------------------------- IsoStack

IsoStack::IsoStack(IsoConfig config, IsoListener& listener)
    : m_impl(std::make_unique<Impl>(std::move(config), listener, m_counters)) {}

IsoStack::~IsoStack() {
    stop();
}

bool IsoStack::start() {
    auto& d = *m_impl;
    if (d.io.running())
        return true;
    d.io.start();
    return d.io.call([&] {
        bool ok = true;
        for (auto& lc : d.cfg.links) {
            auto l = std::make_unique<Link>();
            l->stack = &d;
            l->cfg = lc;
            l->ep = std::make_unique<WsEndpoint>(d.io.context(), lc.ws, *l, d.counters);
            auto r = l->ep->start();
            if (!r) {
                ok = false;
                d.event(IsoSeverity::Error, "link " + lc.name + " cannot start: " + r.error());
            }
            d.listener.onLinkState(lc.name, LinkState::Unknown, r ? "connecting" : r.error());
            d.links[lc.name] = std::move(l);
        }
        d.positionTick();
        return ok;
    });
}

void IsoStack::stop() {
    auto& d = *m_impl;
    if (!d.io.running())
        return;
    d.io.call([&] {
        d.positionTimer.cancel();
        for (auto& [n, l] : d.links) {
            l->ep->stop();
            if (l->ackTimer)
                l->ackTimer->cancel();
            if (l->statusTimer)
                l->statusTimer->cancel();
        }
    });
    d.io.stop();
    d.links.clear();
}

void IsoStack::allStopApply(const std::string& link) {
    m_impl->io.post([d = m_impl.get(), link] {
        Link* l = d->upLink(link, "all-stop Apply");
        if (!l)
            return;
        Guid id = newGuid();
        l->issuedIds.insert(id);
        l->allStop.pendingId = id;
        d->send(*l, MachineAllStopRequestV1{"Apply", id});
        d->counters.add("allstop.apply");
        d->event(IsoSeverity::Info, "all-stop Apply " + id + " sent to " + link);
        d->startTimer(*l, l->ackTimer, d->cfg.allStopAckTimeout, "all-stop not acknowledged");
        d->listener.onAllStopChanged(link, l->allStop);
    });
}

void IsoStack::allStopRemove(const std::string& link) {
    m_impl->io.post([d = m_impl.get(), link] {
        Link* l = d->upLink(link, "all-stop Remove");
        if (!l)
            return;
        // "Same ID used in apply must be used when removing" [OA-iso].
        std::optional<Guid> id = l->allStop.activeId ? l->allStop.activeId : l->allStop.pendingId;
        if (!id) {
            d->event(IsoSeverity::Warning, "all-stop Remove refused on " + link + ": no active all-stop id");
            return;
        }
        l->allStop.pendingId = id;
        d->send(*l, MachineAllStopRequestV1{"Remove", *id});
        d->counters.add("allstop.remove");
        d->event(IsoSeverity::Info, "all-stop Remove " + *id + " sent to " + link);
        d->startTimer(*l, l->ackTimer, d->cfg.allStopAckTimeout, "all-stop Remove not acknowledged");
    });
}

void IsoStack::requestAssignment(const std::string& link, const Guid& equipmentId,
                                 std::vector<AssignmentItem> items) {
    m_impl->io.post([d = m_impl.get(), link, equipmentId, items = std::move(items)]() mutable {
        Link* l = d->upLink(link, "assignment request");
        if (!l)
            return;
        auto it = l->machines.find(equipmentId);
        if (it == l->machines.end()) {
            d->event(IsoSeverity::Warning,
                     "assignment refused: machine " + equipmentId + " unknown on " + link);
            return;
        }
        if (it->second.dispatchingCustodian == "AHS") {
            d->event(IsoSeverity::Warning, "assignment refused: " + Impl::label(it->second) +
                                               " is dispatched by the AHS (DispatchingCustodian AHS)");
            return;
        }
        if (items.empty()) {
            d->event(IsoSeverity::Warning, "assignment refused: empty request");
            return;
        }
        for (auto& a : items) {
            if (a.assignmentId.empty())
                a.assignmentId = newGuid();
            if (a.route && !d->cfg.rules.emitNegativeWayIds)
                for (auto& w : *a.route)
                    w.wayId = std::abs(w.wayId); // Q6: negative ids not emitted unless enabled
        }
        it->second.requestedAssignments = items;
        d->send(*l, HaulTruckAssignmentRequestV2{items}, equipmentId);
        d->counters.add("assignment.request");
        d->listener.onMachineChanged(it->second);
    });
}

void IsoStack::resetAssignment(const std::string& link, const Guid& equipmentId) {
    m_impl->io.post([d = m_impl.get(), link, equipmentId] {
        Link* l = d->upLink(link, "assignment reset");
        if (!l)
            return;
        d->send(*l, HaulTruckAssignmentResetV1{newGuid()}, equipmentId);
        d->counters.add("assignment.reset");
    });
}

void IsoStack::setOwnPosition(const Guid& equipmentId, double lat, double lon, double elevation,
                              double headingDeg, double speedKmh) {
    m_impl->io.post([d = m_impl.get(), equipmentId, lat, lon, elevation, headingDeg, speedKmh] {
        IsoPosition p;
        p.latitude = lat;
        p.longitude = lon;
        p.elevation = elevation;
        p.heading = std::fmod(std::fmod(headingDeg, 360.0) + 360.0, 360.0);
        p.speedKmh = speedKmh;
        p.measuredUnixMs = nowMs();
        d->ownPositions[equipmentId] = p;
    });
}

void IsoStack::fetchMap(const std::string& link) {
    m_impl->io.post([d = m_impl.get(), link] {
        Link* l = d->upLink(link, "map fetch");
        if (!l)
            return;
        l->assembler.reset();
        d->requestMap(*l);
    });
}

std::vector<IsoMachineSnapshot> IsoStack::machines(const std::string& link) {
    return m_impl->io.call([&] {
        std::vector<IsoMachineSnapshot> out;
        auto it = m_impl->links.find(link);
        if (it != m_impl->links.end())
            for (auto& [id, m] : it->second->machines)
                out.push_back(m);
        return out;
    });
}

AllStopStatus IsoStack::allStop(const std::string& link) {
    return m_impl->io.call([&] {
        auto it = m_impl->links.find(link);
        return it == m_impl->links.end() ? AllStopStatus{} : it->second->allStop;
    });
}

LinkState IsoStack::linkState(const std::string& link) {
    return m_impl->io.call([&] {
        auto it = m_impl->links.find(link);
        return it == m_impl->links.end() ? LinkState::Unknown : it->second->state;
    });
}

std::vector<std::string> IsoStack::linkNames() const {
    std::vector<std::string> out;
    for (auto& l : m_impl->cfg.links)
        out.push_back(l.name);
    return out;
}

std::shared_ptr<const MapModel> IsoStack::map(const std::string& link) {
    return m_impl->io.call([&]() -> std::shared_ptr<const MapModel> {
        auto it = m_impl->links.find(link);
        return it == m_impl->links.end() ? nullptr : it->second->map;
    });
}

} // namespace ocu::iso23725
