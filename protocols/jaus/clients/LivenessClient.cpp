#include "protocols/jaus/clients/LivenessClient.h"

#include <algorithm>

#include "protocols/jaus/Messages.h"
#include "protocols/jaus/clients/EventsClient.h"

namespace ocu::jaus {

void LivenessClient::registerMessages(MessageTable& table) {
    table.onRequest(msg::QueryHeartbeatPulse, [this](const JausId& src, ByteSpan) {
        m_ctx.send(src, encodeEmpty(msg::ReportHeartbeatPulse));
        return true;
    });
}

void LivenessClient::onServicesKnown(RemoteSubsystem& r) {
    m_events.subscribe(r, r.components.platformManager, encodeEmpty(msg::QueryHeartbeatPulse),
                       m_ctx.config().heartbeatRateHz);
}

bool LivenessClient::heard(RemoteSubsystem& r, bool firstContact) {
    const TimePoint now = m_ctx.now();
    m_lastHeard[r.id()] = now;
    r.snap.lastMessage = now;
    r.snap.lastMessageUnixMs = unixMillisNow();
    if (r.snap.link == LinkState::Up)
        return false;
    const bool wasDown = r.snap.link == LinkState::Down;
    r.snap.link = LinkState::Up;
    if (!wasDown || firstContact)
        return false;
    m_ctx.notify(Severity::Info, EventKind::LinkRestored, r.id(),
                 "link to " + r.snap.callSign + " (" + std::to_string(r.id()) + ") restored");
    return true;
}

void LivenessClient::tick(RemoteSubsystem& r, TimePoint now) {
    auto it = m_lastHeard.try_emplace(r.id(), now).first; // a record made elsewhere counts as heard now
    const Duration age = now - it->second;
    const JausConfig& cfg = m_ctx.config();
    const Duration lost = secondsD(cfg.linkLostS);
    const Duration degraded = std::min(secondsD(2.5 / cfg.heartbeatRateHz), lost / 2);
    const LinkState link = age > lost       ? LinkState::Down
                           : age > degraded ? LinkState::Degraded
                                            : LinkState::Up;
    // A subsystem whose link is down is probed at 1 Hz at its last address (the transport remembers it), so
    // the link is back within about a second of the peer's return, not at the next discovery broadcast.
    // QueryIdentification: every JAUS component answers it (AS5710A Discovery).
    if (link == LinkState::Down) {
        TimePoint& probe = m_lastProbe[r.id()];
        if (now - probe >= std::chrono::seconds(1)) {
            probe = now;
            m_ctx.counters().add("tx.link_probe");
            m_ctx.send(r.components.platformManager, encode(QueryIdentification{IdQueryType::Subsystem}));
        }
    }
    if (link == r.snap.link)
        return;
    r.snap.link = link;
    if (link == LinkState::Down)
        m_ctx.notify(Severity::Error, EventKind::LinkLost, r.id(),
                     "link to " + r.snap.callSign + " (" + std::to_string(r.id()) + ") lost");
    m_ctx.changed(r);
}

} // namespace ocu::jaus
