// The simulated UGV's AccessControl service on the Core Mobility Component (AS5710A AccessControl,
// AEP-4818 §4.3): one controller at a time, pre-emption by a higher authority, release on the access timeout.
#include "sim/jaus/UgvCore.h"

#include <cmath>

#include "protocols/common/Log.h"
#include "sim/jaus/UgvSupport.h"

namespace ocu::sim {

using namespace ocu::jaus;
using ugv::kLog;
using ugv::secondsD;

void UgvCore::registerAccessControl() {
    const JausId mob = mobility();
    m_table.onCommand(msg::RequestControl, mob, [this](const JausId&, const JausId& src, ByteSpan p) {
        auto a = decodeU8(p, msg::RequestControl);
        if (!a)
            return rejectMalformed(a.error());
        accessRequest(src, *a);
    });
    m_table.onCommand(msg::ReleaseControl, mob, [this](const JausId& c, const JausId& src, ByteSpan) {
        if (isController(src)) {
            releaseController(RejectControlCode::Released);
        } else {
            send(c, src, encodeU8(msg::RejectControl, std::uint8_t(RejectControlCode::NotAvailable)));
        }
    });
    m_table.onCommand(msg::SetAuthority, mob, [this](const JausId&, const JausId& src, ByteSpan p) {
        auto a = decodeU8(p, msg::SetAuthority);
        if (!a)
            return rejectMalformed(a.error());
        if (isController(src) && *a >= m_cfg.defaultAuthority)
            m_s.controllerAuthority = *a;
    });
    m_table.onQuery(msg::QueryControl, mob, [this](const JausId&, ByteSpan) {
        return encode(ReportControl{m_s.controller, m_s.controllerAuthority});
    });
    m_table.onQuery(msg::QueryAuthority, mob, [this](const JausId&, ByteSpan) {
        return encodeU8(msg::ReportAuthority,
                        m_s.controller.subsystem ? m_s.controllerAuthority : m_cfg.defaultAuthority);
    });
    m_table.onQuery(msg::QueryTimeout, mob, [this](const JausId&, ByteSpan) {
        return encodeU8(msg::ReportTimeout, std::uint8_t(std::lround(m_cfg.accessTimeoutS)));
    });
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

void UgvCore::tickAccessTimeout(TimePoint now) {
    // Release a controller that stopped re-requesting (AEP-4818 §4.3.4).
    if (m_s.controller.subsystem != 0 && !(m_s.controller == internalClient()) && m_cfg.accessTimeoutS > 0 &&
        now - m_lastRequest > secondsD(m_cfg.accessTimeoutS)) {
        logInfo(kLog, m_cfg.callSign + ": access-control timeout for " + m_s.controller.toString());
        releaseController(RejectControlCode::Released);
    }
}

} // namespace ocu::sim
