#include "sim/iso23725/SimulatedAhs.h"

#include "protocols/iso23725/MapModel.h"

#include "protocols/common/IoThread.h"
#include "protocols/common/Log.h"

#include <boost/asio/steady_timer.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <thread>

namespace ocu::sim {

using namespace ocu::iso23725;

namespace {

constexpr const char* kLog = "ocu.sim.iso";
constexpr double kPi = 3.14159265358979323846;

std::int64_t nowMs() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}

// Stable GUIDs from a seed and an index (v4 layout).
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

struct Leg {
    std::int64_t wayId;
    bool reversed;
};

enum class Phase { Parked, ToLoad, Loading, ToDump, Dumping, ToPark };

struct Truck {
    Guid id;
    std::string hid;
    bool autonomous = true;
    bool manual = false;
    // route being driven: polyline in ENU and the ways it follows
    std::vector<EnuPoint> path;
    std::vector<std::size_t> wayStartIndex; // index into path where each leg starts
    std::vector<std::int64_t> legWays;
    double s = 0;     // distance along path
    double speed = 0; // m/s
    double cruise = 11.0;
    Phase phase = Phase::Parked;
    double dwell = 0;
    int shovel = 0;
    int dump = 0; // dumpCount = crusher
    int payload = 0;
    std::int64_t currentWay = 0;
    EnuPoint pos;
    double headingDeg = 0;
    std::string productionState = "Parked";
    std::vector<AssignmentItem> assignments; // queue (first = current)
    Guid cycleId;
    std::int64_t cycleStartMs = 0;
    double fuel = 80;
    double engineHours = 12000;
    std::vector<DiagnosticEntry> faults;
    double nextHealth = 0;
    HaulTruckProductionStateSensorV1 sensorSent; // last HaulTruckProductionStateSensorV1 sent (on change)
};

// Per-session bookkeeping; one table per socket because session ids are per endpoint.
struct SessionState {
    bool gotFirst = false;
    // Frame counts since the session opened, reported in InterfaceDiagnosticV1 (§5 row 15 [I]).
    std::uint64_t received = 0, sent = 0, rejected = 0;
    std::unique_ptr<boost::asio::steady_timer> diagTimer;
};

enum class Sock { Main, Map };

// The member name a codec error message starts with ("MachineAutonomyModeV1.AutonomyMode: ..."), if any.
std::optional<std::string> memberOfError(const std::string& error) {
    std::size_t n = 0;
    while (n < error.size() && std::isalnum(static_cast<unsigned char>(error[n])))
        ++n;
    if (n == 0 || error.compare(0, n, "message") == 0 || error.compare(0, n, "header") == 0)
        return std::nullopt;
    return error.substr(0, n);
}

// Members only the AHS (or its map service) sends (§5 "Dir"): the FMS sending one is an interface error.
bool onlyAhsSends(const Body& b) {
    return std::visit(
        [](auto&& m) {
            using T = std::decay_t<decltype(m)>;
            return !(std::is_same_v<T, FleetDefinitionV2> || std::is_same_v<T, MachineAllStopRequestV1> ||
                     std::is_same_v<T, MachinePositionV1> || std::is_same_v<T, MapCommandV1> ||
                     std::is_same_v<T, InterfaceDiagnosticV1> ||
                     std::is_same_v<T, HaulTruckAssignmentRequestV2> ||
                     std::is_same_v<T, HaulTruckAssignmentResetV1> || std::is_same_v<T, UnknownMember>);
        },
        b);
}

} // namespace

struct SimulatedAhs::Impl : WsHandler {
    Impl(SimulatedAhsConfig c, Counters& counters)
        : cfg(std::move(c)), counters(counters), io("sim-iso23725"), timer(io.context()), frame(cfg.origin),
          rng(cfg.seed) {}

    SimulatedAhsConfig cfg;
    Counters& counters;
    IoThread io;
    boost::asio::steady_timer timer;
    GeoFrame frame;
    std::mt19937 rng;
    std::unique_ptr<WsEndpoint> ep;
    std::unique_ptr<WsEndpoint> mapEp; // separate map service (Q10), null when the map shares the main socket
    std::map<SessionId, SessionState> sessions, mapSessions;
    std::vector<std::string> fmsFirst;

    // Forwards the map service's callbacks (its own session ids) to the Impl.
    struct MapSide : WsHandler {
        explicit MapSide(Impl& impl) : d(impl) {}
        Impl& d;
        void onOpen(SessionId id, const std::string& peer) override { d.onMapOpen(id, peer); }
        void onText(SessionId id, std::string text) override { d.onFrame(Sock::Map, id, text); }
        void onClose(SessionId id, const std::string& reason) override { d.onMapClose(id, reason); }
    } mapSide{*this};

    MapModel map;
    std::int64_t changeSetMap = 18000, changeSetWay = 3100;
    std::int64_t mapModifiedMs = 0;
    MapConnectivityV1 connectivity;
    std::vector<std::int64_t> loadAreas, dumpAreas, loadRoads, dumpRoads; // dumps include the crusher (last)
    std::int64_t parkArea = 0, parkRoad = 0, rampDown = 0, rampUp = 0;
    std::vector<Truck> trucks;
    bool allStopOn = false;
    std::optional<Guid> allStopId;
    std::uint64_t positionsSent = 0, framesReceived = 0;
    double simTime = 0;

    // ------------------------------------------------------------ map generation
    std::int64_t nextNode = 700001;
    std::int64_t addNode(const EnuPoint& p) {
        MapNode n;
        n.id = nextNode++;
        auto g = frame.toGeodetic(p);
        n.lat = std::round(g.lat * 1e7) / 1e7;
        n.lon = std::round(g.lon * 1e7) / 1e7;
        n.ele = std::round((cfg.origin.alt + p.u) * 100) / 100;
        n.enu = p;
        map.nodes[n.id] = n;
        return n.id;
    }
    // A polyline way with nodes about every 25 m.
    std::int64_t addRoad(std::int64_t id, const std::vector<EnuPoint>& pts, Tags tags) {
        MapWay w;
        w.id = id;
        for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
            double len = std::hypot(pts[i + 1].e - pts[i].e, pts[i + 1].n - pts[i].n);
            int steps = std::max(1, static_cast<int>(len / 25.0));
            for (int k = 0; k < steps; ++k) {
                double t = static_cast<double>(k) / steps;
                w.nodes.push_back(addNode({pts[i].e + t * (pts[i + 1].e - pts[i].e),
                                           pts[i].n + t * (pts[i + 1].n - pts[i].n),
                                           pts[i].u + t * (pts[i + 1].u - pts[i].u)}));
            }
        }
        w.nodes.push_back(addNode(pts.back()));
        w.tags = std::move(tags);
        w.kind = w.tags.count("oneway") && w.tags["oneway"] == "yes" ? WayKind::Lane : WayKind::Road;
        w.changeset = changeSetWay;
        map.ways[id] = w;
        return id;
    }
    std::int64_t addArea(std::int64_t id, const EnuPoint& c, double half, Tags tags) {
        MapWay w;
        w.id = id;
        std::vector<EnuPoint> corners = {{c.e - half, c.n - half, c.u},
                                         {c.e + half, c.n - half, c.u},
                                         {c.e + half, c.n + half, c.u},
                                         {c.e - half, c.n + half, c.u}};
        for (auto& p : corners)
            w.nodes.push_back(addNode(p));
        w.nodes.push_back(w.nodes.front());
        w.tags = std::move(tags);
        w.kind = WayKind::Area;
        w.changeset = changeSetWay;
        map.ways[id] = w;
        return id;
    }
    double wayLength(std::int64_t id) const {
        const auto& w = map.ways.at(id);
        double len = 0;
        for (std::size_t i = 0; i + 1 < w.nodes.size(); ++i) {
            auto& a = map.nodes.at(w.nodes[i]).enu;
            auto& b = map.nodes.at(w.nodes[i + 1]).enu;
            len += std::hypot(b.e - a.e, b.n - a.n, b.u - a.u);
        }
        return len;
    }

    void buildMap() {
        const int ns = std::max(1, cfg.shovelCount), nd = std::max(1, cfg.dumpCount);
        const EnuPoint hub{0, 200, 0}, bottom{0, -300, -60};
        // Haul ramp as two lanes (oneway=yes: node order is the travel direction, §8).
        std::vector<EnuPoint> down, up;
        for (int k = 0; k <= 10; ++k) {
            double t = k / 10.0;
            double bend = 90 * std::sin(kPi * t);
            down.push_back({-6 + bend, 200 - 500 * t, -60 * t});
            up.push_back({6 + bend, -300 + 500 * t, -60 + 60 * t});
        }
        rampDown = addRoad(3001, down,
                           {{"name", "Main ramp down"},
                            {"oneway", "yes"},
                            {"highway", "service"},
                            {"autonomy", "exclusive"}});
        rampUp = addRoad(
            3002, up,
            {{"name", "Main ramp up"}, {"oneway", "yes"}, {"highway", "service"}, {"autonomy", "exclusive"}});
        for (int i = 0; i < ns; ++i) {
            double x = ns == 1 ? 0 : -220 + 440.0 * i / (ns - 1);
            EnuPoint c{x, -470, -60};
            EnuPoint entry{x, -430, -60};
            loadRoads.push_back(addRoad(2101 + i, {bottom, {x * 0.5, -360, -60}, entry},
                                        {{"name", "Bench road " + std::to_string(i + 1)},
                                         {"highway", "service"},
                                         {"oneway", "no"},
                                         {"autonomy", "exclusive"}}));
            loadAreas.push_back(addArea(4101 + i, c, 40,
                                        {{"name", "Pit 1 shovel " + std::to_string(i + 1)},
                                         {"default_task", "load"},
                                         {"autonomy", "exclusive"},
                                         {"landuse", "quarry"}}));
        }
        for (int j = 0; j <= nd; ++j) {
            bool crusher = j == nd;
            double x = crusher ? 420 : (nd == 1 ? -300 : -500 + 400.0 * j / (nd - 1));
            EnuPoint c{x, crusher ? 320.0 : 560.0, 0};
            EnuPoint entry{x, crusher ? 280.0 : 520.0, 0};
            dumpRoads.push_back(addRoad(
                2201 + j, {hub, {x * 0.5, crusher ? 240.0 : 380.0, 0}, entry},
                {{"name", crusher ? std::string("Crusher road") : "Dump road " + std::to_string(j + 1)},
                 {"highway", "service"},
                 {"oneway", "no"},
                 {"autonomy", "mixed"}}));
            dumpAreas.push_back(addArea(
                4201 + j, c, crusher ? 25 : 50,
                {{"name", crusher ? std::string("Primary crusher") : "Waste dump " + std::to_string(j + 1)},
                 {"default_task", "offload"},
                 {"autonomy", "mixed"}}));
        }
        parkRoad =
            addRoad(2301, {hub, {-150, 180, 0}, {-300, 160, 0}},
                    {{"name", "Park road"}, {"highway", "service"}, {"oneway", "no"}, {"autonomy", "mixed"}});
        parkArea = addArea(4301, {-340, 160, 0}, 40,
                           {{"name", "Truck park"},
                            {"default_task", "park"},
                            {"autonomy", "mixed"},
                            {"amenity", "parking"}});
        addArea(4401, {0, -200, -30}, 700, {{"name", "Pit 1 AOZ"}, {"autonomy:area", "AOZ"}});
        // Directed connectivity (§9.1).
        auto road = [&](std::int64_t id, std::vector<std::int64_t> to) {
            ConnectivityItem c;
            c.wayId = id;
            c.wayType = "Road";
            c.roadLength = std::round(wayLength(id) * 10) / 10;
            c.roadName = map.ways.at(id).name();
            for (auto t : to)
                c.connection.push_back(WayRef{t});
            connectivity.items.push_back(c);
        };
        auto area = [&](std::int64_t id, const char* task, std::vector<std::int64_t> to) {
            ConnectivityItem c;
            c.wayId = id;
            c.wayType = "Area";
            c.areaDefaultTask = task;
            c.areaName = map.ways.at(id).name();
            for (auto t : to)
                c.connection.push_back(WayRef{t});
            connectivity.items.push_back(c);
        };
        std::vector<std::int64_t> fromHub = dumpRoads;
        fromHub.push_back(parkRoad);
        fromHub.push_back(rampDown);
        road(rampDown, loadRoads);
        std::vector<std::int64_t> upTo = fromHub;
        upTo.pop_back();
        road(rampUp, upTo);
        for (int i = 0; i < ns; ++i) {
            road(loadRoads[i], {loadAreas[i], rampUp});
            area(loadAreas[i], "Load", {loadRoads[i]});
        }
        for (std::size_t j = 0; j < dumpRoads.size(); ++j) {
            std::vector<std::int64_t> to = fromHub;
            to.erase(std::remove(to.begin(), to.end(), dumpRoads[j]), to.end());
            to.push_back(dumpAreas[j]);
            road(dumpRoads[j], to);
            area(dumpAreas[j], "Offload", {dumpRoads[j]});
        }
        std::vector<std::int64_t> parkTo = dumpRoads;
        parkTo.push_back(rampDown);
        parkTo.push_back(parkArea);
        road(parkRoad, parkTo);
        area(parkArea, "Park", {parkRoad});
        mapModifiedMs = nowMs();
        map.origin = cfg.origin;
    }

    std::vector<std::string> mapChunks() const {
        std::size_t total = map.nodes.size() + map.ways.size();
        std::size_t per =
            cfg.mapChunkElements ? cfg.mapChunkElements : (total + 3) / 4; // 4 chunks by default
        return writeOsmChunks(map, std::min<std::size_t>(per, 10000), changeSetMap, "ocu simulated AHS");
    }
    MapSummaryV1 summary() const {
        MapSummaryV1 s;
        s.timestamp = makeTimestamp(mapModifiedMs);
        s.changeSetMap = changeSetMap;
        s.changeSetWay = changeSetWay;
        s.uid = 1;
        s.nodeCount = static_cast<std::int64_t>(map.nodes.size());
        s.wayCount = static_cast<std::int64_t>(map.ways.size());
        s.documentCount = static_cast<std::int64_t>(mapChunks().size());
        return s;
    }

    // ------------------------------------------------------------ trucks
    void buildFleet() {
        std::uniform_real_distribution<double> u(0, 1);
        for (int i = 0; i < cfg.truckCount; ++i) {
            Truck t;
            t.id = stableGuid(cfg.seed, 1, static_cast<std::uint32_t>(i));
            char hid[16];
            std::snprintf(hid, sizeof hid, "HT%03d", 101 + i);
            t.hid = hid;
            t.shovel = i % std::max(1, cfg.shovelCount);
            t.dump = i % static_cast<int>(dumpAreas.size());
            t.cruise = 9.0 + 3.0 * u(rng);
            t.fuel = 40 + 60 * u(rng);
            t.nextHealth = 5 + 25 * u(rng);
            // Spread the fleet over the cycle so the site looks busy from the start.
            int start = static_cast<int>(u(rng) * 3);
            if (start == 0) {
                t.payload = 0;
                startRoute(t, {{dumpRoads[t.dump], true}, {rampDown, false}, {loadRoads[t.shovel], false}},
                           Phase::ToLoad);
            } else if (start == 1) {
                t.payload = 220 + static_cast<int>(u(rng) * 80);
                startRoute(t, {{loadRoads[t.shovel], true}, {rampUp, false}, {dumpRoads[t.dump], false}},
                           Phase::ToDump);
            } else {
                startRoute(t, {{parkRoad, true}, {rampDown, false}, {loadRoads[t.shovel], false}},
                           Phase::ToLoad);
            }
            t.s = u(rng) * pathLength(t) * 0.9;
            updatePose(t);
            t.cycleId = newGuid();
            t.cycleStartMs = nowMs();
            t.sensorSent = sensor(t); // the starting inputs: only changes are sent from here on
            trucks.push_back(std::move(t));
        }
    }

    static double pathLength(const Truck& t) {
        double len = 0;
        for (std::size_t i = 0; i + 1 < t.path.size(); ++i)
            len += std::hypot(t.path[i + 1].e - t.path[i].e, t.path[i + 1].n - t.path[i].n);
        return len;
    }

    void startRoute(Truck& t, const std::vector<Leg>& legs, Phase phase) {
        t.path.clear();
        t.wayStartIndex.clear();
        t.legWays.clear();
        for (auto& leg : legs) {
            const auto& w = map.ways.at(leg.wayId);
            t.wayStartIndex.push_back(t.path.size());
            t.legWays.push_back(leg.wayId);
            std::vector<std::int64_t> ids = w.nodes;
            if (leg.reversed)
                std::reverse(ids.begin(), ids.end());
            for (auto id : ids)
                t.path.push_back(map.nodes.at(id).enu);
        }
        t.s = 0;
        t.phase = phase;
        t.productionState = phase == Phase::ToDump ? "Hauling" : "Driving";
    }

    void updatePose(Truck& t) {
        double rem = t.s;
        for (std::size_t i = 0; i + 1 < t.path.size(); ++i) {
            auto& a = t.path[i];
            auto& b = t.path[i + 1];
            double len = std::hypot(b.e - a.e, b.n - a.n);
            if (rem <= len || i + 2 == t.path.size()) {
                double f = len > 0 ? std::clamp(rem / len, 0.0, 1.0) : 0.0;
                t.pos = {a.e + f * (b.e - a.e), a.n + f * (b.n - a.n), a.u + f * (b.u - a.u)};
                if (len > 0.01)
                    t.headingDeg = std::fmod(std::atan2(b.e - a.e, b.n - a.n) * 180 / kPi + 360.0, 360.0);
                std::size_t leg = 0;
                for (std::size_t k = 0; k < t.wayStartIndex.size(); ++k)
                    if (t.wayStartIndex[k] <= i)
                        leg = k;
                if (!t.legWays.empty())
                    t.currentWay = t.legWays[leg];
                return;
            }
            rem -= len;
        }
    }

    std::vector<Leg> legsTo(const Truck& t, std::int64_t area) {
        // From the area the truck is in (load i, dump j or park) to the target area.
        auto idx = [](const std::vector<std::int64_t>& v, std::int64_t x) {
            return static_cast<int>(std::find(v.begin(), v.end(), x) - v.begin());
        };
        std::vector<Leg> legs;
        bool atLoad = t.phase == Phase::Loading;
        bool atPark = t.phase == Phase::Parked;
        if (atLoad) {
            legs.push_back({loadRoads[t.shovel], true});
            legs.push_back({rampUp, false});
        } else if (atPark) {
            legs.push_back({parkRoad, true});
        } else {
            legs.push_back({dumpRoads[t.dump], true});
        }
        int li = idx(loadAreas, area), di = idx(dumpAreas, area);
        if (li < static_cast<int>(loadAreas.size())) {
            if (atLoad && li == t.shovel)
                return {}; // already there
            legs.push_back({rampDown, false});
            legs.push_back({loadRoads[li], false});
        } else if (di < static_cast<int>(dumpAreas.size())) {
            legs.push_back({dumpRoads[di], false});
        } else {
            legs.push_back({parkRoad, false});
        }
        return legs;
    }

    static std::string encode(const Body& b, std::optional<Guid> eq) {
        Envelope env;
        env.header.timestamp = makeTimestamp(nowMs());
        env.header.equipmentId = std::move(eq);
        env.members.push_back(Member{b, nlohmann::json::object()});
        return encodeMessage(env);
    }
    std::map<SessionId, SessionState>& table(Sock k) { return k == Sock::Main ? sessions : mapSessions; }
    // Every frame to an FMS goes through here so the session's sent count stays right.
    void sendText(Sock k, SessionId s, std::string text, bool binary = false) {
        auto& t = table(k);
        auto it = t.find(s);
        auto& e = k == Sock::Main ? ep : mapEp;
        if (it == t.end() || !e)
            return;
        if (binary ? e->sendBinary(s, std::move(text)) : e->send(s, std::move(text)))
            ++it->second.sent;
    }
    // To every FMS session on the main socket.
    void send(const Body& b, std::optional<Guid> eq = std::nullopt) {
        std::string text = encode(b, std::move(eq));
        for (auto& [s, st] : sessions)
            sendText(Sock::Main, s, text);
    }
    void sendTo(SessionId s, const Body& b, std::optional<Guid> eq = std::nullopt) {
        sendText(Sock::Main, s, encode(b, std::move(eq)));
    }
    void sendOn(Sock k, SessionId s, const Body& b) { sendText(k, s, encode(b, std::nullopt)); }

    MachinePositionV1 position(const Truck& t) {
        MachinePositionV1 p;
        p.timestamp = makeTimestamp(nowMs());
        auto g = frame.toGeodetic(t.pos);
        p.pose.latitude = std::round(g.lat * 1e7) / 1e7;
        p.pose.longitude = std::round(g.lon * 1e7) / 1e7;
        p.pose.elevation = std::round(g.alt * 100) / 100;
        p.pose.heading = static_cast<std::int64_t>(std::lround(t.headingDeg)) % 360;
        p.pose.speed = std::lround(t.speed * 3.6);
        p.pose.latitudeAccuracy = 0.05;
        p.pose.longitudeAccuracy = 0.05;
        p.pose.elevationAccuracy = 0.1;
        p.pose.headingAccuracy = 0.5;
        return p;
    }
    std::string mode(const Truck& t) const {
        if (t.manual)
            return "Manual";
        return allStopOn ? "AllStop" : "Autonomous";
    }
    HaulTruckProductionStateV2 prodState(const Truck& t) const {
        HaulTruckProductionStateV2 p;
        if (!t.assignments.empty())
            p.assignmentId = t.assignments.front().assignmentId;
        p.wayId = t.currentWay;
        p.autonomyMode = mode(t);
        p.productionState = t.productionState;
        return p;
    }
    void setProduction(Truck& t, const std::string& state) {
        if (t.productionState == state)
            return;
        t.productionState = state;
        send(prodState(t), t.id);
    }

    FleetDefinitionV2 fleetDef() const {
        FleetDefinitionV2 f;
        f.ahsId = cfg.ahsId;
        for (auto& t : trucks)
            f.equipment.push_back(Equipment{t.id, t.hid, "HaulTruck", "Komatsu", "930E", true, 15.6, 9.1});
        return f;
    }

    void snapshotTo(SessionId s) {
        // [ISO-seed] FleetDefinitionV2 first, then the "At Connection" snapshot (research note §10).
        sendTo(s, fleetDef());
        sendTo(s, MachineAllStopV1{allStopOn ? "On" : "Off", allStopId});
        for (auto& t : trucks) {
            Envelope env;
            env.header.timestamp = makeTimestamp(nowMs());
            env.header.equipmentId = t.id;
            env.members.push_back(Member{MachineAutonomyModeV1{mode(t)}, nlohmann::json::object()});
            env.members.push_back(Member{position(t), nlohmann::json::object()}); // piggy-backed (§3)
            sendText(Sock::Main, s, encodeMessage(env));
            sendTo(s, MachineDispatchAvailabilityV1{"FMS", std::nullopt, std::nullopt}, t.id);
            sendTo(s, MachineDiagnosticV2{t.faults}, t.id);
            sendTo(s, prodState(t), t.id);
            sendTo(s, t.sensorSent, t.id); // §5 row 18 [I]: current sensor inputs next to the state
        }
        sendTo(s, connectivity); // §9 connectivity is not part of the map service: always here
        if (!cfg.separateMapService) {
            sendTo(s, MapServiceV1{1});
            sendTo(s, summary());
        }
    }

    // HaulTruckProductionStateSensorV1 (§5 row 18, Q8 [I]): the raw inputs of the production state. Loaded
    // from the end of loading to the end of dumping (the payload is on board), body raised while dumping,
    // park brake when parked or held at rest (all-stop, manual), in the load/dump area while loading/dumping
    // (a truck is only inside an area for those phases here).
    HaulTruckProductionStateSensorV1 sensor(const Truck& t) const {
        const bool halted = (allStopOn && t.autonomous) || t.manual;
        HaulTruckProductionStateSensorV1 v;
        v.loaded = t.payload > 0;
        v.bodyRaised = t.phase == Phase::Dumping;
        v.parkBrake = t.phase == Phase::Parked || (halted && t.speed == 0);
        v.payloadWeight = t.payload;
        v.inLoadArea = t.phase == Phase::Loading;
        v.inDumpArea = t.phase == Phase::Dumping;
        return v;
    }
    // Sent on change only, never periodically.
    void updateSensor(Truck& t) {
        auto v = sensor(t);
        if (v == t.sensorSent)
            return;
        t.sensorSent = v;
        counters.add("sim.tx.sensor");
        send(v, t.id);
    }

    // ------------------------------------------------------------ simulation tick
    void tick() {
        const double dtWall = 1.0 / std::clamp(cfg.positionRateHz, 1.0, 10.0);
        const double dt = dtWall * cfg.timeScale;
        simTime += dt;
        std::uniform_real_distribution<double> u(0, 1);
        for (auto& t : trucks) {
            const bool halted = (allStopOn && t.autonomous) || t.manual;
            if (t.phase == Phase::ToLoad || t.phase == Phase::ToDump || t.phase == Phase::ToPark) {
                double target = halted ? 0.0 : t.cruise * (t.payload > 0 ? 0.75 : 1.0);
                double remaining = pathLength(t) - t.s;
                target = std::min(target, std::sqrt(2 * 1.0 * std::max(0.0, remaining)) + 0.5);
                double accel = target > t.speed ? 1.0 : (allStopOn ? 3.0 : 2.0);
                t.speed = target > t.speed ? std::min(target, t.speed + accel * dt)
                                           : std::max(target, t.speed - accel * dt);
                t.s += t.speed * dt;
                updatePose(t);
                if (halted && t.speed == 0 && allStopOn)
                    setProduction(t, "Stopped");
                else if (!halted && t.productionState == "Stopped")
                    setProduction(t, t.phase == Phase::ToDump ? "Hauling" : "Driving");
                if (t.s >= pathLength(t) - 0.5) {
                    t.speed = 0;
                    arrive(t);
                }
            } else if (!halted) {
                t.dwell -= dt;
                if (t.dwell <= 0)
                    leave(t);
            }
            updateSensor(t);
            if (cfg.healthEvents) {
                t.fuel = std::max(5.0, t.fuel - dt * 0.002);
                t.engineHours += dt / 3600.0;
                if (simTime >= t.nextHealth) {
                    t.nextHealth = simTime + 30;
                    BasicMachineHealthV2 h;
                    h.fuelLevel = std::lround(t.fuel);
                    h.totalEngineHour = std::round(t.engineHours * 10) / 10;
                    h.totalMachineHour = std::round(t.engineHours * 10.5) / 10;
                    h.tire.emplace();
                    for (const char* p : {"1.7", "1.9", "2.6", "2.7", "2.9", "2.10"})
                        h.tire->push_back(
                            Tire{p, 700 + static_cast<int>(u(rng) * 30), 55 + static_cast<int>(u(rng) * 12)});
                    send(h, t.id);
                    // Occasional diagnostics: raise or clear a fault (full list each time, §8.4).
                    if (u(rng) < 0.15) {
                        if (t.faults.empty())
                            t.faults.push_back(DiagnosticEntry{555, 2110});
                        else
                            t.faults.clear();
                        send(MachineDiagnosticV2{t.faults}, t.id);
                    }
                }
            }
        }
        // Positions at the configured rate (§7.4: 1-10 Hz).
        if (!sessions.empty())
            for (auto& t : trucks) {
                send(position(t), t.id);
                ++positionsSent;
            }
    }

    void arrive(Truck& t) {
        if (t.phase == Phase::ToLoad) {
            t.phase = Phase::Loading;
            t.dwell = 30;
            setProduction(t, "Loading");
        } else if (t.phase == Phase::ToDump) {
            t.phase = Phase::Dumping;
            t.dwell = 15;
            setProduction(t, "Dumping");
        } else {
            t.phase = Phase::Parked;
            t.dwell = 60;
            setProduction(t, "Parked");
        }
    }

    std::int64_t areaOf(const Truck& t) const {
        if (t.phase == Phase::Loading)
            return loadAreas[t.shovel];
        if (t.phase == Phase::Dumping)
            return dumpAreas[t.dump];
        return parkArea;
    }

    void leave(Truck& t) {
        std::uniform_real_distribution<double> u(0, 1);
        if (t.phase == Phase::Loading) {
            t.payload = 220 + static_cast<int>(u(rng) * 80);
            HaulTruckPayloadV1 p;
            p.payloadWeight = t.payload;
            p.accuracy = 4.5;
            p.payloadSourceId = stableGuid(cfg.seed, 2, static_cast<std::uint32_t>(t.shovel));
            send(p, t.id);
        } else if (t.phase == Phase::Dumping) {
            HaulTruckDumpV1 d;
            if (!t.assignments.empty())
                d.assignmentId = t.assignments.front().assignmentId;
            d.wayId = dumpAreas[t.dump];
            d.dumpedWeight = t.payload;
            send(d, t.id);
            HaulTruckProductionCycleV1 c;
            c.cycleId = t.cycleId;
            c.loadWayId = loadAreas[t.shovel];
            c.dumpWayId = dumpAreas[t.dump];
            c.loaderEquipmentId = stableGuid(cfg.seed, 2, static_cast<std::uint32_t>(t.shovel));
            c.payloadWeight = t.payload;
            c.stateTimes.push_back(StateTime{"Hauling", makeTimestamp(t.cycleStartMs),
                                             static_cast<double>((nowMs() - t.cycleStartMs) / 1000)});
            send(c, t.id);
            t.cycleId = newGuid();
            t.cycleStartMs = nowMs();
            t.payload = 0;
        }
        // An assignment whose destination is reached is completed.
        if (!t.assignments.empty() && t.assignments.front().destinationId == areaOf(t) &&
            t.phase != Phase::Parked) {
            send(HaulTruckAssignmentV1{t.assignments.front().assignmentId, "Completed",
                                       t.assignments.front().task, t.assignments.front().destinationId},
                 t.id);
            t.assignments.erase(t.assignments.begin());
            if (!t.assignments.empty())
                send(HaulTruckAssignmentV1{t.assignments.front().assignmentId, "Active",
                                           t.assignments.front().task, t.assignments.front().destinationId},
                     t.id);
        }
        std::int64_t dest;
        if (!t.assignments.empty())
            dest = t.assignments.front().destinationId;
        else if (t.phase == Phase::Loading)
            dest = dumpAreas[t.dump];
        else
            dest = loadAreas[t.shovel];
        auto legs = legsTo(t, dest);
        int li = static_cast<int>(std::find(loadAreas.begin(), loadAreas.end(), dest) - loadAreas.begin());
        int di = static_cast<int>(std::find(dumpAreas.begin(), dumpAreas.end(), dest) - dumpAreas.begin());
        Phase next = Phase::ToPark;
        if (li < static_cast<int>(loadAreas.size())) {
            next = Phase::ToLoad;
            t.shovel = li;
        } else if (di < static_cast<int>(dumpAreas.size())) {
            next = Phase::ToDump;
            t.dump = di;
        }
        if (legs.empty()) { // already there: load again
            t.dwell = 30;
            return;
        }
        startRoute(t, legs, next);
        updatePose(t);
        send(prodState(t), t.id);
    }

    // ------------------------------------------------------------ requests from the FMS
    void onOpen(SessionId id, const std::string& peer) override {
        sessions[id];
        logInfo(kLog, "FMS connected from " + peer);
        snapshotTo(id);
        scheduleDiagnostic(id);
    }
    void onClose(SessionId id, const std::string& reason) override {
        sessions.erase(id); // destroys its diagnostic timer: the pending wait ends with operation_aborted
        logInfo(kLog, "FMS disconnected: " + reason);
    }
    void onText(SessionId id, std::string text) override { onFrame(Sock::Main, id, text); }

    // The separate map service (Q10) is a service-identification protocol: the service speaks first
    // (MapServiceV1, then the At-Connection MapSummaryV1; §2 "Connection start", §10.6.1) and expects no
    // FleetDefinitionV2 from the client.
    void onMapOpen(SessionId id, const std::string& peer) {
        mapSessions[id];
        logInfo(kLog, "map service client connected from " + peer);
        sendOn(Sock::Map, id, MapServiceV1{1});
        sendOn(Sock::Map, id, summary());
        counters.add("sim.map.sessions");
    }
    void onMapClose(SessionId id, const std::string& reason) {
        mapSessions.erase(id);
        logInfo(kLog, "map service client disconnected: " + reason);
    }

    std::string mapUrl() const {
        return std::string(cfg.tls ? "wss://" : "ws://") + cfg.bindAddress + ":" +
               std::to_string(mapEp ? mapEp->localPort() : cfg.mapPort) + cfg.mapPath;
    }

    // §5 row 15 [I]: periodic InterfaceDiagnosticV1 with the session's frame counts (main socket only: the
    // map service has its own, identification-first protocol). Period 0 turns it off.
    void scheduleDiagnostic(SessionId id) {
        auto it = sessions.find(id);
        if (it == sessions.end() || cfg.interfaceDiagnosticPeriod.count() <= 0)
            return;
        auto& tm = it->second.diagTimer;
        if (!tm)
            tm = std::make_unique<boost::asio::steady_timer>(io.context());
        tm->expires_after(cfg.interfaceDiagnosticPeriod);
        tm->async_wait([this, id](boost::system::error_code ec) {
            if (ec)
                return;
            auto it = sessions.find(id);
            if (it == sessions.end())
                return;
            const auto& st = it->second;
            InterfaceDiagnosticV1 d;
            d.measurement.push_back(
                DiagMeasurement{"MessagesReceived", static_cast<double>(st.received), "count"});
            d.measurement.push_back(DiagMeasurement{"MessagesSent", static_cast<double>(st.sent), "count"});
            d.measurement.push_back(
                DiagMeasurement{"MessagesRejected", static_cast<double>(st.rejected), "count"});
            counters.add("sim.tx.interface_diagnostic");
            sendOn(Sock::Main, id, d);
            scheduleDiagnostic(id);
        });
    }

    // One text frame from an FMS on either socket. Rejections (invalid JSON or header, a member failing
    // validation, a member only the AHS sends) are answered with one InterfaceDiagnosticV1 of Error
    // messages (§5 row 15 [I]: "on error"), RefMember/RefTimestamp where known.
    void onFrame(Sock k, SessionId id, const std::string& text) {
        auto& tab = table(k);
        auto sit = tab.find(id);
        if (sit == tab.end())
            return;
        auto& st = sit->second;
        ++framesReceived;
        ++st.received;
        std::vector<DiagMessage> errors;
        auto reject = [&](const char* code, const char* counter, std::string detail,
                          std::optional<std::string> member, std::optional<Timestamp> ts) {
            counters.add("sim.rx.rejected");
            counters.add(std::string("sim.rx.rejected.") + counter);
            logWarning(kLog, "message from FMS rejected: " + detail);
            errors.push_back(DiagMessage{"Error", code, std::move(detail), std::move(member), std::move(ts)});
        };
        auto env = decodeMessage(text);
        if (!env) {
            // Nothing of the frame is used; its Timestamp is quoted when the JSON at least parses.
            auto doc = nlohmann::json::parse(text, nullptr, false);
            std::optional<Timestamp> ts;
            if (doc.is_object())
                if (auto t = doc.find("Timestamp"); t != doc.end() && t->is_string())
                    ts = Timestamp{t->get<std::string>(), parseTimestamp(t->get<std::string>(), true)};
            if (doc.is_discarded())
                reject("InvalidJson", "invalid_json", env.error(), std::nullopt, std::nullopt);
            else
                reject("InvalidHeader", "invalid_header", env.error(), std::nullopt, ts);
        } else {
            const Timestamp& ts = env->header.timestamp;
            for (auto& e : env->errors)
                reject("InvalidMember", "invalid_member", e, memberOfError(e), ts);
            if (k == Sock::Main && !st.gotFirst && !env->members.empty()) {
                st.gotFirst = true;
                fmsFirst.push_back(std::string(memberName(env->members.front().body)));
            }
            for (auto& m : env->members) {
                if (onlyAhsSends(m.body)) {
                    std::string name(memberName(m.body));
                    reject("WrongDirection", "wrong_direction", name + " is sent by the AHS, not by the FMS",
                           name, ts);
                    continue;
                }
                if (std::get_if<UnknownMember>(&m.body))
                    counters.add("sim.rx.unknown_member"); // tolerated, never an error (§4.2)
                else if (std::get_if<InterfaceDiagnosticV1>(&m.body))
                    counters.add("sim.rx.interface_diagnostic");
                else if (k == Sock::Map)
                    onMapServiceMember(id, m.body, ts);
                else
                    onMember(id, *env, m.body, ts);
            }
        }
        if (errors.empty())
            return;
        st.rejected += errors.size();
        InterfaceDiagnosticV1 d;
        d.message = std::move(errors);
        counters.add("sim.tx.interface_diagnostic.error"); // counted before it can be seen
        sendOn(k, id, d);
    }

    void onMember(SessionId id, const Envelope& env, const Body& b, const Timestamp& ts) {
        if (auto* r = std::get_if<MachineAllStopRequestV1>(&b))
            onAllStop(*r);
        else if (auto* c = std::get_if<MapCommandV1>(&b))
            onMapCommand(Sock::Main, id, *c, ts);
        else if (auto* a = std::get_if<HaulTruckAssignmentRequestV2>(&b))
            onAssignment(env.header.equipmentId.value_or(""), *a);
        else if (std::get_if<HaulTruckAssignmentResetV1>(&b))
            onReset(env.header.equipmentId.value_or(""));
        else if (std::get_if<MachinePositionV1>(&b))
            counters.add("sim.rx.fms_positions");
        else if (std::get_if<FleetDefinitionV2>(&b))
            counters.add("sim.rx.fms_fleet");
    }

    // On the separate map service only MapCommandV1 means something; a FleetDefinitionV2 is not expected
    // but harmless, anything else belongs on the main socket and is not acted on here.
    void onMapServiceMember(SessionId id, const Body& b, const Timestamp& ts) {
        if (auto* c = std::get_if<MapCommandV1>(&b)) {
            onMapCommand(Sock::Map, id, *c, ts);
        } else if (std::get_if<FleetDefinitionV2>(&b)) {
            counters.add("sim.map.rx.fleet");
        } else {
            std::string name(memberName(b));
            InterfaceDiagnosticV1 d;
            d.message.push_back(DiagMessage{"Warning", "NotMapService",
                                            name + " ignored: the map service only serves MapCommandV1", name,
                                            ts});
            counters.add("sim.map.rx.ignored");
            sendOn(Sock::Map, id, d);
        }
    }

    void onAllStop(const MachineAllStopRequestV1& r) {
        if (r.modeAllStop == "Apply") {
            if (allStopOn && allStopId != r.modeAllStopId) {
                send(MachineAllStopResponseV1{"Rejected", r.modeAllStopId,
                                              std::string("an all-stop is already active with id ") +
                                                  *allStopId});
                return;
            }
            send(
                MachineAllStopResponseV1{"Accepted", r.modeAllStopId,
                                         "Stop commanded to " + std::to_string(trucks.size()) + " machines"});
            allStopOn = true;
            allStopId = r.modeAllStopId;
        } else {
            if (!allStopOn || allStopId != r.modeAllStopId) {
                send(MachineAllStopResponseV1{"Rejected", r.modeAllStopId,
                                              std::string("unknown ModeAllStopId")});
                return;
            }
            send(MachineAllStopResponseV1{"Accepted", r.modeAllStopId, std::nullopt});
            allStopOn = false;
        }
        send(MachineAllStopV1{allStopOn ? "On" : "Off", allStopId});
        for (auto& t : trucks)
            if (t.autonomous && !t.manual)
                send(MachineAutonomyModeV1{mode(t)}, t.id);
        counters.add(allStopOn ? "sim.allstop.on" : "sim.allstop.off");
    }

    void onMapCommand(Sock k, SessionId s, const MapCommandV1& c, const Timestamp& ts) {
        if (k == Sock::Main && cfg.separateMapService) {
            // Q10: the map is served elsewhere; say where instead of silently ignoring the request.
            InterfaceDiagnosticV1 d;
            d.message.push_back(DiagMessage{"Warning", "MapServiceElsewhere",
                                            "the map service is a separate WebSocket service at " + mapUrl(),
                                            std::string("MapCommandV1"), ts});
            counters.add("sim.map.elsewhere");
            sendOn(k, s, d);
        } else if (c.scope == "/summary") {
            sendOn(k, s, summary());
        } else if (c.scope == "/") {
            auto chunks = mapChunks();
            sendOn(k, s, summary());
            for (auto& ch : chunks)
                sendText(k, s, ch); // raw XML, not wrapped in JSON (§8)
            counters.add("sim.map.sent");
        } else {
            InterfaceDiagnosticV1 d;
            d.message.push_back(DiagMessage{"Warning", "UnknownScope",
                                            "MapCommandV1 scope '" + c.scope + "' unknown",
                                            std::string("MapCommandV1"), std::nullopt});
            sendOn(k, s, d);
        }
    }

    Truck* truck(const Guid& id) {
        for (auto& t : trucks)
            if (t.id == id)
                return &t;
        return nullptr;
    }

    void onAssignment(const Guid& eq, const HaulTruckAssignmentRequestV2& req) {
        Truck* t = truck(eq);
        HaulTruckAssignmentResponseV1 resp;
        std::vector<AssignmentItem> accepted;
        for (auto& a : req.items) {
            std::string why;
            auto in = [&](const std::vector<std::int64_t>& v) {
                return std::find(v.begin(), v.end(), a.destinationId) != v.end();
            };
            if (!t)
                why = "unknown machine";
            else if (a.task == "Load" && !in(loadAreas))
                why = "destination " + std::to_string(a.destinationId) + " is not a load area";
            else if (a.task == "Offload" && !in(dumpAreas))
                why = "destination " + std::to_string(a.destinationId) + " is not a dump area";
            else if (a.task == "Park" && a.destinationId != parkArea)
                why = "destination " + std::to_string(a.destinationId) + " is not a park area";
            else if (a.task == "Fuel" || a.task == "Wait")
                why = "task " + a.task + " not supported by this AHS";
            if (why.empty())
                accepted.push_back(a);
            resp.items.push_back(
                AssignmentResponseItem{a.assignmentId, why.empty() ? "Accepted" : "Rejected",
                                       why.empty() ? std::nullopt : std::optional<std::string>(why)});
        }
        send(resp, eq);
        if (t && !accepted.empty()) {
            t->assignments = accepted;
            send(HaulTruckAssignmentV1{accepted.front().assignmentId, "Active", accepted.front().task,
                                       accepted.front().destinationId},
                 t->id);
            if (t->phase == Phase::Parked)
                t->dwell = 0;
        }
    }

    void onReset(const Guid& eq) {
        Truck* t = truck(eq);
        if (!t)
            return;
        if (!t->assignments.empty())
            send(HaulTruckAssignmentV1{t->assignments.front().assignmentId, "Cancelled",
                                       t->assignments.front().task, t->assignments.front().destinationId},
                 t->id);
        t->assignments.clear();
    }

    void schedule() {
        timer.expires_after(std::chrono::microseconds(
            static_cast<std::int64_t>(1e6 / std::clamp(cfg.positionRateHz, 1.0, 10.0))));
        timer.async_wait([this](boost::system::error_code ec) {
            if (ec)
                return;
            tick();
            schedule();
        });
    }
};

SimulatedAhs::SimulatedAhs(SimulatedAhsConfig config)
    : m_impl(std::make_unique<Impl>(std::move(config), m_counters)) {
    m_impl->buildMap();
    m_impl->buildFleet();
}

SimulatedAhs::~SimulatedAhs() {
    stop();
}

bool SimulatedAhs::start() {
    auto& d = *m_impl;
    if (d.io.running())
        return true;
    WsOptions o;
    o.pingInterval = d.cfg.pingInterval;
    o.deadAfter = d.cfg.deadAfter;
    o.backoffMin = std::chrono::milliseconds(200);
    o.backoffMax = std::chrono::milliseconds(2000);
    if (!d.cfg.connectUrl.empty()) {
        o.role = WsRole::Client;
        o.url = d.cfg.connectUrl;
        o.tls.caFile = d.cfg.caFile;
        o.tls.certFile = d.cfg.certFile;
        o.tls.keyFile = d.cfg.keyFile;
    } else {
        o.role = WsRole::Service;
        o.url = std::string(d.cfg.tls ? "wss://" : "ws://") + d.cfg.bindAddress + ":" +
                std::to_string(d.cfg.port) + d.cfg.path;
        o.tls.certFile = d.cfg.certFile;
        o.tls.keyFile = d.cfg.keyFile;
        o.tls.caFile = d.cfg.clientCaFile;
    }
    // Q10: the map service as its own WebSocket service, with the main service's TLS settings.
    WsOptions mo = o;
    mo.role = WsRole::Service;
    mo.url = std::string(d.cfg.tls ? "wss://" : "ws://") + d.cfg.bindAddress + ":" +
             std::to_string(d.cfg.mapPort) + d.cfg.mapPath;
    mo.tls = WsTlsOptions{};
    mo.tls.certFile = d.cfg.certFile;
    mo.tls.keyFile = d.cfg.keyFile;
    mo.tls.caFile = d.cfg.clientCaFile;
    d.io.start();
    auto r = d.io.call([&]() -> Result<bool> {
        d.ep = std::make_unique<WsEndpoint>(d.io.context(), o, d, m_counters);
        auto s = d.ep->start();
        if (s && d.cfg.separateMapService) {
            d.mapEp = std::make_unique<WsEndpoint>(d.io.context(), mo, d.mapSide, m_counters);
            s = d.mapEp->start();
            if (!s) {
                s = makeError("map service: " + s.error());
                d.ep->stop();
            }
        }
        if (s)
            d.schedule();
        return s;
    });
    if (!r) {
        m_error = r.error();
        d.io.call([&] {
            d.mapEp.reset();
            d.ep.reset();
        });
        d.io.stop();
        return false;
    }
    return true;
}

void SimulatedAhs::stop() {
    auto& d = *m_impl;
    if (!d.io.running())
        return;
    d.io.call([&] {
        d.timer.cancel();
        if (d.ep)
            d.ep->stop();
        if (d.mapEp)
            d.mapEp->stop();
        d.sessions.clear(); // with their diagnostic timers
        d.mapSessions.clear();
    });
    d.io.stop();
    d.mapEp.reset();
    d.ep.reset();
}

bool SimulatedAhs::running() const {
    return m_impl->io.running();
}

std::uint16_t SimulatedAhs::port() const {
    auto& d = *m_impl;
    if (!d.ep)
        return d.cfg.port;
    return const_cast<IoThread&>(d.io).call([&] { return d.ep->localPort(); });
}

std::string SimulatedAhs::url() const {
    return std::string(m_impl->cfg.tls ? "wss://" : "ws://") + m_impl->cfg.bindAddress + ":" +
           std::to_string(port()) + m_impl->cfg.path;
}

std::uint16_t SimulatedAhs::mapPort() const {
    auto& d = *m_impl;
    if (!d.mapEp)
        return d.cfg.mapPort;
    return const_cast<IoThread&>(d.io).call([&] { return d.mapEp->localPort(); });
}

std::string SimulatedAhs::mapUrl() const {
    return std::string(m_impl->cfg.tls ? "wss://" : "ws://") + m_impl->cfg.bindAddress + ":" +
           std::to_string(mapPort()) + m_impl->cfg.mapPath;
}

std::vector<Equipment> SimulatedAhs::fleet() const {
    return m_impl->fleetDef().equipment;
}

SimulatedAhsStats SimulatedAhs::stats() {
    auto& d = *m_impl;
    auto f = [&] {
        SimulatedAhsStats s;
        s.positionsSent = d.positionsSent;
        s.framesReceived = d.framesReceived;
        s.queuedBytes = d.ep ? d.ep->queuedBytes() : 0;
        s.sessions = d.sessions.size();
        s.mapSessions = d.mapSessions.size();
        s.allStopOn = d.allStopOn;
        for (auto& t : d.trucks)
            s.movingTrucks += t.speed > 0.05 ? 1 : 0;
        s.fmsFirstMessages = d.fmsFirst;
        return s;
    };
    return d.io.call(f);
}

void SimulatedAhs::bumpMapChangeSet() {
    m_impl->io.post([d = m_impl.get()] {
        ++d->changeSetMap;
        ++d->changeSetWay;
        d->mapModifiedMs = nowMs();
        if (!d->cfg.separateMapService) {
            d->send(d->summary());
            return;
        }
        for (auto& [s, st] : d->mapSessions)
            d->sendOn(Sock::Map, s, d->summary());
    });
}

void SimulatedAhs::sendRaw(const std::string& text) {
    m_impl->io.post([d = m_impl.get(), text] {
        for (auto& [s, st] : d->sessions)
            d->sendText(Sock::Main, s, text);
    });
}

void SimulatedAhs::sendRawBinary(const std::string& data) {
    m_impl->io.post([d = m_impl.get(), data] {
        for (auto& [s, st] : d->sessions)
            d->sendText(Sock::Main, s, data, true);
    });
}

void SimulatedAhs::freezeFor(std::chrono::milliseconds d) {
    m_impl->io.post([d] { std::this_thread::sleep_for(d); });
}

void SimulatedAhs::setTruckManual(int index, bool manual) {
    m_impl->io.post([d = m_impl.get(), index, manual] {
        if (index < 0 || index >= static_cast<int>(d->trucks.size()))
            return;
        auto& t = d->trucks[index];
        t.manual = manual;
        d->send(MachineAutonomyModeV1{d->mode(t)}, t.id);
    });
}

std::vector<double> SimulatedAhs::truckSpeedsKmh() {
    return m_impl->io.call([&] {
        std::vector<double> v;
        for (auto& t : m_impl->trucks)
            v.push_back(t.speed * 3.6);
        return v;
    });
}

} // namespace ocu::sim
