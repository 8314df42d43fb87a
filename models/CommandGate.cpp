#include "models/CommandGate.h"

#include "models/AlarmModel.h"

#include <QDateTime>
#include <QFile>
#include <QJsonDocument>
#include <QUuid>

namespace ocu {

CommandGate::CommandGate(AlarmModel* alarms, QObject* parent) : QObject(parent), m_alarms(alarms) {}

void CommandGate::addBridge(FleetBridge* bridge) {
    if (bridge && !m_bridges.contains(bridge))
        m_bridges.push_back(bridge);
}

QVector<FleetBridge*> CommandGate::bridges() const {
    QVector<FleetBridge*> out;
    for (const auto& b : m_bridges)
        if (b)
            out.push_back(b.data());
    return out;
}

FleetBridge* CommandGate::bridgeFor(const QString& machineId) const {
    for (const auto& b : m_bridges)
        if (b && b->ownsMachine(machineId))
            return b.data();
    return nullptr;
}

CommandResult CommandGate::stopAll(const QString& origin) {
    // Every bridge gets the stop even if an earlier one refused: a partial stop beats no stop.
    QStringList failures;
    int sent = 0;
    for (FleetBridge* b : bridges()) {
        const CommandResult r = b->stopAll();
        if (r.ok)
            ++sent;
        else
            failures.push_back(toText(b->protocol()) + QStringLiteral(": ") + r.message);
    }
    CommandResult result =
        failures.isEmpty() ? CommandResult::success(QStringLiteral("stop sent on %1 protocol(s)").arg(sent))
                           : CommandResult::failure(failures.join(QStringLiteral("; ")));
    if (bridges().isEmpty())
        result = CommandResult::failure(QStringLiteral("no protocol bridge registered"));
    audit(origin, QStringLiteral("stop_all"), QString(), result);
    emit stopAllIssued(result);
    return result;
}

CommandResult CommandGate::stopMachine(const QString& id, const QString& origin) {
    FleetBridge* b = bridgeFor(id);
    const CommandResult r =
        b ? b->stopMachine(id) : CommandResult::failure(QStringLiteral("unknown machine %1").arg(id));
    audit(origin, QStringLiteral("stop"), id, r);
    return r;
}

QString CommandGate::requestClearToken(const QString& id) {
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    // Forget expired tokens.
    for (auto it = m_tokens.begin(); it != m_tokens.end();)
        it = it->expiresMs < now ? m_tokens.erase(it) : std::next(it);
    const QString token = QUuid::createUuid().toString(QUuid::WithoutBraces);
    m_tokens.insert(token, Token{id, now + m_tokenLifetimeMs});
    return token;
}

CommandResult CommandGate::clearStop(const QString& id, const QString& token, const QString& origin) {
    CommandResult r;
    auto it = m_tokens.find(token);
    if (token.isEmpty() || it == m_tokens.end() || it->id != id ||
        it->expiresMs < QDateTime::currentMSecsSinceEpoch()) {
        r = CommandResult::failure(QStringLiteral("release needs a deliberate confirmation"));
    } else {
        m_tokens.erase(it); // single use
        FleetBridge* b = bridgeFor(id);
        r = b ? b->clearStop(id) : CommandResult::failure(QStringLiteral("unknown machine %1").arg(id));
    }
    audit(origin, QStringLiteral("clear_stop"), id, r);
    return r;
}

CommandResult CommandGate::command(const QString& name, const QJsonObject& args, const QString& origin) {
    const QString id = args.value(QStringLiteral("id")).toString();
    FleetBridge* b = bridgeFor(id);
    if (id.isEmpty() && args.contains(QStringLiteral("protocol"))) {
        // Commands for a whole stack (e.g. JAUS release_all) name the protocol instead of a machine.
        const Protocol p = protocolFromString(args.value(QStringLiteral("protocol")).toString());
        for (FleetBridge* candidate : bridges())
            if (candidate->protocol() == p)
                b = candidate;
    }
    const CommandResult r =
        b ? b->command(name, args)
          : CommandResult::failure(id.isEmpty() ? QStringLiteral("missing \"id\" (or \"protocol\")")
                                                : QStringLiteral("unknown machine %1").arg(id));
    audit(origin, name, id, r);
    return r;
}

void CommandGate::audit(const QString& origin, const QString& action, const QString& target,
                        const CommandResult& result) {
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    QJsonObject o;
    o[QStringLiteral("time")] = QDateTime::fromMSecsSinceEpoch(now, Qt::UTC).toString(Qt::ISODateWithMs);
    o[QStringLiteral("origin")] = origin;
    o[QStringLiteral("action")] = action;
    if (!target.isEmpty())
        o[QStringLiteral("target")] = target;
    o[QStringLiteral("ok")] = result.ok;
    o[QStringLiteral("message")] = result.message;
    const QString line = QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact));

    if (m_alarms) {
        // A refused stop is an alarm the operator must see; accepted actions are logged as info.
        FleetEvent ev =
            makeEvent(result.ok ? EventSeverity::Info : EventSeverity::Alarm, EventKind::Audit, target,
                      QStringLiteral("%1 by %2: %3").arg(action, origin, result.message), origin);
        ev.timeMs = now;
        m_alarms->add(ev);
    }
    if (!m_auditPath.isEmpty()) {
        QFile f(m_auditPath);
        if (f.open(QIODevice::WriteOnly | QIODevice::Append))
            f.write(line.toUtf8() + '\n');
    }
    emit audited(line);
}

} // namespace ocu
