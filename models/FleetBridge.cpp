#include "models/FleetBridge.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QTimer>

namespace ocu {

QJsonArray targetsToJson(const QVector<TargetOutcome>& targets) {
    QJsonArray out;
    for (const TargetOutcome& t : targets) {
        QJsonObject j;
        j[QStringLiteral("id")] = targetId(t);
        j[QStringLiteral("sent")] = t.sent;
        if (!t.sent) {
            j[QStringLiteral("cause")] = QLatin1String(nameFor(t.cause));
            j[QStringLiteral("reason")] = reasonText(t);
        }
        if (!t.note.empty())
            j[QStringLiteral("note")] = noteText(t);
        out.append(j);
    }
    return out;
}

quint64 LinkCounters::rejectedTotal() const {
    quint64 n = 0;
    for (quint64 v : rejected)
        n += v;
    return n;
}

LinkCounters LinkCounters::of(const QString& link, const Counters& counters) {
    LinkCounters out;
    out.link = link;
    for (const auto& [name, value] : counters.snapshot()) {
        const QString n = QString::fromStdString(name);
        out.all.insert(n, value);
        if (Counters::isReject(name))
            out.rejected.insert(n.mid(3), value);
    }
    return out;
}

FleetBridge::FleetBridge(Protocol protocol, QObject* parent)
    : QObject(parent), m_protocol(protocol),
      m_machines(this, [this](auto&& batch) { deliverMachines(std::move(batch)); }),
      m_links(this, [this](auto&& batch) { deliverLinks(std::move(batch)); }) {
    qRegisterMetaType<ocu::MachineState>();
    qRegisterMetaType<ocu::FleetEvent>();
    qRegisterMetaType<ocu::LinkStatus>();
    auto* watchdog = new QTimer(this);
    connect(watchdog, &QTimer::timeout, this, &FleetBridge::checkWatchdog);
    watchdog->start(250);
}

FleetBridge::~FleetBridge() = default;

bool FleetBridge::ownsMachine(const QString& id) const {
    return id.startsWith(protocolPrefix(m_protocol));
}

void FleetBridge::publishMachine(const MachineState& state) {
    m_machines.push(state.id, state);
}

void FleetBridge::publishMachines(std::vector<MachineState>&& states) {
    TelemetryCoalescer<QString, std::optional<MachineState>>::Batch batch;
    batch.reserve(states.size());
    for (auto& m : states) {
        QString id = m.id;
        batch.emplace_back(std::move(id), std::move(m));
    }
    m_machines.push(std::move(batch));
}

void FleetBridge::publishRemoval(const QString& id) {
    m_machines.push(id, std::nullopt);
}

void FleetBridge::publishLink(const LinkStatus& status) {
    m_links.push(status.link, status);
}

void FleetBridge::publishEvent(const FleetEvent& event) {
    FleetEvent ev = event;
    if (ev.timeMs == 0)
        ev.timeMs = QDateTime::currentMSecsSinceEpoch();
    if (ev.source.isEmpty())
        ev.source = toText(m_protocol);
    QMetaObject::invokeMethod(
        this, [this, ev] { emit eventRaised(ev); }, Qt::QueuedConnection);
}

CommandResult CommandResult::fromTargets(QVector<TargetOutcome> targets, const QString& whenEmpty) {
    CommandResult r;
    r.targets = std::move(targets);
    if (r.targets.isEmpty()) {
        r.ok = false;
        r.message = whenEmpty.isEmpty()
                        ? QCoreApplication::translate("CommandResult", "no target: nothing sent")
                        : whenEmpty;
        return r;
    }
    QStringList sent;
    for (const TargetOutcome& t : std::as_const(r.targets))
        if (t.sent)
            sent << (t.note.empty() ? targetId(t) : QStringLiteral("%1 (%2)").arg(targetId(t), noteText(t)));
    const QStringList failed = r.notSent();
    r.ok = failed.isEmpty();
    if (r.ok)
        r.message =
            QCoreApplication::translate("CommandResult", "sent to %1").arg(sent.join(QStringLiteral(", ")));
    else if (sent.isEmpty())
        r.message = QCoreApplication::translate("CommandResult", "NOT sent: %1")
                        .arg(failed.join(QStringLiteral("; ")));
    else
        r.message = QCoreApplication::translate("CommandResult", "sent to %1; NOT sent: %2")
                        .arg(sent.join(QStringLiteral(", ")), failed.join(QStringLiteral("; ")));
    return r;
}

QStringList CommandResult::notSent() const {
    QStringList out;
    for (const TargetOutcome& t : targets)
        if (!t.sent)
            out << (t.reason.empty() ? targetId(t)
                                     : QStringLiteral("%1: %2").arg(targetId(t), reasonText(t)));
    return out;
}

TargetOutcome refusal(const QString& target, OutcomeReason cause, const QString& reason) {
    return TargetOutcome::refused(target.toStdString(), cause, reason.toStdString());
}

void FleetBridge::command(const OperatorCommand& command, OutcomeCallback done) {
    QString target = commandTarget(command);
    if (target.isEmpty())
        target = toText(m_protocol);
    done({refusal(target, OutcomeReason::NotSupported,
                  tr("command '%1' not supported by %2").arg(commandName(command), toText(m_protocol)))});
}

QVector<LinkStatus> FleetBridge::links() const {
    QVector<LinkStatus> out;
    out.reserve(m_linkState.size());
    for (const LinkStatus& l : m_linkState)
        out.push_back(l);
    return out;
}

std::optional<LinkStatus> FleetBridge::linkStatus(const QString& link) const {
    auto it = m_linkState.find(link);
    if (it == m_linkState.end())
        return std::nullopt;
    return *it;
}

void FleetBridge::flushPending() {
    m_links.drainNow();
    m_machines.drainNow();
}

void FleetBridge::publishStackStopped(const QString& detail) {
    m_links.drainNow(); // a report still queued from the stack must not arrive after "stopped"
    for (auto it = m_linkState.cbegin(); it != m_linkState.cend(); ++it)
        m_links.push(it.key(), LinkStatus{it.key(), LinkState::Down, -1, detail});
    m_links.drainNow();
}

void FleetBridge::deliverMachines(std::vector<std::pair<QString, std::optional<MachineState>>>&& batch) {
    QVector<MachineState> updated;
    QStringList removed;
    updated.reserve(int(batch.size()));
    for (auto& [id, state] : batch) {
        if (state)
            updated.push_back(std::move(*state));
        else
            removed.push_back(id);
    }
    if (!removed.isEmpty())
        emit machinesRemoved(removed);
    if (!updated.isEmpty())
        emit machinesUpdated(updated);
}

void FleetBridge::deliverLinks(std::vector<std::pair<QString, LinkStatus>>&& batch) {
    for (auto& [name, status] : batch) {
        m_reportedLinks.insert(name, status);
        const LinkStatus shown = shownLink(status);
        m_linkState.insert(name, shown);
        emit linkChanged(shown);
    }
}

LinkStatus FleetBridge::shownLink(const LinkStatus& reported) const {
    if (!m_ioStalled)
        return reported;
    // A stalled io thread neither receives nor sends: whatever the stack last said, the link is degraded at
    // best (a link already down stays down).
    LinkStatus s = reported;
    if (s.state != LinkState::Down)
        s.state = LinkState::Degraded;
    const QString why = tr("%1 io thread not turning").arg(toText(m_protocol));
    s.detail = s.detail.isEmpty() ? why : why + QStringLiteral("; ") + s.detail;
    return s;
}

void FleetBridge::checkWatchdog() {
    const std::chrono::milliseconds stall = ioStalledFor();
    const bool stalled = stall > m_watchdogLimit;
    if (stalled == m_ioStalled)
        return;
    m_ioStalled = stalled;
    // Links still queued by the io thread first, so the override applies to the newest reports.
    m_links.drainNow();
    FleetEvent ev;
    if (stalled) {
        ev = makeEvent(EventSeverity::Alarm, EventKind::LinkLoss, {},
                       tr("%1 io thread has not turned for %2 s (watchdog): its links are degraded, data and "
                          "commands are held up")
                           .arg(toText(m_protocol))
                           .arg(double(stall.count()) / 1000.0, 0, 'f', 1));
    } else {
        ev = makeEvent(EventSeverity::Info, EventKind::LinkLoss, {},
                       tr("%1 io thread turns again (watchdog)").arg(toText(m_protocol)));
    }
    publishEvent(ev);
    for (const LinkStatus& reported : std::as_const(m_reportedLinks)) {
        const LinkStatus shown = shownLink(reported);
        m_linkState.insert(reported.link, shown);
        emit linkChanged(shown);
    }
}

} // namespace ocu
