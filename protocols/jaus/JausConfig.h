#pragma once
// The site configuration's "jaus" section (docs/jaus.md lists every key).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "protocols/common/ConfigReader.h"
#include "protocols/common/PosePlausibility.h"
#include "protocols/jaus/JudpCodec.h"
#include "protocols/jaus/VideoTypes.h"

namespace ocu::jaus {

struct StaticEndpoint {
    JausId id;           // component 255 / node 255 allowed: all components of that node / subsystem
    std::string address; // IPv4
    std::uint16_t port = 3794;
    bool tcp = false; // reach this peer over JTCP (a static list is required for JTCP, AEP-4818 §4.7.1)
};

// AEP-4818 §4.3.2 authority bands an OCU may use: MONITOR 0, PRIMARY_OPERATOR 205-239, SAFETY_CRITICAL
// 240-254.
enum class Role { Monitor, PrimaryOperator, SafetyCritical };

// UDP settings shared by the OCU stack and the simulated UGV.
struct TransportSettings {
    std::string bindAddress = "0.0.0.0";
    std::uint16_t port = 3794; // 0 = ephemeral (replies still reach us: peers learn our source port)
    bool multicast = true;     // logical broadcasts by multicast (default) or UDP broadcast
    std::string multicastGroup = "239.255.0.1";
    std::uint16_t multicastPort = 3794;
    int multicastTtl = 16; // JTS nm.cfg default
    std::string interfaceAddress = "0.0.0.0";
    std::string broadcastAddress = "255.255.255.255"; // when multicast is false
    std::vector<StaticEndpoint> staticEndpoints;
    std::size_t maxFragmentPayload = kMaxFragmentPayload;
    bool jtcpServer = false;       // accept JTCP connections
    std::uint16_t jtcpPort = 3794; // JTCP listening port (0 = ephemeral)
};

struct JausConfig {
    std::uint16_t subsystemId = 200;
    std::uint8_t nodeId = 1;
    std::uint8_t componentId = 1;
    std::string callSign = "OCU";
    Role role = Role::PrimaryOperator;
    std::uint8_t authority = 205; // PRIMARY_OPERATOR band 205-239 (AEP-4818 §4.3.2); MONITOR = 0

    TransportSettings transport;

    double driveRateHz = 20;    // drive stream while a session is open
    double heartbeatRateHz = 1; // requested ReportHeartbeatPulse event rate (≥ 1 Hz, AEP-4818 §4.8)
    double poseRateHz = 10;     // requested pose / velocity-state event rate
    double statusPollHz = 1;    // QueryStatus / QueryControl polling (a mission's active element: ≥ 1 Hz)
    double discoveryIntervalS = 30;  // re-check of every platform manager (AEP-4818 §6.2.2.2.2.1)
    double linkLostS = 5;            // link down after this long without any message
    double accessTimeoutS = 5;       // assumed access-control timeout until QueryTimeout answers
    double eventConfirmTimeoutS = 2; // no ConfirmEventRequest by then: fall back to polling
    int stopRepeats = 5;             // zero commands sent on stop (never a single message)
    // The console's drive demand must be refreshed within this time, or the stream goes to zero: a frozen
    // GUI or script must not keep a vehicle moving on its last command. 0 disables.
    double driveCommandTimeoutS = 0.5;
    bool velocityDrive = true; // default drive mode when a platform offers both drivers
    // Poses outside these are not drawn: the vehicle is marked implausible, its last good pose kept
    // (checked by the console's bridge in the site frame).
    PoseLimits plausibility;
    // Video streams per subsystem for vehicles that announce none: the "video" list of a
    // static_endpoints entry. Published with configured = true beside what the vehicle announces.
    std::map<std::uint16_t, std::vector<VideoEndpoint>> configuredVideo;

    JausId ownId() const { return JausId{subsystemId, nodeId, componentId}; }
    bool mayControl() const { return role != Role::Monitor && authority > 0; }
    // The stop rule, decided here only (the bridge, panels and headless ask it): every role may
    // set an emergency (the Management service accepts SetEmergency from any client, AS6009 Management),
    // only roles with command rights may clear one.
    bool mayStop() const { return true; }
    bool mayClearStop() const { return mayControl(); }
};

// Reads the "jaus" object strictly; errors go to the ConfigErrors of the section. Calls section.finish().
JausConfig parseJausConfig(ocu::ConfigObject& section);

} // namespace ocu::jaus
