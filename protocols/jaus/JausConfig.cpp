#include "jaus/JausConfig.h"

#include <boost/asio/ip/address_v4.hpp>

namespace ocu::jaus {

namespace {

std::string checkedAddress(ConfigObject& o, std::string_view key, const std::string& def) {
    std::string s = o.string(key, def);
    boost::system::error_code ec;
    boost::asio::ip::make_address_v4(s, ec);
    if (ec) {
        o.error(key, "'" + s + "' is not an IPv4 address");
        return def;
    }
    return s;
}

} // namespace

JausConfig parseJausConfig(ConfigObject& s) {
    JausConfig c;
    c.subsystemId = std::uint16_t(s.integer("subsystemId", c.subsystemId, 1, 65534));
    c.nodeId = std::uint8_t(s.integer("nodeId", c.nodeId, 1, 254));
    c.componentId = std::uint8_t(s.integer("componentId", c.componentId, 1, 254));
    c.callSign = s.string("callSign", c.callSign);
    if (c.callSign.size() > 255)
        s.error("callSign", "call sign longer than 255 characters");
    const std::string role = s.choice("role", "operator", {"operator", "monitor"});
    c.role = role == "monitor" ? Role::Monitor : Role::Operator;
    c.authority = std::uint8_t(s.integer("authority", c.role == Role::Monitor ? 0 : 205, 0, 254));
    if (c.role == Role::Monitor && c.authority != 0)
        s.error("authority", "the monitor role has authority 0");
    if (c.role == Role::Operator && c.authority == 0)
        s.error("authority", "authority 0 is the MONITOR role; use role \"monitor\" or an authority of 1-254");

    auto& t = c.transport;
    t.bindAddress = checkedAddress(s, "bindAddress", t.bindAddress);
    t.port = std::uint16_t(s.integer("port", t.port, 0, 65535));
    t.multicast = s.choice("broadcastMode", "multicast", {"multicast", "broadcast"}) == "multicast";
    t.multicastGroup = checkedAddress(s, "multicastGroup", t.multicastGroup);
    t.multicastPort = std::uint16_t(s.integer("multicastPort", t.multicastPort, 1, 65535));
    t.multicastTtl = int(s.integer("multicastTtl", t.multicastTtl, 0, 255));
    t.interfaceAddress = checkedAddress(s, "interfaceAddress", t.interfaceAddress);
    t.broadcastAddress = checkedAddress(s, "broadcastAddress", t.broadcastAddress);
    for (auto& e : s.objectList("staticEndpoints")) {
        StaticEndpoint se;
        se.id.subsystem = std::uint16_t(e.integer("subsystem", 0, 1, 65534));
        se.id.node = std::uint8_t(e.integer("node", 255, 1, 255));
        se.id.component = std::uint8_t(e.integer("component", 255, 1, 255));
        se.address = checkedAddress(e, "address", "127.0.0.1");
        se.port = std::uint16_t(e.integer("port", 3794, 1, 65535));
        e.finish();
        t.staticEndpoints.push_back(se);
    }

    c.driveRateHz = s.number("driveRateHz", c.driveRateHz, 2, 100);
    c.heartbeatRateHz = s.number("heartbeatRateHz", c.heartbeatRateHz, 1, 50);
    c.poseRateHz = s.number("poseRateHz", c.poseRateHz, 1, 100);
    c.statusPollHz = s.number("statusPollHz", c.statusPollHz, 0.2, 20);
    c.discoveryIntervalS = s.number("discoveryIntervalS", c.discoveryIntervalS, 1, 30);
    c.linkLostS = s.number("linkLostS", c.linkLostS, 0.5, 120);
    c.accessTimeoutS = s.number("accessTimeoutS", c.accessTimeoutS, 1, 255);
    c.eventConfirmTimeoutS = s.number("eventConfirmTimeoutS", c.eventConfirmTimeoutS, 0.2, 30);
    c.stopRepeats = int(s.integer("stopRepeats", c.stopRepeats, 2, 50));
    c.velocityDrive = s.choice("driveMode", "velocity", {"velocity", "wrench"}) == "velocity";
    s.finish();
    return c;
}

} // namespace ocu::jaus
