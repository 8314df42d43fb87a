#pragma once
// The headless monitor's command table: what a JSON command line does, by name. One table per monitor (no
// process-wide state); each entry maps a name to its handler, of one of two kinds:
//   local — answered here at once, without a bridge: a read-only query ("list", "counters", a module's
//           status query) or an action of this process (a module's report writer or switch),
//           which the gate's permission table and lock check and which is audited. The handler returns the
//           result's fields ("ok", "message", and its own).
//   gate  — read into its typed OperatorCommand here, once (models/commands/OperatorCommand.h), and forwarded
//           through the CommandGate to the bridge of the machine it names (or of its protocol): audited,
//           answered when every target reported (or at the gate's deadline). An optional prepare step
//           builds the typed command itself (e.g. completes missing identifiers first) and names the
//           fields the result echoes; without it the JSON is read by parseOperatorCommand.
// Besides the entries: stop_all, stop and clear_stop (the stop path, CommandGate), and every other operator
// command parseOperatorCommand knows go to the gate the same way.
// A protocol module registers its entries in ProtocolModule::registerHeadless(); the monitor its own
// ("list", "counters"). Every result line comes from reply():
//   {"type":"result","cmd":<name>,"req":<echoed>,"id":<echoed>, ...fields}
// a gate command's fields being "ok", "targets" (what went on the wire, per target) and "message".
#include "models/CommandGate.h"
#include "models/commands/OperatorCommand.h"

#include <QByteArray>
#include <QHash>
#include <QJsonObject>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>
#include <memory>

namespace ocu {

class HeadlessCommands : public QObject {
public:
    // Writes one finished result line (compact JSON, no newline).
    using LineSink = std::function<void(const QByteArray& line)>;
    HeadlessCommands(CommandGate* gate, LineSink sink, QObject* parent = nullptr);

    // A local entry: returns the result's fields for the command.
    using Answer = std::function<QJsonObject(const QJsonObject& cmd)>;
    // What a gate entry's prepare step makes of the command: the typed command for the gate and the fields
    // the result echoes, or a refusal (nothing is sent, the result says why). A refusal naming a machine
    // (`refusalTarget`) is audited against it by the gate, like a bridge's own refusal.
    struct GateRequest {
        std::optional<OperatorCommand> command;
        QJsonObject echo;
        QString refusal;
        QString refusalTarget;
    };
    using Prepare = std::function<GateRequest(const QJsonObject& cmd)>;
    // The JSON command read by parseOperatorCommand under `name`: the default prepare step.
    static GateRequest read(const QString& name, const QJsonObject& cmd);

    // Whether a local command line acts (switches something, writes a file) rather than asks: an acting line
    // passes the permission table and the lock like a gate command (refused with the reason, nothing done)
    // and is audited as the operator's.
    using Acts = std::function<bool(const QJsonObject& cmd)>;
    static bool always(const QJsonObject&) { return true; }

    // A later entry of the same name replaces the earlier one. Without `acts` the entry only asks.
    void addLocal(const QString& name, Answer answer, Acts acts = {});
    void addGateCommand(const QString& name, Prepare prepare = {});
    void remove(const QString& name);

    // What a module adds to a machine's line ("machine" lines and the "list" answer), e.g. a vehicle's
    // mission under "mission"; called for every machine, it adds nothing to the machines it does not know.
    using MachineFields = std::function<void(const QString& machineId, QJsonObject& line)>;
    void addMachineFields(MachineFields fields) { m_machineFields.push_back(std::move(fields)); }
    void machineFields(const QString& machineId, QJsonObject& line) const {
        for (const MachineFields& f : m_machineFields)
            f(machineId, line);
    }
    // A module's fields of a machine changed without its machine state (a vehicle's mission): the monitor
    // prints the machine's line again, at once when `atOnce` (a change of state), else within its rate limit.
    using MachineRefresh = std::function<void(const QString& machineId, bool atOnce)>;
    void setMachineRefresh(MachineRefresh refresh) { m_refresh = std::move(refresh); }
    void machineFieldsChanged(const QString& machineId, bool atOnce) const {
        if (m_refresh)
            m_refresh(machineId, atOnce);
    }
    bool contains(const QString& name) const;

    // Executes one command (a parsed line). The result line is written when final; it is also returned when
    // it was final at once (otherwise an empty array). `early`: the STOP ALL the stdin reader already sent.
    QByteArray execute(const QJsonObject& cmd, std::shared_ptr<EarlyStop> early = {});
    // The result line for cmd with these fields: written and returned.
    QByteArray reply(const QJsonObject& cmd, QJsonObject fields);
    QByteArray refuse(const QJsonObject& cmd, const QString& message);

    // Gate commands whose result line is not written yet; settled() runs when the last one is.
    int pendingResults() const { return m_pendingResults; }
    void setSettledHandler(std::function<void()> settled) { m_settled = std::move(settled); }

    // The command's name: its "cmd" key, or "command".
    static QString nameOf(const QJsonObject& cmd);
    // The origin of every command of this table in the audit ("headless").
    static QString origin() { return QStringLiteral("headless"); }

private:
    struct Entry {
        Answer answer;   // local
        Prepare prepare; // gate (may be empty)
        bool gate = false;
        Acts acts; // local: empty = a query
    };
    QByteArray stopCommand(const QString& name, const QJsonObject& cmd, std::shared_ptr<EarlyStop> early);
    QByteArray gateEntry(const QString& name, const Entry& entry, const QJsonObject& cmd);
    QByteArray localEntry(const QString& name, const Entry& entry, const QJsonObject& cmd);
    // The one place a command leaves for a bridge through the gate; the result answers cmd.
    QByteArray forwardToGate(const QJsonObject& cmd, const QString& name, const GateRequest& request);
    QByteArray viaGate(const QJsonObject& cmd, const QJsonObject& echo,
                       const std::function<void(CommandGate::ResultHandler)>& issue,
                       const QString& suffix = {});

    QPointer<CommandGate> m_gate;
    LineSink m_sink;
    QHash<QString, Entry> m_entries;
    int m_pendingResults = 0;
    std::function<void()> m_settled;
    QList<MachineFields> m_machineFields;
    MachineRefresh m_refresh;
};

// The "counters" answer: every bridge's stack counters per link, its rejects per reason.
QJsonObject linkCountersFields(const QList<QPointer<FleetBridge>>& bridges);

} // namespace ocu
