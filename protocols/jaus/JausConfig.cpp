#include "protocols/jaus/JausConfig.h"

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
    c.subsystemId = std::uint16_t(s.integer("subsystem_id", c.subsystemId, 1, 65534));
    c.nodeId = std::uint8_t(s.integer("node_id", c.nodeId, 1, 254));
    c.componentId = std::uint8_t(s.integer("component_id", c.componentId, 1, 254));
    c.callSign = s.string("call_sign", c.callSign);
    if (c.callSign.empty() || c.callSign.size() > 255)
        s.error("call_sign", "the call sign must have 1 to 255 characters");
    const std::string role =
        s.choice("role", "primary_operator", {"monitor", "primary_operator", "safety_critical"});
    c.role = role == "monitor"           ? Role::Monitor
             : role == "safety_critical" ? Role::SafetyCritical
                                         : Role::PrimaryOperator;
    // Authority must lie in the role's band (AEP-4818 §4.3.2); MONITOR is 0 and never requests control.
    const int lo = c.role == Role::Monitor ? 0 : c.role == Role::PrimaryOperator ? 205 : 240;
    const int hi = c.role == Role::Monitor ? 0 : c.role == Role::PrimaryOperator ? 239 : 254;
    const std::int64_t a = s.integer("authority", lo, 0, 255);
    if (a < lo || a > hi) {
        s.error("authority", "authority " + std::to_string(a) + " is outside the " + role + " band [" +
                                 std::to_string(lo) + ", " + std::to_string(hi) + "]");
        c.authority = std::uint8_t(lo);
    } else {
        c.authority = std::uint8_t(a);
    }

    auto& t = c.transport;
    t.bindAddress = checkedAddress(s, "bind_address", t.bindAddress);
    t.port = std::uint16_t(s.integer("port", t.port, 0, 65535));
    t.multicast = s.choice("broadcast_mode", "multicast", {"multicast", "broadcast"}) == "multicast";
    t.multicastGroup = checkedAddress(s, "multicast_group", t.multicastGroup);
    t.multicastPort = std::uint16_t(s.integer("multicast_port", t.multicastPort, 1, 65535));
    t.multicastTtl = int(s.integer("multicast_ttl", t.multicastTtl, 0, 255));
    t.interfaceAddress = checkedAddress(s, "interface_address", t.interfaceAddress);
    t.broadcastAddress = checkedAddress(s, "broadcast_address", t.broadcastAddress);
    for (auto& e : s.objectList("static_endpoints")) {
        StaticEndpoint se;
        se.id.subsystem = std::uint16_t(e.integer("subsystem", 0, 1, 65534));
        se.id.node = std::uint8_t(e.integer("node", 255, 1, 255));
        se.id.component = std::uint8_t(e.integer("component", 255, 1, 255));
        se.address = checkedAddress(e, "address", "127.0.0.1");
        se.port = std::uint16_t(e.integer("port", 3794, 1, 65535));
        se.tcp = e.choice("transport", "udp", {"udp", "tcp"}) == "tcp";
        // Cameras of a vehicle that announces none through Digital Resource Discovery.
        for (auto& v : e.objectList("video")) {
            VideoEndpoint ve;
            ve.url = v.string("url", "");
            const auto scheme = ve.url.find("://");
            if (ve.url.empty() || ve.url.size() > 255 || scheme == std::string::npos || scheme == 0)
                v.error("url", "'" + ve.url + "' is not a stream URL (e.g. rtsp://192.168.1.50:8554/front)");
            ve.name = v.string("name", "");
            ve.sensorId = std::uint16_t(v.integer("sensor_id", 0, 0, 65535));
            ve.resourceId = ve.sensorId;
            ve.configured = true;
            v.finish();
            if (!ve.url.empty() && scheme != std::string::npos && scheme != 0 && ve.url.size() <= 255)
                c.configuredVideo[se.id.subsystem].push_back(ve);
        }
        e.finish();
        t.staticEndpoints.push_back(se);
    }
    t.jtcpServer = s.boolean("jtcp_server", t.jtcpServer);
    t.jtcpPort = std::uint16_t(s.integer("jtcp_port", t.jtcpPort, 0, 65535));

    c.driveRateHz = s.number("drive_rate_hz", c.driveRateHz, 2, 100);
    c.heartbeatRateHz = s.number("heartbeat_rate_hz", c.heartbeatRateHz, 1, 50);
    c.poseRateHz = s.number("pose_rate_hz", c.poseRateHz, 1, 100);
    c.statusPollHz = s.number("status_poll_hz", c.statusPollHz, 0.2, 20);
    c.discoveryIntervalS = s.number("discovery_interval_s", c.discoveryIntervalS, 1, 30);
    c.linkLostS = s.number("link_lost_s", c.linkLostS, 0.5, 120);
    c.accessTimeoutS = s.number("access_timeout_s", c.accessTimeoutS, 1, 255);
    c.eventConfirmTimeoutS = s.number("event_confirm_timeout_s", c.eventConfirmTimeoutS, 0.2, 30);
    c.stopRepeats = int(s.integer("stop_repeats", c.stopRepeats, 2, 50));
    c.driveCommandTimeoutS = s.number("drive_command_timeout_s", c.driveCommandTimeoutS, 0, 10);
    // Plausibility gate for poses: outside these a pose is not drawn.
    c.plausibility.extentM = s.number("plausible_extent_m", c.plausibility.extentM, 10, 1e6);
    c.plausibility.maxSpeedMps = s.number("plausible_speed_max_mps", c.plausibility.maxSpeedMps, 0.1, 1000);
    c.plausibility.jumpSlackM = s.number("plausible_jump_slack_m", c.plausibility.jumpSlackM, 0, 1e5);
    c.velocityDrive = s.choice("drive_mode", "velocity", {"velocity", "wrench"}) == "velocity";
    s.finish();
    return c;
}

} // namespace ocu::jaus
