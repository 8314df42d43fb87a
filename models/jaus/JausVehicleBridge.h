#pragma once
// What the JAUS panels (widgets/jaus) see of the JAUS link: the Qt-typed vehicle views, their events, this
// console's identity and the teleop drive stream, on top of the fleet bridge's commands. The concrete
// JausBridge (models/bridges) implements it over the JAUS stack; the panels include only this header.
//
// Threading as for every FleetBridge: the object lives on the GUI thread; its signals are emitted there.
#include "models/FleetBridge.h"
#include "models/jaus/JausVehicle.h"

#include <QList>

#include <optional>

namespace ocu {

class JausVehicleBridge : public FleetBridge {
    Q_OBJECT
public:
    explicit JausVehicleBridge(QObject* parent = nullptr);
    ~JausVehicleBridge() override;

    // "jaus:<subsystem>" and back (nullopt for anything else).
    static QString machineId(quint16 subsystem);
    static std::optional<quint16> subsystemOf(const QString& machineId);

    virtual JausConsoleIdentity identity() const = 0;
    bool mayCommand() const { return identity().mayControl; }

    // GUI thread: the latest view of every vehicle heard of, in subsystem order.
    virtual QList<quint16> subsystems() const = 0;
    virtual std::optional<JausVehicle> subsystem(quint16 id) const = 0;

    // Drive stream for teleop (GUI thread). The session is opened and closed through the CommandGate
    // (commands "drive_start" and "drive_stop" {"id", "reason"}: audited, with what went on the wire); this
    // carries the demands of an open session at the drive rate, without one audit line per message. Refused
    // (nothing posted, the reason in the result) without an open session, control of the vehicle, a running
    // stack or a link; ok = the demand was handed to the stream. A stream message the socket does not take
    // is reported by driveProblem() (and an event), once per failing streak.
    virtual CommandResult drive(quint16 subsystem, const JausDrive& command) = 0;
    // Closes the session with zero demands, several times, without the gate (last resort when the gate is
    // gone, e.g. while the window is destroyed).
    virtual CommandResult stopDriving(quint16 subsystem) = 0;
    // Pan-tilt of a camera (AEP-4818 §9.3.3), GUI thread: rates in rad/s (+ pan = right, + tilt =
    // up), zero = stop. Refused like drive() without control of the vehicle, a running stack or a link;
    // ok = the demand was handed to the stack, which streams it while it is refreshed (a demand not refreshed
    // within the drive command timeout goes to zero) and reports a refusal as an event. The default: this
    // bridge drives no pan-tilt.
    virtual CommandResult panTilt(quint16 subsystem, quint16 sensorId, double panRate, double tiltRate);

signals:
    void subsystemUpdated(const ocu::JausVehicle& vehicle);
    void jausEvent(const ocu::JausVehicleEvent& event);
    // The drive stream to `subsystem` stopped reaching the socket (failing = true, `text` says why) or goes
    // out again (failing = false).
    void driveProblem(quint16 subsystem, const QString& text, bool failing);
};

} // namespace ocu
