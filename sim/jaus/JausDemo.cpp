#include "sim/jaus/JausDemo.h"

#include "protocols/common/Udp.h"

namespace ocu::sim {

jaus::TransportSettings JausDemo::loopbackTransport(std::uint16_t multicastPort, const std::string& group,
                                                    const std::string& interfaceAddress) {
    jaus::TransportSettings t;
    const bool loopback = interfaceAddress == "127.0.0.1";
    t.bindAddress = loopback ? "127.0.0.1" : "0.0.0.0";
    t.port = 0;
    t.multicast = true;
    t.multicastGroup = group;
    t.multicastPort = multicastPort;
    t.multicastTtl = loopback ? 0 : 1; // on loopback never leaves the host (toolchain.md §7)
    t.interfaceAddress = interfaceAddress;
    return t;
}

JausDemo::JausDemo(JausDemoOptions options) : m_opt(std::move(options)) {
    m_mcPort = findFreeUdpPort();
    for (int i = 0; i < m_opt.count; ++i) {
        SimulatedUgvConfig c;
        c.subsystemId = std::uint16_t(m_opt.firstSubsystemId + i);
        c.callSign = "UGV-" + std::to_string(c.subsystemId);
        c.kinematics =
            (m_opt.alternateKinematics && i % 2 == 1) ? Kinematics::Ackermann : Kinematics::SkidSteer;
        c.origin = m_opt.origin;
        c.startX = 0;
        c.startY = m_opt.spacingM * i;
        c.accessTimeoutS = m_opt.accessTimeoutS;
        c.driveTimeoutS = m_opt.driveTimeoutS;
        c.network = loopbackTransport(m_mcPort, m_opt.multicastGroup, m_opt.interfaceAddress);
        if (m_opt.video) {
            SimCameraConfig front;
            front.sensorId = 1000; // drive cameras 1000-1032 (AEP-4818 §9.1.2)
            front.name = "front (pan-tilt)";
            front.path = "front";
            front.panTilt = true;
            SimCameraConfig rear;
            rear.sensorId = 1001;
            rear.name = "rear";
            rear.path = "rear";
            rear.yawOffset = 3.14159265358979;
            rear.forwardOffset = -0.5;
            rear.height = 0.9;
            for (SimCameraConfig* k : {&front, &rear}) {
                k->width = m_opt.videoWidth;
                k->height_px = m_opt.videoHeight;
                k->fps = m_opt.videoFps;
            }
            c.cameras = {front, rear};
        }
        if (m_opt.adjustUgv)
            m_opt.adjustUgv(c);
        auto u = std::make_unique<SimulatedUgv>(c);
        u->start();
        m_ugvs.push_back(std::move(u));
    }
    // Each camera shows the other UGVs as boxes.
    for (auto& u : m_ugvs) {
        SimulatedUgv* self = u.get();
        u->setNeighbours([this, self] {
            std::vector<SceneBox> out;
            for (auto& o : m_ugvs)
                if (o.get() != self)
                    out.push_back(o->box());
            return out;
        });
    }
}

JausDemo::~JausDemo() {
    stop();
}

void JausDemo::stop() {
    for (auto& u : m_ugvs)
        u->stop();
}

SimulatedUgv* JausDemo::find(std::uint16_t ss) {
    for (auto& u : m_ugvs)
        if (u->config().subsystemId == ss)
            return u.get();
    return nullptr;
}

void JausDemo::configure(jaus::JausConfig& config) const {
    auto statics = config.transport.staticEndpoints;
    config.transport = loopbackTransport(m_mcPort, m_opt.multicastGroup, m_opt.interfaceAddress);
    config.transport.staticEndpoints = statics;
    for (auto& u : m_ugvs) {
        jaus::StaticEndpoint e;
        e.id = jaus::JausId{u->config().subsystemId, 0xFF, 0xFF};
        e.address = m_opt.interfaceAddress;
        e.port = u->localPort();
        config.transport.staticEndpoints.push_back(e);
    }
}

} // namespace ocu::sim
