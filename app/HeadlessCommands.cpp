#include "app/HeadlessCommands.h"

#include "models/FleetBridge.h"

#include <QJsonArray>
#include <QJsonDocument>

namespace ocu {

HeadlessCommands::HeadlessCommands(CommandGate* gate, LineSink sink, QObject* parent)
    : QObject(parent), m_gate(gate), m_sink(std::move(sink)) {}

void HeadlessCommands::addLocal(const QString& name, Answer answer, Acts acts) {
    m_entries.insert(name, Entry{std::move(answer), {}, false, std::move(acts)});
}

void HeadlessCommands::addGateCommand(const QString& name, Prepare prepare) {
    m_entries.insert(name, Entry{{}, std::move(prepare), true, {}});
}

void HeadlessCommands::remove(const QString& name) {
    m_entries.remove(name);
}

bool HeadlessCommands::contains(const QString& name) const {
    return m_entries.contains(name);
}

QString HeadlessCommands::nameOf(const QJsonObject& cmd) {
    QString name = cmd.value(QStringLiteral("cmd")).toString();
    if (name.isEmpty())
        name = cmd.value(QStringLiteral("command")).toString();
    return name;
}

QByteArray HeadlessCommands::reply(const QJsonObject& cmd, QJsonObject fields) {
    fields[QStringLiteral("type")] = QStringLiteral("result");
    fields[QStringLiteral("cmd")] = nameOf(cmd);
    for (const QString& echoed : {QStringLiteral("req"), QStringLiteral("id")})
        if (cmd.contains(echoed))
            fields[echoed] = cmd.value(echoed);
    const QByteArray line = QJsonDocument(fields).toJson(QJsonDocument::Compact);
    if (m_sink)
        m_sink(line);
    return line;
}

QByteArray HeadlessCommands::refuse(const QJsonObject& cmd, const QString& message) {
    return reply(cmd, {{QStringLiteral("ok"), false}, {QStringLiteral("message"), message}});
}

QByteArray HeadlessCommands::execute(const QJsonObject& cmd, std::shared_ptr<EarlyStop> early) {
    const QString name = nameOf(cmd);
    if (name != QLatin1String("stop_all"))
        early.reset(); // cannot happen (the reader asked the same question): never attach it elsewhere
    const auto entry = m_entries.constFind(name);
    if (entry != m_entries.constEnd() && !entry->gate)
        return localEntry(name, *entry, cmd);
    if (!m_gate)
        return refuse(cmd, QStringLiteral("no stop controller"));
    if (name == QLatin1String("stop_all") || name == QLatin1String("stop") ||
        name == QLatin1String("clear_stop"))
        return stopCommand(name, cmd, std::move(early));
    if (entry != m_entries.constEnd())
        return gateEntry(name, *entry, cmd);
    if (isOperatorCommand(name)) // e.g. release_all, ping, send_text
        return forwardToGate(cmd, name, read(name, cmd));
    return refuse(cmd, name.isEmpty() ? QStringLiteral("missing \"cmd\"")
                                      : QStringLiteral("unknown command %1").arg(name));
}

QByteArray HeadlessCommands::stopCommand(const QString& name, const QJsonObject& cmd,
                                         std::shared_ptr<EarlyStop> early) {
    CommandGate* gate = m_gate;
    if (name == QLatin1String("stop_all"))
        return viaGate(cmd, {},
                       [&](CommandGate::ResultHandler h) { gate->stopAll(origin(), std::move(h), early); });
    const QString id = cmd.value(QStringLiteral("id")).toString();
    if (id.isEmpty())
        return refuse(cmd, QStringLiteral("missing \"id\""));
    if (name == QLatin1String("stop"))
        return viaGate(cmd, {},
                       [&](CommandGate::ResultHandler h) { gate->stopMachine(id, origin(), std::move(h)); });
    // clear_stop: the scripted equivalent of the GUI's deliberate hold is an explicit "confirm": true.
    if (cmd.value(QStringLiteral("confirm")).toBool(false) != true)
        return viaGate(
            cmd, {},
            [&](CommandGate::ResultHandler h) { gate->clearStop(id, QString(), origin(), std::move(h)); },
            QStringLiteral(" (add \"confirm\": true)")); // audited refusal
    return viaGate(cmd, {}, [&](CommandGate::ResultHandler h) {
        gate->clearStop(id, gate->requestClearToken(id), origin(), std::move(h));
    });
}

QByteArray HeadlessCommands::localEntry(const QString& name, const Entry& entry, const QJsonObject& cmd) {
    if (!entry.acts || !entry.acts(cmd))
        return reply(cmd, entry.answer(cmd));
    QString why;
    if (!m_gate)
        return refuse(cmd, QStringLiteral("no command gate"));
    if (!m_gate->mayIssue(name, &why)) {
        m_gate->auditLocal(origin(), name, cmd, false, why);
        return refuse(cmd, why);
    }
    const QJsonObject fields = entry.answer(cmd);
    m_gate->auditLocal(origin(), name, cmd, fields.value(QStringLiteral("ok")).toBool(),
                       fields.value(QStringLiteral("message")).toString());
    return reply(cmd, fields);
}

QByteArray HeadlessCommands::gateEntry(const QString& name, const Entry& entry, const QJsonObject& cmd) {
    return forwardToGate(cmd, name, entry.prepare ? entry.prepare(cmd) : read(name, cmd));
}

HeadlessCommands::GateRequest HeadlessCommands::read(const QString& name, const QJsonObject& cmd) {
    ParsedCommand parsed = parseOperatorCommand(name, cmd);
    GateRequest r;
    r.command = std::move(parsed.command);
    r.refusal = parsed.error;
    r.refusalTarget = parsed.target;
    return r;
}

QByteArray HeadlessCommands::forwardToGate(const QJsonObject& cmd, const QString& name,
                                           const GateRequest& request) {
    CommandGate* gate = m_gate;
    if (!request.command) {
        if (request.refusalTarget.isEmpty()) {
            QJsonObject fields = request.echo;
            fields[QStringLiteral("ok")] = false;
            fields[QStringLiteral("message")] = request.refusal;
            return reply(cmd, fields);
        }
        // A malformed argument of a command naming a machine: audited as not sent to it.
        return viaGate(cmd, request.echo, [&](CommandGate::ResultHandler h) {
            gate->refuse(name, request.refusalTarget, OutcomeReason::InvalidArgument, request.refusal,
                         origin(), std::move(h));
        });
    }
    // The echoed fields as the typed value says them (e.g. assign's tasks with their AssignmentIds).
    const OperatorCommand& command = *request.command;
    const QJsonObject asSent = toJson(command);
    QJsonObject echo = request.echo;
    for (auto it = echo.begin(); it != echo.end(); ++it)
        if (asSent.contains(it.key()))
            it.value() = asSent.value(it.key());
    return viaGate(cmd, echo,
                   [&](CommandGate::ResultHandler h) { gate->command(command, origin(), std::move(h)); });
}

QByteArray HeadlessCommands::viaGate(const QJsonObject& cmd, const QJsonObject& echo,
                                     const std::function<void(CommandGate::ResultHandler)>& issue,
                                     const QString& suffix) {
    // The gate answers when every stack reported its outcome (or its deadline passed): the result line is
    // written then. When every bridge decided at once, the line is also returned here.
    struct Call {
        bool inCall = true;
        QByteArray line;
    };
    auto call = std::make_shared<Call>();
    ++m_pendingResults;
    QPointer<HeadlessCommands> self(this);
    issue([self, call, cmd, echo, suffix](const CommandResult& r) {
        if (!self)
            return;
        QJsonObject fields = echo;
        fields[QStringLiteral("ok")] = r.ok;
        fields[QStringLiteral("targets")] = targetsToJson(r.targets); // what went on the wire, per target
        fields[QStringLiteral("message")] = !r.ok && !suffix.isEmpty() ? r.message + suffix : r.message;
        const QByteArray line = self->reply(cmd, fields);
        if (call->inCall)
            call->line = line;
        if (--self->m_pendingResults == 0 && self->m_settled)
            self->m_settled();
    });
    call->inCall = false;
    return call->line;
}

QJsonObject linkCountersFields(const QList<QPointer<FleetBridge>>& bridges) {
    QJsonArray links;
    for (const QPointer<FleetBridge>& b : bridges) {
        if (!b)
            continue;
        for (const LinkCounters& c : b->linkCounters()) {
            QJsonObject rejected;
            for (auto it = c.rejected.begin(); it != c.rejected.end(); ++it)
                rejected[it.key()] = double(it.value());
            QJsonObject all;
            for (auto it = c.all.begin(); it != c.all.end(); ++it)
                all[it.key()] = double(it.value());
            QJsonObject l;
            l[QStringLiteral("protocol")] = toText(b->protocol());
            l[QStringLiteral("link")] = c.link;
            l[QStringLiteral("rejected_total")] = double(c.rejectedTotal());
            l[QStringLiteral("rejected")] = rejected;
            l[QStringLiteral("counters")] = all;
            links.append(l);
        }
    }
    return {{QStringLiteral("ok"), true},
            {QStringLiteral("message"), QStringLiteral("%1 links").arg(links.size())},
            {QStringLiteral("links"), links}};
}

} // namespace ocu
