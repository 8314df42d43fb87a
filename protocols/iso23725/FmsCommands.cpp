// The operator's commands on one ISO 23725 link and their answers: all-stop Apply/Remove with its
// acknowledgement and status deadlines (§7.6, §7.7), haul truck assignments and resets (§13.3), the map
// fetch.
#include "protocols/iso23725/FmsCore.h"

#include <algorithm>

namespace ocu::iso23725 {

// ---------------------------------------------------------------- all-stop (§7.6, §7.7)

void FmsCore::setAllStop(const MachineAllStopV1& s) {
    auto& a = m_allStop;
    a.state = s.modeAllStop == "On" ? AllStopState::On : AllStopState::Off;
    a.activeId = s.modeAllStopId;
    a.external = a.state == AllStopState::On && s.modeAllStopId && !m_issuedIds.count(*s.modeAllStopId);
    if (a.pendingId && s.modeAllStopId == a.pendingId) {
        // The status confirms our request: Apply is confirmed by On, Remove by Off with the same id.
        m_statusDeadline.at.reset();
        if (a.state == AllStopState::Off)
            a.pendingId.reset();
    }
    if (a.external)
        event(IsoSeverity::Warning,
              "all-stop active on " + m_link.name + " (external, id " + *a.activeId + ")");
    m_listener.onAllStopChanged(m_link.name, a);
}

void FmsCore::onAllStopResponse(const MachineAllStopResponseV1& b) {
    m_ackDeadline.at.reset();
    std::string d = b.detail ? " (" + *b.detail + ")" : std::string();
    if (b.response == "Accepted") {
        event(IsoSeverity::Info, "all-stop request " + b.modeAllStopId + " accepted by " + m_link.name + d);
        // The response is not the state: only MachineAllStopV1 is (§7.7); wait for it.
        if (m_allStop.state != AllStopState::On || m_allStop.activeId != b.modeAllStopId)
            m_statusDeadline = {m_clock.now() + m_cfg.allStopStatusTimeout,
                                "all-stop accepted but status not confirmed"};
    } else {
        if (b.detail && b.detail->find("not supported") != std::string::npos) {
            m_allStop.supported = false;
            m_listener.onAllStopChanged(m_link.name, m_allStop);
        }
        event(IsoSeverity::Error, "all-stop request " + b.modeAllStopId + " rejected by " + m_link.name + d);
    }
}

bool FmsCore::allStopApply() {
    if (!upOrRefuse("all-stop Apply"))
        return false;
    Guid id = newGuid();
    if (!sendBody(MachineAllStopRequestV1{"Apply", id}, std::nullopt, true)) // ahead of queued frames
        return socketRefused("all-stop Apply");
    m_issuedIds.insert(id);
    m_allStop.pendingId = id;
    m_counters.add("allstop.apply");
    event(IsoSeverity::Info, "all-stop Apply " + id + " sent to " + m_link.name);
    m_ackDeadline = {m_clock.now() + m_cfg.allStopAckTimeout, "all-stop not acknowledged"};
    m_listener.onAllStopChanged(m_link.name, m_allStop);
    return true;
}

bool FmsCore::allStopRemove() {
    if (!upOrRefuse("all-stop Remove"))
        return false;
    // "Same ID used in apply must be used when removing" [OA-iso].
    std::optional<Guid> id = m_allStop.activeId ? m_allStop.activeId : m_allStop.pendingId;
    if (!id) {
        setRefusal(OutcomeReason::Refused, "no active all-stop id on link " + m_link.name);
        event(IsoSeverity::Warning, "all-stop Remove refused on " + m_link.name + ": no active all-stop id");
        return false;
    }
    if (!sendBody(MachineAllStopRequestV1{"Remove", *id}, std::nullopt, true))
        return socketRefused("all-stop Remove");
    m_allStop.pendingId = id;
    m_counters.add("allstop.remove");
    event(IsoSeverity::Info, "all-stop Remove " + *id + " sent to " + m_link.name);
    m_ackDeadline = {m_clock.now() + m_cfg.allStopAckTimeout, "all-stop Remove not acknowledged"};
    return true;
}

// ---------------------------------------------------------------- assignments (§13.3)

bool FmsCore::requestAssignment(const Guid& equipmentId, std::vector<AssignmentItem> items) {
    if (!upOrRefuse("assignment request"))
        return false;
    auto it = m_machines.find(equipmentId);
    if (it == m_machines.end())
        return refuse("assignment request", "machine " + equipmentId + " is unknown on link " + m_link.name,
                      OutcomeReason::UnknownTarget);
    auto& m = it->second;
    // §8.3 [I]: only a truck the AHS handed to the FMS is dispatched by the FMS.
    if (m.dispatchingCustodian != "FMS")
        return refuse("assignment request",
                      label(m) + (m.dispatchingCustodian.empty()
                                      ? " has not reported its DispatchingCustodian yet"
                                      : " is dispatched by the " + m.dispatchingCustodian +
                                            " (DispatchingCustodian " + m.dispatchingCustodian + ")"));
    if (items.empty())
        return refuse("assignment request", "no task given", OutcomeReason::InvalidArgument);
    for (auto& a : items) {
        if (std::find(enums::haulTask.begin(), enums::haulTask.end(), a.task) == enums::haulTask.end())
            return refuse("assignment request",
                          "task '" + a.task + "' is not one of Load, Offload, Fuel, Park, Wait",
                          OutcomeReason::InvalidArgument);
        if (a.destinationEquipmentId && a.destinationSpotId)
            return refuse("assignment request",
                          "DestinationEquipmentId and DestinationSpotId are mutually exclusive (§5 #21)",
                          OutcomeReason::InvalidArgument);
        if (a.destinationEquipmentId && !isGuid(*a.destinationEquipmentId))
            return refuse("assignment request",
                          "DestinationEquipmentId '" + *a.destinationEquipmentId + "' is not a GUID",
                          OutcomeReason::InvalidArgument);
        if (!a.assignmentId.empty() && !isGuid(a.assignmentId))
            return refuse("assignment request", "AssignmentId '" + a.assignmentId + "' is not a GUID",
                          OutcomeReason::InvalidArgument);
    }
    if (std::string why = routeAssignment(m, items); !why.empty())
        return refuse("assignment request", why);
    for (auto& a : items) {
        if (a.assignmentId.empty())
            a.assignmentId = newGuid();
        if (a.route && !m_cfg.rules.emitNegativeWayIds)
            for (auto& w : *a.route)
                w.wayId = std::abs(w.wayId); // Q6: negative ids not emitted unless enabled
    }
    if (!sendBody(HaulTruckAssignmentRequestV2{items}, equipmentId))
        return socketRefused("assignment request");
    m.requestedAssignments = items;
    m.assignmentResponses.clear();
    m_counters.add("assignment.request");
    std::string what;
    for (auto& a : items)
        what += (what.empty() ? "" : ", ") + a.task + " at way " + std::to_string(a.destinationId);
    event(IsoSeverity::Info, "assignment request sent to " + label(m) + ": " + what);
    m_listener.onMachineChanged(m);
    return true;
}

std::string FmsCore::routeAssignment(const IsoMachineSnapshot& m, std::vector<AssignmentItem>& items) const {
    if (m_routes.empty())
        return {}; // no MapConnectivityV1 yet: the AHS alone judges reachability
    std::optional<std::int64_t> from;
    if (m.production && m.production->wayId && m_routes.contains(*m.production->wayId))
        from = m.production->wayId;
    for (auto& a : items) {
        if (!m_routes.contains(a.destinationId))
            return "destination way " + std::to_string(a.destinationId) +
                   " is not in the AHS's MapConnectivityV1";
        if (from) {
            if (a.route) {
                if (std::string why = checkRoute(m_routes, *from, *a.route, a.destinationId); !why.empty())
                    return "task " + a.task + " to way " + std::to_string(a.destinationId) + ": " + why;
            } else {
                RouteResult r = shortestRoute(m_routes, *from, a.destinationId);
                if (!r.ok)
                    return "task " + a.task + ": destination " + r.error;
                // RouteV1 is optional (row 21): a destination next to the truck's way has no way in between,
                // and an empty list would only say that; it is left out then.
                if (std::vector<WayRef> v = r.routeV1(); m_cfg.rules.sendRoutes && !v.empty())
                    a.route = std::move(v);
            }
        }
        from = a.destinationId; // a future task starts where the previous one ends
    }
    return {};
}

bool FmsCore::resetAssignment(const Guid& equipmentId) {
    if (!upOrRefuse("assignment reset"))
        return false;
    auto it = m_machines.find(equipmentId);
    if (it == m_machines.end())
        return refuse("assignment reset", "machine " + equipmentId + " is unknown on link " + m_link.name,
                      OutcomeReason::UnknownTarget);
    if (!sendBody(HaulTruckAssignmentResetV1{newGuid()}, equipmentId))
        return socketRefused("assignment reset");
    m_counters.add("assignment.reset");
    event(IsoSeverity::Info, "assignment reset sent to " + label(it->second));
    return true;
}

void FmsCore::onAssignmentResponse(IsoMachineSnapshot& m, const HaulTruckAssignmentResponseV1& b) {
    for (auto& r : b.items) {
        auto known = std::find_if(m.assignmentResponses.begin(), m.assignmentResponses.end(),
                                  [&](auto& x) { return x.assignmentId == r.assignmentId; });
        // §5 #22 [I]: a Rejected for an assignment already Accepted is the AHS giving it up.
        const bool withdrawn =
            known != m.assignmentResponses.end() && known->response == "Accepted" && r.response == "Rejected";
        if (known != m.assignmentResponses.end())
            *known = r;
        else
            m.assignmentResponses.push_back(r);
        if (r.response == "Accepted")
            m.needsAssignment = false;
        const std::string detail = r.detail ? " (" + *r.detail + ")" : std::string();
        if (withdrawn) {
            m_counters.add("assignment.withdrawn");
            event(IsoSeverity::Warning, "assignment " + r.assignmentId + " of " + label(m) +
                                            " can no longer be done: Rejected by the AHS" + detail);
        } else {
            event(r.response == "Accepted" ? IsoSeverity::Info : IsoSeverity::Warning,
                  "assignment " + r.assignmentId + " for " + label(m) + " " + r.response + detail);
        }
    }
}

// ---------------------------------------------------------------- map service (§10.6, MapServiceClient)

bool FmsCore::fetchMap() {
    if (!separateMapService() && !upOrRefuse("map fetch"))
        return false;
    if (m_mapService.fetch())
        return true;
    if (separateMapService() && m_mapService.channelState() != LinkState::Up)
        setRefusal(OutcomeReason::LinkDown,
                   "the map service of link " + m_link.name + " is " + nameFor(m_mapService.channelState()));
    else
        setRefusal(OutcomeReason::SendFailed,
                   "the WebSocket of link " + m_link.name + " did not take the frame (closing)");
    return false;
}

} // namespace ocu::iso23725
