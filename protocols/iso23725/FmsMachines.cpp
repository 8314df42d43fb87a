// What FmsCore knows of the AHS's machines: positions (§7.4) batched for the listener, the per-machine
// members (autonomy, dispatch custodian, health, production, assignments), the fleet definition and its
// discrepancy check, and the positions of the FMS's own machines.
#include "protocols/iso23725/FleetDiscrepancies.h"
#include "protocols/iso23725/FmsCore.h"

#include <algorithm>
#include <cmath>

namespace ocu::iso23725 {

// ---------------------------------------------------------------- positions (§7.4)

bool FmsCore::applyPosition(IsoMachineSnapshot& m, const MachinePositionV1& b) {
    if (!b.pose.latitude || !b.pose.longitude) {
        m_counters.add("rx.position_unavailable");
        return false;
    }
    if (m.position && m.position->measuredUnixMs && b.timestamp.unixMs &&
        *b.timestamp.unixMs < *m.position->measuredUnixMs) {
        m_counters.add("rx.late_position"); // latest state wins (§2.1 rule 2)
        return false;
    }
    IsoPosition p;
    p.latitude = *b.pose.latitude;
    p.longitude = *b.pose.longitude;
    p.elevation = b.pose.elevation;
    if (b.pose.heading)
        p.heading = static_cast<double>(*b.pose.heading);
    if (b.pose.speed)
        p.speedKmh = static_cast<double>(*b.pose.speed);
    if (b.pose.latitudeAccuracy && b.pose.longitudeAccuracy)
        p.horizontalAccuracy = std::max(*b.pose.latitudeAccuracy, *b.pose.longitudeAccuracy);
    p.measuredUnixMs = b.timestamp.unixMs;
    p.receivedUnixMs = unixMillisNow();
    m.position = p;
    m_counters.add("rx.positions");
    return true;
}

void FmsCore::queuePosition(const IsoMachineSnapshot& m) {
    if (m_positionQueued.insert(&m).second)
        m_positionBatch.push_back(&m);
}

void FmsCore::dropQueuedPosition(const IsoMachineSnapshot& m) {
    if (m_positionQueued.erase(&m))
        m_positionBatch.erase(std::find(m_positionBatch.begin(), m_positionBatch.end(), &m));
}

void FmsCore::flushPositions(std::size_t maxMachines) {
    if (m_positionBatch.empty() || maxMachines == 0)
        return;
    m_counters.add("rx.position_batches");
    if (maxMachines >= m_positionBatch.size()) {
        m_listener.onMachinePositions(m_link.name, m_positionBatch);
        m_positionBatch.clear();
        m_positionQueued.clear();
        return;
    }
    // The earliest arrivals go first; a machine handed over here that moves again joins the end of the batch.
    const auto end = m_positionBatch.begin() + static_cast<std::ptrdiff_t>(maxMachines);
    const std::vector<const IsoMachineSnapshot*> step(m_positionBatch.begin(), end);
    for (const IsoMachineSnapshot* m : step)
        m_positionQueued.erase(m);
    m_positionBatch.erase(m_positionBatch.begin(), end);
    m_listener.onMachinePositions(m_link.name, step);
}

void FmsCore::machineMember(IsoMachineSnapshot& m, const Body& member, std::int64_t hdrMs) {
    std::visit(
        [&](auto&& b) {
            using T = std::decay_t<decltype(b)>;
            if constexpr (std::is_same_v<T, MachineAutonomyModeV1>) {
                m.autonomyMode = b.autonomyMode;
            } else if constexpr (std::is_same_v<T, MachineDispatchAvailabilityV1>) {
                if (m.dispatchingCustodian == "AHS" && b.dispatchingCustodian == "FMS") {
                    m.needsAssignment = true;
                    m_counters.add("assignment.needed");
                    event(IsoSeverity::Warning,
                          "machine " + label(m) + " needs an assignment (custodian AHS -> FMS, §8.3.4)");
                } else if (b.dispatchingCustodian != "FMS") {
                    m.needsAssignment = false;
                }
                m.dispatchingCustodian = b.dispatchingCustodian;
            } else if constexpr (std::is_same_v<T, MachineDiagnosticV2>) {
                m.diagnostics = b.entries; // full list each time; [] clears (§8.4)
            } else if constexpr (std::is_same_v<T, BasicMachineHealthV2>) {
                m.health = b;
            } else if constexpr (std::is_same_v<T, HaulTruckProductionStateV2>) {
                // §2.1 rule 4: a late event never overwrites newer state.
                if (hdrMs < m.productionUnixMs) {
                    m_counters.add("rx.late_event");
                    event(IsoSeverity::Info, "late production state " + b.productionState + " of " +
                                                 label(m) + " at " + formatTimestamp(hdrMs) +
                                                 " kept in history only");
                    return;
                }
                m.production = b;
                m.productionUnixMs = hdrMs;
            } else if constexpr (std::is_same_v<T, HaulTruckPayloadV1>) {
                if (hdrMs < m.payloadUnixMs) {
                    m_counters.add("rx.late_event");
                    event(IsoSeverity::Info, "late payload of " + label(m) + " at " + formatTimestamp(hdrMs) +
                                                 " kept in history only");
                    return;
                }
                m.payload = b;
                m.payloadUnixMs = hdrMs;
            } else if constexpr (std::is_same_v<T, HaulTruckProductionStateSensorV1>) {
                m.sensor = b;
                m_counters.add("rx.production_sensor");
            } else if constexpr (std::is_same_v<T, HaulTruckDumpV1>) {
                m.lastDump = b;
                m.dumpUnixMs = std::max(m.dumpUnixMs, hdrMs);
                event(IsoSeverity::Info,
                      "dump by " + label(m) + " at way " + std::to_string(b.wayId) +
                          (b.dumpedWeight ? ", " + std::to_string(*b.dumpedWeight) + " t" : std::string()));
            } else if constexpr (std::is_same_v<T, HaulTruckProductionCycleV1>) {
                m.lastCycle = b;
                event(IsoSeverity::Info, "cycle " + b.cycleId + " completed by " + label(m));
            } else if constexpr (std::is_same_v<T, HaulTruckAssignmentV1>) {
                m.assignment = b;
                if (b.status == "Active" || b.status == "Pending")
                    m.needsAssignment = false;
            } else if constexpr (std::is_same_v<T, HaulTruckAssignmentResponseV1>) {
                onAssignmentResponse(m, b);
            }
        },
        member);
}

// ---------------------------------------------------------------- fleet definition

void FmsCore::onFleet(const FleetDefinitionV2& f) {
    m_ahsFleet = f;
    std::set<Guid> listed;
    for (auto& e : f.equipment) {
        listed.insert(e.equipmentId);
        auto& m = machine(e.equipmentId);
        m.hid = e.hid;
        m.type = e.type;
        m.oem = e.oem;
        m.model = e.model;
        m.autonomous = e.autonomous;
        m.length = e.length;
        m.width = e.width;
        m.inAhsFleet = true;
        m_listener.onMachineChanged(m);
    }
    // No delete command exists: absence from a re-sent list removes the machine [ISO-seed].
    for (auto it = m_machines.begin(); it != m_machines.end();) {
        if (!listed.count(it->first)) {
            dropQueuedPosition(it->second);
            m_listener.onMachineRemoved(m_link.name, it->first);
            it = m_machines.erase(it);
        } else {
            ++it;
        }
    }
    checkDiscrepancies();
}

void FmsCore::checkDiscrepancies() {
    const auto items = checkFleet(*m_ahsFleet, m_cfg.fleet, m_cfg.dimensionTolerance);
    m_counters.add("fleet.discrepancies", items.size());
    // Reported once, through onFleetDiscrepancies only: an onEvent per item as well made every discrepancy
    // appear twice in the console (once as "discrepancy", once as "info") and flooded it.
    m_listener.onFleetDiscrepancies(m_link.name, items);
}

// ---------------------------------------------------------------- own machines' positions (§7.4)

void FmsCore::sendOwnPositions(const std::map<Guid, IsoPosition>& positions) {
    if (m_state != LinkState::Up)
        return;
    const auto now = unixMillisNow();
    for (auto& [id, p] : positions) {
        MachinePositionV1 m;
        m.timestamp = makeTimestamp(p.measuredUnixMs.value_or(now));
        m.pose.latitude = p.latitude;
        m.pose.longitude = p.longitude;
        m.pose.elevation = p.elevation;
        if (p.heading)
            m.pose.heading = static_cast<std::int64_t>(std::lround(*p.heading)) % 360;
        if (p.speedKmh)
            m.pose.speed = std::lround(*p.speedKmh);
        sendBody(m, id);
    }
}

} // namespace ocu::iso23725
