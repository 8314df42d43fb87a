// The simulated UGV's platform-manager services: Discovery (identification, service lists, subsystem list),
// Liveness on every component, HealthMonitor (AEP-4818 §6.2.2).
#include "sim/jaus/UgvCore.h"

namespace ocu::sim {

using namespace ocu::jaus;

std::vector<ServiceRecord> UgvCore::servicesOf(const JausId& c) const {
    std::vector<ServiceRecord> s{{"urn:jaus:jss:core:Transport", 1, 1},
                                 {"urn:jaus:jss:core:Events", 1, 1},
                                 {"urn:jaus:jss:core:Liveness", 1, 1}};
    if (c == platformManager()) {
        s.push_back({"urn:jaus:jss:core:Discovery", 1, 1});
        s.push_back({"urn:jaus:jss:exp:aeodrs:HealthMonitor", 1, 4});
        s.push_back({"urn:jaus:jss:iop:UnsolicitedHeartbeat", 1, 1});
        for (const ServiceRecord& v : m_video.platformManagerServices())
            s.push_back(v);
    } else if (c == mobility()) {
        s.push_back({"urn:jaus:jss:core:AccessControl", 1, 1});
        s.push_back({"urn:jaus:jss:core:Management", 1, 1});
        if (m_cfg.enhancedAccessControl)
            s.push_back({"urn:jaus:jss:iop:EnhancedAccessControl", 1, 1});
        s.push_back({"urn:jaus:jss:mobility:PrimitiveDriver", 1, 1});
        s.push_back({"urn:jaus:jss:mobility:VelocityStateDriver", 1, 1});
        s.push_back({"urn:jaus:jss:ugv:PlatformSpecifications", 1, 0});
        // The waypoint services (jaus-autonomy.md §13): ListManager core 1.1, the drivers mobility 1.1.
        s.push_back({"urn:jaus:jss:core:ListManager", 1, 1});
        s.push_back({"urn:jaus:jss:mobility:LocalWaypointListDriver", 1, 1});
        s.push_back({"urn:jaus:jss:mobility:GlobalWaypointListDriver", 1, 1});
        s.push_back({"urn:jaus:jss:mobility:LocalWaypointDriver", 1, 1});
        s.push_back({"urn:jaus:jss:mobility:GlobalWaypointDriver", 1, 1});
        // The platform services (UgvPlatform.cpp) sit here, with the one access control of the vehicle.
        s.push_back({"urn:jaus:jss:iop:PlatformMode", 1, 1});
        s.push_back({"urn:jaus:jss:iop:PlatformState", 1, 1});
        s.push_back({"urn:jaus:jss:ugv:IlluminationService", 1, 0});
        s.push_back({"urn:jaus:jss:ugv:OdometryService", 1, 0});
    } else if (c == sensors()) {
        s.push_back({"urn:jaus:jss:mobility:GlobalPoseSensor", 1, 1});
        s.push_back({"urn:jaus:jss:mobility:LocalPoseSensor", 1, 1});
        s.push_back({"urn:jaus:jss:mobility:VelocityStateSensor", 1, 1});
        s.push_back({"urn:jaus:jss:iop:PathReporter", 1, 1});
    }
    return s;
}

void UgvCore::registerDiscovery() {
    const JausId pm = platformManager();
    m_table.onQuery(msg::QueryHeartbeatPulse, std::nullopt,
                    [](const JausId&, ByteSpan) { return encodeEmpty(msg::ReportHeartbeatPulse); });
    m_table.onCommand(msg::QueryIdentification, pm, [this](const JausId& c, const JausId& src, ByteSpan p) {
        answerIdentification(c, src, p);
    });
    m_table.onCommand(msg::QueryServices, pm, [this](const JausId& c, const JausId& src, ByteSpan) {
        answerServices(c, src, msg::QueryServices);
    });
    m_table.onCommand(msg::QueryServiceList, pm, [this](const JausId& c, const JausId& src, ByteSpan) {
        answerServices(c, src, msg::QueryServiceList);
    });
    m_table.onCommand(msg::QuerySubsystemList, pm, [this](const JausId& c, const JausId& src, ByteSpan) {
        send(c, src, encode(ReportSubsystemList{{platformManager()}}));
    });
    // Accepted; payload registration is not simulated.
    m_table.onCommand(msg::RegisterServices, pm, [](const JausId&, const JausId&, ByteSpan) {});
    m_table.onCommand(msg::UpdateHealthSummary, pm, [](const JausId&, const JausId&, ByteSpan) {});
    m_table.onQuery(msg::QueryHealthSummary, pm, [this](const JausId&, ByteSpan) {
        // Node severity 3 for Emergency, 4 for Failure (AEP-4818 §6.2.2.2.1.3).
        std::uint8_t sev = m_s.management == ManagementState::Emergency ? 3
                           : m_s.management == ManagementState::Failure ? 4
                                                                        : 0;
        return encode(HealthSummary{sev, {{1, 0}, {3, sev}}});
    });
}

void UgvCore::answerIdentification(const JausId& c, const JausId& src, ByteSpan p) {
    if (m_cfg.faults.loseDiscovery)
        return;
    auto q = decodeQueryIdentification(p);
    if (!q)
        return rejectMalformed(q.error());
    if (q->type == IdQueryType::System)
        return;
    // Subsystem/node identification carry the call sign (AEP-4818 §10 item 5).
    IdType t = q->type == IdQueryType::Subsystem ? IdType::Vehicle
               : q->type == IdQueryType::Node    ? IdType::Node
                                                 : IdType::Component;
    send(c, src, encode(ReportIdentification{q->type, t, m_cfg.callSign}));
}

void UgvCore::answerServices(const JausId& c, const JausId& src, std::uint16_t id) {
    if (m_cfg.faults.loseDiscovery)
        return;
    std::vector<NodeServices> nodes{{1, {{1, 0, servicesOf(platformManager())}}},
                                    {3, {{1, 0, servicesOf(mobility())}, {2, 0, servicesOf(sensors())}}}};
    if (auto n4 = m_video.node4(); !n4.empty())
        nodes.push_back({4, std::move(n4)});
    if (id == msg::QueryServices)
        send(c, src, encode(ReportServices{nodes}));
    else
        send(c, src, encode(ReportServiceList{{{m_cfg.subsystemId, nodes}}}));
}

} // namespace ocu::sim
