#include "protocols/jaus/JausCore.h"

#include <algorithm>
#include <set>

namespace ocu::jaus {

JausCore::JausCore(JausConfig config, JausListener& listener, JausOutput& output, const Clock& clock,
                   Counters& counters)
    : m_ctx(std::move(config), listener, output, clock, counters), m_events(m_ctx), m_drive(m_ctx),
      m_liveness(m_ctx, m_events), m_discovery(m_ctx, [this](RemoteSubsystem& r) { servicesKnown(r); }),
      m_access(m_ctx, m_drive), m_management(m_ctx, m_events, m_drive), m_pose(m_ctx, m_events),
      m_platform(m_ctx), m_health(m_ctx), m_video(m_ctx), m_mission(m_ctx, m_events, m_access),
      m_platformServices(m_ctx, m_events, m_access), m_handoff(m_ctx, m_access) {
    m_all = {&m_liveness, &m_discovery, &m_events, &m_access,  &m_management,       &m_drive,  &m_pose,
             &m_platform, &m_health,    &m_video,  &m_mission, &m_platformServices, &m_handoff};
    // Timer order within one tick: what discovery found is queried first, commands and streams last.
    m_afterDiscovery = {&m_platform, &m_events, &m_management, &m_access,           &m_health,
                        &m_drive,    &m_video,  &m_mission,    &m_platformServices, &m_handoff};
    // Pan-tilt units and a list driver on a component of its own hold their own access control: their
    // confirmations are the video and mission clients'; so is the list driver's ReportStatus. So are those
    // of a platform-services component the platform client controls itself.
    m_access.setOtherControl([this](RemoteSubsystem& r, const JausId& src, std::uint16_t id, ByteSpan p) {
        return m_video.handleControlMessage(r, src, id, p) || m_mission.handleControlMessage(r, src, id, p) ||
               m_platformServices.handleControlMessage(r, src, id, p);
    });
    m_management.setOtherStatus([this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
        return m_mission.handleStatus(r, src, p);
    });
    for (ClientService* c : m_all)
        c->registerMessages(m_table);
}

void JausCore::servicesKnown(RemoteSubsystem& r) {
    // Liveness, pose and management subscribe to their events here.
    for (ClientService* c : m_all)
        c->onServicesKnown(r);
}

std::optional<SubsystemSnapshot> JausCore::snapshot(std::uint16_t ss) const {
    const RemoteSubsystem* r = m_ctx.find(ss);
    if (!r)
        return std::nullopt;
    return r->snap;
}

std::vector<std::uint16_t> JausCore::subsystems() const {
    std::vector<std::uint16_t> out;
    for (auto& [k, v] : m_ctx.remotes())
        out.push_back(k);
    return out;
}

void JausCore::forget(std::uint16_t ss) {
    m_ctx.erase(ss);
    for (ClientService* c : m_all)
        c->forget(ss);
}

void JausCore::handle(const JausId& src, const JausId& dst, ByteSpan payload) {
    const JausId& self = m_ctx.self();
    if (src == self)
        return; // our own multicast looped back
    const std::uint16_t id = peekMessageId(payload);
    Counters& counters = m_ctx.counters();
    counters.add("rx.messages");
    if (!dst.matches(self) && id != msg::ReportHeartbeatPulse) {
        counters.add("rx.ignored.not_for_us");
        return;
    }
    // The console is a JAUS subsystem too: identification, services, heartbeat, events.
    const bool onlyForUs = m_table.answer(id, src, payload);
    if (src.subsystem == self.subsystem || src.subsystem == 0 || src.subsystem == 0xFFFF || onlyForUs)
        return;
    switch (m_discovery.classify(src, id, payload)) {
    case DiscoveryClient::Sender::NewConsole:
        forget(src.subsystem);
        return;
    case DiscoveryClient::Sender::Console:
        return; // another console: answered above, never listed as a vehicle
    case DiscoveryClient::Sender::Vehicle:
        break;
    }
    const bool firstContact = !m_ctx.find(src.subsystem);
    RemoteSubsystem& r = m_ctx.remote(src.subsystem);
    m_discovery.heardFrom(r, src);
    if (m_liveness.heard(r, firstContact))
        for (ClientService* c : m_all)
            c->onLinkRestored(r); // the platform may have restarted (events subscribe again)
    if (!m_table.dispatch(r, src, id, payload))
        counters.add("rx.unhandled");
}

void JausCore::tick() {
    const TimePoint now = m_ctx.now();
    m_discovery.tickBroadcast(now);
    for (auto& [ss, r] : m_ctx.remotes()) {
        m_liveness.tick(r, now);
        m_discovery.tick(r, now);
        m_video.heard(r);
        if (!r.components.known) {
            m_management.tick(r, now); // a stop sent to every component is repeated like any other
            continue;
        }
        for (ClientService* c : m_afterDiscovery)
            c->tick(r, now);
    }
}

std::vector<TargetOutcome> JausCore::setEmergencyAll(EmergencyCode code,
                                                     const std::vector<std::uint16_t>& alreadySent) {
    std::vector<TargetOutcome> out;
    const TimePoint now = m_ctx.now();
    auto early = [&](std::uint16_t ss) {
        return std::find(alreadySent.begin(), alreadySent.end(), ss) != alreadySent.end();
    };
    std::set<std::uint16_t> named;
    for (std::uint16_t ss : subsystems()) {
        named.insert(ss);
        TargetOutcome o = early(ss) ? emergencySent(ss, code) : emergencyOutcome(ss, setEmergency(ss, code));
        // A vehicle whose link is down still gets the stop at its last address (it may hear us even if we do
        // not hear it); the result says so, and that its confirmation can only come when it is back.
        if (const RemoteSubsystem* r = m_ctx.find(ss); o.sent && r && r->snap.link == LinkState::Down) {
            const auto downS = std::chrono::duration_cast<std::chrono::seconds>(now - r->snap.lastMessage);
            const std::string where =
                m_ctx.endpointOf(r->managementTarget().subsystem ? r->managementTarget() : JausId{ss, 1, 1});
            o.note = "link down (nothing heard for " + std::to_string(downS.count()) +
                     " s): SetEmergency sent to its last address" + (where.empty() ? "" : " " + where) +
                     "; no answer expected until it is back, confirmation pending" +
                     (o.note.empty() ? "" : "; " + o.note);
        }
        out.push_back(std::move(o));
    }
    // Sent on the caller's thread to a subsystem forgotten since: it still went on the wire.
    for (std::uint16_t ss : alreadySent)
        if (named.insert(ss).second)
            out.push_back(TargetOutcome{targetId(ss), true, {}});
    // Configured static endpoints never heard: the stop goes to every component of the subsystem at the
    // configured address, so a vehicle that cannot be discovered (no multicast) is still stopped.
    for (const StaticEndpoint& se : config().transport.staticEndpoints) {
        const std::uint16_t ss = se.id.subsystem;
        if (ss == 0 || ss == 0xFFFF || ss == config().subsystemId || !named.insert(ss).second)
            continue;
        TargetOutcome o = outcome(ss, m_management.setEmergencyUnheard(ss, code));
        if (o.sent)
            o.note = "configured static endpoint, never heard: SetEmergency sent to " + se.address + ":" +
                     std::to_string(se.port) + "; confirmation pending";
        out.push_back(std::move(o));
    }
    return out;
}

TargetOutcome JausCore::outcome(std::uint16_t subsystem, bool sent) const {
    return sent ? TargetOutcome::sentTo(targetId(subsystem))
                : TargetOutcome::refused(targetId(subsystem), m_ctx.lastRefusalCause(), m_ctx.lastRefusal());
}

TargetOutcome JausCore::emergencyOutcome(std::uint16_t subsystem, bool sent) const {
    TargetOutcome o = outcome(subsystem, sent);
    const RemoteSubsystem* r = m_ctx.find(subsystem);
    if (sent && r && !r->components.known)
        o.note = "its services are not known (not reported, or reported with no components): SetEmergency "
                 "sent to every component (" +
                 std::to_string(subsystem) + ".255.255); confirmation pending";
    return o;
}

} // namespace ocu::jaus
