#include "sim/jaus/SimulatedUgv.h"

#include <boost/asio/steady_timer.hpp>

#include <atomic>
#include <mutex>

#include "protocols/common/IoThread.h"
#include "protocols/common/Log.h"
#include "protocols/jaus/JudpTransport.h"
#include "sim/jaus/SimCameraServer.h"

namespace ocu::sim {

using namespace ocu::jaus;

struct SimulatedUgv::Impl : JausOutput {
    Impl(SimulatedUgvConfig c, Clock& clk)
        : cfg(c), clock(clk), io("jaus-ugv-" + std::to_string(c.subsystemId)),
          transport(io.context(), c.network, counters, clock, "ocu.sim.jaus"),
          core(c, *this, clock, counters), timer(io.context()) {}

    void send(const JausId& dst, const Bytes& payload, SendOptions o) override {
        transport.send(core.platformManager(), dst, payload, o);
    }
    void sendFrom(const JausId& src, const JausId& dst, const Bytes& payload, SendOptions o) override {
        transport.send(src, dst, payload, o);
    }
    std::string sendOrWhy(const JausId& dst, const Bytes& payload, SendOptions o) override {
        return transport.send(core.platformManager(), dst, payload, o);
    }
    std::string endpointOf(const JausId& id) const override { return transport.endpointOf(id); }

    void applyNetFaults() {
        auto& f = core.faults();
        NetFaults n;
        n.loss = f.packetLoss;
        n.delay = std::chrono::milliseconds(f.delayMs);
        n.reorder = f.reorder;
        transport.setFaults(n);
    }
    void scheduleTick() {
        timer.expires_after(std::chrono::microseconds(long(1e6 / std::max(cfg.physicsRateHz, 1.0))));
        timer.async_wait([this](boost::system::error_code ec) {
            if (ec)
                return;
            core.tick();
            publishScene();
            scheduleTick();
        });
    }
    // What the cameras' threads read: the pose and pan-tilt of this tick.
    void publishScene() {
        const UgvState& st = core.state();
        std::lock_guard lock(sceneMutex);
        scene.x = st.x;
        scene.y = st.y;
        scene.yaw = st.yaw;
        pt = core.video().panTilt();
    }
    void createCameras() {
        std::vector<CameraStream> streams;
        for (const SimCameraConfig& c : cfg.cameras) {
            CameraStream s;
            s.path = "ugv" + std::to_string(cfg.subsystemId) + "/" + c.path;
            s.width = c.width;
            s.height = c.height_px;
            s.fps = c.fps;
            s.scene = [this, c](CameraPose& pose, std::vector<SceneBox>& boxes) {
                std::function<std::vector<SceneBox>()> others;
                {
                    std::lock_guard lock(sceneMutex);
                    pose.x = scene.x;
                    pose.y = scene.y;
                    pose.yaw = scene.yaw;
                    if (c.panTilt) {
                        pose.pan = pt.pan;
                        pose.tilt = pt.tilt;
                    }
                    others = neighbours;
                }
                pose.forwardOffset = c.forwardOffset;
                pose.height = c.height;
                pose.yawOffset = c.yawOffset;
                pose.horizontalFov = c.horizontalFov;
                if (others)
                    boxes = others();
            };
            streams.push_back(std::move(s));
        }
        cameras = std::make_unique<SimCameraServer>(std::move(streams));
    }
    // Tells the camera component the URLs (it registers them with the DRD on its next tick).
    void announceUrls() {
        for (const SimCameraConfig& c : cfg.cameras) {
            const std::string url = cameras->url("ugv" + std::to_string(cfg.subsystemId) + "/" + c.path);
            const std::uint16_t id = c.sensorId;
            io.post([this, id, url] { core.video().setUrl(id, url); });
        }
    }
    template <class F> void post(F&& f) {
        if (running)
            io.post(std::forward<F>(f));
        else
            f();
    }

    SimulatedUgvConfig cfg;
    Clock& clock;
    Counters counters;
    IoThread io;
    JudpTransport transport;
    UgvCore core;
    boost::asio::steady_timer timer;
    std::atomic<bool> running{false};
    std::shared_ptr<const SimulatedUgv::MessageTap> tap;
    std::atomic<std::uint16_t> port{0};
    std::atomic<std::uint16_t> tcpPort{0};
    // Cameras.
    std::unique_ptr<SimCameraServer> cameras;
    mutable std::mutex sceneMutex; // below
    SceneBox scene;
    PanTiltPose pt;
    std::function<std::vector<SceneBox>()> neighbours;
};

SimulatedUgv::SimulatedUgv(SimulatedUgvConfig config, Clock& clock)
    : m_impl(std::make_unique<Impl>(std::move(config), clock)) {
    m_impl->scene.x = m_impl->cfg.startX;
    m_impl->scene.y = m_impl->cfg.startY;
    m_impl->scene.yaw = m_impl->cfg.startYaw;
    m_impl->scene.length = m_impl->cfg.length;
    m_impl->scene.width = m_impl->cfg.width;
    m_impl->scene.height = m_impl->cfg.height;
    if (!m_impl->cfg.cameras.empty())
        m_impl->createCameras();
}

void SimulatedUgv::setMessageTap(MessageTap tap) {
    std::atomic_store(&m_impl->tap, tap ? std::make_shared<const MessageTap>(std::move(tap))
                                        : std::shared_ptr<const MessageTap>());
}

SimulatedUgv::~SimulatedUgv() {
    stop();
}

void SimulatedUgv::start() {
    Impl* d = m_impl.get();
    if (d->running)
        return;
    d->transport.setLocalIds([d](const JausId& id) { return d->core.isLocal(id); });
    d->transport.setHandlers(
        [d](const JausId& s, const JausId& t, ByteSpan p) {
            if (auto tap = std::atomic_load(&d->tap))
                (*tap)(p);
            d->core.handle(s, t, p);
        },
        {});
    d->transport.open();
    d->applyNetFaults();
    d->port = d->transport.localPort();
    d->tcpPort = d->transport.localTcpPort();
    logInfo("ocu.sim.jaus", "simulated UGV " + d->cfg.callSign + " (subsystem " +
                                std::to_string(d->cfg.subsystemId) + ") on UDP port " +
                                std::to_string(d->port.load()));
    d->running = true;
    d->io.start();
    d->io.post([d] {
        d->core.tick();
        d->scheduleTick();
    });
    if (d->cameras) {
        if (std::string why = d->cameras->start(); !why.empty())
            logWarning("ocu.sim.jaus", d->cfg.callSign + ": cameras not served: " + why);
        else
            d->announceUrls();
    }
}

void SimulatedUgv::stop() {
    if (!m_impl || !m_impl->running)
        return;
    Impl* d = m_impl.get();
    if (d->cameras)
        d->cameras->stop();
    d->io.call([d] {
        d->timer.cancel();
        d->transport.close();
        return 0;
    });
    d->running = false;
    d->io.stop();
}

bool SimulatedUgv::running() const {
    return m_impl->running;
}
std::uint16_t SimulatedUgv::localPort() const {
    return m_impl->port;
}
std::uint16_t SimulatedUgv::localTcpPort() const {
    return m_impl->tcpPort;
}
const SimulatedUgvConfig& SimulatedUgv::config() const {
    return m_impl->cfg;
}
Counters& SimulatedUgv::counters() {
    return m_impl->counters;
}

#define OCU_SIM_POST(body)                                                                                   \
    do {                                                                                                     \
        Impl* d = m_impl.get();                                                                              \
        d->post([=] { body; });                                                                              \
    } while (0)

void SimulatedUgv::setDropHeartbeat(bool on) {
    OCU_SIM_POST(d->core.faults().dropHeartbeat = on);
}
void SimulatedUgv::setHeartbeatRate(double hz) {
    OCU_SIM_POST(d->core.faults().heartbeatRateHz = hz);
}
void SimulatedUgv::setPacketLoss(double p) {
    OCU_SIM_POST(d->core.faults().packetLoss = p; d->applyNetFaults());
}
void SimulatedUgv::setPacketDelay(int ms) {
    OCU_SIM_POST(d->core.faults().delayMs = ms; d->applyNetFaults());
}
void SimulatedUgv::setReorder(bool on) {
    OCU_SIM_POST(d->core.faults().reorder = on; d->applyNetFaults());
}
void SimulatedUgv::setRejectControl(bool on) {
    OCU_SIM_POST(d->core.faults().rejectControl = on);
}
void SimulatedUgv::setRejectEvents(bool on) {
    OCU_SIM_POST(d->core.faults().rejectEvents = on);
}
void SimulatedUgv::setEventRateScale(double s) {
    OCU_SIM_POST(d->core.faults().eventRateScale = s);
}
void SimulatedUgv::setLoseDiscovery(bool on) {
    OCU_SIM_POST(d->core.faults().loseDiscovery = on);
}
void SimulatedUgv::preemptControl(std::uint8_t a) {
    OCU_SIM_POST(d->core.preemptControl(a));
}
void SimulatedUgv::forceDriveTimeout() {
    OCU_SIM_POST(d->core.forceDriveTimeout());
}
void SimulatedUgv::enterEmergency() {
    OCU_SIM_POST(d->core.enterEmergency());
}
void SimulatedUgv::enterFailure() {
    OCU_SIM_POST(d->core.enterFailure());
}
void SimulatedUgv::clearFailure() {
    OCU_SIM_POST(d->core.clearFailure());
}

#undef OCU_SIM_POST

void SimulatedUgv::stopCameras() {
    if (m_impl->cameras)
        m_impl->cameras->stop();
}
std::string SimulatedUgv::startCameras() {
    if (!m_impl->cameras)
        return "this UGV has no cameras";
    return m_impl->cameras->start();
}
bool SimulatedUgv::camerasRunning() const {
    return m_impl->cameras && m_impl->cameras->running();
}
std::string SimulatedUgv::cameraUrl(std::uint16_t sensorId) const {
    if (!m_impl->cameras)
        return {};
    for (const SimCameraConfig& c : m_impl->cfg.cameras)
        if (c.sensorId == sensorId)
            return m_impl->cameras->url("ugv" + std::to_string(m_impl->cfg.subsystemId) + "/" + c.path);
    return {};
}
std::uint64_t SimulatedUgv::cameraFramesRendered() const {
    return m_impl->cameras ? m_impl->cameras->framesRendered() : 0;
}
void SimulatedUgv::setNeighbours(std::function<std::vector<SceneBox>()> neighbours) {
    std::lock_guard lock(m_impl->sceneMutex);
    m_impl->neighbours = std::move(neighbours);
}
SceneBox SimulatedUgv::box() const {
    std::lock_guard lock(m_impl->sceneMutex);
    return m_impl->scene;
}
PanTiltPose SimulatedUgv::panTilt() const {
    std::lock_guard lock(m_impl->sceneMutex);
    return m_impl->pt;
}

UgvState SimulatedUgv::state() const {
    Impl* d = m_impl.get();
    return d->io.call([d] { return d->core.state(); });
}

UgvRoute SimulatedUgv::route() const {
    Impl* d = m_impl.get();
    return d->io.call([d] { return d->core.route(); });
}

jaus::GlobalPose SimulatedUgv::globalPose() const {
    Impl* d = m_impl.get();
    return d->io.call([d] { return d->core.globalPose(); });
}

} // namespace ocu::sim
