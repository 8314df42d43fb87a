#include "protocols/iso23725/Routing.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <queue>
#include <utility>

namespace ocu::iso23725 {

RouteGraph::RouteGraph(const MapConnectivityV1& c) {
    m_items = c.items;
    std::stable_sort(m_items.begin(), m_items.end(), [](auto& a, auto& b) { return a.wayId < b.wayId; });
    // A way listed twice: the last wins, as in ConnectivityGraph (unique over the reversed range keeps it).
    auto keep =
        std::unique(m_items.rbegin(), m_items.rend(), [](auto& a, auto& b) { return a.wayId == b.wayId; });
    m_items.erase(m_items.begin(), keep.base());
    m_index.reserve(m_items.size());
    for (std::size_t i = 0; i < m_items.size(); ++i)
        m_index[m_items[i].wayId] = static_cast<int>(i);
    m_enterCost.resize(m_items.size());
    m_firstSuccessor.assign(m_items.size() + 1, 0);
    for (std::size_t i = 0; i < m_items.size(); ++i) {
        const auto& it = m_items[i];
        // A road without a usable Length still costs something, so fewer hops win among unknown lengths.
        const double len = it.roadLength && *it.roadLength >= 0 ? *it.roadLength : 1.0;
        m_enterCost[i] = it.wayType == "Road" ? len : 0.0;
        m_firstSuccessor[i] = static_cast<int>(m_successors.size());
        for (auto& c : it.connection)
            if (auto f = m_index.find(c.wayId); f != m_index.end())
                m_successors.push_back(f->second);
    }
    m_firstSuccessor[m_items.size()] = static_cast<int>(m_successors.size());
}

const ConnectivityItem* RouteGraph::item(std::int64_t wayId) const {
    auto it = m_index.find(wayId);
    return it == m_index.end() ? nullptr : &m_items[static_cast<std::size_t>(it->second)];
}

std::vector<std::int64_t> RouteGraph::areasWithTask(std::string_view task) const {
    std::vector<std::int64_t> out;
    for (auto& i : m_items)
        if (i.wayType == "Area" && i.areaDefaultTask && *i.areaDefaultTask == task)
            out.push_back(i.wayId);
    return out;
}

std::vector<WayRef> RouteResult::routeV1() const {
    std::vector<WayRef> out;
    for (std::size_t i = 1; i + 1 < ways.size(); ++i)
        out.push_back(WayRef{ways[i]});
    return out;
}

// Dijkstra with a binary heap over way indices.
struct RouteSearch {
    static RouteResult run(const RouteGraph& g, std::int64_t from, const std::vector<std::int64_t>& to) {
        RouteResult r;
        auto s = g.m_index.find(from);
        if (s == g.m_index.end()) {
            r.error = "start way " + std::to_string(from) + " is not in MapConnectivityV1";
            return r;
        }
        const std::size_t n = g.m_items.size();
        std::vector<char> target(n, 0);
        bool anyTarget = false;
        for (auto t : to)
            if (auto f = g.m_index.find(t); f != g.m_index.end()) {
                target[static_cast<std::size_t>(f->second)] = 1;
                anyTarget = true;
            }
        if (!anyTarget) {
            r.error = to.size() == 1
                          ? "destination way " + std::to_string(to.front()) + " is not in MapConnectivityV1"
                          : "none of the destination ways is in MapConnectivityV1";
            return r;
        }
        constexpr double kInf = std::numeric_limits<double>::infinity();
        std::vector<double> dist(n, kInf);
        std::vector<int> prev(n, -1);
        using Q = std::pair<double, int>;
        std::priority_queue<Q, std::vector<Q>, std::greater<>> q;
        dist[static_cast<std::size_t>(s->second)] = 0;
        q.push({0.0, s->second});
        int reached = -1;
        while (!q.empty()) {
            auto [d, w] = q.top();
            q.pop();
            const auto wi = static_cast<std::size_t>(w);
            if (d > dist[wi])
                continue;
            if (target[wi]) {
                reached = w;
                break;
            }
            for (int k = g.m_firstSuccessor[wi]; k < g.m_firstSuccessor[wi + 1]; ++k) {
                const int v = g.m_successors[static_cast<std::size_t>(k)];
                const auto vi = static_cast<std::size_t>(v);
                // A tiny cost per way: among equal lengths (areas) the route with fewer ways wins.
                const double nd = d + g.m_enterCost[vi] + 1e-6;
                if (nd < dist[vi]) {
                    dist[vi] = nd;
                    prev[vi] = w;
                    q.push({nd, v});
                }
            }
        }
        if (reached < 0) {
            std::string dest = to.size() == 1 ? "way " + std::to_string(to.front())
                                              : std::to_string(to.size()) + " destination ways";
            r.error = dest + " unreachable from way " + std::to_string(from) + " over MapConnectivityV1";
            return r;
        }
        for (int w = reached; w >= 0; w = prev[static_cast<std::size_t>(w)])
            r.ways.push_back(g.m_items[static_cast<std::size_t>(w)].wayId);
        std::reverse(r.ways.begin(), r.ways.end());
        for (std::size_t i = 1; i < r.ways.size(); ++i)
            r.length += g.m_enterCost[static_cast<std::size_t>(g.m_index.at(r.ways[i]))];
        r.ok = true;
        return r;
    }
};

RouteResult shortestRoute(const RouteGraph& graph, std::int64_t from, std::int64_t to) {
    return RouteSearch::run(graph, from, {to});
}

RouteResult shortestRoute(const RouteGraph& graph, std::int64_t from, const std::vector<std::int64_t>& to) {
    if (to.empty()) {
        RouteResult r;
        r.error = "no destination way";
        return r;
    }
    return RouteSearch::run(graph, from, to);
}

std::string checkRoute(const RouteGraph& graph, std::int64_t from, const std::vector<WayRef>& route,
                       std::int64_t to) {
    std::vector<std::int64_t> chain{from};
    for (auto& w : route)
        chain.push_back(std::llabs(w.wayId));
    chain.push_back(to);
    for (auto id : chain)
        if (!graph.contains(id))
            return "route way " + std::to_string(id) + " is not in MapConnectivityV1";
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
        if (chain[i] == chain[i + 1])
            continue;
        const auto* it = graph.item(chain[i]);
        const bool linked = std::any_of(it->connection.begin(), it->connection.end(),
                                        [&](const WayRef& c) { return c.wayId == chain[i + 1]; });
        if (!linked)
            return "route breaks: way " + std::to_string(chain[i + 1]) + " is not reachable from way " +
                   std::to_string(chain[i]) + " (MapConnectivityV1)";
    }
    return {};
}

} // namespace ocu::iso23725
