#pragma once
// Starts N simulated UGVs on loopback (free ports, one multicast group) and points a JausConfig at them:
// the built-in simulated site and ocu-sim use it.
#include <functional>
#include <memory>
#include <vector>

#include "protocols/jaus/JausConfig.h"
#include "sim/jaus/SimulatedUgv.h"

namespace ocu::sim {

struct JausDemoOptions {
    int count = 2;
    std::uint16_t firstSubsystemId = 126;
    GeoPoint origin{48.137154, 11.576124, 520}; // site origin: UGVs start around it
    double spacingM = 10;                       // start positions: a row along east
    bool alternateKinematics = true;            // odd ones Ackermann
    std::string multicastGroup = "239.255.0.1";
    double accessTimeoutS = 5;
    double driveTimeoutS = 1;
    // 127.0.0.1 keeps everything on the host (TTL 0); another address serves consoles on other hosts.
    std::string interfaceAddress = "127.0.0.1";
    // Every UGV serves a front camera on a pan-tilt (sensor 1000) and a rear camera (1001) over
    // RTSP on 127.0.0.1, announced through Digital Resource Discovery. Off by default (tests that need no
    // video start no GStreamer); the simulated site turns it on.
    bool video = false;
    int videoWidth = 640, videoHeight = 360, videoFps = 15;
    // Adjusts every UGV's configuration before it starts (tests: a faster vehicle, so that missions end
    // sooner with the same route logic); empty = the defaults above.
    std::function<void(SimulatedUgvConfig&)> adjustUgv;
};

class JausDemo {
public:
    // Picks a free multicast port, starts the UGVs; throws std::runtime_error when sockets fail.
    explicit JausDemo(JausDemoOptions options = {});
    ~JausDemo();

    // Sets the OCU's transport to loopback, the demo's multicast group/port, an ephemeral unicast port and a
    // static table entry for every UGV (so unicast works before the first multicast answer).
    void configure(jaus::JausConfig& config) const;
    std::vector<std::unique_ptr<SimulatedUgv>>& ugvs() { return m_ugvs; }
    SimulatedUgv* find(std::uint16_t subsystem);
    std::uint16_t multicastPort() const { return m_mcPort; }
    void stop();

    // Loopback transport settings (127.0.0.1, TTL 0, the given multicast port, ephemeral unicast port).
    static jaus::TransportSettings loopbackTransport(std::uint16_t multicastPort,
                                                     const std::string& group = "239.255.0.1",
                                                     const std::string& interfaceAddress = "127.0.0.1");

private:
    JausDemoOptions m_opt;
    std::uint16_t m_mcPort = 0;
    std::vector<std::unique_ptr<SimulatedUgv>> m_ugvs;
};

} // namespace ocu::sim
