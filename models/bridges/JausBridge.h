#pragma once
// The Qt face of the JAUS stack: subsystem snapshots become MachineState rows (coalesced), JAUS events
// become fleet events, and console commands are posted to the stack. Also keeps the Qt-typed view of every
// subsystem (models/jaus/JausVehicle.h) for the access-control, teleop and details panels, which see it only
// through JausVehicleBridge.
#include "models/jaus/JausVehicleBridge.h"

#include "protocols/common/GeoFrame.h"
#include "protocols/jaus/JausConfig.h"
#include "protocols/jaus/JausTypes.h"

#include <QHash>
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
    void stop();
    const jaus::JausConfig& config() const { return m_config; }
    JausConsoleIdentity identity() const override;

    // GUI thread: the latest view of every subsystem.
    QList<quint16> subsystems() const override;
    std::optional<JausVehicle> subsystem(quint16 id) const override;

    void stopAll(OutcomeCallback done) override;
    bool stopsFromCallersThread() const override { return true; } // the stack's fast path (issue 13 §10)
    void stopMachine(const QString& id, OutcomeCallback done) override;
    void clearStop(const QString& id, OutcomeCallback done) override;
    // request_control, release_control, release_all, drive, drive_stop, resume, standby, shutdown, reset.
    void command(const QString& name, const QJsonObject& args, OutcomeCallback done) override;
    bool reportsStopped(const QString& target) const override;

    CommandResult drive(quint16 subsystem, const JausDrive& command) override;
    CommandResult stopDriving(quint16 subsystem) override;

private:
    void onSubsystemChanged(const jaus::SubsystemSnapshot& snapshot) override;
    void onEvent(const jaus::JausEvent& event) override;
    MachineState toMachine(const jaus::SubsystemSnapshot& s) const;
    CommandResult refuseIfMonitor(const QString& what) const;
    // GUI thread: a refusal when the subsystem was never heard or its link is down (nothing is posted then).
    CommandResult refuseIfUnreachable(quint16 subsystem, const QString& what) const;
    // True (and `done` called with the refusal) when the stack is not running: it would never answer.
    bool refuseIfNotRunning(const QString& target, OutcomeCallback& done) const;

    jaus::JausConfig m_config;
    GeoFrame m_frame;
    std::unique_ptr<jaus::JausStack> m_stack;
    TelemetryCoalescer<std::uint16_t, jaus::SubsystemSnapshot> m_snapshots;
    QHash<std::uint16_t, JausVehicle> m_latest;
    QHash<std::uint16_t, QTimer*> m_driveTimers;
    // io thread only
    std::map<std::uint16_t, bool> m_linkUp;
    ocu::LinkState m_publishedLink = ocu::LinkState::Unknown;
};

} // namespace ocu
