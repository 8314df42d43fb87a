#pragma once
// A simulated RAS-G IOP UGV on its own io thread: UgvCore behind a JudpTransport (AEP-4818 §10).
// Several can run at once (distinct subsystem IDs, distinct unicast ports, one shared multicast group).
#include <functional>
#include <memory>
#include <optional>

#include "protocols/common/Clock.h"
#include "protocols/common/Counters.h"
#include "sim/jaus/CameraScene.h"
#include "sim/jaus/UgvCore.h"

namespace ocu::sim {

class SimulatedUgv {
public:
    explicit SimulatedUgv(SimulatedUgvConfig config, ocu::Clock& clock = SteadyClock::instance());
    ~SimulatedUgv();
    SimulatedUgv(const SimulatedUgv&) = delete;
    SimulatedUgv& operator=(const SimulatedUgv&) = delete;

    // Throws std::runtime_error when the sockets cannot be opened.
    void start();
    void stop();
    bool running() const;
    std::uint16_t localPort() const;    // unicast port actually bound
    std::uint16_t localTcpPort() const; // JTCP server port (network.jtcpServer), else 0
    const SimulatedUgvConfig& config() const;

    // Thread-safe fault injection (AEP-4818 §10 item 24).
    void setDropHeartbeat(bool on);
    void setHeartbeatRate(double hz);
    void setPacketLoss(double probability);
    void setPacketDelay(int milliseconds);
    void setReorder(bool on);
    void setRejectControl(bool on);
    void setRejectEvents(bool on);
    void setEventRateScale(double scale);
    void setLoseDiscovery(bool on);
    void preemptControl(std::uint8_t authority = 255);
    void forceDriveTimeout();
    void enterEmergency();
    void enterFailure();
    void clearFailure();

    // Every message payload the UGV receives, on its io thread, before it is handled (benchmarks measure
    // command latency on the wire with it). Empty function removes the tap.
    using MessageTap = std::function<void(ByteSpan payload)>;
    void setMessageTap(MessageTap tap);

    // The cameras (config().cameras) served over RTSP on 127.0.0.1 by a SimCameraServer started
    // with the UGV and registered through Digital Resource Discovery. Stopping the server (loss drills and
    // tests) keeps the registration, as a camera whose server fails would; starting it again keeps the URL.
    void stopCameras();
    std::string startCameras(); // empty, or why the server could not start
    bool camerasRunning() const;
    std::string cameraUrl(std::uint16_t sensorId) const; // empty when no such camera or the server is down
    std::uint64_t cameraFramesRendered() const;
    // The other machines the cameras show as boxes (called on the cameras' threads; thread-safe function).
    void setNeighbours(std::function<std::vector<SceneBox>()> neighbours);
    // This UGV as a box for the others' cameras (thread-safe, from the latest physics tick).
    SceneBox box() const;
    // The pan-tilt unit's joint positions (thread-safe, latest tick).
    PanTiltPose panTilt() const;

    // Blocking snapshot of the simulated state (tests, demo).
    UgvState state() const;
    UgvRoute route() const; // the waypoint services' list, active element and path
    jaus::GlobalPose globalPose() const;
    Counters& counters();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace ocu::sim
