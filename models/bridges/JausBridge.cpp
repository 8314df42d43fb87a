#include "models/bridges/JausBridge.h"
#include "models/bridges/JausBridgeRows.h"

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

JausBridge::JausBridge(const JausConfig& config, const GeoFrame& frame, QObject* parent)
    : JausVehicleBridge(parent), m_config(config), m_frame(frame),
      m_snapshots(
          this,
          [this](auto&& batch) {
              for (auto& [id, snap] : batch) {
                  JausVehicle v = jausrow::toVehicle(snap);
                  v.lastMessageUnixMs = modelTimeOfWallMs(v.lastMessageUnixMs); // ages on the models' clock
                  for (JausHandoffPrompt& p : v.handoff.prompts)
                      p.receivedMs = modelTimeOfWallMs(p.receivedMs);
                  JausVehicle& latest = m_latest[id]; // a new vehicle starts default: not in emergency
                  const bool wasStopped = latest.emergency;
                  const bool wasOurs = latest.controlledByUs;
                  const bool wasDenied = latest.access == JausAccess::InsufficientAuthority;
                  const bool wasRunning = latest.mission.state == MissionState::Running;
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
                  if (wasRunning && v.mission.state != MissionState::Running)
                      emit commandReported(
                          QStringLiteral("mission_pause"), machineId(id),
                          tr("%1 reports the mission %2").arg(name, toText(v.mission.state)));
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
    id.ownId = jausrow::toAddress(m_config.ownId());
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
        this, [this, ev = jausrow::toVehicleEvent(event)] { emit jausEvent(ev); }, Qt::QueuedConnection);
    if (event.kind == jaus::EventKind::DriveNotSent)
        QMetaObject::invokeMethod(
            this,
            [this, ss = event.subsystem, text = QString::fromStdString(event.text),
             failing = event.severity != Severity::Info] { emit driveProblem(ss, text, failing); },
            Qt::QueuedConnection);
}

bool JausBridge::confirmsCommand(const QString& action) const {
    return action == QLatin1String("clear_stop") || action == QLatin1String("request_control") ||
           action == QLatin1String("release_control") || action == QLatin1String("mission_pause");
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
    if (action == QLatin1String("mission_pause")) // the list driver no longer drives the vehicle
        return it->mission.state != MissionState::Running;
    return false;
}

bool JausBridge::reportsStopped(const QString& target) const {
    auto sub = subsystemOf(target);
    auto it = sub ? m_latest.find(*sub) : m_latest.end();
    return it != m_latest.end() && it->emergency;
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
