// What the simulated AHS is asked to do with its haul trucks: all-stop and manual mode, FMS assignments and
// resets (§13.3) checked against the map, the dispatching custodian (§8.3), closed ways (§9).
#include "sim/iso23725/HaulFleet.h"

#include <algorithm>
#include <cstdlib>

namespace ocu::sim {

using namespace ocu::iso23725;

// ---------------------------------------------------------------- commands

void HaulFleet::setAllStop(bool on) {
    m_allStopOn = on;
    for (auto& t : m_trucks)
        if (t.autonomous && !t.manual)
            m_emit(MachineAutonomyModeV1{autonomyMode(t)}, t.id);
}

void HaulFleet::setManual(int index, bool manual) {
    if (index < 0 || index >= static_cast<int>(m_trucks.size()))
        return;
    auto& t = m_trucks[static_cast<std::size_t>(index)];
    t.manual = manual;
    m_emit(MachineAutonomyModeV1{autonomyMode(t)}, t.id);
}

std::string HaulFleet::cannotDo(const HaulTruck& t, const AssignmentItem& a, std::int64_t from) const {
    if (t.custodian != "FMS")
        return "DispatchingCustodian is " + t.custodian + ": " + t.hid + " is dispatched by the AHS";
    if (a.task == "Load" && m_map.loadIndex(a.destinationId) < 0)
        return "destination " + std::to_string(a.destinationId) + " is not a load area";
    if (a.task == "Offload" && m_map.dumpIndex(a.destinationId) < 0)
        return "destination " + std::to_string(a.destinationId) + " is not a dump area";
    if (a.task == "Park" && a.destinationId != m_map.parkArea)
        return "destination " + std::to_string(a.destinationId) + " is not a park area";
    if (a.task == "Fuel" || a.task == "Wait")
        return "task " + a.task + " not supported by this AHS";
    if (m_closedWays.count(a.destinationId))
        return "destination " + std::to_string(a.destinationId) + " is closed by the AHS";
    if (a.route) {
        for (auto& w : *a.route)
            if (m_closedWays.count(std::llabs(w.wayId)))
                return "route way " + std::to_string(std::llabs(w.wayId)) + " is closed by the AHS";
        // The FMS planned from the way it last heard of; the part of the route the truck is already past
        // does not count.
        std::vector<WayRef> ahead = *a.route;
        for (std::size_t i = 0; i < a.route->size(); ++i)
            if (std::llabs((*a.route)[i].wayId) == from)
                ahead.assign(a.route->begin() + static_cast<std::ptrdiff_t>(i), a.route->end());
        if (auto why = checkRoute(m_routes, from, ahead, a.destinationId); !why.empty())
            return "RouteV1 cannot be driven: " + why;
    }
    if (auto r = shortestRoute(m_routes, from, a.destinationId); !r.ok)
        return "destination " + r.error;
    return {};
}

void HaulFleet::assign(const Guid& equipmentId, const HaulTruckAssignmentRequestV2& request) {
    HaulTruck* t = truck(equipmentId);
    HaulTruckAssignmentResponseV1 resp;
    std::vector<AssignmentItem> accepted;
    std::int64_t from = t ? t->motion.wayId() : 0;
    for (auto& a : request.items) {
        std::string why = t ? cannotDo(*t, a, from) : "unknown machine";
        if (why.empty()) {
            accepted.push_back(a);
            from = a.destinationId; // the next task starts where this one ends
        }
        resp.items.push_back(
            AssignmentResponseItem{a.assignmentId, why.empty() ? "Accepted" : "Rejected",
                                   why.empty() ? std::nullopt : std::optional<std::string>(why)});
    }
    m_counters.add("sim.assign.requests");
    m_emit(resp, equipmentId);
    if (t && !accepted.empty()) {
        if (!t->assignments.empty() && t->assignments.front().assignmentId != accepted.front().assignmentId) {
            const auto& old = t->assignments.front(); // replaced by the new request
            m_emit(HaulTruckAssignmentV1{old.assignmentId, "Cancelled", old.task, old.destinationId}, t->id);
        }
        t->assignments = accepted;
        t->fmsWork = true;
        t->idle = false;
        const auto& first = accepted.front();
        m_emit(HaulTruckAssignmentV1{first.assignmentId, "Active", first.task, first.destinationId}, t->id);
        if (t->phase == HaulPhase::Parked) {
            t->dwell = 0; // leaves now
        } else if ((t->phase == HaulPhase::ToLoad || t->phase == HaulPhase::ToDump ||
                    t->phase == HaulPhase::ToPark || t->phase == HaulPhase::Queued) &&
                   (t->payload == 0 || first.task == "Offload") &&
                   !(t->phase == HaulPhase::Queued && t->area == first.destinationId)) {
            // On the road (or in a queue): it turns towards the new current task at once, along its route. A
            // loaded truck finishes its haul first unless the task is where to dump; loading and dumping are
            // never interrupted.
            driveTo(*t, first.destinationId, first.route);
        }
    }
}

void HaulFleet::resetAssignments(const Guid& equipmentId) {
    HaulTruck* t = truck(equipmentId);
    if (!t)
        return;
    if (!t->assignments.empty()) {
        const auto& a = t->assignments.front();
        m_emit(HaulTruckAssignmentV1{a.assignmentId, "Cancelled", a.task, a.destinationId}, t->id);
    }
    t->assignments.clear();
}

void HaulFleet::setCustodian(HaulTruck& t, const std::string& actor) {
    if (t.custodian == actor)
        return;
    t.custodian = actor;
    m_emit(MachineDispatchAvailabilityV1{actor, std::nullopt, std::nullopt}, t.id);
}

void HaulFleet::setCustodian(int index, const std::string& actor) {
    if (index < 0 || index >= static_cast<int>(m_trucks.size()) || (actor != "AHS" && actor != "FMS"))
        return;
    setCustodian(m_trucks[static_cast<std::size_t>(index)], actor);
}

void HaulFleet::goIdle(HaulTruck& t) {
    t.fmsWork = false;
    t.idle = true;
    setCustodian(t, "AHS"); // the AHS moves it out of the way itself
    if (!driveTo(t, m_map.parkArea, std::nullopt)) {
        t.phase = HaulPhase::Parked; // no way to the park: it waits where it is
        setProduction(t, "Parked");
        setCustodian(t, "FMS");
    }
}

void HaulFleet::setWayClosed(std::int64_t wayId, bool closed) {
    if (closed ? !m_closedWays.insert(wayId).second : m_closedWays.erase(wayId) == 0)
        return;
    m_connectivity = m_map.connectivity;
    for (auto& item : m_connectivity.items)
        std::erase_if(item.connection, [&](const WayRef& c) { return m_closedWays.count(c.wayId) != 0; });
    m_routes = RouteGraph(m_connectivity);
    m_emit(m_connectivity, Guid()); // §9: on change, to every FMS
    if (!closed)
        return;
    // Accepted tasks that can no longer be driven are given up, with the ones queued after them.
    for (auto& t : m_trucks) {
        std::int64_t from = t.motion.wayId();
        std::size_t firstLost = t.assignments.size();
        std::string why;
        for (std::size_t i = 0; i < t.assignments.size(); ++i) {
            why = cannotDo(t, t.assignments[i], from);
            if (!why.empty()) {
                firstLost = i;
                break;
            }
            from = t.assignments[i].destinationId;
        }
        if (firstLost == t.assignments.size())
            continue;
        HaulTruckAssignmentResponseV1 lost;
        for (std::size_t i = firstLost; i < t.assignments.size(); ++i)
            lost.items.push_back(AssignmentResponseItem{t.assignments[i].assignmentId, "Rejected",
                                                        "can no longer be done: " + why});
        m_counters.add("sim.assign.withdrawn");
        m_emit(lost, t.id);
        if (firstLost == 0) {
            const auto& a = t.assignments.front();
            m_emit(HaulTruckAssignmentV1{a.assignmentId, "Cancelled", a.task, a.destinationId}, t.id);
        }
        t.assignments.resize(firstLost);
    }
}

} // namespace ocu::sim
