// The simulated AHS's haul fleet on its own, on a fake clock and without sockets: trucks run load-haul-dump
// cycles over the generated pit (only over connected ways, reporting payloads, dumps, cycles and production
// states in order), all-stop and manual mode hold them, assignments are checked against the map, and what
// they report is deterministic for a seed.
#include "sim/iso23725/HaulFleet.h"
#include "sim/iso23725/PitMapGenerator.h"

#include "protocols/iso23725/MapModel.h"

#include "protocols/common/Clock.h"

#include <QtTest>

#include <chrono>
#include <cmath>
#include <map>
#include <set>

using namespace ocu;
using namespace ocu::iso23725;
using namespace ocu::sim;
using namespace std::chrono_literals;

namespace {

constexpr std::int64_t kEpochMs = 1'741'918'507'000;

struct Emitted {
    Body body;
    Guid equipmentId;
};

// A fleet on a generated pit, driven by tick() with a fake clock advanced by the same simulated time.
struct Site {
    explicit Site(int trucks = 6, std::uint32_t seed = 1, bool health = true)
        : pit(generatePitMap({2, 2, {}}, kEpochMs)),
          fleet(
              pit, {trucks, seed, health}, counters,
              [this](const Body& b, const Guid& eq) {
                  out.push_back({b, eq});
              },
              [this] {
                  return kEpochMs +
                         std::chrono::duration_cast<std::chrono::milliseconds>(clock.now() - start).count();
              }) {}

    void run(double seconds, double dt = 0.5) {
        for (double t = 0; t < seconds; t += dt) {
            clock.advance(std::chrono::duration_cast<Duration>(std::chrono::duration<double>(dt)));
            fleet.tick(dt);
        }
    }
    template <class T> std::vector<std::pair<T, Guid>> emitted() const {
        std::vector<std::pair<T, Guid>> v;
        for (const auto& e : out)
            if (auto* b = std::get_if<T>(&e.body))
                v.emplace_back(*b, e.equipmentId);
        return v;
    }
    template <class T> std::vector<T> emittedFor(const Guid& id) const {
        std::vector<T> v;
        for (const auto& [b, eq] : emitted<T>())
            if (eq == id)
                v.push_back(b);
        return v;
    }

    FakeClock clock;
    TimePoint start = clock.now();
    Counters counters;
    std::vector<Emitted> out;
    PitMap pit;
    HaulFleet fleet;
};

bool connected(const ConnectivityGraph& g, std::int64_t from, std::int64_t to) {
    auto next = g.successors(from);
    return std::find(next.begin(), next.end(), to) != next.end();
}

} // namespace

class TestHaulFleet : public QObject {
    Q_OBJECT
private slots:
    void trucksAreNamedAndSpreadOverTheirCycles() {
        Site s(12);
        QCOMPARE(s.fleet.trucks().size(), std::size_t(12));
        const auto eq = s.fleet.equipment();
        QCOMPARE(eq.front().hid, std::string("HT101"));
        QCOMPARE(eq.back().hid, std::string("HT112"));
        std::set<Guid> ids;
        for (const auto& e : eq) {
            QVERIFY(isGuid(e.equipmentId));
            QCOMPARE(e.type, std::string("HaulTruck"));
            QVERIFY(e.autonomous);
            ids.insert(e.equipmentId);
        }
        QCOMPARE(ids.size(), std::size_t(12));
        // The same seed gives the same GUIDs (a restarted simulator is the same fleet), another seed others.
        Site again(12), other(12, 2);
        QCOMPARE(again.fleet.equipment().front().equipmentId, eq.front().equipmentId);
        QVERIFY(other.fleet.equipment().front().equipmentId != eq.front().equipmentId);
        // Trucks start on their way somewhere (not all at the start of the same route).
        std::set<double> distances;
        for (const auto& t : s.fleet.trucks()) {
            QVERIFY(t.phase == HaulPhase::ToLoad || t.phase == HaulPhase::ToDump);
            QVERIFY(!t.motion.route().empty());
            distances.insert(t.motion.distance());
        }
        QVERIFY(distances.size() > 6);
        QVERIFY(s.out.empty()); // nothing reported before the first tick
    }

    // Two hours of simulated haulage: every truck completes cycles; each cycle is a payload, then a dump of
    // that payload at a dump area, then the production cycle naming the shovel's load area and that dump;
    // trucks only ever drive over ways the connectivity connects; speeds stay within the trucks' cruise.
    void cyclesOverConnectedWays() {
        Site s(6, 3, false);
        ConnectivityGraph g;
        g.assign(s.pit.connectivity);
        double maxSpeed = 0;
        for (int step = 0; step < 2 * 3600 * 2; ++step) {
            s.run(0.5);
            for (const auto& t : s.fleet.trucks()) {
                maxSpeed = std::max(maxSpeed, t.motion.speed());
                const auto& ways = t.motion.route().legWays();
                for (std::size_t i = 0; i + 1 < ways.size(); ++i)
                    QVERIFY2(connected(g, ways[i], ways[i + 1]),
                             qPrintable(QStringLiteral("%1 -> %2").arg(ways[i]).arg(ways[i + 1])));
            }
        }
        QVERIFY(maxSpeed <= 12.0);
        QVERIFY(maxSpeed > 8.0);
        for (const auto& t : s.fleet.trucks()) {
            const auto payloads = s.emittedFor<HaulTruckPayloadV1>(t.id);
            const auto dumps = s.emittedFor<HaulTruckDumpV1>(t.id);
            const auto cycles = s.emittedFor<HaulTruckProductionCycleV1>(t.id);
            QVERIFY2(cycles.size() >= 3, qPrintable(QString::fromStdString(t.hid)));
            QCOMPARE(dumps.size(), cycles.size());
            QVERIFY(payloads.size() + 1 >= cycles.size()); // a truck may start loaded, hauling
            for (std::size_t i = 0; i < cycles.size(); ++i) {
                QCOMPARE(cycles[i].payloadWeight, dumps[i].dumpedWeight);
                QCOMPARE(cycles[i].dumpWayId, dumps[i].wayId);
                QVERIFY(s.pit.dumpIndex(dumps[i].wayId) >= 0);
                QVERIFY(s.pit.loadIndex(cycles[i].loadWayId) >= 0);
                QVERIFY(*dumps[i].dumpedWeight >= 220 && *dumps[i].dumpedWeight < 300);
            }
        }
    }

    // The production states a truck reports follow the cycle: driving empty to a shovel, queueing when
    // another truck is there, spotting, loading, hauling, (queueing,) spotting, dumping, and round again;
    // each state is reported once, when it changes.
    void productionStatesFollowTheCycle() {
        Site s(4, 5, false);
        s.run(3600);
        const std::map<std::string, std::set<std::string>> next = {
            {"Driving", {"Queued", "Spotting"}},  {"Queued", {"Spotting"}},
            {"Spotting", {"Loading", "Dumping"}}, {"Loading", {"Hauling"}},
            {"Hauling", {"Queued", "Spotting"}},  {"Dumping", {"Driving"}}};
        for (const auto& t : s.fleet.trucks()) {
            const auto states = s.emittedFor<HaulTruckProductionStateV2>(t.id);
            QVERIFY(states.size() >= 8);
            int wayChanges = 0;
            for (std::size_t i = 0; i + 1 < states.size(); ++i) {
                const auto& a = states[i].productionState;
                const auto& b = states[i + 1].productionState;
                if (a == b) { // the same state on the next way (WayId is part of the state, §5 #17)
                    QVERIFY(states[i].wayId != states[i + 1].wayId);
                    ++wayChanges;
                    continue;
                }
                QVERIFY2(next.at(a).count(b), qPrintable(QString::fromStdString(a + " -> " + b)));
                QCOMPARE(states[i].autonomyMode, std::string("Autonomous"));
            }
            QVERIFY(wayChanges > 0);
        }
    }

    // The cycle's duration is measured on the clock the fleet was given (here the fake one).
    void cycleTimesUseTheGivenClock() {
        Site s(3, 1, false);
        s.run(3600);
        for (const auto& t : s.fleet.trucks()) {
            const auto cycles = s.emittedFor<HaulTruckProductionCycleV1>(t.id);
            QVERIFY(cycles.size() >= 2);
            // From the second cycle on, a cycle starts where the previous one ended, and its states follow
            // each other without gaps: return (Driving), [Queued], Spotting, Loading 30 s, Hauling, [Queued],
            // Spotting, Dumping 15 s.
            for (std::size_t i = 1; i < cycles.size(); ++i) {
                const auto& prev = cycles[i - 1].stateTimes.back();
                const auto& states = cycles[i].stateTimes;
                QVERIFY(states.size() >= 6);
                const std::int64_t prevEnd = *prev.start.unixMs + std::int64_t(*prev.duration * 1000);
                QVERIFY(std::llabs(*states.front().start.unixMs - prevEnd) <= 100);
                QCOMPARE(states.front().productionState, std::string("Driving"));
                QCOMPARE(states.back().productionState, std::string("Dumping"));
                double total = 0;
                std::map<std::string, double> by;
                for (std::size_t k = 0; k < states.size(); ++k) {
                    QVERIFY(states[k].duration.has_value());
                    if (k > 0) {
                        const std::int64_t end =
                            *states[k - 1].start.unixMs + std::llround(*states[k - 1].duration * 1000);
                        QVERIFY(std::llabs(*states[k].start.unixMs - end) <= 100);
                    }
                    total += *states[k].duration;
                    by[states[k].productionState] += *states[k].duration;
                }
                QVERIFY(total > 60);
                QVERIFY(std::abs(by["Loading"] - 30) <= 1);
                QVERIFY(std::abs(by["Dumping"] - 15) <= 1);
                QVERIFY(by["Spotting"] > 5);
                QVERIFY(by["Hauling"] > 60);
                QVERIFY(*states.front().start.unixMs >= kEpochMs &&
                        *states.front().start.unixMs < kEpochMs + 3'600'000);
            }
        }
    }

    // One truck at a time under a shovel and on a tip; the others queue at the entry (reported
    // Queued) and spot in arrival order when it leaves.
    void trucksQueueAtShovelsAndDumps() {
        Site s(10, 4, false);
        int maxQueue = 0;
        for (int step = 0; step < 3600 * 2; ++step) {
            s.run(0.5);
            std::map<std::int64_t, int> inside, queued;
            for (const auto& t : s.fleet.trucks()) {
                if (t.phase == HaulPhase::Spotting || t.phase == HaulPhase::Loading ||
                    t.phase == HaulPhase::Dumping)
                    QVERIFY2(++inside[t.area] == 1, qPrintable(QStringLiteral("area %1").arg(t.area)));
                if (t.phase == HaulPhase::Queued) {
                    maxQueue = std::max(maxQueue, ++queued[t.area]);
                    QCOMPARE(t.productionState, std::string("Queued"));
                    QCOMPARE(t.motion.speed(), 0.0);
                }
            }
        }
        QVERIFY(maxQueue >= 1);
        // Queue time is part of the cycles the trucks report.
        double queued = 0;
        for (const auto& [c, eq] : s.emitted<HaulTruckProductionCycleV1>())
            for (const auto& st : c.stateTimes)
                if (st.productionState == "Queued")
                    queued += *st.duration;
        QVERIFY(queued > 0);
    }

    // An assigned task is driven along its RouteV1 from where the truck is: the drive's ways are
    // the truck's way, the route's ways and the destination's, and every position lies on those ways.
    void assignedRouteIsDriven() {
        Site s(1, 1, false);
        const Guid id = s.fleet.trucks()[0].id;
        // Once it drives empty towards its shovel, send it to the other one: it turns at once.
        for (int step = 0; step < 7200 && s.fleet.trucks()[0].phase != HaulPhase::ToLoad; ++step)
            s.run(0.5);
        QCOMPARE(s.fleet.trucks()[0].phase, HaulPhase::ToLoad);
        const int shovel = s.fleet.trucks()[0].shovel == 0 ? 1 : 0;
        const std::int64_t from = s.fleet.trucks()[0].motion.wayId();
        RouteGraph g(s.pit.connectivity);
        const auto r = shortestRoute(g, from, s.pit.loadAreas[shovel]);
        QVERIFY(r.ok);
        HaulTruckAssignmentRequestV2 req;
        req.items.push_back({"r-load", "Load", s.pit.loadAreas[shovel], {}, {}, r.routeV1()});
        s.fleet.assign(id, req);
        QCOMPARE(s.emitted<HaulTruckAssignmentResponseV1>().back().first.items[0].response,
                 std::string("Accepted"));
        std::set<std::int64_t> allowed(r.ways.begin(), r.ways.end());
        bool loaded = false;
        double maxOff = 0;
        for (int step = 0; step < 3600 && !loaded; ++step) {
            s.run(0.5);
            const auto& t = s.fleet.trucks()[0];
            QVERIFY(t.phase != HaulPhase::ToDump);
            if (t.phase == HaulPhase::ToLoad) {
                QVERIFY2(allowed.count(t.motion.wayId()) || t.motion.wayId() == from,
                         qPrintable(QString::number(t.motion.wayId())));
                // On the way's polyline (within a couple of metres of one of its stretches).
                const auto pts = s.pit.wayPoints(t.motion.wayId(), false);
                double best = 1e9;
                for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
                    const auto& a = pts[k];
                    const auto& b = pts[k + 1];
                    const double l2 = (b.e - a.e) * (b.e - a.e) + (b.n - a.n) * (b.n - a.n);
                    const auto& p = t.motion.position();
                    double f = l2 > 0 ? ((p.e - a.e) * (b.e - a.e) + (p.n - a.n) * (b.n - a.n)) / l2 : 0;
                    f = std::clamp(f, 0.0, 1.0);
                    best =
                        std::min(best, std::hypot(p.e - a.e - f * (b.e - a.e), p.n - a.n - f * (b.n - a.n)));
                }
                maxOff = std::max(maxOff, best);
            }
            loaded = t.phase == HaulPhase::Loading && t.area == s.pit.loadAreas[shovel];
        }
        QVERIFY(loaded);
        QVERIFY2(maxOff < 10, qPrintable(QString::number(maxOff))); // junctions are a few metres apart
        QVERIFY(s.counters.get("sim.route.assigned") >= 1);
    }

    // All-stop: every autonomous truck reports AllStop, brakes (at most 3 m/s²) to a standstill it holds,
    // reports Stopped and its park brake; released, they drive on.
    void allStopHoldsTheFleet() {
        Site s(6, 1, false);
        s.run(60);
        std::vector<double> before;
        for (const auto& t : s.fleet.trucks())
            before.push_back(t.motion.speed());
        s.out.clear();
        s.fleet.setAllStop(true);
        QVERIFY(s.fleet.allStopOn());
        const auto modes = s.emitted<MachineAutonomyModeV1>();
        QCOMPARE(modes.size(), s.fleet.trucks().size());
        for (const auto& [m, eq] : modes)
            QCOMPARE(m.autonomyMode, std::string("AllStop"));
        s.run(0.5);
        for (std::size_t i = 0; i < before.size(); ++i)
            QVERIFY(s.fleet.trucks()[i].motion.speed() >= before[i] - 3.0 * 0.5 - 1e-9);
        s.run(5);
        std::vector<double> held;
        for (const auto& t : s.fleet.trucks()) {
            QCOMPARE(t.motion.speed(), 0.0);
            QVERIFY(*t.sensorSent.parkBrake);
            held.push_back(t.motion.distance());
            if (t.phase == HaulPhase::ToLoad || t.phase == HaulPhase::ToDump)
                QCOMPARE(t.productionState, std::string("Stopped"));
        }
        s.run(120); // loading and dumping pause too
        for (std::size_t i = 0; i < held.size(); ++i)
            QCOMPARE(s.fleet.trucks()[i].motion.distance(), held[i]);
        s.fleet.setAllStop(false);
        s.run(10);
        int moving = 0;
        for (const auto& t : s.fleet.trucks()) {
            moving += t.motion.speed() > 0 ? 1 : 0;
            QVERIFY(t.productionState != "Stopped");
        }
        QVERIFY(moving > 0);
    }

    // A truck in manual is held by its driver; the rest of the fleet drives on.
    void manualTruckIsHeld() {
        Site s(4, 1, false);
        s.run(30);
        s.out.clear();
        s.fleet.setManual(1, true);
        const auto modes = s.emitted<MachineAutonomyModeV1>();
        QCOMPARE(modes.size(), std::size_t(1));
        QCOMPARE(modes.front().first.autonomyMode, std::string("Manual"));
        QCOMPARE(modes.front().second, s.fleet.trucks()[1].id);
        s.run(20);
        QCOMPARE(s.fleet.trucks()[1].motion.speed(), 0.0);
        QCOMPARE(s.fleet.autonomyMode(s.fleet.trucks()[1]), std::string("Manual"));
        QVERIFY(s.fleet.trucks()[0].motion.speed() > 0 || s.fleet.trucks()[2].motion.speed() > 0);
        s.fleet.setManual(1, false);
        s.run(10);
        QCOMPARE(s.fleet.autonomyMode(s.fleet.trucks()[1]), std::string("Autonomous"));
        s.fleet.setManual(99, true); // no such truck: nothing happens
    }

    // Assignments (§13.3) are checked against the map; accepted ones become the truck's queue (the first
    // Active), are completed at their destination, and a reset cancels the current one.
    void assignmentsAreCheckedCompletedAndCancelled() {
        Site s(2, 1, false);
        const Guid id = s.fleet.trucks()[0].id;
        HaulTruckAssignmentRequestV2 req;
        req.items.push_back({"a-load", "Load", s.pit.loadAreas[1], {}, {}, {}});
        req.items.push_back({"a-dump", "Offload", s.pit.dumpAreas.back(), {}, {}, {}}); // the crusher
        req.items.push_back({"a-bad", "Load", s.pit.dumpAreas[0], {}, {}, {}});
        req.items.push_back({"a-fuel", "Fuel", s.pit.parkArea, {}, {}, {}});
        s.fleet.assign(id, req);
        const auto resp = s.emitted<HaulTruckAssignmentResponseV1>();
        QCOMPARE(resp.size(), std::size_t(1));
        QCOMPARE(resp[0].second, id);
        const auto& items = resp[0].first.items;
        QCOMPARE(items.size(), std::size_t(4));
        QCOMPARE(items[0].response, std::string("Accepted"));
        QCOMPARE(items[1].response, std::string("Accepted"));
        QCOMPARE(items[2].response, std::string("Rejected"));
        QVERIFY(items[2].detail->find("not a load area") != std::string::npos);
        QCOMPARE(items[3].response, std::string("Rejected"));
        QVERIFY(items[3].detail->find("not supported") != std::string::npos);
        auto status = s.emittedFor<HaulTruckAssignmentV1>(id);
        QCOMPARE(status.size(), std::size_t(1));
        QCOMPARE(status[0].status, std::string("Active"));
        QCOMPARE(status[0].assignmentId, std::optional<Guid>("a-load"));
        QCOMPARE(s.fleet.trucks()[0].assignments.size(), std::size_t(2));

        // Drive until both are done: loaded at shovel 2, dumped at the crusher.
        s.run(2 * 3600);
        status = s.emittedFor<HaulTruckAssignmentV1>(id);
        QVERIFY(status.size() >= 4);
        QCOMPARE(status[1].status, std::string("Completed"));
        QCOMPARE(status[1].assignmentId, std::optional<Guid>("a-load"));
        QCOMPARE(status[2].status, std::string("Active"));
        QCOMPARE(status[2].assignmentId, std::optional<Guid>("a-dump"));
        QCOMPARE(status[3].status, std::string("Completed"));
        const auto dumps = s.emittedFor<HaulTruckDumpV1>(id);
        bool atCrusher = false;
        for (const auto& d : dumps)
            atCrusher = atCrusher || (d.assignmentId == std::optional<Guid>("a-dump") &&
                                      d.wayId == s.pit.dumpAreas.back());
        QVERIFY(atCrusher);

        // Unknown machines are refused; a reset cancels the current assignment.
        s.out.clear();
        s.fleet.assign("00000000-0000-4000-8000-000000000000", req);
        QCOMPARE(s.emitted<HaulTruckAssignmentResponseV1>()[0].first.items[0].detail,
                 std::optional<std::string>("unknown machine"));
        HaulTruckAssignmentRequestV2 park;
        park.items.push_back({"a-park", "Park", s.pit.parkArea, {}, {}, {}});
        s.fleet.assign(id, park);
        s.fleet.resetAssignments(id);
        status = s.emittedFor<HaulTruckAssignmentV1>(id);
        QCOMPARE(status.back().status, std::string("Cancelled"));
        QCOMPARE(status.back().assignmentId, std::optional<Guid>("a-park"));
        QVERIFY(s.fleet.trucks()[0].assignments.empty());
    }

    // A truck the AHS dispatches itself (custodian AHS) rejects the FMS's tasks with the reason;
    // handed back (AHS -> FMS) it takes them again.
    void custodianAhsRejects() {
        Site s(2, 1, false);
        const Guid id = s.fleet.trucks()[0].id;
        s.fleet.setCustodian(0, "AHS");
        auto avail = s.emittedFor<MachineDispatchAvailabilityV1>(id);
        QCOMPARE(avail.size(), std::size_t(1));
        QCOMPARE(avail[0].dispatchingCustodian, std::string("AHS"));
        HaulTruckAssignmentRequestV2 req;
        req.items.push_back({"c-load", "Load", s.pit.loadAreas[0], {}, {}, {}});
        s.fleet.assign(id, req);
        auto resp = s.emitted<HaulTruckAssignmentResponseV1>();
        QCOMPARE(resp.back().first.items[0].response, std::string("Rejected"));
        QCOMPARE(*resp.back().first.items[0].detail,
                 std::string("DispatchingCustodian is AHS: HT101 is dispatched by the AHS"));
        QVERIFY(s.fleet.trucks()[0].assignments.empty());
        s.fleet.setCustodian(0, "FMS");
        s.fleet.assign(id, req);
        QCOMPARE(s.emitted<HaulTruckAssignmentResponseV1>().back().first.items[0].response,
                 std::string("Accepted"));
    }

    // A closed way makes destinations behind it unreachable: new tasks are rejected with the
    // reason, accepted ones are given up with an unsolicited Rejected and the current one Cancelled, and the
    // AHS's MapConnectivityV1 goes out again without the connections into the closed way.
    void closedWayRejectsAndWithdraws() {
        Site s(2, 1, false);
        const Guid id = s.fleet.trucks()[0].id;
        HaulTruckAssignmentRequestV2 req;
        req.items.push_back({"w-load", "Load", s.pit.loadAreas[1], {}, {}, {}});
        req.items.push_back({"w-dump", "Offload", s.pit.dumpAreas[0], {}, {}, {}});
        s.fleet.assign(id, req);
        QCOMPARE(s.fleet.trucks()[0].assignments.size(), std::size_t(2));
        s.out.clear();
        s.fleet.setWayClosed(s.pit.loadRoads[1], true);
        const auto conn = s.emitted<MapConnectivityV1>();
        QCOMPARE(conn.size(), std::size_t(1));
        QVERIFY(conn[0].second.empty()); // not about one truck
        for (const auto& item : conn[0].first.items)
            for (const auto& c : item.connection)
                QVERIFY(c.wayId != s.pit.loadRoads[1]);
        const auto lost = s.emittedFor<HaulTruckAssignmentResponseV1>(id);
        QCOMPARE(lost.size(), std::size_t(1));
        QCOMPARE(lost[0].items.size(), std::size_t(2)); // the load and the dump queued after it
        QCOMPARE(lost[0].items[0].assignmentId, Guid("w-load"));
        QCOMPARE(lost[0].items[0].response, std::string("Rejected"));
        QVERIFY2(lost[0].items[0].detail->find("can no longer be done: destination way") != std::string::npos,
                 lost[0].items[0].detail->c_str());
        const auto status = s.emittedFor<HaulTruckAssignmentV1>(id);
        QCOMPARE(status.back().status, std::string("Cancelled"));
        QCOMPARE(status.back().assignmentId, std::optional<Guid>("w-load"));
        QVERIFY(s.fleet.trucks()[0].assignments.empty());
        QCOMPARE(s.counters.get("sim.assign.withdrawn"), std::uint64_t(1));
        // New tasks there are rejected as unreachable; the other shovel is fine.
        s.out.clear();
        HaulTruckAssignmentRequestV2 again;
        again.items.push_back({"u-load", "Load", s.pit.loadAreas[1], {}, {}, {}});
        again.items.push_back({"o-load", "Load", s.pit.loadAreas[0], {}, {}, {}});
        s.fleet.assign(id, again);
        const auto r = s.emitted<HaulTruckAssignmentResponseV1>().back().first.items;
        QCOMPARE(r[0].response, std::string("Rejected"));
        QVERIFY2(r[0].detail->find("unreachable from way") != std::string::npos, r[0].detail->c_str());
        QCOMPARE(r[1].response, std::string("Accepted"));
        // Reopened: the connectivity is whole again.
        s.out.clear();
        s.fleet.setWayClosed(s.pit.loadRoads[1], false);
        QCOMPARE(s.emitted<MapConnectivityV1>().back().first, s.pit.connectivity);
    }

    // When the FMS's work runs out the AHS parks the truck (custodian AHS meanwhile), then hands
    // it back (custodian FMS: "send me an assignment", §8.3.4) and it waits parked for the next task.
    void idleTruckAsksForWork() {
        Site s(1, 1, false);
        const Guid id = s.fleet.trucks()[0].id;
        HaulTruckAssignmentRequestV2 req;
        req.items.push_back({"i-load", "Load", s.pit.loadAreas[0], {}, {}, {}});
        s.fleet.assign(id, req);
        s.run(3600);
        const auto avail = s.emittedFor<MachineDispatchAvailabilityV1>(id);
        QCOMPARE(avail.size(), std::size_t(2));
        QCOMPARE(avail[0].dispatchingCustodian, std::string("AHS"));
        QCOMPARE(avail[1].dispatchingCustodian, std::string("FMS"));
        const auto& t = s.fleet.trucks()[0];
        QVERIFY(t.idle);
        QCOMPARE(t.phase, HaulPhase::Parked);
        QCOMPARE(t.productionState, std::string("Parked"));
        // It stays parked: no cycle of its own while it waits for the FMS.
        const auto cycles = s.emittedFor<HaulTruckProductionCycleV1>(id).size();
        s.run(1800);
        QCOMPARE(s.emittedFor<HaulTruckProductionCycleV1>(id).size(), cycles);
        QCOMPARE(s.fleet.trucks()[0].phase, HaulPhase::Parked);
        // The next task gets it moving.
        HaulTruckAssignmentRequestV2 next;
        next.items.push_back({"i-dump", "Offload", s.pit.dumpAreas[0], {}, {}, {}});
        s.fleet.assign(id, next);
        s.run(5);
        QVERIFY(s.fleet.trucks()[0].phase != HaulPhase::Parked);
        QVERIFY(!s.fleet.trucks()[0].idle);
    }

    // The sensor inputs are sent when they change, never repeated; health comes every 30 s per truck.
    void sensorOnChangeHealthPeriodic() {
        Site s(3, 4, true);
        s.run(600);
        for (const auto& t : s.fleet.trucks()) {
            const auto sensors = s.emittedFor<HaulTruckProductionStateSensorV1>(t.id);
            QVERIFY(!sensors.empty());
            for (std::size_t i = 0; i + 1 < sensors.size(); ++i)
                QVERIFY(!(sensors[i] == sensors[i + 1]));
            QVERIFY(sensors.back() == t.sensorSent);
            const auto health = s.emittedFor<BasicMachineHealthV2>(t.id);
            QVERIFY(health.size() >= 19 && health.size() <= 21); // 600 s / 30 s
            QCOMPARE(health.back().tire->size(), std::size_t(6));
        }
        QCOMPARE(s.counters.get("sim.tx.sensor"),
                 std::uint64_t(s.emitted<HaulTruckProductionStateSensorV1>().size()));
    }

    // The same seed and steps give the same fleet, message for message.
    void deterministicForASeed() {
        Site a(5, 9), b(5, 9);
        a.run(900);
        b.run(900);
        QCOMPARE(a.out.size(), b.out.size());
        for (std::size_t i = 0; i < a.out.size(); ++i) {
            QCOMPARE(a.out[i].equipmentId, b.out[i].equipmentId);
            QCOMPARE(a.out[i].body.index(), b.out[i].body.index());
        }
        for (std::size_t i = 0; i < a.fleet.trucks().size(); ++i) {
            QCOMPARE(a.fleet.trucks()[i].motion.distance(), b.fleet.trucks()[i].motion.distance());
            QCOMPARE(a.fleet.trucks()[i].productionState, b.fleet.trucks()[i].productionState);
        }
    }

    // The position report is the truck's pose on the globe, rounded as on the wire.
    void positionReport() {
        Site s(1);
        s.run(20);
        const auto& t = s.fleet.trucks()[0];
        const MachinePositionV1 p = s.fleet.position(t);
        const EnuPoint back =
            GeoFrame(s.pit.map.origin).toLocal({*p.pose.latitude, *p.pose.longitude, *p.pose.elevation});
        QVERIFY(std::hypot(back.e - t.motion.position().e, back.n - t.motion.position().n) < 0.03);
        QCOMPARE(*p.pose.speed, std::int64_t(std::lround(t.motion.speed() * 3.6)));
        QVERIFY(*p.pose.heading >= 0 && *p.pose.heading < 360);
        QCOMPARE(*p.timestamp.unixMs, kEpochMs + 20'000);
    }
};

QTEST_GUILESS_MAIN(TestHaulFleet)
#include "test_haul_fleet.moc"
