// bench_iso23725: parse+validate MachinePositionV1 (msgs/s, public decodeMessage and the DOM path alone),
// a 100k-node / 20k-way map document (parse time), and 1,000 simulated trucks at 10 Hz over loopback ws://
// into the IsoStack (does the OCU keep up?).
#include "protocols/iso23725/IsoStack.h"
#include "protocols/iso23725/MapModel.h"
#include "protocols/iso23725/PositionFastPath.h"
#include "protocols/iso23725/Routing.h"
#include "sim/iso23725/SimulatedAhs.h"

#include "protocols/common/Log.h"

#include <benchmark/benchmark.h>

#include <atomic>
#include <random>
#include <thread>

using namespace ocu::iso23725;

namespace {

const std::string kPosition =
    R"({"Protocol":"ISO23725","Version":1,"Timestamp":"2025-03-14T02:15:07.412Z","EquipmentId":"c3a51f7e-0d24-4b9a-8f63-1e2d4c5b6a78",)"
    R"("MachinePositionV1":{"Timestamp":"2025-03-14T02:15:07.380Z","Heading":87,"Latitude":-23.360114,"Longitude":119.730552,"Elevation":512.34,)"
    R"("LatitudeAccuracy":0.05,"LongitudeAccuracy":0.06,"ElevationAccuracy":0.11,"HeadingAccuracy":0.8,"Speed":34}})";

template <class Decode> void runPositionBench(benchmark::State& state, Decode decode) {
    std::int64_t sum = 0;
    for (auto _ : state) {
        auto r = decode(kPosition);
        if (!r || !r->errors.empty())
            state.SkipWithError("decode failed");
        sum += *r->template find<MachinePositionV1>()->pose.heading;
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(state.iterations());
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(kPosition.size()));
}

// The public entry point: clean positions take the fast path.
void BM_ParseValidatePosition(benchmark::State& state) {
    runPositionBench(state, [](std::string_view t) { return decodeMessage(t); });
}
BENCHMARK(BM_ParseValidatePosition);

// The same message through the DOM path alone (nlohmann parse + decodeJson), as before the fast path.
void BM_ParseValidatePositionDomPath(benchmark::State& state) {
    runPositionBench(state, [](std::string_view t) { return decodeMessageDom(t); });
}
BENCHMARK(BM_ParseValidatePositionDomPath);

// Reference on the same machine and load: nlohmann DOM parse alone, no validation.
void BM_JsonParseOnlyReference(benchmark::State& state) {
    std::size_t n = 0;
    for (auto _ : state) {
        auto j = nlohmann::json::parse(kPosition.begin(), kPosition.end(), nullptr, false);
        n += j.size();
    }
    benchmark::DoNotOptimize(n);
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_JsonParseOnlyReference);

std::vector<std::string> bigMap(std::size_t nodes, std::size_t ways) {
    MapModel m;
    for (std::size_t i = 0; i < nodes; ++i) {
        MapNode n;
        n.id = static_cast<std::int64_t>(i + 1);
        n.lat = -23.36 + 0.00001 * static_cast<double>(i % 1000);
        n.lon = 119.73 + 0.00001 * static_cast<double>(i / 1000);
        n.ele = 500.0;
        m.nodes[n.id] = n;
    }
    const std::size_t per = nodes / ways; // 5 nodes per way, rows of the grid
    for (std::size_t w = 0; w < ways; ++w) {
        MapWay way;
        way.id = static_cast<std::int64_t>(w + 1);
        for (std::size_t k = 0; k < per; ++k)
            way.nodes.push_back(static_cast<std::int64_t>(w * per + k + 1));
        way.tags = {{"name", "road " + std::to_string(w)}, {"autonomy", "mixed"}, {"oneway", "no"}};
        m.ways[way.id] = way;
    }
    return writeOsmChunks(m, 10000, 1);
}

void BM_ParseMap100kNodes20kWays(benchmark::State& state) {
    auto chunks = bigMap(100000, 20000);
    std::size_t bytes = 0;
    for (auto& c : chunks)
        bytes += c.size();
    for (auto _ : state) {
        auto r = parseMapDocument(chunks);
        if (!r || r->nodes.size() != 100000 || r->ways.size() != 20000)
            state.SkipWithError(r ? "wrong counts" : r.error().c_str());
    }
    state.counters["chunks"] = static_cast<double>(chunks.size());
    state.counters["MB"] = static_cast<double>(bytes) / 1e6;
}
BENCHMARK(BM_ParseMap100kNodes20kWays)->Unit(benchmark::kMillisecond)->Iterations(3);

// A generated 20,000-way MapConnectivityV1: a 142 x 141 grid of ways, each connected to its
// four neighbours (one in seven of those connections one-way, so the graph is directed), roads of 50-500 m,
// every tenth way an area. The route goes corner to corner: the search visits about the whole graph.
MapConnectivityV1 gridConnectivity(int cols, int rows, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> len(50, 500);
    std::uniform_int_distribution<int> oneWay(0, 6);
    MapConnectivityV1 c;
    auto id = [&](int x, int y) { return std::int64_t(100000 + y * cols + x); };
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < cols; ++x) {
            ConnectivityItem i;
            i.wayId = id(x, y);
            if ((y * cols + x) % 10 == 0) {
                i.wayType = "Area";
                i.areaDefaultTask = "Load";
            } else {
                i.wayType = "Road";
                i.roadLength = len(rng);
            }
            const int dx[] = {1, -1, 0, 0}, dy[] = {0, 0, 1, -1};
            for (int k = 0; k < 4; ++k) {
                const int nx = x + dx[k], ny = y + dy[k];
                if (nx < 0 || ny < 0 || nx >= cols || ny >= rows)
                    continue;
                if (k % 2 == 1 && oneWay(rng) == 0) // some reverse directions missing: one-way
                    continue;
                i.connection.push_back(WayRef{id(nx, ny)});
            }
            c.items.push_back(std::move(i));
        }
    return c;
}

void BM_Route20kWays(benchmark::State& state) {
    const auto conn = gridConnectivity(142, 141, 7);
    const RouteGraph g(conn);
    const std::int64_t from = conn.items.front().wayId, to = conn.items.back().wayId;
    std::size_t ways = 0;
    for (auto _ : state) {
        auto r = shortestRoute(g, from, to);
        if (!r.ok)
            state.SkipWithError(r.error.c_str());
        ways = r.ways.size();
        benchmark::DoNotOptimize(r);
    }
    state.counters["graph_ways"] = static_cast<double>(g.size());
    state.counters["route_ways"] = static_cast<double>(ways);
}
BENCHMARK(BM_Route20kWays)->Unit(benchmark::kMillisecond);

// Indexing a new MapConnectivityV1 (done once per received message, not per route).
void BM_RouteGraphBuild20kWays(benchmark::State& state) {
    const auto conn = gridConnectivity(142, 141, 7);
    for (auto _ : state) {
        RouteGraph g(conn);
        benchmark::DoNotOptimize(g);
    }
}
BENCHMARK(BM_RouteGraphBuild20kWays)->Unit(benchmark::kMillisecond);

struct CountingListener : IsoListener {
    std::atomic<std::uint64_t> changes{0};
    void onMachineChanged(const IsoMachineSnapshot&) override { ++changes; }
};

// 1,000 trucks at 10 Hz: the simulator's send queue must not grow and every position must be decoded.
void BM_Loopback1000TrucksAt10Hz(benchmark::State& state) {
    ocu::setLogThreshold(ocu::LogLevel::Error);
    ocu::sim::SimulatedAhsConfig sc;
    sc.truckCount = 1000;
    sc.positionRateHz = 10;
    sc.healthEvents = false;
    ocu::sim::SimulatedAhs ahs(sc);
    if (!ahs.start()) {
        state.SkipWithError("simulator did not start");
        return;
    }
    IsoConfig ic;
    ic.links.push_back(IsoLinkConfig{"ahs", {}, {}});
    ic.links[0].ws.url = ahs.url();
    CountingListener listener;
    IsoStack stack(ic, listener);
    stack.start();
    for (int i = 0; i < 500 && stack.counters().get("rx.positions") < 1000; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const double seconds = static_cast<double>(state.range(0));
    std::size_t maxQueue = 0, lastQueue = 0;
    for (auto _ : state) {
        auto rx0 = stack.counters().get("rx.positions");
        auto tx0 = ahs.stats().positionsSent;
        auto t0 = std::chrono::steady_clock::now();
        while (std::chrono::steady_clock::now() - t0 < std::chrono::duration<double>(seconds)) {
            std::this_thread::sleep_for(std::chrono::milliseconds(250));
            lastQueue = ahs.stats().queuedBytes;
            maxQueue = std::max(maxQueue, lastQueue);
        }
        double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        state.counters["rx_positions_per_s"] =
            static_cast<double>(stack.counters().get("rx.positions") - rx0) / dt;
        state.counters["tx_positions_per_s"] = static_cast<double>(ahs.stats().positionsSent - tx0) / dt;
    }
    state.counters["max_queue_kB"] = static_cast<double>(maxQueue) / 1024.0;
    state.counters["end_queue_kB"] = static_cast<double>(lastQueue) / 1024.0;
    state.counters["rejected"] = static_cast<double>(stack.counters().sumPrefix("rx.rejected."));
    stack.stop();
    ahs.stop();
}
BENCHMARK(BM_Loopback1000TrucksAt10Hz)->Arg(5)->Iterations(1)->Unit(benchmark::kSecond);

} // namespace

BENCHMARK_MAIN();
