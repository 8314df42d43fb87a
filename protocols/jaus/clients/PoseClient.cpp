#include "protocols/jaus/clients/PoseClient.h"

#include "protocols/jaus/Messages.h"
#include "protocols/jaus/clients/EventsClient.h"

namespace ocu::jaus {

namespace {
constexpr std::uint16_t kAllPoseFields = 0x01FF; // eight values and the timestamp
}

void PoseClient::registerMessages(MessageTable& table) {
    table.onVehicleMessage(msg::ReportGlobalPose, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
        auto m = decodeGlobalPose(p);
        if (!m)
            return m_ctx.rejected(src, m.error());
        r.snap.globalPose = *m;
        m_ctx.changed(r);
    });
    table.onVehicleMessage(msg::ReportLocalPose, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
        auto m = decodeLocalPose(p);
        if (!m)
            return m_ctx.rejected(src, m.error());
        r.snap.localPose = *m;
        m_ctx.changed(r);
    });
    table.onVehicleMessage(msg::ReportVelocityState,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
                               auto m = decodeVelocityState(p);
                               if (!m)
                                   return m_ctx.rejected(src, m.error());
                               r.snap.velocity = *m;
                               m_ctx.changed(r);
                           });
}

void PoseClient::onServicesKnown(RemoteSubsystem& r) {
    const ComponentTable& c = r.components;
    const double hz = m_ctx.config().poseRateHz;
    if (c.globalPoseSensor.subsystem)
        m_events.subscribe(r, c.globalPoseSensor, encodeQueryPv16(msg::QueryGlobalPose, kAllPoseFields), hz);
    if (c.localPoseSensor.subsystem)
        m_events.subscribe(r, c.localPoseSensor, encodeQueryPv16(msg::QueryLocalPose, kAllPoseFields), hz);
    if (c.velocitySensor.subsystem)
        m_events.subscribe(r, c.velocitySensor, encodeQueryPv16(msg::QueryVelocityState, kAllPoseFields), hz);
}

} // namespace ocu::jaus
