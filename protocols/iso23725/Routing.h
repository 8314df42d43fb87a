#pragma once
// Routing for dispatch: shortest paths over MapConnectivityV1 (§9.1), pure code. The graph is
// directed (a way's Connection lists the ways reachable from it), entering a road costs its Length (m),
// entering an area costs nothing. A route is computed from the truck's current way
// (HaulTruckProductionStateV2.WayId) to a destination way or to the nearest of several (an area's ways); no
// route means the destination is refused before anything is sent.
#include "protocols/iso23725/Messages.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ocu::iso23725 {

// MapConnectivityV1 indexed for repeated shortest-path queries (ways by index, successors in one array).
class RouteGraph {
public:
    RouteGraph() = default;
    explicit RouteGraph(const MapConnectivityV1& connectivity);

    bool empty() const { return m_items.empty(); }
    std::size_t size() const { return m_items.size(); }
    bool contains(std::int64_t wayId) const { return m_index.count(wayId) != 0; }
    const ConnectivityItem* item(std::int64_t wayId) const;
    // Areas whose DefaultTask is `task` (Load, Offload, Park, Fuel, ...), in way id order.
    std::vector<std::int64_t> areasWithTask(std::string_view task) const;

private:
    friend struct RouteSearch;
    std::vector<ConnectivityItem> m_items;         // sorted by way id
    std::unordered_map<std::int64_t, int> m_index; // way id -> index in m_items
    std::vector<double> m_enterCost;               // per way: Length for a road, 0 for an area
    std::vector<int> m_firstSuccessor;             // CSR: successors of i in [first[i], first[i+1])
    std::vector<int> m_successors;                 // indices; connections to unknown ways are dropped
};

struct RouteResult {
    bool ok = false;
    std::vector<std::int64_t> ways; // from .. destination, both included
    double length = 0;              // m: the roads entered after the start way
    std::string error;              // why there is no route (ok = false)

    // RouteV1 of an assignment (§5 #21): the ways between the start and the destination, both excluded.
    std::vector<WayRef> routeV1() const;
};

// Shortest route from one way to another (from == to: a route of one way, length 0).
RouteResult shortestRoute(const RouteGraph& graph, std::int64_t from, std::int64_t to);
// Shortest route to the nearest of several destination ways.
RouteResult shortestRoute(const RouteGraph& graph, std::int64_t from, const std::vector<std::int64_t>& to);

// Checks a route given by the operator: from, the route's ways, then to, each connected to the next. Negative
// ids (Q6: traversed against node order) are checked by their absolute value. Empty when the route holds.
std::string checkRoute(const RouteGraph& graph, std::int64_t from, const std::vector<WayRef>& route,
                       std::int64_t to);

} // namespace ocu::iso23725
