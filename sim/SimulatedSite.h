#pragma once
// The built-in simulated site: simulated JAUS UGVs, a simulated ISO 23725 AHS with its haul trucks and an
// OSYRIS paving train, all speaking the real protocols over real loopback sockets. Used by `ocu` without
// arguments, by `ocu-sim`, and by end-to-end tests. It starts the simulator module of every protocol of the
// build (sim/SimModule.h). No Qt.
#include "protocols/site/SiteConfig.h"
#include "sim/SimModule.h"

#include <memory>
#include <string>
#include <vector>

namespace ocu::sim {

class SimulatedSite {
public:
    SimulatedSite();
    ~SimulatedSite();
    SimulatedSite(const SimulatedSite&) = delete;
    SimulatedSite& operator=(const SimulatedSite&) = delete;

    // Starts the simulators that config.simulation asks for, placed around config.origin, and points
    // the config's protocol sections at them (creating the sections when absent). Returns an empty
    // string, or what failed (the simulators that did start keep running).
    std::string start(SiteConfig& config);
    void stop();

    // One module per protocol of this build, in start order.
    const std::vector<std::unique_ptr<SimModule>>& modules() const { return m_modules; }

    // Where each part of the site sits relative to the site origin (metres east, north).
    static constexpr double kUgvAreaE = 180, kUgvAreaN = 120;
    static constexpr double kRoadAreaE = -260, kRoadAreaN = -180;

private:
    std::vector<std::unique_ptr<SimModule>> m_modules;
};

} // namespace ocu::sim
