#pragma once
// The one gate every operator command passes, so each is checked and audited once: STOP ALL, per-machine
// stop, stop release and the protocol commands of every panel and of the headless monitor.
//
// Commands are asynchronous: the gate hands the command to the bridges, collects their per-target outcomes
// (TargetOutcome, reported by the stacks on their io threads and handed over to the GUI thread here) and,
// once every bridge answered or the answer deadline passed (a bridge that did not answer: its part "not
// sent", reason "stack did not answer"), emits the final CommandResult: ok only when there was a target and
// every target was sent. The result is audited with the same truth: an AlarmModel entry (kind Audit) and,
// when configured, one JSON line appended to the audit log file.
//
// Releasing needs a confirmation token obtained from requestClearToken() (the GUI's hold-to-confirm button,
// or the headless "confirm": true), valid once, for one machine, for a short time. Stopping never asks.
//
// Confirmation comes from the machines' own reports: after a stop, each sent target is watched until its
// bridge reports it stopped (FleetBridge::stopReported); the latency is logged as an event, and no report
// within the confirmation time raises an alarm. Protocols without a stop state (OSYRIS) are said to be so.
//
// Who may issue what: the operator at the console (OperatorIdentity) and the one permission table
// (CommandPermissions). A command the operator's role may not issue, or any command but a stop while the
// console is locked, is refused before any bridge sees it (audited as not sent, reason NotPermitted, the
// text naming the role needed). STOP ALL and per-machine stops always pass. Every audit line carries the
// operator, role and console.
#include "models/FleetBridge.h"
#include "models/ModelClock.h"
#include "models/commands/CommandPermissions.h"

#include <QElapsedTimer>
#include <QHash>
#include <QJsonObject>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QVector>

#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace ocu {

class AlarmModel;
struct GateLife;
struct EarlyStop;

class CommandGate : public QObject {
    Q_OBJECT
public:
    using ResultHandler = std::function<void(const CommandResult&)>;

    explicit CommandGate(AlarmModel* alarms = nullptr, QObject* parent = nullptr);
    ~CommandGate() override;

    void addBridge(FleetBridge* bridge);
    QVector<FleetBridge*> bridges() const;
    FleetBridge* bridgeFor(const QString& machineId) const;

    // Append-only audit log (JSON lines); empty = none.
    void setAuditLogPath(const QString& path) { m_auditPath = path; }
    QString auditLogPath() const { return m_auditPath; }
    void setTokenLifetimeMs(qint64 ms) { m_tokenLifetimeMs = ms; }
    // The clock clear tokens expire on (null: the system clock, which a wall-clock step does not move, so a
    // step neither expires a token early nor keeps one alive). Tests give a manual one.
    void setClock(std::shared_ptr<const ModelClock> clock) { m_clock = clockOrSystem(std::move(clock)); }
    // How long the gate waits for the stacks' outcomes before it calls the missing ones not sent.
    void setAnswerDeadlineMs(int ms) { m_answerDeadlineMs = ms; }
    // How long a sent stop may wait for the machine's report before the gate raises an alarm.
    void setConfirmTimeoutMs(int ms) { m_confirmTimeoutMs = ms; }
    int confirmTimeoutMs() const { return m_confirmTimeoutMs; }

    // `origin` is "gui", "headless", "shortcut", "teleop"...; `onFinal` (optional) runs with the final result
    // on the GUI thread, before commandFinished is emitted. It may run before the call returns (every bridge
    // decided at once).
    void stopAll(const QString& origin = QStringLiteral("gui"), ResultHandler onFinal = {});
    // The stop path without waiting for the GUI thread (docs/decisions/stop-from-callers-thread.md). Any
    // thread (the headless stdin reader): STOP ALL now to the bridges that may be called from any thread
    // (FleetBridge::stopAllFromAnyThread; those that send from the caller's thread first); their outcomes
    // wait in the handle. Then, on the gate's thread, stopAll(origin, onFinal, handle) sends the rest and
    // records every part (audit, result, confirmation) as one STOP ALL. Every handle must be passed to
    // stopAll once: it is the audit of what was already sent. Only while the bridges live (the caller stops
    // calling before they are torn down).
    std::shared_ptr<EarlyStop> stopAllEarly();
    void stopAll(const QString& origin, ResultHandler onFinal, std::shared_ptr<EarlyStop> early);
    void stopMachine(const QString& id, const QString& origin = QStringLiteral("gui"),
                     ResultHandler onFinal = {});

    // Release: first obtain a token (after the operator's deliberate confirmation), then clear.
    QString requestClearToken(const QString& id);
    void clearStop(const QString& id, const QString& token, const QString& origin = QStringLiteral("gui"),
                   ResultHandler onFinal = {});

    // Any operator command (models/commands/OperatorCommand.h): STOP ALL, stop and release as above (a
    // ClearStop carries its token), every other command to the bridge owning its machine, or, for a command
    // without one (JAUS release_all, an OSYRIS text to every station), to the bridge of its protocol.
    void command(const OperatorCommand& command, const QString& origin = QStringLiteral("gui"),
                 ResultHandler onFinal = {});
    // A command that could not be read (the headless edge: a malformed argument of a command naming a
    // machine): audited as not sent to `target` with the reason, like a bridge's own refusal.
    void refuse(const QString& action, const QString& target, OutcomeReason cause, const QString& reason,
                const QString& origin, ResultHandler onFinal = {});

    // Who is at the console (default: an unnamed admin, the console without roles) and whether it is locked
    // (only stops pass). The table the modules add their rows to.
    void setOperator(const OperatorIdentity& identity);
    const OperatorIdentity& operatorIdentity() const { return m_operator; }
    void setLocked(bool locked);
    bool isLocked() const { return m_locked; }
    // Who signed in or out, and when the console was locked or unlocked: an audit record like a command's
    // (action "sign_in", "sign_out", "lock", "unlock"), with no machine target. A refusal (wrong password) is
    // information in the event log, not an alarm: it asks no action of the operator.
    void auditSession(const QString& action, const OperatorIdentity& who, bool ok, const QString& message);
    // An action of this console with no machine target (auto dispatch switched, a report written), audited as
    // the current operator's; a refusal is an alarm like a command's.
    void auditLocal(const QString& origin, const QString& action, const QJsonObject& command, bool ok,
                    const QString& message);
    CommandPermissions& permissions() { return m_permissions; }
    const CommandPermissions& permissions() const { return m_permissions; }
    // Whether the operator may issue `command` (commandName) now; `why` gets the refusal text.
    bool mayIssue(const QString& command, QString* why = nullptr) const;

    // Commands whose final result is not in yet.
    int pendingCommands() const { return int(m_pending.size()); }
    // Stops sent and not yet confirmed by the machines (target ids).
    QStringList awaitingConfirmation() const;
    // Other commands sent and not yet confirmed: "action target" per entry.
    QStringList awaitingCommandConfirmation() const;

signals:
    // Every final result (any command, any origin).
    void commandFinished(const ocu::CommandResult& result, const QString& origin);
    // The final result of a STOP ALL or of a per-machine stop.
    void stopFinished(const ocu::CommandResult& result, const QString& origin);
    // A stop target's report arrived (latency in ms from the command) or did not arrive in time.
    void stopConfirmed(const QString& target, const QString& text, qint64 latencyMs);
    void stopUnconfirmed(const QString& target, const QString& text);
    // The same for other commands a bridge confirms (FleetBridge::confirmsCommand): clear_stop,
    // request_control, release_control.
    void commandConfirmed(const QString& action, const QString& target, const QString& text,
                          qint64 latencyMs);
    void commandUnconfirmed(const QString& action, const QString& target, const QString& text);
    void audited(const QString& jsonLine);
    // What the operator may issue changed (another operator or role, locked or unlocked): panels enable and
    // disable their controls again.
    void permissionsChanged();

private:
    struct Pending;
    // Issues `fn(bridge, done)` to each bridge and finalises when all answered or at the deadline.
    void dispatch(const OperatorCommand& command, const QString& origin, const QVector<FleetBridge*>& to,
                  const std::function<void(FleetBridge*, OutcomeCallback)>& fn, ResultHandler onFinal);
    void finish(quint64 id);
    void finishNow(const OperatorCommand& command, const QString& origin, CommandResult r,
                   const ResultHandler& onFinal);
    // `issuer`: who issued the command (its audit names them, also when a switch of operator came between);
    // null: the operator now.
    void finishNow(const QString& action, const QString& target, const QJsonObject& command,
                   const QString& origin, CommandResult r, const ResultHandler& onFinal,
                   const OperatorIdentity* issuer = nullptr);
    FleetBridge* bridgeOf(Protocol protocol) const;
    // Refuses (audited, nothing sent) and returns false when the operator may not issue `command` now.
    bool admit(const OperatorCommand& command, const QString& origin, const ResultHandler& onFinal);
    // `bridge` answered for these targets (null when it is gone): it says whether it can confirm a stop.
    void watchStops(FleetBridge* bridge, const std::vector<TargetOutcome>& outcomes,
                    const QElapsedTimer& since);
    void onStopReported(const QString& target, const QString& text);
    // Other confirmed commands: watched per (action, target) until the bridge reports the effect.
    void watchCommand(const QString& action, FleetBridge* bridge, const std::vector<TargetOutcome>& outcomes,
                      const QElapsedTimer& since);
    void onCommandReported(const QString& action, const QString& target, const QString& text);
    void audit(const QString& origin, const QString& action, const QString& target,
               const QJsonObject& command, const CommandResult& result, const OperatorIdentity& issuer,
               EventSeverity failed = EventSeverity::Alarm);

    QVector<QPointer<FleetBridge>> m_bridges;
    std::mutex m_earlyMutex;                  // stopAllEarly() from another thread
    std::vector<FleetBridge*> m_earlyBridges; // bridges that stop from the caller's thread
    QPointer<AlarmModel> m_alarms;
    CommandPermissions m_permissions;
    OperatorIdentity m_operator{QString(), OperatorRole::Admin, QString()};
    bool m_locked = false;
    QString m_auditPath;
    qint64 m_tokenLifetimeMs = 10000;
    std::shared_ptr<const ModelClock> m_clock = systemModelClock();
    int m_answerDeadlineMs = 1000;
    int m_confirmTimeoutMs = 3000;
    struct Token {
        QString id;
        qint64 expiresMs = 0;
    };
    QHash<QString, Token> m_tokens;
    quint64 m_nextId = 1;
    QHash<quint64, std::shared_ptr<Pending>> m_pending;
    struct Watch {
        QElapsedTimer since;
        QTimer* timer = nullptr;
    };
    QHash<QString, Watch> m_watches;        // stop target -> waiting for its report
    QHash<QString, Watch> m_commandWatches; // action + '\n' + target -> waiting for its report
    std::shared_ptr<GateLife> m_life;
};

} // namespace ocu

Q_DECLARE_METATYPE(ocu::CommandResult)
