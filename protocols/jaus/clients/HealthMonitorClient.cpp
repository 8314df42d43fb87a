#include "protocols/jaus/clients/HealthMonitorClient.h"

#include "protocols/jaus/Messages.h"

namespace ocu::jaus {

void HealthMonitorClient::registerMessages(MessageTable& table) {
    table.onVehicleMessage(
        msg::ReportHealthSummary, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
            auto m = decodeHealthSummary(p);
            if (!m)
                return m_ctx.rejected(src, m.error());
            const std::uint8_t old = r.snap.health ? r.snap.health->severity : 0;
            r.snap.health = *m;
            if (m->severity >= 3 && m->severity != old)
                m_ctx.notify(m->severity >= 4 ? Severity::Error : Severity::Warning, EventKind::HealthFault,
                             r.id(), r.snap.callSign + " health " + (m->severity >= 4 ? "FAIL" : "ERR"));
            m_ctx.changed(r);
        });
}

void HealthMonitorClient::tick(RemoteSubsystem& r, TimePoint now) {
    const JausId target = r.components.healthMonitor;
    if (!target.subsystem || !r.reachable())
        return;
    TimePoint& last = m_lastPoll[r.id()];
    if (now - last >= std::chrono::seconds(5)) {
        last = now;
        m_ctx.send(target, encodeEmpty(msg::QueryHealthSummary));
    }
}

} // namespace ocu::jaus
