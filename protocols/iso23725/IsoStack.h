#pragma once
// The FMS side of ISO 23725 (the OCU): per link a WebSocket session to an AHS, the AHS fleet and machine
// state, fleet discrepancy checks, all-stop, assignments, the map service. Commands are posted to the stack's
// io thread; events leave through IsoListener on that thread (listeners must not block). Positions leave in
// batches (IsoListener::onMachinePositions) at most 5 ms after they arrived.
#include "protocols/iso23725/FmsCore.h"

#include "protocols/common/Clock.h"
#include "protocols/common/CommandOutcome.h"
#include "protocols/common/Counters.h"

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ocu {
class MessageTap;
}

namespace ocu::iso23725 {

class IsoStack {
public:
    // Every timeout (all-stop acknowledgement, status, map service, diagnostics, WebSocket keepalive) is
    // measured on `clock`, which must outlive the stack.
    IsoStack(IsoConfig config, IsoListener& listener, Clock& clock = SteadyClock::instance());
    ~IsoStack();
    IsoStack(const IsoStack&) = delete;
    IsoStack& operator=(const IsoStack&) = delete;

    // Starts the io thread and every link; false (with events) when a link cannot start (bad URL, TLS files).
    bool start();
    void stop();
    // The flight recorder: every decoded frame of every link (and, when the tap wants them, every text frame)
    // goes to `tap` on the io thread. Set before start(); the tap outlives the stack's run.
    void setMessageTap(MessageTap* tap);

    // ---- commands (thread-safe, posted to the io thread; refused with an event while the link is down) ----
    // Every command reports its outcome: `done` runs once on the io thread with one TargetOutcome (sent only
    // when the socket took the frame; never when the stack is not running). All-stop and the map fetch name
    // the link (linkTarget), assignment and reset the truck (machineTarget).
    void allStopApply(const std::string& link, OutcomeCallback done);
    // Removes with the id of the active stop (ours or, after operator confirmation, an external one).
    void allStopRemove(const std::string& link, OutcomeCallback done);
    static std::string linkTarget(const std::string& link) { return "iso23725 link " + link; }
    // Position of one of the FMS's own (manned) machines, sent at positionRateHz when sendPositions is on.
    void setOwnPosition(const Guid& equipmentId, double lat, double lon, double elevation, double headingDeg,
                        double speedKmh);
    // Sends HaulTruckAssignmentRequestV2 (first = current, then future); empty AssignmentIds are generated.
    void requestAssignment(const std::string& link, const Guid& equipmentId,
                           std::vector<AssignmentItem> items, OutcomeCallback done);
    void resetAssignment(const std::string& link, const Guid& equipmentId, OutcomeCallback done);
    // MapCommandV1 GET "/" (summary then all chunks).
    void fetchMap(const std::string& link, OutcomeCallback done);
    static std::string machineTarget(const Guid& equipmentId) { return "iso23725:" + equipmentId; }

    // ---- queries (blocking round trip to the io thread: for tests and start-up, not for hot paths) ----
    Counters& counters() { return m_counters; }
    // One link's counters (they also count into counters()); nullptr for an unknown link. Any thread.
    Counters* linkCounters(const std::string& link) const;
    // Watchdog: how long the io thread has not turned (0 while it turns or is not running).
    std::chrono::milliseconds ioStalledFor() const;
    // Runs f on the io thread without waiting (diagnostics; tests block the thread with it on purpose).
    void postToIo(std::function<void()> f);
    std::vector<IsoMachineSnapshot> machines(const std::string& link);
    AllStopStatus allStop(const std::string& link);
    LinkState linkState(const std::string& link);
    // The map service's socket (Q10): its own state when the link has a separate map URL, else the link's.
    LinkState mapServiceState(const std::string& link);
    std::vector<std::string> linkNames() const;
    std::shared_ptr<const MapModel> map(const std::string& link);

    struct Impl;

private:
    std::unique_ptr<Impl> m_impl;
    Counters m_counters;
};

} // namespace ocu::iso23725
