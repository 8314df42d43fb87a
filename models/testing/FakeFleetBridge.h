#pragma once
// A protocol bridge without a stack, for tests and benchmarks. It records every command and, when
// `simulateMachines` is on, makes its machines report the stop state that was commanded (like a
// well-behaved simulator would), through the same coalescing path as a real bridge.
#include "models/FleetBridge.h"

#include <QHash>
#include <QJsonObject>
#include <QStringList>
#include <mutex>
#include <thread>

namespace ocu {

class FakeFleetBridge : public FleetBridge {
    Q_OBJECT
public:
    explicit FakeFleetBridge(Protocol protocol, QObject* parent = nullptr);

    struct Call {
        QString name; // "stop_all", "stop", "clear_stop", or the command's name (commandName)
        QString id;
        QJsonObject args; // command(): the command as JSON (toJson)
    };

    // Thread-safe: stores the machine (for the simulated stop reports) and publishes it.
    void setMachine(const MachineState& m);
    void removeMachine(const QString& id);

    // Answers at once (on the calling thread) with one target per machine (stop_all) or the machine named.
    void stopAll(OutcomeCallback done) override;
    void stopMachine(const QString& id, OutcomeCallback done) override;
    void clearStop(const QString& id, OutcomeCallback done) override;
    // Every command is sent to its target (the machine, else the protocol), unless refusedCommands names it.
    void command(const OperatorCommand& command, OutcomeCallback done) override;

    QVector<Call> calls() const;
    void clearCalls();

    bool simulateMachines = true;
    // Declares stopAll callable from any thread, sending on the caller's thread (set before addBridge).
    bool fromCallersThread = false;
    bool stopsFromCallersThread() const override { return fromCallersThread; }
    // The thread of the last stopAll call.
    std::thread::id stopAllThread() const {
        std::lock_guard lock(m_mutex);
        return m_stopAllThread;
    }
    // Never answer (a stack that hangs): the CommandGate's deadline must decide.
    bool silent = false;
    // Commands named here are refused (to test role/authority enforcement paths).
    QStringList refusedCommands;
    // Optional pass-count layer / site map exposed through the base interface.
    const PassCountLayer* layer = nullptr;
    SiteMapData map;
    const PassCountLayer* passCountLayer() const override { return layer; }
    SiteMapData siteMap() const override { return map; }

private:
    void answer(OutcomeCallback done, std::vector<TargetOutcome> out);
    void record(const QString& name, const QString& id, const QJsonObject& args = {});
    void setStop(const QString& id, StopState s);

    mutable std::mutex m_mutex;
    QHash<QString, MachineState> m_machines;
    QVector<Call> m_calls;
    std::thread::id m_stopAllThread;
};

} // namespace ocu
