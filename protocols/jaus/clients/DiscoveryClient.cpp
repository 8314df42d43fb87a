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
    // A component registering its services with us as a Discovery service (AS5710A RegisterServices): the
    // same facts as a ReportServices naming that component. Stacks that answer the wildcard QueryServices
    // with no components publish their services this way.
    table.onVehicleMessage(msg::RegisterServices, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
        auto m = decodeRegisterServices(p);
        if (!m)
            return m_ctx.rejected(src, m.error());
        onServices(r, src, {NodeServices{src.node, {ComponentServices{src.component, 0, m->services}}}});
    });
    table.onVehicleMessage(msg::ReportConfiguration,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
                               auto m = decodeReportConfiguration(p);
                               if (!m)
                                   return m_ctx.rejected(src, m.error());
                               onConfiguration(r, *m);
                           });
    // A heartbeat (also the IOP unsolicited one to [ss].255.255) announces a subsystem: identify it.
    table.onVehicleMessage(msg::ReportHeartbeatPulse,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan) {
                               if (r.snap.callSign.empty())
                                   identify(src, m_state[r.id()], m_ctx.now());
                           });
}

// ---- the console as a subsystem -------------------------------------------------------------------------

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
    // A console that may hold a vehicle answers hand-off requests the vehicle forwards (HandoffClient): the
    // HandoffController of AEP-4818 §6.3, in the public 1.1 layouts.
    if (m_ctx.config().mayControl())
        node.components.front().services.push_back({"urn:jaus:jss:iop:HandoffController", 1, 1});
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
    // or unavailable these vehicles are still discovered. The transport sends a destination
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
        State& s = m_state[r.id()];
        r.snap.callSign = ri->identification;
        // Stacks where every component answers the subsystem-level query: the platform manager is the first
        // to answer at that level, or ss.1.1 (the usual Discovery component) whenever it answers.
        if (ri->queryType != IdQueryType::Subsystem) {
            if (!s.managerIdentified)
                r.components.platformManager = src;
        } else if (!s.managerIdentified || src == JausId{r.id(), 1, 1}) {
            r.components.platformManager = src;
            s.managerIdentified = true;
        }
        r.snap.endpoint = m_ctx.endpointOf(src);
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
    bool added = false;
    // Merge (peers send duplicates, jaus-wire.md §6.7; answers and registrations each tell a part).
    for (auto& n : nodes) {
        auto nit = std::find_if(r.snap.services.begin(), r.snap.services.end(),
                                [&](const NodeInfo& x) { return x.node == n.node; });
        for (auto& c : n.components) {
            if (c.services.empty())
                continue; // a component listed without services tells nothing to address
            if (nit == r.snap.services.end()) {
                r.snap.services.push_back(NodeInfo{n.node, {}});
                nit = std::prev(r.snap.services.end());
            }
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
                if (!dup) {
                    cit->services.push_back(s);
                    added = true;
                }
            }
        }
    }
    State& st = m_state[r.id()];
    if (r.snap.services.empty()) {
        // An answer without a single component (the wildcard QueryServices answered empty): not "no
        // services" but "not told". The table stays unknown, so a stop still goes to every component
        // (ManagementClient), and the tick asks for the configuration and each shown component by name.
        if (!st.emptyAnswerWarned) {
            st.emptyAnswerWarned = true;
            m_ctx.counters().add("discovery.empty_services_answer");
            m_ctx.notify(Severity::Warning, EventKind::Discovered, r.id(),
                         (r.snap.callSign.empty() ? "subsystem " + std::to_string(r.id()) : r.snap.callSign) +
                             " answered QueryServices with no components: asking its components by name");
        }
        return;
    }
    assignRoles(r);
    const bool first = !table.known;
    table.known = true;
    if ((first || added) && m_onServicesKnown)
        m_onServicesKnown(r);
    m_ctx.changed(r);
}

void DiscoveryClient::onConfiguration(RemoteSubsystem& r, const ReportConfiguration& configuration) {
    State& st = m_state[r.id()];
    for (const auto& n : configuration.nodes)
        for (const auto& c : n.components)
            if (n.node != 0 && n.node != 0xFF && c.component != 0 && c.component != 0xFF)
                st.shown.try_emplace(std::uint16_t(n.node << 8 | c.component));
}

void DiscoveryClient::heardFrom(RemoteSubsystem& r, const JausId& src) {
    if (src.node == 0 || src.node == 0xFF || src.component == 0 || src.component == 0xFF)
        return;
    m_state[r.id()].shown.try_emplace(std::uint16_t(src.node << 8 | src.component));
}

bool DiscoveryClient::listed(const RemoteSubsystem& r, std::uint8_t node, std::uint8_t component) {
    for (const NodeInfo& n : r.snap.services)
        if (n.node == node)
            for (const ComponentInfo& c : n.components)
                if (c.component == component)
                    return true;
    return false;
}

void DiscoveryClient::askUnlisted(RemoteSubsystem& r, State& st, TimePoint now) {
    const JausId pm = r.components.platformManager;
    for (auto& [key, q] : st.shown) {
        const std::uint8_t node = std::uint8_t(key >> 8), comp = std::uint8_t(key);
        if (listed(r, node, comp))
            continue;
        // Every second for the first few tries, then at the re-check interval: a component that offers
        // nothing (or never answers) must not cost a query a second for ever.
        const Duration every =
            q.sent < 5 ? Duration(std::chrono::seconds(1)) : secondsD(m_ctx.config().discoveryIntervalS);
        if (q.sent > 0 && now - q.last < every)
            continue;
        q.last = now;
        ++q.sent;
        QueryServices named;
        named.nodes = {QueryServices::Node{node, {comp}}};
        const JausId component{r.id(), node, comp};
        // To the Discovery service (the platform manager) and to the component itself: where Discovery does
        // not know the component, the component answers for its own services.
        m_ctx.send(pm, encode(named));
        if (!(component == pm))
            m_ctx.send(component, encode(named));
    }
}

void DiscoveryClient::assignRoles(RemoteSubsystem& r) {
    // Recomputed from the merged service lists: who offers what, directly or by inheritance (AS6009, AS5710A
    // inheritance).
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
    if (driver.subsystem) {
        r.snap.mobilityComponent = driver;
        // What the driver takes: a drive session sends only the demand its services name (a vehicle with
        // a PrimitiveDriver alone never gets SetVelocityCommand).
        for (const NodeInfo& n : r.snap.services)
            for (const ComponentInfo& c : n.components)
                if (n.node == driver.node && c.component == driver.component) {
                    t.driverTakesVelocity = offers(c.services, service::VelocityStateDriver) ||
                                            hasService(c, "VelocityStateDriver");
                    t.driverTakesEffort =
                        offers(c.services, service::PrimitiveDriver) || hasService(c, "PrimitiveDriver");
                }
    }
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
    if (!r.reachable())
        return;
    if (!r.components.known) {
        if (now - s.lastServicesQuery > std::chrono::seconds(1)) {
            s.lastServicesQuery = now;
            ++s.wildcardQueries;
            m_ctx.send(pm, encode(QueryServices{}));
        }
        // Told nothing by the wildcard query (an empty answer, or none to three queries): which nodes and
        // components are there (AS5710A QueryConfiguration, where the platform's Discovery offers it), and
        // each shown one by name.
        if (s.emptyAnswerWarned || s.wildcardQueries > 3) {
            if (now - s.lastConfigurationQuery > secondsD(m_ctx.config().discoveryIntervalS) ||
                s.lastConfigurationQuery == TimePoint{}) {
                s.lastConfigurationQuery = now;
                m_ctx.send(pm, encode(QueryConfiguration{IdQueryType::Subsystem}));
            }
            askUnlisted(r, s, now);
        }
        return;
    }
    // Re-check the platform manager every discovery interval (AEP-4818 §6.2.2.2.2.1).
    if (now - s.lastRecheck > secondsD(m_ctx.config().discoveryIntervalS)) {
        s.lastRecheck = now;
        m_ctx.send(pm, encode(QueryServices{}));
    }
    // A partial answer: components that exist but are not listed are asked for by name.
    askUnlisted(r, s, now);
}

} // namespace ocu::jaus
