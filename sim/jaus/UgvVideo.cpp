#include "sim/jaus/UgvVideo.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "protocols/common/Log.h"

namespace ocu::sim {

using namespace ocu::jaus;

namespace {
constexpr const char* kVideoLog = "ocu.sim.jaus";
constexpr double kPanLimit = 170 * std::numbers::pi / 180, kTiltMin = -45 * std::numbers::pi / 180,
                 kTiltMax = 30 * std::numbers::pi / 180;
constexpr double kMaxRate = 1.5;        // rad/s, the unit's own limit
constexpr double kPtAccessTimeoutS = 5; // AEP-4818 §4.3.4 default
constexpr double kActuatorTimeoutS = 1; // AEP-4818 §9.3.1.2 default
constexpr std::uint8_t kPtDefaultAuthority = 1;

double seconds(Duration d) {
    return std::chrono::duration<double>(d).count();
}
std::uint8_t frameSizeOf(int w, int h) {
    if (w == 640 && h == 480)
        return kFrameSize640x480;
    if (w == 1280 && h == 720)
        return kFrameSize1280x720;
    if (w == 1920 && h == 1080)
        return kFrameSize1920x1080;
    return 0xFF; // not an AS6060 frame size: the field is left out
}

// The presence vector asked for `sensor` (a query for sensor 0 asks for every sensor); nullopt: not asked.
std::optional<std::uint16_t> wanted(std::uint16_t sensor, const QuerySensors& q) {
    for (const SensorQuery& s : q.sensors)
        if (s.sensorId == 0 || s.sensorId == sensor)
            return s.presence;
    return std::nullopt;
}

ReportVisualSensorCapabilities visualCapabilities(const std::vector<SimCameraConfig>& cameras,
                                                  const QuerySensors& q) {
    ReportVisualSensorCapabilities r;
    for (const SimCameraConfig& c : cameras)
        if (auto pv = wanted(c.sensorId, q)) {
            VisualSensorCapabilities v;
            v.sensorId = c.sensorId;
            v.name = c.name;
            if (*pv & 0x01)
                v.supportedStates = 0x01; // Active only
            if (*pv & 0x10)
                v.imagingModes = 0x01; // Color
            r.sensors.push_back(v);
        }
    return r;
}

ReportVisualSensorConfiguration visualConfiguration(const std::vector<SimCameraConfig>& cameras,
                                                    const QuerySensors& q) {
    ReportVisualSensorConfiguration r;
    for (const SimCameraConfig& c : cameras)
        if (auto pv = wanted(c.sensorId, q)) {
            VisualSensorConfiguration v;
            v.sensorId = c.sensorId;
            if (*pv & 0x01)
                v.sensorState = std::uint8_t(SensorState::Active);
            if (*pv & 0x10)
                v.horizontalFov = c.horizontalFov;
            if (*pv & 0x20)
                v.verticalFov = 2 * std::atan(std::tan(c.horizontalFov / 2) * c.height_px / c.width);
            if (*pv & 0x200)
                v.imagingMode = 0;
            r.sensors.push_back(v);
        }
    return r;
}

ReportDigitalVideoCapabilities videoCapabilities(const std::vector<SimCameraConfig>& cameras,
                                                 const QuerySensors& q) {
    ReportDigitalVideoCapabilities r;
    for (const SimCameraConfig& c : cameras)
        if (auto pv = wanted(c.sensorId, q)) {
            DigitalVideoCapabilities v;
            v.sensorId = c.sensorId;
            if (*pv & 0x02)
                v.maxBitRate = 4000;
            if (*pv & 0x08)
                v.maxFrameRate = 30;
            if (*pv & 0x10)
                v.supportedFrameSizes = (1u << kFrameSize640x480) | (1u << kFrameSize1280x720);
            if (*pv & 0x20)
                v.supportedFormats = 1u << kFormatH264;
            r.sensors.push_back(v);
        }
    return r;
}

ReportDigitalVideoConfiguration videoConfiguration(const std::vector<SimCameraConfig>& cameras,
                                                   const QuerySensors& q) {
    ReportDigitalVideoConfiguration r;
    for (const SimCameraConfig& c : cameras)
        if (auto pv = wanted(c.sensorId, q)) {
            DigitalVideoConfiguration v;
            v.sensorId = c.sensorId;
            if (*pv & 0x04)
                v.frameRate = std::uint8_t(c.fps);
            if (const auto fs = frameSizeOf(c.width, c.height_px); (*pv & 0x08) && fs != 0xFF)
                v.frameSize = fs;
            if (*pv & 0x10)
                v.format = kFormatH264;
            r.sensors.push_back(v);
        }
    return r;
}

ReportSensorGeometricProperties geometry(const std::vector<SimCameraConfig>& cameras,
                                         const QuerySensorGeometricProperties& q, const JausId& panTiltUnit) {
    ReportSensorGeometricProperties r;
    for (const SimCameraConfig& c : cameras) {
        if (std::none_of(q.sensorIds.begin(), q.sensorIds.end(),
                         [&](std::uint16_t s) { return s == 0 || s == c.sensorId; }))
            continue;
        SensorGeometry g;
        g.sensorId = c.sensorId;
        if (c.panTilt) {
            g.kind = 2; // on the pan-tilt's tilt joint (V1.JAUS-57)
            g.manipulator = panTiltUnit;
            g.joint = 2;
            g.z = 0.1;
        } else {
            g.kind = 1;
            g.x = c.forwardOffset;
            g.z = c.height;
            g.qd = std::cos(c.yawOffset / 2);
            g.qc = std::sin(c.yawOffset / 2);
        }
        r.sensors.push_back(g);
    }
    return r;
}
} // namespace

UgvVideo::UgvVideo(std::uint16_t subsystem, std::vector<SimCameraConfig> cameras, Send send,
                   const Clock& clock, Counters& counters)
    : m_ss(subsystem), m_cameras(std::move(cameras)), m_send(std::move(send)), m_clock(clock),
      m_counters(counters) {}

std::vector<ServiceRecord> UgvVideo::platformManagerServices() const {
    if (!enabled())
        return {};
    return {{"urn:jaus:jss:iop:DigitalResourceDiscovery", 1, 1}};
}

std::vector<ComponentServices> UgvVideo::node4() const {
    if (!enabled())
        return {};
    const std::vector<ServiceRecord> base{{"urn:jaus:jss:core:Transport", 1, 1},
                                          {"urn:jaus:jss:core:Events", 1, 1},
                                          {"urn:jaus:jss:core:AccessControl", 1, 1}};
    ComponentServices cam{4, 0, base};
    cam.component = camera().component;
    cam.services.push_back({"urn:jaus:jss:environmentSensing:VisualSensor", 1, 0});
    cam.services.push_back({"urn:jaus:jss:environmentSensing:DigitalVideo", 1, 0});
    std::vector<ComponentServices> out{cam};
    if (std::any_of(m_cameras.begin(), m_cameras.end(), [](const SimCameraConfig& c) { return c.panTilt; })) {
        ComponentServices pt{panTiltUnit().component, 0, base};
        pt.services.push_back({"urn:jaus:jss:core:Management", 1, 1});
        pt.services.push_back({"urn:jaus:jss:manipulator:PanTiltJointVelocityDriver", 2, 0});
        pt.services.push_back({"urn:jaus:jss:manipulator:PanTiltJointPositionSensor", 2, 0});
        out.push_back(pt);
    }
    return out;
}

void UgvVideo::setUrl(std::uint16_t sensorId, const std::string& url) {
    Registration& r = m_reg[sensorId];
    r.url = url;
    r.lastTry = TimePoint{}; // register (or remove) on the next tick
}

// ---- Digital Resource Discovery (platform manager) ----

Bytes UgvVideo::drdRegister(const RegisterDigitalResourceEndpoint& m, const JausId& src, bool& confirmed) {
    confirmed = false;
    const JausId host = m.endpoint.host.value_or(src);
    std::optional<std::uint8_t> id;
    for (auto& [k, v] : m_drd)
        if (v.second.host.value_or(v.first) == host && v.second.resourceId == m.endpoint.resourceId)
            id = k; // the same (JAUS_ID, ResourceID) keeps its ID
    if (!id)
        for (std::uint8_t k = 1; k < 255; ++k)
            if (!m_drd.count(k)) {
                id = k;
                break;
            }
    if (!id)
        return {}; // table full: no Confirm (FKIE behaviour)
    m_drd[*id] = {src, m.endpoint};
    m_drdList.clear();
    for (auto& [k, v] : m_drd)
        m_drdList.push_back(v.second);
    confirmed = true;
    return encode(ConfirmDigitalResourceEndpoint{*id, m.requestId});
}

bool UgvVideo::drdRemove(const RemoveDigitalResourceEndpoint& m) {
    if (!m_drd.erase(m.endpointId))
        return false; // unknown ID: no Confirm
    m_drdList.clear();
    for (auto& [k, v] : m_drd)
        m_drdList.push_back(v.second);
    return true;
}

// The camera component registers its streams with the DRD of its own subsystem (AEP-4818 V1.JAUS-54/55):
// the Register and its Confirm are real messages, handed between the two components in process.
void UgvVideo::registerStreams(TimePoint now) {
    for (auto& [sensor, r] : m_reg) {
        if (r.url == r.sent || now - r.lastTry < std::chrono::seconds(1))
            continue;
        r.lastTry = now;
        if (r.url.empty()) {
            if (r.endpointId) {
                const Bytes remove = encode(RemoveDigitalResourceEndpoint{*r.endpointId, m_nextRequest++});
                auto m = decodeRemoveDigitalResourceEndpoint(remove);
                if (m && drdRemove(*m))
                    logInfo(kVideoLog, "UGV " + std::to_string(m_ss) + ": stream of sensor " +
                                           std::to_string(sensor) +
                                           " removed from Digital Resource Discovery");
            }
            r.endpointId.reset();
            r.sent.clear();
            continue;
        }
        RegisterDigitalResourceEndpoint reg;
        reg.requestId = m_nextRequest++;
        if (m_nextRequest == 0)
            m_nextRequest = 1;
        reg.endpoint.serverType = std::uint8_t(ServerType::Rtsp);
        reg.endpoint.url = r.url;
        reg.endpoint.host = camera(); // always both optional fields (FKIE clients read JAUS_ID blindly)
        reg.endpoint.resourceId = sensor;
        r.requestId = reg.requestId;
        const Bytes wire = encode(reg);
        auto m = decodeRegisterDigitalResourceEndpoint(wire);
        bool ok = false;
        const Bytes confirm = m ? drdRegister(*m, camera(), ok) : Bytes{};
        auto c = ok ? decodeConfirmDigitalResourceEndpoint(confirm)
                    : Result<ConfirmDigitalResourceEndpoint>(makeError("none"));
        if (c && c->requestId == r.requestId) {
            r.endpointId = c->endpointId;
            r.sent = r.url;
            m_counters.add("drd.registered");
        }
    }
}

// ---- messages ----

bool UgvVideo::handle(const JausId& to, const JausId& src, std::uint16_t id, ByteSpan p) {
    if (!enabled())
        return false;
    if (to == platformManager()) {
        switch (id) {
        case msg::QueryDigitalResourceEndpoint:
            send(to, src, encode(ReportDigitalResourceEndpoint{m_drdList}));
            return true;
        case msg::RegisterDigitalResourceEndpoint: {
            auto m = decodeRegisterDigitalResourceEndpoint(p);
            if (!m) {
                m_counters.add("rx.rejected.drd");
                return true;
            }
            bool ok = false;
            Bytes c = drdRegister(*m, src, ok);
            if (ok)
                send(to, src, c);
            return true;
        }
        case msg::RemoveDigitalResourceEndpoint: {
            auto m = decodeRemoveDigitalResourceEndpoint(p);
            if (m && drdRemove(*m))
                send(to, src, encode(ConfirmDigitalResourceEndpoint{m->endpointId, m->requestId}));
            return true;
        }
        default:
            return false;
        }
    }
    if (to == camera())
        return handleCamera(src, id, p);
    if (to == panTiltUnit() &&
        std::any_of(m_cameras.begin(), m_cameras.end(), [](auto& c) { return c.panTilt; }))
        return handlePanTilt(src, id, p);
    return false;
}

bool UgvVideo::handleCamera(const JausId& src, std::uint16_t id, ByteSpan p) {
    switch (id) {
    case msg::QueryVisualSensorCapabilities:
        if (auto q = decodeSensorQuery(p, id))
            send(camera(), src, encode(visualCapabilities(m_cameras, *q)));
        return true;
    case msg::QueryVisualSensorConfiguration:
        if (auto q = decodeSensorQuery(p, id))
            send(camera(), src, encode(visualConfiguration(m_cameras, *q)));
        return true;
    case msg::QueryDigitalVideoSensorCapabilities:
        if (auto q = decodeSensorQuery(p, id))
            send(camera(), src, encode(videoCapabilities(m_cameras, *q)));
        return true;
    case msg::QueryDigitalVideoSensorConfiguration:
        if (auto q = decodeSensorQuery(p, id))
            send(camera(), src, encode(videoConfiguration(m_cameras, *q)));
        return true;
    case msg::QuerySensorGeometricProperties:
        if (auto q = decodeQuerySensorGeometricProperties(p))
            send(camera(), src, encode(geometry(m_cameras, *q, panTiltUnit())));
        return true;
    case msg::ControlDigitalVideoSensorStream:
        // RTSP controls the stream: the message may be ignored (AEP-4818 §9.1.3).
        m_counters.add("rx.ignored.stream_control");
        return true;
    case msg::RequestControl:
    case msg::ReleaseControl:
    case msg::QueryControl:
        return false; // the camera needs no control for what is simulated (no Set messages)
    default:
        return false;
    }
}

bool UgvVideo::handlePanTilt(const JausId& src, std::uint16_t id, ByteSpan p) {
    const JausId me = panTiltUnit();
    const TimePoint now = m_clock.now();
    const bool isController = src == m_ptController && src.subsystem != 0;
    auto stop = [&] { m_ptRate = PanTiltPose{}; };
    switch (id) {
    case msg::RequestControl: {
        auto a = decodeU8(p, id);
        if (!a)
            return true;
        if (*a < kPtDefaultAuthority) {
            send(me, src,
                 encodeU8(msg::ConfirmControl, std::uint8_t(ConfirmControlCode::InsufficientAuthority)));
        } else if (m_ptController.subsystem == 0 || isController || *a > m_ptAuthority) {
            if (m_ptController.subsystem != 0 && !isController) {
                send(me, m_ptController,
                     encodeU8(msg::RejectControl, std::uint8_t(RejectControlCode::Released)));
                stop();
                m_ptState = ManagementState::Standby;
            }
            m_ptController = src;
            m_ptAuthority = *a;
            m_ptLastRequest = now;
            send(me, src, encodeU8(msg::ConfirmControl, std::uint8_t(ConfirmControlCode::Accepted)));
        } else {
            send(me, src,
                 encodeU8(msg::ConfirmControl, std::uint8_t(ConfirmControlCode::InsufficientAuthority)));
        }
        return true;
    }
    case msg::ReleaseControl:
        if (isController) {
            send(me, src, encodeU8(msg::RejectControl, std::uint8_t(RejectControlCode::Released)));
            m_ptController = JausId{};
            m_ptAuthority = 0;
            m_ptState = ManagementState::Standby; // leaving Controlled stops the motion
            stop();
        }
        return true;
    case msg::QueryControl:
        send(me, src, encode(ReportControl{m_ptController, m_ptAuthority}));
        return true;
    case msg::QueryStatus:
        send(me, src, encode(ReportStatus{m_ptState, 0}));
        return true;
    case msg::Resume:
        if (isController && m_ptState != ManagementState::Emergency)
            m_ptState = ManagementState::Ready;
        return true;
    case msg::Standby:
        if (isController) {
            m_ptState = ManagementState::Standby;
            stop();
        }
        return true;
    case msg::SetEmergency:
        m_ptState = ManagementState::Emergency;
        stop();
        return true;
    case msg::ClearEmergency:
        if (m_ptState == ManagementState::Emergency)
            m_ptState = ManagementState::Standby;
        return true;
    case msg::SetPanTiltJointVelocity: {
        // Controlled, READY and from the controller (AS6057A guards).
        if (!isController || m_ptState != ManagementState::Ready) {
            m_counters.add("rx.refused.pan_tilt");
            return true;
        }
        auto v = decodePanTiltVelocities(p, id);
        if (!v)
            return true;
        m_ptRate.pan = std::clamp(v->pan, -kMaxRate, kMaxRate);
        m_ptRate.tilt = std::clamp(v->tilt, -kMaxRate, kMaxRate);
        m_ptLastCommand = now;
        return true;
    }
    case msg::QueryPanTiltJointPositions:
        send(me, src, encodePanTiltPositions(msg::ReportPanTiltJointPositions, {m_pt.pan, m_pt.tilt}));
        return true;
    case msg::QueryPanTiltJointVelocity:
        send(me, src,
             encodePanTiltVelocities(msg::ReportPanTiltJointVelocity, {m_ptRate.pan, m_ptRate.tilt}));
        return true;
    default:
        return false;
    }
}

void UgvVideo::panTiltPhysics(TimePoint now) {
    if (m_ptLastPhysics == TimePoint{}) {
        m_ptLastPhysics = now;
        return;
    }
    const double dt = std::min(seconds(now - m_ptLastPhysics), 0.5);
    m_ptLastPhysics = now;
    if (m_ptController.subsystem != 0 &&
        now - m_ptLastRequest > std::chrono::duration<double>(kPtAccessTimeoutS)) {
        send(panTiltUnit(), m_ptController,
             encodeU8(msg::RejectControl, std::uint8_t(RejectControlCode::Released)));
        m_ptController = JausId{};
        m_ptAuthority = 0;
        m_ptState = ManagementState::Standby;
        m_ptRate = PanTiltPose{};
    }
    if ((m_ptRate.pan != 0 || m_ptRate.tilt != 0) &&
        now - m_ptLastCommand > std::chrono::duration<double>(kActuatorTimeoutS)) {
        m_ptRate = PanTiltPose{}; // actuator drive timeout (AEP-4818 §9.3.1.2)
        m_counters.add("pan_tilt.drive_timeouts");
    }
    m_pt.pan = std::clamp(m_pt.pan + m_ptRate.pan * dt, -kPanLimit, kPanLimit);
    m_pt.tilt = std::clamp(m_pt.tilt + m_ptRate.tilt * dt, kTiltMin, kTiltMax);
}

void UgvVideo::tick() {
    if (!enabled())
        return;
    const TimePoint now = m_clock.now();
    registerStreams(now);
    panTiltPhysics(now);
}

} // namespace ocu::sim
