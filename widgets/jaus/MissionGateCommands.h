#pragma once
// The mission panel's sending through the command gate: each call becomes the typed command (MissionUpload,
// MissionStart, MissionPause, MissionResume, MissionAbort, GoTo), audited by the gate and answered per target
// in the event log. A child of the panel it serves.
#include "models/CommandGate.h"
#include "widgets/jaus/MissionCommands.h"

#include <QObject>
#include <QPointer>

namespace ocu {

class MissionGateCommands final : public QObject, public MissionCommands {
    Q_OBJECT
public:
    MissionGateCommands(CommandGate* gate, QObject* parent) : QObject(parent), m_gate(gate) {}

    void upload(const QString& id, const QVector<MissionWaypoint>& waypoints) override {
        send(MissionUpload{id, waypoints, std::nullopt}); // global where the vehicle offers it
    }
    void start(const QString& id, int fromIndex) override { send(MissionStart{id, fromIndex}); }
    void pause(const QString& id) override { send(MissionPause{id}); }
    void resume(const QString& id) override { send(MissionResume{id}); }
    void abort(const QString& id) override { send(MissionAbort{id}); }
    void goTo(const QString& id, const MissionWaypoint& waypoint) override { send(GoTo{id, waypoint}); }

private:
    void send(const OperatorCommand& command) {
        if (m_gate)
            m_gate->command(command, QStringLiteral("gui"));
    }
    QPointer<CommandGate> m_gate;
};

} // namespace ocu
