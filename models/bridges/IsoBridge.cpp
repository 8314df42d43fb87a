#include "models/bridges/IsoBridge.h"
#include "models/QtStrings.h"

#include "models/bridges/FleetDiscrepancyAlarms.h"

#include <QJsonObject>
#include <QMetaObject>

#include <algorithm>
#include <cmath>
#include <mutex>

namespace ocu {

using namespace iso23725;

IsoBridge::IsoBridge(const IsoConfig& config, const GeoFrame& frame, QObject* parent)
    : FleetBridge(Protocol::Iso23725, parent), m_config(config), m_frame(frame),
      m_poseGate(config.plausibility) {
    m_stack = std::make_unique<IsoStack>(m_config, static_cast<IsoListener&>(*this));
}

IsoBridge::~IsoBridge() {
    stop();
}

void IsoBridge::setMessageTap(MessageTap* tap) {
    m_stack->setMessageTap(tap);
}

QString IsoBridge::start() {
    for (const auto& l : m_config.links) {
        const LinkStatus s{QStringLiteral("iso23725:") + toQString(l.name), ocu::LinkState::Unknown, -1,
                           tr("connecting")};
        {
            std::lock_guard lock(m_linkNowMutex);
            m_linkNow.insert(s.link, s);
        }
        publishLink(s);
    }
    const bool ok = m_stack->start();
    m_running = true; // the io thread runs even when a link could not start
    if (!ok)
        return tr("ISO 23725: a link could not start (see the event log)");
    return {};
}

void IsoBridge::stop() {
    const bool wasRunning = m_running;
    m_running = false;
    if (m_stack)
        m_stack->stop();
    if (wasRunning)
        publishStackStopped(tr("ISO 23725 stack stopped"));
}

QStringList IsoBridge::linkNames() const {
    QStringList out;
    for (const auto& l : m_config.links)
        out << toQString(l.name);
    return out;
}

void IsoBridge::setOwnPosition(const QString& equipmentId, double lat, double lon, double altitude,
                               double headingDeg, double speedKmh) {
    m_stack->setOwnPosition(equipmentId.toStdString(), lat, lon, altitude, headingDeg, speedKmh);
}

AllStopState IsoBridge::allStopState(const QString& link) const {
    return static_cast<AllStopState>(m_allStop.value(link, static_cast<int>(AllStopState::Unknown)));
}

// ---- io thread ----

void IsoBridge::onLinkState(const std::string& link, iso23725::LinkState state, const std::string& reason) {
    LinkStatus s;
    s.link = QStringLiteral("iso23725:") + toQString(link);
    s.state = state == iso23725::LinkState::Up     ? ocu::LinkState::Up
              : state == iso23725::LinkState::Down ? ocu::LinkState::Down
                                                   : ocu::LinkState::Unknown;
    s.dataAgeMs = state == iso23725::LinkState::Up ? 0 : -1;
    s.detail = toQString(reason);
    if (state == iso23725::LinkState::Up)
        m_everUp.insert(link);
    // Before the first connection the link is "connecting", not lost: no alarm for that.
    if (state == iso23725::LinkState::Down && !m_everUp.count(link))
        s.state = ocu::LinkState::Unknown;
    {
        std::lock_guard lock(m_linkNowMutex);
        m_linkNow.insert(s.link, s);
    }
    publishLink(s);
    if (state != iso23725::LinkState::Up && m_everUp.count(link)) {
        // §2.1: while the link is down nothing about its machines is known.
        m_allStopIo[link] = AllStopState::Unknown;
        publishEvent(makeEvent(EventSeverity::Warning, ocu::EventKind::LinkLoss, {},
                               tr("ISO 23725 link %1 down: %2").arg(toQString(link), toQString(reason)),
                               QStringLiteral("iso23725")));
        std::vector<MachineState> rows;
        for (auto& [key, io] : m_machinesIo) {
            if (io.snapshot.link != link)
                continue;
            io.snapshot.stateKnown = false;
            io.row = rowOf(io, AllStopState::Unknown);
            rows.push_back(io.row);
            publishDispatch(io.row.id, toDispatchState(io.snapshot));
        }
        publishMachines(std::move(rows));
    }
}

const std::string& IsoBridge::keyOf(const std::string& link, const Guid& equipmentId) {
    m_key.assign(link);
    m_key += '/';
    m_key += equipmentId;
    return m_key;
}

// A full change (anything but a mere position): the slow path, which derives the whole row.
void IsoBridge::onMachineChanged(const IsoMachineSnapshot& machine) {
    auto [it, added] = m_machinesIo.try_emplace(keyOf(machine.link, machine.equipmentId));
    IoMachine& io = it->second;
    const std::optional<IsoPosition> lastGood = added ? std::nullopt : io.snapshot.position;
    // A full change carries the newest position again: judged once, unless it differs in any field (several
    // positions may arrive within one millisecond).
    auto same = [](const IsoPosition& a, const IsoPosition& b) {
        return a.latitude == b.latitude && a.longitude == b.longitude && a.elevation == b.elevation &&
               a.speedKmh == b.speedKmh && a.heading == b.heading && a.measuredUnixMs == b.measuredUnixMs &&
               a.receivedUnixMs == b.receivedUnixMs;
    };
    const bool newPosition = machine.position && (!lastGood || !same(*lastGood, *machine.position));
    io.snapshot = machine;
    io.snapshot.position = lastGood;
    if (newPosition && admitPosition(machine.link, it->first, io, *machine.position))
        io.snapshot.position = machine.position;
    io.row = rowOf(io, m_allStopIo.count(machine.link) ? m_allStopIo[machine.link] : AllStopState::Unknown);
    if (added) {
        std::lock_guard lock(m_machineLinksMutex);
        m_machineLinks.insert(io.row.id, toQString(machine.link));
    }
    publishMachine(io.row);
    publishDispatch(io.row.id, toDispatchState(machine));
}

// The hot path (every machine, 1-10 Hz): only the position fields of the rows change, and the batch goes to
// the GUI thread in one hand-over.
void IsoBridge::onMachinePositions(const std::string& link,
                                   const std::vector<const IsoMachineSnapshot*>& machines) {
    std::vector<MachineState> rows;
    rows.reserve(machines.size());
    for (const IsoMachineSnapshot* m : machines) {
        auto it = m_machinesIo.find(keyOf(link, m->equipmentId));
        if (it == m_machinesIo.end()) { // never seen whole (not expected from FmsCore): take it whole
            onMachineChanged(*m);
            continue;
        }
        if (!m->position)
            continue;
        IoMachine& io = it->second;
        const bool wasImplausible = !io.implausible.isEmpty();
        if (!admitPosition(link, it->first, io, *m->position)) {
            io.row = rowOf(io, m_allStopIo.count(link) ? m_allStopIo[link] : AllStopState::Unknown);
            rows.push_back(io.row);
            continue;
        }
        io.snapshot.position = m->position;
        if (wasImplausible) // the warning mark goes with the next good position
            io.row = rowOf(io, m_allStopIo.count(link) ? m_allStopIo[link] : AllStopState::Unknown);
        else
            setPosition(io.row, *m->position);
        rows.push_back(io.row);
    }
    if (!rows.empty())
        publishMachines(std::move(rows));
}

void IsoBridge::onMachineRemoved(const std::string& link, const Guid& equipmentId) {
    m_poseGate.forget(keyOf(link, equipmentId));
    m_machinesIo.erase(m_key);
    publishRemoval(protocolPrefix(Protocol::Iso23725) + toQString(equipmentId));
    publishDispatch(protocolPrefix(Protocol::Iso23725) + toQString(equipmentId), std::nullopt);
}

void IsoBridge::onAllStopChanged(const std::string& link, const AllStopStatus& status) {
    // A machine's row depends on the all-stop state only: a new request id or status of the same state (every
    // Apply, and the AHS's answer to it) leaves every row as it is, so the io thread does not rebuild and
    // publish the whole fleet then.
    const auto known = m_allStopIo.find(link);
    const AllStopState before = known != m_allStopIo.end() ? known->second : AllStopState::Unknown;
    m_allStopIo[link] = status.state;
    if (before != status.state) {
        std::vector<MachineState> rows;
        for (auto& [key, io] : m_machinesIo)
            if (io.snapshot.link == link) {
                io.row = rowOf(io, status.state);
                rows.push_back(io.row);
            }
        publishMachines(std::move(rows));
    }
    const QString l = toQString(link);
    const int st = static_cast<int>(status.state);
    QMetaObject::invokeMethod(
        this,
        [this, l, st] {
            m_allStop.insert(l, st);
            if (static_cast<AllStopState>(st) == AllStopState::On) // MachineAllStopV1 from the AHS
                emit stopReported(toQString(IsoStack::linkTarget(l.toStdString())),
                                  tr("AHS %1 reports all-stop active").arg(l));
            else if (static_cast<AllStopState>(st) == AllStopState::Off) // the release, confirmed by the AHS
                for (const char* action : {"clear_stop", "all_stop_remove"})
                    emit commandReported(QString::fromLatin1(action),
                                         toQString(IsoStack::linkTarget(l.toStdString())),
                                         tr("AHS %1 reports all-stop inactive").arg(l));
        },
        Qt::QueuedConnection);
    publishEvent(makeEvent(status.state == AllStopState::On ? EventSeverity::Alarm : EventSeverity::Info,
                           ocu::EventKind::Info, {},
                           tr("AHS %1 reports all-stop %2%3")
                               .arg(l, QString::fromUtf8(nameFor(status.state)),
                                    status.external ? tr(" (issued by another system)") : QString()),
                           QStringLiteral("iso23725")));
}

void IsoBridge::onMapProgress(const std::string& link, const MapProgress& progress) {
    const QString l = toQString(link);
    const int r = progress.received, t = progress.total;
    QMetaObject::invokeMethod(
        this, [this, l, r, t] { emit mapProgress(l, r, t); }, Qt::QueuedConnection);
}

void IsoBridge::onMapChanged(const std::string& link, const MapModel& map) {
    // Nodes are re-projected into the site frame through their WGS84 coordinates: the map's own ENU
    // origin (its centroid) is not the site origin.
    SiteMapData data;
    data.features.reserve(static_cast<qsizetype>(map.ways.size()));
    for (const auto& [id, way] : map.ways) {
        MapFeature f;
        f.id = QStringLiteral("%1/%2").arg(toQString(link)).arg(id);
        f.name = toQString(way.name());
        f.kind = way.kind == WayKind::Area   ? MapFeatureKind::Area
                 : way.kind == WayKind::Lane ? MapFeatureKind::Lane
                                             : MapFeatureKind::Road;
        f.defaultTask = toQString(way.defaultTask());
        if (f.defaultTask.isEmpty() && f.kind != MapFeatureKind::Area)
            f.defaultTask = QStringLiteral("haul");
        const std::string autonomy = way.tag(f.kind == MapFeatureKind::Area ? "autonomy:area" : "autonomy");
        f.autonomous =
            autonomy == "yes" || autonomy == "true" || (autonomy.empty() && way.tag("autonomy") == "yes");
        const std::string width = way.tag("width");
        if (!width.empty())
            f.width = std::atof(width.c_str());
        if (f.width <= 0 && f.kind != MapFeatureKind::Area)
            f.width =
                f.kind == MapFeatureKind::Lane ? 10.0 : 20.0; // untagged: typical haul road / lane widths
        for (std::int64_t nid : way.nodes) {
            auto it = map.nodes.find(nid);
            if (it == map.nodes.end())
                continue;
            const EnuPoint p = m_frame.toLocal({it->second.lat, it->second.lon, it->second.ele.value_or(0)});
            f.points.push_back(QPointF(p.e, p.n));
        }
        if (!f.points.isEmpty())
            data.features.push_back(std::move(f));
    }
    QMetaObject::invokeMethod(
        this,
        [this, data = std::move(data)]() mutable {
            data.revision = m_map.revision + 1;
            m_map = std::move(data);
            emit siteMapChanged();
        },
        Qt::QueuedConnection);
}

void IsoBridge::onFleetDiscrepancies(const std::string& link,
                                     const std::vector<iso23725::FleetDiscrepancy>& items) {
    // One alarm per cause and link, the machines in its details.
    for (const FleetEvent& ev : fleetDiscrepancyAlarms(link, items))
        publishEvent(ev);
}

void IsoBridge::onConnectivity(const std::string& link, const MapConnectivityV1& connectivity) {
    QHash<qint64, IsoDestination> areas;
    for (const auto& item : connectivity.items)
        if (item.wayType == "Area")
            areas.insert(item.wayId,
                         IsoDestination{toQString(link), item.wayId, toQString(item.areaName.value_or("")),
                                        toQString(item.areaDefaultTask.value_or(""))});
    const QString l = toQString(link);
    auto graph = std::make_shared<const RouteGraph>(connectivity); // indexed here, off the GUI thread
    QMetaObject::invokeMethod(
        this,
        [this, l, areas = std::move(areas), graph = std::move(graph)]() mutable {
            m_destinations.insert(l, std::move(areas));
            m_routeGraphs.insert(l, std::move(graph));
            emit destinationsChanged(l);
            QStringList ids;
            for (auto& d : m_dispatch)
                if (d.link == l) {
                    const auto a = d.destinationId ? m_destinations[l].constFind(*d.destinationId)
                                                   : m_destinations[l].constEnd();
                    d.destinationName = a != m_destinations[l].constEnd() ? a->name : QString();
                    ids << d.id;
                }
            if (!ids.isEmpty())
                emit dispatchChanged(ids);
        },
        Qt::QueuedConnection);
}

void IsoBridge::publishDispatch(const QString& id, std::optional<IsoDispatchState> state) {
    std::lock_guard lock(m_dispatchMutex);
    m_dispatchPending.insert(id, std::move(state));
    if (m_dispatchScheduled)
        return;
    m_dispatchScheduled = true;
    QMetaObject::invokeMethod(
        this, [this] { deliverDispatch(); }, Qt::QueuedConnection);
}

void IsoBridge::deliverDispatch() {
    QHash<QString, std::optional<IsoDispatchState>> batch;
    {
        std::lock_guard lock(m_dispatchMutex);
        batch.swap(m_dispatchPending);
        m_dispatchScheduled = false;
    }
    QStringList ids;
    for (auto it = batch.begin(); it != batch.end(); ++it) {
        ids << it.key();
        if (!it.value()) {
            m_dispatch.remove(it.key());
            continue;
        }
        IsoDispatchState d = std::move(*it.value());
        const auto& areas = m_destinations.value(d.link);
        if (d.destinationId)
            d.destinationName = areas.value(*d.destinationId).name;
        m_dispatch.insert(it.key(), std::move(d));
    }
    if (!ids.isEmpty())
        emit dispatchChanged(ids);
}

// ---- GUI thread: dispatch ----

QVector<IsoDispatchState> IsoBridge::dispatchStates() const {
    QVector<IsoDispatchState> out;
    out.reserve(m_dispatch.size());
    for (const auto& d : m_dispatch)
        out << d;
    std::sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.id < b.id; });
    return out;
}

std::optional<IsoDispatchState> IsoBridge::dispatchState(const QString& id) const {
    auto it = m_dispatch.constFind(id);
    if (it == m_dispatch.constEnd())
        return std::nullopt;
    return *it;
}

QVector<IsoDestination> IsoBridge::destinations(const QString& link) const {
    QVector<IsoDestination> out;
    for (auto l = m_destinations.constBegin(); l != m_destinations.constEnd(); ++l)
        if (link.isEmpty() || l.key() == link)
            for (const auto& d : l.value())
                out << d;
    std::sort(out.begin(), out.end(),
              [](auto& a, auto& b) { return a.link != b.link ? a.link < b.link : a.wayId < b.wayId; });
    return out;
}

QString IsoBridge::assignRefusal(const QString& id) const {
    const QString link = linkOf(id);
    const auto d = dispatchState(id);
    if (link.isEmpty() || !d)
        return tr("unknown ISO 23725 machine %1").arg(id);
    if (const QString why = linkRefusal(link, tr("assignment")); !why.isEmpty())
        return why;
    if (d->custodian != QLatin1String("FMS"))
        return d->custodian.isEmpty()
                   ? tr("assignment refused: %1 has not reported its DispatchingCustodian yet").arg(d->name)
                   : tr("assignment refused: %1 is dispatched by the %2 (DispatchingCustodian %2)")
                         .arg(d->name, d->custodian);
    return {};
}

Assign IsoBridge::assignCommand(const QString& id, const QVector<IsoTask>& tasks) {
    return Assign{id, tasks};
}

QJsonArray IsoBridge::productionJson() const {
    QJsonArray out;
    for (const auto& d : dispatchStates())
        if (!d.custodian.isEmpty() || !d.assignmentStatus.isEmpty() || !d.productionState.isEmpty())
            out << dispatchToJson(d);
    return out;
}

void IsoBridge::onEvent(IsoSeverity severity, const std::string& text) {
    const EventSeverity s = severity == IsoSeverity::Error     ? EventSeverity::Alarm
                            : severity == IsoSeverity::Warning ? EventSeverity::Warning
                                                               : EventSeverity::Info;
    publishEvent(makeEvent(s, ocu::EventKind::Info, {}, toQString(text), QStringLiteral("iso23725")));
}

static ModeCategory modeCategory(const std::string& mode) {
    QString m = QString::fromStdString(mode).toLower();
    if (m.isEmpty())
        return ModeCategory::Unknown;
    if (m.contains(QLatin1String("auto")))
        return ModeCategory::Autonomous;
    if (m.contains(QLatin1String("manual")))
        return ModeCategory::Manual;
    if (m.contains(QLatin1String("remote")) || m.contains(QLatin1String("tele")))
        return ModeCategory::Remote;
    if (m.contains(QLatin1String("stop")))
        return ModeCategory::Stopped;
    if (m.contains(QLatin1String("fault")) || m.contains(QLatin1String("error")))
        return ModeCategory::Fault;
    if (m.contains(QLatin1String("idle")) || m.contains(QLatin1String("park")))
        return ModeCategory::Idle;
    return ModeCategory::Transition;
}

QString isoWorkText(const IsoMachineSnapshot& s) {
    QStringList parts;
    if (s.production) {
        const auto& p = *s.production;
        parts << (p.wayId ? IsoBridge::tr("%1 on way %2").arg(toQString(p.productionState)).arg(*p.wayId)
                          : toQString(p.productionState));
    }
    if (s.payload && s.payload->payloadWeight) // null = unavailable, never shown as 0 t
        parts << IsoBridge::tr("payload %1 t").arg(*s.payload->payloadWeight);
    if (s.sensor) {
        const auto& x = *s.sensor;
        if (x.loaded)
            parts << (*x.loaded ? IsoBridge::tr("loaded") : IsoBridge::tr("empty"));
        if (x.bodyRaised && *x.bodyRaised)
            parts << IsoBridge::tr("body raised");
        if (x.parkBrake && *x.parkBrake)
            parts << IsoBridge::tr("park brake on");
    }
    if (s.assignment) {
        const auto& a = *s.assignment;
        QString text = IsoBridge::tr("assignment %1").arg(toQString(a.status));
        if (a.task && a.destinationId)
            text += IsoBridge::tr(" (%1 at way %2)").arg(toQString(*a.task)).arg(*a.destinationId);
        parts << text;
    }
    if (s.lastDump)
        parts << (s.lastDump->dumpedWeight ? IsoBridge::tr("last dump %1 t at way %2")
                                                 .arg(*s.lastDump->dumpedWeight)
                                                 .arg(s.lastDump->wayId)
                                           : IsoBridge::tr("last dump at way %1").arg(s.lastDump->wayId));
    return parts.join(QStringLiteral(" · "));
}

MachineState IsoBridge::toMachine(const IsoMachineSnapshot& s, AllStopState stop) const {
    MachineState m;
    m.id = protocolPrefix(Protocol::Iso23725) + toQString(s.equipmentId);
    m.protocol = Protocol::Iso23725;
    m.name = s.hid.empty() ? toQString(s.equipmentId).left(8) : toQString(s.hid);
    m.type = toQString(s.type);
    m.link = s.stateKnown ? ocu::LinkState::Up : ocu::LinkState::Unknown;
    if (s.position)
        setPosition(m, *s.position);
    m.length = s.length.value_or(0);
    m.width = s.width.value_or(0);
    const QString type = m.type.toLower();
    if (type.contains(QLatin1String("truck"))) {
        m.length = m.length > 0 ? m.length : 12.0;
        m.width = m.width > 0 ? m.width : 7.0;
        m.height = 6.5;
    } else if (type.contains(QLatin1String("shovel")) || type.contains(QLatin1String("excavator"))) {
        m.length = m.length > 0 ? m.length : 15.0;
        m.width = m.width > 0 ? m.width : 8.0;
        m.height = 9.0;
    } else {
        m.length = m.length > 0 ? m.length : 5.0;
        m.width = m.width > 0 ? m.width : 2.2;
        m.height = 2.2;
    }
    m.workText = isoWorkText(s);
    m.modeText = toQString(s.autonomyMode);
    m.mode = s.stateKnown ? modeCategory(s.autonomyMode) : ModeCategory::Unknown;
    if (!s.stateKnown || !s.autonomous) {
        m.stop = s.autonomous ? StopState::Unknown : StopState::None;
    } else {
        m.stop = stop == AllStopState::On    ? StopState::Stopped
                 : stop == AllStopState::Off ? StopState::None
                                             : StopState::Unknown;
        if (m.stop == StopState::Stopped)
            m.stopText = tr("all-stop");
    }
    if (s.diagnostics) {
        m.health = s.diagnostics->empty() ? HealthLevel::Ok : HealthLevel::Warning;
        QStringList codes;
        for (const auto& d : *s.diagnostics)
            codes << QStringLiteral("%1:%2").arg(d.componentId).arg(d.faultCode);
        m.healthText = codes.isEmpty() ? tr("no active diagnostics")
                                       : tr("diagnostics %1").arg(codes.join(QLatin1Char(' ')));
    } else if (s.health) {
        m.health = HealthLevel::Ok;
    }
    if (s.health && s.health->fuelLevel && *s.health->fuelLevel < 10) {
        m.health = std::max(m.health, HealthLevel::Warning);
        m.healthText += (m.healthText.isEmpty() ? QString() : QStringLiteral("; ")) +
                        tr("fuel %1 %").arg(*s.health->fuelLevel);
    }
    return m;
}

MachineState IsoBridge::rowOf(const IoMachine& io, AllStopState stop) const {
    MachineState m = toMachine(io.snapshot, stop);
    if (!io.implausible.isEmpty()) {
        m.health = std::max(m.health, HealthLevel::Warning);
        m.healthText =
            io.implausible + (m.healthText.isEmpty() ? QString() : QStringLiteral("; ") + m.healthText);
    }
    return m;
}

bool IsoBridge::admitPosition(const std::string& link, const std::string& key, IoMachine& io,
                              const IsoPosition& p) {
    const EnuPoint e = m_frame.toLocal({p.latitude, p.longitude, p.elevation.value_or(m_frame.origin().alt)});
    std::optional<double> speed;
    if (p.speedKmh)
        speed = *p.speedKmh / 3.6;
    // Latitudes and longitudes beyond the globe are as far outside the site as it gets (GeographicLib would
    // answer NaN for them); a NaN stays NaN.
    const double lat = p.latitude, lon = p.longitude;
    const bool onGlobe = !(std::abs(lat) > 90) && !(std::abs(lon) > 180);
    const PoseGate::Verdict v =
        m_poseGate.check(key, onGlobe ? e.e : 1e300, e.n, e.u, speed, SteadyClock::instance().now());
    if (v.ok()) {
        io.implausible.clear();
        return true;
    }
    const char* cause = nameFor(v.fault);
    if (Counters* c = m_stack->linkCounters(link))
        c->add(std::string("rx.implausible.") + cause);
    const QString why = toQString(describe(v.fault, m_poseGate.limits()));
    io.implausible = tr("implausible position ignored (%1 so far): %2").arg(v.peerCount).arg(why);
    if (v.warn) {
        const QString id = protocolPrefix(Protocol::Iso23725) + toQString(io.snapshot.equipmentId);
        publishEvent(
            makeEvent(EventSeverity::Warning, ocu::EventKind::Diagnostic, id,
                      tr("ISO 23725 link %1, machine %2: position ignored, %3 (lat %4, lon %5, speed "
                         "%6 km/h); last good position kept (counted in rx.implausible.%7; one "
                         "warning per machine and cause every 30 s)")
                          .arg(toQString(link), id, why)
                          .arg(lat, 0, 'g', 10)
                          .arg(lon, 0, 'g', 10)
                          .arg(p.speedKmh.value_or(0))
                          .arg(QLatin1String(cause)),
                      QStringLiteral("iso23725")));
    }
    return false;
}

void IsoBridge::setPosition(MachineState& m, const IsoPosition& p) const {
    const GeoPoint g{p.latitude, p.longitude, p.elevation.value_or(m_frame.origin().alt)};
    placeAt(m, m_frame.toLocal(g), g);
    m.headingDeg = p.heading.value_or(0);
    m.speed = p.speedKmh.value_or(0) / 3.6;
    m.lastDataMs = modelTimeOfWallMs(p.receivedUnixMs);
    m.lastMessageMs = p.measuredUnixMs.value_or(0);
}

std::chrono::milliseconds IsoBridge::ioStalledFor() const {
    return m_stack ? m_stack->ioStalledFor() : std::chrono::milliseconds(0);
}

void IsoBridge::postToIo(std::function<void()> f) {
    if (m_stack)
        m_stack->postToIo(std::move(f));
}

QVector<LinkCounters> IsoBridge::linkCounters() const {
    QVector<LinkCounters> out;
    for (const auto& l : m_config.links)
        if (const Counters* c = m_stack->linkCounters(l.name))
            out.push_back(LinkCounters::of(QStringLiteral("iso23725:") + toQString(l.name), *c));
    return out;
}

} // namespace ocu
