#include "protocols/iso23725/MapModel.h"

#include <pugixml.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <queue>
#include <set>

namespace ocu::iso23725 {

const char* nameFor(WayKind k) {
    switch (k) {
    case WayKind::Road:
        return "road";
    case WayKind::Lane:
        return "lane";
    case WayKind::Area:
        return "area";
    }
    return "?";
}

std::string MapWay::defaultTask() const {
    auto v = tag("default_task");
    return v.empty() ? tag("default task") : v;
}

// ---------------------------------------------------------------- connectivity

void ConnectivityGraph::assign(const MapConnectivityV1& msg) {
    m_items.clear();
    for (auto& i : msg.items)
        m_items[i.wayId] = i;
}

const ConnectivityItem* ConnectivityGraph::find(std::int64_t wayId) const {
    auto it = m_items.find(wayId);
    return it == m_items.end() ? nullptr : &it->second;
}

std::vector<std::int64_t> ConnectivityGraph::successors(std::int64_t wayId) const {
    std::vector<std::int64_t> out;
    if (auto* i = find(wayId))
        for (auto& c : i->connection)
            out.push_back(c.wayId);
    return out;
}

std::vector<std::int64_t> ConnectivityGraph::route(std::int64_t from, std::int64_t to) const {
    if (!find(from) || !find(to))
        return {};
    std::map<std::int64_t, double> dist;
    std::map<std::int64_t, std::int64_t> prev;
    using Q = std::pair<double, std::int64_t>;
    std::priority_queue<Q, std::vector<Q>, std::greater<>> q;
    dist[from] = 0;
    q.push({0, from});
    while (!q.empty()) {
        auto [d, w] = q.top();
        q.pop();
        if (w == to)
            break;
        if (d > dist[w])
            continue;
        for (auto n : successors(w)) {
            auto* ni = find(n);
            if (!ni)
                continue;
            double cost = d + (ni->wayType == "Road" ? ni->roadLength.value_or(1.0) : 0.0) + 1e-6;
            auto it = dist.find(n);
            if (it == dist.end() || cost < it->second) {
                dist[n] = cost;
                prev[n] = w;
                q.push({cost, n});
            }
        }
    }
    if (!dist.count(to))
        return {};
    std::vector<std::int64_t> path{to};
    while (path.back() != from)
        path.push_back(prev[path.back()]);
    std::reverse(path.begin(), path.end());
    return path;
}

std::vector<std::string> ConnectivityGraph::danglingConnections() const {
    std::vector<std::string> out;
    for (auto& [id, i] : m_items)
        for (auto& c : i.connection)
            if (!m_items.count(c.wayId))
                out.push_back("MapConnectivityV1: way " + std::to_string(id) + " connects to unknown way " +
                              std::to_string(c.wayId));
    return out;
}

// ---------------------------------------------------------------- chunk parsing

namespace {

template <class T> bool parseNum(const char* s, T& out) {
    if (!s || !*s)
        return false;
    auto end = s + std::char_traits<char>::length(s);
    auto [p, ec] = std::from_chars(s, end, out);
    return ec == std::errc() && p == end;
}

std::optional<std::int64_t> optInt(const pugi::xml_node& n, const char* attr) {
    std::int64_t v;
    if (parseNum(n.attribute(attr).value(), v))
        return v;
    return std::nullopt;
}

Tags readTags(const pugi::xml_node& n) {
    Tags t;
    for (auto tag : n.children("tag"))
        t[tag.attribute("k").value()] = tag.attribute("v").value();
    return t;
}

bool segmentsCross(const EnuPoint& a, const EnuPoint& b, const EnuPoint& c, const EnuPoint& d) {
    auto orient = [](const EnuPoint& p, const EnuPoint& q, const EnuPoint& r) {
        double v = (q.e - p.e) * (r.n - p.n) - (q.n - p.n) * (r.e - p.e);
        return (v > 1e-9) - (v < -1e-9);
    };
    int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    return o1 * o2 < 0 && o3 * o4 < 0;
}

} // namespace

void MapAssembler::begin(const MapSummaryV1& summary) {
    m_active = true;
    m_model = MapModel{};
    m_model.summary = summary;
    m_progress = MapProgress{0, static_cast<int>(summary.documentCount)};
}

Result<MapProgress> MapAssembler::addChunk(std::string_view xml) {
    if (!m_active)
        return makeError("map chunk received without a pending map request");
    const int seqExpected = m_progress.received + 1;
    const std::string where = "map chunk " + std::to_string(seqExpected);
    auto fail = [&](const std::string& msg) -> Result<MapProgress> {
        m_active = false;
        return makeError(where + ": " + msg);
    };
    if (m_progress.total > 0 && m_progress.received >= m_progress.total)
        return fail("more chunks than DocumentCount " + std::to_string(m_progress.total));
    pugi::xml_document doc;
    auto res = doc.load_buffer(xml.data(), xml.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!res)
        return fail(std::string("not well-formed XML: ") + res.description() + " at offset " +
                    std::to_string(res.offset));
    auto osm = doc.child("osm");
    if (!osm)
        return fail("root element is not <osm>");
    if (std::string_view(osm.attribute("version").value()) != "0.6")
        return fail(std::string("osm version '") + osm.attribute("version").value() + "' is not 0.6");
    std::int64_t seq = 0;
    if (!parseNum(osm.attribute("sequence").value(), seq))
        return fail("missing or malformed 'sequence' attribute (§10.3.2)");
    if (seq != seqExpected)
        return fail("sequence " + std::to_string(seq) + " out of order, expected " +
                    std::to_string(seqExpected));
    for (auto n : osm.children("node")) {
        MapNode node;
        if (!parseNum(n.attribute("id").value(), node.id))
            return fail(std::string("node with malformed id '") + n.attribute("id").value() + "'");
        if (node.id == 0)
            return fail("node id 0 is forbidden (§10.2)");
        if (node.id < 0)
            return fail("node id " + std::to_string(node.id) +
                        " is negative; the service serves positive IDs only (§10.2)");
        if (!parseNum(n.attribute("lat").value(), node.lat) ||
            !parseNum(n.attribute("lon").value(), node.lon))
            return fail("node " + std::to_string(node.id) + ": missing or malformed lat/lon");
        if (std::fabs(node.lat) > 90 || std::fabs(node.lon) > 180)
            return fail("node " + std::to_string(node.id) + ": lat/lon out of range");
        double ele;
        if (parseNum(n.attribute("ele").value(), ele))
            node.ele = ele;
        if (n.child("tag"))
            node.tags = readTags(n);
        auto id = node.id;
        if (!m_model.nodes.emplace(id, std::move(node)).second)
            return fail("duplicate node id " + std::to_string(id) + " (§10.2: IDs are unique per category)");
    }
    for (auto w : osm.children("way")) {
        MapWay way;
        if (!parseNum(w.attribute("id").value(), way.id))
            return fail(std::string("way with malformed id '") + w.attribute("id").value() + "'");
        if (way.id == 0)
            return fail("way id 0 is forbidden (§10.2)");
        if (way.id < 0)
            return fail("way id " + std::to_string(way.id) +
                        " is negative; the service serves positive IDs only (§10.2)");
        for (auto nd : w.children("nd")) {
            std::int64_t ref;
            if (!parseNum(nd.attribute("ref").value(), ref))
                return fail("way " + std::to_string(way.id) + ": malformed nd ref");
            way.nodes.push_back(ref);
        }
        way.tags = readTags(w);
        way.changeset = optInt(w, "changeset");
        way.version = optInt(w, "version");
        auto id = way.id;
        if (!m_model.ways.emplace(id, std::move(way)).second)
            return fail("duplicate way id " + std::to_string(id) + " (§10.2: IDs are unique per category)");
    }
    if (osm.child("relation"))
        m_model.warnings.push_back(where + ": <relation> elements ignored (not part of the map format)");
    ++m_progress.received;
    return m_progress;
}

Result<MapModel> MapAssembler::finish() {
    if (!m_active)
        return makeError("no map being assembled");
    m_active = false;
    if (!m_progress.complete())
        return makeError("map incomplete: " + std::to_string(m_progress.received) + " of " +
                         std::to_string(m_progress.total) + " chunks");
    MapModel& m = m_model;
    if (m.nodes.empty())
        return makeError("map has no nodes");
    // ENU origin: centroid of the nodes.
    double slat = 0, slon = 0;
    for (auto& [id, n] : m.nodes) {
        slat += n.lat;
        slon += n.lon;
    }
    m.origin = GeoPoint{slat / m.nodes.size(), slon / m.nodes.size(), 0};
    GeoFrame frame(m.origin);
    for (auto& [id, n] : m.nodes)
        n.enu = frame.toLocal(GeoPoint{n.lat, n.lon, n.ele.value_or(0)});

    static const std::set<std::string> autonomyValues = {"excluded", "exclusive", "mixed"};
    static const std::set<std::string> areaValues = {"AOZ", "exclusion", "obstacle"};
    static const std::set<std::string> onewayValues = {"yes", "no", "reversible", "alternating"};
    static const std::set<std::string> taskValues = {"load", "offload", "supply", "park",
                                                     "wait", "drive",   "fuel"};
    for (auto& entry : m.ways) {
        // Not a structured binding: lambdas below use w; clang 14 (the fuzz build) cannot capture one.
        const std::int64_t id = entry.first;
        MapWay& w = entry.second;
        const std::string wn = "way " + std::to_string(id);
        for (auto ref : w.nodes)
            if (!m.nodes.count(ref))
                return makeError(wn + ": references unknown node " + std::to_string(ref));
        if (w.nodes.size() > 2000)
            return makeError(wn + ": " + std::to_string(w.nodes.size()) + " nodes, more than 2000 (§10.3.2)");
        bool closed = w.nodes.size() >= 2 && w.nodes.front() == w.nodes.back();
        if (closed) {
            if (w.nodes.size() < 4)
                return makeError(wn + ": an area needs at least 3 distinct nodes");
            w.kind = WayKind::Area;
            m.areas.push_back(id);
        } else {
            if (w.nodes.size() < 2)
                return makeError(wn + ": a road needs at least 2 nodes");
            w.kind = w.tag("oneway") == "yes" ? WayKind::Lane : WayKind::Road;
            (w.kind == WayKind::Lane ? m.lanes : m.roads).push_back(id);
        }
        // No self-crossing (§8): check non-adjacent segments.
        const std::size_t segs = w.nodes.size() - 1;
        for (std::size_t i = 0; i < segs; ++i)
            for (std::size_t j = i + 2; j < segs; ++j) {
                if (closed && i == 0 && j == segs - 1)
                    continue;
                if (segmentsCross(m.nodes[w.nodes[i]].enu, m.nodes[w.nodes[i + 1]].enu,
                                  m.nodes[w.nodes[j]].enu, m.nodes[w.nodes[j + 1]].enu))
                    return makeError(wn + ": crosses itself (segments " + std::to_string(i) + " and " +
                                     std::to_string(j) + ")");
            }
        auto check = [&](const char* key, const std::set<std::string>& allowed, bool areaOnly,
                         bool roadOnly) {
            auto it = w.tags.find(key);
            if (it == w.tags.end())
                return;
            if (!allowed.count(it->second))
                m.warnings.push_back(wn + ": tag " + key + "='" + it->second + "' is not a standard value");
            if ((areaOnly && !closed) || (roadOnly && closed))
                m.warnings.push_back(wn + ": tag " + key + " is not allowed on a " + nameFor(w.kind));
        };
        check("autonomy", autonomyValues, false, false);
        check("autonomy:area", areaValues, true, false);
        check("oneway", onewayValues, false, true);
        check("default_task", taskValues, true, false);
        check("default task", taskValues, true, false);
    }
    if (m.summary.nodeCount && static_cast<std::size_t>(m.summary.nodeCount) != m.nodes.size())
        m.warnings.push_back("MapSummaryV1.NodeCount " + std::to_string(m.summary.nodeCount) + " but " +
                             std::to_string(m.nodes.size()) + " nodes received");
    if (m.summary.wayCount && static_cast<std::size_t>(m.summary.wayCount) != m.ways.size())
        m.warnings.push_back("MapSummaryV1.WayCount " + std::to_string(m.summary.wayCount) + " but " +
                             std::to_string(m.ways.size()) + " ways received");
    return std::move(m_model);
}

Result<MapModel> parseMapDocument(const std::vector<std::string>& chunks, const MapSummaryV1& summary) {
    MapAssembler a;
    MapSummaryV1 s = summary;
    s.documentCount = static_cast<std::int64_t>(chunks.size());
    a.begin(s);
    for (auto& c : chunks) {
        auto r = a.addChunk(c);
        if (!r)
            return makeError(r.error());
    }
    return a.finish();
}

// ---------------------------------------------------------------- writing

namespace {
void escapeInto(std::string& out, const std::string& s) {
    for (char c : s) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
}
void writeTags(std::string& out, const Tags& tags) {
    for (auto& [k, v] : tags) {
        out += "<tag k=\"";
        escapeInto(out, k);
        out += "\" v=\"";
        escapeInto(out, v);
        out += "\"/>";
    }
}
} // namespace

std::vector<std::string> writeOsmChunks(const MapModel& model, std::size_t maxElements,
                                        std::int64_t changeset, const std::string& generator) {
    std::vector<std::int64_t> nodeIds;
    nodeIds.reserve(model.nodes.size());
    for (auto& [id, n] : model.nodes)
        nodeIds.push_back(id);
    std::sort(nodeIds.begin(), nodeIds.end());
    const std::size_t total = nodeIds.size() + model.ways.size();
    maxElements = std::max<std::size_t>(1, maxElements);
    std::vector<std::string> chunks;
    std::string cur;
    std::size_t inChunk = 0;
    auto open = [&] {
        cur = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<osm version=\"0.6\" generator=\"";
        escapeInto(cur, generator);
        cur += "\" sequence=\"" + std::to_string(chunks.size() + 1) + "\">\n";
        inChunk = 0;
    };
    auto close = [&] {
        cur += "</osm>\n";
        chunks.push_back(std::move(cur));
        cur.clear();
    };
    auto next = [&] {
        if (inChunk == maxElements) {
            close();
            open();
        }
        ++inChunk;
    };
    open();
    char buf[160];
    for (auto id : nodeIds) {
        next();
        const auto& n = model.nodes.at(id);
        std::snprintf(buf, sizeof buf, "<node id=\"%lld\" lat=\"%.7f\" lon=\"%.7f\"",
                      static_cast<long long>(id), n.lat, n.lon);
        cur += buf;
        if (n.ele) {
            std::snprintf(buf, sizeof buf, " ele=\"%.2f\"", *n.ele);
            cur += buf;
        }
        cur += " version=\"1\" changeset=\"" + std::to_string(changeset) + "\" visible=\"true\"";
        if (n.tags.empty()) {
            cur += "/>\n";
        } else {
            cur += ">";
            writeTags(cur, n.tags);
            cur += "</node>\n";
        }
    }
    for (auto& [id, w] : model.ways) {
        next();
        cur += "<way id=\"" + std::to_string(id) + "\" version=\"" + std::to_string(w.version.value_or(1)) +
               "\" changeset=\"" + std::to_string(w.changeset.value_or(changeset)) + "\" visible=\"true\">";
        for (auto ref : w.nodes)
            cur += "<nd ref=\"" + std::to_string(ref) + "\"/>";
        writeTags(cur, w.tags);
        cur += "</way>\n";
    }
    close();
    (void)total;
    return chunks;
}

} // namespace ocu::iso23725
