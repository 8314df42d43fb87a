#include "protocols/jaus/clients/DiscoveryClient.h"

#include <algorithm>
#include <string_view>

#include "protocols/jaus/ServiceInheritance.h"

namespace ocu::jaus {

namespace {

// By the last URI segment, whatever the namespace (peers disagree on it, e.g. HealthMonitor).
bool hasService(const ComponentInfo& c, std::string_view name) {
    for (auto& s : c.services) {
        auto pos = s.uri.rfind(':');
        if (pos != std::string::npos && std::string_view(s.uri).substr(pos + 1) == name)
            return true;
    }
    return false;
}

} // namespace

void DiscoveryClient::registerMessages(MessageTable& table) {
    table.onRequest(msg::QueryIdentification,
                    [this](const JausId& src, ByteSpan p) { return answerIdentification(src, p); });
    table.onRequest(msg::QueryServices,
                    [this](const JausId& src, ByteSpan) { return answerServices(src, msg::QueryServices); });
    table.onRequest(msg::QueryServiceList, [this](const JausId& src, ByteSpan) {
        return answerServices(src, msg::QueryServiceList);
    });

    table.onVehicleMessage(msg::ReportIdentification, [this](RemoteSubsystem& r, const JausId& src,
                                                             ByteSpan p) { onIdentification(r, src, p); });
    table.onVehicleMessage(msg::ReportServices, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
        auto m = decodeReportServices(p);
        if (!m)
            return m_ctx.rejected(src, m.error());
        onServices(r, src, m->nodes);
    });
    table.onVehicleMessage(msg::ReportServiceList, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
        auto m = decodeReportServiceList(p);
        if (!m)
            return m_ctx.rejected(src, m.error());
        for (auto& s : m->subsystems)
            if (s.subsystem == src.subsystem)
                onServices(r, src, s.nodes);
    });
    // A heartbeat (also the IOP unsolicited one to [ss].255.255) announces a subsystem: identify it.
    table.onVehicleMessage(msg::ReportHeartbeatPulse,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan) {
                               if (r.snap.callSign.empty())
                                   identify(src, m_state[r.id()], m_ctx.now());
                           });
}

// ---- the console as a subsystem (issue 3 §2)
// ---------------------------------------------------------------

bool DiscoveryClient::answerIdentification(const JausId& src, ByteSpan payload) {
    auto q = decodeQueryIdentification(payload);
    if (!q)
        return true;
    const IdType type = q->type == IdQueryType::Subsystem ? IdType::Ocu
                        : q->type == IdQueryType::Node    ? IdType::Node
                                                          : IdType::Component;
    m_ctx.send(src, encode(ReportIdentification{q->type, type, m_ctx.config().callSign}));
    return true;
}

bool DiscoveryClient::answerServices(const JausId& src, std::uint16_t id) {
    const JausId& self = m_ctx.self();
    NodeServices node{self.node,
                      {{self.component,
                        0,
                        {{"urn:jaus:jss:core:Transport", 1, 1},
                         {"urn:jaus:jss:core:Events", 1, 1},
                         {"urn:jaus:jss:core:Liveness", 1, 1},
                         {"urn:jaus:jss:core:Discovery", 1, 1}}}}};
    if (id == msg::QueryServices)
        m_ctx.send(src, encode(ReportServices{{node}}));
    else
        m_ctx.send(src, encode(ReportServiceList{{{self.subsystem, {node}}}}));
    return true;
}

// ---- vehicles
// ----------------------------------------------------------------------------------------------

void DiscoveryClient::discoverNow() {
    m_lastBroadcast = m_ctx.now();
    // Subsystem-level identification to everyone (AEP-4818 §6.2.2.2.1.1, §9 item 6).
    m_ctx.send(kBroadcastAll, encode(QueryIdentification{IdQueryType::Subsystem}));
    // And unicast to every static endpoint (AEP-4818 §4.7.1 static address list): with multicast filtered
    // or unavailable these vehicles are still discovered (issue 13 §5). The transport sends a destination
    // ss.255.255 (or ss.n.255) that matches a static endpoint to that endpoint's address only.
    for (const StaticEndpoint& se : m_ctx.config().transport.staticEndpoints)
        m_ctx.send(se.id, encode(QueryIdentification{IdQueryType::Subsystem}));
}

void DiscoveryClient::tickBroadcast(TimePoint now) {
    if (!m_started || now - m_lastBroadcast >= secondsD(m_ctx.config().discoveryIntervalS)) {
        m_started = true;
        discoverNow();
    }
}

DiscoveryClient::Sender DiscoveryClient::classify(const JausId& src, std::uint16_t id, ByteSpan payload) {
    if (m_otherOcus.count(src.subsystem))
        return Sender::Console;
    if (id == msg::ReportIdentification) {
        auto ri = decodeReportIdentification(payload);
        if (ri && ri->type == IdType::Ocu) {
            m_otherOcus.insert(src.subsystem);
            return Sender::NewConsole;
        }
    }
    return Sender::Vehicle;
}

void DiscoveryClient::identify(const JausId& target, State& s, TimePoint now) {
    if (now - s.lastIdentQuery > std::chrono::seconds(1)) {
        s.lastIdentQuery = now;
        m_ctx.send(target, encode(QueryIdentification{IdQueryType::Subsystem}));
    }
}

void DiscoveryClient::onIdentification(RemoteSubsystem& r, const JausId& src, ByteSpan p) {
    auto ri = decodeReportIdentification(p);
    if (!ri)
        return m_ctx.rejected(src, ri.error());
    // The subsystem-level answer names the vehicle; a node or component answer only until that arrives.
    if (ri->queryType == IdQueryType::Subsystem || r.snap.callSign.empty()) {
        r.snap.callSign = ri->identification;
        r.components.platformManager = src;
        r.snap.endpoint = m_ctx.endpointOf(src);
        State& s = m_state[r.id()];
        if (!s.discoveredEvent) {
            s.discoveredEvent = true;
            m_ctx.notify(Severity::Info, EventKind::Discovered, r.id(),
                         "discovered " + r.snap.callSign + " (subsystem " + std::to_string(r.id()) + ")");
        }
    }
    m_ctx.changed(r);
}

void DiscoveryClient::onServices(RemoteSubsystem& r, const JausId& /*source*/,
                                 const std::vector<NodeServices>& nodes) {
    ComponentTable& table = r.components;
    // Merge (peers send duplicates, jaus-wire.md §6.7).
    for (auto& n : nodes) {
        auto nit = std::find_if(r.snap.services.begin(), r.snap.services.end(),
                                [&](const NodeInfo& x) { return x.node == n.node; });
        if (nit == r.snap.services.end()) {
            r.snap.services.push_back(NodeInfo{n.node, {}});
            nit = std::prev(r.snap.services.end());
        }
        for (auto& c : n.components) {
            auto cit = std::find_if(nit->components.begin(), nit->components.end(),
                                    [&](const ComponentInfo& x) { return x.component == c.component; });
            if (cit == nit->components.end()) {
                nit->components.push_back(ComponentInfo{c.component, {}});
                cit = std::prev(nit->components.end());
            }
            for (auto& s : c.services) {
                bool dup =
                    std::any_of(cit->services.begin(), cit->services.end(),
                                [&](const ServiceRecord& x) { return x.uri == s.uri && x.major == s.major; });
                if (!dup)
                    cit->services.push_back(s);
            }
        }
    }
    assignRoles(r);
    if (!table.known) {
        table.known = true;
        if (m_onServicesKnown)
            m_onServicesKnown(r);
    }
    m_ctx.changed(r);
}

void DiscoveryClient::assignRoles(RemoteSubsystem& r) {
    // Recomputed from the merged service lists: who offers what, directly or by inheritance (issue 13 §3).
    ComponentTable& t = r.components;
    const std::uint16_t ss = r.id();
    JausId driver, management, access;
    for (const NodeInfo& n : r.snap.services) {
        for (const ComponentInfo& c : n.components) {
            const JausId id{ss, n.node, c.component};
            if (!driver.subsystem &&
                (offers(c.services, service::PrimitiveDriver) ||
                 offers(c.services, service::VelocityStateDriver) || hasService(c, "PrimitiveDriver") ||
                 hasService(c, "VelocityStateDriver")))
                driver = id;
            if (!management.subsystem && offers(c.services, service::Management))
                management = id;
            if (!access.subsystem && offers(c.services, service::AccessControl))
                access = id;
            if (offers(c.services, service::GlobalPoseSensor) || hasService(c, "GlobalPoseSensor"))
                t.globalPoseSensor = id;
            if (offers(c.services, service::LocalPoseSensor) || hasService(c, "LocalPoseSensor"))
                t.localPoseSensor = id;
            if (offers(c.services, service::VelocityStateSensor) || hasService(c, "VelocityStateSensor"))
                t.velocitySensor = id;
            if (hasService(c, "HealthMonitor"))
                t.healthMonitor = id;
            if (hasService(c, "PlatformSpecifications"))
                t.platformSpecs = id;
            if (hasService(c, "Liveness") && n.node == 1 && t.platformManager.subsystem == 0)
                t.platformManager = id;
        }
    }
    if (driver.subsystem)
        r.snap.mobilityComponent = driver;
    // Prefer the driver for management and access control: one component holds the whole vehicle's state
    // (a PrimitiveDriver inherits Management, AS6009), so control of it is what teleop needs.
    t.management = driver.subsystem ? driver : management;
    t.accessControl = driver.subsystem ? driver : management.subsystem ? management : access;
}

void DiscoveryClient::tick(RemoteSubsystem& r, TimePoint now) {
    State& s = m_state[r.id()];
    const JausId pm = r.components.platformManager;
    if (r.snap.callSign.empty())
        identify(pm, s, now);
    if (!r.components.known) {
        if (r.reachable() && now - s.lastServicesQuery > std::chrono::seconds(1)) {
            s.lastServicesQuery = now;
            m_ctx.send(pm, encode(QueryServices{}));
        }
        return;
    }
    // Re-check the platform manager every discovery interval (AEP-4818 §6.2.2.2.2.1).
    if (now - s.lastRecheck > secondsD(m_ctx.config().discoveryIntervalS)) {
        s.lastRecheck = now;
        m_ctx.send(pm, encode(QueryServices{}));
    }
}

} // namespace ocu::jaus
