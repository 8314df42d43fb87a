#include "sim/osyris/SimSite.h"

#include "protocols/common/Log.h"

namespace ocu::sim::osyris {

using namespace ocu::osyris;

struct SimSite::Node {
    SimStationOptions opts;
    std::optional<SimulatedMachine> machine;
    std::unique_ptr<RibbonStore> store;
    std::unique_ptr<PassCountGrid> grid;
    std::unique_ptr<StationCore> core;
    int netId = -1;
    ocu::TimePoint nextTick{};
    double nextPosT = 0;
};

SimSite::SimSite(std::uint32_t seed) : m_t0(m_clock.now()), m_net(m_clock, seed) {}
SimSite::~SimSite() = default;

double SimSite::simTime() const {
    return std::chrono::duration<double>(m_clock.now() - m_t0).count();
}

int SimSite::add(SimStationOptions opts) {
    auto n = std::make_unique<Node>();
    n->opts = std::move(opts);
    if (n->opts.machine)
        n->machine.emplace(*n->opts.machine);
    int i = static_cast<int>(m_nodes.size());
    n->netId = m_net.addNode({}, [this, i] { return truePosition(i); });
    m_nodes.push_back(std::move(n));
    if (m_nodes.back()->opts.started)
        start(i);
    return i;
}

void SimSite::setMachine(int i, std::optional<MachineSpec> m) {
    auto& n = *m_nodes.at(static_cast<std::size_t>(i));
    n.opts.machine = m;
    n.machine.reset();
    if (m)
        n.machine.emplace(*m);
}

std::optional<std::pair<double, double>> SimSite::truePosition(int i) const {
    auto& n = *m_nodes.at(static_cast<std::size_t>(i));
    if (n.machine) {
        auto p = n.machine->poseAt(simTime());
        return std::make_pair(double(p.x), double(p.y));
    }
    return n.opts.fixedPosition;
}

const SimStationOptions& SimSite::options(int i) const {
    return m_nodes.at(static_cast<std::size_t>(i))->opts;
}

void SimSite::start(int i) {
    auto& n = *m_nodes.at(static_cast<std::size_t>(i));
    if (n.core)
        return;
    auto st = RibbonStore::open(n.opts.config.sqlitePath);
    if (!st) {
        logWarning("osyris.sim", st.error());
        st = RibbonStore::open("");
    }
    n.store = std::move(*st);
    n.grid = std::make_unique<PassCountGrid>(n.opts.config.passCount);
    int netId = n.netId;
    n.core = std::make_unique<StationCore>(
        n.opts.config, m_clock, *n.store, n.grid.get(), n.opts.listener,
        [this, netId](const Bytes& d) { m_net.send(netId, d); }, 1000u + n.opts.config.stationIndex);
    Node* np = &n;
    m_net.setDeliver(netId, [np](ByteSpan d) {
        if (np->core)
            np->core->receive(d);
    });
    n.core->start();
    n.core->updateGrid();
    // Stagger the Beats of the stations like unsynchronised machines.
    n.nextTick =
        m_clock.now() + std::chrono::milliseconds((n.opts.config.stationIndex * 37) % n.opts.config.beatMs);
    n.nextPosT = simTime();
}

void SimSite::stop(int i) {
    auto& n = *m_nodes.at(static_cast<std::size_t>(i));
    m_net.setDeliver(n.netId, {});
    n.core.reset();
    n.grid.reset();
    n.store.reset();
}

bool SimSite::running(int i) const {
    return m_nodes.at(static_cast<std::size_t>(i))->core != nullptr;
}
StationCore& SimSite::core(int i) {
    return *m_nodes.at(static_cast<std::size_t>(i))->core;
}
RibbonStore& SimSite::store(int i) {
    return *m_nodes.at(static_cast<std::size_t>(i))->store;
}
PassCountGrid& SimSite::grid(int i) {
    return *m_nodes.at(static_cast<std::size_t>(i))->grid;
}

bool SimSite::runUntil(const std::function<bool()>& pred, double maxSeconds, double stepMs) {
    auto step = std::chrono::duration_cast<Duration>(std::chrono::duration<double, std::milli>(stepMs));
    double end = simTime() + maxSeconds;
    while (simTime() < end) {
        if (pred && pred())
            return true;
        m_clock.advance(step);
        m_net.deliverDue();
        double t = simTime();
        for (auto& np : m_nodes) {
            auto& n = *np;
            if (!n.core)
                continue;
            if (n.machine && t >= n.nextPosT) {
                n.core->publishOwnPosition(
                    n.machine->poseAt(t, 1763683200000 + static_cast<std::int64_t>(t * 1000)));
                n.nextPosT += n.opts.positionPeriodS;
            }
            if (m_clock.now() >= n.nextTick) {
                n.core->tick();
                n.nextTick += std::chrono::milliseconds(n.opts.config.beatMs);
            }
        }
    }
    return pred ? pred() : false;
}

void SimSite::run(double seconds, double stepMs) {
    runUntil({}, seconds, stepMs);
}

} // namespace ocu::sim::osyris
