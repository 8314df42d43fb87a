#pragma once
// Base class of a protocol bridge: the Qt-side face of one protocol stack (JAUS, ISO 23725, OSYRIS).
//
// Threading: the bridge object lives on the GUI thread. The stack's listener callbacks run on the
// stack's io thread and call the thread-safe publish*() methods below; machine and link updates are
// coalesced (latest value per machine / link wins, one queued drain per burst), events are queued one
// by one. All signals are emitted on the GUI thread. Commands (stopAll, stopMachine, clearStop, command)
// are called on the GUI thread and must only post to the stack (IoThread::post) - never block.
//
// A concrete bridge implements the four command methods, maps its stack's vocabulary into MachineState
// (id = protocolPrefix(protocol) + native id) and calls publishMachine/publishRemoval/publishLink/
// publishEvent from its stack listener. Role and authority checks happen in the concrete bridge; a refused
// command returns CommandResult::failure("reason"). A command for a target whose link the bridge last saw
// down (or never saw up) is refused the same way, and nothing is posted: the stack neither sends it nor keeps
// it for later.
#include "models/FleetEvent.h"
#include "models/MachineState.h"
#include "models/SiteMapData.h"
#include "models/TelemetryCoalescer.h"

#include <QHash>
#include <QJsonObject>
#include <QObject>
#include <QStringList>
#include <QVector>
#include <optional>
#include <vector>

namespace ocu {

class PassCountLayer;

struct CommandResult {
    bool ok = false;
    QString message;
    static CommandResult success(const QString& msg = QStringLiteral("sent")) { return {true, msg}; }
    static CommandResult failure(const QString& msg) { return {false, msg}; }
};

struct LinkStatus {
    QString link; // e.g. "jaus", "iso23725:ahs-1", "osyris:239.255.0.1"
    LinkState state = LinkState::Unknown;
    qint64 dataAgeMs = -1; // age of the newest data on this link; -1 = none yet
    QString detail;
};

class FleetBridge : public QObject {
    Q_OBJECT
public:
    explicit FleetBridge(Protocol protocol, QObject* parent = nullptr);
    ~FleetBridge() override;

    Protocol protocol() const { return m_protocol; }
    // True when this bridge is responsible for the machine id (default: the protocol prefix matches).
    virtual bool ownsMachine(const QString& id) const;

    // ---- thread-safe, called from the stack's io thread ----
    void publishMachine(const MachineState& state);
    // Several machines in one hand-over (one lock for the batch), e.g. a burst of positions.
    void publishMachines(std::vector<MachineState>&& states);
    void publishRemoval(const QString& id);
    void publishLink(const LinkStatus& status);
    void publishEvent(const FleetEvent& event);

    // ---- GUI thread: commands (asynchronous; the outcome shows in what the machines report) ----
    // STOP ALL for this protocol: JAUS SetEmergency to every UGV this console controls, ISO 23725 all-stop
    // Apply to every AHS link, OSYRIS stop where supported. Never asks for confirmation.
    virtual CommandResult stopAll() = 0;
    virtual CommandResult stopMachine(const QString& id) = 0;
    // Release a stop (JAUS ClearEmergency, ISO all-stop Remove). The CommandGate has already checked the
    // operator's deliberate confirmation before calling this.
    virtual CommandResult clearStop(const QString& id) = 0;
    // Protocol-specific commands: "request_control", "release_control", "drive" (JAUS) ... with arguments
    // such as {"id": "jaus:101", "linear": 0.5, "angular": 0.1, "duration": 2.0, "mode": "velocity"}.
    // Default: unsupported.
    virtual CommandResult command(const QString& name, const QJsonObject& args);

    // Optional data layers.
    virtual const PassCountLayer* passCountLayer() const { return nullptr; }
    virtual SiteMapData siteMap() const { return {}; }

    // GUI thread: the latest link states, and a way to deliver pending coalesced data synchronously.
    QVector<LinkStatus> links() const;
    std::optional<LinkStatus> linkStatus(const QString& link) const;
    void flushPending();
    // Backlog and counters of the machine coalescer (benchmarks, diagnostics; any thread).
    size_t pendingMachineUpdates() const { return m_machines.pending(); }
    size_t pendingLinkUpdates() const { return m_links.pending(); }
    TelemetryCoalescer<QString, std::optional<MachineState>>::Stats machineStats() const {
        return m_machines.stats();
    }

signals:
    void machinesUpdated(const QVector<ocu::MachineState>& machines);
    void machinesRemoved(const QStringList& ids);
    void linkChanged(const ocu::LinkStatus& status);
    void eventRaised(const ocu::FleetEvent& event);
    // Emitted by concrete bridges (GUI thread) when their map or pass-count data change.
    void siteMapChanged();
    void passCountChanged();

private:
    void deliverMachines(std::vector<std::pair<QString, std::optional<MachineState>>>&& batch);
    void deliverLinks(std::vector<std::pair<QString, LinkStatus>>&& batch);

    Protocol m_protocol;
    TelemetryCoalescer<QString, std::optional<MachineState>> m_machines; // nullopt = removal
    TelemetryCoalescer<QString, LinkStatus> m_links;
    QHash<QString, LinkStatus> m_linkState;
};

} // namespace ocu

Q_DECLARE_METATYPE(ocu::LinkStatus)
