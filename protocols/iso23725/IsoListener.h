#pragma once
// What an ISO 23725 link tells its listener (the console's bridge, tests): link states, everything known
// about each machine of the AHS, the all-stop status, map progress and maps, fleet discrepancies, operator
// events. Called on the stack's io thread; listeners must not block.
#include "protocols/iso23725/FleetDiscrepancies.h"
#include "protocols/iso23725/MapModel.h"
#include "protocols/iso23725/Messages.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ocu::iso23725 {

enum class LinkState { Unknown, Up, Down };
const char* nameFor(LinkState s);

enum class IsoSeverity { Info, Warning, Error };

struct IsoPosition {
    double latitude = 0;
    double longitude = 0;
    std::optional<double> elevation; // WGS84 (Q3: datum kept as received)
    std::optional<double> heading;   // degrees, compass
    std::optional<double> speedKmh;
    std::optional<double> horizontalAccuracy;
    std::optional<std::int64_t> measuredUnixMs; // MachinePositionV1.Timestamp
    std::int64_t receivedUnixMs = 0;
};

// Everything the console knows about one machine of one link.
struct IsoMachineSnapshot {
    std::string link;
    Guid equipmentId;
    std::string hid;
    std::string type;
    std::string oem;
    std::string model;
    bool autonomous = false;
    std::optional<double> length;
    std::optional<double> width;
    bool inAhsFleet = false; // listed in the AHS FleetDefinitionV2
    bool stateKnown = false; // false while the link is down and until the snapshot after reconnect (§2.1)
    std::optional<IsoPosition> position;
    std::string autonomyMode;         // "" = unknown
    std::string dispatchingCustodian; // "" = unknown
    std::optional<BasicMachineHealthV2> health;
    std::optional<std::vector<DiagnosticEntry>> diagnostics; // full active list; nullopt = not reported yet
    std::optional<HaulTruckProductionStateV2> production;
    std::int64_t productionUnixMs = 0;
    std::optional<HaulTruckPayloadV1> payload;
    std::int64_t payloadUnixMs = 0;
    std::optional<HaulTruckProductionStateSensorV1> sensor;
    std::optional<HaulTruckDumpV1> lastDump;
    std::int64_t dumpUnixMs = 0; // header time of lastDump
    std::optional<HaulTruckProductionCycleV1> lastCycle;
    std::optional<HaulTruckAssignmentV1> assignment;  // AHS-reported status
    std::vector<AssignmentItem> requestedAssignments; // last request sent by this FMS
    // Responses to the last request, merged by AssignmentId (a later unsolicited Rejected replaces an
    // Accepted).
    std::vector<AssignmentResponseItem> assignmentResponses;
    // The AHS handed the truck to the FMS (custodian AHS -> FMS, §8.3.4) and no assignment is active since.
    bool needsAssignment = false;
};

enum class AllStopState { Unknown, Off, On };
const char* nameFor(AllStopState s);

struct AllStopStatus {
    AllStopState state = AllStopState::Unknown; // only from MachineAllStopV1 (never from the response)
    std::optional<Guid> activeId;               // ModeAllStopId reported by the AHS
    bool external = false;                      // On with an id this console did not issue
    std::optional<Guid> pendingId;              // our last Apply/Remove awaiting status
    bool supported = true;                      // false after "not supported" rejection
};

class IsoListener {
public:
    virtual ~IsoListener() = default;
    virtual void onLinkState(const std::string& link, LinkState state, const std::string& reason) {
        (void)link, (void)state, (void)reason;
    }
    virtual void onMachineChanged(const IsoMachineSnapshot& machine) { (void)machine; }
    // Machines that only moved (a new MachinePositionV1, nothing else changed), latest position each, in one
    // batch some milliseconds after they arrived: a listener on the hot path reads just the positions (the
    // snapshots are valid during the call only). By default each is an onMachineChanged.
    // One production report as it arrived (§12: HaulTruckProductionStateV2, HaulTruckPayloadV1,
    // HaulTruckDumpV1, HaulTruckProductionCycleV1; late ones too, with their header time), so a production
    // tally sees every cycle and dump even when several come between two deliveries of the machine's state.
    // `machine` is the machine after the report.
    virtual void onProductionReport(const IsoMachineSnapshot& machine, const Body& member,
                                    std::int64_t headerUnixMs) {
        (void)machine, (void)member, (void)headerUnixMs;
    }
    virtual void onMachinePositions(const std::string& link,
                                    const std::vector<const IsoMachineSnapshot*>& machines) {
        (void)link;
        for (const IsoMachineSnapshot* m : machines)
            onMachineChanged(*m);
    }
    virtual void onMachineRemoved(const std::string& link, const Guid& equipmentId) {
        (void)link, (void)equipmentId;
    }
    virtual void onAllStopChanged(const std::string& link, const AllStopStatus& status) {
        (void)link, (void)status;
    }
    virtual void onMapProgress(const std::string& link, const MapProgress& progress) {
        (void)link, (void)progress;
    }
    virtual void onMapChanged(const std::string& link, const MapModel& map) { (void)link, (void)map; }
    // MapConnectivityV1 as received (on connection and on change), also before any map document.
    virtual void onConnectivity(const std::string& link, const MapConnectivityV1& connectivity) {
        (void)link, (void)connectivity;
    }
    // Fleet discrepancies (AHS list vs configured FMS fleet), each with its cause; empty list = consistent.
    // This is the only report of them (no onEvent per item: one event per cause).
    virtual void onFleetDiscrepancies(const std::string& link, const std::vector<FleetDiscrepancy>& items) {
        (void)link, (void)items;
    }
    virtual void onEvent(IsoSeverity severity, const std::string& text) { (void)severity, (void)text; }
};

} // namespace ocu::iso23725
