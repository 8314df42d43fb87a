#pragma once
// The FMS behaviour of one ISO 23725 link, without sockets: what the console knows of the AHS's machines, the
// fleet discrepancy check, all-stop with its acknowledgement and status timeouts, assignments, the map
// service, interface diagnostics. Frames come in as text and leave through FmsOutbound; every timeout is
// measured on an ocu::Clock and checked by poll(), so the whole session runs on a FakeClock in tests.
// Not thread-safe: IsoStack calls it on its io thread only. FmsCore.cpp holds the link's life, the incoming
// frames and the interface diagnostic; FmsMachines.cpp the machines' state; FmsCommands.cpp the commands.
#include "protocols/iso23725/IsoConfig.h"
#include "protocols/iso23725/IsoListener.h"
#include "protocols/iso23725/MapModel.h"
#include "protocols/iso23725/MapServiceClient.h"
#include "protocols/iso23725/Messages.h"
#include "protocols/iso23725/Routing.h"

#include "protocols/common/Clock.h"
#include "protocols/common/CommandOutcome.h"
#include "protocols/common/Counters.h"
#include "protocols/common/MessageTap.h"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace ocu::iso23725 {

// Where the session's frames go. Each returns false when that channel has no open session.
class FmsOutbound {
public:
    virtual ~FmsOutbound() = default;
    virtual bool sendMain(std::string text) = 0;
    // Ahead of the frames queued on the main socket (all-stop Apply/Remove).
    virtual bool sendMainUrgent(std::string text) { return sendMain(std::move(text)); }
    // The map service's own socket (Q10: only when the link has a separate map URL).
    virtual bool sendMap(std::string text) = 0;
};

class FmsCore {
public:
    FmsCore(const IsoConfig& config, IsoLinkConfig link, IsoListener& listener, Counters& counters,
            const Clock& clock, FmsOutbound& out);

    const std::string& name() const { return m_link.name; }
    // Q10: the map service is served on its own socket (link.mapWs.url set) rather than on the main one.
    bool separateMapService() const { return !m_link.mapWs.url.empty(); }

    // ---- main channel (from the transport) ----
    void opened(const std::string& peer);
    void text(std::string_view frame);
    // A binary frame on the link (§2: ignored): a rate-limited warning for the operator.
    void binaryFrame(std::size_t bytes);
    void closed(const std::string& reason);
    void connectFailed(const std::string& reason, std::chrono::milliseconds retryIn);

    // ---- map service channel (separate map URL only) ----
    void mapOpened(const std::string& peer);
    void mapText(std::string_view frame);
    void mapClosed(const std::string& reason);
    LinkState mapChannelState() const { return m_mapService.channelState(); }

    // ---- commands: false (with an operator event) when refused; never queued while down (§2.1 rule 1) ----
    bool allStopApply();
    // Removes with the id of the active stop (ours or, after operator confirmation, an external one).
    bool allStopRemove();
    // HaulTruckAssignmentRequestV2 (first = current, then future); empty AssignmentIds are generated. Refused
    // (lastRefusal says why, nothing sent) unless the truck's DispatchingCustodian is FMS (§8.3 [I]), every
    // task is a haul task, and, once MapConnectivityV1 is known, every destination is on it and reachable
    // from the truck's current way (then from the previous destination); a missing RouteV1 is filled with the
    // shortest route (IsoConfig rules.autoRoute), a given one must hold.
    bool requestAssignment(const Guid& equipmentId, std::vector<AssignmentItem> items);
    bool resetAssignment(const Guid& equipmentId);
    // MapCommandV1 GET "/" (summary then every chunk), on the map service's channel.
    bool fetchMap();
    // MachinePositionV1 of the FMS's own (manned) machines; nothing while the link is down.
    void sendOwnPositions(const std::map<Guid, IsoPosition>& positions);

    // Positions received since the last call, one IsoListener::onMachinePositions batch (latest per machine).
    // The owner calls it shortly after frames arrive (IsoStack: within kPositionBatchInterval). With
    // `maxMachines` the batch holds at most that many (the earliest arrivals) and the rest stay pending, so
    // the owner can hand a large backlog over in short steps and run a command between two of them.
    void flushPositions(std::size_t maxMachines = SIZE_MAX);
    bool positionsPending() const { return !m_positionBatch.empty(); }
    std::size_t pendingPositions() const { return m_positionBatch.size(); }

    // Timeouts and periodic sending due at clock.now(): all-stop acknowledgement and status confirmation,
    // the periodic interface diagnostic, the flush of rate-limited error diagnostics.
    void poll();

    // ---- state ----
    LinkState state() const { return m_state; }
    const AllStopStatus& allStop() const { return m_allStop; }
    // The reason of the latest refused command (a command outcome's reason).
    const std::string& lastRefusal() const { return m_lastRefusal; }
    OutcomeReason lastRefusalCause() const { return m_lastRefusalCause; }
    // The latest refusal as the outcome of a command for `target`.
    TargetOutcome refusalFor(std::string target) const {
        return TargetOutcome::refused(std::move(target), m_lastRefusalCause, m_lastRefusal);
    }
    const std::map<Guid, IsoMachineSnapshot>& machines() const { return m_machines; }
    std::shared_ptr<const MapModel> map() const { return m_mapService.map(); }
    // The AHS's MapConnectivityV1, indexed for routing (empty until received).
    const RouteGraph& routes() const { return m_routes; }
    const std::optional<FleetDefinitionV2>& ahsFleet() const { return m_ahsFleet; }

    // The flight recorder: every decoded frame (and, when the tap wants them, every text frame as received)
    // goes to `tap` (the io thread). Set before the link opens.
    void setMessageTap(MessageTap* tap) { m_tap = tap; }

private:
    MessageTap* m_tap = nullptr;
    std::string m_tapPeer; // the AHS's address, for the tap
    struct Deadline {
        std::optional<TimePoint> at;
        std::string alarm;
    };

    void event(IsoSeverity severity, const std::string& text);
    bool socketRefused(const char* what); // counter, reason, event; returns false
    // A peer's misbehaviour the operator should see: always counted by the caller; a warning
    // event at most once per cause and link every kPeerWarningGap, saying how many were seen since the last
    // one.
    void peerWarning(const std::string& cause, const std::string& text);
    static constexpr Duration kPeerWarningGap = std::chrono::seconds(60);
    struct PeerWarning {
        TimePoint last{};
        std::uint64_t suppressed = 0;
        bool any = false;
    };
    std::map<std::string, PeerWarning> m_peerWarnings; // bounded: a handful of fixed causes
public:
    // Machines not in the AHS's fleet definition that get a snapshot, per link (a bound against invented
    // IDs): beyond this a frame about yet another unknown machine is counted (rx.rejected.machine_cap),
    // warned about once a minute and dropped before anything is allocated for it. Without it every GUID an
    // AHS sent became a machine row for good.
    static constexpr std::size_t kMaxMachinesOutsideFleet = 64;

private:
    bool upOrRefuse(const char* what);
    // Counter, reason, event; false. `cause` Refused: the standard's rules (the reason says which).
    bool refuse(const std::string& what, const std::string& reason,
                OutcomeReason cause = OutcomeReason::Refused);
    void setRefusal(OutcomeReason cause, std::string reason);
    // The routes of an assignment request (see requestAssignment); an error when one cannot be driven.
    std::string routeAssignment(const IsoMachineSnapshot& m, std::vector<AssignmentItem>& items) const;
    void onAssignmentResponse(IsoMachineSnapshot& m, const HaulTruckAssignmentResponseV1& r);
    std::string frame(const Body& body, std::optional<Guid> equipmentId) const;
    bool sendBody(const Body& body, std::optional<Guid> equipmentId = std::nullopt, bool urgent = false);
    bool sendMapBody(const Body& body);
    void handleFrame(std::string_view frame, bool mapChannel);
    void handle(const Envelope& env, bool mapChannel);
    // A per-machine member other than the position (the hot one: applyPosition).
    void machineMember(IsoMachineSnapshot& m, const Body& member, std::int64_t headerMs);
    bool applyPosition(IsoMachineSnapshot& m,
                       const MachinePositionV1& position); // false: unavailable or late
    void queuePosition(const IsoMachineSnapshot& m);
    void dropQueuedPosition(const IsoMachineSnapshot& m);
    IsoMachineSnapshot& machine(const Guid& id);
    static std::string label(const IsoMachineSnapshot& m);
    FleetDefinitionV2 ownFleet() const;
    void onFleet(const FleetDefinitionV2& fleet);
    void checkDiscrepancies();
    void setAllStop(const MachineAllStopV1& status);
    void onAllStopResponse(const MachineAllStopResponseV1& response);
    // Interface diagnostic (§5 #15 [I], Q7): "periodic (60 s) + on error".
    void reportError(const std::string& code, const std::string& detail, std::optional<std::string> refMember,
                     std::optional<Timestamp> refTimestamp);
    void flushErrorDiagnostics();
    void sendPeriodicDiagnostic();

    const IsoConfig& m_cfg;
    IsoLinkConfig m_link;
    IsoListener& m_listener;
    Counters& m_counters;
    const Clock& m_clock;
    FmsOutbound& m_out;

    LinkState m_state = LinkState::Unknown;
    bool m_gotFirstMessage = false;
    std::optional<FleetDefinitionV2> m_ahsFleet;
    std::map<Guid, IsoMachineSnapshot> m_machines;
    AllStopStatus m_allStop;
    std::string m_lastRefusal;
    OutcomeReason m_lastRefusalCause = OutcomeReason::None;
    std::set<Guid> m_issuedIds;
    Deadline m_ackDeadline;
    Deadline m_statusDeadline;

    MapServiceClient m_mapService;
    RouteGraph m_routes;
    // Machines (snapshots in m_machines) whose position changed since the last flushPositions, in arrival
    // order.
    std::vector<const IsoMachineSnapshot*> m_positionBatch;
    std::unordered_set<const IsoMachineSnapshot*> m_positionQueued;

    std::optional<TimePoint> m_nextPeriodicDiagnostic;
    std::optional<TimePoint> m_lastErrorDiagnostic;
    std::vector<DiagMessage> m_pendingErrors;
    std::uint64_t m_framesReceived = 0;
    std::uint64_t m_messagesSent = 0;
    std::uint64_t m_framesRejected = 0;
    std::uint64_t m_errorsDropped = 0;
};

} // namespace ocu::iso23725
