#pragma once
// A JAUS bridge without a stack for the JAUS panels' tests: each test sets the vehicles' views as the real
// bridge would from their reports, and reads back the commands the gate handed over.
#include "models/jaus/JausVehicleBridge.h"

#include <QMap>
#include <QVector>

namespace ocu::testing {

class FakeJausBridge final : public JausVehicleBridge {
public:
    JausConsoleIdentity ident{QStringLiteral("OCU"), 200, 205, true, true, true, 20, {}};
    QMap<quint16, JausVehicle> vehicles;
    // What the gate handed over, as the audit writes it; each is answered as sent to its target.
    QVector<OperatorCommand> commands;

    JausConsoleIdentity identity() const override { return ident; }
    QList<quint16> subsystems() const override { return vehicles.keys(); }
    std::optional<JausVehicle> subsystem(quint16 id) const override {
        return vehicles.contains(id) ? std::optional<JausVehicle>(vehicles.value(id)) : std::nullopt;
    }
    CommandResult drive(quint16, const JausDrive&) override { return CommandResult::failure("no drive"); }
    CommandResult stopDriving(quint16) override { return CommandResult::failure("no drive"); }
    void stopAll(OutcomeCallback done) override { done({}); }
    void stopMachine(const QString&, OutcomeCallback done) override { done({}); }
    void clearStop(const QString&, OutcomeCallback done) override { done({}); }
    void command(const OperatorCommand& c, OutcomeCallback done) override {
        commands << c;
        done({TargetOutcome::sentTo(commandTarget(c).toStdString())});
    }
    void report(const JausVehicle& v) {
        vehicles[v.subsystem] = v;
        emit subsystemUpdated(v);
    }
};

} // namespace ocu::testing
