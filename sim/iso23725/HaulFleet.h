#pragma once
// The simulated AHS's haul trucks on the pit map: load-haul-dump cycles (drive to a shovel, queue while
// another truck is under it, spot, load, haul to a dump or the crusher, queue, spot, dump, drive back), FMS
// assignments choosing the destination and driven along their RouteV1 (or the shortest route over the
// connectivity) from where the truck is, all-stop and manual
// mode holding trucks, the production state and its sensor inputs (sent on change), payloads, dumps and
// production cycles, periodic health with occasional diagnostics. Advanced by tick(dt) in simulated seconds;
// what the trucks report leaves through an emit callback as ISO 23725 members, never through a socket, so
// the fleet runs in tests on a fake clock.
// HaulFleet.cpp drives the trucks through their cycles; HaulFleetCommands.cpp takes what the AHS is asked to
// do.
#include "sim/iso23725/PitMapGenerator.h"
#include "sim/iso23725/TruckKinematics.h"

#include "protocols/iso23725/Messages.h"
#include "protocols/iso23725/Routing.h"

#include "protocols/common/Clock.h"
#include "protocols/common/Counters.h"
#include "protocols/common/GeoFrame.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace ocu::sim {

struct HaulFleetConfig {
    int truckCount = 6;
    std::uint32_t seed = 1;   // truck GUIDs, speeds and the random events follow from it
    bool healthEvents = true; // periodic health, occasional diagnostics
};

// Queued: waiting at the area's entry for the truck under the shovel / on the tip to leave; Spotting:
// creeping from the entry to the loading or dumping spot (then Loading or Dumping).
enum class HaulPhase { Parked, ToLoad, Loading, ToDump, Dumping, ToPark, Queued, Spotting };

struct HaulTruck {
    iso23725::Guid id;
    std::string hid;
    bool autonomous = true;
    bool manual = false;
    TruckMotion motion;
    double cruise = 11.0; // m/s empty; 75 % of it loaded
    HaulPhase phase = HaulPhase::Parked;
    double dwell = 0; // s left loading, dumping or parked
    int shovel = 0;   // index into PitMap::loadAreas
    int dump = 0;     // index into PitMap::dumpAreas (the last is the crusher)
    int payload = 0;  // t on board
    std::string productionState = "Parked";
    std::int64_t area = 0; // the load, dump or park area it is heading to, queued at or in
    // This cycle's production states so far (§5 #16 StateTimes: each with its start, closed with its
    // duration when the next begins); reported with HaulTruckProductionCycleV1 at the end of the dump.
    std::vector<iso23725::StateTime> cycleStates;
    std::vector<iso23725::AssignmentItem> assignments; // queue (first = current)
    std::string custodian = "FMS"; // MachineDispatchAvailabilityV1.DispatchingCustodian (§8.3)
    bool fmsWork = false;          // working through FMS assignments: idle when they run out
    bool idle = false;             // parked, waiting for an FMS assignment
    std::int64_t reportedWay = 0;  // WayId of the last HaulTruckProductionStateV2 sent
    iso23725::Guid cycleId;
    std::int64_t cycleStartMs = 0;
    double fuel = 80;
    double engineHours = 12000;
    std::vector<iso23725::DiagnosticEntry> faults;
    double nextHealth = 0;                                 // simulated time of the next health report
    iso23725::HaulTruckProductionStateSensorV1 sensorSent; // last sensor inputs sent (on change)
};

class HaulFleet {
public:
    // One member about one truck (or, for assignment responses, the machine the request named).
    using Emit = std::function<void(const iso23725::Body& member, const iso23725::Guid& equipmentId)>;
    // Wall-clock time for timestamps on the wire and cycle durations (ms since the Unix epoch).
    using UnixClock = std::function<std::int64_t()>;

    // The map must outlive the fleet. Trucks start spread over their cycles so a site looks busy at once.
    HaulFleet(const PitMap& map, HaulFleetConfig config, Counters& counters, Emit emit,
              UnixClock now = unixMillisNow);

    // Advances every truck by dt simulated seconds (drive, arrive, load/dump, leave; health when due).
    void tick(double dt);

    // ---- what the AHS is asked to do ----
    // All-stop on/off (§7.6): autonomous trucks brake to a stop and stay; emits their new autonomy mode.
    void setAllStop(bool on);
    bool allStopOn() const { return m_allStopOn; }
    // A truck switched to manual (held by its driver) or back; emits its autonomy mode.
    void setManual(int index, bool manual);
    // HaulTruckAssignmentRequestV2 (§13.3): emits the response (per item Accepted or Rejected with the
    // reason) and, when any item was accepted, the first as Active; the accepted items replace the truck's
    // queue.
    void assign(const iso23725::Guid& equipmentId, const iso23725::HaulTruckAssignmentRequestV2& request);
    // HaulTruckAssignmentResetV1: the current assignment is Cancelled and the queue emptied.
    void resetAssignments(const iso23725::Guid& equipmentId);
    // Who dispatches the truck (§8.3): "AHS" (assignments rejected) or "FMS"; emits the availability.
    void setCustodian(int index, const std::string& actor);
    // Closes (or reopens) a way: connections into it leave the AHS's MapConnectivityV1 (emitted, §9 on
    // change); new tasks to or through it are rejected as unreachable; accepted ones that can no longer be
    // driven are given up with an unsolicited HaulTruckAssignmentResponseV1 Rejected (§5 #22 [I]) and the
    // current one Cancelled.
    void setWayClosed(std::int64_t wayId, bool closed);
    const iso23725::MapConnectivityV1& connectivity() const { return m_connectivity; }

    // ---- what the trucks report ----
    const std::vector<HaulTruck>& trucks() const { return m_trucks; }
    HaulTruck* truck(const iso23725::Guid& id);
    std::vector<iso23725::Equipment> equipment() const; // for FleetDefinitionV2
    std::string autonomyMode(const HaulTruck& t) const;
    iso23725::HaulTruckProductionStateV2 productionState(const HaulTruck& t) const;
    iso23725::MachinePositionV1 position(const HaulTruck& t) const;
    double simulatedSeconds() const { return m_simTime; }

private:
    void startRoute(HaulTruck& t, const std::vector<RouteLeg>& legs, HaulPhase phase);
    // Drives the truck from where it is to `area` along the ways `route` names (RouteV1, checked from its
    // current way onwards) or, without one or when it no longer holds, the shortest route; false when the
    // area cannot be reached.
    bool driveTo(HaulTruck& t, std::int64_t area, const std::optional<std::vector<iso23725::WayRef>>& route);
    // The drive over `ways` (connected, from the truck's current way to the destination area): the rest of
    // the current way from the truck's position, the roads between in their travel direction, to where the
    // last road meets the area (a park area: on into the truck's parking slot).
    Route routeAlong(const HaulTruck& t, const std::vector<std::int64_t>& ways) const;
    // At the end of the drive to a load or dump area: spot when the area is free, else queue.
    void reachArea(HaulTruck& t);
    void startSpotting(HaulTruck& t);
    // The truck left its area (or its queue): the next one waiting there spots.
    void releaseArea(HaulTruck& t);
    EnuPoint spotOf(const HaulTruck& t, std::int64_t area) const;
    void changeState(HaulTruck& t, const std::string& state); // production state + the cycle's state log
    void arrive(HaulTruck& t);
    void leave(HaulTruck& t);
    std::int64_t areaOf(const HaulTruck& t) const;
    void setProduction(HaulTruck& t, const std::string& state);
    void emitProduction(HaulTruck& t); // HaulTruckProductionStateV2 now (and the way it reports)
    iso23725::HaulTruckProductionStateSensorV1 sensor(const HaulTruck& t) const;
    void updateSensor(HaulTruck& t);
    void reportHealth(HaulTruck& t);
    // Why the AHS cannot do `a` starting from way `from` (empty: it can).
    std::string cannotDo(const HaulTruck& t, const iso23725::AssignmentItem& a, std::int64_t from) const;
    void setCustodian(HaulTruck& t, const std::string& actor);
    // The FMS's work ran out: the AHS takes the truck to the park area, then hands it back (asks for work).
    void goIdle(HaulTruck& t);

    const PitMap& m_map;
    HaulFleetConfig m_cfg;
    Counters& m_counters;
    Emit m_emit;
    UnixClock m_now;
    GeoFrame m_frame;
    std::mt19937 m_rng;
    std::vector<HaulTruck> m_trucks;
    bool m_allStopOn = false;
    std::set<std::int64_t> m_closedWays;
    iso23725::MapConnectivityV1 m_connectivity; // the map's, without connections into closed ways
    iso23725::RouteGraph m_routes;
    // Per load/dump area: the truck spotting, loading or dumping there (index, -1 none) and the trucks queued
    // at its entry in arrival order. One truck at a time under a shovel, on a tip, at the crusher.
    struct AreaQueue {
        int inside = -1;
        std::vector<int> waiting;
    };
    std::map<std::int64_t, AreaQueue> m_areaQueues;
    double m_simTime = 0;
};

} // namespace ocu::sim
