#include "sim/iso23725/PitMapGenerator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ocu::sim {

using namespace ocu::iso23725;

namespace {

// Adds nodes and ways to a PitMap, numbering nodes from 700001.
class PitMapGenerator {
public:
    PitMapGenerator(PitMap& pit, const GeoPoint& origin) : m_pit(pit), m_map(pit.map), m_frame(origin) {}

    std::int64_t addNode(const EnuPoint& p) {
        MapNode n;
        n.id = m_nextNode++;
        auto g = m_frame.toGeodetic(p);
        n.lat = std::round(g.lat * 1e7) / 1e7;
        n.lon = std::round(g.lon * 1e7) / 1e7;
        n.ele = std::round((m_frame.origin().alt + p.u) * 100) / 100;
        n.enu = p;
        m_map.nodes[n.id] = n;
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
        w.changeset = m_pit.changeSetWay;
        m_map.ways[id] = w;
        return id;
    }
    // A square area (closed way) of half-width `half` around c.
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
        w.changeset = m_pit.changeSetWay;
        m_map.ways[id] = w;
        return id;
    }

    void build(const PitLayout& layout) {
        const int ns = std::max(1, layout.shovels), nd = std::max(1, layout.dumps);
        const EnuPoint hub{0, 200, 0}, bottom{0, -300, -60};
        // Haul ramp as two lanes (oneway=yes: node order is the travel direction, §8).
        std::vector<EnuPoint> down, up;
        for (int k = 0; k <= 10; ++k) {
            double t = k / 10.0;
            double bend = 90 * std::sin(std::numbers::pi * t);
            down.push_back({-6 + bend, 200 - 500 * t, -60 * t});
            up.push_back({6 + bend, -300 + 500 * t, -60 + 60 * t});
        }
        auto& p = m_pit;
        p.rampDown = addRoad(3001, down,
                             {{"name", "Main ramp down"},
                              {"oneway", "yes"},
                              {"highway", "service"},
                              {"autonomy", "exclusive"}});
        p.rampUp = addRoad(
            3002, up,
            {{"name", "Main ramp up"}, {"oneway", "yes"}, {"highway", "service"}, {"autonomy", "exclusive"}});
        for (int i = 0; i < ns; ++i) {
            double x = ns == 1 ? 0 : -220 + 440.0 * i / (ns - 1);
            EnuPoint c{x, -470, -60};
            EnuPoint entry{x, -430, -60};
            p.loadRoads.push_back(addRoad(2101 + i, {bottom, {x * 0.5, -360, -60}, entry},
                                          {{"name", "Bench road " + std::to_string(i + 1)},
                                           {"highway", "service"},
                                           {"oneway", "no"},
                                           {"autonomy", "exclusive"}}));
            p.loadAreas.push_back(addArea(4101 + i, c, 40,
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
            p.dumpRoads.push_back(addRoad(
                2201 + j, {hub, {x * 0.5, crusher ? 240.0 : 380.0, 0}, entry},
                {{"name", crusher ? std::string("Crusher road") : "Dump road " + std::to_string(j + 1)},
                 {"highway", "service"},
                 {"oneway", "no"},
                 {"autonomy", "mixed"}}));
            p.dumpAreas.push_back(addArea(
                4201 + j, c, crusher ? 25 : 50,
                {{"name", crusher ? std::string("Primary crusher") : "Waste dump " + std::to_string(j + 1)},
                 {"default_task", "offload"},
                 {"autonomy", "mixed"}}));
        }
        p.parkRoad =
            addRoad(2301, {hub, {-150, 180, 0}, {-300, 160, 0}},
                    {{"name", "Park road"}, {"highway", "service"}, {"oneway", "no"}, {"autonomy", "mixed"}});
        p.parkArea = addArea(4301, {-340, 160, 0}, 40,
                             {{"name", "Truck park"},
                              {"default_task", "park"},
                              {"autonomy", "mixed"},
                              {"amenity", "parking"}});
        addArea(4401, {0, -200, -30}, 700, {{"name", "Pit 1 AOZ"}, {"autonomy:area", "AOZ"}});
        buildConnectivity(ns);
        m_map.origin = layout.origin;
    }

private:
    // Directed connectivity (§9.1): from each way, the ways a truck may drive onto next.
    void buildConnectivity(int ns) {
        auto& p = m_pit;
        auto road = [&](std::int64_t id, std::vector<std::int64_t> to) {
            ConnectivityItem c;
            c.wayId = id;
            c.wayType = "Road";
            c.roadLength = std::round(p.wayLength(id) * 10) / 10;
            c.roadName = m_map.ways.at(id).name();
            for (auto t : to)
                c.connection.push_back(WayRef{t});
            p.connectivity.items.push_back(c);
        };
        auto area = [&](std::int64_t id, const char* task, std::vector<std::int64_t> to) {
            ConnectivityItem c;
            c.wayId = id;
            c.wayType = "Area";
            c.areaDefaultTask = task;
            c.areaName = m_map.ways.at(id).name();
            for (auto t : to)
                c.connection.push_back(WayRef{t});
            p.connectivity.items.push_back(c);
        };
        std::vector<std::int64_t> fromHub = p.dumpRoads;
        fromHub.push_back(p.parkRoad);
        fromHub.push_back(p.rampDown);
        road(p.rampDown, p.loadRoads);
        std::vector<std::int64_t> upTo = fromHub;
        upTo.pop_back();
        road(p.rampUp, upTo);
        for (int i = 0; i < ns; ++i) {
            road(p.loadRoads[i], {p.loadAreas[i], p.rampUp});
            area(p.loadAreas[i], "Load", {p.loadRoads[i]});
        }
        for (std::size_t j = 0; j < p.dumpRoads.size(); ++j) {
            std::vector<std::int64_t> to = fromHub;
            to.erase(std::remove(to.begin(), to.end(), p.dumpRoads[j]), to.end());
            to.push_back(p.dumpAreas[j]);
            road(p.dumpRoads[j], to);
            area(p.dumpAreas[j], "Offload", {p.dumpRoads[j]});
        }
        std::vector<std::int64_t> parkTo = p.dumpRoads;
        parkTo.push_back(p.rampDown);
        parkTo.push_back(p.parkArea);
        road(p.parkRoad, parkTo);
        area(p.parkArea, "Park", {p.parkRoad});
    }

    PitMap& m_pit;
    MapModel& m_map;
    GeoFrame m_frame;
    std::int64_t m_nextNode = 700001;
};

int indexIn(const std::vector<std::int64_t>& v, std::int64_t x) {
    auto it = std::find(v.begin(), v.end(), x);
    return it == v.end() ? -1 : static_cast<int>(it - v.begin());
}

} // namespace

std::vector<EnuPoint> PitMap::wayPoints(std::int64_t wayId, bool reversed) const {
    std::vector<EnuPoint> out;
    const auto& w = map.ways.at(wayId);
    out.reserve(w.nodes.size());
    for (auto id : w.nodes)
        out.push_back(map.nodes.at(id).enu);
    if (reversed)
        std::reverse(out.begin(), out.end());
    return out;
}

Route PitMap::route(const std::vector<RouteLeg>& legs) const {
    Route r;
    for (const auto& leg : legs)
        r.addLeg(leg.wayId, wayPoints(leg.wayId, leg.reversed));
    return r;
}

double PitMap::wayLength(std::int64_t wayId) const {
    const auto& w = map.ways.at(wayId);
    double len = 0;
    for (std::size_t i = 0; i + 1 < w.nodes.size(); ++i) {
        auto& a = map.nodes.at(w.nodes[i]).enu;
        auto& b = map.nodes.at(w.nodes[i + 1]).enu;
        len += std::hypot(b.e - a.e, b.n - a.n, b.u - a.u);
    }
    return len;
}

int PitMap::loadIndex(std::int64_t areaId) const {
    return indexIn(loadAreas, areaId);
}

int PitMap::dumpIndex(std::int64_t areaId) const {
    return indexIn(dumpAreas, areaId);
}

std::vector<std::string> PitMap::osmChunks(std::size_t chunkElements) const {
    const std::size_t total = map.nodes.size() + map.ways.size();
    const std::size_t per = chunkElements ? chunkElements : (total + 3) / 4; // 4 chunks by default
    return writeOsmChunks(map, std::min<std::size_t>(per, 10000), changeSetMap, "ocu simulated AHS");
}

MapSummaryV1 PitMap::summary(std::size_t chunkElements) const {
    MapSummaryV1 s;
    s.timestamp = makeTimestamp(modifiedUnixMs);
    s.changeSetMap = changeSetMap;
    s.changeSetWay = changeSetWay;
    s.uid = 1;
    s.nodeCount = static_cast<std::int64_t>(map.nodes.size());
    s.wayCount = static_cast<std::int64_t>(map.ways.size());
    s.documentCount = static_cast<std::int64_t>(osmChunks(chunkElements).size());
    return s;
}

void PitMap::edited(std::int64_t nowUnixMs) {
    ++changeSetMap;
    ++changeSetWay;
    modifiedUnixMs = nowUnixMs;
}

PitMap generatePitMap(const PitLayout& layout, std::int64_t nowUnixMs) {
    PitMap pit;
    PitMapGenerator(pit, layout.origin).build(layout);
    pit.modifiedUnixMs = nowUnixMs;
    return pit;
}

} // namespace ocu::sim
