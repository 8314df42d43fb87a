#pragma once
// ISO 23725 map (§10, research note §8): OSM 0.6 XML chunks assembled into nodes, ways, roads, lanes and
// areas with their tags, checked against the ID rules (§10.2); MapConnectivityV1 as a directed graph (§9.1).
#include "protocols/common/GeoFrame.h"
#include "protocols/common/Result.h"
#include "protocols/iso23725/Messages.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ocu::iso23725 {

using Tags = std::map<std::string, std::string>;

struct MapNode {
    std::int64_t id = 0;
    double lat = 0;
    double lon = 0;
    std::optional<double> ele; // metres above MSL (EGM96), §8
    EnuPoint enu;              // local frame around MapModel::origin
    Tags tags;
};

enum class WayKind { Road, Lane, Area };
const char* nameFor(WayKind k);

struct MapWay {
    std::int64_t id = 0;
    std::vector<std::int64_t> nodes;
    Tags tags;
    WayKind kind = WayKind::Road;
    std::optional<std::int64_t> changeset;
    std::optional<std::int64_t> version;
    std::string tag(const std::string& k) const {
        auto it = tags.find(k);
        return it == tags.end() ? std::string() : it->second;
    }
    std::string name() const { return tag("name"); }
    // `default_task` (also accepted as "default task", TOC spelling) for areas.
    std::string defaultTask() const;
};

// MapConnectivityV1 as a directed graph: Connection lists the ways reachable from a way (§9.1.3 [I]).
class ConnectivityGraph {
public:
    void assign(const MapConnectivityV1& msg);
    bool empty() const { return m_items.empty(); }
    std::size_t size() const { return m_items.size(); }
    const ConnectivityItem* find(std::int64_t wayId) const;
    std::vector<std::int64_t> successors(std::int64_t wayId) const;
    // Shortest path by road length (areas cost 0) from one way to another, both included; empty when
    // unreachable.
    std::vector<std::int64_t> route(std::int64_t from, std::int64_t to) const;
    // Connections that point to ways not in the graph.
    std::vector<std::string> danglingConnections() const;
    const std::map<std::int64_t, ConnectivityItem>& items() const { return m_items; }

private:
    std::map<std::int64_t, ConnectivityItem> m_items;
};

struct MapModel {
    MapSummaryV1 summary;
    GeoPoint origin; // ENU origin (centroid of the nodes)
    std::unordered_map<std::int64_t, MapNode> nodes;
    std::map<std::int64_t, MapWay> ways;
    std::vector<std::int64_t> roads; // two-way roads
    std::vector<std::int64_t> lanes; // oneway=yes roads (§8: a lane is always one-way)
    std::vector<std::int64_t> areas; // closed ways
    ConnectivityGraph connectivity;
    std::vector<std::string> warnings; // tolerated deviations (unknown tag values, count mismatches)

    const MapWay* way(std::int64_t id) const {
        auto it = ways.find(id);
        return it == ways.end() ? nullptr : &it->second;
    }
};

struct MapProgress {
    int received = 0;
    int total = 0;
    bool complete() const { return total > 0 && received >= total; }
};

// Assembles DocumentCount chunks after a MapSummaryV1. A bad chunk fails the whole fetch with a message
// naming the chunk and the rule; the caller keeps its previous complete map (never a half-loaded one).
class MapAssembler {
public:
    void begin(const MapSummaryV1& summary);
    void reset() { m_active = false; }
    bool active() const { return m_active; }
    const MapProgress& progress() const { return m_progress; }
    // Parses one chunk; error when it is not well-formed, out of sequence or breaks an ID rule.
    Result<MapProgress> addChunk(std::string_view xml);
    // After the last chunk: cross-chunk checks (references, road/area shapes) and the finished model.
    Result<MapModel> finish();

private:
    bool m_active = false;
    MapProgress m_progress;
    MapModel m_model;
};

// Parses a single document (all chunks in one), for tests and tools.
Result<MapModel> parseMapDocument(const std::vector<std::string>& chunks, const MapSummaryV1& summary = {});

// Writes a map as OSM 0.6 chunks of at most maxElements elements (nodes first, then ways), sequence 1..N.
std::vector<std::string> writeOsmChunks(const MapModel& model, std::size_t maxElements,
                                        std::int64_t changeset,
                                        const std::string& generator = "ocu simulated AHS");

} // namespace ocu::iso23725
