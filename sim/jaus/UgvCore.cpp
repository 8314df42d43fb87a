#include "sim/jaus/UgvCore.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "protocols/common/Log.h"

namespace ocu::sim {

using namespace ocu::jaus;

namespace {

constexpr const char* kLog = "ocu.sim.jaus";
Duration secondsD(double s) {
    return std::chrono::duration_cast<Duration>(std::chrono::duration<double>(s));
}
double seconds(Duration d) {
    return std::chrono::duration<double>(d).count();
}
double wrapAngle(double a) {
    while (a > std::numbers::pi)
        a -= 2 * std::numbers::pi;
    while (a < -std::numbers::pi)
        a += 2 * std::numbers::pi;
    return a;
}
double approach(double cur, double target, double maxStep) {
    if (target > cur)
        return std::min(target, cur + maxStep);
    return std::max(target, cur - maxStep);
}

} // namespace

UgvCore::UgvCore(SimulatedUgvConfig config, JausOutput& output, const Clock& clock, Counters& counters)
    : m_cfg(std::move(config)), m_out(output), m_clock(clock), m_counters(counters), m_geo(m_cfg.origin),
      m_video(
          m_cfg.subsystemId, m_cfg.cameras,
          [this](const JausId& from, const JausId& to, const Bytes& b) { send(from, to, b); }, clock,
          counters) {
    m_s.x = m_cfg.startX;
    m_s.y = m_cfg.startY;
    m_s.yaw = m_cfg.startYaw;
}

bool UgvCore::isLocal(const JausId& id) const {
    return id == platformManager() || id == mobility() || id == sensors() || m_video.isLocal(id);
}

void UgvCore::send(const JausId& from, const JausId& to, const Bytes& payload, Priority prio) {
    m_counters.add("tx.messages");
    m_out.sendFrom(from, to, payload, SendOptions{prio, false});
}

std::vector<ServiceRecord> UgvCore::servicesOf(const JausId& c) const {
    std::vector<ServiceRecord> s{{"urn:jaus:jss:core:Transport", 1, 1},
                                 {"urn:jaus:jss:core:Events", 1, 1},
                                 {"urn:jaus:jss:core:Liveness", 1, 1}};
    if (c == platformManager()) {
        s.push_back({"urn:jaus:jss:core:Discovery", 1, 1});
        s.push_back({"urn:jaus:jss:exp:aeodrs:HealthMonitor", 1, 4});
        s.push_back({"urn:jaus:jss:iop:UnsolicitedHeartbeat", 1, 1});
        for (const ServiceRecord& v : m_video.platformManagerServices())
            s.push_back(v);
    } else if (c == mobility()) {
        s.push_back({"urn:jaus:jss:core:AccessControl", 1, 1});
        s.push_back({"urn:jaus:jss:core:Management", 1, 1});
        s.push_back({"urn:jaus:jss:mobility:PrimitiveDriver", 1, 1});
        s.push_back({"urn:jaus:jss:mobility:VelocityStateDriver", 1, 1});
        s.push_back({"urn:jaus:jss:ugv:PlatformSpecifications", 1, 0});
    } else if (c == sensors()) {
        s.push_back({"urn:jaus:jss:mobility:GlobalPoseSensor", 1, 1});
        s.push_back({"urn:jaus:jss:mobility:LocalPoseSensor", 1, 1});
        s.push_back({"urn:jaus:jss:mobility:VelocityStateSensor", 1, 1});
    }
    return s;
}

bool UgvCore::serves(const JausId& c, std::uint16_t id) const {
    switch (id) {
    case msg::QueryHeartbeatPulse:
    case msg::CreateEvent:
    case msg::UpdateEvent:
    case msg::CancelEvent:
    case msg::QueryEvents:
        return true;
    case msg::QueryIdentification:
    case msg::QueryServices:
    case msg::QueryServiceList:
    case msg::QuerySubsystemList:
    case msg::RegisterServices:
    case msg::QueryHealthSummary:
    case msg::UpdateHealthSummary:
        return c == platformManager();
    case msg::RequestControl:
    case msg::ReleaseControl:
    case msg::QueryControl:
    case msg::QueryAuthority:
    case msg::SetAuthority:
    case msg::QueryTimeout:
    case msg::QueryStatus:
    case msg::Shutdown:
    case msg::Standby:
    case msg::Resume:
    case msg::Reset:
    case msg::SetEmergency:
    case msg::ClearEmergency:
    case msg::SetWrenchEffort:
    case msg::QueryWrenchEffort:
    case msg::SetVelocityCommand:
    case msg::QueryVelocityCommand:
    case msg::QueryPlatformSpecifications:
        return c == mobility();
    case msg::QueryGlobalPose:
    case msg::QueryLocalPose:
    case msg::QueryVelocityState:
        return c == sensors();
    default:
        return false;
    }
}

GlobalPose UgvCore::globalPose() const {
    // Local x north, y east -> ENU (e = y, n = x).
    GeoPoint g = m_geo.toGeodetic(EnuPoint{m_s.y, m_s.x, 0});
    GlobalPose p;
    p.lat = g.lat;
    p.lon = g.lon;
    p.alt = g.alt;
    p.positionRms = 0.05;
    p.roll = 0.0;
    p.pitch = 0.0;
    p.yaw = wrapAngle(m_s.yaw);
    p.attitudeRms = 0.01;
    return p;
}

// ---- messages
// ------------------------------------------------------------------------------------------------

void UgvCore::handle(const JausId& src, const JausId& dst, ByteSpan payload) {
    if (isLocal(src))
        return; // our own broadcast looped back
    const std::uint16_t id = peekMessageId(payload);
    m_counters.add("rx.messages");
    bool any = false;
    for (const JausId& c : {platformManager(), mobility(), sensors()}) {
        if (!dst.matches(c))
            continue;
        if (c == platformManager() && m_video.handle(c, src, id, payload)) {
            any = true; // Digital Resource Discovery
            continue;
        }
        if (!serves(c, id))
            continue;
        // Subsystem-level identification is answered once, by the platform manager (AEP-4818 §6.2.2.2.1.1).
        any = true;
        handleAt(c, src, dst, id, payload);
    }
    for (const JausId& c : {m_video.camera(), m_video.panTiltUnit()})
        if (dst.matches(c) && m_video.handle(c, src, id, payload))
            any = true;
    if (!any)
        m_counters.add("rx.ignored");
}

std::optional<Bytes> UgvCore::report(const JausId& c, ByteSpan q) {
    const std::uint16_t id = peekMessageId(q);
    switch (id) {
    case msg::QueryHeartbeatPulse:
        return encodeEmpty(msg::ReportHeartbeatPulse);
    case msg::QueryStatus:
        return encode(ReportStatus{m_s.management, 0});
    case msg::QueryControl:
        return encode(ReportControl{m_s.controller, m_s.controllerAuthority});
    case msg::QueryAuthority:
        return encodeU8(msg::ReportAuthority,
                        m_s.controller.subsystem ? m_s.controllerAuthority : m_cfg.defaultAuthority);
    case msg::QueryTimeout:
        return encodeU8(msg::ReportTimeout, std::uint8_t(std::lround(m_cfg.accessTimeoutS)));
    case msg::QueryGlobalPose: {
        auto pv = decodeQueryPv16(q, id);
        GlobalPose p = globalPose();
        const std::uint16_t mask = pv ? *pv : 0xFFFF;
        if (!(mask & 1))
            p.lat.reset();
        if (!(mask & 2))
            p.lon.reset();
        if (!(mask & 4))
            p.alt.reset();
        if (!(mask & 8))
            p.positionRms.reset();
        if (!(mask & 16))
            p.roll.reset();
        if (!(mask & 32))
            p.pitch.reset();
        if (!(mask & 64))
            p.yaw.reset();
        if (!(mask & 128))
            p.attitudeRms.reset();
        return encode(p);
    }
    case msg::QueryLocalPose: {
        auto pv = decodeQueryPv16(q, id);
        const std::uint16_t mask = pv ? *pv : 0xFFFF;
        LocalPose p;
        if (mask & 1)
            p.x = m_s.x;
        if (mask & 2)
            p.y = m_s.y;
        if (mask & 4)
            p.z = 0.0;
        if (mask & 64)
            p.yaw = wrapAngle(m_s.yaw);
        return encode(p);
    }
    case msg::QueryVelocityState: {
        auto pv = decodeQueryPv16(q, id);
        const std::uint16_t mask = pv ? *pv : 0xFFFF;
        VelocityState v;
        if (mask & 1)
            v.vx = m_s.v;
        if (mask & 2)
            v.vy = 0.0;
        if (mask & 64)
            v.yawRate = m_s.w;
        return encode(v);
    }
    case msg::QueryWrenchEffort:
        return encodeWrench(msg::ReportWrenchEffort, m_wrench); // echoes the command (AEP-4818 §7.7.2)
    case msg::QueryVelocityCommand: {
        VelocityCommand v = m_velCmd;
        if (q.size() >= 4 && q[3] == 1) { // maximum limits in force
            v = VelocityCommand{};
            v.commandType = 1;
            v.vx = m_cfg.maxForwardSpeed;
            v.yawRate = m_cfg.maxYawRate;
        }
        return encodeVelocityCommand(msg::ReportVelocityCommand, v);
    }
    case msg::QueryPlatformSpecifications: {
        PlatformSpecifications s;
        s.steeringType = m_cfg.kinematics == Kinematics::SkidSteer ? 0 : 1;
        if (s.steeringType == 0) {
            s.trackSeparation = m_cfg.trackWidth;
            s.driveWheelRadius = m_cfg.wheelRadius;
        } else {
            s.minTurnRadius = m_cfg.minTurnRadius;
            s.wheelSeparation = m_cfg.trackWidth;
            s.ackDriveWheelRadius = m_cfg.wheelRadius;
            s.steeringAngleRange = std::atan(m_cfg.wheelBase / m_cfg.minTurnRadius);
        }
        s.maxForwardSpeed = m_cfg.maxForwardSpeed;
        s.maxReverseSpeed = m_cfg.maxReverseSpeed;
        s.maxRotationalSpeed = m_cfg.maxYawRate;
        s.maxForwardAccel = m_cfg.maxAccel;
        s.maxReverseAccel = m_cfg.maxAccel;
        s.maxForwardDecel = m_cfg.maxAccel;
        s.maxReverseDecel = m_cfg.maxAccel;
        s.name =
            "OCU-SIM " + std::string(m_cfg.kinematics == Kinematics::SkidSteer ? "SkidSteer" : "Ackermann");
        s.front = m_cfg.length / 2;
        s.back = m_cfg.length / 2;
        s.left = m_cfg.width / 2;
        s.right = m_cfg.width / 2;
        s.bottom = 0.0;
        s.top = m_cfg.height;
        return encode(s);
    }
    case msg::QueryHealthSummary: {
        // Node severity 3 for Emergency, 4 for Failure (AEP-4818 §6.2.2.2.1.3).
        std::uint8_t sev = m_s.management == ManagementState::Emergency ? 3
                           : m_s.management == ManagementState::Failure ? 4
                                                                        : 0;
        return encode(HealthSummary{sev, {{1, 0}, {3, sev}}});
    }
    case msg::QueryEvents: {
        ReportEvents re;
        for (auto& [k, e] : m_events)
            if (e.component == c)
                re.events.push_back({e.type, e.eventId, e.query});
        return encode(re);
    }
    default:
        return std::nullopt;
    }
}

void UgvCore::createEvent(const JausId& comp, const JausId& src, const CreateEvent& ce) {
    RejectEventRequest rej;
    rej.requestId = ce.requestId;
    if (m_cfg.faults.rejectEvents) {
        rej.responseCode = ce.type == EventType::Periodic ? 1 : 2;
        send(comp, src, encode(rej));
        return;
    }
    const std::uint16_t qid = peekMessageId(ce.queryMessage);
    if (!serves(comp, qid) || !report(comp, ce.queryMessage)) {
        rej.responseCode = 5;
        send(comp, src, encode(rej));
        return;
    }
    if (ce.type == EventType::Periodic && ce.rateHz <= 0) {
        rej.responseCode = 4;
        send(comp, src, encode(rej));
        return;
    }
    EventSub e;
    e.eventId = m_nextEventId++;
    if (m_nextEventId == 0)
        m_nextEventId = 1;
    e.requestId = ce.requestId;
    e.requester = src;
    e.component = comp;
    e.type = ce.type;
    e.rateHz = ce.type == EventType::Periodic ? std::min(ce.rateHz, 100.0) * m_cfg.faults.eventRateScale : 0;
    e.query = ce.queryMessage;
    m_events[e.eventId] = e;
    send(comp, src, encode(ConfirmEventRequest{ce.requestId, e.eventId, e.rateHz}));
}

void UgvCore::handleAt(const JausId& c, const JausId& src, const JausId& dst, std::uint16_t id, ByteSpan p) {
    const TimePoint now = m_clock.now();
    auto bad = [&](const std::string& err) {
        m_counters.add("rx.rejected." + rejectReason(err));
        logWarning(kLog, m_cfg.callSign + ": " + err);
    };
    switch (id) {
    case msg::QueryIdentification: {
        if (m_cfg.faults.loseDiscovery)
            return;
        auto q = decodeQueryIdentification(p);
        if (!q)
            return bad(q.error());
        if (q->type == IdQueryType::System)
            return;
        // Subsystem/node identification carry the call sign (AEP-4818 §10 item 5).
        IdType t = q->type == IdQueryType::Subsystem ? IdType::Vehicle
                   : q->type == IdQueryType::Node    ? IdType::Node
                                                     : IdType::Component;
        send(c, src, encode(ReportIdentification{q->type, t, m_cfg.callSign}));
        return;
    }
    case msg::QueryServices:
    case msg::QueryServiceList: {
        if (m_cfg.faults.loseDiscovery)
            return;
        std::vector<NodeServices> nodes{{1, {{1, 0, servicesOf(platformManager())}}},
                                        {3, {{1, 0, servicesOf(mobility())}, {2, 0, servicesOf(sensors())}}}};
        if (auto n4 = m_video.node4(); !n4.empty())
            nodes.push_back({4, std::move(n4)});
        if (id == msg::QueryServices)
            send(c, src, encode(ReportServices{nodes}));
        else
            send(c, src, encode(ReportServiceList{{{m_cfg.subsystemId, nodes}}}));
        return;
    }
    case msg::QuerySubsystemList:
        send(c, src, encode(ReportSubsystemList{{platformManager()}}));
        return;
    case msg::RegisterServices:
        return; // accepted; payload registration is not simulated
    case msg::UpdateHealthSummary:
        return;
    case msg::CreateEvent: {
        auto ce = decodeCreateEvent(p);
        if (!ce)
            return bad(ce.error());
        createEvent(c, src, *ce);
        return;
    }
    case msg::UpdateEvent: {
        auto ue = decodeUpdateEvent(p);
        if (!ue)
            return bad(ue.error());
        auto it = m_events.find(ue->eventId);
        if (it == m_events.end() || !(it->second.requester == src)) {
            RejectEventRequest rej;
            rej.requestId = ue->requestId;
            rej.responseCode = 6;
            send(c, src, encode(rej));
            return;
        }
        it->second.type = ue->type;
        it->second.rateHz = std::min(ue->rateHz, 100.0) * m_cfg.faults.eventRateScale;
        it->second.query = ue->queryMessage;
        it->second.requestId = ue->requestId;
        send(c, src, encode(ConfirmEventRequest{ue->requestId, ue->eventId, it->second.rateHz}));
        return;
    }
    case msg::CancelEvent: {
        auto ce = decodeCancelEvent(p);
        if (!ce)
            return bad(ce.error());
        auto it = m_events.find(ce->eventId);
        if (it == m_events.end()) {
            RejectEventRequest rej;
            rej.requestId = ce->requestId;
            rej.responseCode = 6;
            send(c, src, encode(rej));
            return;
        }
        m_events.erase(it);
        send(c, src, encode(ConfirmEventRequest{ce->requestId, ce->eventId, 0}));
        return;
    }
    // ---- access control (AS5710A AccessControl, AEP-4818 §4.3) ----
    case msg::RequestControl: {
        auto a = decodeU8(p, id);
        if (!a)
            return bad(a.error());
        accessRequest(src, *a);
        return;
    }
    case msg::ReleaseControl:
        if (isController(src)) {
            releaseController(RejectControlCode::Released);
        } else {
            send(c, src, encodeU8(msg::RejectControl, std::uint8_t(RejectControlCode::NotAvailable)));
        }
        return;
    case msg::SetAuthority: {
        auto a = decodeU8(p, id);
        if (!a)
            return bad(a.error());
        if (isController(src) && *a >= m_cfg.defaultAuthority)
            m_s.controllerAuthority = *a;
        return;
    }
    // ---- management ----
    case msg::SetEmergency: {
        auto code = decodeU16(p, id);
        if (!code)
            return bad(code.error());
        // Any client may stop the vehicle (codes 0 from JTS, 1 STOP, 2 SAFETY all accepted).
        enterEmergency();
        return;
    }
    case msg::ClearEmergency: {
        if (m_s.management == ManagementState::Emergency) {
            m_s.management = m_beforeEmergency == ManagementState::Emergency ? ManagementState::Standby
                                                                             : m_beforeEmergency;
            logInfo(kLog, m_cfg.callSign + ": emergency cleared");
        }
        return;
    }
    case msg::Shutdown:
    case msg::Standby:
    case msg::Resume:
    case msg::Reset: {
        if (!isController(src)) {
            m_counters.add("rx.refused.not_controller");
            return;
        }
        auto& m = m_s.management;
        if (m == ManagementState::Emergency || m == ManagementState::Failure) {
            if (id == msg::Reset && m == ManagementState::Failure)
                m = ManagementState::Standby;
            return;
        }
        if (id == msg::Resume && m != ManagementState::Shutdown)
            m = ManagementState::Ready;
        else if (id == msg::Standby && m != ManagementState::Shutdown)
            m = ManagementState::Standby;
        else if (id == msg::Shutdown)
            m = ManagementState::Shutdown;
        else if (id == msg::Reset)
            m = ManagementState::Standby;
        return;
    }
    // ---- driving ----
    case msg::SetWrenchEffort: {
        if (!isController(src)) {
            m_counters.add("rx.refused.not_controller");
            return;
        }
        auto w = decodeWrench(p, id);
        if (!w)
            return bad(w.error());
        m_wrench = *w;
        m_velocityMode = false;
        // One scaled-integer step around zero is zero (0 % encodes as 0x8000 = +0.0015 %).
        auto dead = [](double pct) { return std::abs(pct) < 0.01 ? 0.0 : pct; };
        const double lin = dead(w->propLinX.value_or(0)) / 100.0;
        m_cmdV = lin >= 0 ? lin * m_cfg.maxForwardSpeed : lin * m_cfg.maxReverseSpeed;
        m_cmdW = dead(w->propRotZ.value_or(0)) / 100.0 * m_cfg.maxYawRate;
        m_brake = dead(w->resLinX.value_or(0)) / 100.0;
        driveMessage(now);
        return;
    }
    case msg::SetVelocityCommand: {
        if (!isController(src)) {
            m_counters.add("rx.refused.not_controller");
            return;
        }
        auto v = decodeVelocityCommand(p, id);
        if (!v)
            return bad(v.error());
        if (v->commandType != 0)
            return; // limits (type 1-3) are fixed to the platform specification in the simulator
        m_velCmd = *v;
        m_velocityMode = true;
        m_cmdV = std::clamp(v->vx.value_or(0), -m_cfg.maxReverseSpeed, m_cfg.maxForwardSpeed);
        m_cmdW = std::clamp(v->yawRate.value_or(0), -m_cfg.maxYawRate, m_cfg.maxYawRate);
        m_brake = 0;
        driveMessage(now);
        return;
    }
    default: {
        // Queries.
        if (auto r = report(c, p))
            send(c, src, *r);
        return;
    }
    }
    (void)dst;
}

void UgvCore::accessRequest(const JausId& src, std::uint8_t authority) {
    const JausId me = mobility();
    const TimePoint now = m_clock.now();
    // The current controller keeps control through an emergency (its re-requests are confirmed);
    // nobody new takes over a vehicle in emergency.
    const bool emergency = m_s.management == ManagementState::Emergency;
    if (m_cfg.faults.rejectControl || (emergency && !isController(src))) {
        send(me, src, encodeU8(msg::ConfirmControl, std::uint8_t(ConfirmControlCode::NotAvailable)));
        return;
    }
    if (authority < m_cfg.defaultAuthority) {
        send(me, src, encodeU8(msg::ConfirmControl, std::uint8_t(ConfirmControlCode::InsufficientAuthority)));
        return;
    }
    if (m_s.controller.subsystem == 0) {
        m_s.controller = src;
        m_s.controllerAuthority = authority;
        m_lastRequest = now;
        send(me, src, encodeU8(msg::ConfirmControl, std::uint8_t(ConfirmControlCode::Accepted)));
        logInfo(kLog, m_cfg.callSign + ": control granted to " + src.toString());
        return;
    }
    if (isController(src)) {
        m_s.controllerAuthority = authority;
        m_lastRequest = now; // the controller re-requests within the timeout (AEP-4818 §4.3.4)
        send(me, src, encodeU8(msg::ConfirmControl, std::uint8_t(ConfirmControlCode::Accepted)));
        return;
    }
    if (authority > m_s.controllerAuthority) {
        // Pre-emption by a higher authority: the old controller is told (RejectControl CONTROL_RELEASED).
        if (m_s.controller.subsystem != 0)
            send(me, m_s.controller, encodeU8(msg::RejectControl, std::uint8_t(RejectControlCode::Released)));
        logInfo(kLog, m_cfg.callSign + ": control pre-empted by " + src.toString());
        m_s.controller = src;
        m_s.controllerAuthority = authority;
        m_lastRequest = now;
        m_haveDrive = false;
        m_cmdV = m_cmdW = 0;
        send(me, src, encodeU8(msg::ConfirmControl, std::uint8_t(ConfirmControlCode::Accepted)));
        return;
    }
    send(me, src, encodeU8(msg::ConfirmControl, std::uint8_t(ConfirmControlCode::InsufficientAuthority)));
}

void UgvCore::releaseController(RejectControlCode code) {
    if (m_s.controller.subsystem != 0)
        send(mobility(), m_s.controller, encodeU8(msg::RejectControl, std::uint8_t(code)));
    m_s.controller = JausId{};
    m_s.controllerAuthority = 0;
    m_haveDrive = false;
    m_cmdV = m_cmdW = 0;
    // Without a controller nobody may drive: back to STANDBY.
    if (m_s.management == ManagementState::Ready)
        m_s.management = ManagementState::Standby;
}

void UgvCore::preemptControl(std::uint8_t authority) {
    if (m_s.controller.subsystem != 0)
        send(mobility(), m_s.controller,
             encodeU8(msg::RejectControl, std::uint8_t(RejectControlCode::Released)));
    m_s.controller = internalClient();
    m_s.controllerAuthority = authority;
    m_haveDrive = false;
    m_cmdV = m_cmdW = 0;
    if (m_s.management == ManagementState::Ready)
        m_s.management = ManagementState::Standby;
}

void UgvCore::forceDriveTimeout() {
    m_s.driveTimedOut = true;
    m_recoveryStart = TimePoint{};
}

void UgvCore::enterEmergency() {
    if (m_s.management != ManagementState::Emergency)
        m_beforeEmergency = m_s.management;
    m_s.management = ManagementState::Emergency;
    // Safe stop: zero motion at once, parking brake on (AEP-4818 §4.5.2).
    m_s.v = 0;
    m_s.w = 0;
    m_cmdV = m_cmdW = 0;
    logWarning(kLog, m_cfg.callSign + ": EMERGENCY");
}

void UgvCore::enterFailure() {
    m_s.management = ManagementState::Failure;
    m_s.v = m_s.w = 0;
    m_cmdV = m_cmdW = 0;
}

void UgvCore::clearFailure() {
    if (m_s.management == ManagementState::Failure)
        m_s.management = ManagementState::Standby;
}

void UgvCore::driveMessage(TimePoint now) {
    // Drive timeout recovery: commands must arrive continuously for driveRecoveryS (AEP-4818 §7.1.1).
    if (m_s.driveTimedOut) {
        const Duration maxGap = secondsD(1.0 / std::max(m_cfg.minDriveRateHz, 0.1));
        if (m_recoveryStart == TimePoint{} || now - m_lastDrive > maxGap)
            m_recoveryStart = now;
        if (now - m_recoveryStart >= secondsD(m_cfg.driveRecoveryS)) {
            m_s.driveTimedOut = false;
            logInfo(kLog, m_cfg.callSign + ": drive timeout recovered");
        }
    }
    m_lastDrive = now;
    m_haveDrive = true;
}

void UgvCore::physics(TimePoint now) {
    if (m_lastPhysics == TimePoint{}) {
        m_lastPhysics = now;
        return;
    }
    const double dt = std::min(seconds(now - m_lastPhysics), 0.5);
    m_lastPhysics = now;
    if (dt <= 0)
        return;
    if (m_cfg.driveTimeoutS > 0 && m_haveDrive && !m_s.driveTimedOut &&
        now - m_lastDrive > secondsD(m_cfg.driveTimeoutS)) {
        m_s.driveTimedOut = true;
        m_recoveryStart = TimePoint{};
        m_counters.add("drive.timeouts"); // stays counted after recovery (tests tell a stop from a timeout)
        logWarning(kLog, m_cfg.callSign + ": drive timeout");
    }
    const bool mayMove = m_s.management == ManagementState::Ready && m_s.controller.subsystem != 0 &&
                         !m_s.driveTimedOut && m_haveDrive;
    double tv = mayMove ? m_cmdV * (1.0 - m_brake) : 0.0;
    double tw = mayMove ? m_cmdW : 0.0;
    if (m_cfg.kinematics == Kinematics::Ackermann) {
        // No turning on the spot: |yaw rate| ≤ |v| / minimum turn radius.
        const double maxW = std::abs(m_s.v) / std::max(m_cfg.minTurnRadius, 0.1);
        tw = std::clamp(tw, -maxW, maxW);
    }
    if (m_s.management == ManagementState::Emergency || m_s.management == ManagementState::Failure) {
        m_s.v = m_s.w = 0;
    } else {
        m_s.v = approach(m_s.v, tv, m_cfg.maxAccel * dt);
        m_s.w = approach(m_s.w, tw, m_cfg.maxYawAccel * dt);
    }
    // + yaw rate = turn right = clockwise from above (AEP-4818 §7.7); x north, y east.
    m_s.yaw = wrapAngle(m_s.yaw + m_s.w * dt);
    m_s.x += m_s.v * std::cos(m_s.yaw) * dt;
    m_s.y += m_s.v * std::sin(m_s.yaw) * dt;
    m_s.odometer += std::abs(m_s.v) * dt;
}

void UgvCore::tick() {
    const TimePoint now = m_clock.now();
    if (!m_started) {
        m_started = true;
        m_lastHeartbeat = now - std::chrono::seconds(10);
    }
    physics(now);
    m_video.tick();
    // Access-control timeout: release a controller that stopped re-requesting (AEP-4818 §4.3.4).
    if (m_s.controller.subsystem != 0 && !(m_s.controller == internalClient()) && m_cfg.accessTimeoutS > 0 &&
        now - m_lastRequest > secondsD(m_cfg.accessTimeoutS)) {
        logInfo(kLog, m_cfg.callSign + ": access-control timeout for " + m_s.controller.toString());
        releaseController(RejectControlCode::Released);
    }
    // Unsolicited heartbeat to [SubsystemID].255.255 at ≥ 1 Hz (AEP-4818 V1.JAUS-43).
    const auto& f = m_cfg.faults;
    if (!f.dropHeartbeat && f.heartbeatRateHz > 0 &&
        now - m_lastHeartbeat >= secondsD(1.0 / f.heartbeatRateHz)) {
        m_lastHeartbeat = now;
        send(platformManager(), JausId{m_cfg.subsystemId, 0xFF, 0xFF},
             encodeEmpty(msg::ReportHeartbeatPulse));
    }
    // Events: periodic at the confirmed rate, on-change when the report differs (checked every tick).
    for (auto& [id, e] : m_events) {
        if (e.type == EventType::Periodic) {
            if (e.rateHz <= 0 || now - e.lastSent < secondsD(1.0 / e.rateHz))
                continue;
        }
        auto r = report(e.component, e.query);
        if (!r)
            continue;
        if (e.type == EventType::EveryChange && *r == e.lastReport)
            continue;
        e.lastSent = now;
        e.lastReport = *r;
        send(e.component, e.requester, encode(EventMsg{e.eventId, e.sequence++, *r}));
    }
}

} // namespace ocu::sim
