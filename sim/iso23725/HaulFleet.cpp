#include "sim/iso23725/HaulFleet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ocu::sim {

using namespace ocu::iso23725;

namespace {

constexpr double kLoadingSeconds = 30;
constexpr double kDumpingSeconds = 15;
constexpr double kParkedSeconds = 60;
constexpr double kHealthPeriodSeconds = 30;
constexpr double kBrakeDecel = 2.0;    // m/s², ordinary stop
constexpr double kAllStopDecel = 3.0;  // m/s², all-stop
constexpr double kLoadedSpeed = 0.75;  // of the cruise speed
constexpr double kSpottingSpeed = 2.5; // m/s, creeping from the area entry to the spot

// Stable GUIDs from a seed and an index (v4 layout): kind 1 = trucks, 2 = shovels.
Guid stableGuid(std::uint32_t seed, std::uint32_t kind, std::uint32_t index) {
    std::mt19937_64 r((static_cast<std::uint64_t>(seed) << 32) ^ (static_cast<std::uint64_t>(kind) << 20) ^
                      index);
    std::uint64_t a = r(), b = r();
    char buf[48];
    std::snprintf(buf, sizeof buf, "%08x-%04x-4%03x-%04x-%012llx", unsigned(a >> 32),
                  unsigned((a >> 16) & 0xffff), unsigned(a & 0xfff), unsigned(0x8000 | ((b >> 48) & 0x3fff)),
                  static_cast<unsigned long long>(b & 0xffffffffffffULL));
    return buf;
}

} // namespace

HaulFleet::HaulFleet(const PitMap& map, HaulFleetConfig config, Counters& counters, Emit emit, UnixClock now)
    : m_map(map), m_cfg(config), m_counters(counters), m_emit(std::move(emit)), m_now(std::move(now)),
      m_frame(map.map.origin), m_rng(config.seed), m_connectivity(map.connectivity),
      m_routes(map.connectivity) {
    std::uniform_real_distribution<double> u(0, 1);
    const int shovels = static_cast<int>(m_map.loadAreas.size());
    const int dumps = static_cast<int>(m_map.dumpAreas.size());
    for (int i = 0; i < m_cfg.truckCount; ++i) {
        HaulTruck t;
        t.id = stableGuid(m_cfg.seed, 1, static_cast<std::uint32_t>(i));
        char hid[16];
        std::snprintf(hid, sizeof hid, "HT%03d", 101 + i);
        t.hid = hid;
        t.shovel = i % shovels;
        t.dump = i % dumps;
        t.cruise = 9.0 + 3.0 * u(m_rng);
        t.fuel = 40 + 60 * u(m_rng);
        t.nextHealth = 5 + 25 * u(m_rng);
        // Spread the fleet over the cycle so the site looks busy from the start.
        int start = static_cast<int>(u(m_rng) * 3);
        if (start == 0) {
            t.payload = 0;
            startRoute(t,
                       {{m_map.dumpRoads[t.dump], true},
                        {m_map.rampDown, false},
                        {m_map.loadRoads[t.shovel], false}},
                       HaulPhase::ToLoad);
        } else if (start == 1) {
            t.payload = 220 + static_cast<int>(u(m_rng) * 80);
            startRoute(
                t,
                {{m_map.loadRoads[t.shovel], true}, {m_map.rampUp, false}, {m_map.dumpRoads[t.dump], false}},
                HaulPhase::ToDump);
        } else {
            startRoute(t,
                       {{m_map.parkRoad, true}, {m_map.rampDown, false}, {m_map.loadRoads[t.shovel], false}},
                       HaulPhase::ToLoad);
        }
        t.motion.placeAt(u(m_rng) * t.motion.route().length() * 0.9);
        t.cycleId = newGuid();
        t.cycleStartMs = m_now();
        t.sensorSent = sensor(t); // the starting inputs: only changes are sent from here on
        m_trucks.push_back(std::move(t));
    }
}

HaulTruck* HaulFleet::truck(const Guid& id) {
    for (auto& t : m_trucks)
        if (t.id == id)
            return &t;
    return nullptr;
}

std::vector<Equipment> HaulFleet::equipment() const {
    std::vector<Equipment> out;
    for (auto& t : m_trucks)
        out.push_back(Equipment{t.id, t.hid, "HaulTruck", "Komatsu", "930E", true, 15.6, 9.1});
    return out;
}

std::string HaulFleet::autonomyMode(const HaulTruck& t) const {
    if (t.manual)
        return "Manual";
    return m_allStopOn ? "AllStop" : "Autonomous";
}

void HaulFleet::emitProduction(HaulTruck& t) {
    t.reportedWay = t.motion.wayId();
    m_emit(productionState(t), t.id);
}

HaulTruckProductionStateV2 HaulFleet::productionState(const HaulTruck& t) const {
    HaulTruckProductionStateV2 p;
    if (!t.assignments.empty())
        p.assignmentId = t.assignments.front().assignmentId;
    p.wayId = t.motion.wayId();
    p.autonomyMode = autonomyMode(t);
    p.productionState = t.productionState;
    return p;
}

MachinePositionV1 HaulFleet::position(const HaulTruck& t) const {
    MachinePositionV1 p;
    p.timestamp = makeTimestamp(m_now());
    auto g = m_frame.toGeodetic(t.motion.position());
    p.pose.latitude = std::round(g.lat * 1e7) / 1e7;
    p.pose.longitude = std::round(g.lon * 1e7) / 1e7;
    p.pose.elevation = std::round(g.alt * 100) / 100;
    p.pose.heading = static_cast<std::int64_t>(std::lround(t.motion.headingDeg())) % 360;
    p.pose.speed = std::lround(t.motion.speed() * 3.6);
    p.pose.latitudeAccuracy = 0.05;
    p.pose.longitudeAccuracy = 0.05;
    p.pose.elevationAccuracy = 0.1;
    p.pose.headingAccuracy = 0.5;
    return p;
}

// ---------------------------------------------------------------- haul cycle

void HaulFleet::startRoute(HaulTruck& t, const std::vector<RouteLeg>& legs, HaulPhase phase) {
    t.motion.setRoute(m_map.route(legs));
    t.phase = phase;
    t.area = phase == HaulPhase::ToLoad   ? m_map.loadAreas[t.shovel]
             : phase == HaulPhase::ToDump ? m_map.dumpAreas[t.dump]
                                          : m_map.parkArea;
    changeState(t, phase == HaulPhase::ToDump ? "Hauling" : "Driving");
}

namespace {

double dist2(const EnuPoint& a, const EnuPoint& b) {
    return (a.e - b.e) * (a.e - b.e) + (a.n - b.n) * (a.n - b.n);
}

EnuPoint centroid(const std::vector<EnuPoint>& pts) {
    EnuPoint c{0, 0, 0};
    // A closed way repeats its first node: count it once.
    const std::size_t n =
        pts.size() > 1 && dist2(pts.front(), pts.back()) < 1e-6 ? pts.size() - 1 : pts.size();
    for (std::size_t i = 0; i < n; ++i) {
        c.e += pts[i].e / static_cast<double>(n);
        c.n += pts[i].n / static_cast<double>(n);
        c.u += pts[i].u / static_cast<double>(n);
    }
    return c;
}

} // namespace

EnuPoint HaulFleet::spotOf(const HaulTruck& t, std::int64_t area) const {
    EnuPoint c = centroid(m_map.wayPoints(area, false));
    if (area == m_map.parkArea) { // a row of parking slots, 14 m apart
        const auto index = static_cast<int>(&t - m_trucks.data());
        c.e += 14.0 * (index % 5 - 2);
        c.n += 16.0 * ((index / 5) % 4 - 1.5);
    }
    return c;
}

Route HaulFleet::routeAlong(const HaulTruck& t, const std::vector<std::int64_t>& ways) const {
    Route r;
    EnuPoint last = t.motion.position();
    auto isArea = [&](std::int64_t w) {
        auto it = m_map.map.ways.find(w);
        return it == m_map.map.ways.end() || it->second.kind == iso23725::WayKind::Area;
    };
    // Where a way can be joined: its two ends (a road), or its centre (an area).
    auto ends = [&](std::int64_t w) {
        auto pts = m_map.wayPoints(w, false);
        return isArea(w) ? std::vector<EnuPoint>{centroid(pts)}
                         : std::vector<EnuPoint>{pts.front(), pts.back()};
    };
    for (std::size_t i = 0; i < ways.size(); ++i) {
        const std::int64_t w = std::llabs(ways[i]);
        if (!m_map.map.ways.count(w))
            continue;
        if (isArea(w)) {
            if (i == 0)
                r.addLeg(w, {last}); // leaving the area it is in, from where it stands
            else if (w == m_map.parkArea && i + 1 == ways.size())
                r.addLeg(w, {spotOf(t, w)}); // on into its parking slot
            continue;                        // a load or dump area is entered by spotting (queues first)
        }
        auto pts = m_map.wayPoints(w, false);
        bool reversed;
        if (m_map.map.ways.at(w).kind == iso23725::WayKind::Lane)
            reversed = ways[i] < 0; // one-way: node order is the travel direction (Q6: negative = against it)
        else if (i + 1 < ways.size()) {
            // Leave it at the end nearest the next way.
            double dFront = 1e300, dBack = 1e300;
            for (const auto& p : ends(std::llabs(ways[i + 1]))) {
                dFront = std::min(dFront, dist2(pts.front(), p));
                dBack = std::min(dBack, dist2(pts.back(), p));
            }
            reversed = dFront < dBack;
        } else {
            reversed = dist2(pts.back(), last) < dist2(pts.front(), last);
        }
        if (reversed)
            std::reverse(pts.begin(), pts.end());
        if (i == 0 && pts.size() >= 2) {
            // On this way already: from the truck's position (its nearest stretch) onwards.
            std::size_t best = 0;
            double bestD = 1e300;
            for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
                const auto& a = pts[k];
                const auto& b = pts[k + 1];
                const double len2 = dist2(a, b);
                double f =
                    len2 > 0 ? ((last.e - a.e) * (b.e - a.e) + (last.n - a.n) * (b.n - a.n)) / len2 : 0;
                f = std::clamp(f, 0.0, 1.0);
                const EnuPoint q{a.e + f * (b.e - a.e), a.n + f * (b.n - a.n), a.u + f * (b.u - a.u)};
                if (dist2(q, last) < bestD) {
                    bestD = dist2(q, last);
                    best = k;
                }
            }
            std::vector<EnuPoint> rest{last};
            rest.insert(rest.end(), pts.begin() + static_cast<std::ptrdiff_t>(best) + 1, pts.end());
            pts = std::move(rest);
        }
        r.addLeg(w, pts);
        last = pts.back();
    }
    return r;
}

bool HaulFleet::driveTo(HaulTruck& t, std::int64_t area, const std::optional<std::vector<WayRef>>& route) {
    const std::int64_t from = t.motion.wayId();
    std::vector<std::int64_t> ways;
    if (route) {
        // RouteV1 (§5 #21): the ways between the truck and the destination; the part already behind the truck
        // does not count.
        std::vector<WayRef> ahead = *route;
        for (std::size_t i = 0; i < route->size(); ++i)
            if (std::llabs((*route)[i].wayId) == from)
                ahead.assign(route->begin() + static_cast<std::ptrdiff_t>(i), route->end());
        if (checkRoute(m_routes, from, ahead, area).empty()) {
            ways.push_back(from);
            for (const auto& w : ahead)
                if (std::llabs(w.wayId) != from)
                    ways.push_back(w.wayId);
            ways.push_back(area);
            m_counters.add("sim.route.assigned");
        }
    }
    if (ways.empty()) {
        auto r = shortestRoute(m_routes, from, area);
        if (!r.ok)
            return false;
        ways = r.ways;
    }
    if (t.phase == HaulPhase::Queued)
        releaseArea(t);
    const int li = m_map.loadIndex(area), di = m_map.dumpIndex(area);
    if (li >= 0)
        t.shovel = li;
    if (di >= 0)
        t.dump = di;
    t.phase = li >= 0 ? HaulPhase::ToLoad : di >= 0 ? HaulPhase::ToDump : HaulPhase::ToPark;
    t.area = area;
    t.motion.setRoute(routeAlong(t, ways));
    t.motion.placeAt(0);
    changeState(t, t.payload > 0 ? "Hauling" : "Driving");
    emitProduction(t);
    return true;
}

void HaulFleet::tick(double dt) {
    m_simTime += dt;
    for (auto& t : m_trucks) {
        const bool halted = (m_allStopOn && t.autonomous) || t.manual;
        if (t.phase == HaulPhase::ToLoad || t.phase == HaulPhase::ToDump || t.phase == HaulPhase::ToPark ||
            t.phase == HaulPhase::Spotting) {
            const double speed = t.phase == HaulPhase::Spotting
                                     ? kSpottingSpeed
                                     : t.cruise * (t.payload > 0 ? kLoadedSpeed : 1.0);
            t.motion.drive(dt, halted ? 0.0 : speed, m_allStopOn ? kAllStopDecel : kBrakeDecel);
            const std::string moving = t.phase == HaulPhase::Spotting ? "Spotting"
                                       : t.phase == HaulPhase::ToDump ? "Hauling"
                                                                      : "Driving";
            if (halted && t.motion.speed() == 0 && m_allStopOn)
                setProduction(t, "Stopped");
            else if (!halted && t.productionState == "Stopped")
                setProduction(t, moving);
            if (t.motion.arrived()) {
                t.motion.halt();
                arrive(t);
            } else if (t.motion.wayId() != t.reportedWay) {
                // WayId is part of the production state (§5 #17, "current way"): a new way is a change.
                emitProduction(t);
            }
        } else if (!halted && !t.idle && t.phase != HaulPhase::Queued) {
            t.dwell -= dt;
            if (t.dwell <= 0)
                leave(t);
        }
        updateSensor(t);
        if (m_cfg.healthEvents) {
            t.fuel = std::max(5.0, t.fuel - dt * 0.002);
            t.engineHours += dt / 3600.0;
            if (m_simTime >= t.nextHealth)
                reportHealth(t);
        }
    }
}

void HaulFleet::reachArea(HaulTruck& t) {
    auto& q = m_areaQueues[t.area];
    const int index = static_cast<int>(&t - m_trucks.data());
    if (q.inside < 0) {
        q.inside = index;
        startSpotting(t);
        return;
    }
    q.waiting.push_back(index);
    t.phase = HaulPhase::Queued;
    setProduction(t, "Queued");
}

void HaulFleet::startSpotting(HaulTruck& t) {
    Route r;
    r.addLeg(t.area, {t.motion.position(), spotOf(t, t.area)});
    t.motion.setRoute(std::move(r));
    t.motion.placeAt(0);
    t.phase = HaulPhase::Spotting;
    setProduction(t, "Spotting");
}

void HaulFleet::releaseArea(HaulTruck& t) {
    auto it = m_areaQueues.find(t.area);
    if (it == m_areaQueues.end())
        return;
    auto& q = it->second;
    const int index = static_cast<int>(&t - m_trucks.data());
    std::erase(q.waiting, index);
    if (q.inside != index)
        return;
    q.inside = -1;
    if (q.waiting.empty())
        return;
    q.inside = q.waiting.front();
    q.waiting.erase(q.waiting.begin());
    startSpotting(m_trucks[static_cast<std::size_t>(q.inside)]);
}

void HaulFleet::arrive(HaulTruck& t) {
    if (t.phase == HaulPhase::ToLoad || t.phase == HaulPhase::ToDump) {
        reachArea(t);
    } else if (t.phase == HaulPhase::Spotting) {
        const bool load = m_map.loadIndex(t.area) >= 0;
        t.phase = load ? HaulPhase::Loading : HaulPhase::Dumping;
        t.dwell = load ? kLoadingSeconds : kDumpingSeconds;
        setProduction(t, load ? "Loading" : "Dumping");
    } else {
        t.phase = HaulPhase::Parked;
        t.dwell = kParkedSeconds;
        setProduction(t, "Parked");
        if (t.custodian == "AHS" && !t.fmsWork && t.idle) {
            // Parked out of the way: the AHS hands the truck back and so asks for work (§8.3.4).
            setCustodian(t, "FMS");
        }
    }
}

std::int64_t HaulFleet::areaOf(const HaulTruck& t) const {
    if (t.phase == HaulPhase::Loading)
        return m_map.loadAreas[t.shovel];
    if (t.phase == HaulPhase::Dumping)
        return m_map.dumpAreas[t.dump];
    return m_map.parkArea;
}

void HaulFleet::leave(HaulTruck& t) {
    std::uniform_real_distribution<double> u(0, 1);
    if (t.phase == HaulPhase::Loading) {
        t.payload = 220 + static_cast<int>(u(m_rng) * 80);
        HaulTruckPayloadV1 p;
        p.payloadWeight = t.payload;
        p.accuracy = 4.5;
        p.payloadSourceId = stableGuid(m_cfg.seed, 2, static_cast<std::uint32_t>(t.shovel));
        m_emit(p, t.id);
    } else if (t.phase == HaulPhase::Dumping && t.payload > 0) { // an empty truck has nothing to dump
        HaulTruckDumpV1 d;
        if (!t.assignments.empty())
            d.assignmentId = t.assignments.front().assignmentId;
        d.wayId = m_map.dumpAreas[t.dump];
        d.dumpedWeight = t.payload;
        m_emit(d, t.id);
        HaulTruckProductionCycleV1 c;
        c.cycleId = t.cycleId;
        if (!t.assignments.empty())
            c.assignmentId = t.assignments.front().assignmentId;
        c.loadWayId = m_map.loadAreas[t.shovel];
        c.dumpWayId = m_map.dumpAreas[t.dump];
        c.loaderEquipmentId = stableGuid(m_cfg.seed, 2, static_cast<std::uint32_t>(t.shovel));
        c.payloadWeight = t.payload;
        changeState(t, {}); // closes the Dumping entry
        c.stateTimes = std::move(t.cycleStates);
        t.cycleStates.clear();
        m_emit(c, t.id);
        t.cycleId = newGuid();
        t.cycleStartMs = m_now();
        t.payload = 0;
    }
    // An assignment whose destination is reached is completed.
    if (!t.assignments.empty() && t.assignments.front().destinationId == areaOf(t) &&
        t.phase != HaulPhase::Parked) {
        const auto& done = t.assignments.front();
        m_emit(HaulTruckAssignmentV1{done.assignmentId, "Completed", done.task, done.destinationId}, t.id);
        t.assignments.erase(t.assignments.begin());
        if (!t.assignments.empty()) {
            const auto& next = t.assignments.front();
            m_emit(HaulTruckAssignmentV1{next.assignmentId, "Active", next.task, next.destinationId}, t.id);
        }
    }
    if (t.phase == HaulPhase::Loading || t.phase == HaulPhase::Dumping)
        releaseArea(t);
    if (t.assignments.empty() && t.fmsWork) {
        goIdle(t);
        return;
    }
    std::int64_t dest;
    std::optional<std::vector<WayRef>> route;
    if (!t.assignments.empty()) {
        dest = t.assignments.front().destinationId;
        route = t.assignments.front().route;
    } else if (t.phase == HaulPhase::Loading) {
        dest = m_map.dumpAreas[t.dump];
    } else {
        dest = m_map.loadAreas[t.shovel];
    }
    if (dest == areaOf(t) && t.phase == HaulPhase::Loading) { // already there: load again
        m_areaQueues[dest].inside = static_cast<int>(&t - m_trucks.data());
        t.dwell = kLoadingSeconds;
        return;
    }
    if (!driveTo(t, dest, route)) {
        // Cannot get there any more (a way closed meanwhile): give the task up and ask for other work.
        if (!t.assignments.empty()) {
            HaulTruckAssignmentResponseV1 lost;
            for (const auto& a : t.assignments)
                lost.items.push_back(AssignmentResponseItem{
                    a.assignmentId, "Rejected", "can no longer be done: destination unreachable"});
            m_emit(lost, t.id);
            const auto& a = t.assignments.front();
            m_emit(HaulTruckAssignmentV1{a.assignmentId, "Cancelled", a.task, a.destinationId}, t.id);
            t.assignments.clear();
        }
        if (t.fmsWork) {
            goIdle(t);
        } else if (!driveTo(t, m_map.parkArea, std::nullopt)) {
            t.phase = HaulPhase::Parked;
            setProduction(t, "Parked");
        }
    }
}

void HaulFleet::changeState(HaulTruck& t, const std::string& state) {
    const std::int64_t now = m_now();
    if (!t.cycleStates.empty() && !t.cycleStates.back().duration) {
        auto& open = t.cycleStates.back();
        open.duration = std::round(static_cast<double>(now - open.start.unixMs.value_or(now)) / 100.0) / 10.0;
    }
    if (!state.empty()) {
        t.cycleStates.push_back(StateTime{state, makeTimestamp(now), std::nullopt});
        t.productionState = state;
    }
}

void HaulFleet::setProduction(HaulTruck& t, const std::string& state) {
    if (t.productionState == state)
        return;
    changeState(t, state);
    emitProduction(t);
}

// HaulTruckProductionStateSensorV1 (§5 row 18, Q8 [I]): the raw inputs of the production state. Loaded from
// the end of loading to the end of dumping (the payload is on board), body raised while dumping, park brake
// when parked or held at rest (all-stop, manual), in the load/dump area while loading/dumping (a truck is
// only inside an area for those phases here).
HaulTruckProductionStateSensorV1 HaulFleet::sensor(const HaulTruck& t) const {
    const bool halted = (m_allStopOn && t.autonomous) || t.manual;
    HaulTruckProductionStateSensorV1 v;
    v.loaded = t.payload > 0;
    v.bodyRaised = t.phase == HaulPhase::Dumping;
    v.parkBrake = t.phase == HaulPhase::Parked || (halted && t.motion.speed() == 0);
    v.payloadWeight = t.payload;
    v.inLoadArea = t.phase == HaulPhase::Loading;
    v.inDumpArea = t.phase == HaulPhase::Dumping;
    return v;
}

// Sent on change only, never periodically.
void HaulFleet::updateSensor(HaulTruck& t) {
    auto v = sensor(t);
    if (v == t.sensorSent)
        return;
    t.sensorSent = v;
    m_counters.add("sim.tx.sensor");
    m_emit(v, t.id);
}

void HaulFleet::reportHealth(HaulTruck& t) {
    std::uniform_real_distribution<double> u(0, 1);
    t.nextHealth = m_simTime + kHealthPeriodSeconds;
    BasicMachineHealthV2 h;
    h.fuelLevel = std::lround(t.fuel);
    h.totalEngineHour = std::round(t.engineHours * 10) / 10;
    h.totalMachineHour = std::round(t.engineHours * 10.5) / 10;
    h.tire.emplace();
    for (const char* p : {"1.7", "1.9", "2.6", "2.7", "2.9", "2.10"})
        h.tire->push_back(
            Tire{p, 700 + static_cast<int>(u(m_rng) * 30), 55 + static_cast<int>(u(m_rng) * 12)});
    m_emit(h, t.id);
    // Occasional diagnostics: raise or clear a fault (full list each time, §8.4).
    if (u(m_rng) < 0.15) {
        if (t.faults.empty())
            t.faults.push_back(DiagnosticEntry{555, 2110});
        else
            t.faults.clear();
        m_emit(MachineDiagnosticV2{t.faults}, t.id);
    }
}

} // namespace ocu::sim
