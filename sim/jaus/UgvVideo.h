#pragma once
// The simulated UGV's video services (AEP-4818 §9.1.2-9.1.8, §9.3.3; layouts in
// shared/research/jaus-services-extra.md): a socket-free state machine beside UgvCore.
//  * platform manager ss.1.1: urn:jaus:jss:iop:DigitalResourceDiscovery 1.1 (Query/Register/Remove, IDs
//    1..254, re-registering the same (JAUS_ID, ResourceID) keeps its ID; no Confirm for an unknown Remove);
//  * camera component ss.4.1: VisualSensor 1.0 + DigitalVideo 1.0 for every camera (capabilities with the
//    camera name, configuration, geometry: the pan-tilt camera reports "on manipulator ss.4.2 joint 2",
//    V1.JAUS-57), ControlDigitalVideoSensorStream accepted and ignored (RTSP controls the stream, §9.1.3);
//    it registers each stream with the DRD (RegisterDigitalResourceEndpoint / Confirm) once its RTSP URL is
//    known, and again until confirmed (V1.JAUS-~55);
//  * pan-tilt component ss.4.2: PanTiltJointVelocityDriver + PanTiltJointPositionSensor 2.0 with its own
//    access control and management (commands only from the controller in READY), actuator drive timeout 1 s
//    (§9.3.1.2), joint limits pan ±170°, tilt -45°..+30°.
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "protocols/common/Clock.h"
#include "protocols/common/Counters.h"
#include "protocols/jaus/Messages.h"
#include "protocols/jaus/MessagesVideo.h"

namespace ocu::sim {

struct SimCameraConfig {
    std::uint16_t sensorId = 1000; // 1000-1032: drive cameras (AEP-4818 §9.1.2)
    std::string name = "front";
    std::string path = "front"; // RTSP mount point /<path>
    double yawOffset = 0;       // rad, camera axis relative to the vehicle's heading (rear = π)
    double forwardOffset = 0.5; // m ahead of the reference point (negative: behind)
    double height = 1.1;        // m above ground
    double horizontalFov = 1.2; // rad
    bool panTilt = false;       // mounted on the pan-tilt unit
    int width = 640, height_px = 360, fps = 15;
};

// What a camera's renderer needs of the pan-tilt (thread-safe copies are made by SimulatedUgv).
struct PanTiltPose {
    double pan = 0, tilt = 0; // rad, + pan = right, + tilt = up
};

class UgvVideo {
public:
    // send(from, to, payload): messages leave through UgvCore's output.
    using Send = std::function<void(const jaus::JausId&, const jaus::JausId&, const Bytes&)>;
    UgvVideo(std::uint16_t subsystem, std::vector<SimCameraConfig> cameras, Send send, const Clock& clock,
             Counters& counters);

    jaus::JausId platformManager() const { return {m_ss, 1, 1}; }
    jaus::JausId camera() const { return {m_ss, 4, 1}; }
    jaus::JausId panTiltUnit() const { return {m_ss, 4, 2}; }
    bool isLocal(const jaus::JausId& id) const { return id == camera() || id == panTiltUnit(); }
    bool enabled() const { return !m_cameras.empty(); }

    // Services for ReportServices: added to the platform manager's list, and node 4's components.
    std::vector<jaus::ServiceRecord> platformManagerServices() const;
    std::vector<jaus::ComponentServices> node4() const;
    // Handles a message for component `to` (true when this service set handles its ID there).
    bool handle(const jaus::JausId& to, const jaus::JausId& src, std::uint16_t id, ByteSpan payload);
    // Registration retries, pan-tilt motion and timeouts.
    void tick();

    // The RTSP URL of a camera (empty: the server is down). Registration follows on the next tick.
    void setUrl(std::uint16_t sensorId, const std::string& url);
    PanTiltPose panTilt() const { return m_pt; }
    const std::vector<jaus::DigitalResourceEndpoint>& registered() const { return m_drdList; }
    const std::vector<SimCameraConfig>& cameras() const { return m_cameras; }
    bool panTiltControlled() const { return m_ptController.subsystem != 0; }

private:
    struct Registration {
        std::string url;  // what should be registered ("" = removed)
        std::string sent; // what the DRD confirmed
        std::optional<std::uint8_t> endpointId;
        std::uint8_t requestId = 0;
        TimePoint lastTry{};
    };
    void send(const jaus::JausId& from, const jaus::JausId& to, const Bytes& b) { m_send(from, to, b); }
    // The DRD server side, and the registrant's handling of its Confirm (both in this subsystem).
    Bytes drdRegister(const jaus::RegisterDigitalResourceEndpoint& m, const jaus::JausId& src,
                      bool& confirmed);
    bool drdRemove(const jaus::RemoveDigitalResourceEndpoint& m);
    void registerStreams(TimePoint now);
    bool handleCamera(const jaus::JausId& src, std::uint16_t id, ByteSpan p);
    bool handlePanTilt(const jaus::JausId& src, std::uint16_t id, ByteSpan p);
    void panTiltPhysics(TimePoint now);

    std::uint16_t m_ss;
    std::vector<SimCameraConfig> m_cameras;
    Send m_send;
    const Clock& m_clock;
    Counters& m_counters;
    // DRD table: endpoint ID -> (registrant, endpoint)
    std::map<std::uint8_t, std::pair<jaus::JausId, jaus::DigitalResourceEndpoint>> m_drd;
    std::vector<jaus::DigitalResourceEndpoint> m_drdList;
    std::map<std::uint16_t, Registration> m_reg;
    std::uint8_t m_nextRequest = 1;
    // Pan-tilt unit.
    jaus::JausId m_ptController;
    std::uint8_t m_ptAuthority = 0;
    TimePoint m_ptLastRequest{}, m_ptLastCommand{}, m_ptLastPhysics{};
    jaus::ManagementState m_ptState = jaus::ManagementState::Standby;
    PanTiltPose m_pt, m_ptRate;
    bool m_started = false;
};

} // namespace ocu::sim
