#include "protocols/jaus/clients/ManagementClient.h"

#include "protocols/jaus/clients/DriveClient.h"
#include "protocols/jaus/clients/EventsClient.h"

namespace ocu::jaus {

void ManagementClient::registerMessages(MessageTable& table) {
    table.onVehicleMessage(msg::ReportStatus, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
        onStatus(r, src, p);
    });
}

void ManagementClient::onServicesKnown(RemoteSubsystem& r) {
    // Management state on change: an emergency shows at once, not at the next poll.
    if (r.managementTarget().subsystem)
        m_events.subscribe(r, r.managementTarget(), encodeEmpty(msg::QueryStatus),
                           m_ctx.config().statusPollHz, EventType::EveryChange);
}

bool ManagementClient::command(std::uint16_t ss, std::uint16_t id, const char* what) {
    if (!m_ctx.config().mayControl())
        return m_ctx.refuse(ss, std::string("the monitor role may not ") + what, OutcomeReason::NotPermitted);
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!r || !r->managementTarget().subsystem)
        return m_ctx.refuseNoTarget(ss, "Management");
    if (!r->snap.controlledByUs)
        return m_ctx.refuse(
            ss, std::string(what) + " needs control of " + r->snap.callSign + " (request control first)",
            OutcomeReason::NotControlled);
    if (!m_ctx.send(r->managementTarget(), encodeEmpty(id)))
        return m_ctx.sendFailed(ss, what);
    m_ctx.send(r->managementTarget(), encodeEmpty(msg::QueryStatus));
    return true;
}

bool ManagementClient::sendEmergency(const JausId& target, EmergencyCode code) {
    // SetEmergency goes to the component offering Management at safety-critical priority (AEP-4818
    // §4.5.2.1.1).
    const bool sent = m_ctx.send(target, encodeU16(msg::SetEmergency, std::uint16_t(code)),
                                 SendOptions{Priority::Safety, false});
    m_ctx.send(target, encodeEmpty(msg::QueryStatus));
    return sent;
}

std::optional<JausId> ManagementClient::emergencyTarget(std::uint16_t ss) const {
    const RemoteSubsystem* r = m_ctx.find(ss);
    if (!r)
        return std::nullopt;
    // Services not known (not reported yet, reported with no components, or never learnt at all): the stop
    // still goes out, to every component of the subsystem (ss.255.255), because a stop must reach the
    // vehicle if anything can. Services known and none offers Management (directly or by inheritance):
    // nobody there would obey, so the outcome says so instead of "sent".
    JausId target = r->managementTarget();
    if (!target.subsystem) {
        if (r->components.known)
            return std::nullopt;
        target = JausId{ss, 0xFF, 0xFF};
    }
    return target;
}

bool ManagementClient::setEmergency(std::uint16_t ss, EmergencyCode code, bool alreadySent) {
    // Allowed for every role, the monitor included: an E-stop must never be refused by the console.
    const auto target = emergencyTarget(ss);
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!target || !r)
        return alreadySent ? true : m_ctx.refuseNoTarget(ss, "Management");
    State& s = m_state[ss];
    s.emergencyCode = code;
    m_drive.endSession(*r, true);
    // Repeated until ReportStatus shows EMERGENCY (see tick).
    s.emergencyRetries = 5;
    s.lastEmergencySent = m_ctx.now();
    if (alreadySent) {
        m_ctx.send(*target, encodeEmpty(msg::QueryStatus));
        return true;
    }
    if (!sendEmergency(*target, code))
        return m_ctx.sendFailed(ss, "SetEmergency");
    return true;
}

bool ManagementClient::setEmergencyUnheard(std::uint16_t ss, EmergencyCode code) {
    if (!sendEmergency(JausId{ss, 0xFF, 0xFF}, code))
        return m_ctx.sendFailed(ss, "SetEmergency");
    return true;
}

bool ManagementClient::clearEmergency(std::uint16_t ss) {
    if (!m_ctx.config().mayClearStop())
        return m_ctx.refuse(ss,
                            "this console's role (monitor, authority 0) may stop but not clear an emergency;"
                            " clear it from a console with command rights",
                            OutcomeReason::NotPermitted);
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!r || !r->managementTarget().subsystem)
        return m_ctx.refuseNoTarget(ss, "Management");
    State& s = m_state[ss];
    s.emergencyRetries = 0;
    if (!m_ctx.send(r->managementTarget(), encodeU16(msg::ClearEmergency, std::uint16_t(s.emergencyCode)),
                    SendOptions{Priority::Safety, false}))
        return m_ctx.sendFailed(ss, "ClearEmergency");
    m_ctx.send(r->managementTarget(), encodeEmpty(msg::QueryStatus));
    return true;
}

void ManagementClient::onStatus(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    if (m_other && m_other(r, src, p))
        return;
    auto m = decodeReportStatus(p);
    if (!m)
        return m_ctx.rejected(src, m.error());
    const auto old = r.snap.management;
    r.snap.management = m->status;
    const bool emergency = m->status == ManagementState::Emergency;
    if (emergency && !r.snap.emergency)
        m_ctx.notify(Severity::Error, EventKind::Emergency, r.id(), r.snap.callSign + " is in EMERGENCY");
    if (!emergency && r.snap.emergency)
        m_ctx.notify(Severity::Info, EventKind::EmergencyCleared, r.id(),
                     r.snap.callSign + " left EMERGENCY");
    r.snap.emergency = emergency;
    if (emergency)
        m_state[r.id()].emergencyRetries = 0;
    if (old != m->status)
        m_ctx.notify(m->status == ManagementState::Failure ? Severity::Error : Severity::Info,
                     EventKind::ManagementChanged, r.id(),
                     r.snap.callSign + " management " + nameFor(m->status));
    m_ctx.changed(r);
}

void ManagementClient::tick(RemoteSubsystem& r, TimePoint now) {
    const JausId mob = r.managementTarget();
    State& s = m_state[r.id()];
    if (mob.subsystem && r.reachable() && now - s.lastStatusPoll >= periodOf(m_ctx.config().statusPollHz)) {
        s.lastStatusPoll = now;
        m_ctx.send(mob, encodeEmpty(msg::QueryStatus));
    }
    if (s.emergencyRetries > 0 && now - s.lastEmergencySent >= std::chrono::milliseconds(200)) {
        --s.emergencyRetries;
        s.lastEmergencySent = now;
        sendEmergency(mob.subsystem ? mob : JausId{r.id(), 0xFF, 0xFF}, s.emergencyCode);
    }
}

} // namespace ocu::jaus
