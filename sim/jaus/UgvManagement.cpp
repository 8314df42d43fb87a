// The simulated UGV's Management service on the Core Mobility Component (AS5710A Management, AEP-4818
// §4.5): STANDBY / READY / SHUTDOWN for the controller, EMERGENCY from anyone, FAILURE by fault injection.
#include "sim/jaus/UgvCore.h"

#include "protocols/common/Log.h"
#include "sim/jaus/UgvSupport.h"

namespace ocu::sim {

using namespace ocu::jaus;
using ugv::kLog;

void UgvCore::registerManagement() {
    const JausId mob = mobility();
    for (std::uint16_t id : {msg::Shutdown, msg::Standby, msg::Resume, msg::Reset})
        m_table.onCommand(
            id, mob, [this, id](const JausId&, const JausId& src, ByteSpan) { managementCommand(src, id); });
    m_table.onCommand(msg::SetEmergency, mob, [this](const JausId&, const JausId&, ByteSpan p) {
        auto code = decodeU16(p, msg::SetEmergency);
        if (!code)
            return rejectMalformed(code.error());
        // Any client may stop the vehicle (codes 0 from JTS, 1 STOP, 2 SAFETY all accepted).
        enterEmergency();
    });
    m_table.onCommand(msg::ClearEmergency, mob, [this](const JausId&, const JausId&, ByteSpan) {
        if (m_s.management == ManagementState::Emergency) {
            m_s.management = m_beforeEmergency == ManagementState::Emergency ? ManagementState::Standby
                                                                             : m_beforeEmergency;
            logInfo(kLog, m_cfg.callSign + ": emergency cleared");
        }
    });
    m_table.onQuery(msg::QueryStatus, mob, [this](const JausId&, ByteSpan) {
        return encode(ReportStatus{m_s.management, 0});
    });
}

void UgvCore::managementCommand(const JausId& src, std::uint16_t id) {
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
    else if (id == msg::Standby && m != ManagementState::Shutdown) {
        m = ManagementState::Standby;
        m_route.speed = 0; // leaving Ready (JSIDL resetTravelSpeed)
    } else if (id == msg::Shutdown)
        m = ManagementState::Shutdown;
    else if (id == msg::Reset)
        m = ManagementState::Standby;
}

void UgvCore::enterEmergency() {
    if (m_s.management != ManagementState::Emergency)
        m_beforeEmergency = m_s.management;
    m_s.management = ManagementState::Emergency;
    // Safe stop: zero motion at once, parking brake on (AEP-4818 §4.5.2).
    m_s.v = 0;
    m_s.w = 0;
    m_cmdV = m_cmdW = 0;
    // Leaving Ready resets the waypoint drivers' travel speed at once (JSIDL resetTravelSpeed): a clear
    // that follows within one physics step must not find the old speed.
    m_route.speed = 0;
    m_routeManagement = ManagementState::Emergency;
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

} // namespace ocu::sim
