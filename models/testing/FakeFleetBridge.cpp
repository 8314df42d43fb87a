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
}

CommandResult FakeFleetBridge::stopAll() {
    record(QStringLiteral("stop_all"), {});
    if (refusedCommands.contains(QStringLiteral("stop_all")))
        return CommandResult::failure(QStringLiteral("refused"));
    QStringList ids;
    {
        std::lock_guard lock(m_mutex);
        ids = m_machines.keys();
    }
    for (const QString& id : ids)
        setStop(id, StopState::Stopped);
    return CommandResult::success(QStringLiteral("stop sent to %1 machines").arg(ids.size()));
}

CommandResult FakeFleetBridge::stopMachine(const QString& id) {
    record(QStringLiteral("stop"), id);
    if (refusedCommands.contains(QStringLiteral("stop")))
        return CommandResult::failure(QStringLiteral("refused"));
    setStop(id, StopState::Stopped);
    return CommandResult::success();
}

CommandResult FakeFleetBridge::clearStop(const QString& id) {
    record(QStringLiteral("clear_stop"), id);
    if (refusedCommands.contains(QStringLiteral("clear_stop")))
        return CommandResult::failure(QStringLiteral("refused"));
    setStop(id, StopState::None);
    return CommandResult::success();
}

CommandResult FakeFleetBridge::command(const QString& name, const QJsonObject& args) {
    record(name, args.value(QStringLiteral("id")).toString(), args);
    if (refusedCommands.contains(name))
        return CommandResult::failure(QStringLiteral("insufficient authority"));
    return CommandResult::success();
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
