#include "models/bridges/IsoDispatchSource.h"

#include "models/bridges/IsoBridge.h"
#include "protocols/iso23725/Routing.h"

#include <QUuid>

#include <cstdlib>

namespace ocu {

DispatchTruck toDispatchTruck(const IsoDispatchState& s) {
    DispatchTruck t;
    t.id = s.id;
    t.link = s.link;
    t.name = s.name;
    t.stateKnown = s.stateKnown;
    t.custodian = s.custodian;
    t.needsAssignment = s.needsAssignment;
    t.autonomyMode = s.autonomyMode;
    t.assignmentId = s.assignmentId;
    t.assignmentStatus = s.assignmentStatus;
    t.task = s.task;
    t.destinationId = s.destinationId;
    t.destinationName = s.destinationName;
    if (!s.requested.isEmpty()) {
        const IsoTask& first = s.requested.front();
        t.requestedAssignmentId = first.assignmentId;
        t.requestedTask = first.task;
        t.requestedDestination = first.destinationId;
        if (const IsoAssignmentResponse* r = s.response(first.assignmentId)) {
            t.lastResponse = r->response;
            t.lastResponseDetail = r->detail;
        }
    }
    t.productionState = s.productionState;
    t.wayId = s.wayId;
    t.productionSinceMs = s.productionSinceMs;
    t.payloadTonnes = s.payloadTonnes;
    t.loaded = s.loaded;
    return t;
}

IsoDispatchSource::IsoDispatchSource(IsoBridge* bridge, QObject* parent)
    : DispatchSource(parent), m_bridge(bridge) {
    connect(bridge, &IsoBridge::dispatchChanged, this, &DispatchSource::trucksChanged);
    connect(bridge, &IsoBridge::destinationsChanged, this, [this] {
        emit areasChanged();
        // Routes and destination names depend on the connectivity: every truck of the bridge may change.
        QStringList ids;
        for (const auto& d : m_bridge->dispatchStates())
            ids << d.id;
        if (!ids.isEmpty())
            emit trucksChanged(ids);
    });
}

QVector<DispatchTruck> IsoDispatchSource::trucks() const {
    QVector<DispatchTruck> out;
    if (!m_bridge)
        return out;
    const auto states = m_bridge->dispatchStates();
    out.reserve(states.size());
    for (const auto& s : states)
        out << toDispatchTruck(s);
    return out;
}

std::optional<DispatchTruck> IsoDispatchSource::truck(const QString& id) const {
    if (!m_bridge)
        return std::nullopt;
    const auto s = m_bridge->dispatchState(id);
    if (!s)
        return std::nullopt;
    return toDispatchTruck(*s);
}

QVector<DispatchArea> IsoDispatchSource::areas() const {
    QVector<DispatchArea> out;
    if (!m_bridge)
        return out;
    for (const auto& d : m_bridge->destinations())
        out << DispatchArea{d.link, d.wayId, d.name, d.defaultTask};
    return out;
}

QString IsoDispatchSource::assignRefusal(const QString& id) const {
    return m_bridge ? m_bridge->assignRefusal(id) : tr("the ISO 23725 bridge is gone");
}

DispatchRoute IsoDispatchSource::route(const QString& id) const {
    DispatchRoute r;
    const auto s = m_bridge ? m_bridge->dispatchState(id) : std::nullopt;
    if (!s) {
        r.error = tr("unknown truck");
        return r;
    }
    r.link = s->link;
    const bool heading =
        s->assignmentStatus == QLatin1String("Pending") || s->assignmentStatus == QLatin1String("Active");
    if (!heading || !s->destinationId) {
        r.error = tr("no active assignment");
        return r;
    }
    if (!s->wayId) {
        r.error = tr("the truck has not reported its way");
        return r;
    }
    const auto graph = m_bridge->routeGraph(s->link);
    if (!graph || graph->empty()) {
        r.error = tr("no MapConnectivityV1 from the AHS yet");
        return r;
    }
    const qint64 from = *s->wayId, to = *s->destinationId;
    // The route this console sent with the assignment (RouteV1: the ways between start and destination), from
    // the truck's current way onwards; otherwise the console's shortest path (what FmsCore sends as well).
    for (const IsoTask& t : s->requested) {
        if (t.assignmentId != s->assignmentId || !t.route || t.destinationId != to)
            continue;
        QVector<qint64> ways{from};
        const qsizetype at = t.route->indexOf(from);
        for (qsizetype i = at < 0 ? 0 : at + 1; i < t.route->size(); ++i)
            ways << std::llabs((*t.route)[i]); // negative: driven against node order (Q6)
        if (from != to)
            ways << to;
        double length = 0;
        for (qsizetype i = 1; i < ways.size(); ++i)
            if (const auto* item = graph->item(ways[i]); item && item->wayType == "Road")
                length += item->roadLength.value_or(0);
        r.ways = ways;
        r.lengthM = length;
        r.fromAssignment = true;
        return r;
    }
    const iso23725::RouteResult best = iso23725::shortestRoute(*graph, from, to);
    if (!best.ok) {
        r.error = QString::fromStdString(best.error);
        return r;
    }
    for (auto w : best.ways)
        r.ways << w;
    r.lengthM = best.length;
    return r;
}

DispatchRoute IsoDispatchSource::routeTo(const QString& id, const DispatchArea& area) const {
    DispatchRoute r;
    const auto s = m_bridge ? m_bridge->dispatchState(id) : std::nullopt;
    if (!s || s->link != area.link) {
        r.error = tr("unknown truck or another AHS's area");
        return r;
    }
    r.link = s->link;
    const auto graph = m_bridge->routeGraph(s->link);
    if (!s->wayId || !graph || graph->empty()) {
        r.error = !s->wayId ? tr("the truck has not reported its way")
                            : tr("no MapConnectivityV1 from the AHS yet");
        return r;
    }
    const iso23725::RouteResult best = iso23725::shortestRoute(*graph, *s->wayId, area.wayId);
    if (!best.ok) {
        r.error = QString::fromStdString(best.error);
        return r;
    }
    for (auto w : best.ways)
        r.ways << w;
    r.lengthM = best.length;
    return r;
}

Assign IsoDispatchSource::assignCommand(const QString& id, const QString& task, const DispatchArea& area,
                                        QString* assignmentId) const {
    IsoTask t;
    t.assignmentId = QUuid::createUuid().toString(QUuid::WithoutBraces);
    if (assignmentId)
        *assignmentId = t.assignmentId;
    t.task = task;
    t.destinationId = area.wayId;
    return IsoBridge::assignCommand(id, {t});
}

} // namespace ocu
