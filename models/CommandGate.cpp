#include "models/CommandGate.h"

#include "models/AlarmModel.h"
#include "protocols/common/ThreadPriority.h"

#include <QDateTime>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QThread>
#include <QUuid>

#include <algorithm>
#include <map>
#include <mutex>
#include <optional>
#include <utility>

namespace ocu {

// The gate's liveness for outcome callbacks that run on io threads: a callback holds the mutex while it
// posts to the gate, and the gate's destructor marks it dead under the same mutex.
struct GateLife {
    std::mutex mutex;
    CommandGate* gate = nullptr;
};

// The outcomes of a STOP ALL sent early on another thread, per bridge, until the gate's thread takes them
// (attach: at once when in, else when they arrive).
struct EarlyStop {
    std::mutex mutex;
    std::vector<FleetBridge*> bridges; // called early
    std::map<FleetBridge*, std::vector<TargetOutcome>> got;
    std::map<FleetBridge*, OutcomeCallback> waiting;
    bool covers(FleetBridge* b) const {
        return std::find(bridges.begin(), bridges.end(), b) != bridges.end();
    }
    void arrived(FleetBridge* b, std::vector<TargetOutcome> o) {
        OutcomeCallback done;
        {
            std::lock_guard lock(mutex);
            auto it = waiting.find(b);
            if (it == waiting.end()) {
                got[b] = std::move(o);
                return;
            }
            done = std::move(it->second);
            waiting.erase(it);
        }
        done(std::move(o));
    }
    void attach(FleetBridge* b, OutcomeCallback done) {
        std::vector<TargetOutcome> o;
        {
            std::lock_guard lock(mutex);
            auto it = got.find(b);
            if (it == got.end()) {
                waiting[b] = std::move(done);
                return;
            }
            o = std::move(it->second);
            got.erase(it);
        }
        done(std::move(o));
    }
};

struct CommandGate::Pending {
    QString action;
    QString target;      // the machine (or empty for STOP ALL)
    QJsonObject command; // the typed command as JSON (the audit line's "command")
    QString origin;
    OperatorIdentity issuer; // the operator when it was issued
    QVector<QPointer<FleetBridge>> bridges;
    std::vector<std::optional<std::vector<TargetOutcome>>> outcomes; // per bridge; nullopt = not answered
    int answered = 0;
    bool issuing = true;
    std::vector<std::function<void()>> deferred; // answers on the GUI thread while issuing
    QTimer* deadline = nullptr;
    ResultHandler onFinal;
    QElapsedTimer since; // when the command was issued (confirmation latency)
};

CommandGate::CommandGate(AlarmModel* alarms, QObject* parent) : QObject(parent), m_alarms(alarms) {
    qRegisterMetaType<ocu::CommandResult>();
    m_life = std::make_shared<GateLife>();
    m_life->gate = this;
}

CommandGate::~CommandGate() {
    std::lock_guard lock(m_life->mutex);
    m_life->gate = nullptr;
}

void CommandGate::addBridge(FleetBridge* bridge) {
    if (!bridge || m_bridges.contains(bridge))
        return;
    m_bridges.push_back(bridge);
    if (bridge->stopAllFromAnyThread()) {
        std::lock_guard lock(m_earlyMutex);
        m_earlyBridges.push_back(bridge);
        // Those that send from the caller's thread first (a woken io thread may take this core).
        std::stable_partition(m_earlyBridges.begin(), m_earlyBridges.end(),
                              [](FleetBridge* b) { return b->stopsFromCallersThread(); });
    }
    connect(bridge, &FleetBridge::stopReported, this, &CommandGate::onStopReported);
    connect(bridge, &FleetBridge::commandReported, this, &CommandGate::onCommandReported);
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

void CommandGate::dispatch(const OperatorCommand& command, const QString& origin,
                           const QVector<FleetBridge*>& to,
                           const std::function<void(FleetBridge*, OutcomeCallback)>& fn,
                           ResultHandler onFinal) {
    const quint64 id = m_nextId++;
    auto p = std::make_shared<Pending>();
    p->action = commandName(command);
    p->target = commandTarget(command);
    p->command = toJson(command);
    p->origin = origin;
    p->issuer = m_operator;
    p->onFinal = std::move(onFinal);
    p->since.start();
    for (FleetBridge* b : to)
        p->bridges.push_back(b);
    p->outcomes.resize(size_t(to.size()));
    m_pending.insert(id, p);

    std::weak_ptr<GateLife> life = m_life;
    QThread* guiThread = thread();
    for (int i = 0; i < to.size(); ++i) {
        // Runs once, on the GUI thread (a bridge's own refusal) or on a stack's io thread.
        OutcomeCallback done = [this, life, guiThread, id, i](std::vector<TargetOutcome> outcomes) {
            auto apply = [this, id, i](std::vector<TargetOutcome> o) {
                auto it = m_pending.find(id);
                if (it == m_pending.end())
                    return; // too late: the deadline already called this bridge's part not sent
                Pending& pend = **it;
                if (pend.outcomes[size_t(i)])
                    return; // a second call: the first one counts
                // Watch each sent stop target from now on: its machine's report may come before the other
                // bridges answered.
                if (pend.action == QLatin1String("stop_all") || pend.action == QLatin1String("stop"))
                    watchStops(pend.bridges[i].data(), o, pend.since);
                else if (FleetBridge* b = pend.bridges[i].data(); b && b->confirmsCommand(pend.action))
                    watchCommand(pend.action, b, o, pend.since);
                pend.outcomes[size_t(i)] = std::move(o);
                if (++pend.answered == int(pend.outcomes.size()) && !pend.issuing)
                    finish(id);
            };
            if (QThread::currentThread() == guiThread) {
                // Answered while the gate is still calling bridges (a refusal, or a stack that sent from
                // this thread): recorded after every bridge was called, so no model, alarm or watch work
                // delays the next bridge's sends.
                if (auto it = m_pending.find(id); it != m_pending.end() && (*it)->issuing) {
                    (*it)->deferred.push_back(
                        [apply, o = std::move(outcomes)]() mutable { apply(std::move(o)); });
                    return;
                }
                apply(std::move(outcomes));
                return;
            }
            auto l = life.lock();
            if (!l)
                return;
            std::lock_guard lock(l->mutex);
            if (!l->gate)
                return;
            QMetaObject::invokeMethod(
                l->gate, [apply, o = std::move(outcomes)]() mutable { apply(std::move(o)); },
                Qt::QueuedConnection);
        };
        fn(to[i], std::move(done));
    }
    // The deadline timer after the bridges were called: nothing but the command itself before the sends.
    p->deadline = new QTimer(this);
    p->deadline->setSingleShot(true);
    connect(p->deadline, &QTimer::timeout, this, [this, id] { finish(id); });
    p->deadline->start(m_answerDeadlineMs);
    for (auto& f : std::exchange(p->deferred, {}))
        f();
    p->issuing = false;
    if (p->answered == int(p->outcomes.size()))
        finish(id);
}

void CommandGate::finish(quint64 id) {
    auto p = m_pending.take(id);
    if (!p)
        return;
    p->deadline->stop();
    p->deadline->deleteLater();
    QVector<TargetOutcome> targets;
    for (size_t i = 0; i < p->outcomes.size(); ++i) {
        if (p->outcomes[i]) {
            for (TargetOutcome& o : *p->outcomes[i])
                targets.push_back(std::move(o));
        } else {
            const FleetBridge* b = p->bridges[int(i)];
            targets.push_back(refusal(b ? toText(b->protocol()) : tr("protocol stack"),
                                      OutcomeReason::NoAnswer,
                                      tr("stack did not answer within %1 ms").arg(m_answerDeadlineMs)));
        }
    }
    finishNow(p->action, p->target, p->command, p->origin,
              CommandResult::fromTargets(targets, tr("no protocol bridge registered: nothing sent")),
              p->onFinal, &p->issuer);
}

void CommandGate::finishNow(const OperatorCommand& command, const QString& origin, CommandResult r,
                            const ResultHandler& onFinal) {
    finishNow(commandName(command), commandTarget(command), toJson(command), origin, std::move(r), onFinal);
}

void CommandGate::finishNow(const QString& action, const QString& target, const QJsonObject& command,
                            const QString& origin, CommandResult r, const ResultHandler& onFinal,
                            const OperatorIdentity* issuer) {
    r.action = action;
    audit(origin, action, target, command, r, issuer ? *issuer : m_operator);
    const bool isStop = action == QLatin1String("stop_all") || action == QLatin1String("stop");
    if (onFinal)
        onFinal(r);
    emit commandFinished(r, origin);
    if (isStop)
        emit stopFinished(r, origin);
}

void CommandGate::stopAll(const QString& origin, ResultHandler onFinal) {
    stopAll(origin, std::move(onFinal), nullptr);
}

std::shared_ptr<EarlyStop> CommandGate::stopAllEarly() {
    ScopedStopPathBoost boost;
    auto early = std::make_shared<EarlyStop>();
    {
        std::lock_guard lock(m_earlyMutex);
        early->bridges = m_earlyBridges;
    }
    for (FleetBridge* b : early->bridges)
        b->stopAll([early, b](std::vector<TargetOutcome> o) { early->arrived(b, std::move(o)); });
    return early;
}

void CommandGate::stopAll(const QString& origin, ResultHandler onFinal, std::shared_ptr<EarlyStop> early) {
    ScopedStopPathBoost boost; // no io thread takes this core between two protocols' sends
    // Every bridge gets the stop even if an earlier one refused: a partial stop beats no stop. Those that
    // send from this thread first: a stack's io thread woken by a post may take this thread's core.
    QVector<FleetBridge*> to = bridges();
    std::stable_partition(to.begin(), to.end(), [](FleetBridge* b) { return b->stopsFromCallersThread(); });
    dispatch(
        StopAll{}, origin, to,
        [early](FleetBridge* b, OutcomeCallback done) {
            if (early && early->covers(b))
                early->attach(b, std::move(done)); // sent already: its outcome, now or when it comes
            else
                b->stopAll(std::move(done));
        },
        std::move(onFinal));
}

void CommandGate::stopMachine(const QString& id, const QString& origin, ResultHandler onFinal) {
    const StopMachine stop{id};
    FleetBridge* b = bridgeFor(id);
    if (!b) {
        finishNow(stop, origin,
                  CommandResult::fromTargets(
                      {refusal(id, OutcomeReason::UnknownTarget, tr("unknown machine %1").arg(id))}),
                  onFinal);
        return;
    }
    dispatch(
        stop, origin, {b},
        [id](FleetBridge* br, OutcomeCallback done) { br->stopMachine(id, std::move(done)); },
        std::move(onFinal));
}

QString CommandGate::requestClearToken(const QString& id) {
    const qint64 now = m_clock->nowMs();
    // Forget expired tokens.
    for (auto it = m_tokens.begin(); it != m_tokens.end();)
        it = it->expiresMs < now ? m_tokens.erase(it) : std::next(it);
    const QString token = QUuid::createUuid().toString(QUuid::WithoutBraces);
    m_tokens.insert(token, Token{id, now + m_tokenLifetimeMs});
    return token;
}

void CommandGate::setOperator(const OperatorIdentity& identity) {
    if (identity == m_operator)
        return;
    m_operator = identity;
    emit permissionsChanged();
}

void CommandGate::setLocked(bool locked) {
    if (locked == m_locked)
        return;
    m_locked = locked;
    emit permissionsChanged();
}

bool CommandGate::mayIssue(const QString& command, QString* why) const {
    if (m_permissions.isStop(command))
        return true; // never refused: locked or not, whatever the role
    QString text;
    if (m_locked)
        text = tr("the console is locked: only stops are accepted");
    else if (m_operator.role != OperatorRole::Admin || m_permissions.hasRow(command))
        text = m_permissions.refusalText(command, m_operator.role);
    if (why)
        *why = text;
    return text.isEmpty();
}

bool CommandGate::admit(const OperatorCommand& command, const QString& origin, const ResultHandler& onFinal) {
    QString why;
    if (mayIssue(commandName(command), &why))
        return true;
    const CommandRoute route = commandRoute(command);
    const QString target = !route.machine.isEmpty() ? route.machine
                           : route.protocol         ? toText(*route.protocol)
                                                    : commandName(command);
    finishNow(command, origin,
              CommandResult::fromTargets({refusal(target, OutcomeReason::NotPermitted, why)}), onFinal);
    return false;
}

void CommandGate::clearStop(const QString& id, const QString& token, const QString& origin,
                            ResultHandler onFinal) {
    const ClearStop clear{id, false, {}}; // the token is never audited
    if (!admit(clear, origin, onFinal))
        return;
    auto it = m_tokens.find(token);
    if (token.isEmpty() || it == m_tokens.end() || it->id != id || it->expiresMs < m_clock->nowMs()) {
        finishNow(clear, origin,
                  CommandResult::fromTargets({refusal(id, OutcomeReason::NotPermitted,
                                                      tr("release needs a deliberate confirmation"))}),
                  onFinal);
        return;
    }
    m_tokens.erase(it); // single use
    FleetBridge* b = bridgeFor(id);
    if (!b) {
        finishNow(clear, origin,
                  CommandResult::fromTargets(
                      {refusal(id, OutcomeReason::UnknownTarget, tr("unknown machine %1").arg(id))}),
                  onFinal);
        return;
    }
    dispatch(
        ClearStop{id, true, {}}, origin, {b},
        [id](FleetBridge* br, OutcomeCallback done) { br->clearStop(id, std::move(done)); },
        std::move(onFinal));
}

FleetBridge* CommandGate::bridgeOf(Protocol protocol) const {
    for (FleetBridge* b : bridges())
        if (b->protocol() == protocol)
            return b;
    return nullptr;
}

void CommandGate::command(const OperatorCommand& command, const QString& origin, ResultHandler onFinal) {
    if (std::holds_alternative<StopAll>(command))
        return stopAll(origin, std::move(onFinal));
    if (const auto* stop = std::get_if<StopMachine>(&command))
        return stopMachine(stop->id, origin, std::move(onFinal));
    if (const auto* clear = std::get_if<ClearStop>(&command))
        return clearStop(clear->id, clear->token, origin, std::move(onFinal));
    if (!admit(command, origin, onFinal))
        return;
    // The bridge owning the machine, else (commands for a whole stack: JAUS release_all, an OSYRIS text
    // to every station) the bridge of the command's protocol.
    const CommandRoute route = commandRoute(command);
    FleetBridge* b = route.machine.isEmpty() ? (route.protocol ? bridgeOf(*route.protocol) : nullptr)
                                             : bridgeFor(route.machine);
    if (!b) {
        CommandResult r =
            route.machine.isEmpty()
                ? CommandResult::fromTargets(
                      {refusal(route.protocol ? toText(*route.protocol) : commandName(command),
                               OutcomeReason::UnknownTarget,
                               tr("no %1 bridge in this console: nothing sent")
                                   .arg(route.protocol ? toText(*route.protocol) : QString()))})
                : CommandResult::fromTargets({refusal(route.machine, OutcomeReason::UnknownTarget,
                                                      tr("unknown machine %1").arg(route.machine))});
        finishNow(command, origin, r, onFinal);
        return;
    }
    dispatch(
        command, origin, {b},
        [command](FleetBridge* br, OutcomeCallback done) { br->command(command, std::move(done)); },
        std::move(onFinal));
}

void CommandGate::refuse(const QString& action, const QString& target, OutcomeReason cause,
                         const QString& reason, const QString& origin, ResultHandler onFinal) {
    QJsonObject command{{QStringLiteral("cmd"), action}};
    if (!target.isEmpty())
        command[QStringLiteral("id")] = target;
    finishNow(action, target, command, origin,
              CommandResult::fromTargets({refusal(target.isEmpty() ? action : target, cause, reason)}),
              onFinal);
}

QStringList CommandGate::awaitingConfirmation() const {
    return m_watches.keys();
}

void CommandGate::watchStops(FleetBridge* b, const std::vector<TargetOutcome>& outcomes,
                             const QElapsedTimer& since) {
    // The bridge that answered for the targets is known: no guessing the owner from the target's name.
    QStringList noStopState;
    for (const TargetOutcome& o : outcomes) {
        if (!o.sent)
            continue;
        const QString id = targetId(o);
        if (b && !b->reportsStopState()) {
            noStopState << id;
            continue;
        }
        if (b && b->reportsStopped(id)) {
            emit stopConfirmed(id, tr("%1 already reports being stopped").arg(id), 0);
            if (m_alarms)
                m_alarms->add(makeEvent(EventSeverity::Info, EventKind::Audit, id,
                                        tr("%1 already reports being stopped").arg(id),
                                        QStringLiteral("gate")));
            continue;
        }
        Watch& w = m_watches[id];
        w.since = since;
        if (!w.timer) {
            w.timer = new QTimer(this);
            w.timer->setSingleShot(true);
            const QString target = id;
            connect(w.timer, &QTimer::timeout, this, [this, target] {
                auto it = m_watches.find(target);
                if (it == m_watches.end())
                    return;
                it->timer->deleteLater();
                m_watches.erase(it);
                const QString text =
                    tr("%1 has not reported being stopped %2 ms after the stop command was sent")
                        .arg(target)
                        .arg(m_confirmTimeoutMs);
                if (m_alarms)
                    m_alarms->add(makeEvent(EventSeverity::Alarm, EventKind::Timeout, target, text,
                                            QStringLiteral("gate")));
                emit stopUnconfirmed(target, text);
            });
        }
        w.timer->start(std::max<qint64>(0, m_confirmTimeoutMs - since.elapsed()));
    }
    if (!noStopState.isEmpty() && m_alarms)
        m_alarms->add(
            makeEvent(EventSeverity::Info, EventKind::Audit, {},
                      tr("%1: OSYRIS carries no stop state, so no machine can confirm the stop; the "
                         "STOP text went to the drivers' displays")
                          .arg(noStopState.join(QStringLiteral(", "))),
                      QStringLiteral("gate")));
}

void CommandGate::onStopReported(const QString& target, const QString& text) {
    auto it = m_watches.find(target);
    if (it == m_watches.end())
        return;
    const qint64 ms = it->since.elapsed();
    it->timer->stop();
    it->timer->deleteLater();
    m_watches.erase(it);
    const QString line = tr("%1 %2 ms after the command").arg(text).arg(ms);
    if (m_alarms)
        m_alarms->add(makeEvent(EventSeverity::Info, EventKind::Audit, target, line, QStringLiteral("gate")));
    emit stopConfirmed(target, line, ms);
}

QStringList CommandGate::awaitingCommandConfirmation() const {
    QStringList out;
    for (auto it = m_commandWatches.cbegin(); it != m_commandWatches.cend(); ++it)
        out << QString(it.key()).replace(QLatin1Char('\n'), QLatin1Char(' '));
    return out;
}

void CommandGate::watchCommand(const QString& action, FleetBridge* b,
                               const std::vector<TargetOutcome>& outcomes, const QElapsedTimer& since) {
    for (const TargetOutcome& o : outcomes) {
        if (!o.sent)
            continue;
        const QString id = targetId(o);
        if (b->reportsConfirmed(action, id)) {
            const QString text = tr("%1 already reports the effect of %2").arg(id, action);
            if (m_alarms)
                m_alarms->add(
                    makeEvent(EventSeverity::Info, EventKind::Audit, id, text, QStringLiteral("gate")));
            emit commandConfirmed(action, id, text, 0);
            continue;
        }
        const QString key = action + QLatin1Char('\n') + id;
        Watch& w = m_commandWatches[key];
        w.since = since;
        if (!w.timer) {
            w.timer = new QTimer(this);
            w.timer->setSingleShot(true);
            const QString target = id;
            connect(w.timer, &QTimer::timeout, this, [this, key, action, target] {
                auto it = m_commandWatches.find(key);
                if (it == m_commandWatches.end())
                    return;
                it->timer->deleteLater();
                m_commandWatches.erase(it);
                const QString text = tr("%1 has not confirmed %2 %3 ms after the command was sent")
                                         .arg(target, action)
                                         .arg(m_confirmTimeoutMs);
                if (m_alarms)
                    m_alarms->add(makeEvent(EventSeverity::Alarm, EventKind::Timeout, target, text,
                                            QStringLiteral("gate")));
                emit commandUnconfirmed(action, target, text);
            });
        }
        w.timer->start(std::max<qint64>(0, m_confirmTimeoutMs - since.elapsed()));
    }
}

void CommandGate::onCommandReported(const QString& action, const QString& target, const QString& text) {
    auto it = m_commandWatches.find(action + QLatin1Char('\n') + target);
    if (it == m_commandWatches.end())
        return;
    const qint64 ms = it->since.elapsed();
    it->timer->stop();
    it->timer->deleteLater();
    m_commandWatches.erase(it);
    const QString line = tr("%1 %2 ms after the command").arg(text).arg(ms);
    if (m_alarms)
        m_alarms->add(makeEvent(EventSeverity::Info, EventKind::Audit, target, line, QStringLiteral("gate")));
    emit commandConfirmed(action, target, line, ms);
}

void CommandGate::audit(const QString& origin, const QString& action, const QString& target,
                        const QJsonObject& command, const CommandResult& result,
                        const OperatorIdentity& issuer, EventSeverity failed) {
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    QJsonObject o;
    o[QStringLiteral("time")] = QDateTime::fromMSecsSinceEpoch(now, Qt::UTC).toString(Qt::ISODateWithMs);
    o[QStringLiteral("origin")] = origin;
    o[QStringLiteral("operator")] = issuer.user;
    o[QStringLiteral("role")] = issuer.roleText();
    o[QStringLiteral("console")] = issuer.console;
    o[QStringLiteral("action")] = action;
    if (!target.isEmpty())
        o[QStringLiteral("target")] = target;
    o[QStringLiteral("command")] = command;
    o[QStringLiteral("ok")] = result.ok;
    o[QStringLiteral("targets")] = targetsToJson(result.targets);
    o[QStringLiteral("message")] = result.message;
    const QString line = QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact));

    if (m_alarms) {
        // A command that did not reach every target is an alarm the operator must see; the rest is info.
        QString text = QStringLiteral("%1 by %2: %3").arg(action, origin, result.message);
        if (!issuer.user.isEmpty())
            text += QStringLiteral(" (%1, %2)").arg(issuer.user, issuer.roleText());
        FleetEvent ev =
            makeEvent(result.ok ? EventSeverity::Info : failed, EventKind::Audit, target, text, origin);
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

void CommandGate::auditSession(const QString& action, const OperatorIdentity& who, bool ok,
                               const QString& message) {
    CommandResult r;
    r.ok = ok;
    r.message = message;
    audit(QStringLiteral("gui"), action, QString(), QJsonObject(), r, who, EventSeverity::Info);
}

void CommandGate::auditLocal(const QString& origin, const QString& action, const QJsonObject& command,
                             bool ok, const QString& message) {
    CommandResult r;
    r.ok = ok;
    r.message = message;
    audit(origin, action, QString(), command, r, m_operator);
}

} // namespace ocu
