#include "models/bridges/JausBridge.h"

#include "protocols/jaus/JausStack.h"

#include <QDateTime>
#include <QJsonObject>
#include <QPointer>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>

namespace ocu {

using namespace jaus;

namespace {

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

template <class T, class F>
auto mapOptional(const std::optional<T>& v, F&& f) -> std::optional<decltype(f(*v))> {
    if (!v)
        return std::nullopt;
    return f(*v);
}

// The panels' view of a subsystem (GUI thread, only for the snapshots the coalescer delivers).
JausVehicle toVehicle(const SubsystemSnapshot& s) {
    JausVehicle v;
    v.subsystem = s.subsystem;
    v.callSign = QString::fromStdString(s.callSign);
    v.endpoint = QString::fromStdString(s.endpoint);
    v.link = s.link == jaus::LinkState::Up         ? JausLink::Up
             : s.link == jaus::LinkState::Degraded ? JausLink::Degraded
                                                   : JausLink::Down;
    v.linkText = QString::fromUtf8(jaus::toString(s.link));
    v.lastMessageUnixMs = s.lastMessageUnixMs;
    v.access = toAccess(s.access);
    v.controller = toAddress(s.controller);
    v.controllerAuthority = s.controllerAuthority;
    v.controlledByUs = s.controlledByUs;
    v.accessTimeoutS = s.accessTimeoutS;
    if (s.management) {
        v.management = toManagement(*s.management);
        v.managementText = QString::fromUtf8(jaus::toString(*s.management));
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
    return v;
}

JausVehicleEvent toVehicleEvent(const JausEvent& e) {
    JausVehicleEvent v;
    v.severity = e.severity == Severity::Error     ? JausEventSeverity::Error
                 : e.severity == Severity::Warning ? JausEventSeverity::Warning
                                                   : JausEventSeverity::Info;
    v.kindText = QString::fromUtf8(jaus::toString(e.kind));
    v.subsystem = e.subsystem;
    v.text = QString::fromStdString(e.text);
    return v;
}

} // namespace

JausBridge::JausBridge(const JausConfig& config, const GeoFrame& frame, QObject* parent)
    : JausVehicleBridge(parent), m_config(config), m_frame(frame),
      m_snapshots(
          this,
          [this](auto&& batch) {
              for (auto& [id, snap] : batch) {
                  const JausVehicle v = toVehicle(snap);
                  JausVehicle& latest = m_latest[id]; // a new vehicle starts default: not in emergency
                  const bool wasStopped = latest.emergency;
                  const bool wasOurs = latest.controlledByUs;
                  const bool wasDenied = latest.access == JausAccess::InsufficientAuthority;
                  latest = v;
                  emit subsystemUpdated(v);
                  const QString name = v.callSign.isEmpty() ? machineId(id) : v.callSign;
                  if (v.emergency && !wasStopped) // the vehicle's own report (ReportStatus: Emergency)
                      emit stopReported(machineId(id), tr("%1 reports EMERGENCY").arg(name));
                  // Confirmations of other commands come from the vehicle's own reports too.
                  if (!v.emergency && wasStopped)
                      emit commandReported(
                          QStringLiteral("clear_stop"), machineId(id),
                          tr("%1 reports %2: emergency cleared")
                              .arg(name, v.managementText.isEmpty() ? tr("no emergency") : v.managementText));
                  if (v.controlledByUs && !wasOurs)
                      emit commandReported(QStringLiteral("request_control"), machineId(id),
                                           tr("%1 confirms control by this console").arg(name));
                  else if (v.access == JausAccess::InsufficientAuthority && !wasDenied)
                      emit commandReported(QStringLiteral("request_control"), machineId(id),
                                           tr("%1 refuses control: insufficient authority").arg(name));
                  if (!v.controlledByUs && wasOurs)
                      emit commandReported(QStringLiteral("release_control"), machineId(id),
                                           tr("%1 reports control released").arg(name));
              }
          }),
      m_poseGate(config.plausibility) {
    m_stack = std::make_unique<JausStack>(m_config, static_cast<JausListener&>(*this));
}

JausBridge::~JausBridge() {
    stop();
}

void JausBridge::setMessageTap(MessageTap* tap) {
    m_stack->setMessageTap(tap);
}

QString JausBridge::start() {
    // Published before the io thread runs: a vehicle answering within the first millisecond publishes "up"
    // from there, and this must not overwrite it (the link would show "searching" for ever).
    publishLink({QStringLiteral("jaus"), ocu::LinkState::Degraded, -1, tr("searching for subsystems")});
    try {
        m_stack->start();
    } catch (const std::exception& e) {
        publishLink({QStringLiteral("jaus"), ocu::LinkState::Down, -1, QString::fromUtf8(e.what())});
        return tr("JAUS: %1").arg(QString::fromUtf8(e.what()));
    }
    return {};
}

QString JausBridge::statusNote() const {
    const auto group = m_stack->groupSocketProblem();
    if (!group || !m_stack->running())
        return {};
    if (group->heldByOther)
        return tr("JAUS: no group socket (%1 held by another process)").arg(group->port);
    return tr("JAUS: no group socket (%1)").arg(QString::fromStdString(group->reason));
}

void JausBridge::stop() {
    if (!m_stack || !m_stack->running())
        return;
    m_stack->stop(); // releases control after zero drive commands
    publishStackStopped(tr("JAUS stack stopped"));
}

JausConsoleIdentity JausBridge::identity() const {
    JausConsoleIdentity id;
    id.callSign = QString::fromStdString(m_config.callSign);
    id.subsystemId = m_config.subsystemId;
    id.authority = m_config.authority;
    id.mayControl = m_config.mayControl();
    id.mayStop = m_config.mayStop();
    id.mayClearStop = m_config.mayClearStop();
    id.driveRateHz = m_config.driveRateHz;
    id.ownId = toAddress(m_config.ownId());
    return id;
}

QList<quint16> JausBridge::subsystems() const {
    auto keys = m_latest.keys();
    std::sort(keys.begin(), keys.end());
    return keys;
}

std::optional<JausVehicle> JausBridge::subsystem(quint16 id) const {
    auto it = m_latest.find(id);
    if (it == m_latest.end())
        return std::nullopt;
    return *it;
}

// ---- io thread ----

void JausBridge::onSubsystemChanged(const SubsystemSnapshot& reported) {
    // The plausibility gate first: neither the fleet nor the vehicle panels see a pose that
    // cannot be on this site.
    SubsystemSnapshot snapshot = reported;
    const QString implausible = admitPose(snapshot);
    m_snapshots.push(snapshot.subsystem, snapshot);
    MachineState row = toMachine(snapshot);
    if (!implausible.isEmpty()) {
        row.health = std::max(row.health, HealthLevel::Warning);
        row.healthText =
            implausible + (row.healthText.isEmpty() ? QString() : QStringLiteral("; ") + row.healthText);
    }
    publishMachine(row);
    // The JAUS link is up while at least one subsystem is; published on change only (data age comes from
    // the machines).
    m_linkUp[snapshot.subsystem] = snapshot.link == jaus::LinkState::Up;
    bool anyUp = false;
    for (const auto& [id, up] : m_linkUp)
        anyUp = anyUp || up;
    const ocu::LinkState state = anyUp ? ocu::LinkState::Up : ocu::LinkState::Degraded;
    if (state != m_publishedLink) {
        m_publishedLink = state;
        publishLink({QStringLiteral("jaus"), state, 0,
                     anyUp ? tr("%n subsystem(s) up", "",
                                int(std::count_if(m_linkUp.begin(), m_linkUp.end(),
                                                  [](auto& p) { return p.second; })))
                           : tr("no subsystem answering")});
    }
}

QString JausBridge::admitPose(SubsystemSnapshot& s) {
    PoseIo& io = m_poseIo[s.subsystem];
    double pose[4] = {0, 0, 0, 0};
    bool hasPose = false;
    bool onGlobe = true;
    if (s.globalPose && s.globalPose->lat && s.globalPose->lon) {
        const double lat = *s.globalPose->lat, lon = *s.globalPose->lon;
        onGlobe = !(std::abs(lat) > 90) && !(std::abs(lon) > 180);
        const EnuPoint p = m_frame.toLocal({lat, lon, s.globalPose->alt.value_or(m_frame.origin().alt)});
        pose[0] = onGlobe ? p.e : 1e300; // beyond the globe: as far outside the site as it gets
        pose[1] = p.n;
        pose[2] = p.u;
        hasPose = true;
    } else if (s.localPose && s.localPose->x && s.localPose->y) {
        pose[0] = *s.localPose->y; // x north, y east
        pose[1] = *s.localPose->x;
        pose[2] = s.localPose->z.value_or(0);
        hasPose = true;
    }
    std::optional<double> speed;
    if (s.velocity && s.velocity->vx)
        speed = std::hypot(*s.velocity->vx, s.velocity->vy.value_or(0));
    pose[3] = speed.value_or(0);
    if (!hasPose)
        return {};
    // A snapshot changes for many reasons (status, control, heartbeats): the same pose is judged once.
    if (!io.hasChecked || std::memcmp(io.checked, pose, sizeof pose) != 0) {
        std::memcpy(io.checked, pose, sizeof pose);
        io.hasChecked = true;
        const PoseGate::Verdict v = m_poseGate.check(std::to_string(s.subsystem), pose[0], pose[1], pose[2],
                                                     speed, SteadyClock::instance().now());
        if (v.ok()) {
            io.implausible.clear();
            io.globalPose = s.globalPose;
            io.localPose = s.localPose;
            io.velocity = s.velocity;
        } else {
            const char* cause = toString(v.fault);
            m_stack->counters().add(std::string("rx.implausible.") + cause);
            const QString why = QString::fromStdString(describe(v.fault, m_poseGate.limits()));
            io.implausible = tr("implausible pose ignored (%1 so far): %2").arg(v.peerCount).arg(why);
            if (v.warn)
                publishEvent(
                    makeEvent(EventSeverity::Warning, ocu::EventKind::Diagnostic, machineId(s.subsystem),
                              tr("JAUS subsystem %1: pose ignored, %2 (east %3 m, north %4 m, speed %5 "
                                 "m/s); last good pose kept (counted in rx.implausible.%6; one warning "
                                 "per vehicle and cause every 30 s)")
                                  .arg(s.subsystem)
                                  .arg(why)
                                  .arg(pose[0], 0, 'g', 6)
                                  .arg(pose[1], 0, 'g', 6)
                                  .arg(pose[3], 0, 'g', 6)
                                  .arg(QLatin1String(cause)),
                              QStringLiteral("jaus")));
        }
    }
    if (!io.implausible.isEmpty()) {
        s.globalPose = io.globalPose;
        s.localPose = io.localPose;
        s.velocity = io.velocity;
    }
    return io.implausible;
}

void JausBridge::onEvent(const JausEvent& event) {
    FleetEvent e = makeEvent(EventSeverity::Info, ocu::EventKind::Info,
                             event.subsystem ? machineId(event.subsystem) : QString(),
                             QString::fromStdString(event.text), QStringLiteral("jaus"));
    switch (event.kind) {
    case jaus::EventKind::LinkLost:
        e.kind = ocu::EventKind::LinkLoss;
        break;
    case jaus::EventKind::ControlLost:
    case jaus::EventKind::ControlPreempted:
    case jaus::EventKind::ControlRejected:
        e.kind = ocu::EventKind::ControlLost;
        break;
    case jaus::EventKind::HealthFault:
        e.kind = ocu::EventKind::HealthFault;
        break;
    default:
        e.kind = ocu::EventKind::Info;
        break;
    }
    switch (event.severity) {
    case Severity::Info:
        e.severity = EventSeverity::Info;
        break;
    case Severity::Warning:
        e.severity = EventSeverity::Warning;
        break;
    case Severity::Error:
        e.severity = EventSeverity::Alarm;
        break;
    }
    if (event.kind == jaus::EventKind::Emergency)
        e.severity = EventSeverity::Alarm;
    e.requiresAck = e.severity >= EventSeverity::Warning;
    publishEvent(e);
    QMetaObject::invokeMethod(
        this, [this, ev = toVehicleEvent(event)] { emit jausEvent(ev); }, Qt::QueuedConnection);
    if (event.kind == jaus::EventKind::DriveNotSent)
        QMetaObject::invokeMethod(
            this,
            [this, ss = event.subsystem, text = QString::fromStdString(event.text),
             failing = event.severity != Severity::Info] { emit driveProblem(ss, text, failing); },
            Qt::QueuedConnection);
}

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
    m.lastDataMs = s.lastMessageUnixMs;
    m.lastMessageMs = s.lastMessageUnixMs;
    if (s.globalPose && s.globalPose->lat && s.globalPose->lon) {
        const GeoPoint g{*s.globalPose->lat, *s.globalPose->lon,
                         s.globalPose->alt.value_or(m_frame.origin().alt)};
        const EnuPoint p = m_frame.toLocal(g);
        m.hasPosition = true;
        m.e = p.e;
        m.n = p.n;
        m.u = p.u;
        m.lat = g.lat;
        m.lon = g.lon;
        if (s.globalPose->yaw) // JAUS yaw: from north, positive clockwise (NED), radians
            m.headingDeg = std::fmod(*s.globalPose->yaw * 180.0 / M_PI + 360.0, 360.0);
    } else if (s.localPose && s.localPose->x && s.localPose->y) {
        // Local pose is in the vehicle's NED-like frame: x north, y east.
        const EnuPoint p{*s.localPose->y, *s.localPose->x, 0};
        const GeoPoint g = m_frame.toGeodetic(p);
        m.hasPosition = true;
        m.e = p.e;
        m.n = p.n;
        m.lat = g.lat;
        m.lon = g.lon;
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
        m.modeText = QString::fromUtf8(jaus::toString(*s.management));
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

// ---- GUI thread: commands ----

CommandResult JausBridge::refuseIfMonitor(const QString& what) const {
    if (!m_config.mayControl())
        return CommandResult::failure(tr("%1 refused: this console's JAUS role is MONITOR").arg(what));
    return CommandResult::success();
}

CommandResult JausBridge::refuseIfUnreachable(quint16 subsystem, const QString& what) const {
    auto it = m_latest.find(subsystem);
    if (it == m_latest.end())
        return CommandResult::failure(tr("%1 refused: %2 has not been heard on the JAUS link; nothing sent")
                                          .arg(what, machineId(subsystem)));
    if (it->link == JausLink::Down)
        return CommandResult::failure(
            tr("%1 refused: the link to %2 is down; nothing sent").arg(what, machineId(subsystem)));
    return CommandResult::success();
}

bool JausBridge::refuseIfNotRunning(const QString& target, OutcomeCallback& done) const {
    if (m_stack->running())
        return false;
    done({refusal(target, tr("the JAUS stack is not running; nothing sent"))});
    return true;
}

void JausBridge::stopAll(OutcomeCallback done) {
    if (!m_config.mayStop()) { // the one stop rule (JausConfig): every role may stop today
        done({refusal(QStringLiteral("jaus"), tr("emergency stop refused by this console's JAUS role"))});
        return;
    }
    if (!m_stack->running()) {
        // Nothing can go out; the result names every vehicle the console knows (heard earlier, or configured
        // as a static endpoint), each with the reason (one target per machine).
        std::vector<TargetOutcome> out;
        for (quint16 ss : knownSubsystems())
            out.push_back(refusal(machineId(ss), tr("the JAUS stack is not running; nothing sent")));
        if (out.empty())
            out.push_back(
                refusal(QStringLiteral("jaus"),
                        tr("no JAUS vehicle known and the JAUS stack is not running; nothing sent")));
        done(std::move(out));
        return;
    }
    // SetEmergency to every discovered subsystem, controlled by this console or not: the Management service
    // accepts it from any client, and to every configured static endpoint. No vehicle known at all: say that
    // nothing went out on JAUS.
    m_stack->setEmergencyAll(EmergencyCode::Safety, [done = std::move(done)](std::vector<TargetOutcome> out) {
        if (out.empty())
            out.push_back(TargetOutcome{"jaus", false,
                                        "no JAUS vehicle known (none discovered, no static endpoint "
                                        "configured): no SetEmergency sent"});
        done(std::move(out));
    });
}

QList<quint16> JausBridge::knownSubsystems() const {
    QList<quint16> out = subsystems();
    for (const StaticEndpoint& se : m_config.transport.staticEndpoints)
        if (se.id.subsystem != 0 && se.id.subsystem != 0xFFFF && se.id.subsystem != m_config.subsystemId &&
            !out.contains(se.id.subsystem))
            out << se.id.subsystem;
    std::sort(out.begin(), out.end());
    return out;
}

void JausBridge::stopMachine(const QString& id, OutcomeCallback done) {
    auto sub = subsystemOf(id);
    if (!sub) {
        done({refusal(id, tr("not a JAUS machine"))});
        return;
    }
    if (!m_config.mayStop()) {
        done({refusal(id, tr("emergency stop refused by this console's JAUS role"))});
        return;
    }
    if (auto r = refuseIfUnreachable(*sub, tr("emergency stop")); !r.ok) {
        done({refusal(id, r.message)});
        return;
    }
    if (refuseIfNotRunning(id, done))
        return;
    m_stack->setEmergency(*sub, EmergencyCode::Safety, std::move(done));
}

void JausBridge::clearStop(const QString& id, OutcomeCallback done) {
    auto sub = subsystemOf(id);
    if (!sub) {
        done({refusal(id, tr("not a JAUS machine"))});
        return;
    }
    if (!m_config.mayClearStop()) { // only roles with command rights may clear (JausConfig)
        done({refusal(id, tr("clear emergency refused: this console's JAUS role has no command rights"))});
        return;
    }
    if (auto r = refuseIfUnreachable(*sub, tr("clear emergency")); !r.ok) {
        done({refusal(id, r.message)});
        return;
    }
    if (refuseIfNotRunning(id, done))
        return;
    m_stack->clearEmergency(*sub, std::move(done));
}

bool JausBridge::confirmsCommand(const QString& action) const {
    return action == QLatin1String("clear_stop") || action == QLatin1String("request_control") ||
           action == QLatin1String("release_control");
}

bool JausBridge::reportsConfirmed(const QString& action, const QString& target) const {
    auto sub = subsystemOf(target);
    auto it = sub ? m_latest.find(*sub) : m_latest.end();
    if (it == m_latest.end())
        return false;
    if (action == QLatin1String("clear_stop"))
        return !it->emergency;
    if (action == QLatin1String("request_control"))
        return it->controlledByUs;
    if (action == QLatin1String("release_control"))
        return !it->controlledByUs;
    return false;
}

bool JausBridge::reportsStopped(const QString& target) const {
    auto sub = subsystemOf(target);
    auto it = sub ? m_latest.find(*sub) : m_latest.end();
    return it != m_latest.end() && it->emergency;
}

namespace {
DriveCommand toDriveCommand(const JausDrive& demand) {
    DriveCommand command;
    command.mode =
        demand.mode == JausDrive::Mode::Wrench ? DriveCommand::Mode::Wrench : DriveCommand::Mode::Velocity;
    command.linear = demand.linear;
    command.angular = demand.angular;
    command.brake = demand.brake;
    return command;
}
} // namespace

CommandResult JausBridge::refuseDriving(quint16 subsystem) const {
    if (auto r = refuseIfMonitor(tr("drive")); !r.ok)
        return r;
    if (!m_stack->running())
        return CommandResult::failure(tr("drive refused: the JAUS stack is not running; nothing sent"));
    auto s = this->subsystem(subsystem);
    if (s && s->link == JausLink::Down)
        return refuseIfUnreachable(subsystem, tr("drive"));
    if (!s || !s->controlledByUs)
        return CommandResult::failure(
            tr("drive refused: this console does not control %1").arg(machineId(subsystem)));
    return CommandResult::success();
}

CommandResult JausBridge::drive(quint16 subsystem, const JausDrive& demand) {
    if (auto r = refuseDriving(subsystem); !r.ok)
        return r;
    if (!m_sessions.contains(subsystem))
        return CommandResult::failure(tr("drive refused: no drive session open for %1 (a session starts "
                                         "through the command gate)")
                                          .arg(machineId(subsystem)));
    m_stack->setDriveCommand(subsystem, toDriveCommand(demand), {}); // the stream: failures are events
    return CommandResult::success(tr("drive demand handed to the drive stream"));
}

CommandResult JausBridge::stopDriving(quint16 subsystem) {
    m_sessions.remove(subsystem);
    if (QTimer* t = m_driveTimers.take(subsystem)) {
        t->stop();
        t->deleteLater();
    }
    if (!m_stack->running())
        return CommandResult::failure(tr("the JAUS stack is not running; no zero drive commands sent"));
    m_stack->stopDriving(subsystem, {}); // zeros, several times
    return CommandResult::success(tr("zero drive commands handed to the stack"));
}

CommandResult JausBridge::panTilt(quint16 subsystem, quint16 sensorId, double panRate, double tiltRate) {
    // Same rules as driving: role, running stack, link, control of the vehicle.
    if (auto r = refuseIfMonitor(tr("pan-tilt")); !r.ok)
        return r;
    if (!m_stack->running())
        return CommandResult::failure(tr("pan-tilt refused: the JAUS stack is not running; nothing sent"));
    auto s = this->subsystem(subsystem);
    if (s && s->link == JausLink::Down)
        return refuseIfUnreachable(subsystem, tr("pan-tilt"));
    if (!s || !s->controlledByUs)
        return CommandResult::failure(
            tr("pan-tilt refused: this console does not control %1").arg(machineId(subsystem)));
    if (!std::isfinite(panRate) || !std::isfinite(tiltRate))
        return CommandResult::failure(tr("pan-tilt refused: the rates must be finite numbers"));
    // Refusals on the io thread (no camera on a pan-tilt, control of the unit not confirmed yet) arrive as
    // CommandRefused events; the stream is not audited per message, like the drive stream.
    m_stack->panTilt(subsystem, sensorId, panRate, tiltRate, [](std::vector<TargetOutcome>) {});
    return CommandResult::success(tr("pan-tilt demand handed to the stack"));
}

void JausBridge::startSession(quint16 subsystem, OutcomeCallback done) {
    m_sessions.insert(subsystem);
    // A session the stack refused (or whose first message did not leave) is no session: the stream would
    // only be refused at the drive rate.
    QPointer<JausBridge> self(this);
    m_stack->startDriving(subsystem, [self, subsystem, done = std::move(done)](std::vector<TargetOutcome> o) {
        if (!allSent(o))
            QMetaObject::invokeMethod(
                self.data(),
                [self, subsystem] {
                    if (self)
                        self->m_sessions.remove(subsystem);
                },
                Qt::QueuedConnection);
        done(std::move(o));
    });
}

void JausBridge::command(const QString& name, const QJsonObject& args, OutcomeCallback done) {
    if (name == QLatin1String("release_all")) {
        if (refuseIfNotRunning(QStringLiteral("jaus"), done))
            return;
        // One target per subsystem this console controls; releaseAll also drops pending wishes for control.
        QList<quint16> controlled;
        for (const auto& v : std::as_const(m_latest))
            if (v.controlledByUs)
                controlled << v.subsystem;
        if (controlled.isEmpty()) {
            m_stack->releaseAll();
            done({refusal(QStringLiteral("jaus"),
                          tr("this console controls no JAUS vehicle: nothing to release"))});
            return;
        }
        struct Collect {
            std::mutex mutex;
            std::vector<TargetOutcome> out;
            int missing = 0;
            OutcomeCallback done;
        };
        auto c = std::make_shared<Collect>();
        c->missing = int(controlled.size());
        c->done = std::move(done);
        for (quint16 ss : controlled)
            m_stack->releaseControl(ss, [c](std::vector<TargetOutcome> o) {
                std::unique_lock lock(c->mutex);
                c->out.insert(c->out.end(), o.begin(), o.end());
                if (--c->missing == 0) {
                    auto out = std::move(c->out);
                    lock.unlock();
                    c->done(std::move(out));
                }
            });
        m_stack->releaseAll();
        return;
    }
    const QString id = args.value(QStringLiteral("id")).toString();
    auto sub = subsystemOf(id);
    if (!sub) {
        done({refusal(id.isEmpty() ? QStringLiteral("jaus") : id,
                      tr("%1: \"id\" must name a JAUS machine such as \"jaus:101\"").arg(name))});
        return;
    }
    auto refuse = [&](const QString& why) { done({refusal(id, why)}); };
    // Releasing is never refused for a down link: it also drops the wish for control, so the console does not
    // take control back when the vehicle is heard again.
    if (name == QLatin1String("release_control")) {
        if (!refuseIfNotRunning(id, done))
            m_stack->releaseControl(*sub, std::move(done));
        return;
    }
    if (auto r = refuseIfMonitor(name); !r.ok)
        return refuse(r.message);
    if (name == QLatin1String("drive_stop")) {
        // End of a drive session (release, focus loss, joystick loss, vehicle changed...): zeros, several
        // times; the result says whether the first one left, and why the session ended.
        const QString why = args.value(QStringLiteral("reason")).toString();
        if (QTimer* t = m_driveTimers.take(*sub)) {
            t->stop();
            t->deleteLater();
        }
        m_sessions.remove(*sub);
        if (refuseIfNotRunning(id, done))
            return;
        m_stack->stopDriving(*sub, [why, done = std::move(done)](std::vector<TargetOutcome> o) {
            if (!why.isEmpty())
                for (TargetOutcome& t : o)
                    if (t.sent)
                        t.note = "session ended: " + why.toStdString();
            done(std::move(o));
        });
        return;
    }
    if (name == QLatin1String("drive_start")) {
        // A teleop session: one gate command (and audit line) per session, not per message.
        if (auto r = refuseDriving(*sub); !r.ok)
            return refuse(r.message);
        startSession(*sub, std::move(done));
        return;
    }
    static const QStringList kOverTheLink{QStringLiteral("request_control"), QStringLiteral("resume"),
                                          QStringLiteral("standby"), QStringLiteral("shutdown"),
                                          QStringLiteral("reset")};
    if (kOverTheLink.contains(name))
        if (auto r = refuseIfUnreachable(*sub, name); !r.ok)
            return refuse(r.message);
    if (refuseIfNotRunning(id, done))
        return;
    if (name == QLatin1String("request_control")) {
        m_stack->requestControl(*sub, std::move(done));
        return;
    }
    // Management commands: the stack says per vehicle what went on the wire (or why not); the vehicle's
    // management state shows the effect.
    if (name == QLatin1String("resume"))
        return m_stack->resume(*sub, std::move(done));
    if (name == QLatin1String("standby"))
        return m_stack->standby(*sub, std::move(done));
    if (name == QLatin1String("shutdown"))
        return m_stack->shutdown(*sub, std::move(done));
    if (name == QLatin1String("reset"))
        return m_stack->reset(*sub, std::move(done));
    // A timed drive (headless): the session opens if needed, and the result says whether the demand itself
    // was taken by the socket; the demand is then refreshed at the drive rate (the stack zeroes a stale one)
    // and the session ends with zeros after `duration`.
    if (name == QLatin1String("drive")) {
        JausDrive c;
        const QString mode = args.value(QStringLiteral("mode")).toString(QStringLiteral("velocity"));
        if (mode != QLatin1String("velocity") && mode != QLatin1String("effort"))
            return refuse(tr("drive: \"mode\" must be \"velocity\" or \"effort\""));
        c.mode = mode == QLatin1String("effort") ? JausDrive::Mode::Wrench : JausDrive::Mode::Velocity;
        c.linear = args.value(QStringLiteral("linear")).toDouble(0);
        c.angular = args.value(QStringLiteral("angular")).toDouble(0);
        const double duration = args.value(QStringLiteral("duration")).toDouble(1.0);
        if (!(duration > 0 && duration <= 60))
            return refuse(tr("drive: \"duration\" must be between 0 and 60 seconds"));
        if (c.mode == JausDrive::Mode::Wrench && (std::abs(c.linear) > 100 || std::abs(c.angular) > 100))
            return refuse(tr("drive: effort must be within ±100 %"));
        if (auto r = refuseDriving(*sub); !r.ok)
            return refuse(r.message);
        if (!m_sessions.contains(*sub))
            startSession(*sub, [](std::vector<TargetOutcome>) {}); // the demand's outcome tells
        m_stack->setDriveCommand(*sub, toDriveCommand(c), std::move(done));
        // The demand is refreshed at the drive rate for the duration (the stack zeroes a stale demand),
        // then the session stops with zeros.
        QTimer*& t = m_driveTimers[*sub];
        if (!t) {
            t = new QTimer(this);
            t->setTimerType(Qt::PreciseTimer);
        }
        t->disconnect();
        const std::uint16_t s = *sub;
        const qint64 until = QDateTime::currentMSecsSinceEpoch() + static_cast<qint64>(duration * 1000);
        connect(t, &QTimer::timeout, this, [this, s, c, until] {
            if (QDateTime::currentMSecsSinceEpoch() >= until || !drive(s, c).ok)
                stopDriving(s);
        });
        t->start(static_cast<int>(1000.0 / std::max(1.0, m_config.driveRateHz)));
        return;
    }
    FleetBridge::command(name, args, std::move(done));
}

std::chrono::milliseconds JausBridge::ioStalledFor() const {
    return m_stack ? m_stack->ioStalledFor() : std::chrono::milliseconds(0);
}

void JausBridge::postToIo(std::function<void()> f) {
    if (m_stack)
        m_stack->postToIo(std::move(f));
}

QVector<LinkCounters> JausBridge::linkCounters() const {
    return {LinkCounters::of(QStringLiteral("jaus"), m_stack->counters())};
}

} // namespace ocu
