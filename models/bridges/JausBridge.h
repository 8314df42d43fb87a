#pragma once
// The Qt face of the JAUS stack: subsystem snapshots become MachineState rows (coalesced), JAUS events
// become fleet events, and console commands are posted to the stack. Also keeps the Qt-typed view of every
// subsystem (models/jaus/JausVehicle.h) for the access-control, teleop and details panels, which see it only
// through JausVehicleBridge.
// One job per file: JausBridge.cpp the stack's life and its reports, JausBridgeRows.cpp the pure row
// mapping, JausPoseAdmission.cpp the pose plausibility gate, JausBridgeCommands.cpp the operator commands,
// JausDriveSessions.cpp the drive sessions and streams.
#include "models/jaus/JausVehicleBridge.h"

#include "protocols/common/GeoFrame.h"
#include "protocols/common/MessageTap.h"
#include "protocols/common/PosePlausibility.h"
#include "protocols/jaus/JausConfig.h"
#include "protocols/jaus/JausTypes.h"

#include <QHash>
#include <QSet>
#include <QTimer>

#include <map>
#include <memory>

namespace ocu::jaus {
class JausStack;
}

namespace ocu {

class JausBridge : public JausVehicleBridge, private jaus::JausListener {
    Q_OBJECT
public:
    JausBridge(const jaus::JausConfig& config, const GeoFrame& frame, QObject* parent = nullptr);
    ~JausBridge() override;

    // Starts the stack; returns an empty string or why it could not (e.g. the UDP port is taken).
    QString start();
    // The flight recorder's tap on the stack's inbound messages (before start()).
    void setMessageTap(MessageTap* tap);
    void stop();
    const jaus::JausConfig& config() const { return m_config; }
    JausConsoleIdentity identity() const override;

    // GUI thread: the latest view of every subsystem.
    QList<quint16> subsystems() const override;
    std::optional<JausVehicle> subsystem(quint16 id) const override;

    void stopAll(OutcomeCallback done) override;
    bool stopsFromCallersThread() const override { return true; } // the stack's fast path
    void stopMachine(const QString& id, OutcomeCallback done) override;
    void clearStop(const QString& id, OutcomeCallback done) override;
    // RequestControl, ReleaseControl, ReleaseAll, Management (resume, standby, shutdown, reset), DriveStart,
    // DriveStop, TimedDrive, the mission commands and the platform services' (SetPlatformMode,
    // SetPlatformState, SetLights, Odometry); every other command is not supported.
    void command(const OperatorCommand& command, OutcomeCallback done) override;
    bool reportsStopped(const QString& target) const override;
    // clear_stop (the vehicle reports no EMERGENCY), request_control / release_control (ReportControl /
    // ConfirmControl as the vehicle reports them).
    bool confirmsCommand(const QString& action) const override;
    bool reportsConfirmed(const QString& action, const QString& target) const override;

    CommandResult drive(quint16 subsystem, const JausDrive& command) override;
    // Watchdog: the stack's io thread.
    QVector<LinkCounters> linkCounters() const override;
    std::chrono::milliseconds ioStalledFor() const override;
    // Runs f on the stack's io thread without waiting (diagnostics; the watchdog tests block it on purpose).
    void postToIo(std::function<void()> f);
    // The stack without its group socket (JausStack::groupSocketProblem): "JAUS: no group socket (3794 held
    // by another process)"; empty otherwise.
    QString statusNote() const override;
    CommandResult stopDriving(quint16 subsystem) override;
    CommandResult panTilt(quint16 subsystem, quint16 sensorId, double panRate, double tiltRate) override;

private:
    void onSubsystemChanged(const jaus::SubsystemSnapshot& snapshot) override;
    void onEvent(const jaus::JausEvent& event) override;
    MachineState toMachine(const jaus::SubsystemSnapshot& s) const;
    // GUI thread: the refusal of `what` to `target` when this console's role is MONITOR; none when it may.
    std::optional<TargetOutcome> refuseIfMonitor(const QString& target, const QString& what) const;
    // GUI thread: a refusal when the subsystem was never heard or its link is down (nothing is posted then).
    std::optional<TargetOutcome> refuseIfUnreachable(quint16 subsystem, const QString& what) const;
    // True (and `done` called with the refusal) when the stack is not running: it would never answer.
    bool refuseIfNotRunning(const QString& target, OutcomeCallback& done) const;
    // Why the console may not drive `subsystem` now (role, stack, link, control); none when it may.
    std::optional<TargetOutcome> refuseDriving(quint16 subsystem) const;
    // The subsystem `id` names, or none (and `done` called with the refusal of `what`).
    std::optional<quint16> vehicleOf(const QString& id, const QString& what, OutcomeCallback& done) const;
    // A command over the link to one vehicle (request control, management): refused for the monitor role, a
    // vehicle not heard or whose link is down, a stopped stack; else `send` posts it.
    void sendToVehicle(const QString& id, const QString& what, OutcomeCallback done,
                       const std::function<void(quint16, OutcomeCallback)>& send);
    void releaseAll(OutcomeCallback done);
    void timedDrive(const TimedDrive& command, OutcomeCallback done);
    // Reads the odometers now (or resets the trip); a sent target's note says what was last reported.
    void odometry(const Odometry& command, OutcomeCallback done);
    void platformOrHandoffCommand(const OperatorCommand& command, const QString& what, OutcomeCallback done);
    // Opens a drive session in the stack (its first zero demand): `done` says whether it left.
    void startSession(quint16 subsystem, OutcomeCallback done);
    // A timed drive (headless "drive"): opens the session if needed, hands the demand to the stack (`done`
    // says whether the socket took it), refreshes it at the drive rate and ends with zeros after durationS.
    void startTimedDrive(quint16 subsystem, const JausDrive& demand, double durationS, OutcomeCallback done);
    // Ends a drive session (release, focus loss, joystick loss...): zeros, several times; `done` says whether
    // the first one left, with `why` as the note of the sent targets.
    void endSession(quint16 subsystem, const QString& why, OutcomeCallback done);
    // Every vehicle this console knows: heard (now or earlier) or configured as a static endpoint.
    QList<quint16> knownSubsystems() const;

    jaus::JausConfig m_config;
    GeoFrame m_frame;
    std::unique_ptr<jaus::JausStack> m_stack;
    TelemetryCoalescer<std::uint16_t, jaus::SubsystemSnapshot> m_snapshots;
    QHash<std::uint16_t, JausVehicle> m_latest;
    QHash<std::uint16_t, QTimer*> m_driveTimers;
    QSet<quint16> m_sessions; // drive sessions opened through the gate (or a headless "drive")
    // io thread: why the snapshot's pose may not be drawn (empty when it may). Then its pose and
    // velocity are replaced by the last plausible ones, the cause counted (rx.implausible.<cause>) and a
    // warning raised once per vehicle and cause every 30 s.
    QString admitPose(jaus::SubsystemSnapshot& snapshot);
    struct PoseIo {
        std::optional<jaus::GlobalPose> globalPose;
        std::optional<jaus::LocalPose> localPose;
        std::optional<jaus::VelocityState> velocity;
        double checked[4] = {0, 0, 0, 0}; // e, n, u, speed of the pose last checked (bitwise: NaN included)
        bool hasChecked = false;
        QString implausible; // the verdict on it
    };
    std::map<std::uint16_t, PoseIo> m_poseIo;
    PoseGate m_poseGate;
    // io thread only
    std::map<std::uint16_t, bool> m_linkUp;
    ocu::LinkState m_publishedLink = ocu::LinkState::Unknown;
};

} // namespace ocu
