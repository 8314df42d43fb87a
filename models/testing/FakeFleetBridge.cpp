#include "models/testing/FakeFleetBridge.h"

namespace ocu {

FakeFleetBridge::FakeFleetBridge(Protocol protocol, QObject* parent) : FleetBridge(protocol, parent) {}

void FakeFleetBridge::setMachine(const MachineState& m) {
    {
        std::lock_guard lock(m_mutex);
        m_machines.insert(m.id, m);
    }
    publishMachine(m);
}

void FakeFleetBridge::removeMachine(const QString& id) {
    {
        std::lock_guard lock(m_mutex);
        m_machines.remove(id);
    }
    publishRemoval(id);
}

void FakeFleetBridge::record(const QString& name, const QString& id, const QJsonObject& args) {
    std::lock_guard lock(m_mutex);
    m_calls.push_back({name, id, args});
}

void FakeFleetBridge::setStop(const QString& id, StopState s) {
    if (!simulateMachines)
        return;
    MachineState m;
    {
        std::lock_guard lock(m_mutex);
        auto it = m_machines.find(id);
        if (it == m_machines.end())
            return;
        it->stop = s;
        it->stopText = s == StopState::Stopped ? QStringLiteral("emergency") : QString();
        m = *it;
    }
    publishMachine(m);
    if (s == StopState::Stopped)
        QMetaObject::invokeMethod(
            this, [this, id] { emit stopReported(id, QStringLiteral("%1 reports stopped").arg(id)); },
            Qt::QueuedConnection);
}

void FakeFleetBridge::answer(OutcomeCallback done, std::vector<TargetOutcome> out) {
    if (silent)
        return; // a stack that never answers: the gate's deadline decides
    done(std::move(out));
}

void FakeFleetBridge::stopAll(OutcomeCallback done) {
    record(QStringLiteral("stop_all"), {});
    {
        std::lock_guard lock(m_mutex);
        m_stopAllThread = std::this_thread::get_id();
    }
    if (refusedCommands.contains(QStringLiteral("stop_all")))
        return answer(std::move(done),
                      {refusal(toText(protocol()), OutcomeReason::Refused, QStringLiteral("refused"))});
    QStringList ids;
    {
        std::lock_guard lock(m_mutex);
        ids = m_machines.keys();
    }
    ids.sort();
    std::vector<TargetOutcome> out;
    for (const QString& id : ids) {
        setStop(id, StopState::Stopped);
        out.push_back(TargetOutcome::sentTo(id.toStdString()));
    }
    answer(std::move(done), std::move(out));
}

void FakeFleetBridge::stopMachine(const QString& id, OutcomeCallback done) {
    record(QStringLiteral("stop"), id);
    if (refusedCommands.contains(QStringLiteral("stop")))
        return answer(std::move(done), {refusal(id, OutcomeReason::Refused, QStringLiteral("refused"))});
    setStop(id, StopState::Stopped);
    answer(std::move(done), {TargetOutcome::sentTo(id.toStdString())});
}

void FakeFleetBridge::clearStop(const QString& id, OutcomeCallback done) {
    record(QStringLiteral("clear_stop"), id);
    if (refusedCommands.contains(QStringLiteral("clear_stop")))
        return answer(std::move(done), {refusal(id, OutcomeReason::Refused, QStringLiteral("refused"))});
    setStop(id, StopState::None);
    answer(std::move(done), {TargetOutcome::sentTo(id.toStdString())});
}

void FakeFleetBridge::command(const OperatorCommand& command, OutcomeCallback done) {
    const QString name = commandName(command);
    const QString id = commandTarget(command);
    record(name, id, toJson(command));
    const QString target = id.isEmpty() ? toText(protocol()) : id;
    if (refusedCommands.contains(name))
        return answer(std::move(done), {refusal(target, OutcomeReason::NotPermitted,
                                                QStringLiteral("insufficient authority"))});
    answer(std::move(done), {TargetOutcome::sentTo(target.toStdString())});
}

QVector<FakeFleetBridge::Call> FakeFleetBridge::calls() const {
    std::lock_guard lock(m_mutex);
    return m_calls;
}

void FakeFleetBridge::clearCalls() {
    std::lock_guard lock(m_mutex);
    m_calls.clear();
}

} // namespace ocu
