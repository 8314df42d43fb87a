#include "models/bridges/JausBridgeRows.h"
#include "models/bridges/JausBridge.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace ocu {

using namespace jaus;

namespace jausrow {

JausAddress toAddress(const JausId& id) {
    return {id.subsystem, id.node, id.component};
}

JausAccess toAccess(AccessState a) {
    switch (a) {
    case AccessState::NotAvailable:
        return JausAccess::NotAvailable;
    case AccessState::NotControlled:
        return JausAccess::NotControlled;
    case AccessState::Monitoring:
        return JausAccess::Monitoring;
    case AccessState::ControlAccepted:
        return JausAccess::ControlAccepted;
    case AccessState::ControlReleased:
        return JausAccess::ControlReleased;
    case AccessState::Timeout:
        return JausAccess::Timeout;
    case AccessState::InsufficientAuthority:
        return JausAccess::InsufficientAuthority;
    case AccessState::Preempted:
        return JausAccess::Preempted;
    }
    return JausAccess::NotAvailable;
}

JausManagement toManagement(ManagementState m) {
    switch (m) {
    case ManagementState::Init:
        return JausManagement::Init;
    case ManagementState::Ready:
        return JausManagement::Ready;
    case ManagementState::Standby:
        return JausManagement::Standby;
    case ManagementState::Shutdown:
        return JausManagement::Shutdown;
    case ManagementState::Failure:
        return JausManagement::Failure;
    case ManagementState::Emergency:
        return JausManagement::Emergency;
    }
    return JausManagement::Failure;
}

namespace {
template <class T, class F>
auto mapOptional(const std::optional<T>& v, F&& f) -> std::optional<decltype(f(*v))> {
    if (!v)
        return std::nullopt;
    return f(*v);
}
} // namespace

// The panels' view of a subsystem (GUI thread, only for the snapshots the coalescer delivers).
JausVehicle toVehicle(const SubsystemSnapshot& s) {
    JausVehicle v;
    v.subsystem = s.subsystem;
    v.callSign = QString::fromStdString(s.callSign);
    v.endpoint = QString::fromStdString(s.endpoint);
    v.link = s.link == jaus::LinkState::Up         ? JausLink::Up
             : s.link == jaus::LinkState::Degraded ? JausLink::Degraded
                                                   : JausLink::Down;
    v.linkText = QString::fromUtf8(jaus::nameFor(s.link));
    v.lastMessageUnixMs = s.lastMessageUnixMs;
    v.access = toAccess(s.access);
    v.controller = toAddress(s.controller);
    v.controllerAuthority = s.controllerAuthority;
    v.controlledByUs = s.controlledByUs;
    v.accessTimeoutS = s.accessTimeoutS;
    if (s.management) {
        v.management = toManagement(*s.management);
        v.managementText = QString::fromUtf8(jaus::nameFor(*s.management));
    }
    v.emergency = s.emergency;
    v.driving = s.driving;
    v.globalPose = mapOptional(s.globalPose, [](const GlobalPose& p) {
        return JausGlobalPose{p.lat, p.lon, p.alt, p.yaw};
    });
    v.localPose = mapOptional(s.localPose, [](const LocalPose& p) { return JausLocalPose{p.x, p.y, p.yaw}; });
    v.velocity = mapOptional(s.velocity, [](const VelocityState& p) {
        return JausVelocity{p.vx, p.vy, p.yawRate};
    });
    v.platform = mapOptional(s.platform, [](const PlatformSpecifications& p) {
        return JausPlatform{QString::fromStdString(p.name),
                            p.steeringType,
                            p.front,
                            p.back,
                            p.left,
                            p.right,
                            p.top,
                            p.bottom,
                            p.maxForwardSpeed,
                            p.maxReverseSpeed,
                            p.maxRotationalSpeed};
    });
    v.health = mapOptional(s.health, [](const HealthSummary& h) {
        JausHealth out;
        out.severity = h.severity;
        for (auto [node, severity] : h.nodes)
            out.nodes.push_back({node, severity});
        return out;
    });
    v.mobilityComponent = toAddress(s.mobilityComponent);
    for (const NodeInfo& n : s.services) {
        JausNodeServices node{n.node, {}};
        for (const ComponentInfo& c : n.components) {
            JausComponentServices comp{c.component, {}};
            for (const ServiceRecord& r : c.services)
                comp.services.push_back({QString::fromStdString(r.uri), r.major, r.minor});
            node.components.push_back(comp);
        }
        v.services.push_back(node);
    }
    for (const jaus::VideoEndpoint& e : s.videoEndpoints)
        v.videoEndpoints.push_back({e.resourceId, e.sensorId, QString::fromStdString(e.url),
                                    QString::fromStdString(e.name), e.panTilt, e.configured});
    v.mission = toMission(s.mission);
    v.platformServices = toPlatformServices(s.platformServices);
    v.handoff = toHandoff(s.handoff);
    return v;
}

JausPlatformServices toPlatformServices(const PlatformServicesStatus& p) {
    auto offered = [](const OfferedService& s) {
        return JausOfferedService{s.offered, QString::fromStdString(s.uri), s.major, s.minor};
    };
    auto number = [](const auto& o) { return o ? std::optional<int>(int(*o)) : std::nullopt; };
    JausPlatformServices out;
    out.modeService = offered(p.modeService);
    out.stateService = offered(p.stateService);
    out.illuminationService = offered(p.illuminationService);
    out.odometryService = offered(p.odometryService);
    out.commsLostService = offered(p.commsLostService);
    out.mode = number(p.mode);
    out.modeStatus = number(p.modeStatus);
    for (std::uint8_t m : p.supportedModes)
        out.supportedModes.push_back(m);
    out.state = number(p.state);
    out.stateRefusal = QString::fromStdString(p.stateRefusal);
    // The light bits are the wire's (JausLight mirrors them).
    out.lights = p.lights;
    out.lightsSupported = p.lightsSupported;
    out.odometerM = p.odometerM;
    out.tripM = p.tripM;
    return out;
}

static_assert(int(HandoffPhase::None) == int(HandoffState::None) &&
                  int(HandoffPhase::Completed) == int(HandoffState::Completed) &&
                  int(HandoffPhase::Preempting) == int(HandoffState::Preempting) &&
                  int(HandoffPhase::Waiting) == int(HandoffState::Waiting),
              "HandoffState mirrors jaus::HandoffPhase");

JausHandoff toHandoff(const HandoffStatus& h) {
    JausHandoff out;
    out.offered = h.offered;
    out.state = HandoffState(int(h.phase)); // the same states in the same order (HandoffTypes.h)
    out.reason = QString::fromStdString(h.reason);
    out.requestTimeoutS = h.requestTimeoutS;
    out.decisionTimeoutS = h.decisionTimeoutS;
    for (const HandoffPrompt& p : h.prompts)
        out.prompts.push_back({p.id, p.requester.subsystem, QString::fromStdString(p.requester.toString()),
                               p.authority, QString::fromStdString(p.explanation), p.receivedUnixMs,
                               p.decisionTimeoutS, p.waited});
    return out;
}

JausMission toMission(const MissionStatus& m) {
    JausMission out;
    switch (m.phase) {
    case MissionPhase::None:
        out.state = MissionState::None;
        break;
    case MissionPhase::Uploading:
        out.state = MissionState::Uploading;
        break;
    case MissionPhase::Uploaded:
        out.state = MissionState::Uploaded;
        break;
    case MissionPhase::Running:
        out.state = MissionState::Running;
        break;
    case MissionPhase::Paused:
        out.state = MissionState::Paused;
        break;
    case MissionPhase::Completed:
        out.state = MissionState::Completed;
        break;
    case MissionPhase::Aborted:
        out.state = MissionState::Aborted;
        break;
    case MissionPhase::StoppedByEmergency:
        out.state = MissionState::StoppedByEmergency;
        break;
    case MissionPhase::Lost:
        out.state = MissionState::Lost;
        break;
    case MissionPhase::Rejected:
        out.state = MissionState::Rejected;
        break;
    }
    for (const MissionPoint& p : m.waypoints)
        out.waypoints.push_back(MissionWaypoint{p.lat, p.lon, p.speed, p.tolerance});
    out.global = m.global;
    out.activeIndex = m.activeIndex;
    out.lastSeenIndex = m.lastSeenIndex;
    out.distanceToGoM = m.distanceToGoM;
    out.etaS = m.etaS;
    out.ours = m.ours;
    out.reason = QString::fromStdString(m.reason);
    out.drivenPath.reserve(qsizetype(m.drivenPath.size()));
    for (const auto& [lat, lon] : m.drivenPath)
        out.drivenPath.push_back({lat, lon});
    out.pathSource = QString::fromStdString(m.pathSource);
    return out;
}

JausVehicleEvent toVehicleEvent(const JausEvent& e) {
    JausVehicleEvent v;
    v.severity = e.severity == Severity::Error     ? JausEventSeverity::Error
                 : e.severity == Severity::Warning ? JausEventSeverity::Warning
                                                   : JausEventSeverity::Info;
    v.kindText = QString::fromUtf8(jaus::nameFor(e.kind));
    v.subsystem = e.subsystem;
    v.text = QString::fromStdString(e.text);
    return v;
}

} // namespace jausrow

MachineState JausBridge::toMachine(const SubsystemSnapshot& s) const {
    MachineState m;
    m.id = machineId(s.subsystem);
    m.protocol = Protocol::Jaus;
    m.name =
        s.callSign.empty() ? QStringLiteral("UGV %1").arg(s.subsystem) : QString::fromStdString(s.callSign);
    m.type = QStringLiteral("UGV");
    m.link = s.link == jaus::LinkState::Up         ? ocu::LinkState::Up
             : s.link == jaus::LinkState::Degraded ? ocu::LinkState::Degraded
                                                   : ocu::LinkState::Down;
    m.lastDataMs = modelTimeOfWallMs(s.lastMessageUnixMs);
    m.lastMessageMs = s.lastMessageUnixMs;
    if (s.globalPose && s.globalPose->lat && s.globalPose->lon) {
        const GeoPoint g{*s.globalPose->lat, *s.globalPose->lon,
                         s.globalPose->alt.value_or(m_frame.origin().alt)};
        placeAt(m, m_frame.toLocal(g), g);
        if (s.globalPose->yaw) // JAUS yaw: from north, positive clockwise (NED), radians
            m.headingDeg = std::fmod(*s.globalPose->yaw * 180.0 / M_PI + 360.0, 360.0);
    } else if (s.localPose && s.localPose->x && s.localPose->y) {
        // Local pose is in the vehicle's NED-like frame: x north, y east.
        const EnuPoint p{*s.localPose->y, *s.localPose->x, 0};
        placeAt(m, p, m_frame.toGeodetic(p));
        if (s.localPose->yaw)
            m.headingDeg = std::fmod(*s.localPose->yaw * 180.0 / M_PI + 360.0, 360.0);
    }
    if (s.velocity && s.velocity->vx)
        m.speed = std::hypot(*s.velocity->vx, s.velocity->vy.value_or(0));
    if (s.platform) {
        const auto& p = *s.platform;
        if (p.front && p.back)
            m.length = *p.front + *p.back;
        if (p.left && p.right)
            m.width = *p.left + *p.right;
        if (p.top)
            m.height = *p.top + p.bottom.value_or(0);
    }
    if (m.length <= 0)
        m.length = 1.2;
    if (m.width <= 0)
        m.width = 0.8;
    if (s.management) {
        m.modeText = QString::fromUtf8(jaus::nameFor(*s.management));
        switch (*s.management) {
        case ManagementState::Ready:
            m.mode = s.controlledByUs || s.controller.subsystem ? ModeCategory::Remote : ModeCategory::Idle;
            break;
        case ManagementState::Standby:
        case ManagementState::Init:
            m.mode = ModeCategory::Idle;
            break;
        case ManagementState::Shutdown:
            m.mode = ModeCategory::Shutdown;
            break;
        case ManagementState::Failure:
            m.mode = ModeCategory::Fault;
            break;
        case ManagementState::Emergency:
            m.mode = ModeCategory::Stopped;
            break;
        }
        m.stop = s.emergency ? StopState::Stopped : StopState::None;
    } else {
        m.stop = s.emergency ? StopState::Stopped : StopState::Unknown;
    }
    if (s.emergency)
        m.stopText = tr("emergency");
    if (s.controlledByUs) {
        m.control = ControlState::ControlledByMe;
        m.controller = tr("this console (%1)").arg(s.controllerAuthority);
    } else if (s.controller.subsystem != 0) {
        m.control = ControlState::ControlledByOther;
        m.controller = QStringLiteral("%1.%2.%3 (%4)")
                           .arg(s.controller.subsystem)
                           .arg(s.controller.node)
                           .arg(s.controller.component)
                           .arg(s.controllerAuthority);
    } else if (s.access == AccessState::InsufficientAuthority) {
        m.control = ControlState::Denied;
    } else {
        m.control = ControlState::Monitoring;
    }
    if (s.health) {
        switch (s.health->severity) {
        case 0:
        case 1:
            m.health = HealthLevel::Ok;
            break;
        case 2:
            m.health = HealthLevel::Warning;
            break;
        default:
            m.health = HealthLevel::Fault;
            break;
        }
        static const char* names[] = {"none", "info", "warning", "error", "failure"};
        m.healthText = QString::fromLatin1(names[std::min<int>(s.health->severity, 4)]);
    } else if (s.management == ManagementState::Failure) {
        m.health = HealthLevel::Fault;
    }
    return m;
}

} // namespace ocu
