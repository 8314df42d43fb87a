#include "protocols/jaus/clients/VideoClient.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "protocols/jaus/ServiceInheritance.h"

namespace ocu::jaus {

namespace {

constexpr std::string_view kDrd = "urn:jaus:jss:iop:DigitalResourceDiscovery";
constexpr std::string_view kVisualSensor = "urn:jaus:jss:environmentSensing:VisualSensor";
constexpr std::string_view kPanTiltVelocity = "urn:jaus:jss:manipulator:PanTiltJointVelocityDriver";

// By URI and inheritance, or by the last URI segment whatever the namespace (peers disagree on namespaces;
// the AS6060 2.0 DigitalResourceDiscovery lives under environmentSensing).
bool provides(const std::vector<ServiceRecord>& services, std::string_view uri) {
    if (offers(services, uri))
        return true;
    const std::string_view name = uri.substr(uri.rfind(':') + 1);
    for (const ServiceRecord& s : services) {
        const auto pos = s.uri.rfind(':');
        if (pos != std::string::npos && std::string_view(s.uri).substr(pos + 1) == name)
            return true;
    }
    return false;
}

constexpr auto kDrdRetry = std::chrono::seconds(1);
constexpr auto kDrdRefresh = std::chrono::seconds(10);
constexpr auto kNameRetry = std::chrono::seconds(2);
constexpr auto kStreamPeriod = std::chrono::milliseconds(100); // 10 Hz, well inside the 1 s drive timeout
constexpr int kZeroRepeats = 3;

} // namespace

void VideoClient::registerMessages(MessageTable& table) {
    table.onVehicleMessage(
        msg::ReportDigitalResourceEndpoint, [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
            auto m = decodeReportDigitalResourceEndpoint(p);
            if (!m)
                return m_ctx.rejected(src, m.error());
            State& s = m_state[r.id()];
            // An empty report may only mean the cameras have not registered yet (they
            // retry until the DRD confirms, V1.JAUS-~55): keep asking every second for
            // 30 s before settling to the slow refresh.
            const TimePoint now = m_ctx.now();
            if (s.firstDrdReport == TimePoint{})
                s.firstDrdReport = now;
            s.drdAnswered = !m->endpoints.empty() || now - s.firstDrdReport >= std::chrono::seconds(30);
            s.endpoints = m->endpoints;
            // A camera not named yet: its host is asked (again) for its capabilities.
            for (const DigitalResourceEndpoint& e : s.endpoints) {
                const JausId host = hostOf(s, e);
                if (!s.names.count({host.value(), e.resourceId.value_or(0)})) {
                    s.capsAnswered[host.value()] = false;
                    s.geometryAnswered[host.value()] = false;
                }
            }
            publish(r, s);
        });
    // A registrant's confirmation: the console registers nothing, so one reaching it is only counted.
    table.onVehicleMessage(msg::ConfirmDigitalResourceEndpoint,
                           [](RemoteSubsystem&, const JausId&, ByteSpan) {});
    table.onVehicleMessage(msg::ReportVisualSensorCapabilities,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
                               auto m = decodeReportVisualSensorCapabilities(p);
                               if (!m)
                                   return m_ctx.rejected(src, m.error());
                               State& s = m_state[r.id()];
                               for (const VisualSensorCapabilities& c : m->sensors)
                                   s.names[{src.value(), c.sensorId}] = c.name;
                               s.capsAnswered[src.value()] = true;
                               publish(r, s);
                           });
    table.onVehicleMessage(msg::ReportSensorGeometricProperties,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
                               auto m = decodeReportSensorGeometricProperties(p);
                               if (!m)
                                   return m_ctx.rejected(src, m.error());
                               State& s = m_state[r.id()];
                               s.geometryAnswered[src.value()] = true;
                               for (const SensorGeometry& g : m->sensors)
                                   if (g.kind == 2)
                                       s.mounts[{src.value(), g.sensorId}] =
                                           JausId{g.manipulator.subsystem ? g.manipulator.subsystem : r.id(),
                                                  g.manipulator.node, g.manipulator.component};
                               publish(r, s);
                           });
    table.onVehicleMessage(msg::ReportPanTiltJointPositions,
                           [this](RemoteSubsystem& r, const JausId& src, ByteSpan p) {
                               auto m = decodePanTiltPositions(p, msg::ReportPanTiltJointPositions);
                               if (!m)
                                   return m_ctx.rejected(src, m.error());
                               State& s = m_state[r.id()];
                               if (PanTilt* u = unitFor(s, src)) {
                                   u->report.pan = m->pan;
                                   u->report.tilt = m->tilt;
                                   publish(r, s);
                               }
                           });
    // Known and unused: the console shows camera names and streams, not encoder settings.
    for (std::uint16_t id : {msg::ReportVisualSensorConfiguration, msg::ReportDigitalVideoSensorCapabilities,
                             msg::ReportDigitalVideoSensorConfiguration, msg::ReportPanTiltJointVelocity,
                             msg::ConfirmSensorConfiguration})
        table.onVehicleMessage(id, [](RemoteSubsystem&, const JausId&, ByteSpan) {});
}

void VideoClient::locate(RemoteSubsystem& r, State& s) {
    s.located = true;
    s.drd = JausId{};
    s.visualSensors.clear();
    std::vector<JausId> pts;
    for (const NodeInfo& n : r.snap.services)
        for (const ComponentInfo& c : n.components) {
            const JausId id{r.id(), n.node, c.component};
            if (!s.drd.subsystem && provides(c.services, kDrd))
                s.drd = id;
            if (provides(c.services, kVisualSensor) ||
                provides(c.services, "urn:jaus:jss:environmentSensing:DigitalVideo"))
                s.visualSensors.push_back(id);
            if (provides(c.services, kPanTiltVelocity))
                pts.push_back(id);
        }
    for (const JausId& id : pts)
        if (!unitFor(s, id)) {
            PanTilt u;
            u.component = id;
            u.report.component = id;
            s.panTilts.push_back(u);
        }
}

VideoClient::PanTilt* VideoClient::unitFor(State& s, const JausId& c) {
    for (PanTilt& u : s.panTilts)
        if (u.component == c)
            return &u;
    return nullptr;
}

void VideoClient::onServicesKnown(RemoteSubsystem& r) {
    locate(r, m_state[r.id()]);
}

void VideoClient::onLinkRestored(RemoteSubsystem& r) {
    State& s = m_state[r.id()];
    s.drdAnswered = false; // the platform may have restarted: ask again at once
    s.firstDrdReport = TimePoint{};
    s.lastDrdQuery = TimePoint{};
    s.geometryAnswered.clear();
    s.capsAnswered.clear();
    s.lastNameQuery.clear();
    for (PanTilt& u : s.panTilts) {
        u.control = PanTiltControl::None;
        u.report.controlledByUs = false;
    }
}

JausId VideoClient::hostOf(const State& s, const DigitalResourceEndpoint& e) const {
    if (e.host && e.host->subsystem)
        return *e.host;
    // No JAUS_ID in the registration (optional field): the subsystem's (first) visual sensor component.
    return s.visualSensors.empty() ? JausId{} : s.visualSensors.front();
}

void VideoClient::heard(RemoteSubsystem& r) {
    State& s = m_state[r.id()];
    if (!s.published) {
        s.published = true;
        publish(r, s);
    }
}

void VideoClient::publish(RemoteSubsystem& r, State& s) {
    std::vector<VideoEndpoint> out;
    for (const DigitalResourceEndpoint& e : s.endpoints) {
        if (e.serverType != std::uint8_t(ServerType::Rtsp) || e.url.empty())
            continue; // pull over RTSP/RTP only (AEP-4818 §9.1.4)
        VideoEndpoint v;
        v.resourceId = e.resourceId.value_or(0);
        v.sensorId = v.resourceId; // for visual sensors the ResourceID is the SensorID
        v.url = e.url;
        const JausId host = hostOf(s, e);
        if (auto it = s.names.find({host.value(), v.sensorId}); it != s.names.end())
            v.name = it->second;
        if (auto it = s.mounts.find({host.value(), v.sensorId}); it != s.mounts.end())
            v.panTilt = unitFor(s, it->second) != nullptr;
        else
            v.panTilt = unitFor(s, host) != nullptr; // the camera's own component drives its pan-tilt
        out.push_back(std::move(v));
    }
    if (auto it = m_ctx.config().configuredVideo.find(r.id()); it != m_ctx.config().configuredVideo.end())
        for (const VideoEndpoint& c : it->second)
            if (std::none_of(out.begin(), out.end(), [&](const VideoEndpoint& v) { return v.url == c.url; }))
                out.push_back(c);
    std::vector<PanTiltState> pts;
    for (const PanTilt& u : s.panTilts)
        pts.push_back(u.report);
    if (out == r.snap.videoEndpoints && pts == r.snap.panTilts)
        return;
    const bool more = out.size() > r.snap.videoEndpoints.size();
    r.snap.videoEndpoints = std::move(out);
    r.snap.panTilts = std::move(pts);
    if (more)
        m_ctx.notify(Severity::Info, EventKind::Discovered, r.id(),
                     r.snap.callSign + ": " + std::to_string(r.snap.videoEndpoints.size()) +
                         " video stream(s)");
    m_ctx.changed(r);
}

void VideoClient::tick(RemoteSubsystem& r, TimePoint now) {
    State& s = m_state[r.id()];
    // Services are merged as reports arrive (and re-checked every discovery interval): locate again.
    if (!s.located || now - s.lastLocate >= std::chrono::seconds(5)) {
        s.lastLocate = now;
        locate(r, s);
    }
    if (!r.reachable())
        return;
    // Digital Resource Discovery: every second until the first report, then a slow refresh.
    if (s.drd.subsystem &&
        now - s.lastDrdQuery >= (s.drdAnswered ? Duration(kDrdRefresh) : Duration(kDrdRetry))) {
        s.lastDrdQuery = now;
        m_ctx.send(s.drd, encodeEmpty(msg::QueryDigitalResourceEndpoint));
    }
    // Names and mounts from the hosts that offer a Visual Sensor service, each asked until it answers.
    for (const DigitalResourceEndpoint& e : s.endpoints) {
        const JausId host = hostOf(s, e);
        if (e.serverType != std::uint8_t(ServerType::Rtsp) || !host.subsystem ||
            std::find(s.visualSensors.begin(), s.visualSensors.end(), host) == s.visualSensors.end())
            continue;
        const bool named = s.capsAnswered[host.value()];
        const bool geometry = s.geometryAnswered[host.value()];
        TimePoint& last = s.lastNameQuery[host.value()];
        if ((named && geometry) || now - last < kNameRetry)
            continue;
        last = now;
        if (!named)
            m_ctx.send(host, encodeSensorQuery(msg::QueryVisualSensorCapabilities, QuerySensors{}));
        if (!geometry)
            m_ctx.send(host, encode(QuerySensorGeometricProperties{}));
    }
    for (PanTilt& u : s.panTilts)
        tickPanTilt(r, u, now);
}

void VideoClient::tickPanTilt(RemoteSubsystem& r, PanTilt& u, TimePoint now) {
    const JausConfig& cfg = m_ctx.config();
    State& s = m_state[r.id()];
    const bool want = r.snap.controlledByUs && cfg.mayControl() && !r.snap.emergency;
    // Control of the pan-tilt component follows control of the vehicle; re-requested within its timeout.
    if (want && now >= u.refusedUntil &&
        (u.control == PanTiltControl::None || now - u.lastRequest > secondsD(0.4 * cfg.accessTimeoutS))) {
        if (u.control == PanTiltControl::None)
            u.control = PanTiltControl::Requested;
        u.lastRequest = now;
        m_ctx.send(u.component, encodeU8(msg::RequestControl, cfg.authority));
    } else if (!want && u.control != PanTiltControl::None) {
        if (u.control == PanTiltControl::Controlled)
            m_ctx.send(u.component, encodePanTiltVelocities(msg::SetPanTiltJointVelocity, {}));
        m_ctx.send(u.component, encodeEmpty(msg::ReleaseControl));
        u.control = PanTiltControl::None;
        u.pan = u.tilt = 0;
        u.zerosLeft = 0;
        u.report.controlledByUs = false;
        publish(r, s);
    }
    // The velocity stream: a demand not refreshed goes to zero (a frozen GUI must not keep the head moving).
    const bool moving = u.pan != 0 || u.tilt != 0;
    if (moving && cfg.driveCommandTimeoutS > 0 && now - u.lastDemand > secondsD(cfg.driveCommandTimeoutS)) {
        u.pan = u.tilt = 0;
        u.zerosLeft = kZeroRepeats;
    }
    if (u.control == PanTiltControl::Controlled && (moving || u.zerosLeft > 0) &&
        now - u.lastSent >= kStreamPeriod) {
        u.lastSent = now;
        m_ctx.send(u.component, encodePanTiltVelocities(msg::SetPanTiltJointVelocity, {u.pan, u.tilt}));
        if (!moving)
            --u.zerosLeft;
    }
    // Position: 5 Hz while moving (and shortly after), 1 Hz otherwise.
    const bool active = moving || u.zerosLeft > 0 || now - u.lastDemand < std::chrono::seconds(2);
    if (now - u.lastPoll >=
        (active ? Duration(std::chrono::milliseconds(200)) : Duration(std::chrono::seconds(1)))) {
        u.lastPoll = now;
        m_ctx.send(u.component, encodeEmpty(msg::QueryPanTiltJointPositions));
    }
}

bool VideoClient::handleControlMessage(RemoteSubsystem& r, const JausId& src, std::uint16_t id, ByteSpan p) {
    auto it = m_state.find(r.id());
    if (it == m_state.end())
        return false;
    State& s = it->second;
    PanTilt* u = unitFor(s, src);
    if (!u || src == r.controlTarget())
        return false; // the vehicle's own control component: AccessControlClient's business
    if (id == msg::ConfirmControl) {
        auto m = decodeU8(p, id);
        if (!m) {
            m_ctx.rejected(src, m.error());
            return true;
        }
        if (*m == std::uint8_t(ConfirmControlCode::Accepted)) {
            if (u->control == PanTiltControl::None) {
                m_ctx.send(src, encodeEmpty(msg::ReleaseControl)); // late accept after we gave up
                return true;
            }
            if (u->control == PanTiltControl::Requested) {
                u->control = PanTiltControl::Controlled;
                // The drivers obey only in READY (AS6057A via core:Management).
                m_ctx.send(src, encodeEmpty(msg::Resume));
            }
        } else {
            u->control = PanTiltControl::None;
            u->refusedUntil = m_ctx.now() + std::chrono::seconds(5);
            m_ctx.notify(Severity::Warning, EventKind::ControlRejected, r.id(),
                         r.snap.callSign + ": pan-tilt " + src.toString() + " refused control (code " +
                             std::to_string(*m) + ")");
        }
    } else if (id == msg::RejectControl) {
        if (u->control == PanTiltControl::Controlled)
            m_ctx.notify(Severity::Warning, EventKind::ControlLost, r.id(),
                         r.snap.callSign + ": control of pan-tilt " + src.toString() + " lost");
        u->control = PanTiltControl::None;
        u->pan = u->tilt = 0;
        u->zerosLeft = 0;
    } else {
        return false; // ReportControl etc.: not asked for by this client
    }
    u->report.controlledByUs = u->control == PanTiltControl::Controlled;
    publish(r, s);
    return true;
}

bool VideoClient::refusePanTilt(std::uint16_t ss, const std::string& why) {
    State& s = m_state[ss];
    const TimePoint now = m_ctx.now();
    if (why == s.lastRefusal && now - s.lastRefusalAt < std::chrono::seconds(2)) {
        s.lastRefusalAt = now;
        return m_ctx.refuseQuietly(why);
    }
    s.lastRefusal = why;
    s.lastRefusalAt = now;
    return m_ctx.refuse(ss, why);
}

bool VideoClient::panTilt(std::uint16_t ss, std::uint16_t sensorId, double panRate, double tiltRate) {
    if (!m_ctx.config().mayControl())
        return refusePanTilt(ss, "the monitor role may not move a pan-tilt");
    RemoteSubsystem* r = m_ctx.find(ss);
    if (!r || !r->snap.controlledByUs)
        return refusePanTilt(ss, "pan-tilt needs control of subsystem " + std::to_string(ss));
    if (r->snap.emergency)
        return refusePanTilt(ss, r->snap.callSign + " is in EMERGENCY");
    if (!std::isfinite(panRate) || !std::isfinite(tiltRate))
        return refusePanTilt(ss, "pan-tilt rates must be finite numbers");
    State& s = m_state[ss];
    auto ep = std::find_if(r->snap.videoEndpoints.begin(), r->snap.videoEndpoints.end(),
                           [&](const VideoEndpoint& v) { return v.sensorId == sensorId && !v.configured; });
    if (ep == r->snap.videoEndpoints.end())
        return refusePanTilt(ss, r->snap.callSign + " announces no camera with sensor ID " +
                                     std::to_string(sensorId));
    JausId unit;
    for (const DigitalResourceEndpoint& e : s.endpoints) {
        if (e.resourceId.value_or(0) != sensorId)
            continue;
        const JausId host = hostOf(s, e);
        auto it = s.mounts.find({host.value(), sensorId});
        unit = it != s.mounts.end() ? it->second : host;
        break;
    }
    PanTilt* u = unitFor(s, unit);
    if (!u)
        return refusePanTilt(ss, r->snap.callSign + ": camera " + std::to_string(sensorId) +
                                     " is not on a pan-tilt");
    if (u->control != PanTiltControl::Controlled)
        return refusePanTilt(ss, r->snap.callSign + ": control of pan-tilt " + u->component.toString() +
                                     " is not confirmed yet (RequestControl pending)");
    // Clamped to the message range (±10π rad/s); the unit clamps to its own limits.
    const double lim = 10 * 3.14159265358979;
    panRate = std::clamp(panRate, -lim, lim);
    tiltRate = std::clamp(tiltRate, -lim, lim);
    const bool changed = panRate != u->pan || tiltRate != u->tilt;
    u->pan = panRate;
    u->tilt = tiltRate;
    u->lastDemand = m_ctx.now();
    if (panRate == 0 && tiltRate == 0 && changed)
        u->zerosLeft = kZeroRepeats; // several zero commands, never a single message
    if (!changed)
        return true; // streamed at 10 Hz
    u->lastSent = m_ctx.now();
    if (!m_ctx.send(u->component, encodePanTiltVelocities(msg::SetPanTiltJointVelocity, {panRate, tiltRate})))
        return m_ctx.sendFailed(ss, "SetPanTiltJointVelocity");
    if (panRate == 0 && tiltRate == 0)
        --u->zerosLeft;
    return true;
}

} // namespace ocu::jaus
