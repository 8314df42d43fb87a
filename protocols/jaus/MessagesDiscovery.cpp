// Discovery messages (AS5710A): identification, services, service list, subsystem list.
#include "protocols/jaus/Messages.h"

#include "protocols/jaus/MessageSupport.h"

namespace ocu::jaus {

using namespace codec;

namespace {

void putServices(ByteWriter& w, const std::vector<ServiceRecord>& s) {
    w.u8(std::uint8_t(std::min<std::size_t>(s.size(), 255)));
    for (std::size_t i = 0; i < s.size() && i < 255; ++i) {
        putString8(w, s[i].uri);
        w.u8(s[i].major);
        w.u8(s[i].minor);
    }
}
std::vector<ServiceRecord> getServices(ByteReader& r) {
    std::vector<ServiceRecord> out;
    auto n = r.u8();
    for (int i = 0; i < n && r.ok(); ++i) {
        ServiceRecord s;
        s.uri = getString8(r);
        s.major = r.u8();
        s.minor = r.u8();
        out.push_back(std::move(s));
    }
    return out;
}
void putNodes(ByteWriter& w, const std::vector<NodeServices>& nodes) {
    w.u8(std::uint8_t(std::min<std::size_t>(nodes.size(), 255)));
    for (auto& n : nodes) {
        w.u8(n.node);
        w.u8(std::uint8_t(std::min<std::size_t>(n.components.size(), 255)));
        for (auto& c : n.components) {
            w.u8(c.component);
            w.u8(c.instance);
            putServices(w, c.services);
        }
    }
}
std::vector<NodeServices> getNodes(ByteReader& r) {
    std::vector<NodeServices> out;
    auto nn = r.u8();
    for (int i = 0; i < nn && r.ok(); ++i) {
        NodeServices n;
        n.node = r.u8();
        auto nc = r.u8();
        for (int j = 0; j < nc && r.ok(); ++j) {
            ComponentServices c;
            c.component = r.u8();
            c.instance = r.u8();
            c.services = getServices(r);
            n.components.push_back(std::move(c));
        }
        out.push_back(std::move(n));
    }
    return out;
}

} // namespace

Bytes encode(const QueryIdentification& m) {
    return encodeU8(msg::QueryIdentification, std::uint8_t(m.type));
}
Result<QueryIdentification> decodeQueryIdentification(ByteSpan p) {
    auto v = decodeU8(p, msg::QueryIdentification);
    if (!v)
        return makeError(v.error());
    if (*v < 1 || *v > 4)
        return makeError("value: QueryIdentification type " + std::to_string(*v) + " out of range");
    return QueryIdentification{IdQueryType(*v)};
}
Bytes encode(const ReportIdentification& m) {
    Bytes out;
    auto w = start(out, msg::ReportIdentification);
    w.u8(std::uint8_t(m.queryType));
    w.u16(std::uint16_t(m.type));
    putString8(w, m.identification);
    return out;
}
Result<ReportIdentification> decodeReportIdentification(ByteSpan p) {
    auto r = open(p, msg::ReportIdentification);
    if (!r)
        return makeError(r.error());
    ReportIdentification m;
    m.queryType = IdQueryType(r->u8());
    m.type = IdType(r->u16());
    m.identification = getString8(*r);
    return finish(*r, m, msg::ReportIdentification);
}

Bytes encode(const RegisterServices& m) {
    Bytes out;
    auto w = start(out, msg::RegisterServices);
    putServices(w, m.services);
    return out;
}
Result<RegisterServices> decodeRegisterServices(ByteSpan p) {
    auto r = open(p, msg::RegisterServices);
    if (!r)
        return makeError(r.error());
    RegisterServices m;
    m.services = getServices(*r);
    return finish(*r, m, msg::RegisterServices);
}

Bytes encode(const QueryServices& m) {
    Bytes out;
    auto w = start(out, msg::QueryServices);
    w.u8(std::uint8_t(m.nodes.size()));
    for (auto& n : m.nodes) {
        w.u8(n.node);
        w.u8(std::uint8_t(n.components.size()));
        for (auto c : n.components)
            w.u8(c);
    }
    return out;
}
Result<QueryServices> decodeQueryServices(ByteSpan p) {
    auto r = open(p, msg::QueryServices);
    if (!r)
        return makeError(r.error());
    QueryServices m;
    m.nodes.clear();
    auto nn = r->u8();
    for (int i = 0; i < nn && r->ok(); ++i) {
        QueryServices::Node n;
        n.node = r->u8();
        n.components.clear();
        auto nc = r->u8();
        for (int j = 0; j < nc && r->ok(); ++j)
            n.components.push_back(r->u8());
        m.nodes.push_back(std::move(n));
    }
    return finish(*r, m, msg::QueryServices);
}

Bytes encode(const ReportServices& m) {
    Bytes out;
    auto w = start(out, msg::ReportServices);
    putNodes(w, m.nodes);
    return out;
}
Result<ReportServices> decodeReportServices(ByteSpan p) {
    auto r = open(p, msg::ReportServices);
    if (!r)
        return makeError(r.error());
    ReportServices m;
    m.nodes = getNodes(*r);
    return finish(*r, m, msg::ReportServices);
}

Bytes encode(const QueryServiceList& m) {
    Bytes out;
    auto w = start(out, msg::QueryServiceList);
    w.u16(std::uint16_t(m.subsystems.size()));
    for (auto& s : m.subsystems) {
        w.u16(s.subsystem);
        w.u8(std::uint8_t(s.nodes.size()));
        for (auto& n : s.nodes) {
            w.u8(n.node);
            w.u8(std::uint8_t(n.components.size()));
            for (auto& c : n.components) {
                w.u8(c.searchFilter ? 1 : 0);
                w.u8(c.component);
                if (c.searchFilter)
                    putString8(w, *c.searchFilter);
            }
        }
    }
    return out;
}
Result<QueryServiceList> decodeQueryServiceList(ByteSpan p) {
    auto r = open(p, msg::QueryServiceList);
    if (!r)
        return makeError(r.error());
    QueryServiceList m;
    m.subsystems.clear();
    auto ns = r->u16();
    for (int i = 0; i < ns && r->ok(); ++i) {
        QueryServiceList::Subsystem s;
        s.subsystem = r->u16();
        s.nodes.clear();
        auto nn = r->u8();
        for (int j = 0; j < nn && r->ok(); ++j) {
            QueryServiceList::Node n;
            n.node = r->u8();
            n.components.clear();
            auto nc = r->u8();
            for (int k = 0; k < nc && r->ok(); ++k) {
                QueryServiceList::Comp c;
                auto pv = r->u8();
                c.component = r->u8();
                if (pv & 1)
                    c.searchFilter = getString8(*r);
                n.components.push_back(std::move(c));
            }
            s.nodes.push_back(std::move(n));
        }
        m.subsystems.push_back(std::move(s));
    }
    return finish(*r, m, msg::QueryServiceList);
}

Bytes encode(const ReportServiceList& m) {
    Bytes out;
    auto w = start(out, msg::ReportServiceList);
    w.u16(std::uint16_t(m.subsystems.size()));
    for (auto& s : m.subsystems) {
        w.u16(s.subsystem);
        putNodes(w, s.nodes);
    }
    return out;
}
Result<ReportServiceList> decodeReportServiceList(ByteSpan p) {
    auto r = open(p, msg::ReportServiceList);
    if (!r)
        return makeError(r.error());
    ReportServiceList m;
    auto ns = r->u16();
    for (int i = 0; i < ns && r->ok(); ++i) {
        ReportServiceList::Subsystem s;
        s.subsystem = r->u16();
        s.nodes = getNodes(*r);
        m.subsystems.push_back(std::move(s));
    }
    return finish(*r, m, msg::ReportServiceList);
}

Bytes encode(const QueryConfiguration& m) {
    return encodeU8(msg::QueryConfiguration, std::uint8_t(m.type));
}
Bytes encode(const ReportConfiguration& m) {
    Bytes out;
    auto w = start(out, msg::ReportConfiguration);
    w.u8(std::uint8_t(std::min<std::size_t>(m.nodes.size(), 255)));
    for (auto& n : m.nodes) {
        w.u8(n.node);
        w.u8(std::uint8_t(std::min<std::size_t>(n.components.size(), 255)));
        for (std::size_t i = 0; i < n.components.size() && i < 255; ++i) {
            w.u8(n.components[i].component);
            w.u8(n.components[i].instance);
        }
    }
    return out;
}
Result<ReportConfiguration> decodeReportConfiguration(ByteSpan p) {
    auto r = open(p, msg::ReportConfiguration);
    if (!r)
        return makeError(r.error());
    ReportConfiguration m;
    auto nn = r->u8();
    for (int i = 0; i < nn && r->ok(); ++i) {
        ReportConfiguration::Node n;
        n.node = r->u8();
        auto nc = r->u8();
        for (int j = 0; j < nc && r->ok(); ++j) {
            ReportConfiguration::Component c;
            c.component = r->u8();
            c.instance = r->u8();
            n.components.push_back(c);
        }
        m.nodes.push_back(std::move(n));
    }
    return finish(*r, m, msg::ReportConfiguration);
}

Bytes encode(const ReportSubsystemList& m) {
    Bytes out;
    auto w = start(out, msg::ReportSubsystemList);
    w.u8(std::uint8_t(std::min<std::size_t>(m.subsystems.size(), 255)));
    for (std::size_t i = 0; i < m.subsystems.size() && i < 255; ++i) {
        w.u16(m.subsystems[i].subsystem);
        w.u8(m.subsystems[i].node);
        w.u8(m.subsystems[i].component);
    }
    return out;
}
Result<ReportSubsystemList> decodeReportSubsystemList(ByteSpan p) {
    auto r = open(p, msg::ReportSubsystemList);
    if (!r)
        return makeError(r.error());
    ReportSubsystemList m;
    auto n = r->u8();
    for (int i = 0; i < n && r->ok(); ++i) {
        JausId id;
        id.subsystem = r->u16();
        id.node = r->u8();
        id.component = r->u8();
        m.subsystems.push_back(id);
    }
    return finish(*r, m, msg::ReportSubsystemList);
}

} // namespace ocu::jaus
