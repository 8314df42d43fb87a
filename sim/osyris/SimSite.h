#pragma once
// A whole simulated OSYRIS site in one thread on a FakeClock: stations (StationCore + ribbon store +
// pass-count grid), their machines, and the in-memory radio. Used by tests (accelerated time) and by any
// caller that wants a reproducible site without sockets.
#include "protocols/osyris/StationCore.h"
#include "sim/osyris/SimNetwork.h"
#include "sim/osyris/SimulatedRoller.h"

#include <memory>
#include <optional>
#include <vector>

namespace ocu::sim::osyris {

struct SimStationOptions {
    ocu::osyris::OsyrisConfig config;   // stationIndex, active, beat, sqlitePath, ...
    std::optional<MachineSpec> machine; // the machine this station is on (none = office/relay box)
    std::optional<std::pair<double, double>>
        fixedPosition;            // for range-limited links when there is no machine
    double positionPeriodS = 0.5; // a stable position is written every period
    bool started = true;
    ocu::osyris::OsyrisListener* listener = nullptr;
};

class SimSite {
public:
    explicit SimSite(std::uint32_t seed = 1);
    ~SimSite();

    ocu::FakeClock& clock() { return m_clock; }
    SimNetwork& network() { return m_net; }
    double simTime() const;

    int add(SimStationOptions opts);
    void start(int i);
    void stop(int i); // the station goes away; its SQLite file (if any) keeps what was committed
    bool running(int i) const;
    void run(double seconds, double stepMs = 10);
    // Runs until pred() or the time limit; returns whether pred() became true.
    bool runUntil(const std::function<bool()>& pred, double maxSeconds, double stepMs = 10);

    std::size_t size() const { return m_nodes.size(); }
    ocu::osyris::StationCore& core(int i);
    ocu::osyris::RibbonStore& store(int i);
    ocu::osyris::PassCountGrid& grid(int i);
    std::optional<std::pair<double, double>> truePosition(int i) const;
    const SimStationOptions& options(int i) const;
    void setMachine(int i, std::optional<MachineSpec> m);

private:
    struct Node;
    ocu::FakeClock m_clock;
    ocu::TimePoint m_t0;
    SimNetwork m_net;
    std::vector<std::unique_ptr<Node>> m_nodes;
};

} // namespace ocu::sim::osyris
