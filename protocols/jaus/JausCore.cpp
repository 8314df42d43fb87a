#include "protocols/jaus/JausCore.h"

#include <algorithm>
#include <cmath>

#include "protocols/common/Log.h"

namespace ocu::jaus {

namespace {

constexpr const char* kLog = "ocu.jaus";

Duration secondsD(double s) {
    return std::chrono::duration_cast<Duration>(std::chrono::duration<double>(s));
}
Duration periodOf(double hz) {
    return secondsD(1.0 / std::max(hz, 0.01));
}

bool hasService(const ComponentServices& c, std::string_view name) {
    for (auto& s : c.services) {
        auto pos = s.uri.rfind(':');
        if (pos != std::string::npos && std::string_view(s.uri).substr(pos + 1) == name)
            return true;
    }
    return false;
}

} // namespace

const char* toString(LinkState s) {
    switch (s) {
    case LinkState::Up:
        return "up";
    case LinkState::Degraded:
        return "degraded";
    case LinkState::Down:
        return "down";
    }
    return "?";
}
const char* toString(AccessState s) {
    switch (s) {
    case AccessState::NotAvailable:
        return "NOT_AVAILABLE";
    case AccessState::NotControlled:
        return "NOT_CONTROLLED";
    case AccessState::Monitoring:
        return "MONITORING";
    case AccessState::ControlAccepted:
        return "CONTROL_ACCEPTED";
    case AccessState::ControlReleased:
        return "CONTROL_RELEASED";
    case AccessState::Timeout:
        return "TIMEOUT";
    case AccessState::InsufficientAuthority:
        return "INSUFFICIENT_AUTHORITY";
    case AccessState::Preempted:
        return "PREEMPTED";
    }
    return "?";
}
const char* toString(EventKind k) {
    switch (k) {
    case EventKind::Discovered:
        return "discovered";
    case EventKind::LinkLost:
        return "link-lost";
    case EventKind::LinkRestored:
        return "link-restored";
    case EventKind::ControlAccepted:
        return "control-accepted";
    case EventKind::ControlRejected:
        return "control-rejected";
    case EventKind::ControlReleased:
        return "control-released";
    case EventKind::ControlLost:
        return "control-lost";
    case EventKind::ControlPreempted:
        return "control-preempted";
    case EventKind::Emergency:
        return "emergency";
    case EventKind::EmergencyCleared:
        return "emergency-cleared";
    case EventKind::ManagementChanged:
        return "management-changed";
    case EventKind::HealthFault:
        return "health-fault";
    case EventKind::DecodeError:
        return "decode-error";
    case EventKind::CommandRefused:
        return "command-refused";
    case EventKind::TransportError:
        return "transport-error";
    }
    return "?";
}

JausCore::JausCore(JausConfig config, JausListener& listener, JausOutput& output, const Clock& clock,
                   Counters& counters)
    : m_cfg(std::move(config)), m_listener(listener), m_out(output), m_clock(clock), m_counters(counters),
      m_self(m_cfg.ownId()) {}

void JausCore::send(const JausId& dst, const Bytes& payload, SendOptions o) {
    m_counters.add("tx.messages");
    m_out.send(dst, payload, o);
}

void JausCore::notify(Severity s, EventKind k, std::uint16_t ss, std::string text) {
    if (s != Severity::Info)
        logWarning(kLog, text);
    m_listener.onEvent(JausEvent{s, k, ss, std::move(text)});
}

void JausCore::changed(Remote& r) {
    m_listener.onSubsystemChanged(r.snap);
}

JausCore::Remote& JausCore::remote(std::uint16_t ss) {
    auto it = m_remotes.find(ss);
    if (it != m_remotes.end())
        return it->second;
    Remote& r = m_remotes[ss];
    r.snap.subsystem = ss;
    r.snap.access = AccessState::Monitoring;
    r.lastHeard = m_clock.now();
    r.snap.link = LinkState::Up;
    r.platformManager = JausId{ss, 1, 1};
    return r;
}

JausCore::Remote* JausCore::find(std::uint16_t ss) {
    auto it = m_remotes.find(ss);
    return it == m_remotes.end() ? nullptr : &it->second;
}

std::optional<SubsystemSnapshot> JausCore::snapshot(std::uint16_t ss) const {
    auto it = m_remotes.find(ss);
    if (it == m_remotes.end())
        return std::nullopt;
    return it->second.snap;
}

std::vector<std::uint16_t> JausCore::subsystems() const {
    std::vector<std::uint16_t> out;
    for (auto& [k, v] : m_remotes)
        out.push_back(k);
    return out;
}

bool JausCore::anyDriveActive() const {
    for (auto& [k, r] : m_remotes)
        if (r.driveActive || r.stopRepeatsLeft > 0)
            return true;
    return false;
}

bool JausCore::refuse(std::uint16_t ss, const std::string& why) {
    m_counters.add("cmd.refused");
    notify(Severity::Warning, EventKind::CommandRefused, ss, why);
    return false;
}

void JausCore::discoverNow() {
    m_lastDiscovery = m_clock.now();
    // Subsystem-level identification to everyone (AEP-4818 §6.2.2.2.1.1, §9 item 6).
    send(kBroadcastAll, encode(QueryIdentification{IdQueryType::Subsystem}));
}

// ---- received messages ------------------------------------------------------------------------------------

void JausCore::handle(const JausId& src, const JausId& dst, ByteSpan payload) {
    if (src == m_self)
        return; // our own multicast looped back
    const std::uint16_t id = peekMessageId(payload);
    m_counters.add("rx.messages");
    if (!dst.matches(m_self) && id != msg::ReportHeartbeatPulse) {
        m_counters.add("rx.ignored.not_for_us");
        return;
    }
    answerOwn(src, id, payload);
    if (src.subsystem == m_self.subsystem || src.subsystem == 0 || src.subsystem == 0xFFFF)
        return;
    // Queries from other OCUs are answered above; only platform traffic goes further.
    if (id == msg::QueryIdentification || id == msg::QueryServices || id == msg::QueryServiceList ||
        id == msg::QueryHeartbeatPulse)
        return;

    if (m_otherOcus.count(src.subsystem))
        return; // another console: answered above, never listed as a vehicle
    if (id == msg::ReportIdentification) {
        auto ri = decodeReportIdentification(payload);
        if (ri && ri->type == IdType::Ocu) {
            m_otherOcus.insert(src.subsystem);
            m_remotes.erase(src.subsystem);
            return;
        }
    }
    const TimePoint now = m_clock.now();
    const bool isNew = !find(src.subsystem);
    Remote& r = remote(src.subsystem);
    r.lastHeard = now;
    r.snap.lastMessage = now;
    r.snap.lastMessageUnixMs = unixMillisNow();
    if (r.snap.link != LinkState::Up) {
        const bool wasDown = r.snap.link == LinkState::Down;
        r.snap.link = LinkState::Up;
        if (wasDown && !isNew) {
            notify(Severity::Info, EventKind::LinkRestored, src.subsystem,
                   "link to " + r.snap.callSign + " (" + std::to_string(src.subsystem) + ") restored");
            // The platform may have restarted: subscribe again.
            for (auto& [k, s] : r.subs)
                s.state = SubState::None;
        }
    }
    if (id == msg::ReportIdentification) {
        auto ri = decodeReportIdentification(payload);
        if (!ri) {
            m_counters.add("rx.rejected." + rejectReason(ri.error()));
            return;
        }
        if (ri->queryType == IdQueryType::Subsystem || r.snap.callSign.empty()) {
            const bool first = r.snap.callSign.empty();
            if (ri->queryType == IdQueryType::Subsystem)
                r.snap.callSign = ri->identification;
            else if (first)
                r.snap.callSign = ri->identification;
            r.platformManager = src;
            r.snap.endpoint = m_out.endpointOf(src);
            if (!r.discoveredEvent) {
                r.discoveredEvent = true;
                notify(Severity::Info, EventKind::Discovered, src.subsystem,
                       "discovered " + r.snap.callSign + " (subsystem " + std::to_string(src.subsystem) +
                           ")");
            }
        }
        changed(r);
        return;
    }
    handleReport(r, src, id, payload);
}

void JausCore::answerOwn(const JausId& src, std::uint16_t id, ByteSpan payload) {
    // The OCU is a JAUS subsystem too (issue 3 §2): identification, services, heartbeat.
    switch (id) {
    case msg::QueryIdentification: {
        auto q = decodeQueryIdentification(payload);
        if (!q)
            return;
        send(src, encode(ReportIdentification{q->type,
                                              q->type == IdQueryType::Subsystem ? IdType::Ocu
                                              : q->type == IdQueryType::Node    ? IdType::Node
                                                                                : IdType::Component,
                                              m_cfg.callSign}));
        return;
    }
    case msg::QueryServices:
    case msg::QueryServiceList: {
        NodeServices node{m_self.node,
                          {{m_self.component,
                            0,
                            {{"urn:jaus:jss:core:Transport", 1, 1},
                             {"urn:jaus:jss:core:Events", 1, 1},
                             {"urn:jaus:jss:core:Liveness", 1, 1},
                             {"urn:jaus:jss:core:Discovery", 1, 1}}}}};
        if (id == msg::QueryServices)
            send(src, encode(ReportServices{{node}}));
        else
            send(src, encode(ReportServiceList{{{m_self.subsystem, {node}}}}));
        return;
    }
    case msg::QueryHeartbeatPulse:
        send(src, encodeEmpty(msg::ReportHeartbeatPulse));
        return;
    case msg::CreateEvent: {
        auto ce = decodeCreateEvent(payload);
        if (!ce)
            return;
        RejectEventRequest rej;
        rej.requestId = ce->requestId;
        rej.responseCode = 5; // message not supported: the OCU serves no events
        send(src, encode(rej));
        return;
    }
    default:
        return;
    }
}

void JausCore::onServices(Remote& r, const JausId& src, const std::vector<NodeServices>& nodes) {
    // Merge (peers send duplicates, jaus-wire.md §6.7).
    for (auto& n : nodes) {
        auto nit = std::find_if(r.snap.services.begin(), r.snap.services.end(),
                                [&](const NodeInfo& x) { return x.node == n.node; });
        if (nit == r.snap.services.end()) {
            r.snap.services.push_back(NodeInfo{n.node, {}});
            nit = std::prev(r.snap.services.end());
        }
        for (auto& c : n.components) {
            auto cit = std::find_if(nit->components.begin(), nit->components.end(),
                                    [&](const ComponentInfo& x) { return x.component == c.component; });
            if (cit == nit->components.end()) {
                nit->components.push_back(ComponentInfo{c.component, {}});
                cit = std::prev(nit->components.end());
            }
            for (auto& s : c.services) {
                bool dup =
                    std::any_of(cit->services.begin(), cit->services.end(),
                                [&](const ServiceRecord& x) { return x.uri == s.uri && x.major == s.major; });
                if (!dup)
                    cit->services.push_back(s);
            }
            const JausId id{src.subsystem, n.node, c.component};
            if (hasService(c, "PrimitiveDriver") || hasService(c, "VelocityStateDriver"))
                r.snap.mobilityComponent = id;
            if (hasService(c, "GlobalPoseSensor"))
                r.globalPoseSensor = id;
            if (hasService(c, "LocalPoseSensor"))
                r.localPoseSensor = id;
            if (hasService(c, "VelocityStateSensor"))
                r.velocitySensor = id;
            if (hasService(c, "HealthMonitor"))
                r.healthMonitor = id;
            if (hasService(c, "PlatformSpecifications"))
                r.platformSpecs = id;
            if (hasService(c, "Liveness") && n.node == 1 && r.platformManager.subsystem == 0)
                r.platformManager = id;
        }
    }
    if (!r.servicesKnown) {
        r.servicesKnown = true;
        subscribe(r, r.platformManager, msg::QueryHeartbeatPulse, encodeEmpty(msg::QueryHeartbeatPulse),
                  m_cfg.heartbeatRateHz);
        if (r.globalPoseSensor.subsystem)
            subscribe(r, r.globalPoseSensor, msg::QueryGlobalPose,
                      encodeQueryPv16(msg::QueryGlobalPose, 0x01FF), m_cfg.poseRateHz);
        if (r.localPoseSensor.subsystem)
            subscribe(r, r.localPoseSensor, msg::QueryLocalPose, encodeQueryPv16(msg::QueryLocalPose, 0x01FF),
                      m_cfg.poseRateHz);
        if (r.velocitySensor.subsystem)
            subscribe(r, r.velocitySensor, msg::QueryVelocityState,
                      encodeQueryPv16(msg::QueryVelocityState, 0x01FF), m_cfg.poseRateHz);
        // Management state on change: an emergency shows at once, not at the next poll.
        if (r.snap.mobilityComponent.subsystem)
            subscribe(r, r.snap.mobilityComponent, msg::QueryStatus, encodeEmpty(msg::QueryStatus),
                      m_cfg.statusPollHz, EventType::EveryChange);
    }
    changed(r);
}

void JausCore::subscribe(Remote& r, const JausId& target, std::uint16_t queryId, Bytes query, double rateHz,
                         EventType type) {
    Subscription s;
    s.type = type;
    s.queryId = queryId;
    s.target = target;
    s.query = std::move(query);
    s.rateHz = rateHz;
    r.subs[queryId] = std::move(s);
}

void JausCore::handleReport(Remote& r, const JausId& src, std::uint16_t id, ByteSpan p) {
    auto reject = [&](const std::string& err) {
        m_counters.add("rx.rejected." + rejectReason(err));
        logWarning(kLog, "from " + src.toString() + ": " + err);
    };
    const TimePoint now = m_clock.now();
    switch (id) {
    case msg::ReportServices: {
        auto m = decodeReportServices(p);
        if (!m)
            return reject(m.error());
        onServices(r, src, m->nodes);
        return;
    }
    case msg::ReportServiceList: {
        auto m = decodeReportServiceList(p);
        if (!m)
            return reject(m.error());
        for (auto& s : m->subsystems)
            if (s.subsystem == src.subsystem)
                onServices(r, src, s.nodes);
        return;
    }
    case msg::ReportHeartbeatPulse:
        if (r.snap.callSign.empty() && now - r.lastIdentQuery > std::chrono::seconds(1)) {
            r.lastIdentQuery = now;
            send(JausId{src.subsystem, src.node, src.component},
                 encode(QueryIdentification{IdQueryType::Subsystem}));
        }
        return;
    case msg::ConfirmControl: {
        auto m = decodeU8(p, id);
        if (!m)
            return reject(m.error());
        r.lastConfirm = now;
        if (*m == std::uint8_t(ConfirmControlCode::Accepted)) {
            if (!r.wantControl) {
                // A late accept after we gave up: hand it back.
                send(src, encodeEmpty(msg::ReleaseControl));
                return;
            }
            r.snap.controller = m_self;
            r.snap.controllerAuthority = m_cfg.authority;
            if (!r.snap.controlledByUs) {
                r.snap.controlledByUs = true;
                r.snap.access = AccessState::ControlAccepted;
                notify(Severity::Info, EventKind::ControlAccepted, r.snap.subsystem,
                       "control of " + r.snap.callSign + " accepted (authority " +
                           std::to_string(m_cfg.authority) + ")");
                changed(r);
            }
            return;
        }
        const bool had = r.snap.controlledByUs;
        r.wantControl = false;
        r.snap.controlledByUs = false;
        r.driveActive = false;
        r.snap.driving = false;
        r.snap.access = *m == std::uint8_t(ConfirmControlCode::NotAvailable)
                            ? AccessState::NotAvailable
                            : AccessState::InsufficientAuthority;
        const std::string why = *m == 1 ? "not available" : "insufficient authority";
        if (had) {
            r.snap.access = AccessState::Preempted;
            notify(Severity::Warning, EventKind::ControlPreempted, r.snap.subsystem,
                   "control of " + r.snap.callSign + " lost: re-request refused (" + why + ")");
        } else {
            notify(Severity::Warning, EventKind::ControlRejected, r.snap.subsystem,
                   "control of " + r.snap.callSign + " refused: " + why);
        }
        send(src, encodeEmpty(msg::QueryControl));
        changed(r);
        return;
    }
    case msg::RejectControl: {
        auto m = decodeU8(p, id);
        if (!m)
            return reject(m.error());
        if (r.releasing) {
            r.releasing = false;
            r.snap.controlledByUs = false;
            r.snap.access = AccessState::ControlReleased;
            notify(Severity::Info, EventKind::ControlReleased, r.snap.subsystem,
                   "control of " + r.snap.callSign + " released");
            changed(r);
            return;
        }
        if (r.snap.controlledByUs || r.wantControl)
            onControlLost(r, *m == 0 ? "released by the platform" : "control not available");
        return;
    }
    case msg::ReportControl: {
        auto m = decodeReportControl(p);
        if (!m)
            return reject(m.error());
        r.snap.controller = m->controller;
        r.snap.controllerAuthority = m->authority;
        const bool ours = m->controller == m_self;
        if (r.classifyLoss) {
            classify(r, *m);
        } else if (r.snap.controlledByUs && !ours && m->controller.subsystem != 0 &&
                   now - r.lastConfirm > std::chrono::milliseconds(500)) {
            // Someone else holds control although we think we do (a missed RejectControl).
            r.classifyLoss = true;
            classify(r, *m);
        } else if (!r.snap.controlledByUs && !r.wantControl &&
                   (r.snap.access == AccessState::Monitoring ||
                    r.snap.access == AccessState::NotControlled)) {
            r.snap.access =
                m->controller.subsystem == 0 ? AccessState::NotControlled : AccessState::Monitoring;
        }
        changed(r);
        return;
    }
    case msg::ReportTimeout: {
        auto m = decodeU8(p, id);
        if (!m)
            return reject(m.error());
        r.snap.accessTimeoutS = *m;
        changed(r);
        return;
    }
    case msg::ReportStatus: {
        auto m = decodeReportStatus(p);
        if (!m)
            return reject(m.error());
        const auto old = r.snap.management;
        r.snap.management = m->status;
        const bool emergency = m->status == ManagementState::Emergency;
        if (emergency && !r.snap.emergency)
            notify(Severity::Error, EventKind::Emergency, r.snap.subsystem,
                   r.snap.callSign + " is in EMERGENCY");
        if (!emergency && r.snap.emergency)
            notify(Severity::Info, EventKind::EmergencyCleared, r.snap.subsystem,
                   r.snap.callSign + " left EMERGENCY");
        r.snap.emergency = emergency;
        if (emergency)
            r.emergencyRetries = 0;
        if (old != m->status) {
            notify(m->status == ManagementState::Failure ? Severity::Error : Severity::Info,
                   EventKind::ManagementChanged, r.snap.subsystem,
                   r.snap.callSign + " management " + toString(m->status));
        }
        changed(r);
        return;
    }
    case msg::ReportGlobalPose: {
        auto m = decodeGlobalPose(p);
        if (!m)
            return reject(m.error());
        r.snap.globalPose = *m;
        changed(r);
        return;
    }
    case msg::ReportLocalPose: {
        auto m = decodeLocalPose(p);
        if (!m)
            return reject(m.error());
        r.snap.localPose = *m;
        changed(r);
        return;
    }
    case msg::ReportVelocityState: {
        auto m = decodeVelocityState(p);
        if (!m)
            return reject(m.error());
        r.snap.velocity = *m;
        changed(r);
        return;
    }
    case msg::ReportPlatformSpecifications: {
        auto m = decodePlatformSpecifications(p);
        if (!m)
            return reject(m.error());
        r.snap.platform = *m;
        changed(r);
        return;
    }
    case msg::ReportHealthSummary: {
        auto m = decodeHealthSummary(p);
        if (!m)
            return reject(m.error());
        const std::uint8_t old = r.snap.health ? r.snap.health->severity : 0;
        r.snap.health = *m;
        if (m->severity >= 3 && m->severity != old)
            notify(m->severity >= 4 ? Severity::Error : Severity::Warning, EventKind::HealthFault,
                   r.snap.subsystem, r.snap.callSign + " health " + (m->severity >= 4 ? "FAIL" : "ERR"));
        changed(r);
        return;
    }
    case msg::ConfirmEventRequest: {
        auto m = decodeConfirmEventRequest(p);
        if (!m)
            return reject(m.error());
        for (auto& [k, s] : r.subs) {
            if (s.state == SubState::Pending && s.requestId == m->requestId) {
                s.eventId = m->eventId;
                // Accepted at a much lower rate than asked: poll instead (issue 3 §3, events).
                if (s.type == EventType::Periodic && m->rateHz + 1e-6 < s.rateHz * 0.5) {
                    send(s.target, encode(CancelEvent{s.requestId, s.eventId}));
                    s.state = SubState::Polling;
                    m_counters.add("events.fallback.rate");
                } else {
                    s.state = SubState::Active;
                }
            }
        }
        return;
    }
    case msg::RejectEventRequest: {
        auto m = decodeRejectEventRequest(p);
        if (!m)
            return reject(m.error());
        for (auto& [k, s] : r.subs)
            if (s.state == SubState::Pending && s.requestId == m->requestId) {
                s.state = SubState::Polling;
                m_counters.add("events.fallback.rejected");
            }
        return;
    }
    case msg::Event: {
        auto m = decodeEvent(p);
        if (!m)
            return reject(m.error());
        const std::uint16_t inner = peekMessageId(m->reportMessage);
        if (inner == msg::Event)
            return reject("nested: Event wraps an Event");
        handleReport(r, src, inner, m->reportMessage);
        return;
    }
    case msg::ReportAuthority:
        return;
    default:
        m_counters.add("rx.unhandled");
        return;
    }
}

void JausCore::onControlLost(Remote& r, const std::string& why) {
    r.wantControl = false;
    r.snap.controlledByUs = false;
    r.driveActive = false;
    r.stopRepeatsLeft = 0;
    r.snap.driving = false;
    // Find out who holds control now to tell pre-emption from a timeout (AEP-4818 §9 item 14).
    r.classifyLoss = true;
    r.classifyDeadline = m_clock.now() + std::chrono::seconds(1);
    r.snap.access = AccessState::ControlReleased;
    if (r.snap.mobilityComponent.subsystem)
        send(r.snap.mobilityComponent, encodeEmpty(msg::QueryControl));
    logInfo(kLog, "control of " + r.snap.callSign + " ended: " + why);
    changed(r);
}

void JausCore::classify(Remote& r, const ReportControl& rc) {
    r.classifyLoss = false;
    r.snap.controlledByUs = false;
    r.wantControl = false;
    r.driveActive = false;
    r.snap.driving = false;
    if (rc.controller.subsystem != 0 && !(rc.controller == m_self) && rc.authority > m_cfg.authority) {
        r.snap.access = AccessState::Preempted;
        notify(Severity::Warning, EventKind::ControlPreempted, r.snap.subsystem,
               "control of " + r.snap.callSign + " pre-empted by " + rc.controller.toString() +
                   " (authority " + std::to_string(rc.authority) + ")");
    } else {
        r.snap.access = AccessState::Timeout;
        notify(Severity::Warning, EventKind::ControlLost, r.snap.subsystem,
               "control of " + r.snap.callSign + " lost");
    }
    changed(r);
}

// ---- commands ---------------------------------------------------------------------------------------------

bool JausCore::requestControl(std::uint16_t ss) {
    if (!m_cfg.mayControl())
        return refuse(ss, "the monitor role (authority 0) never requests control");
    Remote* r = find(ss);
    if (!r || !r->snap.mobilityComponent.subsystem)
        return refuse(ss, "subsystem " + std::to_string(ss) + " has no known mobility component yet");
    r->wantControl = true;
    r->releasing = false;
    r->classifyLoss = false;
    r->lastRequest = m_clock.now();
    send(r->snap.mobilityComponent, encodeU8(msg::RequestControl, m_cfg.authority));
    if (!r->timeoutQueried) {
        r->timeoutQueried = true;
        send(r->snap.mobilityComponent, encodeEmpty(msg::QueryTimeout));
    }
    return true;
}

bool JausCore::releaseControl(std::uint16_t ss) {
    Remote* r = find(ss);
    if (!r || !r->snap.mobilityComponent.subsystem)
        return refuse(ss, "subsystem " + std::to_string(ss) + " is unknown");
    if (r->driveActive)
        stopDriving(ss);
    // Zero drive commands go out before the release in the same tick order.
    for (int i = 0; i < 2 && r->snap.controlledByUs; ++i)
        sendDrive(*r, true);
    r->stopRepeatsLeft = 0;
    r->snap.driving = false;
    r->wantControl = false;
    r->releasing = r->snap.controlledByUs;
    if (!r->releasing && r->snap.access == AccessState::ControlAccepted)
        r->snap.access = AccessState::ControlReleased;
    send(r->snap.mobilityComponent, encodeEmpty(msg::ReleaseControl));
    return true;
}

void JausCore::releaseAll() {
    for (auto& [ss, r] : m_remotes)
        if (r.wantControl || r.snap.controlledByUs)
            releaseControl(ss);
}

bool JausCore::setEmergency(std::uint16_t ss, EmergencyCode code) {
    // Allowed for every role, the monitor included: an E-stop must never be refused by the console.
    Remote* r = find(ss);
    if (!r)
        return refuse(ss, "subsystem " + std::to_string(ss) + " is unknown");
    const JausId target =
        r->snap.mobilityComponent.subsystem ? r->snap.mobilityComponent : JausId{ss, 0xFF, 0xFF};
    r->emergencyCode = code;
    r->driveActive = false;
    r->stopRepeatsLeft = 0;
    r->snap.driving = false;
    // SetEmergency goes to the Core Mobility Component at safety-critical priority (AEP-4818 §4.5.2.1.1);
    // repeated until ReportStatus shows EMERGENCY (see tickRemote).
    send(target, encodeU16(msg::SetEmergency, std::uint16_t(code)), SendOptions{Priority::Safety, false});
    send(target, encodeEmpty(msg::QueryStatus));
    r->emergencyRetries = 5;
    r->lastEmergencySent = m_clock.now();
    return true;
}

bool JausCore::clearEmergency(std::uint16_t ss) {
    if (m_cfg.role == Role::Monitor)
        return refuse(ss, "the monitor role may not clear an emergency");
    Remote* r = find(ss);
    if (!r || !r->snap.mobilityComponent.subsystem)
        return refuse(ss, "subsystem " + std::to_string(ss) + " is unknown");
    r->emergencyRetries = 0;
    send(r->snap.mobilityComponent, encodeU16(msg::ClearEmergency, std::uint16_t(r->emergencyCode)),
         SendOptions{Priority::Safety, false});
    send(r->snap.mobilityComponent, encodeEmpty(msg::QueryStatus));
    return true;
}

bool JausCore::management(std::uint16_t ss, std::uint16_t id, const char* what) {
    if (!m_cfg.mayControl())
        return refuse(ss, std::string("the monitor role may not ") + what);
    Remote* r = find(ss);
    if (!r || !r->snap.mobilityComponent.subsystem)
        return refuse(ss, "subsystem " + std::to_string(ss) + " is unknown");
    if (!r->snap.controlledByUs)
        return refuse(ss, std::string(what) + " needs control of " + r->snap.callSign);
    send(r->snap.mobilityComponent, encodeEmpty(id));
    send(r->snap.mobilityComponent, encodeEmpty(msg::QueryStatus));
    return true;
}

bool JausCore::startDriving(std::uint16_t ss) {
    if (!m_cfg.mayControl())
        return refuse(ss, "the monitor role may not drive");
    Remote* r = find(ss);
    if (!r || !r->snap.controlledByUs)
        return refuse(ss, "driving needs control of subsystem " + std::to_string(ss));
    if (r->snap.emergency)
        return refuse(ss, r->snap.callSign + " is in EMERGENCY");
    // Drivers obey only in READY (AEP-4818 §4.2.2, §9 item 18).
    if (r->snap.management != ManagementState::Ready) {
        send(r->snap.mobilityComponent, encodeEmpty(msg::Resume));
        send(r->snap.mobilityComponent, encodeEmpty(msg::QueryStatus));
    }
    r->driveActive = true;
    r->stopRepeatsLeft = 0;
    r->drive = DriveCommand{};
    r->drive.mode = m_cfg.velocityDrive ? DriveCommand::Mode::Velocity : DriveCommand::Mode::Wrench;
    r->snap.driving = true;
    r->lastDriveSent = TimePoint{};
    r->lastDriveUpdate = m_clock.now();
    r->driveStale = false;
    changed(*r);
    return true;
}

bool JausCore::setDriveCommand(std::uint16_t ss, DriveCommand c) {
    Remote* r = find(ss);
    if (!r || !r->driveActive)
        return refuse(ss, "no drive session open for subsystem " + std::to_string(ss));
    // Clamp to the platform specifications (AEP-4818 §7.2, §9 item 24).
    if (c.mode == DriveCommand::Mode::Wrench) {
        c.linear = std::clamp(c.linear, -100.0, 100.0);
        c.angular = std::clamp(c.angular, -100.0, 100.0);
        c.brake = std::clamp(c.brake, 0.0, 100.0);
    } else if (r->snap.platform) {
        auto& p = *r->snap.platform;
        if (p.maxForwardSpeed)
            c.linear = std::min(c.linear, *p.maxForwardSpeed);
        if (p.maxReverseSpeed)
            c.linear = std::max(c.linear, -*p.maxReverseSpeed);
        if (p.maxRotationalSpeed)
            c.angular = std::clamp(c.angular, -*p.maxRotationalSpeed, *p.maxRotationalSpeed);
    }
    const bool changed = c.mode != r->drive.mode || c.linear != r->drive.linear ||
                         c.angular != r->drive.angular || c.brake != r->drive.brake || r->driveStale;
    r->drive = c;
    r->lastDriveUpdate = m_clock.now();
    r->driveStale = false;
    // A new demand goes out at once (teleop latency); the periodic stream repeats it.
    if (changed && r->snap.mobilityComponent.subsystem)
        sendDrive(*r, false);
    return true;
}

bool JausCore::stopDriving(std::uint16_t ss) {
    Remote* r = find(ss);
    if (!r)
        return refuse(ss, "subsystem " + std::to_string(ss) + " is unknown");
    r->driveActive = false;
    // Several zero commands, never a single message (AEP-4818 §9 item 21).
    r->stopRepeatsLeft = r->snap.controlledByUs ? m_cfg.stopRepeats : 0;
    r->drive.linear = r->drive.angular = 0;
    if (r->stopRepeatsLeft > 0) {
        sendDrive(*r, true);
        --r->stopRepeatsLeft;
    }
    r->snap.driving = r->stopRepeatsLeft > 0;
    changed(*r);
    return true;
}

void JausCore::sendDrive(Remote& r, bool zero) {
    r.lastDriveSent = m_clock.now();
    const DriveCommand c = r.drive;
    if (c.mode == DriveCommand::Mode::Velocity) {
        VelocityCommand v;
        v.vx = zero ? 0.0 : c.linear;
        v.yawRate = zero ? 0.0 : c.angular;
        send(r.snap.mobilityComponent, encodeVelocityCommand(msg::SetVelocityCommand, v));
    } else {
        WrenchEffort w;
        w.propLinX = zero ? 0.0 : c.linear;
        w.propRotZ = zero ? 0.0 : c.angular;
        w.resLinX = zero ? 0.0 : c.brake;
        send(r.snap.mobilityComponent, encodeWrench(msg::SetWrenchEffort, w));
    }
    m_counters.add("tx.drive");
}

Duration JausCore::reRequestPeriod(const Remote& r) const {
    const double timeout = r.snap.accessTimeoutS > 0 ? r.snap.accessTimeoutS : m_cfg.accessTimeoutS;
    // Re-request well inside the timeout (AEP-4818 §4.3.4): 40 % of it, i.e. at most half.
    return secondsD(timeout * 0.4);
}

// ---- timers
// -------------------------------------------------------------------------------------------------

void JausCore::tick() {
    const TimePoint now = m_clock.now();
    if (!m_started || now - m_lastDiscovery >= secondsD(m_cfg.discoveryIntervalS)) {
        m_started = true;
        discoverNow();
    }
    for (auto& [ss, r] : m_remotes)
        tickRemote(r, now);
}

void JausCore::tickRemote(Remote& r, TimePoint now) {
    // Liveness: any message counts; down after linkLostS (AEP-4818 §9 item 9).
    const Duration age = now - r.lastHeard;
    const Duration lost = secondsD(m_cfg.linkLostS);
    const Duration degraded = std::min(secondsD(2.5 / m_cfg.heartbeatRateHz), lost / 2);
    LinkState link = age > lost ? LinkState::Down : age > degraded ? LinkState::Degraded : LinkState::Up;
    if (link != r.snap.link) {
        r.snap.link = link;
        if (link == LinkState::Down)
            notify(Severity::Error, EventKind::LinkLost, r.snap.subsystem,
                   "link to " + r.snap.callSign + " (" + std::to_string(r.snap.subsystem) + ") lost");
        changed(r);
    }
    const bool reachable = link != LinkState::Down;

    if (r.snap.callSign.empty() && now - r.lastIdentQuery > std::chrono::seconds(1)) {
        r.lastIdentQuery = now;
        send(r.platformManager, encode(QueryIdentification{IdQueryType::Subsystem}));
    }
    if (!r.servicesKnown && reachable && now - r.lastServicesQuery > std::chrono::seconds(1)) {
        r.lastServicesQuery = now;
        send(r.platformManager, encode(QueryServices{}));
    }
    if (!r.servicesKnown)
        return;
    // Re-check the platform manager every discovery interval (AEP-4818 §6.2.2.2.2.1).
    if (now - r.lastRecheck > secondsD(m_cfg.discoveryIntervalS)) {
        r.lastRecheck = now;
        send(r.platformManager, encode(QueryServices{}));
    }
    if (reachable && !r.snap.platform && r.platformSpecs.subsystem &&
        now - r.lastSpecsQuery > std::chrono::seconds(2)) {
        r.lastSpecsQuery = now;
        send(r.platformSpecs, encodeEmpty(msg::QueryPlatformSpecifications));
    }
    if (reachable) {
        for (auto& [k, s] : r.subs) {
            switch (s.state) {
            case SubState::None: {
                s.requestId = m_nextRequestId++;
                if (m_nextRequestId == 0)
                    m_nextRequestId = 1;
                s.state = SubState::Pending;
                s.sent = now;
                send(s.target, encode(CreateEvent{s.requestId, s.type,
                                                  s.type == EventType::Periodic ? s.rateHz : 0.0, s.query}));
                break;
            }
            case SubState::Pending:
                if (now - s.sent > secondsD(m_cfg.eventConfirmTimeoutS)) {
                    s.state = SubState::Polling;
                    m_counters.add("events.fallback.timeout");
                }
                break;
            case SubState::Polling:
                if (now - s.lastPoll >= periodOf(s.rateHz)) {
                    s.lastPoll = now;
                    send(s.target, s.query);
                }
                break;
            case SubState::Active:
                break;
            }
        }
    }
    const JausId mob = r.snap.mobilityComponent;
    if (mob.subsystem && reachable && now - r.lastStatusPoll >= periodOf(m_cfg.statusPollHz)) {
        r.lastStatusPoll = now;
        send(mob, encodeEmpty(msg::QueryStatus));
        send(mob, encodeEmpty(msg::QueryControl));
    }
    if (r.healthMonitor.subsystem && reachable && now - r.lastHealthPoll >= std::chrono::seconds(5)) {
        r.lastHealthPoll = now;
        send(r.healthMonitor, encodeEmpty(msg::QueryHealthSummary));
    }
    // Access control: keep re-requesting inside the timeout; notice silence.
    if (r.wantControl && mob.subsystem) {
        const Duration period = r.snap.controlledByUs ? reRequestPeriod(r) : std::chrono::seconds(1);
        if (now - r.lastRequest >= period) {
            r.lastRequest = now;
            send(mob, encodeU8(msg::RequestControl, m_cfg.authority));
        }
        const double timeout = r.snap.accessTimeoutS > 0 ? r.snap.accessTimeoutS : m_cfg.accessTimeoutS;
        if (r.snap.controlledByUs && now - r.lastConfirm > secondsD(timeout)) {
            r.wantControl = false;
            r.snap.controlledByUs = false;
            r.driveActive = false;
            r.snap.driving = false;
            r.snap.access = AccessState::Timeout;
            notify(Severity::Warning, EventKind::ControlLost, r.snap.subsystem,
                   "control of " + r.snap.callSign +
                       " lost: no confirmation within the access-control timeout");
            changed(r);
        }
    }
    if (r.classifyLoss && now > r.classifyDeadline)
        classify(r, ReportControl{});
    if (r.emergencyRetries > 0 && now - r.lastEmergencySent >= std::chrono::milliseconds(200)) {
        --r.emergencyRetries;
        r.lastEmergencySent = now;
        const JausId target = mob.subsystem ? mob : JausId{r.snap.subsystem, 0xFF, 0xFF};
        send(target, encodeU16(msg::SetEmergency, std::uint16_t(r.emergencyCode)),
             SendOptions{Priority::Safety, false});
        send(target, encodeEmpty(msg::QueryStatus));
    }
    // Drive command watchdog: the stream carries the console's demand only while the console refreshes it.
    if (r.driveActive && !r.driveStale && m_cfg.driveCommandTimeoutS > 0 &&
        now - r.lastDriveUpdate > secondsD(m_cfg.driveCommandTimeoutS) &&
        (r.drive.linear != 0 || r.drive.angular != 0)) {
        r.driveStale = true;
        r.drive.linear = r.drive.angular = 0;
        notify(Severity::Warning, EventKind::CommandRefused, r.snap.subsystem,
               "drive demand for " + r.snap.callSign + " not refreshed within " +
                   std::to_string(m_cfg.driveCommandTimeoutS) + " s: streaming zero");
    }
    if ((r.driveActive || r.stopRepeatsLeft > 0) && now - r.lastDriveSent >= periodOf(m_cfg.driveRateHz)) {
        if (r.driveActive) {
            sendDrive(r, false);
        } else {
            sendDrive(r, true);
            if (--r.stopRepeatsLeft == 0) {
                r.snap.driving = false;
                changed(r);
            }
        }
    }
}

} // namespace ocu::jaus
