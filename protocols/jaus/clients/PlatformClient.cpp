// Platform mode and state, illumination, odometry: discovery of the services, their reports, the commands
// with the control each needs, and the comms-lost service's presence.
#include "protocols/jaus/clients/PlatformClient.h"

#include <algorithm>
#include <string_view>

#include "protocols/jaus/clients/AccessControlClient.h"
#include "protocols/jaus/clients/EventsClient.h"

namespace ocu::jaus {

namespace {

constexpr auto kControlWait = std::chrono::seconds(5); // a command waits this long for control
constexpr auto kControlHold = std::chrono::seconds(3); // own control released after the last command
constexpr auto kRetry = std::chrono::seconds(1);
constexpr auto kCapabilityRetry = std::chrono::seconds(2);
constexpr auto kOdometryPoll = std::chrono::seconds(1);

// The last URI segment, whatever the namespace (public stacks and the AEP disagree, jaus-autonomy.md §6.1).
bool named(const ServiceRecord& s, std::string_view name) {
    const auto pos = s.uri.rfind(':');
    return pos != std::string::npos && std::string_view(s.uri).substr(pos + 1) == name;
}

} // namespace

void PlatformClient::registerMessages(MessageTable& table) {
    table.onVehicleMessage(msg::ReportPlatformMode,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
                               auto m = decodeReportPlatformMode(p);
                               if (!m)
                                   return m_ctx.rejected(src, m.error());
                               r.snap.platformServices.mode = m->mode;
                               r.snap.platformServices.modeStatus = m->status;
                               m_ctx.changed(r);
                           });
    table.onVehicleMessage(msg::ReportSupportedPlatformModes,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
                               auto m = decodeReportSupportedPlatformModes(p);
                               if (!m)
                                   return m_ctx.rejected(src, m.error());
                               r.snap.platformServices.supportedModes = m->modes;
                               m_ctx.changed(r);
                           });
    table.onVehicleMessage(msg::ReportPlatformState,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
                               auto m = decodeU8(p, msg::ReportPlatformState);
                               if (!m)
                                   return m_ctx.rejected(src, m.error());
                               PlatformServicesStatus& ps = r.snap.platformServices;
                               const bool changed = ps.state != *m;
                               const bool wasEmergency = ps.emergencyState();
                               ps.state = *m;
                               if (changed && (wasEmergency || ps.emergencyState()))
                                   m_ctx.notify(ps.emergencyState() ? Severity::Warning : Severity::Info,
                                                EventKind::ManagementChanged, r.id(),
                                                r.snap.callSign + " platform state " + platformStateName(*m));
                               m_ctx.changed(r);
                           });
    table.onVehicleMessage(
        msg::ConfirmPlatformStateRequest,
        [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) { onConfirmState(r, src, p); });
    auto lights = [this](std::uint16_t id) {
        return [this, id](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
            auto m = decodeIllumination(p, id);
            if (!m)
                return m_ctx.rejected(src, m.error());
            if (id == msg::ReportIlluminationState)
                r.snap.platformServices.lights = *m;
            else
                r.snap.platformServices.lightsSupported = illuminationStateMaskOf(*m);
            m_ctx.changed(r);
        };
    };
    table.onVehicleMessage(msg::ReportIlluminationState, lights(msg::ReportIlluminationState));
    table.onVehicleMessage(msg::ReportIlluminationConfiguration,
                           lights(msg::ReportIlluminationConfiguration));
    table.onVehicleMessage(msg::ReportOdometry, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
        onOdometry(r, src, p);
    });
}

void PlatformClient::onServicesKnown(RemoteSubsystem& r) {
    State& s = m_state[r.id()];
    PlatformServicesStatus& ps = r.snap.platformServices;
    s.mode = s.state = s.illumination = s.odometry = JausId{};
    ps.modeService = ps.stateService = ps.illuminationService = ps.odometryService = ps.commsLostService =
        OfferedService{};
    for (const NodeInfo& n : r.snap.services)
        for (const ComponentInfo& c : n.components)
            for (const ServiceRecord& svc : c.services) {
                auto pick = [&](std::string_view name, JausId* slot, OfferedService& shown) {
                    if (shown.offered || !named(svc, name))
                        return;
                    shown = OfferedService{true, svc.uri, svc.major, svc.minor};
                    if (slot)
                        *slot = JausId{r.id(), n.node, c.component};
                };
                pick("PlatformMode", &s.mode, ps.modeService);
                pick("PlatformState", &s.state, ps.stateService);
                pick("IlluminationService", &s.illumination, ps.illuminationService);
                pick("OdometryService", &s.odometry, ps.odometryService);
                pick("CommsLostPolicyManager", nullptr, ps.commsLostService);
            }
    const double hz = m_ctx.config().statusPollHz;
    if (s.mode.subsystem)
        m_events.subscribe(r, s.mode, encodeEmpty(msg::QueryPlatformMode), hz, EventType::EveryChange);
    if (s.state.subsystem)
        m_events.subscribe(r, s.state, encodeEmpty(msg::QueryPlatformState), hz, EventType::EveryChange);
    if (s.illumination.subsystem)
        m_events.subscribe(r, s.illumination, encodeEmpty(msg::QueryIlluminationState), hz,
                           EventType::EveryChange);
    m_ctx.changed(r);
}

JausId& PlatformClient::componentOf(State& s, Service service) {
    switch (service) {
    case Service::Mode:
        return s.mode;
    case Service::State:
        return s.state;
    case Service::Illumination:
        return s.illumination;
    case Service::Odometry:
        break;
    }
    return s.odometry;
}

// ---- commands -------------------------------------------------------------------------------------------

bool PlatformClient::setMode(std::uint16_t ss, std::uint8_t mode) {
    if (const RemoteSubsystem* r = m_ctx.find(ss); r && !r->snap.platformServices.supportedModes.empty()) {
        const auto& modes = r->snap.platformServices.supportedModes;
        if (std::find(modes.begin(), modes.end(), mode) == modes.end())
            return m_ctx.refuse(
                ss, r->snap.callSign + " does not support the " + platformModeName(mode) + " mode",
                OutcomeReason::NotSupported);
    }
    return command(ss, Service::Mode, encodeU8(msg::SetPlatformMode, mode),
                   encodeEmpty(msg::QueryPlatformMode), "platform mode " + platformModeName(mode));
}

bool PlatformClient::setState(std::uint16_t ss, std::uint8_t state) {
    if (state > std::uint8_t(PlatformState::RenderUseless))
        return m_ctx.refuse(ss, "platform state " + std::to_string(state) + " does not exist",
                            OutcomeReason::InvalidArgument);
    return command(ss, Service::State, encodeU8(msg::SetPlatformState, state),
                   encodeEmpty(msg::QueryPlatformState), "platform state " + platformStateName(state));
}

bool PlatformClient::setLights(std::uint16_t ss, std::uint32_t mask, std::uint32_t on) {
    if (mask == 0 || (mask & ~light::kOperatorSwitchable))
        return m_ctx.refuse(
            ss,
            "only headlights, running lights, turn signals, brake lights and the IR source may be "
            "switched from the console",
            OutcomeReason::InvalidArgument);
    const RemoteSubsystem* r = m_ctx.find(ss);
    const PlatformServicesStatus* ps = r ? &r->snap.platformServices : nullptr;
    if (ps && ps->lightsSupported && (mask & on & ~*ps->lightsSupported))
        return m_ctx.refuse(ss, r->snap.callSign + " does not have every light asked for",
                            OutcomeReason::NotSupported);
    // Every other light (VisibleLightSource included) keeps what the vehicle reports.
    const std::uint32_t base = ps && ps->lights ? *ps->lights : 0;
    const std::uint32_t bits = (base & ~mask) | (on & mask);
    return command(ss, Service::Illumination, encodeIllumination(msg::SetIlluminationState, bits),
                   encodeEmpty(msg::QueryIlluminationState), "lights");
}

bool PlatformClient::resetTrip(std::uint16_t ss) {
    return command(ss, Service::Odometry, encodeU8(msg::ResetOdometry, std::uint8_t(OdometryType::TripA)),
                   encodeU8(msg::QueryOdometry, std::uint8_t(OdometryType::TripA)), "trip odometer reset");
}

bool PlatformClient::queryOdometry(std::uint16_t ss) {
    RemoteSubsystem* r = m_ctx.find(ss);
    auto it = m_state.find(ss);
    if (!r || !r->components.known || it == m_state.end() || !it->second.odometry.subsystem)
        return m_ctx.refuseNoTarget(ss, "OdometryService");
    if (!r->reachable())
        return m_ctx.refuse(ss, r->snap.callSign + ": link down, odometry not asked for",
                            OutcomeReason::LinkDown);
    const JausId target = it->second.odometry;
    if (!m_ctx.send(target, encodeU8(msg::QueryOdometry, std::uint8_t(OdometryType::Platform))))
        return m_ctx.sendFailed(ss, "QueryOdometry");
    m_ctx.send(target, encodeU8(msg::QueryOdometry, std::uint8_t(OdometryType::TripA)));
    return true;
}

bool PlatformClient::emergencyState(std::uint16_t ss) const {
    const RemoteSubsystem* r = m_ctx.find(ss);
    return r && r->snap.platformServices.emergencyState();
}

bool PlatformClient::refuseInEmergency(std::uint16_t ss, const char* what, bool quietly) {
    if (!emergencyState(ss))
        return false;
    const std::string why = m_ctx.find(ss)->snap.callSign + " reports the emergency platform state: " + what +
                            " refused until it leaves it (AEP-4818 §6.2.6)";
    if (quietly)
        m_ctx.refuseQuietly(why);
    else
        m_ctx.refuse(ss, why);
    return true;
}

bool PlatformClient::command(std::uint16_t ss, Service service, Bytes payload, Bytes readBack,
                             std::string what) {
    if (!m_ctx.config().mayControl())
        return m_ctx.refuse(ss, "the monitor role may not set the " + what, OutcomeReason::NotPermitted);
    RemoteSubsystem* r = m_ctx.find(ss);
    auto it = m_state.find(ss);
    const char* serviceName = service == Service::Mode           ? "PlatformMode"
                              : service == Service::State        ? "PlatformState"
                              : service == Service::Illumination ? "IlluminationService"
                                                                 : "OdometryService";
    if (!r || !r->components.known || it == m_state.end() || !componentOf(it->second, service).subsystem)
        return m_ctx.refuseNoTarget(ss, serviceName);
    if (!r->reachable())
        return m_ctx.refuse(ss, r->snap.callSign + ": link down, " + what + " not sent",
                            OutcomeReason::LinkDown);
    State& s = it->second;
    Pending p{componentOf(s, service), std::move(payload), std::move(readBack), std::move(what), m_ctx.now()};
    if (ready(*r, s, p.target)) {
        if (!m_ctx.send(p.target, p.payload))
            return m_ctx.sendFailed(ss, serviceName);
        m_ctx.send(p.target, p.readBack);
        return true;
    }
    // Control first, as the mission client takes it: the vehicle's own control for its control target, a
    // RequestControl of our own for a component that holds access control by itself.
    if (p.target == r->controlTarget()) {
        if (!m_access.wantsControl(ss) && !m_access.requestControl(ss))
            return false;
    } else {
        Control& c = s.own[p.target.value()];
        if (c.phase == OwnControl::None) {
            c.phase = OwnControl::Requested;
            c.lastRequest = m_ctx.now();
            if (!m_ctx.send(p.target, encodeU8(msg::RequestControl, m_ctx.config().authority))) {
                c.phase = OwnControl::None;
                return m_ctx.sendFailed(ss, "RequestControl");
            }
        }
    }
    s.pending.push_back(std::move(p));
    return true;
}

bool PlatformClient::ready(const RemoteSubsystem& r, State& s, const JausId& target) {
    if (target == r.controlTarget())
        return r.snap.controlledByUs;
    auto it = s.own.find(target.value());
    if (it == s.own.end() || it->second.phase != OwnControl::Controlled)
        return false;
    it->second.lastUse = m_ctx.now();
    return true;
}

void PlatformClient::sendNow(RemoteSubsystem& r, State&, const Pending& p) {
    if (!m_ctx.send(p.target, p.payload))
        m_ctx.notify(Severity::Warning, EventKind::CommandRefused, r.id(),
                     r.snap.callSign + ": " + p.what + " not sent (" + m_ctx.lastSendError() + ")");
    else
        m_ctx.send(p.target, p.readBack);
}

// ---- reports --------------------------------------------------------------------------------------------

void PlatformClient::onConfirmState(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeConfirmPlatformStateRequest(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    PlatformServicesStatus& ps = r.snap.platformServices;
    if (m->code == std::uint8_t(PlatformStateAnswer::InvalidState)) {
        ps.stateRefusal =
            "the vehicle refused platform state " + platformStateName(m->state) + " (invalid state)";
        m_ctx.notify(Severity::Warning, EventKind::CommandRefused, r.id(),
                     r.snap.callSign + ": " + ps.stateRefusal);
    } else {
        ps.stateRefusal.clear();
    }
    m_ctx.send(src, encodeEmpty(msg::QueryPlatformState)); // the state comes from its report
    m_ctx.changed(r);
}

void PlatformClient::onOdometry(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto m = decodeReportOdometry(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    PlatformServicesStatus& ps = r.snap.platformServices;
    if (m->type == std::uint8_t(OdometryType::Platform))
        ps.odometerM = m->distanceM;
    else if (m->type == std::uint8_t(OdometryType::TripA))
        ps.tripM = m->distanceM;
    else
        return;
    m_ctx.changed(r);
}

bool PlatformClient::handleControlMessage(RemoteSubsystem& r, const JausId& src, std::uint16_t id,
                                          ByteSpan p) {
    auto it = m_state.find(r.id());
    if (it == m_state.end() || src == r.controlTarget())
        return false;
    State& s = it->second;
    auto c = s.own.find(src.value());
    if (c == s.own.end())
        return false;
    auto code = decodeU8(p, id);
    if (!code) {
        m_ctx.rejected(src, code.error());
        return true;
    }
    if (id == msg::ConfirmControl && *code == std::uint8_t(ConfirmControlCode::Accepted)) {
        if (c->second.phase == OwnControl::None) {
            m_ctx.send(src, encodeEmpty(msg::ReleaseControl)); // late: no longer wanted
            return true;
        }
        if (c->second.phase == OwnControl::Requested)
            c->second.lastUse = m_ctx.now(); // the hold counts from the first grant, not from re-requests
        c->second.phase = OwnControl::Controlled;
        c->second.lastConfirm = m_ctx.now();
        return true;
    }
    const bool refused = id == msg::ConfirmControl;
    c->second.phase = OwnControl::None;
    auto waiting = std::remove_if(s.pending.begin(), s.pending.end(), [&](const Pending& q) {
        if (!(q.target == src))
            return false;
        if (refused)
            m_ctx.notify(
                Severity::Warning, EventKind::ControlRejected, r.id(),
                r.snap.callSign + ": " + q.what + " not sent, control of " + src.toString() + " refused (" +
                    (*code == std::uint8_t(ConfirmControlCode::NotAvailable) ? "not available"
                                                                             : "insufficient authority") +
                    ")");
        return refused;
    });
    s.pending.erase(waiting, s.pending.end());
    return true;
}

// ---- timers ---------------------------------------------------------------------------------------------

void PlatformClient::tick(RemoteSubsystem& r, TimePoint now) {
    auto it = m_state.find(r.id());
    if (it == m_state.end())
        return;
    State& s = it->second;
    tickPending(r, s, now);
    tickControl(r, s, now);
    if (r.reachable())
        tickQueries(r, s, now);
}

void PlatformClient::tickPending(RemoteSubsystem& r, State& s, TimePoint now) {
    auto done = std::remove_if(s.pending.begin(), s.pending.end(), [&](const Pending& p) {
        if (ready(r, s, p.target)) {
            sendNow(r, s, p);
            return true;
        }
        if (now - p.queued < kControlWait)
            return false;
        m_ctx.notify(Severity::Warning, EventKind::CommandRefused, r.id(),
                     r.snap.callSign + ": " + p.what + " not sent, control of " + p.target.toString() +
                         " not granted within 5 s");
        return true;
    });
    s.pending.erase(done, s.pending.end());
}

void PlatformClient::tickControl(RemoteSubsystem&, State& s, TimePoint now) {
    const double timeout = m_ctx.config().accessTimeoutS;
    for (auto& [value, c] : s.own) {
        const JausId target = JausId::fromValue(value);
        const bool waitedFor = std::any_of(s.pending.begin(), s.pending.end(),
                                           [&](const Pending& p) { return p.target == target; });
        if (c.phase == OwnControl::Controlled && !waitedFor && now - c.lastUse >= kControlHold) {
            m_ctx.send(target, encodeEmpty(msg::ReleaseControl));
            c.phase = OwnControl::None;
            continue;
        }
        if (c.phase == OwnControl::Controlled && now - c.lastConfirm > secondsD(timeout)) {
            c.phase = waitedFor ? OwnControl::Requested : OwnControl::None; // the control lapsed
            continue;
        }
        // Re-request inside the access timeout while held, every second while asking.
        const Duration period =
            c.phase == OwnControl::Controlled ? secondsD(timeout * 0.4) : Duration(kRetry);
        if (c.phase != OwnControl::None && now - c.lastRequest >= period) {
            c.lastRequest = now;
            m_ctx.send(target, encodeU8(msg::RequestControl, m_ctx.config().authority));
        }
    }
}

void PlatformClient::tickQueries(RemoteSubsystem& r, State& s, TimePoint now) {
    const PlatformServicesStatus& ps = r.snap.platformServices;
    if (s.odometry.subsystem && now - s.lastOdometryPoll >= kOdometryPoll) {
        s.lastOdometryPoll = now;
        m_ctx.send(s.odometry, encodeU8(msg::QueryOdometry, std::uint8_t(OdometryType::Platform)));
        m_ctx.send(s.odometry, encodeU8(msg::QueryOdometry, std::uint8_t(OdometryType::TripA)));
    }
    const bool wantModes = s.mode.subsystem && ps.supportedModes.empty();
    const bool wantLights = s.illumination.subsystem && !ps.lightsSupported;
    if ((wantModes || wantLights) && now - s.lastCapabilityQuery >= kCapabilityRetry) {
        s.lastCapabilityQuery = now;
        if (wantModes)
            m_ctx.send(s.mode, encodeEmpty(msg::QuerySupportedPlatformModes));
        if (wantLights)
            m_ctx.send(s.illumination, encodeEmpty(msg::QueryIlluminationConfiguration));
    }
}

} // namespace ocu::jaus
