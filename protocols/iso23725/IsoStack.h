#pragma once
// The FMS side of ISO 23725 (the OCU): per link a WebSocket session to an AHS, the AHS fleet and machine
// state, fleet discrepancy checks, all-stop, assignments, the map service. Commands are posted to the stack's
// io thread; events leave through IsoListener on that thread (listeners must not block).
#include "IsoConfig.h"
#include "MapModel.h"
#include "Messages.h"

#include "common/Counters.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ocu::iso23725 {

enum class LinkState { Unknown, Up, Down };
const char* toString(LinkState s);

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
    std::optional<HaulTruckProductionCycleV1> lastCycle;
    std::optional<HaulTruckAssignmentV1> assignment;         // AHS-reported status
    std::vector<AssignmentItem> requestedAssignments;        // last request sent by this FMS
    std::vector<AssignmentResponseItem> assignmentResponses; // last response received
};

enum class AllStopState { Unknown, Off, On };
const char* toString(AllStopState s);

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
    // Fleet discrepancies (AHS list vs configured FMS fleet); empty list = consistent.
    virtual void onFleetDiscrepancies(const std::string& link, const std::vector<std::string>& items) {
        (void)link, (void)items;
    }
    virtual void onEvent(IsoSeverity severity, const std::string& text) { (void)severity, (void)text; }
};

class IsoStack {
public:
    IsoStack(IsoConfig config, IsoListener& listener);
    ~IsoStack();
    IsoStack(const IsoStack&) = delete;
    IsoStack& operator=(const IsoStack&) = delete;

    // Starts the io thread and every link; false (with events) when a link cannot start (bad URL, TLS files).
    bool start();
    void stop();

    // ---- commands (thread-safe, posted to the io thread; refused with an event while the link is down) ----
    void allStopApply(const std::string& link);
    // Removes with the id of the active stop (ours or, after operator confirmation, an external one).
    void allStopRemove(const std::string& link);
    // Sends HaulTruckAssignmentRequestV2 (first = current, then future); empty AssignmentIds are generated.
    void requestAssignment(const std::string& link, const Guid& equipmentId,
                           std::vector<AssignmentItem> items);
    void resetAssignment(const std::string& link, const Guid& equipmentId);
    // Position of one of the FMS's own (manned) machines, sent at positionRateHz when sendPositions is on.
    void setOwnPosition(const Guid& equipmentId, double lat, double lon, double elevation, double headingDeg,
                        double speedKmh);
    // MapCommandV1 GET "/" (summary then all chunks).
    void fetchMap(const std::string& link);

    // ---- queries (blocking round trip to the io thread: for tests and start-up, not for hot paths) ----
    Counters& counters() { return m_counters; }
    std::vector<IsoMachineSnapshot> machines(const std::string& link);
    AllStopStatus allStop(const std::string& link);
    LinkState linkState(const std::string& link);
    std::vector<std::string> linkNames() const;
    std::shared_ptr<const MapModel> map(const std::string& link);

    struct Impl;

private:
    std::unique_ptr<Impl> m_impl;
    Counters m_counters;
};

} // namespace ocu::iso23725
