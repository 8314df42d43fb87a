// The site configuration's "jaus" section: defaults, every key, and strict rejection of bad values.
#include <QtTest>

#include "protocols/common/ConfigReader.h"
#include "protocols/jaus/JausConfig.h"

using namespace ocu;
using namespace ocu::jaus;

namespace {

struct Parsed {
    JausConfig config;
    ConfigErrors errors;
};

Parsed parse(const char* json) {
    Parsed p;
    auto doc = ConfigDocument::parse(json, "site.json");
    if (!doc)
        qFatal("%s", doc.error().c_str());
    ConfigObject section(*doc, "/jaus", p.errors);
    p.config = parseJausConfig(section);
    return p;
}

} // namespace

class TestJausConfig : public QObject {
    Q_OBJECT

private slots:
    void defaults() {
        auto p = parse(R"({"jaus": {}})");
        QVERIFY2(p.errors.empty(), p.errors.joined().c_str());
        const JausConfig& c = p.config;
        QCOMPARE(c.authority, std::uint8_t(205));
        QCOMPARE(c.role, Role::PrimaryOperator);
        QCOMPARE(c.transport.port, std::uint16_t(3794));
        QCOMPARE(c.transport.multicastGroup, std::string("239.255.0.1"));
        QCOMPARE(c.transport.multicastPort, std::uint16_t(3794));
        QVERIFY(c.transport.multicast);
        QCOMPARE(c.driveRateHz, 20.0);
        QCOMPARE(c.linkLostS, 5.0);
        QCOMPARE(c.accessTimeoutS, 5.0);
        QVERIFY(c.mayControl());
    }
    void everyKey() {
        auto p = parse(R"({"jaus": {
            "subsystem_id": 150, "node_id": 64, "component_id": 200, "call_sign": "BASE-1",
            "role": "primary_operator", "authority": 230,
            "bind_address": "127.0.0.1", "port": 0, "broadcast_mode": "broadcast",
            "multicast_group": "239.255.0.2", "multicast_port": 4000, "multicast_ttl": 2,
            "interface_address": "127.0.0.1", "broadcast_address": "127.255.255.255",
            "static_endpoints": [ {"subsystem": 126, "address": "10.0.0.5", "port": 3794},
                                  {"subsystem": 127, "node": 3, "component": 1, "address": "10.0.0.6",
                                   "transport": "tcp"} ],
            "jtcp_server": true, "jtcp_port": 3795,
            "drive_rate_hz": 25, "heartbeat_rate_hz": 2, "pose_rate_hz": 5, "status_poll_hz": 2,
            "discovery_interval_s": 10, "link_lost_s": 3, "access_timeout_s": 4, "event_confirm_timeout_s": 1,
            "stop_repeats": 6, "drive_mode": "wrench", "plausible_extent_m": 2000,
            "plausible_speed_max_mps": 4, "plausible_jump_slack_m": 5 }})");
        QVERIFY2(p.errors.empty(), p.errors.joined().c_str());
        const JausConfig& c = p.config;
        QCOMPARE(c.ownId(), (JausId{150, 64, 200}));
        QCOMPARE(c.callSign, std::string("BASE-1"));
        QCOMPARE(c.authority, std::uint8_t(230));
        QCOMPARE(c.transport.port, std::uint16_t(0));
        QVERIFY(!c.transport.multicast);
        QCOMPARE(c.transport.multicastPort, std::uint16_t(4000));
        QCOMPARE(c.transport.staticEndpoints.size(), std::size_t(2));
        QCOMPARE(c.transport.staticEndpoints[0].id, (JausId{126, 255, 255}));
        QCOMPARE(c.transport.staticEndpoints[1].id, (JausId{127, 3, 1}));
        QCOMPARE(c.transport.staticEndpoints[1].port, std::uint16_t(3794));
        QVERIFY(c.transport.staticEndpoints[1].tcp && !c.transport.staticEndpoints[0].tcp);
        QVERIFY(c.transport.jtcpServer);
        QCOMPARE(c.transport.jtcpPort, std::uint16_t(3795));
        QCOMPARE(c.driveRateHz, 25.0);
        QCOMPARE(c.stopRepeats, 6);
        QVERIFY(!c.velocityDrive);
        QCOMPARE(c.plausibility, (PoseLimits{2000, 4, 5}));
        QCOMPARE(JausConfig{}.plausibility, (PoseLimits{50000, 30, 50})); // the safe defaults
    }
    // Streams configured for a vehicle that announces none.
    void configuredVideo() {
        // Plain literals: moc's scanner mistakes "//" inside a raw string for a comment.
        auto p = parse("{\"jaus\": {\"static_endpoints\": [{\"subsystem\": 127, \"address\": \"127.0.0.1\", "
                       "\"video\": [{\"url\": \"rtsp:\\/\\/10.0.0.5:8554/front\", \"name\": \"front\", "
                       "\"sensor_id\": 1000}, {\"url\": \"rtsp:\\/\\/10.0.0.5:8554/rear\"}]}]}}");
        QVERIFY2(p.errors.empty(), p.errors.joined().c_str());
        const auto& v = p.config.configuredVideo.at(127);
        QCOMPARE(v.size(), std::size_t(2));
        QCOMPARE(v[0].url, std::string("rtsp:") + "/" + "/10.0.0.5:8554/front");
        QCOMPARE(v[0].name, std::string("front"));
        QCOMPARE(v[0].sensorId, std::uint16_t(1000));
        QVERIFY(v[0].configured && v[1].configured);
        auto bad =
            parse("{\"jaus\": {\"static_endpoints\": [{\"subsystem\": 127, \"address\": \"127.0.0.1\", "
                  "\"video\": [{\"url\": \"front camera\"}, {\"name\": \"x\"}, "
                  "{\"url\": \"rtsp:\\/\\/ok/1\", \"colour\": 1}]}]}}");
        const std::string errors = bad.errors.joined();
        QVERIFY2(errors.find("is not a stream URL") != std::string::npos, errors.c_str());
        QVERIFY2(errors.find("colour") != std::string::npos, errors.c_str()); // unknown key reported
        QCOMPARE(bad.config.configuredVideo[127].size(), std::size_t(1));     // the good one is kept
    }

    void roles() {
        auto m = parse(R"({"jaus": {"role": "monitor"}})");
        QVERIFY(m.errors.empty());
        QCOMPARE(m.config.authority, std::uint8_t(0));
        QVERIFY(!m.config.mayControl());
        auto sc = parse(R"({"jaus": {"role": "safety_critical"}})");
        QVERIFY(sc.errors.empty());
        QCOMPARE(sc.config.authority, std::uint8_t(240));
        QVERIFY(sc.config.mayControl());
    }
    void rejectsBadValues() {
        struct Case {
            const char* json;
            const char* mentions;
        } cases[] = {
            {R"({"jaus": {"authority": 0}})", "authority"},
            {R"({"jaus": {"authority": 240}})", "primary_operator band"},
            {R"({"jaus": {"role": "monitor", "authority": 205}})", "authority"},
            {R"({"jaus": {"authority": 300}})", "authority"},
            {R"({"jaus": {"role": "admin"}})", "role"},
            {R"({"jaus": {"port": 70000}})", "port"},
            {R"({"jaus": {"port": "3794"}})", "port"},
            {R"({"jaus": {"multicast_group": "not-an-ip"}})", "multicast_group"},
            {R"({"jaus": {"drive_rate_hz": 0.5}})", "drive_rate_hz"},
            {R"({"jaus": {"subsystem_id": 65535}})", "subsystem_id"},
            {R"({"jaus": {"callsign": "typo"}})", "callsign"},
            {R"({"jaus": {"call_sign": ""}})", "call_sign"},
            {R"({"jaus": {"static_endpoints": [{"subsystem": 1, "adress": "1.2.3.4"}]}})", "adress"},
            {R"({"jaus": {"static_endpoints": [{"subsystem": 1, "transport": "sctp"}]}})", "transport"},
        };
        for (auto& c : cases) {
            auto p = parse(c.json);
            QVERIFY2(!p.errors.empty(), c.json);
            QVERIFY2(p.errors.joined().find(c.mentions) != std::string::npos, p.errors.joined().c_str());
        }
    }
};

QTEST_GUILESS_MAIN(TestJausConfig)
#include "test_jaus_config.moc"
