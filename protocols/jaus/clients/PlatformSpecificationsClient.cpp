#include "protocols/jaus/clients/PlatformSpecificationsClient.h"

#include "protocols/jaus/Messages.h"

namespace ocu::jaus {

void PlatformSpecificationsClient::registerMessages(MessageTable& table) {
    table.onVehicleMessage(msg::ReportPlatformSpecifications,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
                               auto m = decodePlatformSpecifications(p);
                               if (!m)
                                   return m_ctx.rejected(src, m.error());
                               r.snap.platform = *m;
                               m_ctx.changed(r);
                           });
}

void PlatformSpecificationsClient::tick(RemoteSubsystem& r, TimePoint now) {
    const JausId target = r.components.platformSpecs;
    if (!r.reachable() || r.snap.platform || !target.subsystem)
        return;
    TimePoint& last = m_lastQuery[r.id()];
    if (now - last > std::chrono::seconds(2)) {
        last = now;
        m_ctx.send(target, encodeEmpty(msg::QueryPlatformSpecifications));
    }
}

} // namespace ocu::jaus
