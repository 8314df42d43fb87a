#include "models/AutoDispatcher.h"

#include "models/AlarmModel.h"
#include "models/CommandGate.h"

#include <QDateTime>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ocu {

namespace {
bool hasTask(const DispatchTruck& t) {
    return t.assignmentStatus == QLatin1String("Pending") || t.assignmentStatus == QLatin1String("Active");
}
QString areaName(const DispatchArea& a) {
    return a.name.isEmpty() ? AutoDispatcher::tr("way %1").arg(a.wayId) : a.name;
}
QString areaKey(const QString& link, qint64 way) {
    return link + QLatin1Char('/') + QString::number(way);
}
} // namespace

AutoDispatcher::AutoDispatcher(DispatchSource* source, CommandGate* gate, QObject* parent)
    : QObject(parent), m_source(source), m_gate(gate) {
    setObjectName(QStringLiteral("auto-dispatcher"));
    m_soon.setSingleShot(true);
    m_soon.setInterval(0);
    connect(&m_soon, &QTimer::timeout, this, &AutoDispatcher::step);
    m_every.setInterval(1000);
    connect(&m_every, &QTimer::timeout, this, &AutoDispatcher::step);
    if (source) {
        connect(source, &DispatchSource::trucksChanged, this, &AutoDispatcher::schedule);
        connect(source, &DispatchSource::areasChanged, this, &AutoDispatcher::schedule);
    }
}

void AutoDispatcher::setAlarms(AlarmModel* alarms) {
    m_alarms = alarms;
}

void AutoDispatcher::setOn(bool on, const QString& origin) {
    if (on == m_on)
        return;
    m_on = on;
    if (on) {
        m_every.start();
        schedule();
    } else {
        m_every.stop();
        m_soon.stop();
        m_inFlight.clear(); // the gate still audits the answers of what was sent
        m_avoidUntil.clear();
    }
    say(on ? tr("Auto dispatch ON (%1): idle FMS trucks go to the shortest queue").arg(origin)
           : tr("Auto dispatch OFF (%1)").arg(origin));
    emit stateChanged(on);
}

void AutoDispatcher::schedule() {
    if (m_on && !m_soon.isActive())
        m_soon.start();
}

QString AutoDispatcher::key(const QString& truckId, const DispatchArea& a) const {
    return truckId + QLatin1Char('|') + areaKey(a.link, a.wayId);
}

void AutoDispatcher::say(const QString& line, EventSeverity severity, const QString& machine) {
    m_last = QStringLiteral("%1 %2").arg(
        QDateTime::fromMSecsSinceEpoch(m_clock->nowMs()).toString(QStringLiteral("HH:mm:ss")), line);
    emit acted(line);
    if (m_alarms) {
        FleetEvent e = makeEvent(severity, EventKind::Info, machine, tr("Auto dispatch: %1").arg(line),
                                 QStringLiteral("auto-dispatch"));
        e.requiresAck = false;
        m_alarms->add(e);
    }
}

// A request out is settled when the truck reports that assignment, answers Rejected, or the answer is late.
void AutoDispatcher::followAnswers(const QVector<DispatchTruck>& trucks) {
    const qint64 now = m_clock->nowMs();
    QHash<QString, const DispatchTruck*> byId;
    for (const auto& t : trucks)
        byId.insert(t.id, &t);
    for (auto it = m_inFlight.begin(); it != m_inFlight.end();) {
        const DispatchTruck* t = byId.value(it.key());
        const InFlight& f = it.value();
        if (!t) {
            it = m_inFlight.erase(it);
            continue;
        }
        if (t->requestedAssignmentId == f.assignmentId && t->lastResponse == QLatin1String("Rejected")) {
            m_avoidUntil.insert(it.key() + QLatin1Char('|') + areaKey(f.areaLink, f.areaWay), now + kRetryMs);
            say(tr("%1 rejected way %2: %3").arg(t->name).arg(f.areaWay).arg(t->lastResponseDetail),
                EventSeverity::Info, t->id);
            it = m_inFlight.erase(it);
            continue;
        }
        if (t->assignmentId == f.assignmentId && !t->assignmentStatus.isEmpty()) {
            it = m_inFlight.erase(
                it); // the truck reports it: from now on its own state says whether it is idle
            continue;
        }
        if (now - f.sentMs > kAnswerTimeoutMs) {
            m_avoidUntil.insert(it.key() + QLatin1Char('|') + areaKey(f.areaLink, f.areaWay), now + kRetryMs);
            say(tr("%1 did not report the assignment to way %2 within %3 s")
                    .arg(t->name)
                    .arg(f.areaWay)
                    .arg(kAnswerTimeoutMs / 1000),
                EventSeverity::Info, t->id);
            it = m_inFlight.erase(it);
            continue;
        }
        ++it;
    }
    for (auto it = m_avoidUntil.begin(); it != m_avoidUntil.end();)
        it = it.value() <= now ? m_avoidUntil.erase(it) : std::next(it);
}

QVector<AutoDispatcher::Decision> AutoDispatcher::plan() const {
    QVector<Decision> out;
    if (!m_source)
        return out;
    QVector<DispatchTruck> trucks = m_source->trucks();
    std::sort(trucks.begin(), trucks.end(), [](const DispatchTruck& a, const DispatchTruck& b) {
        return a.name != b.name ? a.name < b.name : a.id < b.id;
    });
    QVector<DispatchArea> loads, dumps;
    for (const DispatchArea& a : m_source->areas()) {
        if (a.defaultTask == QLatin1String("Load"))
            loads << a;
        else if (a.defaultTask == QLatin1String("Offload"))
            dumps << a;
    }
    // Queues: at the area, or assigned to it and on the way, or asked from here and not reported yet.
    QHash<QString, int> queue; // area key -> trucks
    for (const auto* list : {&loads, &dumps})
        for (const DispatchArea& a : *list)
            queue.insert(areaKey(a.link, a.wayId), 0);
    for (const DispatchTruck& t : trucks) {
        if (auto f = m_inFlight.constFind(t.id); f != m_inFlight.constEnd()) {
            queue[areaKey(f->areaLink, f->areaWay)] += 1;
            continue;
        }
        if (t.wayId)
            if (auto at = queue.find(areaKey(t.link, *t.wayId)); at != queue.end()) {
                ++*at;
                continue;
            }
        if (const auto dest = t.activeDestination())
            if (auto to = queue.find(areaKey(t.link, *dest)); to != queue.end())
                ++*to;
    }
    const qint64 now = m_clock->nowMs();
    for (const DispatchTruck& t : trucks) {
        if (out.size() >= kMaxPerStep)
            break;
        if (!t.stateKnown || t.custodian != QLatin1String("FMS") || m_inFlight.contains(t.id) ||
            m_avoidUntil.value(t.id, 0) > now)
            continue;
        if (hasTask(t) && !t.needsAssignment)
            continue;
        if (!m_source->assignRefusal(t.id).isEmpty()) // link down, or whatever the bridge would refuse
            continue;
        const bool loaded = t.loaded.value_or(false);
        const QVector<DispatchArea>& candidates = loaded ? dumps : loads;
        const DispatchArea* best = nullptr;
        int bestQueue = std::numeric_limits<int>::max();
        double bestLength = std::numeric_limits<double>::infinity();
        for (const DispatchArea& a : candidates) {
            if (a.link != t.link)
                continue;
            if (m_avoidUntil.value(key(t.id, a), 0) > now)
                continue;
            const DispatchRoute r = m_source->routeTo(t.id, a);
            if (r.ways.isEmpty() && !r.error.isEmpty())
                continue; // unreachable from where the truck is
            const double length = r.ways.isEmpty() ? std::numeric_limits<double>::infinity() : r.lengthM;
            const int q = queue.value(areaKey(a.link, a.wayId));
            if (!best || q < bestQueue || (q == bestQueue && length < bestLength) ||
                (q == bestQueue && length == bestLength && areaName(a) < areaName(*best))) {
                best = &a;
                bestQueue = q;
                bestLength = length;
            }
        }
        if (!best)
            continue;
        Decision d;
        d.truckId = t.id;
        d.truckName = t.name;
        d.task = loaded ? QStringLiteral("Offload") : QStringLiteral("Load");
        d.area = *best;
        d.queue = bestQueue;
        d.routeM = std::isfinite(bestLength) ? bestLength : -1;
        out << d;
        queue[areaKey(best->link, best->wayId)] += 1; // the next truck sees this one in the queue
    }
    return out;
}

void AutoDispatcher::step() {
    if (!m_on || !m_source)
        return;
    followAnswers(m_source->trucks());
    if (!m_gate)
        return;
    for (const Decision& d : plan()) {
        if (!m_on)
            break;
        QString assignmentId;
        const Assign assign = m_source->assignCommand(d.truckId, d.task, d.area, &assignmentId);
        m_inFlight.insert(d.truckId,
                          InFlight{assignmentId, d.area.wayId, d.area.link, m_clock->nowMs(), false});
        const QString what =
            tr("%1: %2 at %3 (queue %4)").arg(d.truckName, d.task, areaName(d.area)).arg(d.queue);
        QPointer<AutoDispatcher> self(this);
        const QString truckId = d.truckId;
        m_gate->command(assign, QStringLiteral("auto-dispatch"),
                        [self, truckId, what](const CommandResult& r) {
                            if (self)
                                self->onResult(truckId, what, r);
                        });
    }
}

void AutoDispatcher::onResult(const QString& truckId, const QString& what, const CommandResult& r) {
    QStringList notSent = r.notSent();
    if (r.ok) {
        ++m_sent;
        say(tr("%1 — sent").arg(what), EventSeverity::Info, truckId);
        if (auto it = m_inFlight.find(truckId); it != m_inFlight.end())
            it->answered = true;
        return;
    }
    // Nothing on the wire: no answer to wait for. The truck is left alone for kRetryMs (a refused command is
    // an alarm of the gate: never one per second).
    m_inFlight.remove(truckId);
    m_avoidUntil.insert(truckId, m_clock->nowMs() + kRetryMs);
    say(tr("%1 — NOT sent: %2").arg(what, notSent.isEmpty() ? r.message : notSent.join(QStringLiteral("; "))),
        EventSeverity::Info, truckId);
}

} // namespace ocu
