#pragma once
// The Qt face of the JAUS stack: subsystem snapshots become MachineState rows (coalesced), JAUS events
// become fleet events, and console commands are posted to the stack. Also keeps the full JAUS
// snapshot of every subsystem for the access-control, teleop and details panels.
#include "models/FleetBridge.h"

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

Q_DECLARE_METATYPE(ocu::jaus::SubsystemSnapshot)
Q_DECLARE_METATYPE(ocu::jaus::JausEvent)

namespace ocu {

class JausBridge : public FleetBridge, private jaus::JausListener {
    Q_OBJECT
public:
    JausBridge(const jaus::JausConfig& config, const GeoFrame& frame, QObject* parent = nullptr);
    ~JausBridge() override;

    // Starts the stack; returns an empty string or why it could not (e.g. the UDP port is taken).
    QString start();
    void stop();
    jaus::JausStack* stack() const { return m_stack.get(); }
    const jaus::JausConfig& config() const { return m_config; }
    bool mayCommand() const { return m_config.mayControl(); }

    static QString machineId(std::uint16_t subsystem);
    static std::optional<std::uint16_t> subsystemOf(const QString& machineId);

    // GUI thread: the latest full snapshots.
    QList<std::uint16_t> subsystems() const;
    std::optional<jaus::SubsystemSnapshot> subsystem(std::uint16_t id) const;

    CommandResult stopAll() override;
    CommandResult stopMachine(const QString& id) override;
    CommandResult clearStop(const QString& id) override;
    // request_control, release_control, release_all, drive, drive_stop, resume, standby, shutdown, reset.
    CommandResult command(const QString& name, const QJsonObject& args) override;

    // Drive stream for teleop (GUI thread): opens the session on first use.
    CommandResult drive(std::uint16_t subsystem, const jaus::DriveCommand& command);
    CommandResult stopDriving(std::uint16_t subsystem);

signals:
    void subsystemUpdated(const ocu::jaus::SubsystemSnapshot& snapshot);
    void jausEvent(const ocu::jaus::JausEvent& event);

private:
    void onSubsystemChanged(const jaus::SubsystemSnapshot& snapshot) override;
    void onEvent(const jaus::JausEvent& event) override;
    MachineState toMachine(const jaus::SubsystemSnapshot& s) const;
    CommandResult refuseIfMonitor(const QString& what) const;

    jaus::JausConfig m_config;
    GeoFrame m_frame;
    std::unique_ptr<jaus::JausStack> m_stack;
    TelemetryCoalescer<std::uint16_t, jaus::SubsystemSnapshot> m_snapshots;
    QHash<std::uint16_t, jaus::SubsystemSnapshot> m_latest;
    QHash<std::uint16_t, QTimer*> m_driveTimers;
    // io thread only
    std::map<std::uint16_t, bool> m_linkUp;
    ocu::LinkState m_publishedLink = ocu::LinkState::Unknown;
};

} // namespace ocu
