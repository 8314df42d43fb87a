#include "sim/jaus/UgvCore.h"

#include "protocols/common/Log.h"
#include "sim/jaus/UgvSupport.h"

namespace ocu::sim {

using namespace ocu::jaus;
using ugv::kLog;
using ugv::secondsD;

UgvCore::UgvCore(SimulatedUgvConfig config, JausOutput& output, const Clock& clock, Counters& counters)
    : m_cfg(std::move(config)), m_out(output), m_clock(clock), m_counters(counters), m_geo(m_cfg.origin),
      m_video(
          m_cfg.subsystemId, m_cfg.cameras,
          [this](const JausId& from, const JausId& to, const Bytes& b) { send(from, to, b); }, clock,
          counters) {
    m_s.x = m_cfg.startX;
    m_s.y = m_cfg.startY;
    m_s.yaw = m_cfg.startYaw;
    registerDiscovery();
    registerEvents();
    registerAccessControl();
    registerManagement();
    registerDriving();
    registerPoseSensors();
    registerWaypoints();
    registerPlatform();
    if (m_cfg.enhancedAccessControl)
        registerHandoff();
}

bool UgvCore::isLocal(const JausId& id) const {
    return id == platformManager() || id == mobility() || id == sensors() || m_video.isLocal(id);
}

void UgvCore::send(const JausId& from, const JausId& to, const Bytes& payload, Priority prio) {
    m_counters.add("tx.messages");
    m_out.sendFrom(from, to, payload, SendOptions{prio, false});
}

void UgvCore::rejectMalformed(const std::string& error) {
    m_counters.add("rx.rejected." + rejectReason(error));
    logWarning(kLog, m_cfg.callSign + ": " + error);
}

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
        if (auto answer = m_table.handle(c, src, id, payload))
            send(c, src, *answer);
    }
    for (const JausId& c : {m_video.camera(), m_video.panTiltUnit()})
        if (dst.matches(c) && m_video.handle(c, src, id, payload))
            any = true;
    if (!any)
        m_counters.add("rx.ignored");
}

void UgvCore::tick() {
    const TimePoint now = m_clock.now();
    if (!m_started) {
        m_started = true;
        m_lastHeartbeat = now - std::chrono::seconds(10);
    }
    physics(now);
    m_video.tick();
    tickAccessTimeout(now);
    tickHandoff(now);
    // Unsolicited heartbeat to [SubsystemID].255.255 at ≥ 1 Hz (AEP-4818 V1.JAUS-43).
    const auto& f = m_cfg.faults;
    if (!f.dropHeartbeat && f.heartbeatRateHz > 0 &&
        now - m_lastHeartbeat >= secondsD(1.0 / f.heartbeatRateHz)) {
        m_lastHeartbeat = now;
        send(platformManager(), JausId{m_cfg.subsystemId, 0xFF, 0xFF},
             encodeEmpty(msg::ReportHeartbeatPulse));
    }
    tickEvents(now);
}

} // namespace ocu::sim
