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
// publishEvent from its stack listener. Commands report what went on the wire
// (docs/decisions/command-outcome-per-target.md): `done` runs exactly once with one TargetOutcome per target
// (a machine or a link), sent or refused with the reason - on the GUI thread when the bridge refuses by
// itself (role, unknown machine, link down: nothing is posted, the stack neither sends it nor keeps it for
// later), on the stack's io thread when the stack decides. Only the CommandGate calls them; it hands the
// outcomes over to the GUI thread.
#include "models/FleetEvent.h"
#include "models/MachineState.h"
#include "models/ModelClock.h"
#include "models/SiteMapData.h"
#include "models/TelemetryCoalescer.h"
#include "models/commands/OperatorCommand.h"

#include "protocols/common/CommandOutcome.h"
#include "protocols/common/Counters.h"

#include <QHash>
#include <QJsonArray>
#include <QJsonObject>
#include <QMap>
#include <QObject>
#include <QStringList>
#include <QVector>
#include <chrono>
#include <optional>
#include <vector>

namespace ocu {

class PassCountLayer;

// [{"id":…,"sent":…,"cause":… and "reason":… (only when not sent),"note":… (only when there is one)}, …]: the
// same in headless results and audit lines.
QJsonArray targetsToJson(const QVector<TargetOutcome>& targets);

// A target's name, reason and note as the GUI shows them.
inline QString targetId(const TargetOutcome& t) {
    return QString::fromStdString(t.target);
}
inline QString reasonText(const TargetOutcome& t) {
    return QString::fromStdString(t.reason);
}
inline QString noteText(const TargetOutcome& t) {
    return QString::fromStdString(t.note);
}

// The final result of one operator command: ok only when there was at least one target and every target
// was sent; `message` summarises for people (and carries the refusal when there is no target at all).
struct CommandResult {
    bool ok = false;
    QString message;
    QVector<TargetOutcome> targets;
    QString action; // "stop_all", "stop", "clear_stop" or the command name (set by the CommandGate)
    static CommandResult success(const QString& msg = QStringLiteral("sent")) { return {true, msg, {}, {}}; }
    static CommandResult failure(const QString& msg) { return {false, msg, {}, {}}; }
    // ok = every target sent (and at least one); message = what was sent and what was not.
    static CommandResult fromTargets(QVector<TargetOutcome> targets, const QString& whenEmpty = {});
    QStringList notSent() const; // "target: reason" for every target not sent
};

// A target not sent: the kind of refusal and the words for people.
TargetOutcome refusal(const QString& target, OutcomeReason cause, const QString& reason);

struct LinkStatus {
    QString link; // e.g. "jaus", "iso23725:ahs-1", "osyris:239.255.0.1"
    LinkState state = LinkState::Unknown;
    qint64 dataAgeMs = -1; // age of the newest data on this link; -1 = none yet
    QString detail;
};

// One link's counters: rejected peer input by reason (Counters::isReject, names without the
// leading "rx.": "rejected.too_short", "implausible.speed", "unknown_member") and every counter by name.
struct LinkCounters {
    QString link;
    QMap<QString, quint64> rejected;
    QMap<QString, quint64> all;
    quint64 rejectedTotal() const;
    static LinkCounters of(const QString& link, const Counters& counters);
};

class FleetBridge : public QObject {
    Q_OBJECT
public:
    explicit FleetBridge(Protocol protocol, QObject* parent = nullptr);
    ~FleetBridge() override;

    Protocol protocol() const { return m_protocol; }
    // True when this bridge is responsible for the machine id (default: the protocol prefix matches).
    virtual bool ownsMachine(const QString& id) const;

    // The clock the bridge's data times (MachineState::lastDataMs) are on, the fleet model's (null: the
    // system clock). Set it before the stack runs: the io thread reads it unlocked.
    void setClock(std::shared_ptr<const ModelClock> clock) { m_clock = clockOrSystem(std::move(clock)); }
    const ModelClock& clock() const { return *m_clock; }
    // A stack's wall-clock receive time on the bridge's clock (wallStampToModelMs); any thread.
    qint64 modelTimeOfWallMs(qint64 wallMs) const { return wallStampToModelMs(*m_clock, wallMs); }

    // ---- thread-safe, called from the stack's io thread ----
    void publishMachine(const MachineState& state);
    // Several machines in one hand-over (one lock for the batch), e.g. a burst of positions.
    void publishMachines(std::vector<MachineState>&& states);
    void publishRemoval(const QString& id);
    void publishLink(const LinkStatus& status);
    void publishEvent(const FleetEvent& event);
    // GUI thread: a record of the protocol's own for the flight recorder, beside the machine states (a UGV's
    // mission): `kind` names it, `data` is the protocol's encoding, handed back as it is in a replay.
    void publishDetail(const QString& machineId, const QString& kind, const QByteArray& data) {
        emit detailRecorded(machineId, kind, data);
    }

    // ---- GUI thread: commands (asynchronous; `done` as described above) ----
    // STOP ALL for this protocol: JAUS SetEmergency to every discovered UGV, ISO 23725 all-stop Apply on
    // every AHS link, the OSYRIS stop text to the group. Never asks for confirmation.
    virtual void stopAll(OutcomeCallback done) = 0;
    // True when stopAll puts its stop on the wire from the calling thread (no io-thread hop) and may be
    // called from any thread (it reads only constant or atomic state): the gate calls these bridges first, so
    // a woken io thread of another stack never delays them, and CommandGate::stopAllEarly calls them from
    // the headless stdin reader.
    virtual bool stopsFromCallersThread() const { return false; }
    // True when stopAll may be called from any thread (reads only constant, atomic or locked state) even
    // though its stack sends on its io thread (ISO 23725): CommandGate::stopAllEarly calls these too, after
    // those that send from the caller's thread.
    virtual bool stopAllFromAnyThread() const { return stopsFromCallersThread(); }
    virtual void stopMachine(const QString& id, OutcomeCallback done) = 0;
    // Release a stop (JAUS ClearEmergency, ISO all-stop Remove). The CommandGate has already checked the
    // operator's deliberate confirmation before calling this.
    virtual void clearStop(const QString& id, OutcomeCallback done) = 0;
    // The other operator commands (models/commands/OperatorCommand.h): each bridge acts on those of its
    // protocol (RequestControl, TimedDrive... for JAUS) and refuses the rest. The default refuses every
    // command as not supported (one target: the command's machine, else the protocol).
    virtual void command(const OperatorCommand& command, OutcomeCallback done);

    // Stop confirmation (GUI thread): false when the protocol carries no stop state at all (OSYRIS), so a
    // stop can never be confirmed by the machines; true when the target reports being stopped now.
    virtual bool reportsStopState() const { return true; }
    virtual bool reportsStopped(const QString& /*target*/) const { return false; }
    // Confirmation of other commands (clear_stop, request_control, release_control...): true
    // when this bridge watches `action`'s effect in the machines' own reports (commandReported), and whether
    // `target` shows that effect now.
    virtual bool confirmsCommand(const QString& /*action*/) const { return false; }
    virtual bool reportsConfirmed(const QString& /*action*/, const QString& /*target*/) const {
        return false;
    }

    // Optional data layers.
    virtual const PassCountLayer* passCountLayer() const { return nullptr; }
    virtual SiteMapData siteMap() const { return {}; }

    // Per link, what its stack counted so far (link details, headless {"cmd":"counters"}). Any thread.
    virtual QVector<LinkCounters> linkCounters() const { return {}; }
    // A standing condition of the stack since it started that the operator should see in the status bar
    // beside the link indicator, in the operator's language (e.g. "JAUS: no group socket (3794 held by
    // another process)"); empty when there is none. GUI thread.
    virtual QString statusNote() const { return {}; }

    // ---- io-thread watchdog, GUI thread ----
    // How long the stack's io thread has not turned; 0 while it turns, when it is not running, or when the
    // bridge has no io thread of its own (the default). Any thread.
    virtual std::chrono::milliseconds ioStalledFor() const { return std::chrono::milliseconds(0); }
    // A stall longer than the limit (default 1 s) raises an alarm and shows every link of this bridge
    // degraded until the thread turns again (then an info event and the links as the stack reported them).
    // The bridge's own timer checks every 250 ms; checkWatchdog() checks now.
    void setWatchdogLimit(std::chrono::milliseconds limit) { m_watchdogLimit = limit; }
    void checkWatchdog();
    bool ioStalled() const { return m_ioStalled; }

    // GUI thread: the latest link states, and a way to deliver pending coalesced data synchronously.
    QVector<LinkStatus> links() const;
    std::optional<LinkStatus> linkStatus(const QString& link) const;
    void flushPending();
    // GUI thread, after the stack stopped: every link this bridge has published shows down with `detail`
    // ("stack stopped"), delivered at once - the status bar reflects the stack's own state, not its last
    // report.
    void publishStackStopped(const QString& detail);
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
    // publishDetail(): the flight recorder keeps it.
    void detailRecorded(const QString& machineId, const QString& kind, const QByteArray& data);
    // A stop target (as named in TargetOutcome) reports being stopped: the machine's own report (JAUS
    // emergency state, ISO 23725 MachineAllStop on). `text` says so for people ("UGV-126 reports EMERGENCY").
    void stopReported(const QString& target, const QString& text);
    // A target's own report answers a command (confirmsCommand): "UGV-126 reports READY (emergency
    // cleared)", "UGV-126 confirms control by this console", "AHS ahs reports all-stop inactive".
    void commandReported(const QString& action, const QString& target, const QString& text);

private:
    void deliverMachines(std::vector<std::pair<QString, std::optional<MachineState>>>&& batch);
    void deliverLinks(std::vector<std::pair<QString, LinkStatus>>&& batch);

    LinkStatus shownLink(const LinkStatus& reported) const;

    Protocol m_protocol;
    std::shared_ptr<const ModelClock> m_clock = systemModelClock();
    std::chrono::milliseconds m_watchdogLimit{1000};
    bool m_ioStalled = false;
    QHash<QString, LinkStatus> m_reportedLinks; // as the stack reported them (m_linkState: as shown)
    TelemetryCoalescer<QString, std::optional<MachineState>> m_machines; // nullopt = removal
    TelemetryCoalescer<QString, LinkStatus> m_links;
    QHash<QString, LinkStatus> m_linkState;
};

} // namespace ocu

Q_DECLARE_METATYPE(ocu::LinkStatus)
